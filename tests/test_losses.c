/* Tests of the contact loss integrals and the drag loss (MODEL.md 6). */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "acbb/losses.h"

static void scene_min(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    s->pitch_diameter = 54e-3;
    s->ball_diameter = 6.35e-3;
    s->n_balls = 21;
    s->mu_bd = 0.1;
    s->hysteresis = 0.007;
    s->drag_cd = 0.45;
    s->loss_shear = s->loss_slip = s->loss_spin = s->loss_rolling = s->loss_drag = true;
    s->ehl_film = false; /* boundary friction only: the integrals have closed forms */
    s->roughness_race = 0.34e-6;
    s->roughness_ball = 0.10e-6;
}

/* A circular contact of radius a carrying Q, with no rolling and no race
 * motion (V = 0 everywhere), spinning at w. */
static acbb_contact_in circle(double Q, double a, double w)
{
    acbb_contact_in c = { 0 };
    c.inner = 0;
    c.Q = Q;
    c.a = c.b = a;
    c.pmax = 3 * Q / (2 * M_PI * a * a);
    c.alpha = 0.3;
    c.f = 0.54;
    c.D = 6.35e-3;
    c.dm = 54e-3;
    c.Rx = 3e-3; c.kappa = 1; c.E_eff = 227.5e9;
    c.spin = w;
    return c;
}

static void test_spin_closed_form(void)
{
    acbb_scene s;
    scene_min(&s);
    acbb_oil_state oil = { 0 };
    double Q = 100, a = 0.5e-3, w = 200;
    acbb_contact_in c = circle(Q, a, w);
    /* Spin friction moment of a Hertz circle: M = (3 pi / 16) mu Q a. */
    double want = w * 3 * M_PI / 16 * s.mu_bd * Q * a;
    double err_prev = 1e9;
    int shrinking = 1;
    int grids[] = { 4, 8, 16, 32, 64 };
    for (int g = 0; g < 5; g++) {
        acbb_quad q;
        acbb_quad_init(&q, grids[g]);
        acbb_contact_loss L;
        ok(acbb_contact_losses(&s, &q, &c, &oil, &L) == ACBB_OK, "losses %dx%d", grids[g], grids[g]);
        double err = fabs(L.P[ACBB_LOSS_SPIN] - want) / want;
        shrinking &= err < err_prev;
        err_prev = err;
        if (grids[g] == 32)
            is_close(L.P[ACBB_LOSS_SPIN], want, 2e-3, 0, "spin loss = w (3 pi/16) mu Q a (32x32)");
        if (grids[g] == 16) {
            ok(L.P[ACBB_LOSS_SLIP] == 0 && L.P[ACBB_LOSS_SHEAR] == 0, "no translational slip -> no P_t, no P_L");
            ok(L.P[ACBB_LOSS_ROLLING] == 0, "no entrainment -> no rolling loss");
        }
    }
    ok(shrinking, "spin loss error shrinks as the grid is refined (last %.2e)", err_prev);
}

static void test_slip_and_rolling(void)
{
    acbb_scene s;
    scene_min(&s);
    acbb_oil_state oil = { 0 };
    acbb_quad q;
    acbb_quad_init(&q, 32);
    acbb_contact_in c = circle(150, 0.6e-3, 0);
    c.a = 1.0e-3; c.b = 0.2e-3;
    c.pmax = 3 * c.Q / (2 * M_PI * c.a * c.b);
    c.race = -700;               /* outer race seen from the orbiting frame */
    c.roll = 6000;
    c.u = 19.0;
    acbb_contact_loss L;
    acbb_contact_losses(&s, &q, &c, &oil, &L);
    /* With boundary friction only, P_t = mu * integral(p |V|) = mu Q slide. */
    is_close(L.P[ACBB_LOSS_SLIP], s.mu_bd * c.Q * L.slide, 2e-3, 0, "P_t = mu Q (pressure-weighted slip)");
    ok(L.slide > 0, "non-zero sliding speed (%.3g m/s)", L.slide);
    double Pr = 4 * s.hysteresis * c.Q * c.a / (3 * M_PI * c.D) * c.u;
    is_close(L.P[ACBB_LOSS_ROLLING], Pr, 1e-12, 0, "P_r = 4 eps Q a u / (3 pi D) (hand value)");
    s.hyst_axis = ACBB_HYST_MINOR;
    acbb_contact_losses(&s, &q, &c, &oil, &L);
    is_close(L.P[ACBB_LOSS_ROLLING], Pr * 0.2, 1e-12, 0, "hysteresis on the minor axis scales with b/a");
    s.loss_slip = s.loss_rolling = s.loss_spin = s.loss_shear = false;
    acbb_contact_losses(&s, &q, &c, &oil, &L);
    ok(L.P[ACBB_LOSS_SLIP] == 0 && L.P[ACBB_LOSS_ROLLING] == 0 && L.P[ACBB_LOSS_SPIN] == 0 && L.P[ACBB_LOSS_SHEAR] == 0, "disabled losses are zero");
}

