/* acbb — figure sizes for print (issue 29 item 9): `--size` as pixels
 * ("900x600"), a physical width ("85mm", "8.5cm", "85mmx60mm") or a named
 * journal width ("column": 8.5 cm, "full": 17.5 cm), and the text size that
 * goes with a width. A journal column is 8.5 cm = 241 pt and wants 8-9 pt
 * text, so a figure W pixels wide, printed at column width, needs text
 * 8.5/241 of W high; wider figures (full width and beyond, drawn at
 * 300 dpi) keep 9 pt at 300 dpi, 37.5 px. Physical sizes are drawn at
 * 300 dpi, the usual journal minimum for line art in PNG. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/plot.h"

#define COLUMN_PT 241.0          /* 8.5 cm in points */
#define TEXT_PT 8.5
#define DPI 300.0
#define MAX_FONT_PX (9.0 * DPI / 72.0)
#define MIN_FONT_PX 10.0
#define ASPECT 0.75              /* height / width when only a width is given */

double acbb_plot_font_px(int width)
{
    double px = TEXT_PT * width / COLUMN_PT;
    return px < MIN_FONT_PX ? MIN_FONT_PX : px > MAX_FONT_PX ? MAX_FONT_PX : px;
}

/* "85mm", "8.5cm", "3.3in" -> pixels at 300 dpi; -1 if not a length. */
static int length_px(const char *s, const char **end)
{
    static const struct { const char *unit; double per_in; } u[] = {
        { "mm", 25.4 }, { "cm", 2.54 }, { "in", 1.0 } };
    char *e = NULL;
    errno = 0;
    double v = strtod(s, &e);
    if (errno || e == s || !(v > 0.0) || v > 1000.0) return -1;
    for (size_t i = 0; i < sizeof u / sizeof u[0]; i++)
        if (strncmp(e, u[i].unit, 2) == 0) {
            *end = e + 2;
            return (int)lround(v / u[i].per_in * DPI);
        }
    return -1;
}

static int whole_px(const char *s, const char **end)
{
    char *e = NULL;
    errno = 0;
    long v = strtol(s, &e, 10);
    if (errno || e == s || v < 1 || v > 100000 || (*e == '.' || (*e >= 'a' && *e != 'x')))
        return -1;
    *end = e;
    return (int)v;
}

int acbb_plot_parse_size(const char *text, int *w, int *h)
{
    if (!text) return -1;
    if (strcmp(text, "column") == 0) return *w = 1004, *h = 753, 0;  /* 8.5 x 6.4 cm */
    if (strcmp(text, "full") == 0) return *w = 2067, *h = 1034, 0;   /* 17.5 x 8.75 cm */
    const char *e = text;
    int x = whole_px(text, &e), y;
    if (x > 0) { /* pixels: WxH */
        if (*e != 'x' && *e != 'X') return -1;
        y = whole_px(e + 1, &e);
        if (y < 0 || *e) return -1;
    } else {     /* a width, optionally x a height */
        x = length_px(text, &e);
        if (x < 0) return -1;
        y = (int)lround(ASPECT * x);
        if (*e == 'x' || *e == 'X') y = length_px(e + 1, &e);
        if (y < 0 || *e) return -1;
    }
    *w = x;
    *h = y;
    return 0;
}
