/* Tests of the coupled stepper on the 7008C scene (MODEL.md 9, 12) and
 * its hard cases (MODEL.md 11). */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "acbb/sim.h"
#include "snapshot_check.h"

#define RPM (M_PI / 30.0)

static acbb_scene base(double rpm, double Fx, int te)
{
    acbb_scene s;
    acbb_scene_default(&s);
    s.inner_speed = rpm * RPM;
    s.axial_load = Fx;
    s.thermal_expansion = te;
    return s;
}


/* Run a scene to its end; returns the final status and fills snap. */
static acbb_status run(const acbb_scene *s, acbb_snapshot *snap, acbb_error *err)
{
    acbb_sim *sim;
    acbb_status rc = acbb_sim_create(s, NULL, &sim, err);
    if (rc != ACBB_OK) return rc;
    rc = acbb_sim_run(sim);
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    return rc;
}

static acbb_snapshot snap_a, snap_b; /* large structs off the stack */

static void test_seed_conclusion_1(void)
{
    double loads[] = { 50, 1000 };
    double Qi[2][2], squeeze[2] = { 0, 0 };
    for (int l = 0; l < 2; l++)
        for (int te = 0; te < 2; te++) {
            acbb_scene s = base(15000, loads[l], te);
            acbb_error err = { "" };
            acbb_status rc = run(&s, &snap_a, &err);
            ok(rc == ACBB_OK && snap_a.state == ACBB_RUN_CONVERGED,
               "15000 rpm, %.0f N, %s converges (%s %s)", loads[l], te ? "TE" : "WTE",
               acbb_status_name(rc), snap_a.message);
            ok(snapshot_plausible(&snap_a, 1),
               "snapshot plausible (temperatures, losses, angles, film)");
            ok(snap_a.T_outer_ring > s.ambient_C + 0.1, "outer ring heats up (%.2f C)",
               snap_a.T_outer_ring);
            double sum = snap_a.losses.P[ACBB_LOSS_SHEAR] + snap_a.losses.P[ACBB_LOSS_SLIP] + snap_a.losses.P[ACBB_LOSS_SPIN]
                       + snap_a.losses.P[ACBB_LOSS_ROLLING] + snap_a.losses.P[ACBB_LOSS_DRAG];
            is_close(snap_a.losses.total, sum, 1e-12, 0, "total = sum of the five losses");
            ok(snap_a.losses.P[ACBB_LOSS_SHEAR] >= 0 && snap_a.losses.P[ACBB_LOSS_SLIP] >= 0 && snap_a.losses.P[ACBB_LOSS_SPIN] >= 0
               && snap_a.losses.P[ACBB_LOSS_ROLLING] >= 0 && snap_a.losses.P[ACBB_LOSS_DRAG] >= 0, "every loss >= 0");
            is_close(snap_a.heat_out, snap_a.heat_in, 1e-6, 0,
                     "steady state: heat in = heat out (1e-6)");
            Qi[l][te] = snap_a.balls[0].Qi;
            /* Net growth of the interference along the contact line: ring
             * growths act radially, ball growth shortens both contacts. */
            if (te)
                squeeze[l] = (snap_a.exp_inner + snap_a.exp_inner_cen - snap_a.exp_outer)
                           * cos(snap_a.balls[0].alpha_i) + 2 * snap_a.exp_ball;
        }
    /* Seed conclusion 1 says TE raises the contact loads. In this model the
     * sign follows the net squeeze: the test checks the mechanism, and the
     * diagnostic says whether the seed's claim holds with the defaults. */
    for (int l = 0; l < 2; l++)
        ok((Qi[l][1] - Qi[l][0]) * squeeze[l] > 0,
           "%.0f N: TE - WTE inner load (%+.3f N) has the sign of the net squeeze (%+.3f um)",
           loads[l], Qi[l][1] - Qi[l][0], squeeze[l] * 1e6);
    printf("# seed conclusion 1 (TE Qi > WTE Qi at 1000 N): %s (TE %.2f N, WTE %.2f N)\n",
           Qi[1][1] > Qi[1][0] ? "held" : "NOT held", Qi[1][1], Qi[1][0]);
    ok(Qi[0][1] > Qi[0][0], "50 N: TE raises the inner load (%.3f > %.3f N)", Qi[0][1], Qi[0][0]);
}

