/* Contact spot resistances from moving-heat-source theory
 * (docs/contact_heat.md, src/physics/contact_heat.c): the high-speed
 * constant against its own quadrature and Archard's published 0.31, the
 * moving resistance against a hand evaluation of the formula at a low and
 * a high Peclet number (stationary limit, Pe^-1/2 asymptote), and the
 * 7008C runs with thermal.contact_model = moving: the ball-ring difference
 * shrinks, heat in = heat out, the key's error message. */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "contact_heat.h"
#include "acbb/sim.h"
#include "tap.h"

#define K_STEEL 40.1
#define KAPPA_STEEL (40.1 / (7810.0 * 450.0))   /* 7008C rings and balls, m^2/s */

/* Mean over the unit circle of sqrt(s), s = distance from the leading edge
 * along x: strips across y, each integral (2/3) L^(3/2) exact. */
static double mean_sqrt_s(void)
{
    const int n = 200000;
    double sum = 0.0, dy = 2.0 / n;
    for (int i = 0; i < n; i++) {
        double y = -1.0 + (i + 0.5) * dy, L = 2.0 * sqrt(1.0 - y * y);
        sum += (2.0 / 3.0) * pow(L, 1.5) * dy;
    }
    return sum / M_PI;
}

static void test_fast_constant(void)
{
    /* (2 q / k) sqrt(kappa / (pi v)) <sqrt s> over Q / k = q pi a b / k,
     * circle of radius 1: C = 2 <sqrt s> / pi^(3/2) */
    double C = 2.0 * mean_sqrt_s() / pow(M_PI, 1.5);
    ok(fabs(acbb_spot_c_fast() - C) <= 1e-6 * C,
       "C_inf = %.6f equals the exposure-time quadrature %.6f", acbb_spot_c_fast(), C);
    ok(fabs(acbb_spot_c_fast() - 0.31) <= 0.005 * 0.31,
       "C_inf = %.5f is Archard's (1959) 0.31 (high-speed circular source)",
       acbb_spot_c_fast());
}

/* The formula by hand for a circle of radius a at Peclet number Pe:
 * R0 = 1/(4 k a); R_inf = C / (k a sqrt(2 Pe)); R = (R0^-2 + R_inf^-2)^-1/2. */
static double hand_circle(double a, double Pe, double *R0, double *Rinf)
{
    *R0 = 1.0 / (4.0 * K_STEEL * a);
    *Rinf = 0.309955 / (K_STEEL * a * sqrt(2.0 * Pe));
    return 1.0 / sqrt(1.0 / (*R0 * *R0) + 1.0 / (*Rinf * *Rinf));
}

static double moving_at(double a, double b, double Pe)
{
    double v = 2.0 * KAPPA_STEEL * Pe / b;
    ok(fabs(acbb_spot_peclet(b, KAPPA_STEEL, v) - Pe) <= 1e-12 * Pe, "Pe = v b / (2 kappa) = %g",
       Pe);
    return acbb_spot_r_moving(a, b, K_STEEL, KAPPA_STEEL, v);
}

static void test_limits(void)
{
    const double a = 0.5e-3;
    double R0, Rinf;
    /* low Pe: the stationary spot within (R0/R_inf)^2 / 2 = 7e-5 */
    double hand = hand_circle(a, 1e-4, &R0, &Rinf), R = moving_at(a, a, 1e-4);
    ok(fabs(R - hand) <= 1e-5 * hand, "Pe = 1e-4: R = %.6g K/W, hand %.6g", R, hand);
    ok(fabs(R - R0) <= 1e-4 * R0, "Pe = 1e-4: within 1e-4 of the stationary 1/(4 k a) = %.6g",
       R0);
    /* high Pe: the asymptote C / (k a sqrt(2 Pe)) within 1e-4 */
    hand = hand_circle(a, 1e4, &R0, &Rinf);
    R = moving_at(a, a, 1e4);
    ok(fabs(R - hand) <= 1e-5 * hand, "Pe = 1e4: R = %.6g K/W, hand %.6g", R, hand);
    ok(fabs(R - Rinf) <= 1e-4 * Rinf, "Pe = 1e4: within 1e-4 of Archard's asymptote %.6g", Rinf);
    double R4 = moving_at(a, a, 4e4);
    ok(fabs(R4 / R - 0.5) <= 1e-4, "Pe x4 halves R (Pe^-1/2): ratio %.6f", R4 / R);
    ok(acbb_spot_r_moving(a, a, K_STEEL, KAPPA_STEEL, 0.0) == acbb_spot_r_stationary(a, a, K_STEEL),
       "v = 0: exactly the stationary spot");
    ok(isinf(acbb_spot_r_moving(0.0, a, K_STEEL, KAPPA_STEEL, 20.0)),
       "no contact: infinite (the network caps it)");
    /* ellipse, a across and b along the motion: the fast limit uses b for the
     * passage time and a for the width: C sqrt(kappa/(v b)) / (k a) */
    double v = 20.0, b = 0.15e-3, A = 1.1e-3;
    double fast = 0.309955 * sqrt(KAPPA_STEEL / (v * b)) / (K_STEEL * A);
    ok(fabs(acbb_spot_r_fast(A, b, K_STEEL, KAPPA_STEEL, v) - fast) <= 1e-5 * fast,
       "ellipse 1.1 x 0.15 mm at 20 m/s: fast limit %.5g K/W", fast);
}

