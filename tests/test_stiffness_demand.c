/* Stiffness on demand (issue 30 lever 2): a run created with
 * acbb_sim_opts.skip_stiffness reaches the same state as one without (the
 * probes run after convergence and leave it alone) and reports every
 * stiffness missing; the default computes them; a sensitivity of a
 * non-stiffness metric (which skips them) gives the value a plain run
 * gives, one of a stiffness metric still gets its stiffness. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "acbb/sim.h"
#include "acbb/tools/sensitivity.h"
#include "acbb/tools/sweep.h"

static acbb_status run(const acbb_scene *s, int skip, acbb_snapshot *snap)
{
    acbb_sim *sim = NULL;
    acbb_error err = { "" };
    acbb_status rc = acbb_sim_create(s, &(acbb_sim_opts){ .skip_stiffness = skip }, &sim, &err);
    if (rc == ACBB_OK) rc = acbb_sim_run(sim);
    if (sim) acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    return rc;
}

static void test_skip(const acbb_scene *s)
{
    static acbb_snapshot a, b;
    acbb_status ra = run(s, 0, &a), rb = run(s, 1, &b);
    ok(ra == ACBB_OK && rb == ACBB_OK, "both runs converge (%s, %s)", acbb_status_name(ra),
       acbb_status_name(rb));
    ok(a.stiffness_failed == 0 && a.stiffness_axial > 0 && a.stiffness_radial > 0
       && a.stiffness_tilt > 0 && a.stiffness_tilt_held > 0,
       "default: every stiffness computed (axial %.4g N/m)", a.stiffness_axial);
    ok(b.stiffness_failed == (ACBB_STIFF_AXIAL | ACBB_STIFF_RADIAL | ACBB_STIFF_TILT
                              | ACBB_STIFF_TILT_HELD) && b.stiffness_axial == 0.0,
       "skipped: every stiffness missing (bits %#x)", b.stiffness_failed);
    int same = a.losses.total == b.losses.total && a.n_nodes == b.n_nodes;
    for (int i = 0; i < a.n_nodes && same; i++) same = a.T[i] == b.T[i];
    ok(same, "skipped: the same state bit for bit (loss %.17g W, %.17g W)", a.losses.total,
       b.losses.total);
}

static void test_sensitivity(acbb_scene *s)
{
    static acbb_snapshot a;
    s->thermal_mode = ACBB_THERMAL_STEADY;
    ok(run(s, 0, &a) == ACBB_OK, "steady run");
    const char *metric[] = { "losses_W.total", "ring.stiffness_radial_N_per_um" };
    double want[] = { a.losses.total, a.stiffness_radial * 1e-6 };
    for (int k = 0; k < 2; k++) {
        double y = NAN;
        acbb_sens_opts o = { .jobs = 1 };
        snprintf(o.metric, sizeof o.metric, "%s", metric[k]);
        acbb_status rc = acbb_sens_eval(s, 1, &o, &y, NULL, 0, NULL);
        ok(rc == ACBB_OK && y == want[k], "sensitivity run of %s: %.17g (plain run %.17g)",
           metric[k], y, want[k]);
    }
}

/* A sweep with skip_stiffness: its points' stiffness missing, their
 * losses those of the sweep without it. */
typedef struct {
    double loss[2];
    unsigned failed[2];
} sweep_seen;

static void on_point(void *ctx, const acbb_sweep_result *r)
{
    sweep_seen *w = ctx;
    if (r->index < 2) {
        w->loss[r->index] = r->snap.losses.total;
        w->failed[r->index] = r->snap.stiffness_failed;
    }
}

static void test_sweep(const acbb_scene *s)
{
    acbb_sweep *g = NULL;
    acbb_error err = { "" };
    int built = acbb_sweep_new(&g) == ACBB_OK
                && acbb_sweep_add(g, "operating.axial_load_N=300,600", &err) == ACBB_OK;
    sweep_seen seen[2];
    memset(seen, 0, sizeof seen);
    for (int skip = 0; skip < 2 && built; skip++) {
        acbb_sweep_opts o = { .jobs = 1, .done = on_point, .ctx = &seen[skip],
                              .skip_stiffness = skip };
        built = acbb_sweep_run(g, s, &o, NULL) == ACBB_OK;
    }
    ok(built, "two sweeps of two points ran (%s)", err.msg);
    ok(seen[0].failed[0] == 0 && seen[0].failed[1] == 0 && seen[1].failed[0] == 0xfu
       && seen[1].failed[1] == 0xfu, "sweep: stiffness computed by default, missing when "
       "skipped (bits %#x %#x)", seen[1].failed[0], seen[1].failed[1]);
    ok(seen[0].loss[0] == seen[1].loss[0] && seen[0].loss[1] == seen[1].loss[1]
       && seen[0].loss[0] > 0, "sweep: the same losses (%.17g W, %.17g W)", seen[1].loss[0],
       seen[1].loss[1]);
    acbb_sweep_free(g);
}

