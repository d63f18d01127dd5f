/* acbb — plots through a short-lived gnuplot process (plot.h; DESIGN.md
 * "Practical notes").
 *
 * The whole gnuplot script (terminal, labels, one named datablock, the plot
 * command) is built in memory first, then fed to `gnuplot` on stdin by
 * gnuplot_run.c (a spawned process, never a shell; its pipes serviced
 * together so it cannot deadlock). Nothing here prints. */
#define _GNU_SOURCE /* pipe2 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "acbb/tools/plot.h"
#include "acbb/tools/outfile.h"
#include "acbb/units.h"
#include "plot_priv.h"

#define ACBB_PI 3.14159265358979323846
#define PLOT_MIN_PX 64
#define PLOT_MAX_PX 20000
/* Below ~20 x 8 characters gnuplot's dumb chart has no room for a tic. */
#define PLOT_MIN_COLS 20
#define PLOT_MIN_ROWS 8
#define PLOT_MAX_CHARS 2000
#define PLOT_MAX_SERIES (ACBB_LOSS_KINDS + 1)

/* ---- names ---- */

static const char *const format_names[] = { "png", "svg", "dumb" };

/* One plot kind: where x and the y series come from, and the labels. */
typedef struct {
    char label[48];     /* curve title */
    size_t off;         /* offset of a double in acbb_history_point or acbb_ball_view */
} plot_series;

typedef struct {
    const char *name;    /* acbb_plot_kind_name */
    const char *what;    /* default title */
    const char *xlabel, *ylabel;
    bool per_ball;       /* x = ball azimuth from the snapshot, else x = history time */
    double y_scale;      /* rad -> deg for the angles, else 1 */
    bool losses;         /* series = the loss table (those not zero throughout) + total */
    int n;
    plot_series s[PLOT_MAX_SERIES];
} plot_kind_spec;

#define HP(f) offsetof(acbb_history_point, f)
#define BV(f) offsetof(acbb_ball_view, f)

/* Indexed by acbb_plot_kind. */
static const plot_kind_spec kind_specs[] = {
    { "temperature", "bearing temperatures", "time (s)", "temperature (C)", false, 1.0, false, 4,
      { { "outer ring", HP(T_outer_ring) }, { "inner ring", HP(T_inner_ring) },
        { "ball", HP(T_ball) }, { "housing", HP(T_housing) } } },
    { "losses", "power losses", "time (s)", "power loss (W)", false, 1.0, true, 0, { { "", 0 } } },
    { "loads", "contact loads per ball", "ball azimuth (deg)", "load (N)", true, 1.0, false, 2,
      { { "inner contact Q_i", BV(Qi) }, { "outer contact Q_o", BV(Qo) } } },
    { "angles", "contact angles per ball", "ball azimuth (deg)", "angle (deg)", true,
      180.0 / ACBB_PI, false, 2,
      { { "inner contact alpha_i", BV(alpha_i) }, { "outer contact alpha_o", BV(alpha_o) } } },
    { "history-loads", "contact loads of ball 0", "time (s)", "load (N)", false, 1.0, false, 2,
      { { "inner contact Q_i", HP(Qi) }, { "outer contact Q_o", HP(Qo) } } },
    { "set-preload", "preload of the bearing set", "time (s)", "axial force (N)", false, 1.0,
      false, 1, { { "set preload", HP(set_preload) } } },
    { "set-temperature", "outer ring of each bearing", "time (s)", "temperature (C)", false,
      1.0, false, 0, { { "", 0 } } },
};
#define N_KINDS (sizeof kind_specs / sizeof kind_specs[0])

const char *acbb_plot_program(void)
{
    const char *p = getenv("ACBB_GNUPLOT");
    return p && *p ? p : "gnuplot";
}

int acbb_plot_format_from_name(const char *name)
{
    if (!name) return -1;
    for (size_t i = 0; i < 3; i++)
        if (strcasecmp(name, format_names[i]) == 0) return (int)i;
    const char *base = strrchr(name, '/');
    const char *dot = strrchr(base ? base + 1 : name, '.');
    if (!dot || dot[1] == '\0') return -1;
    /* "dumb" is a terminal, not a file format. */
    for (size_t i = 0; i < 2; i++)
        if (strcasecmp(dot + 1, format_names[i]) == 0) return (int)i;
    return -1;
}

