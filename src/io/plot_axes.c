/* acbb — the axes of an x-y figure laid out for the text size of print
 * (issue 29 item 9): gnuplot's own tics ignore how wide their labels are,
 * so at 8.5 pt in a column-width figure they ran together. Here the tic
 * step is the smallest 1-2-5 step whose labels fit the plot area at the
 * figure's text size (labels about 0.6 em a character, a gap of 1.5 em;
 * rows 2 em apart), and each axis spans whole steps around the data, so
 * the key's placement (plot_key.c) knows where data are drawn. A quantity
 * that is never negative gets no negative axis. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include "plot_priv.h"

#define CHAR_EM 0.6     /* a digit is about 0.55-0.6 em wide in sans */

/* The number of 1-2-5 steps spanning [lo, hi] with step s. */
static double spans(double lo, double hi, double s) { return ceil(hi / s - 1e-9) - floor(lo / s + 1e-9); }

double nice_step(double lo, double hi, int max_tics)
{
    static const double m[3] = { 1.0, 2.0, 5.0 };
    if (max_tics < 2) max_tics = 2;
    double s = pow(10.0, floor(log10((hi - lo) / max_tics)) - 1.0);
    for (int i = 0; i < 60; i++, s *= 10.0)
        for (int k = 0; k < 3; k++)
            if (spans(lo, hi, m[k] * s) <= max_tics - 1) return m[k] * s;
    return hi - lo;
}

/* The widest tic label of [lo, hi] at step s, in characters. */
static int tic_chars(double lo, double hi, double s)
{
    int w = 1;
    for (double v = floor(lo / s + 1e-9) * s; v <= hi + 0.5 * s; v += s) {
        char t[32];
        snprintf(t, sizeof t, "%g", fabs(v) < 1e-9 * s ? 0.0 : v);
        if ((int)strlen(t) > w) w = (int)strlen(t);
    }
    return w;
}

/* A range with room to draw: a flat series gets +-10 % (or +-1). */
static void widen(double *lo, double *hi)
{
    if (*hi > *lo) return;
    double d = *lo != 0.0 ? 0.1 * fabs(*lo) : 1.0;
    bool positive = *lo >= 0.0;
    *lo -= d;
    *hi += d;
    if (positive && *lo < 0.0) *lo = 0.0;
}

void axes_range(xy_layout *L, const key_pts *k)
{
    L->x0 = L->y0 = INFINITY;
    L->x1 = L->y1 = -INFINITY;
    for (size_t i = 0; i < k->n; i++) {
        L->x0 = fmin(L->x0, k->x[i]), L->x1 = fmax(L->x1, k->x[i]);
        L->y0 = fmin(L->y0, k->y[i]), L->y1 = fmax(L->y1, k->y[i]);
    }
    if (!(L->x0 <= L->x1)) L->x0 = 0.0, L->x1 = 1.0, L->y0 = 0.0, L->y1 = 1.0;
    double x0 = L->x0, x1 = L->x1, y0 = L->y0, y1 = L->y1;
    widen(&x0, &x1);
    widen(&y0, &y1);
    double em = L->em;
    L->plot_h = L->h - (1.5 * L->title_lines + 1.5 + 4.0) * em;
    L->y0 = y0;
    L->y1 = y1;
    axes_fit_y(L, y1);
    L->plot_w = L->w - ((L->ychars * CHAR_EM + 3.2) + 1.5) * em;
    /* x labels: guess their width, then check it with the step chosen */
    int xc = tic_chars(x0, x1, (x1 - x0) / 4.0);
    for (int pass = 0; pass < 2; pass++) {
        L->xs = nice_step(x0, x1, (int)(L->plot_w / ((xc * CHAR_EM + 1.5) * em)) + 1);
        xc = tic_chars(x0, x1, L->xs);
    }
    /* x spans the data (a sweep's 2000..16000 rpm, not 0..20000) */
    L->gx0 = x0;
    L->gx1 = x1;
}

void axes_fit_y(xy_layout *L, double top)
{
    double hi = fmax(L->y1, top);
    L->ys = nice_step(L->y0, hi, (int)(L->plot_h / (2.0 * L->em)) + 1);
    L->gy0 = floor(L->y0 / L->ys + 1e-9) * L->ys;
    L->gy1 = ceil(hi / L->ys - 1e-9) * L->ys;
    L->ychars = tic_chars(L->gy0, L->gy1, L->ys);
}

void axes_emit(sbuf *b, const xy_layout *L)
{
    sb_printf(b, "set xrange [%.17g:%.17g]\nset yrange [%.17g:%.17g]\n", L->gx0, L->gx1, L->gy0,
              L->gy1);
    /* a 1-2-5 step: 15 digits print it exactly (0.2, not 0.20000000000000001) */
    sb_printf(b, "set xtics %.15g\nset ytics %.15g\nset mxtics 2\nset mytics 2\n", L->xs, L->ys);
}

/* Up to three lines of about `per_line` characters, broken at spaces. */
int title_lines(const char *text, double per_line, char lines[3][160])
{
    int n = 0;
    size_t len = strlen(text), at = 0, max = per_line < 10 ? 10 : (size_t)per_line;
    while (at < len && n < 3) {
        size_t cut = len - at;
        if (cut > max && n < 2) {
            cut = max;
            while (cut > 0 && text[at + cut] != ' ') cut--;
            if (cut == 0) cut = max;
        }
        if (cut >= 160) cut = 159;
        memcpy(lines[n], text + at, cut);
        lines[n++][cut] = '\0';
        at += cut;
        while (text[at] == ' ') at++;
    }
    return n;
}
