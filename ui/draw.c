/* acbb TUI — drawing helpers shared by the screens. All drawing goes to
 * stdscr; the frame is erased, drawn, and flushed once by the event loop. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/measure.h"
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

/* Byte length of the next line of at most w columns of s, broken at a
 * space when there is one; *next is where the following line starts. */
static size_t wrap_line(const char *s, int w, const char **next)
{
    size_t n = clip_bytes(s, w);
    if (!s[n]) {
        *next = s + n;
        return n;
    }
    size_t cut = n;
    while (cut > 0 && s[cut] != ' ') cut--;
    if (cut == 0) cut = n; /* one long word: hard break */
    const char *p = s + cut;
    while (*p == ' ') p++;
    *next = p;
    return cut;
}

int acbb_wrap_count(const char *text, int w)
{
    int rows = 0;
    if (w <= 0) return 0;
    for (const char *p = text; *p; rows++) wrap_line(p, w, &p);
    return rows;
}

int acbb_put_wrap(acbb_app *a, int y, int x, int w, int max_rows, acbb_role r, const char *text)
{
    int row = 0;
    if (w <= 0) return 0;
    for (const char *p = text; *p && row < max_rows; row++) {
        const char *next;
        size_t n = wrap_line(p, w, &next);
        /* The last row that fits keeps the rest, marked as cut. */
        if (row == max_rows - 1 && *next) {
            acbb_put(a, y + row, x, w, r, "%.*s%s", (int)clip_bytes(p, w - 1), p, a->term.g.ellipsis);
            return row + 1;
        }
        acbb_put(a, y + row, x, w, r, "%.*s", (int)n, p);
        p = next;
    }
    return row;
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

void acbb_draw_job_line(acbb_app *a, int y, int x, int w, int cancelling, double started_s,
                        size_t done, size_t total, const char *what)
{
    char el[16], left[96];
    acbb_fmt_duration(1e-3 * acbb_now_ms() - started_s, el, sizeof el);
    snprintf(left, sizeof left, "%s %zu/%zu %s ", cancelling ? "cancelling" : "running", done, total,
             what);
    acbb_put(a, y, x, w, cancelling ? ACBB_ROLE_WARN : ACBB_ROLE_OK, "%s", left);
    int bx = x + (int)strlen(left);
    acbb_bar(a, y, bx, 20, total ? (double)done / (double)total : 0.0, ACBB_ROLE_BAR);
    acbb_put(a, y, bx + 21, x + w - bx - 21, ACBB_ROLE_NORMAL, "%s  x/Esc cancels", el);
}
