/* acbb TUI — drawing helpers shared by the screens. All drawing goes to
 * stdscr; the frame is erased, drawn, and flushed once by the event loop. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "app.h"

void acbb_role_on(acbb_app *a, acbb_role r)
{
    attrset(a->term.attr[r]);
}

/* Bytes of `s` that make up at most `w` columns (one column per UTF-8
 * character: all our text and glyphs are narrow). */
static size_t clip_bytes(const char *s, int w)
{
    size_t i = 0;
    int cols = 0;
    while (s[i]) {
        if (((unsigned char)s[i] & 0xC0) != 0x80) {
            if (cols == w) break;
            cols++;
        }
        i++;
    }
    return i;
}

static void put_clipped(int y, int x, int w, const char *s)
{
    if (w <= 0) return;
    mvaddnstr(y, x, s, (int)clip_bytes(s, w));
}

void acbb_put(acbb_app *a, int y, int x, int w, acbb_role r, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    acbb_role_on(a, r);
    put_clipped(y, x, w, buf);
    acbb_role_on(a, ACBB_ROLE_NORMAL);
}

void acbb_bar(acbb_app *a, int y, int x, int w, double f, acbb_role r)
{
    if (w <= 0 || !isfinite(f)) return;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    int eighths = (int)lround(f * w * 8);
    acbb_role_on(a, r);
    move(y, x);
    for (int i = 0; i < w; i++) {
        int e = eighths - 8 * i;
        e = e < 0 ? 0 : e > 8 ? 8 : e;
        addstr(a->term.g.eighths[e]);
    }
    acbb_role_on(a, ACBB_ROLE_NORMAL);
}

void acbb_hrule(acbb_app *a, int y, int x, int w)
{
    acbb_role_on(a, ACBB_ROLE_DIM);
    move(y, x);
    for (int i = 0; i < w; i++) addstr(a->term.g.hline);
    acbb_role_on(a, ACBB_ROLE_NORMAL);
}

void acbb_fmt_duration(double s, char *buf, size_t n)
{
    if (!(s >= 0) || !isfinite(s)) snprintf(buf, n, "--");
    else if (s < 60) snprintf(buf, n, "%.1fs", s);
    else if (s < 3600) snprintf(buf, n, "%dm%02ds", (int)(s / 60), (int)fmod(s, 60));
    else snprintf(buf, n, "%dh%02dm", (int)(s / 3600), (int)fmod(s / 60, 60));
}

#define LABEL_W 9 /* y-axis labels: "%8.4g " */

void acbb_draw_chart(acbb_app *a, acbb_rect r, const char *title, const double *x,
                     const double *const *ys, const char *const *names, int nser, size_t n)
{
    static const acbb_role series_role[3] = { ACBB_ROLE_SERIES1, ACBB_ROLE_SERIES2, ACBB_ROLE_WARN };
    if (r.h < 3 || r.w < LABEL_W + 4) return;
    double lo = INFINITY, hi = -INFINITY, xlo = INFINITY, xhi = -INFINITY;
    for (int s = 0; s < nser; s++) acbb_chart_extend(ys[s], n, &lo, &hi);
    acbb_chart_extend(x, n, &xlo, &xhi);

    /* Title row: the name, the latest value of each series, the x range. */
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%s", title);
    int col = r.x + (int)strlen(title) + 2;
    for (int s = 0; s < nser && n > 0; s++) {
        char item[96];
        snprintf(item, sizeof item, "%s %.2f  ", names[s], ys[s][n - 1]);
        if (col + (int)strlen(item) > r.x + r.w) break;
        acbb_put(a, r.y, col, r.w - (col - r.x), series_role[s % 3], "%s", item);
        col += (int)strlen(item);
    }
    if (n == 0 || !isfinite(lo)) {
        acbb_put(a, r.y + 1, r.x + LABEL_W, r.w - LABEL_W, ACBB_ROLE_DIM, "(no data yet)");
        return;
    }
    int ph = r.h - 1, pw = r.w - LABEL_W;
    acbb_chart *c = &a->chart;
    acbb_chart_init(c, pw, ph, xlo, xhi, lo, hi);
    for (int s = 0; s < nser; s++) acbb_chart_plot(c, x, ys[s], n, s);
    acbb_put(a, r.y + 1, r.x, LABEL_W, ACBB_ROLE_DIM, "%8.4g", c->ymax);
    acbb_put(a, r.y + ph, r.x, LABEL_W, ACBB_ROLE_DIM, "%8.4g", c->ymin);
    for (int row = 0; row < c->h; row++) {
        move(r.y + 1 + row, r.x + LABEL_W);
        for (int cc = 0; cc < c->w; cc++) {
            char g[8];
            int owner = acbb_chart_cell(c, row, cc, a->term.g.utf8, g);
            acbb_role_on(a, owner >= 0 ? series_role[owner % 3] : ACBB_ROLE_NORMAL);
            addstr(g);
        }
    }
    acbb_role_on(a, ACBB_ROLE_NORMAL);
}

int acbb_scroll_key(int ch, int page, int n, int *top)
{
    int t = *top;
    switch (ch) {
    case 'j': case KEY_DOWN: t++; break;
    case 'k': case KEY_UP: t--; break;
    case KEY_NPAGE: t += page; break;
    case KEY_PPAGE: t -= page; break;
    case KEY_HOME: t = 0; break;
    default: return 0;
    }
    if (t > n - page) t = n - page;
    if (t < 0) t = 0;
    *top = t;
    return 1;
}