static void test_zero_speed(void)
{
    acbb_scene s = base(0, 500, 1);
    acbb_error err = { "" };
    acbb_status rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_OK && snap_a.state == ACBB_RUN_CONVERGED, "zero speed converges: %s",
       snap_a.message);
    is_close(snap_a.losses.total, 0.0, 0, 1e-12, "zero speed: no loss");
    double dmax = 0;
    for (int i = 0; i < snap_a.n_nodes; i++) dmax = fmax(dmax, fabs(snap_a.T[i] - s.ambient_C));
    is_close(dmax, 0.0, 0, 1e-9, "zero speed: every node at ambient");
}

static void test_steady_mode_matches_transient(void)
{
    acbb_scene s = base(12000, 400, 1);
    acbb_error err = { "" };
    run(&s, &snap_a, &err);
    s.thermal_mode = ACBB_THERMAL_STEADY;
    acbb_status rc = run(&s, &snap_b, &err);
    ok(rc == ACBB_OK, "direct steady mode converges: %s", snap_b.message);
    is_close(snap_b.T_outer_ring, snap_a.T_outer_ring, 1e-6, 1e-6,
             "direct steady = end of the transient (outer ring T)");
    is_close(snap_b.losses.total, snap_a.losses.total, 1e-6, 0,
             "direct steady = end of the transient (total loss)");
    ok(snap_b.iteration < snap_a.iteration, "direct steady needs fewer steps (%ld < %ld)",
       snap_b.iteration, snap_a.iteration);
}

static void test_hard_cases(void)
{
    acbb_error err = { "" };
    /* Light load, high speed (skidding regime of MODEL.md 11). */
    acbb_scene s = base(16000, 50, 1);
    acbb_status rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_OK && snapshot_plausible(&snap_a, 1), "50 N at 16000 rpm: converged, plausible (%s)",
       snap_a.message);
    ok(snap_a.balls[0].alpha_o < snap_a.balls[0].alpha_i,
       "light load, high speed: alpha_o < alpha_i");
    /* ... and with boundary friction only (no EHL film: Lambda -> 0), where
     * the Level-2 traction field is pure stick/slip. */
    s = base(16000, 50, 1);
    s.ehl_film = false;
    rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_OK && snapshot_plausible(&snap_a, 0), "50 N, 16000 rpm, no film: converged (%s)",
       snap_a.message);
    ok(snap_a.losses.P[ACBB_LOSS_SHEAR] == 0 && snap_a.losses.P[ACBB_LOSS_SLIP] > 0,
       "no film: no lubricant shear, asperity slip instead (%.3f W)", snap_a.losses.P[ACBB_LOSS_SLIP]);
    /* Combined load with a load zone. */
    s = base(10000, 600, 1);
    s.radial_load = 1200;
    rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_OK && snapshot_plausible(&snap_a, 1), "combined load converges (%s)",
       snap_a.message);
    ok(snap_a.balls[0].Qi > 3 * snap_a.balls[snap_a.n_balls / 2].Qi,
       "load zone: ball under the load carries > 3x the opposite one");
    /* Runaway: a temperature limit below the steady temperature. */
    s = base(15000, 1000, 1);
    s.temp_limit_C = 30;
    rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_RUNAWAY && snap_a.state == ACBB_RUN_FAILED, "temp limit -> ACBB_RUNAWAY (%s)",
       acbb_status_name(rc));
    has_substr(snap_a.message, "thermal runaway", "runaway message names it");
    ok(snapshot_plausible(&snap_a, 1), "runaway keeps a plausible last good state");
    /* Step limit. */
    s = base(15000, 1000, 1);
    s.max_steps = 3;
    rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_NOT_CONVERGED && snap_a.iteration == 3, "max_steps -> ACBB_NOT_CONVERGED");
    /* Rigid (displacement) preload at high speed: ends with a named status,
     * never NaN. */
    s = base(16000, 0, 1);
    s.preload = ACBB_PRELOAD_DISPLACEMENT;
    s.preload_force = 1000;
    rc = run(&s, &snap_a, &err);
    ok((rc == ACBB_OK || rc == ACBB_RUNAWAY) && snapshot_plausible(&snap_a, 1),
       "rigid preload 1000 N at 16000 rpm: %s, plausible", acbb_status_name(rc));
    ok(snap_a.reaction_x > 1000, "rigid preload: heat and speed raise the axial reaction (%.0f N)",
       snap_a.reaction_x);
    /* 7-node teaching network. */
    s = base(8000, 300, 1);
    s.network = ACBB_NET_7;
    rc = run(&s, &snap_a, &err);
    ok(rc == ACBB_OK && snap_a.n_nodes == 7, "7-node network converges (%s)", snap_a.message);
    is_close(snap_a.heat_out, snap_a.heat_in, 1e-6, 0, "7-node: heat in = heat out");
}

