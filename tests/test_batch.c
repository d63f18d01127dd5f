/* Tests of the batch runner (include/acbb/batch.h): results independent of
 * the job count bit for bit, cancel mid-batch (every point reported once,
 * the ones not started as such), the CPU count under an affinity mask,
 * progress counts, a failing point's status and message, and the steady
 * solve against the transient (MODEL.md 9) to a stated tolerance. */
#define _GNU_SOURCE /* sched_setaffinity */
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "acbb/batch.h"
#include "acbb/tools/sweep.h"
#include "acbb/tools/fidelity.h"

#define NPTS 6
#define MAXN 16

static acbb_scene load(const char *path)
{
    acbb_scene s;
    acbb_error err = { { 0 } };
    if (acbb_scene_load(path, &s, &err) != ACBB_OK) {
        printf("Bail out! cannot load %s: %s\n", path, err.msg);
        exit(1);
    }
    return s;
}

/* What a test batch does per point, and what came back. */
typedef struct {
    acbb_scene base;
    int as_is;                   /* run the base itself (no load of its own per point) */
    int bad_index;               /* the scene callback fails here (-1: none) */
    int cancel_at_index;         /* its step sets `cancel` at iteration 5 (-1: none) */
    size_t cancel_after_done;    /* done sets `cancel` after this many results (0: never) */
    atomic_int cancel;
    int reports[MAXN];           /* done calls per index */
    acbb_batch_result res[MAXN];
    char msg[MAXN][128];
    acbb_snapshot snap[MAXN];
    int have_snap[MAXN];
    size_t last_done, total;
    int done_in_order;           /* r->done counted 1, 2, 3, ... */
    pthread_t threads[MAXN];     /* the worker that reported each index */
} batch_case;

/* Point i: the base at 200 + 150 i N, quasi-static (milliseconds a run). */
static acbb_status scene_cb(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                            acbb_error *err)
{
    batch_case *c = ctx;
    (void)mode;
    if ((int)i == c->bad_index) return acbb_error_set(err, ACBB_EINVAL, "bad point %zu", i);
    *out = c->base;
    if (!c->as_is) out->axial_load = 200.0 + 150.0 * (double)i;
    return ACBB_OK;
}

static void step_cb(void *ctx, size_t i, const acbb_sim *sim)
{
    batch_case *c = ctx;
    acbb_snapshot *s = malloc(sizeof *s);
    if (!s) return;
    acbb_sim_snapshot(sim, s);
    if ((int)i == c->cancel_at_index && s->iteration == 5) atomic_store(&c->cancel, 1);
    free(s);
}

static void done_cb(void *ctx, const acbb_batch_result *r)
{
    batch_case *c = ctx;
    size_t i = r->index;
    if (i >= MAXN) return;
    c->reports[i]++;
    c->res[i] = *r;
    snprintf(c->msg[i], sizeof c->msg[i], "%s", r->message ? r->message : "");
    c->have_snap[i] = r->snap != NULL;
    if (r->snap) c->snap[i] = *r->snap;
    c->done_in_order &= r->done == c->last_done + 1;
    c->last_done = r->done;
    c->total = r->total;
    c->threads[i] = pthread_self();
    if (c->cancel_after_done && r->done == c->cancel_after_done) atomic_store(&c->cancel, 1);
}

static void case_init(batch_case *c, const acbb_scene *base)
{
    memset(c, 0, sizeof *c);
    c->base = *base;
    c->bad_index = c->cancel_at_index = -1;
    c->done_in_order = 1;
    atomic_init(&c->cancel, 0);
}

static acbb_status run_case(batch_case *c, size_t n, int jobs, acbb_batch_mode mode,
                            acbb_batch_stats *st)
{
    acbb_batch_opts o = { .jobs = jobs, .cancel = &c->cancel, .mode = mode, .scene = scene_cb,
                          .step = step_cb, .done = done_cb, .ctx = c };
    return acbb_batch_run(n, &o, st);
}

/* Bit for bit: the numbers a client reads (wall time aside). */
static int same_snap(const acbb_snapshot *a, const acbb_snapshot *b)
{
    int same = a->iteration == b->iteration && a->status == b->status &&
               a->n_nodes == b->n_nodes && a->n_balls == b->n_balls &&
               memcmp(&a->time, &b->time, sizeof a->time) == 0 &&
               memcmp(a->T, b->T, sizeof a->T[0] * (size_t)a->n_nodes) == 0 &&
               memcmp(&a->losses, &b->losses, sizeof a->losses) == 0 &&
               memcmp(&a->delta_x, &b->delta_x, sizeof a->delta_x) == 0 &&
               memcmp(&a->stiffness_axial, &b->stiffness_axial, sizeof(double)) == 0;
    for (int j = 0; same && j < a->n_balls; j++)
        same = memcmp(&a->balls[j], &b->balls[j], sizeof a->balls[j]) == 0;
    return same;
}

