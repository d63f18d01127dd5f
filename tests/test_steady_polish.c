/* The steady polish's relaxation control (src/run/steady_polish.h, issue
 * 18) on linear fixed-point maps x -> x* + g (x - x*) per component, whose
 * behaviour is known in closed form: undamped Picard contracts iff |g| < 1,
 * relaxation w turns the gain into 1 - w + w g. The sim's own use (the
 * issue's rigid-preload case, gain about -1.5) is in test_hard_cases and
 * test_energy_balance. */
#include <math.h>
#include <string.h>
#include "tap.h"
#include "steady_polish.h"

#define NMAX 2
#define RESOLUTION 1e-7 /* K, the map's resolution passed to the polish */

typedef struct {
    int n;
    double x[NMAX], xs[NMAX], g[NMAX];
    int fail_at;        /* step number that fails with ACBB_CANCELLED; 0 never */
    double jump;        /* added to the fixed point after step 1 (a map change) */
    double noise;       /* the fixed point alternates between two values 2 noise apart */
    int steps;
    double relax_seen[128];
    double move[NMAX]; /* the last undamped move (acbb_polish_turn) */
} linmap;

static acbb_status step(void *ctx, double relax, double *res, double *turn, acbb_error *err)
{
    linmap *m = ctx;
    if (++m->steps == m->fail_at) return acbb_error_set(err, ACBB_CANCELLED, "stopped here");
    m->relax_seen[m->steps < 128 ? m->steps : 127] = relax;
    *res = 0.0;
    if (m->steps == 2) m->xs[0] += m->jump;
    m->xs[0] += (m->steps % 2 ? 2.0 : -2.0) * m->noise;
    double xn[NMAX];
    for (int i = 0; i < m->n; i++) {
        double r = m->g[i] * (m->x[i] - m->xs[i]) + m->xs[i] - m->x[i]; /* F(x) - x */
        *res = fmax(*res, fabs(r));
        xn[i] = m->x[i] + relax * r;
    }
    *turn = acbb_polish_turn(m->move, m->x, xn, relax, m->n);
    memcpy(m->x, xn, sizeof(double) * (size_t)m->n);
    return ACBB_OK;
}

static linmap map1(double g, double x0)
{
    linmap m = { .n = 1, .x = { x0 }, .xs = { 40.0 }, .g = { g } };
    return m;
}

static double dist(const linmap *m)
{
    double d = 0.0;
    for (int i = 0; i < m->n; i++) d = fmax(d, fabs(m->x[i] - m->xs[i]));
    return d;
}

/* A contracting map takes exactly the plain Picard path: relaxation 1 at
 * every step, as many steps as undamped iteration needs to move < 1e-9. */
static void test_contracting_undamped(void)
{
    linmap m = map1(0.5, 40.1);
    acbb_polish_result r;
    acbb_error err = { "" };
    acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    /* residual at step k is 0.1 * 0.5^(k-1) (|g - 1| = 0.5 times the
     * distance 0.1 * 0.5^(k-1)): 0.05 * 0.5^(k-1) < 1e-9 first at k = 27 */
    int want = 1;
    for (double res = 0.05; res >= ACBB_POLISH_TOL_K; res *= 0.5) want++;
    int all_one = 1;
    for (int k = 1; k <= m.steps; k++) all_one = all_one && m.relax_seen[k] == 1.0;
    ok(rc == ACBB_OK && r.relax == 1.0 && all_one && r.iterations == want,
       "g = 0.5: converges undamped in %d steps (plain Picard: %d), relaxation %g", r.iterations,
       want, r.relax);
    ok(dist(&m) < ACBB_POLISH_TOL_K, "g = 0.5: within %g of the fixed point (%.2g)",
       ACBB_POLISH_TOL_K, dist(&m));
}

/* The gain: undamped it grows 1.5x a step; one halving gives
 * 1 - 0.5 + 0.5 (-1.5) = -0.25 and it converges to the resolution. A gain
 * of exactly -1 (a two-state cycle: the residual neither grows nor
 * shrinks) is damped too: w = 0.5 lands on the fixed point at once. */
static void test_gain_below_minus_one(void)
{
    const double gains[] = { -1.5, -4.0, -20.0, -1.0 };
    const double relax[] = { 0.5, 0.25, 1.0 / 16, 0.5 }; /* largest w = 2^-k with |1-w+wg| < 1 */
    for (int k = 0; k < 4; k++) {
        linmap m = map1(gains[k], 40.05);
        acbb_polish_result r;
        acbb_error err = { "" };
        acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
        ok(rc == ACBB_OK && r.relax == relax[k] && r.residual < RESOLUTION,
           "g = %g: converges damped at relaxation %g (want %g), residual %.2g K in %d steps: %s",
           gains[k], r.relax, relax[k], r.residual, r.iterations, rc == ACBB_OK ? "ok" : err.msg);
        /* residual = (1 - g) * distance, below the resolution before the
         * last (contracting) move */
        ok(dist(&m) < RESOLUTION / (1.0 - gains[k]),
           "g = %g: the state is the fixed point to the resolution (%.2g K off)", gains[k],
           dist(&m));
    }
}

