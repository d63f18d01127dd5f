/* Hard operating points (MODEL.md 11) as a suite: each case is the 7008C
 * scene with a few edits and the status physics expects, decided from
 * MODEL.md 11 and the seed, not from what the code happens to give:
 *   converged      a steady state exists and is reached
 *   runaway        heat beyond what the surroundings remove below
 *                  thermal.temp_limit_C (MODEL.md 9 detectors)
 *   ill_posed      no equilibrium can exist (pure radial load on a single
 *                  force-preloaded ACBB, MODEL.md 11)
 *   invalid        the scene contradicts itself (scene rules)
 *   not_converged  the step budget ends first
 * Every case also: no NaN/Inf in any double of the snapshot (walked field
 * by field), and a bound on its cost that holds on any machine: the step
 * budget, and at most WORK_BOUND work units (acbb_accuracy_work_units,
 * millions of instructions from the deterministic work counters; the wall
 * time is only reported, issue 16 item 6).
 * Usage: test_hard_cases [--slow]: without it the fast cases (default
 * suite, a few seconds), with it the dynamic-level ones (test hard_cases_dynamic). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "acbb/tools/accuracy.h"
#include "acbb/tools/measure.h"
#include "acbb/scene.h"
#include "acbb/sim.h"

#define MAX_EDITS 9
/* 30 G instructions' worth (the old bound was 30 s of wall time). Measured
 * (2026-11): the fast cases take at most 240 units (moment 20 N m), the
 * dynamic ones 4354 and 11376 (light-load skid). */
#define WORK_BOUND 30000.0

typedef struct {
    const char *name;
    const char *edits[MAX_EDITS];
    const char *expect;
    int slow;
    const char *todo;      /* a known engine error, reported as TAP TODO */
} hard_case;