int acbb_plot_kind_from_name(const char *name)
{
    if (!name) return -1;
    for (size_t i = 0; i < N_KINDS; i++)
        if (strcmp(name, kind_specs[i].name) == 0) return (int)i;
    return -1;
}

const char *acbb_plot_kind_name(acbb_plot_kind k)
{
    return (size_t)k < N_KINDS ? kind_specs[k].name : "unknown";
}

/* ---- script buffer ---- */

/* sbuf: plot_priv.h */

static bool sb_reserve(sbuf *b, size_t extra)
{
    if (b->oom) return false;
    if (b->n + extra + 1 <= b->cap) return true;
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < b->n + extra + 1) cap *= 2;
    char *p = realloc(b->p, cap);
    if (!p) {
        b->oom = true;
        return false;
    }
    b->p = p;
    b->cap = cap;
    return true;
}

void sb_printf(sbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (len < 0 || !sb_reserve(b, (size_t)len)) {
        b->oom = true;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(b->p + b->n, (size_t)len + 1, fmt, ap);
    va_end(ap);
    b->n += (size_t)len;
}

/* A gnuplot single-quoted string: no escapes are processed inside, and ''
 * stands for one quote. A control character would end the command line,
 * so it becomes a space (callers reject control characters in paths). */
void sb_quoted(sbuf *b, const char *s)
{
    if (!sb_reserve(b, 2 * strlen(s) + 2)) return;
    b->p[b->n++] = '\'';
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '\'') b->p[b->n++] = '\'';
        b->p[b->n++] = (c < 0x20 || c == 0x7f) ? ' ' : (char)c;
    }
    b->p[b->n++] = '\'';
    b->p[b->n] = '\0';
}

bool has_control_char(const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 0x20 || *s == 0x7f) return true;
    return false;
}

/* ---- the script ---- */

static double field(const void *base, size_t off)
{
    double v;
    memcpy(&v, (const char *)base + off, sizeof v);
    return v;
}

/* One data row; false (nothing written) if any value is not finite, so
 * gnuplot never sees a NaN and a bad row costs one point, not the plot. */
static bool data_row(sbuf *b, const plot_kind_spec *k, double x, const void *base)
{
    double y[PLOT_MAX_SERIES];
    if (!isfinite(x)) return false;
    for (int i = 0; i < k->n; i++) {
        y[i] = k->y_scale * field(base, k->s[i].off);
        if (!isfinite(y[i])) return false;
    }
    sb_printf(b, "%.17g", x);
    for (int i = 0; i < k->n; i++) sb_printf(b, " %.17g", y[i]);
    sb_printf(b, "\n");
    return true;
}

/* The datablock $D: x then one column per series. Returns the row count. */
static size_t datablock(sbuf *b, const plot_kind_spec *k, const acbb_plot_data *d)
{
    size_t rows = 0;
    sb_printf(b, "$D << EOD\n");
    if (k->per_ball) {
        const acbb_snapshot *s = d->snapshot;
        int nb = s->n_balls < ACBB_MAX_BALLS ? s->n_balls : ACBB_MAX_BALLS;
        for (int i = 0; i < nb; i++)
            rows += data_row(b, k, s->balls[i].psi * 180.0 / ACBB_PI, &s->balls[i]);
    } else {
        const acbb_history *h = d->history;
        size_t n = h->n < ACBB_HISTORY_CAP ? h->n : ACBB_HISTORY_CAP;
        for (size_t i = 0; i < n; i++) rows += data_row(b, k, h->p[i].time, &h->p[i]);
    }
    sb_printf(b, "EOD\n");
    return rows;
}

/* A marked-up label (plot_markup.c) as a quoted gnuplot string. */
static void sb_label(sbuf *b, const char *plain)
{
    char m[256];
    plot_markup(plain, m, sizeof m);
    sb_quoted(b, m);
}