/* Two modes, one overshooting (-1.5), one slow (0.6): damping the first
 * slows the second to 1 - 0.5 * 0.4 = 0.8 a step; still converges within
 * the cap. */
static void test_two_modes(void)
{
    linmap m = { .n = 2, .x = { 40.05, 30.2 }, .xs = { 40.0, 30.0 }, .g = { -1.5, 0.6 } };
    acbb_polish_result r;
    acbb_error err = { "" };
    acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    ok(rc == ACBB_OK && r.relax == 0.5 && r.iterations < ACBB_POLISH_ITERS,
       "gains -1.5 and 0.6: converges at relaxation %g in %d steps", r.relax, r.iterations);
}

/* Starting in the noise band (the steady branch of the issue case starts
 * at 1e-8 K): growth below ten resolutions is not judged, so the
 * overshoot grows past 1e-6 first, then is damped. */
static void test_start_below_noise(void)
{
    linmap m = map1(-1.5, 40.0 + 4e-9);
    acbb_polish_result r;
    acbb_error err = { "" };
    acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    int first_damped = 0;
    for (int k = 1; k <= m.steps && !first_damped; k++)
        if (m.relax_seen[k] < 1.0) first_damped = k;
    /* residual 1e-8 * 1.5^(k-1): first above 1e-6 at k = 13, judged there,
     * so step 14 is the first damped one */
    ok(rc == ACBB_OK && r.relax == 0.5 && first_damped == 14,
       "g = -1.5 from 1e-8 K: undamped while in the noise band, first damped step %d (want 14)",
       first_damped);
}

/* The first polish step changes the map (every ball recomputed, a set's
 * resistances synced): a second residual larger than the first is not
 * overshoot, and a contracting map stays undamped. */
static void test_map_change_not_judged(void)
{
    linmap m = map1(0.5, 40.001);
    m.jump = 0.01;
    acbb_polish_result r;
    acbb_error err = { "" };
    acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    ok(rc == ACBB_OK && r.relax == 1.0 && dist(&m) < ACBB_POLISH_TOL_K,
       "g = 0.5, fixed point moved after step 1: converges undamped (relaxation %g), %d steps",
       r.relax, r.iterations);
}

/* A map that cannot resolve its fixed point below its noise: stalled
 * within ten resolutions after the cap is converged (sim: 3e-7 to 2e-6 K
 * at a resolution of 1e-6 K for a 100 mm bore); beyond them it is not. */
static void test_stalled(void)
{
    const double noise[] = { 4e-7, 2e-6 };
    for (int k = 0; k < 2; k++) {
        linmap m = map1(0.5, 40.01);
        m.noise = noise[k];
        acbb_polish_result r;
        acbb_error err = { "" };
        acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
        /* beyond the band the alternation is judged as overshoot and damped */
        ok(r.iterations == ACBB_POLISH_ITERS && (k || r.relax == 1.0)
           && rc == (k ? ACBB_DIVERGED : ACBB_OK),
           "noise %g K, resolution %g K: %s after %d steps (residual %.2g K, relaxation %g)",
           noise[k], RESOLUTION, acbb_status_name(rc), r.iterations, r.residual, r.relax);
    }
}

/* The dynamic level's losses are resolved to its integrator's tolerance
 * (issue 26 item 11, presets/combined-load.ini: windows that differ by
 * 2e-4 K at a spread of 13.4 K, a tolerance of 1.34e-7 K from mech_tol):
 * the polish's resolution follows it, so that noise is within the band;
 * from mech_tol it is taken for overshoot and ends diverged. */
static void test_dynamic_resolution(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    s.model = ACBB_MODEL_QUASI_DYNAMIC;
    s.mech_tol = 1e-8;
    double qd = acbb_polish_loss_rtol(&s);
    s.model = ACBB_MODEL_DYNAMIC;
    double dyn = acbb_polish_loss_rtol(&s);
    s.mech_tol = 1e-3;
    ok(qd == 1e-8 && dyn == 1e-4 && acbb_polish_loss_rtol(&s) == 1e-3,
       "losses resolved to mech_tol, at the dynamic level to at least 1e-4 (%g, %g)", qd, dyn);
    const double T[2] = { 20.0, 33.4 };
    const double rtol[2] = { 1e-8, 1e-4 };
    for (int k = 0; k < 2; k++) {
        linmap m = map1(0.5, 40.01);
        m.noise = 1e-4; /* the fixed point alternates 2e-4 K apart */
        acbb_polish_result r;
        acbb_error err = { "" };
        acbb_status rc = acbb_polish_iterate(step, &m, acbb_polish_resolution(rtol[k], T, 2), &r,
                                             &err);
        ok(rc == (k ? ACBB_OK : ACBB_DIVERGED), "2e-4 K noise over a 13.4 K spread, losses to "
           "%g: %s (residual %.2g K, relaxation %g)", rtol[k], acbb_status_name(rc), r.residual,
           r.relax);
    }
}