static void test_jobs_independent(const acbb_scene *base)
{
    static batch_case one, three;
    acbb_batch_stats s1, s3;
    case_init(&one, base);
    case_init(&three, base);
    acbb_status r1 = run_case(&one, NPTS, 1, ACBB_BATCH_AS_SCENE, &s1);
    acbb_status r3 = run_case(&three, NPTS, 3, ACBB_BATCH_AS_SCENE, &s3);
    ok(r1 == ACBB_OK && r3 == ACBB_OK && s1.ran == NPTS && s3.ran == NPTS && s1.failed == 0 &&
           s3.failed == 0, "6 points with 1 and with 3 jobs: all ran and converged");
    ok(s1.workers == 1 && s3.workers == 3, "workers: %d and %d (jobs 1 and 3)", s1.workers,
       s3.workers);
    int same = 1, distinct = 1;
    for (int i = 0; i < NPTS; i++) {
        same &= one.have_snap[i] && three.have_snap[i] && same_snap(&one.snap[i], &three.snap[i]);
        if (i) distinct &= one.snap[i].losses.total != one.snap[i - 1].losses.total;
    }
    ok(same, "every point bit for bit the same with 1 and 3 jobs");
    ok(distinct, "... and the points differ from each other (not vacuous)");
    int once = 1;
    for (int i = 0; i < NPTS; i++) once &= one.reports[i] == 1 && three.reports[i] == 1;
    ok(once, "every index reported exactly once");
    ok(one.done_in_order && three.done_in_order && three.last_done == NPTS &&
           three.total == NPTS, "progress: done counts 1..%d, total %d", NPTS, NPTS);
}

/* One job: point 0 finishes, point 1's step cancels at iteration 5, points
 * 2.. never start. */
static void test_cancel_serial(const acbb_scene *base)
{
    static batch_case c;
    acbb_batch_stats st;
    case_init(&c, base);
    c.cancel_at_index = 1;
    acbb_status rc = run_case(&c, NPTS, 1, ACBB_BATCH_AS_SCENE, &st);
    ok(rc == ACBB_CANCELLED, "cancel mid-batch: ACBB_CANCELLED (%s)", acbb_status_name(rc));
    ok(c.res[0].status == ACBB_OK && c.res[0].ran, "point 0 finished before the cancel");
    ok(c.res[1].ran && c.res[1].status == ACBB_CANCELLED && c.have_snap[1] &&
           c.snap[1].iteration == 5, "point 1: cancelled mid-run at iteration %ld, last state kept",
       c.snap[1].iteration);
    int rest = 1;
    for (int i = 2; i < NPTS; i++)
        rest &= !c.res[i].ran && c.res[i].status == ACBB_CANCELLED && !c.have_snap[i] &&
                strcmp(c.msg[i], "not run: cancelled before it started") == 0;
    ok(rest, "points 2..5: not run, status cancelled, no snapshot, said so");
    ok(st.ran == 2 && st.not_run == NPTS - 2 && st.ran + st.not_run == NPTS,
       "stats: ran %zu + not run %zu = %d", st.ran, st.not_run, NPTS);
}

/* Three jobs, the cancel from `done` after the third result: whatever the
 * timing, each index once, done + not run = n. */
static void test_cancel_parallel(const acbb_scene *base)
{
    static batch_case c;
    acbb_batch_stats st;
    case_init(&c, base);
    c.cancel_after_done = 3;
    size_t n = 12;
    acbb_status rc = run_case(&c, n, 3, ACBB_BATCH_AS_SCENE, &st);
    int once = 1;
    size_t not_run = 0, ran = 0;
    for (size_t i = 0; i < n; i++) {
        once &= c.reports[i] == 1;
        not_run += !c.res[i].ran;
        ran += c.res[i].ran;
    }
    ok(rc == ACBB_CANCELLED && once, "3 jobs, cancel after 3 results: each of 12 reported once");
    ok(ran + not_run == n && st.ran == ran && st.not_run == not_run && not_run >= n - 3 - 3,
       "ran %zu + not run %zu = 12 (at most 3 more were in flight)", ran, not_run);
    ok(c.done_in_order && c.last_done == n, "progress counts every report, not-run ones too");
}

