/* acbb TUI — a line chart worth projecting: nice-number axes that only
 * widen during a run (no frame-to-frame jumps), tick labels with units on
 * both axes, full-intensity labels, a legend when there are several
 * series, and the final steady solve drawn as a marked point instead of a
 * last segment that looks like a physical jump (MODEL.md 9: the run ends
 * with a steady polish, not a thermal step). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "app.h"

static const acbb_role series_role[3] = { ACBB_ROLE_SERIES1, ACBB_ROLE_SERIES2, ACBB_ROLE_OK };

/* Decimals that make ticks of `step` distinct (2.5 needs one more). */
static int decimals(double step)
{
    int d = (int)ceil(-log10(step) - 1e-9);
    if (fabs(step / pow(10.0, floor(log10(step))) - 2.5) < 1e-9) d++;
    return d < 0 ? 0 : d > 6 ? 6 : d;
}

/* The axis ranges: nice, and (with a memo of the same key) the union with
 * the last frame's, so they only widen. */
static void ranges(const acbb_chart_spec *sp, int yticks, int xticks, double r[4], double step[2])
{
    double ylo = INFINITY, yhi = -INFINITY, xlo = 0.0, xhi = -INFINITY;
    for (int s = 0; s < sp->nser; s++) acbb_chart_extend(sp->ys[s], sp->n, &ylo, &yhi);
    if (sp->x_fixed) { /* a sweep: its whole range from the first point on */
        xlo = fmin(sp->x0, sp->x1);
        xhi = fmax(sp->x0, sp->x1);
        if (!(xhi > xlo)) xlo -= 0.5, xhi += 0.5;
    } else {
        acbb_chart_extend(sp->x, sp->n, &xlo, &xhi);
    }
    if (!(xhi > xlo)) xhi = xlo + 1.0; /* one point at 0: an axis 0..1, not -1..1 */
    if (isfinite(sp->floor_y)) ylo = fmin(ylo, sp->floor_y), yhi = fmax(yhi, sp->floor_y);
    acbb_axis_memo *m = sp->memo;
    if (m && m->valid && m->key == sp->memo_key) {
        ylo = fmin(ylo, m->r[2]);
        yhi = fmax(yhi, m->r[3]);
        xhi = fmax(xhi, m->r[1]);
    }
    acbb_chart_nice(xlo, xhi, xticks, &r[0], &r[1], &step[0]);
    acbb_chart_nice(ylo, yhi, yticks, &r[2], &r[3], &step[1]);
    if (m) {
        memcpy(m->r, r, sizeof m->r);
        m->key = sp->memo_key;
        m->valid = 1;
    }
}

/* One legend entry: the swatch (a line in colour, the series' mark
 * without; `tight`: one cell of it and one space after the text), then the
 * text. Returns the next column. */
static int legend_item(acbb_app *a, int y, int col, int end, int s, const char *text, int tight)
{
    const char *sw = s < 0 ? ACBB_CHART_SHARED_MARK : a->term.colour ? a->term.g.hline : acbb_chart_mark(s);
    acbb_role role = s < 0 ? ACBB_ROLE_NORMAL : series_role[s % 3];
    acbb_put(a, y, col, 2, role, tight ? "%s" : "%s%s", sw, sw);
    col += tight ? 2 : 3;
    acbb_put(a, y, col, end - col, role, "%s", text);
    return col + (int)strlen(text) + (tight ? 1 : 2);
}

/* Length of the words the names all start with ("bearing " of "bearing 0"
 * and "bearing 1"), 0 if none or only one name. */
static size_t common_words(const char *const *names, int n)
{
    if (n < 2) return 0;
    size_t k = 0, words = 0;
    for (;; k++) {
        char ch = names[0][k];
        for (int s = 1; s < n; s++)
            if (names[s][k] != ch) return words;
        if (ch == '\0') return words;
        if (ch == ' ') words = k + 1;
    }
}

/* The legend's texts at a level: 2 = name and latest value, 1 = name,
 * 0 = the names less their common words (put once before them, *pre).
 * Returns the columns they take after the title. */
static int legend_texts(const acbb_chart_spec *sp, int ns, int level, int shared, char item[3][96],
                        size_t *pre)
{
    *pre = level == 0 ? common_words(sp->names, ns) : 0;
    int swatch = ns > 1 || shared ? 3 - (level == 0) : 0, need = *pre ? (int)*pre : 0;
    for (int s = 0; s < ns; s++) {
        double v = sp->ys[s][sp->n - 1];
        if (level == 2 && isfinite(v)) snprintf(item[s], sizeof item[s], "%s %.2f", sp->names[s], v);
        else snprintf(item[s], sizeof item[s], "%s", sp->names[s] + *pre);
        need += swatch + (int)strlen(item[s]) + 2 - (level == 0);
    }
    return need + (shared ? 9 - 2 * (level == 0) : 0) - 2 + (level == 0);
}