/* The points of the plot, for the key's corner. */
static void kind_points(const plot_kind_spec *k, const acbb_plot_data *d, key_pts *kp)
{
    if (k->per_ball) {
        const acbb_snapshot *s = d->snapshot;
        int nb = s->n_balls < ACBB_MAX_BALLS ? s->n_balls : ACBB_MAX_BALLS;
        for (int i = 0; i < nb; i++)
            for (int j = 0; j < k->n; j++)
                key_pts_add(kp, s->balls[i].psi * 180.0 / ACBB_PI,
                            k->y_scale * field(&s->balls[i], k->s[j].off));
        return;
    }
    const acbb_history *h = d->history;
    size_t n = h->n < ACBB_HISTORY_CAP ? h->n : ACBB_HISTORY_CAP;
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j < k->n; j++)
            key_pts_add(kp, h->p[i].time, k->y_scale * field(&h->p[i], k->s[j].off));
}

/* Key and axes of a PNG/SVG kind: the key where it covers no data, tic
 * steps that fit, no negative axis for a positive quantity. The number of
 * points per series. */
static size_t print_layout(sbuf *b, const plot_kind_spec *k, const acbb_plot_data *d, int w,
                           int h)
{
    key_pts kp = { 0 };
    kind_points(k, d, &kp);
    xy_layout L = { .w = w, .h = h, .em = acbb_plot_font_px(w), .title_lines = 1 };
    axes_range(&L, &kp);
    double chars = 0;
    for (int i = 0; i < k->n; i++) { /* the characters shown: a "_" is markup */
        double c = 0;
        for (const char *p = k->s[i].label; *p; p++) c += *p != '_';
        chars = fmax(chars, c);
    }
    size_t rows = k->n > 0 ? kp.n / (size_t)k->n : 0;
    key_place(b, &kp, &L, k->n, chars);
    axes_emit(b, &L);
    return rows;
}

static void labels_and_plot(sbuf *b, const plot_kind_spec *k, const acbb_plot_data *d,
                            bool dumb, int w, int h)
{
    char title[640];
    /* The dumb terminal cannot rotate text and drops the y label, so there
     * the quantity and unit go into the title. */
    snprintf(title, sizeof title, "%s%s%s%s%s", d->title && d->title[0] ? d->title : "",
             d->title && d->title[0] ? ": " : "", k->what, dumb ? ", " : "",
             dumb ? k->ylabel : "");
    sb_printf(b, "set title ");
    sb_quoted(b, title); /* the user's title: plain */
    sb_printf(b, " noenhanced\nset xlabel ");
    if (dumb) sb_quoted(b, k->xlabel);
    else sb_label(b, k->xlabel);
    sb_printf(b, "\nset ylabel ");
    if (dumb) sb_quoted(b, k->ylabel);
    else sb_label(b, k->ylabel);
    sb_printf(b, "\nset grid\n");
    size_t rows = 0;
    if (!dumb) /* the key clear of the data, axes for print (plot_axes.c) */
        rows = print_layout(b, k, d, w, h);
    sb_printf(b, "plot ");
    for (int i = 0; i < k->n; i++) {
        sb_printf(b, "%s$D using 1:%d ", i ? ", " : "", i + 2);
        if (dumb) { /* text: one character per series already */
            sb_printf(b, "with %s linewidth 2 title ", k->per_ball ? "linespoints pointtype 7" : "lines");
            sb_quoted(b, k->s[i].label);
            continue;
        }
        /* each series its colour, dash and marker: apart in grey too */
        acbb_plot_series st = { k->s[i].label, NULL, NULL, rows, i + 1, 1 + i % 5, 1 };
        series_style(b, &st, rows);
        sb_printf(b, "title ");
        sb_label(b, k->s[i].label);
    }
    sb_printf(b, "\n");
}

/* The losses plot lists the loss table: every loss that is not zero over
 * the whole run (a switched-off effect draws no flat line), then the total. */