static void test_failures(const acbb_scene *base)
{
    static batch_case c;
    acbb_batch_stats st;
    case_init(&c, base);
    c.bad_index = 1;
    c.base.max_steps = 3;            /* every run stops after 3 steps */
    run_case(&c, 3, 2, ACBB_BATCH_AS_SCENE, &st);
    ok(c.res[1].ran && c.res[1].status == ACBB_EINVAL && !c.have_snap[1] &&
           strcmp(c.msg[1], "bad point 1") == 0, "a failing scene: its status and message (%s)",
       c.msg[1]);
    ok(c.res[0].status == ACBB_NOT_CONVERGED && c.have_snap[0] && c.snap[0].iteration == 3 &&
           strstr(c.msg[0], "no steady state within the limits"),
       "a run that stops at max_steps: not_converged, its snapshot and message (%s)", c.msg[0]);
    ok(st.failed == 3 && st.ran == 3, "stats: 3 failed of 3");
    case_init(&c, base);
    c.base.ball_diameter = -1.0;     /* refused by acbb_sim_create */
    run_case(&c, 1, 1, ACBB_BATCH_AS_SCENE, &st);
    ok(c.res[0].status == ACBB_EINVAL && !c.have_snap[0] && c.msg[0][0],
       "a scene the engine refuses: EINVAL with the validation message (%s)", c.msg[0]);
    ok(acbb_batch_run(1, &(acbb_batch_opts){ 0 }, NULL) == ACBB_EINVAL,
       "no scene callback: EINVAL");
}

/* ---- the CPUs the process may use ---- */

typedef struct {
    pthread_t main;
    int others;
} thread_seen;

static void sweep_done(void *ctx, const acbb_sweep_result *r)
{
    thread_seen *t = ctx;
    (void)r;
    t->others += !pthread_equal(pthread_self(), t->main);
}

static void test_affinity(const acbb_scene *base)
{
    cpu_set_t all, one;
    if (sched_getaffinity(0, sizeof all, &all) != 0) {
        skip("sched_getaffinity failed", "affinity");
        return;
    }
    int n = CPU_COUNT(&all);
    ok(acbb_batch_cpus() == n, "acbb_batch_cpus() = %d, the affinity mask's count", n);
    ok(acbb_batch_workers(100, 0) == n && acbb_batch_workers(1, 0) == 1 &&
           acbb_batch_workers(5, 3) == 3 && acbb_batch_workers(0, 4) == 1,
       "workers: min(jobs or CPUs, points), at least 1");
    int first = 0;
    while (!CPU_ISSET(first, &all)) first++;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    if (sched_setaffinity(0, sizeof one, &one) != 0) {
        skip("sched_setaffinity refused", "one CPU");
        return;
    }
    ok(acbb_batch_cpus() == 1, "under a one-CPU mask (taskset -c %d): 1 CPU", first);
    acbb_sweep *g = NULL;
    acbb_error err = { { 0 } };
    thread_seen seen = { pthread_self(), 0 };
    acbb_sweep_opts o = { .jobs = 0, .done = sweep_done, .ctx = &seen };
    size_t ran = 0;
    int built = acbb_sweep_new(&g) == ACBB_OK &&
                acbb_sweep_add(g, "operating.axial_load_N=200,400,600,800", &err) == ACBB_OK;
    ok(built && acbb_sweep_run(g, base, &o, &ran) == ACBB_OK && ran == 4 && seen.others == 0,
       "a sweep with the default jobs ran its 4 points on the calling thread alone");
    acbb_sweep_free(g);
    sched_setaffinity(0, sizeof all, &all);
    ok(acbb_batch_cpus() == n, "mask restored: %d CPUs again", n);
}

static void count_fn(void *ctx, size_t i)
{
    atomic_int *hits = ctx;
    atomic_fetch_add(&hits[i], 1);
}

static void test_for(void)
{
    atomic_int hits[50];
    for (int i = 0; i < 50; i++) atomic_init(&hits[i], 0);
    size_t ran = acbb_batch_for(50, 3, count_fn, hits, NULL);
    int once = 1;
    for (int i = 0; i < 50; i++) once &= atomic_load(&hits[i]) == 1;
    ok(ran == 50 && once, "parallel for: each of 50 indices once");
    atomic_int stop;
    atomic_init(&stop, 1);
    ok(acbb_batch_for(50, 3, count_fn, hits, &stop) == 0, "parallel for: cancelled first, none run");
}