/* MODEL.md section 9: a transient step that moves the total loss by more
 * than 5 % is rejected and retried with half the step; no accepted step
 * may do so unless the step is already at its 0.05 s minimum. A 600 s
 * initial step provokes the rule from the start. */
static void test_step_rejection(void)
{
    acbb_scene s = base(15000, 1000, 1);
    s.time_step = 600;
    acbb_sim *sim;
    acbb_error err = { "" };
    if (acbb_sim_create(&s, NULL, &sim, &err) != ACBB_OK) {
        ok(0, "sim_new: %s", err.msg);
        return;
    }
    acbb_sim_snapshot(sim, &snap_a);
    double prev = snap_a.losses.total, worst = 0.0, first_dt = 0.0;
    int steps = 0;
    while (acbb_sim_state(sim) == ACBB_RUN_RUNNING && steps < 2000) {
        double t0 = snap_a.time;
        acbb_sim_step(sim);
        acbb_sim_snapshot(sim, &snap_a);
        double dt = snap_a.time - t0, change = fabs(snap_a.losses.total - prev) / snap_a.losses.total;
        if (steps == 0) first_dt = dt;
        if (dt > 0.05 + 1e-12 && snap_a.state == ACBB_RUN_RUNNING) worst = fmax(worst, change);
        prev = snap_a.losses.total;
        steps++;
    }
    acbb_sim_free(sim);
    ok(snap_a.state == ACBB_RUN_CONVERGED, "600 s initial step still converges");
    ok(first_dt < 600, "the 600 s first step was cut (accepted %.3g s)", first_dt);
    ok(worst <= 0.05 + 1e-12, "no accepted step above the minimum moved the loss > 5 %% (%.2f %%)",
       100 * worst);
}

static void test_bad_scene(void)
{
    acbb_scene s = base(15000, 1000, 1);
    s.contact_grid = 100;
    acbb_sim *sim = NULL;
    acbb_error err = { "" };
    ok(acbb_sim_create(&s, NULL, &sim, &err) == ACBB_EINVAL, "a scene built in code is validated too");
    has_substr(err.msg, "fidelity.contact_grid = 100", "message names the key and value");
    s = base(15000, 0, 1);
    s.radial_load = 500;
    ok(acbb_sim_create(&s, NULL, &sim, &err) == ACBB_ILL_POSED, "pure radial load is ill-posed");
}

/* The one constructor: opts NULL is the all-zero opts (the default run). */
static void test_null_opts(void)
{
    acbb_scene s = base(15000, 1000, 1);
    s.heating = false; /* isothermal: one mechanics solve, quick */
    acbb_sim *a = NULL, *b = NULL;
    acbb_error err = { "" };
    ok(acbb_sim_create(&s, NULL, &a, &err) == ACBB_OK
       && acbb_sim_create(&s, &(acbb_sim_opts){ 0 }, &b, &err) == ACBB_OK,
       "acbb_sim_create takes opts NULL and all-zero opts (%s)", err.msg);
    if (!a || !b) {
        acbb_sim_free(a);
        acbb_sim_free(b);
        return;
    }
    ok(acbb_sim_run(a) == ACBB_OK && acbb_sim_run(b) == ACBB_OK, "both run");
    acbb_sim_snapshot(a, &snap_a);
    acbb_sim_snapshot(b, &snap_b);
    ok(snap_a.iteration == snap_b.iteration && memcmp(snap_a.T, snap_b.T, sizeof snap_a.T) == 0
       && memcmp(&snap_a.losses, &snap_b.losses, sizeof snap_a.losses) == 0
       && snap_a.stiffness_axial == snap_b.stiffness_axial && snap_a.stiffness_axial > 0,
       "the same run bit for bit, stiffness included (%.4g N/m)", snap_a.stiffness_axial);
    acbb_sim_free(a);
    acbb_sim_free(b);
}

static void test_disabled_effects(void)
{
    /* A scene without the drag effect computes no drag at all. */
    acbb_scene s = base(15000, 1000, 0);
    s.loss_drag = false;
    s.loss_spin = false;
    acbb_error err = { "" };
    run(&s, &snap_a, &err);
    ok(snap_a.losses.P[ACBB_LOSS_DRAG] == 0 && snap_a.losses.P[ACBB_LOSS_SPIN] == 0, "disabled losses are not computed");
    ok(snap_a.losses.total > 0, "the enabled ones still are");
}

