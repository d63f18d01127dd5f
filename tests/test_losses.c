/* Tests of the contact loss integrals and the drag loss (MODEL.md 6). */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "losses.h"
#include "mechanics.h"

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
    /* Johnson 1985 ch. 9, a sphere rolling: F = (3/16) eps Q b / R_x, b along
     * the rolling direction, R_x = 3 mm here: 3/16 * 0.007 * 150 * 0.2e-3 /
     * 3e-3 = 0.013125 N, times u = 19 m/s = 0.249375 W. */
    s.roll_hyst = ACBB_ROLL_HYST_JOHNSON;
    s.hyst_axis = ACBB_HYST_MAJOR;   /* no effect under johnson */
    acbb_contact_losses(&s, &q, &c, &oil, &L);
    is_close(L.P[ACBB_LOSS_ROLLING], 0.249375 * s.hysteresis / 0.007, 1e-12, 0,
             "P_r Johnson = (3/16) eps Q b u / R_x (hand value 0.249 W at eps 0.007)");
    s.roll_hyst = ACBB_ROLL_HYST_SEED;
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
    /* The quadrature takes a row's slip speed from its mirror row at -x
     * (issue 30): it depends on x through x^2 alone, bit for bit, with
     * and without pivoting. */
    int same = 1;
    for (int pv = 0; pv < 2; pv++) {
        c.pivot = pv ? 2.0 : 0.0;
        for (double x = 0.05e-3; x < 1e-3; x += 0.0937e-3) {
            double p = acbb_slip_speed(&c, x), m = acbb_slip_speed(&c, -x);
            same &= memcmp(&p, &m, sizeof p) == 0 && p > 0.0;
        }
    }
    ok(same, "slip speed at -x = at x, bit for bit (with and without pivot)");
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

/* The loss skip of transient steps (sim.c, LOSS_SKIP_TOL = 3e-4) keeps a
 * ball's losses while its inputs (acbb_ball_inputs: loads, angles, inlet
 * viscosity, speeds) moved less than tol. Its premise, checked here on a
 * lubricated contact at 15000 rpm: moving any one input by tol moves every
 * loss of the contact by at most 3 tol of the contact's total (a kept loss
 * is that close to the recomputed one). */
static acbb_status contact_total(const acbb_scene *s, const acbb_quad *q, const acbb_contact_in *c,
                                 const acbb_oil_state *o, acbb_contact_loss *out, double *tot)
{
    acbb_status rc = acbb_contact_losses(s, q, c, o, out);
    *tot = 0.0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) *tot += out->P[l];
    return rc;
}