/* ---- steady solve vs transient ---- */

static void modes(const char *path, double tol)
{
    static batch_case tr, sd;
    acbb_scene s = load(path);
    case_init(&tr, &s);
    case_init(&sd, &s);
    tr.as_is = sd.as_is = 1;
    run_case(&tr, 1, 1, ACBB_BATCH_TRANSIENT, NULL);
    run_case(&sd, 1, 1, ACBB_BATCH_STEADY, NULL);
    const acbb_snapshot *a = &tr.snap[0], *b = &sd.snap[0];
    double worst = 0.0, worst_T = 0.0;
    /* Each loss kind on the scale of the total (a kind near zero moves by
     * more relative to itself: 1e-7 for a 0.1 mW slip loss). */
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        worst = fmax(worst, fabs(a->losses.P[l] - b->losses.P[l]) / a->losses.total);
    worst = fmax(worst, fabs(a->losses.total - b->losses.total) / a->losses.total);
    worst = fmax(worst, fabs(a->balls[0].Qi - b->balls[0].Qi) / a->balls[0].Qi);
    for (int i = 0; i < a->n_nodes; i++) worst_T = fmax(worst_T, fabs(a->T[i] - b->T[i]));
    ok(a->state == ACBB_RUN_CONVERGED && b->state == ACBB_RUN_CONVERGED && a->time > 0 &&
           b->time == 0 && b->iteration < a->iteration,
       "%s: transient (%ld steps, %.0f s) and steady solve (%ld iterations) converge", path,
       a->iteration, a->time, b->iteration);
    ok(a->state == ACBB_RUN_CONVERGED && b->state == ACBB_RUN_CONVERGED && worst <= tol &&
           worst_T <= 1e-6,
       "%s: losses (of the total) and Qi to %.2g relative (need <= %g), nodes to %.2g K (<= 1e-6)",
       path, worst, tol, worst_T);
}

static void test_modes(void)
{
    /* Each run's losses are resolved to the mechanics' tolerance
     * (fidelity.mech_tol = 1e-8 relative, its ball solves warm-started
     * along a different path), so two converged runs agree to twice it.
     * Measured: 4.7e-9 (7008C) and 1.6e-9 (combined-load) in a debug
     * build, 8.6e-9 for combined-load in a release build; 1.2e-8 since
     * issue 30's envelope Cholesky and contact-angle ratios moved the
     * round-off. */
    modes("presets/7008C.ini", 2e-8);
    modes("presets/combined-load.ini", 2e-8);
    /* Not equivalent for a runaway scene (batch.h). */
    static batch_case tr, sd;
    acbb_scene s = load("presets/runaway-rigid-preload.ini");
    case_init(&tr, &s);
    case_init(&sd, &s);
    tr.as_is = sd.as_is = 1;
    run_case(&tr, 1, 1, ACBB_BATCH_TRANSIENT, NULL);
    run_case(&sd, 1, 1, ACBB_BATCH_STEADY, NULL);
    ok(tr.res[0].status == ACBB_RUNAWAY && sd.res[0].status == ACBB_OK,
       "runaway preset: the transient ends runaway, the steady solve converges (%s / %s)",
       acbb_status_name(tr.res[0].status), acbb_status_name(sd.res[0].status));
    /* The mode wins over a fidelity preset's own thermal mode. */
    acbb_scene p = load("presets/7008C.ini");
    acbb_error err = { { 0 } };
    acbb_scene_set(&p, "fidelity.preset", "fast", &err);
    case_init(&sd, &p);
    case_init(&tr, &p);
    tr.as_is = sd.as_is = 1;
    run_case(&sd, 1, 1, ACBB_BATCH_STEADY, NULL);
    run_case(&tr, 1, 1, ACBB_BATCH_TRANSIENT, NULL);
    ok(sd.have_snap[0] && sd.snap[0].time == 0 && tr.have_snap[0] && tr.snap[0].time > 0,
       "fidelity.preset = fast: STEADY and TRANSIENT still decide the thermal mode");
}

/* ---- warm starts (issue 30): a steady point from another's state ---- */

typedef struct {
    acbb_scene scene;
    acbb_batch_mode mode;
    const acbb_warm *from;
    acbb_warm *kept;
    acbb_snapshot snap;
} warm_case;

