/* acbb TUI — the accuracy screen's error-vs-time chart: the log-log model
 * of acc_chart.c drawn on the braille/ASCII raster of chart.c. Each knob's
 * settings are joined coarse to fine, each setting is its knob's letter
 * (the frontier picks in reverse video), and the frontier tolerance is a
 * dashed line; every glyph but the braille cells is ASCII, so the C locale
 * and NO_COLOR lose nothing but colour. */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acc_chart.h"
#include "app.h"

#define LABEL_W 7 /* y labels: "1e-10%" + a space */

static const acbb_role series_role[3] = { ACBB_ROLE_SERIES1, ACBB_ROLE_SERIES2, ACBB_ROLE_WARN };

static int is_pick(const acbb_bench_state *s, size_t i)
{
    return s->phase == ACBB_BENCH_DONE && s->picks[s->rows[i].knob] == (long)i;
}

/* The title row: what the axes are, then each knob's letter. All seven
 * knobs' names take 75 columns, so at 80 the title gives way to them. */
static void chart_legend(acbb_app *a, acbb_rect r, const acbb_acc_chart *m)
{
    const char *title = "max(loss,T) error % vs ms, log-log:";
    char items[ACBB_KNOB_COUNT][48];
    int present[ACBB_KNOB_COUNT] = { 0 }, need = 0;
    for (size_t i = 0; i < m->n; i++) present[m->p[i].knob] = 1;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        snprintf(items[k], sizeof items[k], "%c %s ", acbb_acc_knob_letter((acbb_accuracy_knob)k),
                 acbb_accuracy_knob_name((acbb_accuracy_knob)k));
        if (present[k]) need += (int)strlen(items[k]);
    }
    int x = r.x;
    if (need == 0 || (int)strlen(title) + 1 + need <= r.w) {
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%s", title);
        x += (int)strlen(title) + 1;
    }
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        if (!present[k] || x + (int)strlen(items[k]) > r.x + r.w) continue;
        acbb_put(a, r.y, x, r.x + r.w - x, series_role[k % 3], "%s", items[k]);
        x += (int)strlen(items[k]);
    }
}

/* Decade labels on the left: the tolerance and the top first, then any
 * decade with a free row on both sides; the bottom row is the home of
 * exact zeros. Decades are whole numbers, so the ranges' ints are exact. */
static void y_labels(acbb_app *a, acbb_rect r, const acbb_chart *c)
{
    int used[ACBB_CHART_MAX_H] = { 0 };
    int ltol = (int)lround(log10(100.0 * ACBB_ACCURACY_FRONTIER_TOL));
    int order[ACBB_CHART_MAX_H + 2], n = 0;
    order[n++] = ltol;
    order[n++] = (int)c->ymax;
    for (int d = (int)c->ymax - 1; d > (int)c->ymin && n < ACBB_CHART_MAX_H + 2; d--)
        if (d != ltol) order[n++] = d;
    used[c->h - 1] = 1;
    acbb_put(a, r.y + 1 + c->h - 1, r.x, LABEL_W, ACBB_ROLE_NORMAL, "%6s", "0");
    for (int i = 0; i < n; i++) {
        int row, col;
        if (!acbb_chart_locate(c, c->xmin, order[i], &row, &col) || used[row]) continue;
        if (i >= 2 && ((row > 0 && used[row - 1]) || (row + 1 < c->h && used[row + 1]))) continue;
        used[row] = 1;
        char t[16];
        acbb_acc_fmt_pct_decade(order[i], t, sizeof t);
        acbb_put(a, r.y + 1 + row, r.x, LABEL_W, ACBB_ROLE_NORMAL, "%6s", t);
    }
}

static void x_labels(acbb_app *a, acbb_rect r, const acbb_chart *c)
{
    int y = r.y + r.h - 1, last_end = r.x;
    for (int d = (int)c->xmin; d <= (int)c->xmax; d++) {
        int row, col;
        if (!acbb_chart_locate(c, d, c->ymin, &row, &col)) continue;
        char t[16];
        acbb_acc_fmt_ms_decade(d, t, sizeof t);
        int len = (int)strlen(t), x = r.x + LABEL_W + col;
        if (x + len > r.x + r.w) x = r.x + r.w - len;
        if (x < last_end + 1 && d != (int)c->xmin) continue;
        acbb_put(a, y, x, len, ACBB_ROLE_NORMAL, "%s", t);
        last_end = x + len;
    }
}

static void plot_points(acbb_app *a, acbb_rect r, const acbb_acc_chart *m)
{
    acbb_chart *c = &a->chart;
    /* Each knob's settings joined in plan order (coarse to fine). */
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        double xs[ACBB_BENCH_MAX_ROWS], ys[ACBB_BENCH_MAX_ROWS];
        size_t cnt = 0;
        for (size_t i = 0; i < m->n; i++)
            if ((int)m->p[i].knob == k) {
                xs[cnt] = m->p[i].x;
                ys[cnt++] = m->p[i].y;
            }
        acbb_chart_plot(c, xs, ys, cnt, k);
    }
    acbb_chart_blit(a, c, r.y + 1, r.x + LABEL_W, series_role, 3);
}

void acbb_draw_accuracy_chart(acbb_app *a, acbb_rect r, const acbb_bench_state *st)
{
    acbb_acc_chart m;
    if (r.h < 4 || r.w < LABEL_W + 16) return;
    acbb_acc_chart_build(st->rows, st->n, &m);
    chart_legend(a, r, &m);
    if (m.n == 0) {
        acbb_put(a, r.y + 1, r.x + LABEL_W, r.w - LABEL_W, ACBB_ROLE_DIM, "%s",
                 st->phase == ACBB_BENCH_RUNNING ? "(points appear when the plan has run)"
                                                    : "(no errors to plot)");
        return;
    }
    acbb_chart *c = &a->chart;
    acbb_chart_init(c, r.w - LABEL_W, r.h - 2, m.xmin, m.xmax, m.ymin, m.ymax);
    plot_points(a, r, &m);
    /* The tolerance as a dashed line where nothing was drawn. */
    int trow, tcol;
    if (acbb_chart_locate(c, c->xmin, log10(100.0 * ACBB_ACCURACY_FRONTIER_TOL), &trow, &tcol))
        for (int col = 0; col < c->w; col += 2)
            if (c->dots[trow][col] == 0)
                acbb_put(a, r.y + 1 + trow, r.x + LABEL_W + col, 1, ACBB_ROLE_DIM, "-");
    /* Each setting as its knob's letter; frontier picks stand out. */
    for (size_t i = 0; i < m.n; i++) {
        int row, col;
        if (!acbb_chart_locate(c, m.p[i].x, m.p[i].y, &row, &col)) continue;
        int k = (int)m.p[i].knob;
        acbb_role role = is_pick(st, m.p[i].row) ? ACBB_ROLE_SELECTED : series_role[k % 3];
        acbb_put(a, r.y + 1 + row, r.x + LABEL_W + col, 1, role, "%c",
                 acbb_acc_knob_letter((acbb_accuracy_knob)k));
    }
    y_labels(a, r, c);
    x_labels(a, r, c);
}
