/* acbb TUI — history charts of the whole run: outer-ring temperature,
 * total loss, and the contact loads of ball 0, against simulated time or
 * iteration. */
#include <stdio.h>
#include "screens.h"

static void draw(acbb_app *a)
{
    double x[ACBB_HISTORY_CAP], t5[ACBB_HISTORY_CAP], tb[ACBB_HISTORY_CAP];
    double tot[ACBB_HISTORY_CAP], qi[ACBB_HISTORY_CAP], qo[ACBB_HISTORY_CAP];
    size_t n = a->hist.n;
    for (size_t k = 0; k < n; k++) {
        const acbb_history_point *p = &a->hist.p[k];
        x[k] = a->chart_by_time ? p->time : (double)p->iteration;
        t5[k] = p->T_outer_ring;
        tb[k] = p->T_ball;
        tot[k] = p->total;
        qi[k] = p->Qi;
        qo[k] = p->Qo;
    }
    char xr[64];
    snprintf(xr, sizeof xr, "  [x: %s 0..%.0f, i toggles]", a->chart_by_time ? "time s" : "iteration",
             n ? x[n - 1] : 0.0);
    char title[3][128];
    snprintf(title[0], sizeof title[0], "Temperature C%s", xr);
    snprintf(title[1], sizeof title[1], "Total loss W");
    snprintf(title[2], sizeof title[2], "Contact load N (ball 0)");
    const double *s0[2] = { t5, tb }, *s1[1] = { tot }, *s2[2] = { qi, qo };
    const char *n0[2] = { "outer ring", "ball" }, *n1[1] = { "total" }, *n2[2] = { "Qi", "Qo" };
    acbb_draw_chart(a, a->lay.charts[0], title[0], x, s0, n0, 2, n);
    acbb_draw_chart(a, a->lay.charts[1], title[1], x, s1, n1, 1, n);
    acbb_draw_chart(a, a->lay.charts[2], title[2], x, s2, n2, 2, n);
}

static int on_key(acbb_app *a, int ch)
{
    if (ch != 'i') return 0;
    a->chart_by_time = !a->chart_by_time;
    return 1;
}

static const acbb_help_line help[] = {
    { "i", "x axis: time / iteration" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_charts = {
    .name = "Charts", .key = '4', .draw = draw, .on_key = on_key, .help = help,
};