/* The sixth loss (MODEL.md 6 iii): off by default and then exactly zero;
 * on, it adds its heat to the cage node and the steady state still
 * balances (heat in = heat out through the fixed nodes). */
static void test_cage_loss(void)
{
    acbb_scene s = base(15000, 1000, 1);
    acbb_error err = { "" };
    run(&s, &snap_a, &err);
    s.loss_cage = true;
    acbb_status rc = run(&s, &snap_b, &err);
    ok(snap_a.losses.P[ACBB_LOSS_CAGE] == 0.0, "cage loss off by default: exactly 0 W");
    ok(rc == ACBB_OK && snap_b.losses.P[ACBB_LOSS_CAGE] > 0.0,
       "cage loss on: %.4g W", snap_b.losses.P[ACBB_LOSS_CAGE]);
    double sum = 0.0;
    for (int k = 0; k < ACBB_LOSS_KINDS; k++) sum += snap_b.losses.P[k];
    is_close(snap_b.losses.total, sum, 1e-12, 0, "total = sum of the six losses");
    is_close(snap_b.heat_out, snap_b.heat_in, 1e-6, 0, "steady state with the cage loss: heat in = out");
    is_close(snap_b.heat_in, snap_b.losses.total, 1e-9, 0, "every loss reaches the network");
    ok(snap_b.T[14] > snap_a.T[14], "the cage node warms (%.3f > %.3f C)", snap_b.T[14], snap_a.T[14]);
}

/* ---- any bearing in any mounting (MODEL.md 8.1, 13 "Surroundings") ---- */

/* is_close with a formatted name. */
static char close_name[200];
#define CLOSE(got, want, rtol, ...) \
    (snprintf(close_name, sizeof close_name, __VA_ARGS__), \
     is_close((got), (want), (rtol), 0, close_name))

/* The 7008C bearing scaled by k = bore / 40 mm (every diameter, radius and
 * width; Z = 21 kept): 70xx proportions. The surroundings are left derived. */
static acbb_scene scaled_7008c(double bore_mm, double Fx, double rpm)
{
    acbb_scene s = base(rpm, Fx, 1);
    double k = bore_mm / 40.0;
    double *dims[] = {&s.pitch_diameter, &s.ball_diameter, &s.inner_groove_radius,
                      &s.outer_groove_radius, &s.bore, &s.outer_diameter, &s.width,
                      &s.cage_width, &s.cage_diameter, &s.inner_land_diameter,
                      &s.outer_land_diameter};
    for (size_t i = 0; i < sizeof dims / sizeof dims[0]; i++) *dims[i] *= k;
    s.max_time = 1e7;   /* thermal time constants grow about as k^2 */
    s.max_steps = 100000;
    return s;
}

/* Bores 10..200 mm run with the derived surroundings. Loads scale with k^2
 * (same contact stress); speeds keep d_m n = 0.81e6 mm rpm up to 100 mm and
 * halve it at 200 mm (25 kN at 3000 rpm runs away, as such a bearing would
 * under oil-air at that load). */
static void test_any_bearing(void)
{
    static const double cases[][3] = {
        {10, 62.5, 60000}, {40, 1000, 15000}, {100, 6250, 6000}, {200, 25000, 1500},
    };
    for (int i = 0; i < 4; i++) {
        acbb_scene s = scaled_7008c(cases[i][0], cases[i][1], cases[i][2]);
        acbb_error err = { "" };
        acbb_status rc = run(&s, &snap_a, &err);
        ok(rc == ACBB_OK && snap_a.state == ACBB_RUN_CONVERGED,
           "bore %g mm, %g N, %g rpm, derived surroundings: converges (%s %s%s)",
           cases[i][0], cases[i][1], cases[i][2], acbb_status_name(rc), snap_a.message, err.msg);
        ok(snapshot_plausible(&snap_a, 1), "bore %g mm: snapshot plausible", cases[i][0]);
        CLOSE(snap_a.heat_out, snap_a.heat_in, 1e-6,
              "bore %g mm: heat in = heat out (%.4g W, 1e-6)", cases[i][0], snap_a.heat_in);
    }
}

/* A convective shaft bore (h = 500 W/m^2K, coolant at ambient) adds a film
 * to the heat path of the shaft, so the shaft and the inner ring run warmer
 * than with the bore held at ambient (MODEL.md 13: the seed's choice is
 * the limit h -> infinity); h = 1e9 W/m^2K reproduces the fixed bore. */