static void loss_series(plot_kind_spec *k, const acbb_history *h)
{
    k->n = 0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        bool any = false;
        for (size_t i = 0; i < h->n && !any; i++) any = h->p[i].loss[l] != 0.0;
        if (!any) continue;
        plot_series *s = &k->s[k->n++];
        snprintf(s->label, sizeof s->label, "%s %s", acbb_loss_label((acbb_loss_kind)l),
                 acbb_loss_symbol((acbb_loss_kind)l));
        s->off = HP(loss) + (size_t)l * sizeof(double);
    }
    k->s[k->n++] = (plot_series){ "total", HP(total) };
}

/* A bearing set's kinds (MODEL.md 14): one outer-ring curve per bearing. */
static acbb_status set_series(plot_kind_spec *k, const acbb_plot_data *d, acbb_error *err)
{
    int n = d->snapshot ? d->snapshot->n_bearings : 0;
    if (n < 2)
        return acbb_error_set(err, ACBB_EINVAL, "%s plot: needs a bearing set "
                              "(set.arrangement other than single)", k->name);
    if (k->n > 0) return ACBB_OK;
    for (int b = 0; b < n && b < ACBB_MAX_SET; b++) {
        plot_series *s = &k->s[k->n++];
        snprintf(s->label, sizeof s->label, "bearing %d", b);
        s->off = HP(T_outer_set) + (size_t)b * sizeof(double);
    }
    return ACBB_OK;
}

/* Checks shared by the file and dumb paths; fills *spec. */
static acbb_status check_data(acbb_plot_kind kind, const acbb_plot_data *d,
                              plot_kind_spec *spec, acbb_error *err)
{
    if ((size_t)kind >= N_KINDS)
        return acbb_error_set(err, ACBB_EINVAL, "unknown plot kind %d", (int)kind);
    const plot_kind_spec *k = &kind_specs[kind];
    if (!d)
        return acbb_error_set(err, ACBB_EINVAL, "%s plot: no data", k->name);
    if (k->per_ball && (!d->snapshot || d->snapshot->n_balls < 1))
        return acbb_error_set(err, ACBB_EINVAL, "%s plot: needs a snapshot with balls",
                              k->name);
    if (!k->per_ball && (!d->history || d->history->n < 1))
        return acbb_error_set(err, ACBB_EINVAL, "%s plot: needs a non-empty run history",
                              k->name);
    *spec = *k;
    if (k->losses) loss_series(spec, d->history);
    if (kind >= ACBB_PLOT_SET_PRELOAD) return set_series(spec, d, err);
    return ACBB_OK;
}

/* The script after the terminal/output lines; EINVAL if no row is finite. */
static acbb_status script_body(sbuf *b, const plot_kind_spec *k, const acbb_plot_data *d,
                               bool dumb, int w, int h, acbb_error *err)
{
    if (datablock(b, k, d) == 0)
        return acbb_error_set(err, ACBB_EINVAL, "%s plot: no finite data to plot", k->name);
    labels_and_plot(b, k, d, dumb, w, h);
    /* `set output` with no file closes (and so completes) the image. */
    sb_printf(b, "set output\nexit\n");
    if (b->oom) return acbb_error_set(err, ACBB_ENOMEM, "out of memory building the plot");
    return ACBB_OK;
}

/* ---- public entry points ---- */

