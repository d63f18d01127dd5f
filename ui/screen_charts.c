/* acbb TUI — history charts of the whole run: temperatures, total loss,
 * and the contact loads of ball 0, against simulated time or iteration. */
#include <math.h>
#include <stdio.h>
#include "screens.h"

extern const acbb_screen acbb_screen_charts;

/* This screen's own state (screens.h state_size). */
typedef struct {
    int by_iteration;              /* x = iteration (1) or simulated time (0, the default) */
    acbb_axis_memo memo[3];        /* each chart's widen-only ranges */
} charts_ui;

static charts_ui *ch(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_charts);
}

static void draw(acbb_app *a)
{
    const int by_time = !ch(a)->by_iteration;
    double x[ACBB_HISTORY_CAP], y[5][ACBB_HISTORY_CAP]; /* 48 kB each: fine on the stack */
    size_t n = a->hist.n;
    for (size_t k = 0; k < n; k++) {
        const acbb_history_point *p = &a->hist.p[k];
        x[k] = by_time ? p->time : (double)p->iteration;
        y[0][k] = p->T_outer_ring;
        y[1][k] = p->T_inner_ring;
        y[2][k] = p->T_ball;
        y[3][k] = p->total;
        y[4][k] = p->Qi;
    }
    double qo[ACBB_HISTORY_CAP];
    for (size_t k = 0; k < n; k++) qo[k] = a->hist.p[k].Qo;
    const double *s0[3] = { y[0], y[1], y[2] }, *s1[1] = { y[3] }, *s2[2] = { y[4], qo };
    const char *n0[3] = { "outer ring", "inner ring", "ball" }, *n1[1] = { "total" },
               *n2[2] = { "Qi", "Qo" };
    const char *titles[3] = { "Temperature", "Total loss", "Contact load, ball 0" };
    const char *units[3] = { "C", "W", "N" };
    const double *const *ser[3] = { s0, s1, s2 };
    const char *const *names[3] = { n0, n1, n2 };
    const int nser[3] = { 3, 1, 2 };
    const char *xunit = by_time ? "s" : "iteration";
    /* The memo key changes with the run and the x mode (i). */
    unsigned long key = a->st.run_id * 2 + (unsigned long)by_time;
    for (int i = 0; i < 3; i++) {
        acbb_chart_spec sp = { .title = titles[i], .yunit = units[i], .xunit = xunit, .x = x,
                               .ys = ser[i], .names = names[i], .nser = nser[i], .n = n,
                               .polish = acbb_app_polished(a),
                               .floor_y = i == 0 ? a->st.scene.ambient_C : NAN,
                               .memo = &ch(a)->memo[i], .memo_key = key };
        acbb_chart_draw(a, a->lay.charts[i], &sp);
    }
}

static int on_key(acbb_app *a, int key)
{
    if (key != 'i') return 0;
    ch(a)->by_iteration = !ch(a)->by_iteration;
    return 1;
}

static const acbb_help_line help[] = {
    { "i", "x axis: time / iteration" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_charts = {
    .name = "Charts", .key = '4', .draw = draw, .on_key = on_key, .help = help,
    .state_size = sizeof(charts_ui),
};
