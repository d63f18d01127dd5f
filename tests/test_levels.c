/* The fidelity ladder (issue 4): every model level converges on the 7008C
 * scene over the seed's load and speed range without NaN; the quasi-
 * dynamic level shows spin at both contacts and omega_y' -> 0 at heavy
 * load; the dynamic level's time-averaged state settles onto the quasi-
 * dynamic one. */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "acbb/sim.h"
#include "snapshot_check.h"

#define RPM (M_PI / 30.0)

static acbb_snapshot snap, ref;

static acbb_status run(acbb_model_level level, double rpm, double Fx, int grid,
                       acbb_thermal_mode mode, acbb_snapshot *out)
{
    acbb_scene s;
    acbb_scene_default(&s);
    s.model = level;
    s.inner_speed = rpm * RPM;
    s.axial_load = Fx;
    s.contact_grid = grid;
    s.thermal_mode = mode;
    acbb_sim *sim;
    acbb_error err = { "" };
    acbb_status rc = acbb_sim_create(&s, NULL, &sim, &err);
    if (rc != ACBB_OK) {
        printf("# %s\n", err.msg);
        return rc;
    }
    rc = acbb_sim_run(sim);
    acbb_sim_snapshot(sim, out);
    acbb_sim_free(sim);
    return rc;
}

static void test_grid(void)
{
    const char *names[] = { "static", "quasi-static", "quasi-dynamic", "dynamic" };
    double loads[] = { 50, 200, 1000 }, speeds[] = { 2000, 8000, 16000 };
    for (int level = 0; level < 4; level++) {
        /* The dynamic level integrates ball motion in time: it runs the
         * direct steady thermal solve on an 8x8 grid to keep the test short. */
        int dyn = level == ACBB_MODEL_DYNAMIC;
        for (int l = 0; l < 3; l++)
            for (int v = 0; v < 3; v++) {
                acbb_status rc = run((acbb_model_level)level, speeds[v], loads[l], dyn ? 8 : 16,
                                     dyn ? ACBB_THERMAL_STEADY : ACBB_THERMAL_TRANSIENT, &snap);
                ok(rc == ACBB_OK && snap.state == ACBB_RUN_CONVERGED
                       && snapshot_plausible(&snap, 1),
                   "%s, %.0f N, %.0f rpm: converged, plausible (%s)", names[level], loads[l],
                   speeds[v], snap.message);
            }
    }
}

static void test_quasi_dynamic_behaviour(void)
{
    run(ACBB_MODEL_QUASI_DYNAMIC, 15000, 1000, 16, ACBB_THERMAL_STEADY, &snap);
    const acbb_ball_view *b = &snap.balls[0];
    ok(fabs(b->spin_o) > 0.1 * fabs(b->spin_i),
       "quasi-dynamic: spin at both contacts (inner %.0f, outer %.0f rad/s)", b->spin_i, b->spin_o);
    ok(fabs(b->omega_y) < 0.01 * fabs(b->omega_x),
       "1000 N: |omega_y'| (%.2f) < 1%% |omega_x'| (%.0f) (MODEL 12 item 17)", b->omega_y,
       b->omega_x);
    double heavy = b->slide_i;
    ok(heavy < 0.1, "1000 N: micro-sliding only (inner slide %.3f m/s < 0.1)", heavy);
    run(ACBB_MODEL_QUASI_STATIC, 15000, 1000, 16, ACBB_THERMAL_STEADY, &ref);
    ok(fabs(ref.balls[0].spin_o) < 1e-6 * fabs(ref.balls[0].spin_i),
       "quasi-static outer race control: no outer spin (the levels differ)");
}

static void test_dynamic_settles_on_quasi_dynamic(void)
{
    run(ACBB_MODEL_QUASI_DYNAMIC, 15000, 1000, 8, ACBB_THERMAL_STEADY, &ref);
    acbb_status rc = run(ACBB_MODEL_DYNAMIC, 15000, 1000, 8, ACBB_THERMAL_STEADY, &snap);
    ok(rc == ACBB_OK, "dynamic 15000 rpm, 1000 N converges");
    /* Stated tolerance: 1e-4 relative on time-averaged speeds and loads. */
    is_close(snap.balls[0].omega_m, ref.balls[0].omega_m, 1e-4, 0,
             "dynamic time-averaged omega_m = quasi-dynamic (1e-4)");
    is_close(snap.balls[0].omega_x, ref.balls[0].omega_x, 1e-4, 0,
             "dynamic time-averaged omega_x' = quasi-dynamic (1e-4)");
    is_close(snap.balls[0].Qi, ref.balls[0].Qi, 1e-4, 0, "dynamic Qi = quasi-dynamic (1e-4)");
    is_close(snap.balls[0].Qo, ref.balls[0].Qo, 1e-4, 0, "dynamic Qo = quasi-dynamic (1e-4)");
    is_close(snap.losses.total, ref.losses.total, 1e-4, 0, "dynamic total loss = quasi-dynamic");
}

/* presets/combined-load.ini at the dynamic level (issue 26 item 11): the
 * polish took its windows' integration noise (2e-4 K, losses resolved to
 * ACBB_DYN_RTOL) for overshoot, damped to the floor and ended diverged. A
 * steady state that converges balances its heat (MODEL.md 12 item 18). */
static void test_combined_load_dynamic(void)
{
    acbb_scene s;
    acbb_error err = { "" };
    acbb_sim *sim = NULL;
    acbb_status rc = acbb_scene_load("presets/combined-load.ini", &s, &err);
    if (rc == ACBB_OK) rc = acbb_scene_set(&s, "fidelity.model", "dynamic", &err);
    if (rc == ACBB_OK) rc = acbb_sim_create(&s, NULL, &sim, &err);
    if (rc == ACBB_OK) {
        rc = acbb_sim_run(sim);
        acbb_sim_snapshot(sim, &snap);
        acbb_sim_free(sim);
    }
    ok(rc == ACBB_OK && snap.state == ACBB_RUN_CONVERGED && snapshot_plausible(&snap, 1),
       "combined-load, dynamic level: converged, plausible (%s)",
       rc == ACBB_OK ? snap.message : err.msg);
    is_close(snap.heat_out, snap.heat_in, ACBB_BALANCE_TOL, 0,
             "combined-load, dynamic level: heat out = heat in (W)");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_combined_load_dynamic();
    test_quasi_dynamic_behaviour();
    test_dynamic_settles_on_quasi_dynamic();
    test_grid();
    return done_testing();
}
