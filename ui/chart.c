/* acbb TUI — chart rasteriser (see chart.h). Hand-written because the
 * curses libraries have no plotting; gnuplot's dumb terminal is used for
 * the export preview, but spawning it ten times a second is too slow. */
#include <math.h>
#include <string.h>
#include "chart.h"

/* Braille dot bits by (dot row 0..3, dot column 0..1), Unicode's order. */
static const unsigned char braille_bit[4][2] = {
    { 0x01, 0x08 }, { 0x02, 0x10 }, { 0x04, 0x20 }, { 0x40, 0x80 } };

void acbb_chart_init(acbb_chart *c, int w, int h, double xmin, double xmax, double ymin,
                     double ymax)
{
    c->w = w < 1 ? 1 : w > ACBB_CHART_MAX_W ? ACBB_CHART_MAX_W : w;
    c->h = h < 1 ? 1 : h > ACBB_CHART_MAX_H ? ACBB_CHART_MAX_H : h;
    if (!(xmax > xmin)) xmax = xmin + 1.0;
    if (!(ymax > ymin)) {
        double mid = ymin, pad = fabs(mid) > 0 ? 0.05 * fabs(mid) : 1.0;
        ymin = mid - pad;
        ymax = mid + pad;
    }
    c->xmin = xmin;
    c->xmax = xmax;
    c->ymin = ymin;
    c->ymax = ymax;
    memset(c->dots, 0, sizeof c->dots);
    memset(c->owner, -1, sizeof c->owner);
    memset(c->seen, 0, sizeof c->seen);
    memset(c->top_s, -1, sizeof c->top_s);
    memset(c->bot_s, -1, sizeof c->bot_s);
}

static void set_dot(acbb_chart *c, int dx, int dy, int series)
{
    /* dy counts from the top dot row. */
    if (dx < 0 || dy < 0 || dx >= 2 * c->w || dy >= 4 * c->h) return;
    int row = dy / 4, col = dx / 2;
    c->dots[row][col] |= braille_bit[dy % 4][dx % 2];
    c->owner[row][col] = (signed char)series;
    c->seen[row][col] |= (unsigned char)(1u << (series & 7));
    int r = dy % 4;
    if (c->top_s[row][col] < 0 || r < c->top_dy[row][col]) {
        c->top_s[row][col] = (signed char)series;
        c->top_dy[row][col] = (unsigned char)r;
    }
    if (c->bot_s[row][col] < 0 || r > c->bot_dy[row][col]) {
        c->bot_s[row][col] = (signed char)series;
        c->bot_dy[row][col] = (unsigned char)r;
    }
}

static int to_dx(const acbb_chart *c, double x)
{
    double f = (x - c->xmin) / (c->xmax - c->xmin);
    return (int)lround(f * (2 * c->w - 1));
}

static int to_dy(const acbb_chart *c, double y)
{
    double f = (y - c->ymin) / (c->ymax - c->ymin);
    return (int)lround((1.0 - f) * (4 * c->h - 1));
}

/* Bresenham between two dots, so steep changes stay connected. */
static void line(acbb_chart *c, int x0, int y0, int x1, int y1, int series)
{
    int dx = x1 > x0 ? x1 - x0 : x0 - x1, sx = x0 < x1 ? 1 : -1;
    int dy = y1 > y0 ? y0 - y1 : y1 - y0, sy = y0 < y1 ? 1 : -1;
    int e = dx + dy, steps = dx - dy + 1; /* dy <= 0 here */
    for (int k = 0; k <= steps; k++) {
        set_dot(c, x0, y0, series);
        if (x0 == x1 && y0 == y1) break;
        int e2 = 2 * e;
        if (e2 >= dy) { e += dy; x0 += sx; }
        if (e2 <= dx) { e += dx; y0 += sy; }
    }
}

void acbb_chart_plot(acbb_chart *c, const double *x, const double *y, size_t n, int series)
{
    int have = 0, px = 0, py = 0;
    for (size_t k = 0; k < n; k++) {
        if (!isfinite(x[k]) || !isfinite(y[k])) { have = 0; continue; }
        /* Clamp far-out values so lround cannot overflow. */
        double yy = fmax(c->ymin - (c->ymax - c->ymin), fmin(y[k], c->ymax + (c->ymax - c->ymin)));
        int qx = to_dx(c, x[k]), qy = to_dy(c, yy);
        if (have) line(c, px, py, qx, qy, series);
        else set_dot(c, qx, qy, series);
        px = qx;
        py = qy;
        have = 1;
    }
}