static acbb_status warm_scene(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                              acbb_error *err)
{
    (void)i, (void)err;
    *out = ((warm_case *)ctx)->scene;
    *mode = ((warm_case *)ctx)->mode;
    return ACBB_OK;
}

static const acbb_warm *warm_from(void *ctx, size_t i) { (void)i; return ((warm_case *)ctx)->from; }

static void warm_keep(void *ctx, size_t i, acbb_warm *w)
{
    (void)i;
    acbb_warm_free(((warm_case *)ctx)->kept);
    ((warm_case *)ctx)->kept = w;
}

static void warm_done(void *ctx, const acbb_batch_result *r)
{
    if (r->snap) ((warm_case *)ctx)->snap = *r->snap;
}

static void warm_run(warm_case *c, acbb_batch_mode mode, const acbb_warm *from)
{
    c->mode = mode;
    c->from = from;
    acbb_batch_opts o = { .jobs = 1, .scene = warm_scene, .done = warm_done, .ctx = c,
                          .skip_stiffness = 1, .warm = warm_from, .keep = warm_keep };
    acbb_batch_run(1, &o, NULL);
}

static void test_warm(void)
{
    static warm_case base, cold, warm;
    base.scene = load("presets/7008C.ini");
    warm_run(&base, ACBB_BATCH_STEADY, NULL);
    ok(base.kept != NULL, "a converged steady point's state is kept");
    acbb_error err = { { 0 } };
    cold.scene = base.scene;
    acbb_scene_set(&cold.scene, "lubricant.boundary_friction", "0.12", &err);
    acbb_scene_set(&cold.scene, "operating.axial_load_N", "220", &err);
    warm.scene = cold.scene;
    warm_run(&cold, ACBB_BATCH_STEADY, NULL);
    warm_run(&warm, ACBB_BATCH_STEADY, base.kept);
    const acbb_snapshot *a = &cold.snap, *b = &warm.snap;
    double worst = fabs(a->losses.total - b->losses.total) / a->losses.total, worst_T = 0.0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        worst = fmax(worst, fabs(a->losses.P[l] - b->losses.P[l]) / a->losses.total);
    worst = fmax(worst, fabs(a->balls[0].Qi - b->balls[0].Qi) / a->balls[0].Qi);
    for (int i = 0; i < a->n_nodes; i++) worst_T = fmax(worst_T, fabs(a->T[i] - b->T[i]));
    /* both to the steady solve's tolerance: twice mech_tol, as test_modes */
    ok(a->state == ACBB_RUN_CONVERGED && b->state == ACBB_RUN_CONVERGED && worst <= 2e-8 &&
           worst_T <= 1e-6,
       "warm start from another point: the cold start's losses and Qi to %.2g (<= 2e-8), "
       "nodes to %.2g K (<= 1e-6)", worst, worst_T);
    ok(warm.kept == NULL && cold.kept != NULL, "a warm-started point keeps no state (its "
       "caller has one), a cold one does");
    ok(b->work.mechanics_solves < a->work.mechanics_solves && b->iteration <= a->iteration,
       "... with %ld mechanics solves instead of %ld, %ld iterations instead of %ld",
       b->work.mechanics_solves, a->work.mechanics_solves, b->iteration, a->iteration);
    static warm_case tc, tw;
    tc.scene = tw.scene = cold.scene;
    warm_run(&tc, ACBB_BATCH_TRANSIENT, NULL);
    warm_run(&tw, ACBB_BATCH_TRANSIENT, base.kept);
    ok(same_snap(&tc.snap, &tw.snap), "a transient point starts from ambient whatever is given");
    acbb_warm_free(base.kept);
    acbb_warm_free(cold.kept);
    acbb_warm_free(warm.kept);
    acbb_warm_free(tc.kept);
    acbb_warm_free(tw.kept);
}

/* Issue 30, sixth round: a transient takes of another transient's kept
 * state only its set-up (the room-temperature mechanics at speed), and
 * only when its mechanics are built the same: bit for bit its own run,
 * with the set-up's continuation solves not made again. */