static acbb_status run(const char *model, const char *mode, acbb_snapshot *p)
{
    acbb_scene s;
    acbb_error err = { "" };
    char e1[64], e2[64];
    snprintf(e1, sizeof e1, "thermal.contact_model=%s", model);
    snprintf(e2, sizeof e2, "fidelity.thermal_mode=%s", mode);
    const char *e[] = { e1, e2 };
    if (acbb_scene_load("presets/7008C.ini", &s, &err) != ACBB_OK ||
        acbb_scene_apply_edits(&s, e, 2, &err) != ACBB_OK)
        return ACBB_EINVAL;
    acbb_sim *sim = NULL;
    acbb_status rc = acbb_sim_create(&s, NULL, &sim, &err);
    if (rc != ACBB_OK) return rc;
    rc = acbb_sim_run(sim);
    acbb_sim_snapshot(sim, p);
    acbb_sim_free(sim);
    return rc;
}

static double ball_over_rings(const acbb_snapshot *p)
{
    return p->T_ball - fmax(p->T_inner_ring, p->T_outer_ring);
}

static void test_7008c(void)
{
    static acbb_snapshot st, mv;
    const char *modes[] = { "transient", "steady" };
    for (int m = 0; m < 2; m++) {
        ok(run("stationary", modes[m], &st) == ACBB_OK && st.state == ACBB_RUN_CONVERGED,
           "7008C stationary, %s: %s", modes[m], st.message);
        ok(run("moving", modes[m], &mv) == ACBB_OK && mv.state == ACBB_RUN_CONVERGED,
           "7008C moving, %s: %s", modes[m], mv.message);
        ok(fabs(mv.heat_in - mv.heat_out) <= ACBB_BALANCE_TOL * mv.heat_in,
           "7008C moving, %s: %.9g W in = %.9g W out", modes[m], mv.heat_in, mv.heat_out);
        ok(ball_over_rings(&mv) < ball_over_rings(&st) && ball_over_rings(&mv) >= 0.0,
           "7008C %s: ball above the hotter ring %.2f K moving < %.2f K stationary "
           "(ball %.2f / %.2f C, IR %.2f / %.2f C, OR %.2f / %.2f C)", modes[m],
           ball_over_rings(&mv), ball_over_rings(&st), mv.T_ball, st.T_ball, mv.T_inner_ring,
           st.T_inner_ring, mv.T_outer_ring, st.T_outer_ring);
    }
}

static void test_bad_value(void)
{
    acbb_scene s;
    acbb_error err = { "" };
    acbb_scene_default(&s);
    const char *e[] = { "thermal.contact_model=sliding" };
    ok(acbb_scene_apply_edits(&s, e, 1, &err) == ACBB_EINVAL, "contact_model = sliding rejected");
    const char *want = "thermal.contact_model=sliding: thermal.contact_model = sliding: must be "
                       "one of: stationary, moving";
    ok(strcmp(err.msg, want) == 0, "message: \"%s\"", err.msg);
    acbb_scene_default(&s);
    ok(s.contact_model == ACBB_CONTACT_STATIONARY, "default: stationary");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_fast_constant();
    test_limits();
    test_bad_value();
    test_7008c();
    return done_testing();
}
