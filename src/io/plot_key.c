/* acbb — the key (legend) where it covers no data (issue 21 item 9, issue
 * 29 item 9): inside a corner whose box, sized from the text, holds no
 * point; else the y axis raised until a band at the top is free; else
 * below the plot. */
#include <math.h>
#include <stdlib.h>
#include "plot_priv.h"

void key_pts_add(key_pts *k, double x, double y)
{
    if (!isfinite(x) || !isfinite(y)) return;
    if (k->n == k->cap) {
        size_t cap = k->cap ? 2 * k->cap : 256;
        double *nx = realloc(k->x, cap * sizeof *nx);
        if (!nx) return;
        k->x = nx;
        double *ny = realloc(k->y, cap * sizeof *ny);
        if (!ny) return;
        k->y = ny;
        k->cap = cap;
    }
    k->x[k->n] = x;
    k->y[k->n++] = y;
}

/* ---- the x-y figures' key (issue 29 item 9) ----
 * The key's box from the text size (a row 1.45 em, a character 0.6 em,
 * the sample and margins 4.5 em, and 6 % of the plot around it: gnuplot's
 * own box measured on the seed figures), as fractions of the plot area. */
#define KEY_ROW_EM 1.45
#define KEY_CHAR_EM 0.6
#define KEY_PAD_EM 4.5
#define KEY_MARGIN 0.06

static size_t in_box(const key_pts *k, const xy_layout *L, int corner, double fw, double fh)
{
    size_t n = 0;
    double wx = L->gx1 - L->gx0, wy = L->gy1 - L->gy0;
    for (size_t i = 0; i < k->n; i++) {
        double u = (k->x[i] - L->gx0) / wx, v = (k->y[i] - L->gy0) / wy;
        bool right = u >= 1.0 - fw - KEY_MARGIN, left = u <= fw + KEY_MARGIN;
        bool top = v >= 1.0 - fh - KEY_MARGIN, bottom = v <= fh + KEY_MARGIN;
        n += corner == 0 ? top && right : corner == 1 ? top && left
           : corner == 2 ? bottom && right : bottom && left;
    }
    return n;
}

/* A key of `cols` columns: its box as fractions of the plot area. */
static void key_box(const xy_layout *L, int entries, double chars, int cols, double *fw,
                    double *fh)
{
    int rows = (entries + cols - 1) / cols;
    *fw = cols * (chars * KEY_CHAR_EM + KEY_PAD_EM) * L->em / L->plot_w;
    *fh = (rows * KEY_ROW_EM + 0.8) * L->em / L->plot_h;
}

/* A free corner for a key of 1..3 columns: the corner (0..3), or -1. */
static int free_corner(const key_pts *k, const xy_layout *L, int entries, double chars,
                       int *cols)
{
    for (*cols = 1; *cols <= 3; (*cols)++) {
        double fw, fh;
        key_box(L, entries, chars, *cols, &fw, &fh);
        for (int c = 0; c < 4 && fw < 0.95 && fh < 0.95; c++)
            if (in_box(k, L, c, fw, fh) == 0) return c;
    }
    return -1;
}

void key_place(sbuf *b, key_pts *k, xy_layout *L, int entries, double chars)
{
    static const char *const where[4] = { "top right", "top left", "bottom right", "bottom left" };
    static const char style[] = "opaque nobox samplen 2.5 spacing 1.1 height 0.8";
    int cols = 1, c = free_corner(k, L, entries, chars, &cols);
    double fw = 1.0, fh = 1.0;
    if (c < 0) /* the fewest columns whose rows fit a band at the top */
        for (cols = 1; cols <= 3; cols++) {
            key_box(L, entries, chars, cols, &fw, &fh);
            if (fw < 0.95 && fh <= 0.6) break;
        }
    int rows = (entries + cols - 1) / cols;
    if (c >= 0) {
        sb_printf(b, "set key inside %s %s maxrows %d\n", where[c], style, rows);
    } else if (cols <= 3) {
        /* raise the y axis until the data stay below the key's band */
        axes_fit_y(L, L->gy0 + (L->y1 - L->gy0) / (1.0 - fh - 2.0 * KEY_MARGIN));
        sb_printf(b, "set key inside top right %s maxrows %d\n", style, rows);
    } else { /* below the plot, as many columns as fit */
        /* below, a column needs the label and sample only (the width
         * taken back below) */
        cols = (int)(L->w / ((chars * 0.55 + 2.5) * L->em));
        cols = cols < 1 ? 1 : cols;
        rows = (entries + cols - 1) / cols;
        L->plot_h -= (rows * KEY_ROW_EM + 1.0) * L->em;
        axes_fit_y(L, L->y1);
        /* gnuplot sizes a column by the bytes of its enhanced-text label
         * (markup, UTF-8): with several columns, take back what that adds */
        sb_printf(b, "set key outside below center horizontal nobox samplen 2.5 width %d "
                     "maxcols %d\n", cols > 1 ? -4 : 0, cols);
    }
    free(k->x);
    free(k->y);
    *k = (key_pts){ 0 };
}