static void test_setup_shared(void)
{
    static warm_case base, net, netw, mu, muw;
    base.scene = load("presets/7008C.ini");
    warm_run(&base, ACBB_BATCH_TRANSIENT, NULL);
    acbb_error err = { { 0 } };
    net.scene = base.scene; /* a network input: the mechanics read none */
    acbb_scene_set(&net.scene, "mounting.h_face_W_m2K", "10000", &err);
    mu.scene = base.scene; /* read by the mechanics (the gyroscopic moment's friction) */
    acbb_scene_set(&mu.scene, "lubricant.boundary_friction", "0.12", &err);
    netw.scene = net.scene;
    muw.scene = mu.scene;
    warm_run(&net, ACBB_BATCH_TRANSIENT, NULL);
    warm_run(&netw, ACBB_BATCH_TRANSIENT, base.kept);
    warm_run(&mu, ACBB_BATCH_TRANSIENT, NULL);
    warm_run(&muw, ACBB_BATCH_TRANSIENT, base.kept);
    long made = net.snap.work.mechanics_solves, shared = netw.snap.work.mechanics_solves;
    /* The first state's passes taken too (sim_first.c): P Level-2 passes
     * and 1 + P mechanics solves not made (P = 1..4, QD_PASSES). */
    long passes = net.snap.work.traction_solves - netw.snap.work.traction_solves;
    ok(base.kept != NULL && net.snap.state == ACBB_RUN_CONVERGED
       && same_snap(&net.snap, &netw.snap) && passes >= 1 && passes <= 4
       && shared == made - 4 - 1 - passes,
       "transient from a kept set-up (h_face changed): every result bit for bit its own run's, "
       "%ld mechanics solves instead of %ld (the continuation's 4 and the first state's %ld "
       "passes taken)", shared, made, passes);
    ok(same_snap(&mu.snap, &muw.snap)
       && muw.snap.work.mechanics_solves == mu.snap.work.mechanics_solves,
       "transient whose mechanics differ (boundary friction): the set-up made afresh, the same "
       "bits and solves");
    ok(netw.kept == NULL && muw.kept == NULL, "a point given a start keeps none");
    acbb_warm_free(base.kept);
    acbb_warm_free(net.kept);
    acbb_warm_free(mu.kept);
}

/* Fresh and from base's kept set-up, the scene with key = val: 1 if both
 * reach the same bits; *setup 1 if the set-up's continuation (4 solves)
 * was taken, *passes the first state's Level-2 passes taken. */
static int first_pair(const acbb_warm *kept, const acbb_scene *base, const char *key,
                      const char *val, int *setup, long *passes)
{
    static warm_case own, from;
    acbb_error err = { { 0 } };
    own.scene = *base;
    if (acbb_scene_set(&own.scene, key, val, &err) != ACBB_OK) return 0;
    from.scene = own.scene;
    warm_run(&own, ACBB_BATCH_TRANSIENT, NULL);
    warm_run(&from, ACBB_BATCH_TRANSIENT, kept);
    *passes = own.snap.work.traction_solves - from.snap.work.traction_solves;
    *setup = own.snap.work.mechanics_solves - from.snap.work.mechanics_solves
             == 4 + (*passes > 0 ? 1 + *passes : 0);
    acbb_warm_free(own.kept);
    acbb_warm_free(from.kept);
    own.kept = from.kept = NULL;
    return own.snap.state == ACBB_RUN_CONVERGED && same_snap(&own.snap, &from.snap);
}

/* Issue 30: a transient that takes its set-up from a kept one takes its
 * first state's mechanics and Level-2 passes too (sim_first.c) where
 * every input of those passes is the same bits: a thermal network's input
 * gives its own run's bits with the passes taken; an input Level 2 reads
 * (the limiting shear stress, the drag coefficient, the oil's
 * conductivity: not the mechanics, so the set-up is taken) makes the
 * passes afresh. An expansion coefficient is not read by the passes but
 * through the expansions, which are zero at ambient whatever it is. */