void terminal_line(sbuf *b, acbb_plot_format fmt, int w, int h)
{
    /* UTF-8 labels (Greek, degree sign: plot_markup.c); enhanced text
     * only where a plot writes marked-up labels, user text noenhanced. */
    /* Text for print (plot_size.c): pngcairo takes points at 96 dpi, svg
     * takes the em in its pixels; lines and markers grow with the text. */
    double em = acbb_plot_font_px(w), lw = em / 16.0;
    if (fmt == ACBB_PLOT_PNG)
        sb_printf(b, "set encoding utf8\nset terminal pngcairo enhanced size %d,%d "
                     "font 'sans,%.1f' linewidth %.2f\n", w, h, 0.75 * em, lw);
    else if (fmt == ACBB_PLOT_SVG)
        sb_printf(b, "set encoding utf8\nset terminal svg enhanced size %d,%d "
                     "font 'sans,%.1f' linewidth %.2f\n", w, h, em, lw);
    else
        sb_printf(b, "set terminal dumb nofeed size %d,%d\n", w, h);
    if (fmt == ACBB_PLOT_DUMB) {
        sb_printf(b, "set termoption noenhanced\n");
        return;
    }
    /* Okabe & Ito's colour-blind-safe palette ("Color Universal Design",
     * 2002; yellow swapped for grey, too pale on white), so neighbouring
     * series differ in hue for every reader and in print. */
    static const char *const rgb[8] = { "#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                        "#E69F00", "#56B4E9", "#000000", "#999999" };
    for (int i = 0; i < 8; i++) sb_printf(b, "set linetype %d linecolor rgb '%s'\n", i + 1, rgb[i]);
    sb_printf(b, "set pointsize %.2f\n", em / 20.0);
    sb_printf(b, "set linetype cycle 8\n");
}

/* An image is complete when it ends as its format ends: PNG with the IEND
 * chunk, SVG with </svg> (a full disk leaves neither). */
bool image_complete(int fd, acbb_plot_format fmt)
{
    static const unsigned char iend[8] = { 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82 };
    unsigned char tail[64] = { 0 };
    struct stat st;
    if (fstat(fd, &st) != 0 || st.st_size <= 0) return false;
    off_t from = st.st_size > (off_t)sizeof tail ? st.st_size - (off_t)sizeof tail : 0;
    ssize_t n = pread(fd, tail, sizeof tail, from);
    if (n <= 0) return false;
    if (fmt == ACBB_PLOT_PNG) return n >= 8 && memcmp(tail + n - 8, iend, 8) == 0;
    return memmem(tail, (size_t)n, "</svg>", 6) != NULL;
}

/* gnuplot writes the image to its stdout, which is our temporary file: no
 * file name ever reaches gnuplot's string scanner. */
static acbb_status render_file(const sbuf *b, acbb_plot_format fmt, const char *path,
                               acbb_error *err)
{
    acbb_out *o = NULL;
    acbb_status st = acbb_out_open(path, &o, NULL, err);
    if (st != ACBB_OK) return st;
    gp_io io = { .to_file = true, .file_fd = acbb_out_fd(o) };
    st = run_gnuplot(b, &io, err);
    if (st == ACBB_OK && !image_complete(io.file_fd, fmt))
        st = acbb_error_set(err, ACBB_EIO, "gnuplot did not finish %s (disk full?); "
                            "the old file is kept", path);
    if (st != ACBB_OK) {
        acbb_out_abort(o);
        return st;
    }
    return acbb_out_commit(o, err);
}

acbb_status acbb_plot_check_size(acbb_plot_format fmt, int w, int h, acbb_error *err)
{
    if (fmt == ACBB_PLOT_DUMB) {
        if (w < PLOT_MIN_COLS || h < PLOT_MIN_ROWS || w > PLOT_MAX_CHARS || h > PLOT_MAX_CHARS)
            return acbb_error_set(err, ACBB_EINVAL,
                                  "plot size %dx%d: need %d..%d columns and %d..%d rows", w, h,
                                  PLOT_MIN_COLS, PLOT_MAX_CHARS, PLOT_MIN_ROWS, PLOT_MAX_CHARS);
    } else if (w < PLOT_MIN_PX || h < PLOT_MIN_PX || w > PLOT_MAX_PX || h > PLOT_MAX_PX) {
        return acbb_error_set(err, ACBB_EINVAL, "plot size %dx%d: each side must be %d..%d pixels",
                              w, h, PLOT_MIN_PX, PLOT_MAX_PX);
    }
    return ACBB_OK;
}

acbb_status acbb_plot_file(acbb_plot_kind kind, acbb_plot_format fmt, const char *path,
                           int width, int height, const acbb_plot_data *d, acbb_error *err)
{
    plot_kind_spec spec, *k = &spec;
    acbb_status st = check_data(kind, d, k, err);
    if (st != ACBB_OK) return st;
    if (fmt != ACBB_PLOT_PNG && fmt != ACBB_PLOT_SVG)
        return acbb_error_set(err, ACBB_EINVAL, "plot file format must be png or svg");
    if (!path || !path[0] || has_control_char(path))
        return acbb_error_set(err, ACBB_EINVAL, "plot path is empty or has a control character");
    if ((st = acbb_plot_check_size(fmt, width, height, err))) return st;

    sbuf b = { 0 };
    terminal_line(&b, fmt, width, height);
    st = script_body(&b, k, d, false, width, height, err);
    if (st == ACBB_OK) st = render_file(&b, fmt, path, err);
    free(b.p);
    return st;
}

/* gnuplot 5.4's dumb terminal starts every page with a form feed even with
 * `nofeed`; on a screen or in a file it is noise. */
static void drop_form_feeds(char *text)
{
    char *w = text;
    for (const char *r = text; *r; r++)
        if (*r != '\f') *w++ = *r;
    *w = '\0';
}

acbb_status acbb_plot_dumb(acbb_plot_kind kind, int cols, int rows, const acbb_plot_data *d,
                           char *text, size_t text_len, acbb_error *err)
{
    if (!text || text_len == 0)
        return acbb_error_set(err, ACBB_EINVAL, "dumb plot: no text buffer");
    text[0] = '\0';
    plot_kind_spec spec, *k = &spec;
    acbb_status st = check_data(kind, d, k, err);
    if (st != ACBB_OK) return st;
    if ((st = acbb_plot_check_size(ACBB_PLOT_DUMB, cols, rows, err))) return st;
    sbuf b = { 0 };
    terminal_line(&b, ACBB_PLOT_DUMB, cols, rows);
    st = script_body(&b, k, d, true, cols, rows, err);
    gp_io io = { .out = text, .out_cap = text_len };
    if (st == ACBB_OK) st = run_gnuplot(&b, &io, err);
    if (st != ACBB_OK) text[0] = '\0';
    else drop_form_feeds(text);
    free(b.p);
    return st;
}

/* ---- accuracy versus time (include/acbb/tools/accuracy.h) ---- */

/* log axes cannot show the references' exact zero: they sit on this floor. */
#define ACC_FLOOR_PCT 1e-10

/* The frontier's criterion, max(e_loss, e_T), in %; NaN if undefined. */
static double accuracy_error_pct(const acbb_accuracy_row *r)
{
    if (r->status != ACBB_OK || r->skipped || !isfinite(r->e_loss) || !isfinite(r->e_T))
        return NAN;
    double e = 100.0 * fmax(r->e_loss, r->e_T);
    return e < ACC_FLOOR_PCT ? ACC_FLOOR_PCT : e;
}

/* Datablock $K<k>: wall ms, error %, "label" for each drawable row of
 * knob k. Labels are fixed plan values; a double quote or control
 * character (none expected) would break the datablock and becomes '_'. */
static size_t accuracy_block(sbuf *b, const acbb_accuracy_row *rows, size_t n, int k)
{
    size_t count = 0;
    sb_printf(b, "$K%d << EOD\n", k);
    for (size_t i = 0; i < n; i++) {
        const acbb_accuracy_row *r = &rows[i];
        double y = accuracy_error_pct(r);
        if ((int)r->knob != k || !isfinite(y) || !(r->wall_ms > 0.0)) continue;
        char label[40];
        snprintf(label, sizeof label, "%s", r->value);
        for (char *c = label; *c; c++)
            if (*c == '"' || (unsigned char)*c < 0x20) *c = '_';
        sb_printf(b, "%.17g %.17g \"%s\"\n", r->wall_ms, y, label);
        count++;
    }
    sb_printf(b, "EOD\n");
    return count;
}

/* a marker shape per knob (apart in grey) */
static const int k_marks[8] = { 7, 5, 9, 11, 13, 15, 1, 2 };

static acbb_status accuracy_script(sbuf *b, const acbb_accuracy_row *rows, size_t n,
                                   const char *title, acbb_error *err)
{
    bool used[ACBB_KNOB_COUNT];
    size_t total = 0;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        size_t c = accuracy_block(b, rows, n, k);
        used[k] = c > 0;
        total += c;
    }
    if (total == 0)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy plot: no converged setting to plot");
    char t[640];
    snprintf(t, sizeof t, "%s%smax(loss, T-rise error) vs wall time, one knob at a time, "
             "floor %g %%",
             title && title[0] ? title : "", title && title[0] ? ": " : "", ACC_FLOOR_PCT);
    sb_printf(b, "set title ");
    sb_quoted(b, t);
    sb_printf(b, "\nset xlabel 'median wall time per run (ms)'\n");
    /* short enough for the plot's height at print size; the title and
     * BENCHMARKS.md say what the error is and its floor */
    sb_printf(b, "set ylabel 'error vs the reference (%%)'\n");
    sb_printf(b, "set logscale xy\nset grid\nset format y '%%g'\nset termoption noenhanced\n");
    /* the knobs' points spread over the whole plot and carry labels: the
     * key beside it, where it covers nothing (issue 29 item 9) */
    sb_printf(b, "set key outside right top vertical samplen 2.5\n");
    sb_printf(b, "set arrow from graph 0, first %g to graph 1, first %g nohead dashtype 2\n",
              100.0 * ACBB_ACCURACY_FRONTIER_TOL, 100.0 * ACBB_ACCURACY_FRONTIER_TOL);
    sb_printf(b, "plot ");
    bool first = true;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        if (!used[k]) continue;
        sb_printf(b, "%s$K%d using 1:2 with linespoints linewidth 2 pointtype %d dashtype %d "
                  "linecolor %d title ", first ? "" : ", ", k, k_marks[k % 8], 1 + k % 5, k + 1);
        sb_quoted(b, acbb_accuracy_knob_name((acbb_accuracy_knob)k));
        sb_printf(b, ", $K%d using 1:2:3 with labels offset char 0.6,0.6 left "
                     "textcolor lt %d notitle", k, k + 1);
        first = false;
    }
    sb_printf(b, "\nset output\nexit\n");
    if (b->oom) return acbb_error_set(err, ACBB_ENOMEM, "out of memory building the plot");
    return ACBB_OK;
}

