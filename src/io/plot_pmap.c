/* acbb — the preload window's chart (plot.h: acbb_plot_pmap_chart), one
 * definition for `acbb preload-map --plot` and the TUI's export, so the
 * two never disagree on what is a limit (issue 29 item 9: the grid's
 * bounds drawn as limits read as physics). */
#include <math.h>
#include <stdbool.h>
#include "acbb/tools/plot.h"

void acbb_plot_pmap_chart(const acbb_pmap_opts *o, const acbb_pmap_row *rows, size_t n,
                          acbb_plot_pmap *c, acbb_plot_xy *p)
{
    if (n > ACBB_PMAP_MAX_AXIS) n = ACBB_PMAP_MAX_AXIS;
    for (size_t s = 0; s < n; s++) {
        const acbb_pmap_row *r = &rows[s];
        c->x[s] = r->speed_rpm;
        /* the grid's ends (acbb_pmap_axis k = 0 and n - 1, to rounding) */
        bool lo_edge = fabs(r->lo_N - o->preload_lo) <= 1e-9 * o->preload_lo;
        bool hi_edge = fabs(r->hi_N - o->preload_hi) <= 1e-9 * o->preload_hi;
        bool in = r->lo_N >= 0;
        c->y[ACBB_PLOT_PMAP_FLOOR][s] = in && !lo_edge ? r->lo_N : NAN;
        c->y[ACBB_PLOT_PMAP_CEIL][s] = in && !hi_edge ? r->hi_N : NAN;
        c->y[ACBB_PLOT_PMAP_GRID_LO][s] = in && lo_edge ? r->lo_N : NAN;
        c->y[ACBB_PLOT_PMAP_GRID_HI][s] = in && hi_edge ? r->hi_N : NAN;
    }
    /* label, x, y, n, colour, dash, points (lines with markers / markers only) */
    static const struct { const char *label; int color, dash, points; } look[ACBB_PLOT_PMAP_N] = {
        { "no-skid floor", 1, 1, 1 },
        { "upper limit", 2, 2, 1 },
        { "grid bottom, no skid", 3, 1, 2 },
        { "grid top, no limit", 4, 2, 2 },
    };
    for (int k = 0; k < ACBB_PLOT_PMAP_N; k++)
        c->series[k] = (acbb_plot_series){ look[k].label, c->x, c->y[k], n, look[k].color,
                                           look[k].dash, look[k].points };
    *p = (acbb_plot_xy){ "Preload window per speed", "inner-ring speed (rpm)", "preload (N)",
                         c->series, ACBB_PLOT_PMAP_N };
}