/* No relaxation helps a gain above 1 (a monotone runaway) nor one below
 * the floor's reach (-300 needs w < 2/301 < 1/64): ACBB_DIVERGED after the
 * cap, with the residual, never OK. */
static void test_diverged(void)
{
    const double gains[] = { 1.5, -300.0 };
    for (int k = 0; k < 2; k++) {
        linmap m = map1(gains[k], 40.01);
        acbb_polish_result r;
        acbb_error err = { "" };
        acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
        ok(rc == ACBB_DIVERGED && r.iterations == ACBB_POLISH_ITERS
           && r.relax == ACBB_POLISH_RELAX_MIN,
           "g = %g: %s after %d steps at relaxation %g", gains[k], acbb_status_name(rc),
           r.iterations, r.relax);
        char want[200];
        snprintf(want, sizeof want, "the steady iteration did not converge: residual %.3g K after "
                 "100 iterations (relaxation 0.015625, tolerance 1e-07 K)",
                 r.residual);
        ok(strcmp(err.msg, want) == 0, "g = %g: message \"%s\"", gains[k], err.msg);
    }
}

/* The cosine between successive undamped moves, by hand: (1, 0) then
 * (-1, 1) / 0.5 at relaxation 0.5 is -1 / sqrt(2); the first move has
 * nothing to turn from (0). */
static void test_turn(void)
{
    double prev[2] = { 0.0, 0.0 }, T[2] = { 10.0, 20.0 };
    const double T1[2] = { 11.0, 20.0 }, T2[2] = { 10.5, 20.5 };
    double c1 = acbb_polish_turn(prev, T, T1, 1.0, 2);
    double c2 = acbb_polish_turn(prev, T1, T2, 0.5, 2);
    ok(c1 == 0.0 && fabs(c2 + 1.0 / sqrt(2.0)) < 1e-15 && prev[0] == -1.0 && prev[1] == 1.0,
       "turn: first move 0 (%g), then -1/sqrt(2) (%.17g), the undamped move kept", c1, c2);
}

/* A slow overshoot (acbb new 6232 under the reference profile: gain
 * -0.966, the residual shrank 3.4 % a step and was 3.9e-4 K after the
 * cap, undamped): moves that reverse and shrink by more than 1/3 a step,
 * too slowly to reach 1e-9 K within the cap, are damped; one halving
 * gives 1 - 0.5 + 0.5 (-0.966) = 0.017 a step. An overshoot fast enough
 * (-0.5) and a slow monotone approach (+0.966, which damping only slows)
 * keep plain Picard. */
static void test_slow_overshoot(void)
{
    linmap m = map1(-0.966, 40.55);
    acbb_polish_result r;
    acbb_error err = { "" };
    acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    ok(rc == ACBB_OK && r.relax == 0.5 && r.iterations < 20 && dist(&m) < RESOLUTION,
       "g = -0.966: converges at relaxation %g (want 0.5) in %d steps, %.2g K off: %s", r.relax,
       r.iterations, dist(&m), rc == ACBB_OK ? "ok" : err.msg);
    m = map1(-0.5, 40.55);
    rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    int all_one = 1;
    for (int k = 1; k <= m.steps; k++) all_one = all_one && m.relax_seen[k] == 1.0;
    ok(rc == ACBB_OK && all_one && dist(&m) < ACBB_POLISH_TOL_K,
       "g = -0.5: plain Picard to %g K in %d steps (relaxation 1 throughout: %d)",
       ACBB_POLISH_TOL_K, r.iterations, all_one);
    m = map1(0.966, 40.55);
    rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    ok(rc == ACBB_DIVERGED && r.relax == 1.0,
       "g = +0.966: not damped (relaxation %g), %s after %d steps", r.relax,
       acbb_status_name(rc), r.iterations);
}

/* A step that fails ends the polish with its status and message. */
static void test_step_failure(void)
{
    linmap m = map1(-1.5, 40.05);
    m.fail_at = 3;
    acbb_polish_result r;
    acbb_error err = { "" };
    acbb_status rc = acbb_polish_iterate(step, &m, RESOLUTION, &r, &err);
    ok(rc == ACBB_CANCELLED && r.iterations == 2 && strcmp(err.msg, "stopped here") == 0,
       "a failing step: %s after %d steps, \"%s\"", acbb_status_name(rc), r.iterations, err.msg);
}

int main(void)
{
    test_contracting_undamped();
    test_gain_below_minus_one();
    test_two_modes();
    test_start_below_noise();
    test_map_change_not_judged();
    test_stalled();
    test_dynamic_resolution();
    test_diverged();
    test_step_failure();
    test_turn();
    test_slow_overshoot();
    return done_testing();
}