/* Title row: the title with its unit, then a legend naming every series
 * drawn (issue 29 item 4): with each latest value when they all fit, else
 * the names, else the names less their common words; "&& both" where
 * curves share cells (the mark drawn there). */
static void title_row(acbb_app *a, acbb_rect r, const acbb_chart_spec *sp, int shared)
{
    char head[160], item[3][96];
    snprintf(head, sizeof head, "%s [%s]", sp->title, sp->yunit);
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%s", head);
    int col = r.x + (int)strlen(head) + 2, end = r.x + r.w, ns = sp->nser < 3 ? sp->nser : 3;
    if (sp->n == 0) return;
    size_t pre = 0;
    int level = 2;
    for (; level > 0; level--)
        if (col + legend_texts(sp, ns, level, shared, item, &pre) <= end) break;
    if (level == 0) legend_texts(sp, ns, 0, shared, item, &pre);
    int tight = level == 0;
    if (pre) {
        acbb_put(a, r.y, col, end - col, ACBB_ROLE_NORMAL, "%.*s", (int)pre, sp->names[0]);
        col += (int)pre;
    }
    for (int s = 0; s < ns; s++) {
        int w = (ns > 1 || shared ? 3 - tight : 0) + (int)strlen(item[s]);
        if (col + w > end) break;
        if (ns > 1 || shared) col = legend_item(a, r.y, col, end, s, item[s], tight);
        else {
            acbb_put(a, r.y, col, end - col, series_role[0], "%s", item[s]);
            col += (int)strlen(item[s]) + 2;
        }
    }
    if (shared && col + 7 - 2 * tight <= end) legend_item(a, r.y, col, end, -1, "both", tight);
}

/* y tick labels (with unit) down the left, one per distinct row. */
static int y_labels(acbb_app *a, acbb_rect r, const acbb_chart_spec *sp, const double rg[4], double step,
                    int ph)
{
    int d = decimals(step), lw = 0, last = -1;
    char lab[32];
    for (double v = rg[2]; v <= rg[3] + 1e-9 * step; v += step) {
        int n = snprintf(lab, sizeof lab, "%.*f %s", d, v, sp->yunit);
        if (n > lw) lw = n;
    }
    lw += 1;
    for (double v = rg[3]; v >= rg[2] - 1e-9 * step; v -= step) {
        int row = (int)lround((rg[3] - v) / (rg[3] - rg[2]) * (ph - 1));
        if (row == last) continue;
        last = row;
        snprintf(lab, sizeof lab, "%.*f %s", d, v, sp->yunit);
        acbb_put(a, r.y + 1 + row, r.x, lw, ACBB_ROLE_NORMAL, "%*s", lw - 1, lab);
    }
    return lw;
}

/* x tick labels under the plot, the unit at the right end. */
static void x_labels(acbb_app *a, int y, int x0, int pw, const acbb_chart_spec *sp, const double rg[4],
                     double step)
{
    int d = decimals(step), next_free = x0;
    char lab[32];
    int unit_at = x0 + pw - (int)strlen(sp->xunit);
    for (double v = rg[0]; v <= rg[1] + 1e-9 * step; v += step) {
        int col = x0 + (int)lround((v - rg[0]) / (rg[1] - rg[0]) * (pw - 1));
        int n = snprintf(lab, sizeof lab, "%.*f", d, v);
        col -= n / 2;
        if (col < x0) col = x0;
        if (col < next_free || col + n >= unit_at) continue;
        acbb_put(a, y, col, n, ACBB_ROLE_NORMAL, "%s", lab);
        next_free = col + n + 1;
    }
    acbb_put(a, y, unit_at, (int)strlen(sp->xunit), ACBB_ROLE_NORMAL, "%s", sp->xunit);
    if (sp->polish && sp->n > 1 && next_free + 18 < unit_at)
        acbb_put(a, y, unit_at - 18, 17, ACBB_ROLE_NORMAL, "* = steady solve");
}

/* The glyph series s leaves in an empty cell next to a shared one it was
 * moved out of: its mark without colour, else dots on the side facing its
 * curve (the bottom ones above the shared cell, the top ones below). */
static const char *moved_glyph(const acbb_app *a, int s, int dir)
{
    if (!a->term.colour) return acbb_chart_mark(s);
    if (a->term.g.utf8) return dir < 0 ? "\xe2\xa3\x80" : "\xe2\xa0\x89"; /* U+28C0, U+2809 */
    return dir < 0 ? "." : "'";
}