static const hard_case cases[] = {
    { "zero axial load", { "operating.axial_load_N=0" }, "converged", 0, NULL },
    { "tiny axial load 1e-5 N", { "operating.axial_load_N=1e-5" }, "converged", 0, NULL },
    { "tiny axial load 1e-3 N", { "operating.axial_load_N=1e-3" }, "converged", 0, NULL },
    { "tiny axial load 1e-5 N at 0 rpm", { "operating.axial_load_N=1e-5",
      "operating.inner_speed_rpm=0" }, "converged", 0, NULL },
    { "zero speed", { "operating.inner_speed_rpm=0" }, "converged", 0, NULL },
    { "1 rpm", { "operating.inner_speed_rpm=1" }, "converged", 0, NULL },
    { "60000 rpm at 1000 N (n dm 3.2e6)", { "operating.inner_speed_rpm=60000" },
      "runaway", 0, NULL },
    { "60000 rpm at 50 N", { "operating.inner_speed_rpm=60000", "operating.axial_load_N=50" },
      "runaway", 0, NULL },
    { "light-load skid 16000 rpm, 50 N", { "operating.inner_speed_rpm=16000",
      "operating.axial_load_N=50" }, "converged", 0, NULL },
    { "pure radial 500 N, force preload", { "operating.axial_load_N=0",
      "operating.radial_load_N=500" }, "ill_posed", 0, NULL },
    { "pure radial 500 N, displacement preload", { "operating.axial_load_N=0",
      "operating.radial_load_N=500", "mounting.preload=displacement" }, "converged", 0, NULL },
    { "radial 500 N at 0 rpm, displacement preload", { "operating.inner_speed_rpm=0",
      "operating.axial_load_N=0", "operating.radial_load_N=500",
      "mounting.preload=displacement" }, "converged", 0, NULL },
    { "combined 1000 N axial + 500 N radial", { "operating.radial_load_N=500" },
      "converged", 0, NULL },
    { "huge axial 20 kN at 15000 rpm", { "operating.axial_load_N=20000" }, "runaway", 0, NULL },
    { "huge axial 20 kN at 100 rpm", { "operating.axial_load_N=20000",
      "operating.inner_speed_rpm=100" }, "converged", 0, NULL },
    { "moment 5 N m with 1000 N", { "operating.moment_load_Nm=5" }, "converged", 0, NULL },
    { "moment 20 N m with 1000 N (needs 926 N of thrust)", { "operating.moment_load_Nm=20" },
      "converged", 0, NULL },
    /* A moment without enough thrust: every Q sin(alpha) of the loaded side
     * pushes the same way, as for a pure radial load (scene_rules.c). */
    { "moment 200 N m with 100 N at 15000 rpm", { "operating.moment_load_Nm=200",
      "operating.axial_load_N=100" }, "ill_posed", 0, NULL },
    { "moment 50 N m, no axial load", { "operating.moment_load_Nm=50",
      "operating.axial_load_N=0" }, "ill_posed", 0, NULL },
    { "moment 20 N m, no axial load, displacement preload, 6000 rpm", {
      "operating.moment_load_Nm=20", "operating.axial_load_N=0", "mounting.preload=displacement",
      "operating.inner_speed_rpm=6000" }, "converged", 0, NULL },
    { "3 balls, 300 N at 6000 rpm", { "bearing.n_balls=3", "operating.axial_load_N=300",
      "operating.inner_speed_rpm=6000" }, "converged", 0, NULL },
    { "26 balls", { "bearing.n_balls=26" }, "converged", 0, NULL },
    { "near-conformal grooves f = 0.505 at 6000 rpm", {
      "bearing.inner_groove_radius_mm=3.20675", "bearing.outer_groove_radius_mm=3.20675",
      "operating.inner_speed_rpm=6000" }, "converged", 0, NULL },
    { "open grooves f = 0.6", { "bearing.inner_groove_radius_mm=3.81",
      "bearing.outer_groove_radius_mm=3.81" }, "converged", 0, NULL },
    { "ambient -40 C", { "operating.ambient_C=-40" }, "converged", 0, NULL },
    { "ambient 140 C, limit 150 C", { "operating.ambient_C=140" }, "runaway", 0, NULL },
    { "ambient above the runaway limit", { "operating.ambient_C=160" }, "invalid", 0, NULL },
    { "rigid (displacement) preload at 50000 rpm", { "mounting.preload=displacement",
      "operating.inner_speed_rpm=50000" }, "runaway", 0, NULL },
    { "2-step budget", { "thermal.max_steps=2" }, "not_converged", 0, NULL },
    { "heating off", { "effects.heating=off" }, "converged", 0, NULL },
    { "deep groove (0 deg) under thrust", { "bearing.contact_angle_deg=0",
      "operating.axial_load_N=100" }, "converged", 0, NULL },
    { "steady thermal mode", { "fidelity.thermal_mode=steady" }, "converged", 0, NULL },
    { "7-node network", { "fidelity.network=7" }, "converged", 0, NULL },
    { "static level", { "fidelity.model=static" }, "converged", 0, NULL },
    { "quasi-static level", { "fidelity.model=quasi-static" }, "converged", 0, NULL },
    { "quasi-dynamic level", { "fidelity.model=quasi-dynamic" }, "converged", 0, NULL },
    { "static level, 1e-5 N", { "fidelity.model=static", "operating.axial_load_N=1e-5" },
      "converged", 0, NULL },
    /* Issue 18: presets/runaway-rigid-preload.ini with the edits.
     * The transient settles (its small steps damp the coupling), so a
     * steady state exists; the undamped polish after it overshot (loop
     * gain about -1.5) into a cycle between 43 W and 1 W and ended
     * unbalanced. The steady solve must reach the same state. */
    { "issue 18 rigid preload, flat inner groove, 7-node", { "operating.inner_speed_rpm=16000",
      "mounting.preload=displacement", "mounting.preload_N=1000",
      "bearing.inner_groove_radius_mm=52.9824", "fidelity.network=7",
      "lubricant.air_density_kg_m3=0.00479549", "effects.loss_spin=off",
      "fidelity.model=quasi-static" }, "converged", 0, NULL },
    { "issue 18 case, steady thermal mode", { "operating.inner_speed_rpm=16000",
      "mounting.preload=displacement", "mounting.preload_N=1000",
      "bearing.inner_groove_radius_mm=52.9824", "fidelity.network=7",
      "lubricant.air_density_kg_m3=0.00479549", "effects.loss_spin=off",
      "fidelity.model=quasi-static", "fidelity.thermal_mode=steady" }, "converged", 0, NULL },
    { "dynamic level (3x3 grid)", { "fidelity.model=dynamic", "fidelity.contact_grid=3" },
      "converged", 1, NULL },
    { "dynamic level, light-load skid", { "fidelity.model=dynamic", "fidelity.contact_grid=3",
      "operating.axial_load_N=50", "operating.inner_speed_rpm=16000" }, "converged", 1, NULL },
};

/* Every double of the snapshot, field by field; returns how many are not
 * finite (their names go to `bad`). The ball view, losses and squeeze are
 * all-double structs and are walked as arrays. */
#define ALL_DOUBLES(T) _Static_assert(sizeof(T) % sizeof(double) == 0, #T " is not all doubles")
ALL_DOUBLES(acbb_ball_view);
ALL_DOUBLES(acbb_losses);
ALL_DOUBLES(acbb_squeeze);

static int count_bad(const double *v, size_t n, const char *what, char *bad, size_t cap)
{
    int k = 0;
    for (size_t i = 0; i < n; i++) {
        if (isfinite(v[i])) continue;
        k++;
        size_t len = strlen(bad);
        snprintf(bad + len, cap - len, " %s[%zu]", what, i);
    }
    return k;
}

