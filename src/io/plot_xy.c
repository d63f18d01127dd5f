/* acbb — the general x-y plot (plot.h: acbb_plot_xy_files), for the seed's
 * figures (figures.h): N labelled series, lines or lines with points.
 *
 * One gnuplot process draws both formats: the script sets the pngcairo
 * terminal with `set output '/dev/fd/3'`, plots, then the svg terminal with
 * '/dev/fd/4' and plots again. Those two strings are ours; the descriptors
 * are the unnamed temporaries of acbb_out, so a user path never enters the
 * script (DESIGN.md "Practical notes"), and a gnuplot start-up (the cost of
 * a figure) is paid once per figure, not once per image. */
#define _GNU_SOURCE /* F_DUPFD_CLOEXEC */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/tools/outfile.h"
#include "acbb/tools/plot.h"
#include "plot_priv.h"

/* Descriptors at or above this are safe dup2 sources for gnuplot's 3 and 4. */
#define XY_FD_MIN 10

/* Datablocks $S0.. of the finite points; the count of series drawn. */
static size_t xy_blocks(sbuf *b, const acbb_plot_xy *p, bool *drawn)
{
    size_t used = 0;
    for (size_t k = 0; k < p->n_series; k++) {
        const acbb_plot_series *s = &p->series[k];
        size_t rows = 0;
        sb_printf(b, "$S%zu << EOD\n", k);
        for (size_t i = 0; i < s->n; i++) {
            if (!isfinite(s->x[i]) || !isfinite(s->y[i])) continue;
            sb_printf(b, "%.17g %.17g\n", s->x[i], s->y[i]);
            rows++;
        }
        sb_printf(b, "EOD\n");
        drawn[k] = rows > 0;
        used += drawn[k];
    }
    return used;
}

static void xy_label(sbuf *b, const char *cmd, const char *plain)
{
    char m[256];
    plot_markup(plain ? plain : "", m, sizeof m);
    sb_printf(b, "%s", cmd);
    sb_quoted(b, m);
    sb_printf(b, "\n");
}

/* The characters a label shows (a Greek name is one, markup none). */
static double shown_chars(const char *plain)
{
    char m[256];
    double n = 0;
    plot_markup(plain ? plain : "", m, sizeof m);
    for (const unsigned char *c = (const unsigned char *)m; *c; c++)
        n += (*c & 0xc0) != 0x80 && !strchr("_{}\\", *c);
    return n;
}

/* The title broken into lines that fit the width (issue 29 item 9: at
 * print size a one-line title was cut); lines joined by "\n" in gnuplot's
 * string concatenation. Returns the number of lines. */
static int xy_title(sbuf *b, const char *title, const xy_layout *L)
{
    char lines[3][160];
    if (!title || !title[0]) return 0;
    int n = title_lines(title, L->w / (0.55 * L->em) - 4.0, lines);
    sb_printf(b, "set title ");
    for (int i = 0; i < n; i++) {
        char m[256];
        plot_markup(lines[i], m, sizeof m);
        if (i) sb_printf(b, ".\"\\n\".");
        sb_quoted(b, m);
    }
    sb_printf(b, "\n");
    return n;
}

/* Markers by colour: eight shapes, filled for solid lines and open for
 * dashed ones (TE solid and filled, WTE dashed and open), so two curves
 * differ in colour, dash and marker and survive grey print. */
void series_style(sbuf *b, const acbb_plot_series *s, size_t n)
{
    static const int filled[8] = { 7, 5, 9, 11, 13, 15, 1, 3 },
                     open[8] = { 6, 4, 8, 10, 12, 14, 2, 3 };
    int dash = s->dash > 0 ? s->dash : 1;
    int c = s->color > 0 ? s->color : 0;
    const char *with = s->points == 2 ? "points" : s->points ? "linespoints" : "lines";
    sb_printf(b, "with %s linewidth 2 dashtype %d ", with, dash);
    if (c > 0) sb_printf(b, "linecolor %d ", c);
    else sb_printf(b, "linecolor rgb '#000000' ");
    if (s->points)
        sb_printf(b, "pointtype %d pointinterval %zu ", (dash > 1 ? open : filled)[(c > 0 ? c - 1 : 0) % 8],
                  n > 16 ? (n + 7) / 8 : 1);
}