int acbb_chart_blit(acbb_app *a, const acbb_chart *c, int y, int x, const acbb_role *roles, int nroles)
{
    int amp = 0;
    static char glyph[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W][8];
    static signed char who[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W]; /* role index; -1 normal */
    for (int row = 0; row < c->h; row++)
        for (int col = 0; col < c->w; col++) {
            int owner = acbb_chart_cell(c, row, col, a->term.g.utf8, glyph[row][col]);
            /* Without colour the dots cannot say whose they are: the mark does. */
            if (owner >= 0 && !a->term.colour) strcpy(glyph[row][col], acbb_chart_mark(owner));
            who[row][col] = (signed char)owner;
        }
    /* Where several series drew, one colour or mark would hide the others
     * (issue 29 item 5): the upper curve moves a row up (or the lower one
     * down) into an empty cell; where none is free, the shared mark. */
    for (int row = 0; row < c->h; row++)
        for (int col = 0; col < c->w; col++) {
            if (!acbb_chart_shared(c, row, col)) continue;
            int moved, kept, d = acbb_chart_offset(c, row, col, &moved, &kept);
            if (d != 0 && who[row + d][col] < 0) {
                strcpy(glyph[row + d][col], moved_glyph(a, moved, d));
                who[row + d][col] = (signed char)moved;
                who[row][col] = (signed char)kept;
                if (!a->term.colour) strcpy(glyph[row][col], acbb_chart_mark(kept));
            } else {
                strcpy(glyph[row][col], ACBB_CHART_SHARED_MARK);
                who[row][col] = -1;
                amp = 1;
            }
        }
    for (int row = 0; row < c->h; row++) {
        move(y + row, x);
        for (int col = 0; col < c->w; col++) {
            acbb_role_on(a, who[row][col] >= 0 ? roles[who[row][col] % nroles] : ACBB_ROLE_NORMAL);
            addstr(glyph[row][col]);
        }
    }
    acbb_role_on(a, ACBB_ROLE_NORMAL);
    return amp;
}

void acbb_chart_draw(acbb_app *a, acbb_rect r, const acbb_chart_spec *sp)
{
    if (r.h < 4 || r.w < 24) return;
    if (sp->n == 0) {
        title_row(a, r, sp, 0);
        acbb_put(a, r.y + 1, r.x + 2, r.w - 2, ACBB_ROLE_NORMAL, "(no data yet: r starts a run)");
        return;
    }
    int ph = r.h - 2;
    double rg[4], step[2];
    ranges(sp, ph >= 8 ? 5 : ph >= 4 ? 3 : 2, r.w >= 100 ? 8 : 5, rg, step);
    int lw = y_labels(a, r, sp, rg, step[1], ph), pw = r.w - lw;
    acbb_chart *c = &a->chart;
    acbb_chart_init(c, pw, ph, rg[0], rg[1], rg[2], rg[3]);
    /* The steady solve is a point, not the end of the transient's line. */
    size_t line_n = sp->polish && sp->n > 1 ? sp->n - 1 : sp->n;
    for (int s = 0; s < sp->nser; s++) acbb_chart_plot(c, sp->x, sp->ys[s], line_n, s);
    int amp = acbb_chart_blit(a, c, r.y + 1, r.x + lw, series_role, 3);
    title_row(a, r, sp, amp);
    for (int s = 0; sp->polish && s < sp->nser && line_n < sp->n; s++) {
        int row, col;
        if (acbb_chart_locate(c, sp->x[sp->n - 1], sp->ys[s][sp->n - 1], &row, &col))
            acbb_put(a, r.y + 1 + row, r.x + lw + col, 1, series_role[s % 3], "*");
    }
    acbb_role_on(a, ACBB_ROLE_NORMAL);
    x_labels(a, r.y + r.h - 1, r.x + lw, pw, sp, rg, step[0]);
}

/* The Run screen's chart: outer ring, inner ring and ball against time,
 * from ambient up. */
void acbb_draw_temp_chart(acbb_app *a, acbb_rect r)
{
    double x[ACBB_HISTORY_CAP], y[3][ACBB_HISTORY_CAP];
    size_t n = a->hist.n;
    for (size_t k = 0; k < n; k++) {
        x[k] = a->hist.p[k].time;
        y[0][k] = a->hist.p[k].T_outer_ring;
        y[1][k] = a->hist.p[k].T_inner_ring;
        y[2][k] = a->hist.p[k].T_ball;
    }
    const double *ys[3] = { y[0], y[1], y[2] };
    const char *names[3] = { "outer ring", "inner ring", "ball" };
    acbb_chart_spec sp = { .title = "Temperature", .yunit = "C", .xunit = "s", .x = x, .ys = ys,
                           .names = names, .nser = 3, .n = n, .polish = acbb_app_polished(a),
                           .floor_y = a->st.scene.ambient_C, .memo = &a->run_memo,
                           .memo_key = a->st.run_id * 2 + 1 };
    acbb_chart_draw(a, r, &sp);
}
