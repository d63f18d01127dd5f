/* acbb — the key (legend) inside the plot where it covers the least data
 * (issue 21 item 9): outside it took a quarter to a third of the width.
 * Of the four corners, the one whose box (40 % of the width, 30 % of the
 * height of the data's range) holds the fewest points; the key is opaque,
 * so a point it still covers is hidden rather than drawn through text;
 * with data in all four, the y range grows on the key's side by what
 * its rows need (at least 30 %). */
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

void key_corner(sbuf *b, key_pts *k, int entries)
{
    static const char *const where[4] = { "top right", "top left", "bottom right", "bottom left" };
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (size_t i = 0; i < k->n; i++) {
        x0 = fmin(x0, k->x[i]), x1 = fmax(x1, k->x[i]);
        y0 = fmin(y0, k->y[i]), y1 = fmax(y1, k->y[i]);
    }
    size_t count[4] = { 0, 0, 0, 0 };
    double wx = x1 > x0 ? x1 - x0 : 1.0, wy = y1 > y0 ? y1 - y0 : 1.0;
    for (size_t i = 0; i < k->n; i++) {
        double u = (k->x[i] - x0) / wx, v = (k->y[i] - y0) / wy;
        int right = u >= 0.6, left = u <= 0.4, top = v >= 0.7, bottom = v <= 0.3;
        count[0] += top && right;
        count[1] += top && left;
        count[2] += bottom && right;
        count[3] += bottom && left;
    }
    int best = 0;
    for (int c = 1; c < 4; c++)
        if (count[c] < count[best]) best = c;
    sb_printf(b, "set key inside %s opaque box samplen 2\n", where[best]);
    /* Data in every corner: room above (or below) the data for the key. */
    if (count[best] > 0) { /* about a twentieth of the height per key row */
        double room = fmin(1.0, fmax(0.3, 0.06 * entries));
        sb_printf(b, best < 2 ? "set offsets 0, 0, graph %g, 0\n" : "set offsets 0, 0, 0, graph %g\n", room);
    }
    free(k->x);
    free(k->y);
    *k = (key_pts){ 0 };
}