int acbb_chart_locate(const acbb_chart *c, double x, double y, int *row, int *col)
{
    if (!isfinite(x) || !isfinite(y) || x < c->xmin || x > c->xmax || y < c->ymin || y > c->ymax)
        return 0;
    *row = to_dy(c, y) / 4;
    *col = to_dx(c, x) / 2;
    return 1;
}

int acbb_chart_cell(const acbb_chart *c, int row, int col, int utf8, char *buf)
{
    unsigned char d = c->dots[row][col];
    if (utf8) {
        /* U+2800 + d as UTF-8: E2, A0 + (d >> 6), 80 + (d & 0x3F). */
        if (d == 0) { strcpy(buf, " "); return -1; }
        buf[0] = (char)0xE2;
        buf[1] = (char)(0xA0 | (d >> 6));
        buf[2] = (char)(0x80 | (d & 0x3F));
        buf[3] = '\0';
    } else {
        int top = d & (0x01 | 0x08 | 0x02 | 0x10), bottom = d & (0x04 | 0x20 | 0x40 | 0x80);
        strcpy(buf, top && bottom ? ":" : top ? "'" : bottom ? "." : " ");
    }
    return c->owner[row][col];
}

int acbb_chart_shared(const acbb_chart *c, int row, int col)
{
    unsigned m = c->seen[row][col];
    return (m & (m - 1)) != 0;
}

int acbb_chart_any_shared(const acbb_chart *c)
{
    for (int row = 0; row < c->h; row++)
        for (int col = 0; col < c->w; col++)
            if (acbb_chart_shared(c, row, col)) return 1;
    return 0;
}

int acbb_chart_offset(const acbb_chart *c, int row, int col, int *moved, int *kept)
{
    if (!acbb_chart_shared(c, row, col)) return 0;
    unsigned m = c->seen[row][col];
    int hi = c->top_s[row][col], lo = c->bot_s[row][col], n = 0;
    for (unsigned b = m; b; b &= b - 1) n++;
    if (n != 2 || hi == lo) return 0; /* three curves, or one above and below the other */
    if (row > 0 && c->seen[row - 1][col] == 0) {
        *moved = hi;
        *kept = lo;
        return -1;
    }
    if (row + 1 < c->h && c->seen[row + 1][col] == 0) {
        *moved = lo;
        *kept = hi;
        return 1;
    }
    return 0;
}

const char *acbb_chart_mark(int series)
{
    static const char *const marks[] = { "o", "+", "x", "#" };
    return marks[(series < 0 ? 0 : series) % 4];
}

#define FLAT_REL 1e-6 /* spread / value under which a series is flat */

static double nice_step(double raw)
{
    double p = pow(10.0, floor(log10(raw))), f = raw / p;
    double m = f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 2.5 ? 2.5 : f <= 5.0 ? 5.0 : 10.0;
    return m * p;
}

void acbb_chart_nice(double lo, double hi, int ticks, double *nlo, double *nhi, double *step)
{
    if (!isfinite(lo) || !isfinite(hi)) lo = hi = 0.0;
    if (hi < lo) { double t = lo; lo = hi; hi = t; }
    /* Flat: a band around it. A spread under a millionth of the value is
     * solver noise (a spring pair's preload moves 1e-5 N at 300 N): an
     * axis fitted to it drew the noise as spikes (issue 29 item 6). */
    if (!(hi - lo > FLAT_REL * fmax(1.0, fmax(fabs(lo), fabs(hi))))) {
        double pad = fabs(lo) > 0 ? 0.05 * fabs(lo) : 1.0;
        lo -= pad;
        hi += pad;
    }
    if (ticks < 2) ticks = 2;
    double s = nice_step((hi - lo) / (ticks - 1));
    /* A small tolerance so an end already on a multiple stays put. */
    *nlo = floor(lo / s + 1e-9) * s;
    *nhi = ceil(hi / s - 1e-9) * s;
    *step = s;
}

void acbb_chart_extend(const double *v, size_t n, double *lo, double *hi)
{
    for (size_t k = 0; k < n; k++) {
        if (!isfinite(v[k])) continue;
        if (v[k] < *lo) *lo = v[k];
        if (v[k] > *hi) *hi = v[k];
    }
}