/* Format, path and size of a plot file, checked before any work. */
static acbb_status check_file_args(acbb_plot_format fmt, const char *path, int width,
                                   int height, acbb_error *err)
{
    if (fmt != ACBB_PLOT_PNG && fmt != ACBB_PLOT_SVG)
        return acbb_error_set(err, ACBB_EINVAL, "plot file format must be png or svg");
    if (!path || !path[0] || has_control_char(path))
        return acbb_error_set(err, ACBB_EINVAL, "plot path is empty or has a control character");
    return acbb_plot_check_size(fmt, width, height, err);
}

/* The terminal line, then `body` (already checked), rendered into path. */
static acbb_status render_body(const sbuf *body, acbb_plot_format fmt, const char *path,
                               int width, int height, acbb_error *err)
{
    sbuf b = { 0 };
    terminal_line(&b, fmt, width, height);
    if (sb_reserve(&b, body->n)) {
        memcpy(b.p + b.n, body->p, body->n);
        b.n += body->n;
        b.p[b.n] = '\0';
    }
    acbb_status st = b.oom ? acbb_error_set(err, ACBB_ENOMEM, "out of memory building the plot")
                           : render_file(&b, fmt, path, err);
    free(b.p);
    return st;
}

acbb_status acbb_plot_accuracy_file(const acbb_accuracy_row *rows, size_t n,
                                    acbb_plot_format fmt, const char *path, int width,
                                    int height, const char *title, acbb_error *err)
{
    if (!rows || n == 0)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy plot: no data");
    acbb_status st = check_file_args(fmt, path, width, height, err);
    if (st != ACBB_OK) return st;
    /* The data are checked before a temporary file is made. */
    sbuf body = { 0 };
    st = accuracy_script(&body, rows, n, title, err);
    if (st == ACBB_OK) st = render_body(&body, fmt, path, width, height, err);
    free(body.p);
    return st;
}

