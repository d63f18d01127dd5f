/* The steady solve's relaxation (issue 30 lever 1): the polish's rule
 * (src/run/steady_polish.h) instead of MODEL.md 9's fixed 0.5. The rule
 * itself, judged residual by residual, and the steady solve of the 7008C,
 * whose map contracts about 25x a step: undamped it needs about
 * log(40 K / 1e-7 K) / log(25) = 6 moves plus the three quiet steps,
 * where a fixed 0.5 (gain 0.5 + 0.5 / 25 = 0.52 a step) needed 33. The
 * overshooting case (gain about -1.5) is test_energy_balance's issue 18
 * case, steady solve. */
#include <math.h>
#include "tap.h"
#include "acbb/sim.h"
#include "steady_polish.h"

/* Start undamped; the first two residuals are not judged (the first
 * step changes the map); a residual that grows above the floor after a
 * move at the relaxation in force halves it, one below the floor or one
 * made by an older relaxation does not. */
static void test_rule(void)
{
    acbb_relax_ctl c;
    acbb_relax_start(&c);
    ok(c.relax == 1.0, "starts undamped (%g)", c.relax);
    acbb_relax_judge(&c, 1.0, 1.0, 1e-6);
    acbb_relax_judge(&c, 1.0, 2.0, 1e-6);
    ok(c.relax == 1.0, "the second residual's growth is not judged (%g)", c.relax);
    acbb_relax_judge(&c, 1.0, 3.0, 1e-6);
    ok(c.relax == 0.5, "growth on the third residual halves it (%g)", c.relax);
    acbb_relax_judge(&c, 1.0, 4.0, 1e-6);
    ok(c.relax == 0.5, "growth after a move at the old relaxation is not judged again (%g)",
       c.relax);
    acbb_relax_judge(&c, 0.5, 5.0, 1e-6);
    acbb_relax_judge(&c, 0.5, 6.0, 1e-6);
    ok(c.relax == 0.25, "growth after a move at 0.5 halves again (%g)", c.relax);
    ok(acbb_relax_reject(&c, ACBB_CONTACT_LOST) && c.relax == 0.125,
       "a move that lost the contacts is retried at half the relaxation (%g)", c.relax);
    ok(!acbb_relax_reject(&c, ACBB_CANCELLED) && c.relax == 0.125,
       "a cancelled one is not (%g)", c.relax);
    acbb_relax_ctl d;
    acbb_relax_start(&d);
    for (int k = 1; k <= 5; k++) acbb_relax_judge(&d, 1.0, 1e-7 * k, 1e-6);
    ok(d.relax == 1.0, "growth below the floor is noise, not overshoot (%g)", d.relax);
}

static void test_7008C_steady(void)
{
    acbb_scene s;
    acbb_error err = { "" };
    ok(acbb_scene_load("presets/7008C.ini", &s, &err) == ACBB_OK, "preset: %s", err.msg);
    s.thermal_mode = ACBB_THERMAL_STEADY;
    acbb_sim *sim = NULL;
    acbb_status rc = acbb_sim_create(&s, NULL, &sim, &err);
    if (rc == ACBB_OK) rc = acbb_sim_run(sim);
    acbb_snapshot snap;
    if (sim) acbb_sim_snapshot(sim, &snap);
    ok(rc == ACBB_OK && sim && snap.state == ACBB_RUN_CONVERGED, "7008C steady solve: %s (%s)",
       acbb_status_name(rc), sim ? snap.message : err.msg);
    /* 6 to 8 moves to 1e-7 K, then the three quiet steps */
    ok(sim && snap.iteration <= 12, "7008C steady solve: %ld iterations (fixed 0.5: 33)",
       sim ? snap.iteration : -1L);
    acbb_sim_free(sim);
}

/* The steady solve's first state (at ambient) takes one Level-2 pass: it
 * only starts the iterations, each of which converges its passes (issue
 * 30). The transient's first state is the start of its path: converged
 * (QD_PASSES, until omega_m moves < 1e-9). */
static long setup_passes(int steady)
{
    acbb_scene s;
    acbb_error err = { "" };
    if (acbb_scene_load("presets/7008C.ini", &s, &err) != ACBB_OK) return -1;
    s.thermal_mode = steady ? ACBB_THERMAL_STEADY : ACBB_THERMAL_TRANSIENT;
    acbb_sim *sim = NULL;
    if (acbb_sim_create(&s, NULL, &sim, &err) != ACBB_OK) return -1;
    acbb_snapshot snap;
    acbb_sim_snapshot(sim, &snap);
    acbb_sim_free(sim);
    return snap.work.traction_solves;
}

static void test_setup_passes(void)
{
    long st = setup_passes(1), tr = setup_passes(0);
    ok(st == 1, "steady set-up: one Level-2 pass (%ld)", st);
    ok(tr >= 2, "transient set-up: converged, %ld passes", tr);
}

int main(void)
{
    test_rule();
    test_7008C_steady();
    test_setup_passes();
    return done_testing();
}