static int snapshot_nonfinite(const acbb_snapshot *s, char *bad, size_t cap)
{
    const double scalars[] = { s->time, s->dt, s->residual, s->wall_ms, s->T_outer_ring,
        s->T_inner_ring, s->T_ball, s->T_housing, s->T_shaft, s->T_cavity, s->exp_ball,
        s->exp_inner, s->exp_inner_cen, s->exp_outer, s->delta_x, s->delta_z, s->tilt_y,
        s->stiffness_axial, s->reaction_x, s->heat_in, s->heat_out };
    bad[0] = '\0';
    int k = count_bad(scalars, sizeof scalars / sizeof scalars[0], "scalar", bad, cap);
    k += count_bad(s->T, (size_t)s->n_nodes, "T", bad, cap);
    k += count_bad((const double *)&s->losses, sizeof s->losses / sizeof(double), "losses",
                   bad, cap);
    k += count_bad((const double *)&s->squeeze, sizeof s->squeeze / sizeof(double),
                   "squeeze", bad, cap);
    k += count_bad((const double *)s->balls,
                   (size_t)s->n_balls * sizeof(acbb_ball_view) / sizeof(double), "balls",
                   bad, cap);
    return k;
}

/* Run one case; `got` is the status name. */
static void run_case(const hard_case *c, acbb_scene *sc, acbb_snapshot *snap, int *have,
                     const char **got, char *msg, size_t n)
{
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_error err = { { 0 } };
    size_t k = 0;
    while (k < MAX_EDITS && c->edits[k]) k++;
    *have = 0;
    acbb_status st = acbb_scene_apply_edits(&s, c->edits, k, &err);
    acbb_sim *sim = NULL;
    if (st == ACBB_OK) st = acbb_sim_create(&s, NULL, &sim, &err);
    if (st != ACBB_OK) {
        *got = st == ACBB_EINVAL ? "invalid" : acbb_status_name(st);
        snprintf(msg, n, "%s", err.msg);
        return;
    }
    *sc = s;
    acbb_sim_drive(sim, NULL);
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    *have = 1;
    *got = acbb_run_status_name(snap);
    snprintf(msg, n, "%s", snap->message);
}

static void check_case(const hard_case *c, acbb_snapshot *snap)
{
    char msg[512], bad[512];
    const char *got;
    int have;
    acbb_scene sc;
    acbb_scene_default(&sc);
    double t0 = acbb_now_ms();
    run_case(c, &sc, snap, &have, &got, msg, sizeof msg);
    double ms = acbb_now_ms() - t0;
    int pass = strcmp(got, c->expect) == 0;
    if (c->todo) {
        printf("%s %d - %s: %s (expected %s) # TODO %s\n", pass ? "ok" : "not ok", ++tap_n,
               c->name, got, c->expect, c->todo);
    } else {
        ok(pass, "%s: %s (expected %s)", c->name, got, c->expect);
    }
    if (!pass) printf("#   %s\n", msg);
    printf("# %s: %.0f ms wall (reported, not judged)\n", c->name, ms);
    if (!have) return;
    double units = acbb_accuracy_work_units(&sc, &snap->work);
    ok(snap->iteration <= sc.max_steps && units < WORK_BOUND,
       "%s: %ld steps (budget %d), %.0f work units (bound %.0f)", c->name, snap->iteration,
       sc.max_steps, units, WORK_BOUND);
    int nb = snapshot_nonfinite(snap, bad, sizeof bad);
    ok(nb == 0 && snap->status != ACBB_NONFINITE, "%s: every double of the snapshot finite%s",
       c->name, bad);
    /* Heat is only generated: no node below ambient, no negative loss. */
    int sane = 1;
    for (int k = 0; k < ACBB_LOSS_KINDS; k++) sane = sane && snap->losses.P[k] >= 0.0;
    for (int i = 0; i < snap->n_nodes; i++) sane = sane && snap->T[i] >= sc.ambient_C - 1e-6;
    ok(sane, "%s: every loss >= 0, no node below ambient", c->name);
    if (snap->state == ACBB_RUN_CONVERGED && sc.heating) {
        /* MODEL.md 12 item 18: a steady state balances its heat */
        double in = snap->heat_in, out = snap->heat_out;
        ok(fabs(in - out) <= fmax(ACBB_BALANCE_TOL * fabs(in), ACBB_BALANCE_FLOOR_W),
           "%s: converged, heat in %.9g W = heat out %.9g W (tolerance %g)", c->name, in, out,
           ACBB_BALANCE_TOL);
    }
    if (sc.inner_speed == 0.0) {
        /* MODEL.md 11 "zero speed": no film, no loss, temperatures stay ambient. */
        double dT = 0.0;
        for (int i = 0; i < snap->n_nodes; i++) dT = fmax(dT, fabs(snap->T[i] - sc.ambient_C));
        ok(snap->losses.total == 0.0 && dT < 1e-9, "%s: no loss (%g W), ambient everywhere",
           c->name, snap->losses.total);
    }
}

int main(int argc, char **argv)
{
    int slow = argc > 1 && !strcmp(argv[1], "--slow");
    gsl_set_error_handler_off(); /* statuses are checked; the default handler aborts */
    acbb_snapshot *snap = malloc(sizeof *snap);
    if (!snap) return 1;
    int run = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        if (cases[i].slow != slow) continue;
        check_case(&cases[i], snap);
        run++;
    }
    ok(run > 0, "%d %s cases run", run, slow ? "slow" : "fast");
    free(snap);
    printf("1..%d\n", tap_n);
    return tap_failed != 0;
}