static void test_first_shared(void)
{
    static warm_case base;
    base.scene = load("presets/7008C.ini");
    warm_run(&base, ACBB_BATCH_TRANSIENT, NULL);
    /* key, value, 1: its passes taken (a thermal network's input, an
     * expansion coefficient, the rolling hysteresis, the oil's specific
     * heat); 0: read by Level 2, made afresh */
    static const struct {
        const char *key, *val;
        int taken;
    } cases[] = {
        { "mounting.h_fit_outer_W_m2K", "20000", 1 }, { "mounting.h_fit_inner_W_m2K", "1000", 1 },
        { "mounting.h_natural_W_m2K", "50", 1 }, { "thermal.contact_multiplier", "2", 1 },
        { "lubricant.mixture_k_W_mK", "0.06", 1 }, { "surroundings.cap_h_W_m2K", "50", 1 },
        { "materials.ring_expansion_ppm_K", "13", 1 }, { "lubricant.hysteresis_loss", "0.01", 1 },
        { "lubricant.oil_cp_J_kgK", "2100", 1 },
        { "lubricant.limiting_shear_ratio", "0.1", 0 }, { "lubricant.drag_coefficient", "0.5", 0 },
        { "lubricant.oil_k_W_mK", "0.15", 0 },
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        int setup = 0;
        long passes = 0;
        int same = first_pair(base.kept, &base.scene, cases[k].key, cases[k].val, &setup, &passes);
        ok(same && setup && (cases[k].taken ? passes >= 1 && passes <= 4 : passes == 0),
           "%s = %s: its own run's bits, the set-up taken, the first state's passes %s (%ld "
           "taken)", cases[k].key, cases[k].val, cases[k].taken ? "taken" : "made", passes);
    }
    acbb_warm_free(base.kept);
}

/* Issue 30: skip_life (the robustness's runs): the rating life is neither
 * made nor published (all zero), every other result the same bits. */
static void test_skip_life(void)
{
    static acbb_snapshot with, without;
    acbb_scene s = load("presets/7008C.ini");
    s.thermal_mode = ACBB_THERMAL_STEADY;
    acbb_snapshot *out[2] = { &with, &without };
    for (int k = 0; k < 2; k++) {
        acbb_sim_opts o = { .skip_stiffness = 1, .skip_life = k };
        acbb_sim *sim = NULL;
        acbb_error err = { { 0 } };
        if (acbb_sim_create(&s, &o, &sim, &err) == ACBB_OK) acbb_sim_run(sim);
        acbb_sim_snapshot(sim, out[k]);
        acbb_sim_free(sim);
    }
    static const acbb_life zero;
    ok(with.life.C > 0.0 && with.life.C0 > 0.0 && with.life.L10r_h > 0.0
       && memcmp(&without.life, &zero, sizeof zero) == 0,
       "skip_life: the life is made by default (C %.0f N), all zero when skipped", with.life.C);
    ok(with.state == ACBB_RUN_CONVERGED && same_snap(&with, &without),
       "skip_life: every other result bit for bit the same");
}

/* The scenes a spare-workspace test's worker runs in turn. */
#define SPARE_MAX 4
static acbb_scene spare_scene[SPARE_MAX];
static acbb_status spare_scene_cb(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                                  acbb_error *err)
{
    (void)ctx, (void)mode, (void)err;
    *out = spare_scene[i];
    return ACBB_OK;
}

/* 1 if one worker's runs of spare_scene[0..n) each converge to the bits
 * (and mechanics solves) of a Sim of its own. */
static int spare_runs_own_bits(int n)
{
    static batch_case c;
    static acbb_snapshot own;
    case_init(&c, &spare_scene[0]);
    acbb_batch_opts o = { .jobs = 1, .scene = spare_scene_cb, .done = done_cb, .ctx = &c };
    acbb_batch_run((size_t)n, &o, NULL);
    int same = 1;
    for (int i = 0; i < n; i++) {
        acbb_sim *sim = NULL;
        acbb_error err = { { 0 } };
        if (acbb_sim_create(&spare_scene[i], NULL, &sim, &err) == ACBB_OK) acbb_sim_run(sim);
        acbb_sim_snapshot(sim, &own);
        acbb_sim_free(sim);
        int one = c.have_snap[i] && own.state == ACBB_RUN_CONVERGED
                  && same_snap(&own, &c.snap[i])
                  && own.work.mechanics_solves == c.snap[i].work.mechanics_solves;
        if (!one) printf("# run %d differs from its own Sim's\n", i);
        same = same && one;
    }
    return same;
}

/* Issue 30, sixth round: a worker renews its last run's mechanics
 * workspace for the next (acbb_mech_renew): each run bit for bit a Sim of
 * its own, through a radial load and back (learnt Jacobians, ring
 * freedoms and predictors all made afresh). */
static void test_spare_mech(void)
{
    acbb_scene base = load("presets/7008C.ini"); /* quasi-dynamic, transient */
    for (int i = 0; i < 3; i++) spare_scene[i] = base;
    spare_scene[1].radial_load = spare_scene[2].radial_load = 300.0;
    spare_scene[2].h_face = 10000.0; /* the same loads and speed as the run before */
    ok(spare_runs_own_bits(3), "one worker's three runs (pure thrust; 300 N radial; the same "
       "with another face film) in one renewed mechanics workspace: each the bits of a Sim of "
       "its own");
}