/* The points a key must not cover: the data and, between two points of a
 * line, eight more along the segment. */
static void xy_points(key_pts *kp, const acbb_plot_xy *p, const bool *drawn)
{
    for (size_t k = 0; k < p->n_series; k++) {
        const acbb_plot_series *s = &p->series[k];
        double px = NAN, py = NAN;
        for (size_t i = 0; drawn[k] && i < s->n; i++) {
            if (!isfinite(s->x[i]) || !isfinite(s->y[i])) continue;
            for (int j = 1; s->points != 2 && isfinite(px) && j < 8; j++)
                key_pts_add(kp, px + (s->x[i] - px) * j / 8.0, py + (s->y[i] - py) * j / 8.0);
            key_pts_add(kp, px = s->x[i], py = s->y[i]);
        }
    }
}

static void xy_plot(sbuf *b, const acbb_plot_xy *p, const acbb_plot_look *look,
                    const bool *drawn, int w, int h)
{
    xy_layout L = { .w = w, .h = h, .em = acbb_plot_font_px(w) };
    L.title_lines = xy_title(b, p->title, &L);
    xy_label(b, "set xlabel ", p->xlabel);
    xy_label(b, "set ylabel ", p->ylabel);
    sb_printf(b, "set grid\n");
    key_pts kp = { 0 };
    xy_points(&kp, p, drawn);
    axes_range(&L, &kp);
    bool own = look && look->n_key > 0;
    int entries = 0;
    double chars = 0;
    for (size_t k = 0; k < (own ? look->n_key : p->n_series); k++) {
        if (!own && !drawn[k]) continue;
        entries++;
        chars = fmax(chars, shown_chars(own ? look->key[k].label : p->series[k].label));
    }
    key_place(b, &kp, &L, entries, chars);
    axes_emit(b, &L);
    sb_printf(b, "plot ");
    bool first = true;
    for (size_t k = 0; k < p->n_series; k++) {
        const acbb_plot_series *s = &p->series[k];
        if (!drawn[k]) continue;
        sb_printf(b, "%s$S%zu using 1:2 ", first ? "" : ", ", k);
        series_style(b, s, s->n);
        first = false;
        if (own) {
            sb_printf(b, "notitle");
            continue;
        }
        char m[256];
        plot_markup(s->label ? s->label : "", m, sizeof m);
        sb_printf(b, "title ");
        sb_quoted(b, m);
    }
    for (size_t k = 0; own && k < look->n_key; k++) {
        char m[256];
        sb_printf(b, ", keyentry ");
        series_style(b, &look->key[k], 1);
        plot_markup(look->key[k].label ? look->key[k].label : "", m, sizeof m);
        sb_printf(b, "title ");
        sb_quoted(b, m);
    }
    sb_printf(b, "\n");
}

static acbb_status xy_check(const acbb_plot_xy *p, const char *png, const char *svg, int w,
                            int h, acbb_error *err)
{
    if (!p || !p->series || p->n_series == 0)
        return acbb_error_set(err, ACBB_EINVAL, "x-y plot: no series");
    if (!png && !svg) return acbb_error_set(err, ACBB_EINVAL, "x-y plot: no output file");
    const char *paths[2] = { png, svg };
    for (int i = 0; i < 2; i++)
        if (paths[i] && (!paths[i][0] || has_control_char(paths[i])))
            return acbb_error_set(err, ACBB_EINVAL,
                                  "plot path is empty or has a control character");
    acbb_status st = acbb_plot_check_size(ACBB_PLOT_PNG, w, h, err);
    if (st != ACBB_OK) return st;
    return ACBB_OK;
}