static void test_convective_bore(acbb_network_kind net)
{
    const char *tag = net == ACBB_NET_46 ? "46-node" : "7-node";
    acbb_scene s = base(15000, 1000, 1);
    s.network = net;
    acbb_error err = { "" };
    acbb_status rc = run(&s, &snap_a, &err);
    s.bore_bc.kind = ACBB_BC_CONVECTIVE;
    s.bore_bc.h = 500;
    acbb_status rc2 = run(&s, &snap_b, &err);
    ok(rc == ACBB_OK && rc2 == ACBB_OK && snap_b.state == ACBB_RUN_CONVERGED,
       "%s: fixed and convective (500 W/m^2K) bores converge (%s)", tag, err.msg);
    ok(snap_b.T_shaft > snap_a.T_shaft + 0.1, "%s: convective bore: warmer shaft (%.3f > %.3f C)",
       tag, snap_b.T_shaft, snap_a.T_shaft);
    ok(snap_b.T_inner_ring > snap_a.T_inner_ring, "%s: convective bore: warmer inner ring "
       "(%.3f > %.3f C)", tag, snap_b.T_inner_ring, snap_a.T_inner_ring);
    CLOSE(snap_b.heat_out, snap_b.heat_in, 1e-6, "%s: convective bore: heat in = out", tag);
    s.bore_bc.h = 1e9;
    run(&s, &snap_b, &err);
    double rise_a = snap_a.T_shaft - s.ambient_C, rise_b = snap_b.T_shaft - s.ambient_C;
    CLOSE(rise_b, rise_a, 1e-4, "%s: h = 1e9 W/m^2K: shaft rise equals the fixed bore's "
          "(%.6f vs %.6f K)", tag, rise_b, rise_a);
    CLOSE(snap_b.T_inner_ring - s.ambient_C, snap_a.T_inner_ring - s.ambient_C, 1e-4,
          "%s: h = 1e9 W/m^2K: inner ring rise equals the fixed bore's", tag);
    CLOSE(snap_b.losses.total, snap_a.losses.total, 1e-4,
          "%s: h = 1e9 W/m^2K: total loss equals the fixed bore's", tag);
}

/* acbb_sim_opts.threads (sim.h): the dynamic level spreads a step's
 * distinct balls over that many workers; a pool passes 1. The answer must
 * not depend on it: a combined load (11 distinct balls) driven 3 steps on
 * 1 and on 3 workers gives the same snapshot bit for bit. */
static int stop_after_3(void *ctx, const acbb_sim *sim)
{
    (void)sim;
    return ++*(int *)ctx >= 3;
}

static int dynamic_steps(int threads, acbb_snapshot *snap)
{
    acbb_scene s;
    acbb_scene_default(&s);
    s.model = ACBB_MODEL_DYNAMIC;
    s.contact_grid = 3;
    s.radial_load = 500.0;
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (acbb_sim_create(&s, &(acbb_sim_opts){ .threads = threads }, &sim, &err) != ACBB_OK) {
        printf("# %s\n", err.msg);
        return 0;
    }
    int n = 0;
    acbb_sim_drive(sim, &(acbb_run_ctl){ stop_after_3, &n, NULL });
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    snap->wall_ms = 0.0;
    return n == 3;
}

static void test_threads_option(void)
{
    static acbb_snapshot one, three;
    ok(dynamic_steps(1, &one) && dynamic_steps(3, &three),
       "dynamic combined load: 3 steps on 1 worker and on 3");
    ok(one.iteration == three.iteration && one.iteration > 0, "same steps taken (%ld)",
       (long)one.iteration);
    ok(memcmp(one.T, three.T, sizeof one.T) == 0
       && memcmp(&one.losses, &three.losses, sizeof one.losses) == 0
       && memcmp(one.balls, three.balls, sizeof one.balls) == 0,
       "temperatures, losses and every ball identical bit for bit");
    ok(one.balls[0].Qi != one.balls[5].Qi, "the balls really differ (Qi %.1f vs %.1f N)",
       one.balls[0].Qi, one.balls[5].Qi);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_cage_loss();
    test_seed_conclusion_1();
    test_zero_speed();
    test_steady_mode_matches_transient();
    test_hard_cases();
    test_step_rejection();
    test_bad_scene();
    test_null_opts();
    test_disabled_effects();
    test_any_bearing();
    test_convective_bore(ACBB_NET_46);
    test_convective_bore(ACBB_NET_7);
    test_threads_option();
    return done_testing();
}