/* Issue 30, seventh round: a worker renews its last run's Level-2
 * workspace for the next too (acbb_qd_renew), and keeps it through a run
 * at another level: each run bit for bit a Sim of its own, with Jacobians,
 * skipped inputs and root histories of other balls, speeds and modes
 * before it (cleared), and another contact grid (new traction tables). */
static void test_spare_qd(void)
{
    static const struct {
        double radial, rpm;
        acbb_thermal_mode mode;
        acbb_model_level model;
        int grid;
    } pt[SPARE_MAX] = {
        { 300.0, 15000.0, ACBB_THERMAL_STEADY, ACBB_MODEL_QUASI_DYNAMIC, 6 },
        { 300.0, 15000.0, ACBB_THERMAL_STEADY, ACBB_MODEL_QUASI_STATIC, 6 }, /* keeps it */
        { 0.0, 12000.0, ACBB_THERMAL_TRANSIENT, ACBB_MODEL_QUASI_DYNAMIC, 6 },
        { 300.0, 18000.0, ACBB_THERMAL_TRANSIENT, ACBB_MODEL_QUASI_DYNAMIC, 5 },
    };
    acbb_scene base = load("presets/7008C.ini"); /* quasi-dynamic, transient, grid 6 */
    for (int i = 0; i < SPARE_MAX; i++) {
        acbb_scene *s = &spare_scene[i];
        acbb_scene_resolve(&base, s, NULL);
        s->radial_load = pt[i].radial;
        s->inner_speed = pt[i].rpm * M_PI / 30.0;
        s->thermal_mode = pt[i].mode;
        s->model = pt[i].model;
        s->contact_grid = pt[i].grid;
    }
    ok(spare_runs_own_bits(SPARE_MAX), "one worker's four runs (300 N radial steady; the same "
       "quasi-static; axial transient at 12000 rpm; radial transient at 18000 rpm on a 5-point "
       "grid) in one renewed Level-2 workspace: each the bits of a Sim of its own");
}

/* Issue 30, sixth round: snap_to makes each final snapshot in the
 * caller's record (r->snap points there), the same bits as the worker's. */
static acbb_snapshot to_rec[3];
static acbb_snapshot *snap_to_cb(void *ctx, size_t i)
{
    (void)ctx;
    return i < 3 ? &to_rec[i] : NULL;
}

static void test_snap_to(const acbb_scene *base)
{
    static batch_case a, b;
    case_init(&a, base);
    case_init(&b, base);
    run_case(&a, 4, 1, ACBB_BATCH_AS_SCENE, NULL);
    acbb_batch_opts o = { .jobs = 1, .cancel = &b.cancel, .scene = scene_cb, .step = step_cb,
                          .done = done_cb, .ctx = &b, .snap_to = snap_to_cb };
    acbb_batch_run(4, &o, NULL);
    int same = 1, there = 1;
    for (size_t i = 0; i < 4; i++) {
        same = same && a.have_snap[i] && b.have_snap[i] && same_snap(&a.snap[i], &b.snap[i]);
        there = there && (i < 3 ? b.res[i].snap == &to_rec[i] && same_snap(&to_rec[i], &a.snap[i])
                                : b.res[i].snap != NULL);
    }
    ok(same && there && !strcmp(a.msg[0], b.msg[0]),
       "snap_to: each final snapshot made in the caller's record (the worker's where it gives "
       "none), the same bits and message as without");
}

int main(void)
{
    /* No gsl_set_error_handler_off here: the engine turns GSL's aborting
     * handler off itself while it works (src/base/gsl_quiet.h). */
    acbb_scene base = load("presets/7008C.ini");
    acbb_error err = { { 0 } };
    if (acbb_scene_set(&base, "fidelity.model", "quasi-static", &err) != ACBB_OK) {
        printf("Bail out! %s\n", err.msg);
        return 1;
    }
    test_warm();
    test_skip_life();
    test_setup_shared();
    test_first_shared();
    test_snap_to(&base);
    test_spare_mech();
    test_spare_qd();
    test_jobs_independent(&base);
    test_cancel_serial(&base);
    test_cancel_parallel(&base);
    test_failures(&base);
    test_affinity(&base);
    test_for();
    test_modes();
    return done_testing();
}