/* The whole script: data once, then one terminal + output + plot per format. */
static acbb_status xy_script(sbuf *b, const acbb_plot_xy *p, const acbb_plot_look *look,
                             const bool want[2], int w, int h, acbb_error *err)
{
    bool *drawn = calloc(p->n_series, sizeof *drawn);
    if (!drawn) return acbb_error_set(err, ACBB_ENOMEM, "out of memory building the plot");
    size_t used = xy_blocks(b, p, drawn);
    for (int f = 0, fd = 3; f < 2 && used; f++) {
        if (!want[f]) continue;
        terminal_line(b, f == 0 ? ACBB_PLOT_PNG : ACBB_PLOT_SVG, w, h);
        sb_printf(b, "set output '/dev/fd/%d'\n", fd++);
        xy_plot(b, p, look, drawn, w, h);
        /* `set output` with no file closes (and so completes) the image. */
        sb_printf(b, "set output\n");
    }
    sb_printf(b, "exit\n");
    free(drawn);
    if (!used)
        return acbb_error_set(err, ACBB_EINVAL, "x-y plot '%s': no finite point to plot",
                              p->title ? p->title : "");
    if (b->oom) return acbb_error_set(err, ACBB_ENOMEM, "out of memory building the plot");
    return ACBB_OK;
}

/* Open the targets, run gnuplot on copies of their descriptors, check and
 * commit both (or neither). */
static acbb_status xy_render(const sbuf *b, const char *paths[2], acbb_error *err)
{
    acbb_out *o[2] = { NULL, NULL };
    gp_io io = { .to_file = false };
    acbb_status st = ACBB_OK;
    for (int f = 0; f < 2 && st == ACBB_OK; f++) {
        if (!paths[f]) continue;
        st = acbb_out_open(paths[f], &o[f], NULL, err);
        if (st != ACBB_OK) break;
        int fd = fcntl(acbb_out_fd(o[f]), F_DUPFD_CLOEXEC, XY_FD_MIN);
        if (fd < 0) st = acbb_error_set(err, ACBB_EIO, "cannot pass %s to gnuplot", paths[f]);
        else io.extra[io.n_extra++] = fd;
    }
    if (st == ACBB_OK) st = run_gnuplot(b, &io, err);
    for (int f = 0; f < 2 && st == ACBB_OK; f++)
        if (o[f] && !image_complete(acbb_out_fd(o[f]), f == 0 ? ACBB_PLOT_PNG : ACBB_PLOT_SVG))
            st = acbb_error_set(err, ACBB_EIO, "gnuplot did not finish %s (disk full?); "
                                "the old file is kept", paths[f]);
    for (int k = 0; k < io.n_extra; k++) close(io.extra[k]);
    for (int f = 0; f < 2; f++) {
        if (!o[f]) continue;
        if (st == ACBB_OK) st = acbb_out_commit(o[f], err);
        else acbb_out_abort(o[f]);
    }
    return st;
}

acbb_status acbb_plot_xy_styled(const acbb_plot_xy *p, const acbb_plot_look *look,
                                const char *png_path, const char *svg_path, int width,
                                int height, acbb_error *err)
{
    acbb_status st = xy_check(p, png_path, svg_path, width, height, err);
    if (st != ACBB_OK) return st;
    for (size_t k = 0; look && k < look->n_key; k++)
        if (look->key[k].label && has_control_char(look->key[k].label))
            return acbb_error_set(err, ACBB_EINVAL, "x-y plot: a key label has a control character");
    const char *paths[2] = { png_path, svg_path };
    bool want[2] = { png_path != NULL, svg_path != NULL };
    sbuf b = { 0 };
    st = xy_script(&b, p, look, want, width, height, err);
    if (st == ACBB_OK) st = xy_render(&b, paths, err);
    free(b.p);
    return st;
}

acbb_status acbb_plot_xy_files(const acbb_plot_xy *p, const char *png_path,
                               const char *svg_path, int width, int height, acbb_error *err)
{
    return acbb_plot_xy_styled(p, NULL, png_path, svg_path, width, height, err);
}