/* A set's members skip theirs too (the preload map's pairs), and so does
 * the set; the set's state is the same. */
static void test_set(void)
{
    acbb_scene s;
    acbb_error err = { "" };
    ok(acbb_scene_load("presets/pair-DB-heated.ini", &s, &err) == ACBB_OK, "pair: %s", err.msg);
    static acbb_snapshot a, b, ma, mb;
    unsigned flags[2] = { 0, 0 };
    for (int skip = 0; skip < 2; skip++) {
        acbb_sim *sim = NULL;
        acbb_status rc = acbb_sim_create(&s, &(acbb_sim_opts){ .skip_stiffness = skip }, &sim,
                                         &err);
        if (rc == ACBB_OK) rc = acbb_sim_run(sim);
        if (rc == ACBB_OK) {
            acbb_sim_snapshot(sim, skip ? &b : &a);
            acbb_sim_bearing_snapshot(sim, 0, skip ? &mb : &ma);
            flags[skip] = (skip ? &mb : &ma)->stiffness_failed;
        }
        ok(rc == ACBB_OK, "pair, skip %d: %s", skip, acbb_status_name(rc));
        acbb_sim_free(sim);
    }
    ok(flags[0] == 0 && flags[1] == 0xfu && ma.stiffness_axial > 0,
       "pair: the members' stiffness computed by default, missing when skipped (%#x, %#x)",
       flags[0], flags[1]);
    int same = a.losses.total == b.losses.total && a.n_nodes == b.n_nodes;
    for (int i = 0; i < a.n_nodes && same; i++) same = a.T[i] == b.T[i];
    ok(same, "pair: the same state bit for bit (%.17g W, %.17g W)", a.losses.total,
       b.losses.total);
    /* The set's own nose probes are skipped with its members' (issue 30):
     * its radial and tilt stiffness reported missing (0, as before
     * convergence), its preload and lift-off the same bit for bit. */
    ok(a.set.stiffness_radial > 0.0 && a.set.stiffness_tilt > 0.0 && b.set.stiffness_radial == 0.0
       && b.set.stiffness_tilt == 0.0,
       "pair: the set's nose stiffness computed by default (%.4g N/m), missing when skipped",
       a.set.stiffness_radial);
    ok(a.set.preload_N == b.set.preload_N && a.set.liftoff_thrust_N == b.set.liftoff_thrust_N
       && a.set.liftoff_remainder_N == b.set.liftoff_remainder_N,
       "pair: the set's preload %.17g N and lift-off %.17g N the same when skipped",
       b.set.preload_N, b.set.liftoff_thrust_N);
    /* skip_liftoff (issue 30: the study's DB pair): no preload or lift-off
     * probe, while running or at the end; the run's path the same bits. */
    static acbb_snapshot c, mc;
    acbb_sim *sim = NULL;
    acbb_status rc = acbb_sim_create(&s, &(acbb_sim_opts){ .skip_stiffness = 1,
                                                          .skip_liftoff = 1 }, &sim, &err);
    if (rc == ACBB_OK) rc = acbb_sim_run(sim);
    if (rc == ACBB_OK) {
        acbb_sim_snapshot(sim, &c);
        acbb_sim_bearing_snapshot(sim, 0, &mc);
    }
    acbb_sim_free(sim);
    same = rc == ACBB_OK && c.losses.total == b.losses.total && c.n_nodes == b.n_nodes
           && c.iteration == b.iteration && c.time == b.time && mc.balls[0].Qi == mb.balls[0].Qi;
    for (int i = 0; i < c.n_nodes && same; i++) same = c.T[i] == b.T[i];
    ok(same && b.set.preload_N > 0.0 && b.set.liftoff_thrust_N > 0.0 && c.set.preload_N == 0.0
       && c.set.liftoff_thrust_N == 0.0,
       "pair, skip_liftoff: no preload or lift-off (0; %.4g N and %.4g N otherwise), the same "
       "%ld steps and state bit for bit", b.set.preload_N, b.set.liftoff_thrust_N, c.iteration);
}

int main(void)
{
    acbb_scene s;
    acbb_error err = { "" };
    ok(acbb_scene_load("presets/7008C.ini", &s, &err) == ACBB_OK, "preset: %s", err.msg);
    test_skip(&s);
    test_sensitivity(&s);
    test_sweep(&s);
    test_set();
    return done_testing();
}