static void test_slip_field(void)
{
    /* Pure rolling at the centre when the race speeds satisfy the rolling
     * condition; V grows away from the centre (Heathcote slip). */
    acbb_contact_in c = circle(100, 0.5e-3, 0);
    c.a = 1e-7; /* vanishing contact: the surface point at x = 0 is at D/2 */
    double h0 = 0.5 * c.D, rm = 0.5 * c.dm;
    c.race = -600;
    c.roll = -c.race * (rm + h0 * cos(c.alpha)) / h0;
    is_close(acbb_slip_velocity(&c, 0.0), 0.0, 0, 1e-9, "outer contact rolls at x = 0");
    c.a = 1e-3;
    ok(fabs(acbb_slip_velocity(&c, 0.9e-3)) > 1e-3, "Heathcote slip off the centre");
}

static void test_drag(void)
{
    acbb_scene s;
    scene_min(&s);
    acbb_mixture mix = { .rho = 1.128 };
    double wm = 696.0;
    double v = wm * s.pitch_diameter / 2;
    double Fv = 0.5 * s.drag_cd * mix.rho * M_PI * s.ball_diameter * s.ball_diameter / 4 * v * v;
    is_close(acbb_drag_force(&s, &mix, wm), Fv, 1e-12, 0, "drag force = 1/2 Cd rho A v^2");
    is_close(acbb_drag_loss(&s, &mix, wm), 21 * Fv * v, 1e-12, 0, "drag loss = Z F v");
    is_close(acbb_drag_loss(&s, &mix, 0.0), 0.0, 0, 1e-15, "no drag at rest");
}

/* MODEL.md 6 note iii: Petroff's cage-land shear with the 7008C cage
 * (d_c 57.7 mm, d_2 58.1 mm -> c_g 0.2 mm, W_c 10.1 mm). */
static void test_cage(void)
{
    acbb_scene s;
    scene_min(&s);
    s.cage_diameter = 57.7e-3;
    s.outer_land_diameter = 58.1e-3;
    s.cage_width = 10.1e-3;
    acbb_mixture mix = { .eta = 1.9e-5 };
    double wm = 660.0, rc = 28.85e-3;
    double want = 2 * M_PI * 1.9e-5 * rc * rc * rc * 10.1e-3 * wm * wm / 0.2e-3;
    is_close(acbb_cage_loss(&s, &mix, wm), want, 1e-9, 0, "cage loss = 2 pi eta r^3 W w^2 / c_g");
    is_close(acbb_cage_loss(&s, &mix, 2 * wm), 4 * want, 1e-12, 0, "cage loss ~ w^2");
}

/* The loss table: one row per kind, each with a name, symbol, effect switch
 * and exactly one formula; names are unique JSON keys. */
static void test_table(void)
{
    int good = 1;
    for (int k = 0; k < ACBB_LOSS_KINDS; k++) {
        const acbb_loss_desc *d = &acbb_loss_table[k];
        int formulas = (d->point != NULL) + (d->contact != NULL) + (d->bearing != NULL);
        if (!d->name || !d->symbol || !d->label || !d->effect || formulas != 1) good = 0;
        for (int j = 0; j < k && good; j++)
            if (strcmp(d->name, acbb_loss_table[j].name) == 0) good = 0;
    }
    ok(good, "every loss row has names, an effect and exactly one formula; names unique");
    acbb_scene s;
    acbb_scene_default(&s);
    ok(!acbb_loss_enabled(&s, ACBB_LOSS_CAGE) && acbb_loss_enabled(&s, ACBB_LOSS_SHEAR),
       "default scene: the five seed losses on, the cage loss off");
    s.loss_cage = true;
    ok(acbb_loss_enabled(&s, ACBB_LOSS_CAGE), "effects.loss_cage switches it on");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_cage();
    test_table();
    test_spin_closed_form();
    test_slip_and_rolling();
    test_slip_field();
    test_drag();
    return done_testing();
}
