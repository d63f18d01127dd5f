/* acbb TUI — the overview screen: key temperatures, the five losses,
 * mechanics, and the outer-ring chart. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "acbb/units.h"
#include "screens.h"

static void temps_panel(acbb_app *a, acbb_rect r)
{
    const acbb_snapshot *s = &a->st.snap;
    double amb = a->st.scene.ambient_C;
    const struct { const char *name; double T; } rows[] = {
        { "Outer ring (5)", s->T_outer_ring }, { "Inner ring", s->T_inner_ring },
        { "Ball", s->T_ball }, { "Housing", s->T_housing }, { "Shaft", s->T_shaft },
        { "Oil-air", s->T_cavity },
    };
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Temperature        C   rise(%.0f)", amb);
    double hi = 1.0;
    for (size_t i = 0; i < 6; i++) hi = fmax(hi, rows[i].T - amb);
    for (size_t i = 0; i < 6 && (int)i + 1 < r.h; i++) {
        acbb_put(a, r.y + 1 + (int)i, r.x, r.w, ACBB_ROLE_NORMAL, "%-15s %7.2f %+7.2f",
                 rows[i].name, rows[i].T, rows[i].T - amb);
        acbb_bar(a, r.y + 1 + (int)i, r.x + 32, r.w - 33, (rows[i].T - amb) / hi, ACBB_ROLE_BAR2);
    }
}

/* The rows of the loss table that the scene switches on (or that carry a
 * value, for a run started before an edit), then the total. */
static void losses_panel(acbb_app *a, acbb_rect r)
{
    const acbb_losses *l = &a->st.snap.losses;
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Power loss        W      %%");
    double tot = l->total > 0 ? l->total : 1.0;
    int row = 1;
    for (int k = 0; k < ACBB_LOSS_KINDS && row < r.h; k++) {
        const acbb_loss_desc *d = &acbb_loss_table[k];
        if (!acbb_loss_enabled(&a->ed.scene, (acbb_loss_kind)k) && l->P[k] == 0.0) continue;
        char name[16];
        snprintf(name, sizeof name, "%.7s %s", d->name, d->symbol);
        acbb_put(a, r.y + row, r.x, r.w, ACBB_ROLE_NORMAL, "%-12s %7.2f %6.1f", name, l->P[k],
                 100 * l->P[k] / tot);
        acbb_bar(a, r.y + row, r.x + 28, r.w - 29, l->P[k] / tot, ACBB_ROLE_BAR);
        row++;
    }
    if (row < r.h)
        acbb_put(a, r.y + row, r.x, r.w, ACBB_ROLE_HEADER, "%-12s %7.2f %6.1f", "Total",
                 l->total, 100.0);
}

/* Min and max of a ball quantity over the balls (one ball under pure axial load). */
static void span(const acbb_snapshot *s, size_t off, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < s->n_balls; i++) {
        double v;
        memcpy(&v, (const char *)&s->balls[i] + off, sizeof v);
        *lo = fmin(*lo, v);
        *hi = fmax(*hi, v);
    }
    if (s->n_balls == 0) *lo = *hi = 0.0;
}

static void mech_panel(acbb_app *a, acbb_rect r)
{
    const acbb_snapshot *s = &a->st.snap;
    const char *deg = a->term.g.deg;
    double qi0, qi1, qo0, qo1, ai0, ai1, ao0, ao1;
    span(s, offsetof(acbb_ball_view, Qi), &qi0, &qi1);
    span(s, offsetof(acbb_ball_view, Qo), &qo0, &qo1);
    span(s, offsetof(acbb_ball_view, alpha_i), &ai0, &ai1);
    span(s, offsetof(acbb_ball_view, alpha_o), &ao0, &ao1);
    const double R2D = 1.0 / ACBB_DEG /* deg per rad */, UM = 1e6;
    char item[6][288];
    snprintf(item[0], sizeof item[0], "Qi %.1f..%.1f N  Qo %.1f..%.1f N", qi0, qi1, qo0, qo1);
    snprintf(item[1], sizeof item[1], "a_i %.2f..%.2f%s  a_o %.2f..%.2f%s", ai0 * R2D, ai1 * R2D, deg,
             ao0 * R2D, ao1 * R2D, deg);
    snprintf(item[2], sizeof item[2], "growth um: ball %.2f IR %.2f OR %.2f", s->exp_ball * UM,
             (s->exp_inner + s->exp_inner_cen) * UM, s->exp_outer * UM);
    snprintf(item[3], sizeof item[3], "Fx %.0f N  dx %.2f um  dt %.3g s", s->reaction_x,
             s->delta_x * UM, s->dt);
    snprintf(item[4], sizeof item[4], "heat in %.2f W  out %.2f W", s->heat_in, s->heat_out);
    snprintf(item[5], sizeof item[5], "%s", s->message);
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Mechanics (min..max, %d balls)", s->n_balls);
    /* A tall panel (wide layout) gets one item per row, a short one pairs. */
    int per_row = r.h - 1 >= 6 ? 1 : 2;
    for (int k = 0, row = 1; k < 6 && row < r.h; k += per_row, row++) {
        if (per_row == 1)
            acbb_put(a, r.y + row, r.x, r.w, ACBB_ROLE_NORMAL, "%s", item[k]);
        else
            acbb_put(a, r.y + row, r.x, r.w, ACBB_ROLE_NORMAL, "%-38s  %s", item[k], item[k + 1]);
    }
}

static void chart_panel(acbb_app *a, acbb_rect r)
{
    double x[ACBB_HISTORY_CAP], y[ACBB_HISTORY_CAP];
    size_t n = a->hist.n;
    for (size_t k = 0; k < n; k++) {
        x[k] = a->hist.p[k].time;
        y[k] = a->hist.p[k].T_outer_ring;
    }
    const double *ys[1] = { y };
    const char *names[1] = { "T5" };
    char title[96];
    snprintf(title, sizeof title, "Outer ring C vs time 0..%.0f s", n ? x[n - 1] : 0.0);
    acbb_draw_chart(a, r, title, x, ys, names, 1, n);
}

static void draw(acbb_app *a)
{
    if (!a->st.has_snapshot) {
        acbb_put(a, a->lay.body.y + 1, 2, a->lay.body.w - 4, ACBB_ROLE_ERROR, "%s",
                 a->st.message[0] ? a->st.message : "no simulation yet");
        return;
    }
    temps_panel(a, a->lay.temps);
    losses_panel(a, a->lay.losses);
    mech_panel(a, a->lay.mech);
    chart_panel(a, a->lay.chart);
}

const acbb_screen acbb_screen_run = {
    .name = "Run", .key = '1', .draw = draw,
};