static void test_skip_bound(void)
{
    const double tol = 3e-4, wi = 1570.8;
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_quad q;
    acbb_quad_init(&q, s.contact_grid);
    acbb_oil_state oil, o2;
    acbb_oil_at(&s, 40.0, &oil);
    acbb_contact_in c = circle(200.0, 0.4e-3, 350.0);
    c.b = 0.15e-3;
    c.pmax = 3 * c.Q / (2 * M_PI * c.a * c.b);
    c.inner = 1;
    c.roll = 6790.0; /* near rolling: V ~ 0.03 m/s at the centre */
    c.race = 1570.8 - 670.0;
    c.u = 22.0;
    c.omega_m = 670.0;
    c.pivot = 2.0;
    acbb_contact_loss L0, L1;
    double P0, P1, worst = 0.0;
    acbb_status rc = contact_total(&s, &q, &c, &oil, &L0, &P0);
    ok(rc == ACBB_OK && P0 > 0.0 && L0.film.phi_f > 0.0,
       "lubricated inner contact: %.3g W, fluid share %.2f", P0, L0.film.phi_f);
    for (int k = 0; k < 4; k++) {
        acbb_contact_in m = c;
        o2 = oil;
        /* Each input by tol over its weight (acbb_ball_loss_weights). */
        const double *wt = acbb_ball_loss_weights;
        if (k == 0) { /* load: Hertz a, b ~ Q^(1/3), pmax ~ Q^(1/3) */
            double e = tol / wt[0], g = cbrt(1.0 + e);
            m.Q *= 1.0 + e; m.a *= g; m.b *= g; m.pmax *= g;
        } else if (k == 1) {
            m.alpha += tol / wt[2];
        } else if (k == 2) {
            o2.eta0 *= 1.0 + tol / wt[4];
        } else { /* every speed by tol omega_i / weight */
            double dw = tol / wt[6] * wi;
            m.roll += dw; m.race += dw; m.spin += dw; m.pivot += dw; m.omega_m += dw;
        }
        contact_total(&s, &q, &m, &o2, &L1, &P1);
        double w = 0.0;
        for (int l = 0; l < ACBB_LOSS_KINDS; l++)
            w = fmax(w, fabs(L1.P[l] - L0.P[l]) / P0);
        worst = fmax(worst, w);
    }
    /* acbb_ball_moved by hand: Qi +1 % (relative), alpha_o 2e-4 rad (x3),
     * wy 1e-5 omega_i (x100): the largest weighted move is 1e-2. */
    double a[ACBB_BALL_INPUTS] = { 100, 120, 0.3, 0.28, 0.01, 0.012, 0.4, 0.01, 0.0, 0.9 };
    double b[ACBB_BALL_INPUTS];
    memcpy(b, a, sizeof b);
    b[0] = 101.0; b[3] += 2e-4; b[8] = 1e-5;
    is_close(acbb_ball_moved(a, b, NULL), 1e-2, 1e-12, 0,
             "ball inputs moved (unweighted) = 1 % load");
    is_close(acbb_ball_moved(a, b, acbb_ball_loss_weights), 1e-2, 1e-9, 0,
             "ball inputs moved (loss weights) = max(1e-2, 3 x 2e-4, 100 x 1e-5)");
    b[8] = 2e-4;
    is_close(acbb_ball_moved(a, b, acbb_ball_loss_weights), 2e-2, 1e-9, 0,
             "a ball speed move of 2e-4 omega_i weighs 2e-2 for the losses");
    ok(worst <= 3.0 * tol, "an input moved by tol = %.0e (weighted) moves a loss by %.2e of "
       "the contact total (<= 3 tol: a kept loss is within that of the computed)", tol, worst);
}

/* The quadrature copies a node's integrands from its mirror node (the
 * row at -x, the column at -y) when the bits allow it (issue 30). A grid
 * whose negative nodes are moved by 1 ulp has no exact pair of rows or
 * columns left, so each node is evaluated on its own: the losses must
 * agree to rounding (the nodes moved by ~1e-16 relative). */
static void test_mirror_nodes(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_quad q, qb;
    acbb_quad_init(&q, s.contact_grid);
    qb = q;
    for (int k = 0; 2 * k + 1 < qb.n; k++) qb.x[k] = nextafter(qb.x[k], 0.0);
    acbb_oil_state oil;
    acbb_oil_at(&s, 40.0, &oil);
    acbb_contact_in c = circle(200.0, 0.4e-3, 350.0);
    c.b = 0.15e-3;
    c.pmax = 3 * c.Q / (2 * M_PI * c.a * c.b);
    c.inner = 1;
    c.roll = 6790.0;
    c.race = 1570.8 - 670.0;
    c.u = 22.0;
    c.omega_m = 670.0;
    c.pivot = 2.0;
    acbb_contact_loss La, Lb;
    acbb_contact_losses(&s, &q, &c, &oil, &La);
    acbb_contact_losses(&s, &qb, &c, &oil, &Lb);
    double worst = 0.0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        if (La.P[l] != 0.0) worst = fmax(worst, fabs(La.P[l] / Lb.P[l] - 1.0));
    ok(La.P[ACBB_LOSS_SHEAR] > 0.0 && La.P[ACBB_LOSS_SPIN] > 0.0 && worst < 1e-12,
       "mirror nodes copied = every node evaluated (%.1e relative)", worst);
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
    test_skip_bound();
    test_mirror_nodes();
    return done_testing();
}