/* ---- tornado chart (acbb sensitivity) ---- */

/* Datablock $T: one row per drawable bar, top (largest) first: y, base,
 * low-end value, high-end value, "label". A bar with a non-finite end
 * draws that end at the base (no bar). */
static size_t tornado_block(sbuf *b, const acbb_tornado_bar *bars, size_t n, double base)
{
    size_t count = 0;
    sb_printf(b, "$T << EOD\n");
    for (size_t i = 0; i < n; i++) {
        char label[96];
        snprintf(label, sizeof label, "%s", bars[i].label ? bars[i].label : "?");
        for (char *c = label; *c; c++)
            if (*c == '"' || (unsigned char)*c < 0x20) *c = '_';
        double lo = isfinite(bars[i].lo) ? bars[i].lo : base;
        double hi = isfinite(bars[i].hi) ? bars[i].hi : base;
        sb_printf(b, "%zu %.17g %.17g %.17g \"%s\"\n", n - i, base, lo, hi, label);
        count++;
    }
    sb_printf(b, "EOD\n");
    return count;
}

static acbb_status tornado_script(sbuf *b, const acbb_tornado_bar *bars, size_t n, double base,
                                  const char *title, const char *xlabel, acbb_error *err)
{
    if (!isfinite(base)) return acbb_error_set(err, ACBB_EINVAL, "tornado plot: no base value");
    tornado_block(b, bars, n, base);
    sb_printf(b, "set title ");
    sb_quoted(b, title && title[0] ? title : "sensitivity, one input at a time");
    sb_printf(b, "\nset xlabel ");
    sb_quoted(b, xlabel && xlabel[0] ? xlabel : "metric");
    sb_printf(b, "\nset ytics nomirror\nset grid xtics\nset yrange [0.3:%zu.7]\n", n);
    sb_printf(b, "set style fill solid 0.6 border -1\nset key outside top center horizontal maxrows 1\nset termoption noenhanced\n");
    /* dashed: the scene's value; solid: zero, where the metric changes
     * sign (drawn only when a bar reaches it) */
    double lo = base, hi = base;
    for (size_t i = 0; i < n; i++) {
        if (isfinite(bars[i].lo)) lo = fmin(lo, bars[i].lo), hi = fmax(hi, bars[i].lo);
        if (isfinite(bars[i].hi)) lo = fmin(lo, bars[i].hi), hi = fmax(hi, bars[i].hi);
    }
    sb_printf(b, "set arrow from %.17g, graph 0 to %.17g, graph 1 nohead dashtype 2\n", base, base);
    if (lo <= 0.0 && hi >= 0.0)
        sb_printf(b, "set arrow from 0, graph 0 to 0, graph 1 nohead linewidth 2 "
                     "linecolor 'black'\n");
    sb_printf(b, "plot $T using (($2+$3)/2):1:(($3<$2)?$3:$2):(($3<$2)?$2:$3):($1-0.35):($1+0.35)"
                 ":ytic(5) with boxxyerror linecolor 1 title 'low end of the range', "
                 "$T using (($2+$4)/2):1:(($4<$2)?$4:$2):(($4<$2)?$2:$4):($1-0.35):($1+0.35) "
                 "with boxxyerror linecolor 2 title 'high end of the range'\n");
    sb_printf(b, "set output\nexit\n");
    if (b->oom) return acbb_error_set(err, ACBB_ENOMEM, "out of memory building the plot");
    return ACBB_OK;
}

acbb_status acbb_plot_tornado_file(const acbb_tornado_bar *bars, size_t n, double base,
                                   acbb_plot_format fmt, const char *path, int width,
                                   int height, const char *title, const char *xlabel,
                                   acbb_error *err)
{
    if (!bars || n == 0) return acbb_error_set(err, ACBB_EINVAL, "tornado plot: no data");
    acbb_status st = check_file_args(fmt, path, width, height, err);
    if (st != ACBB_OK) return st;
    sbuf body = { 0 };
    st = tornado_script(&body, bars, n, base, title, xlabel, err);
    if (st == ACBB_OK) st = render_body(&body, fmt, path, width, height, err);
    free(body.p);
    return st;
}
