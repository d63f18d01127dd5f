/* acbb — the batch runner (batch.h): the engine's only pool of threads for
 * runs. Workers take indices from one atomic counter; each owns one slot
 * (scene, snapshot, message: tens of kilobytes, allocated once per worker)
 * and takes the one lock only to hand a finished point to `done`. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include <limits.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include "acbb/batch.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/measure.h"
#include "cancel.h"
#include "sim_priv.h"

int acbb_batch_cpus(void)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return CPU_COUNT(&set);
    long n = sysconf(_SC_NPROCESSORS_ONLN); /* more CPUs than a cpu_set_t holds */
    return n < 1 ? 1 : n > INT_MAX ? INT_MAX : (int)n;
}

int acbb_batch_workers(size_t n, int jobs)
{
    size_t j = jobs > 0 ? (size_t)jobs : (size_t)acbb_batch_cpus();
    if (j > n) j = n;
    return j < 1 ? 1 : (int)j;
}

/* fn(arg) on `workers` threads, the caller's one of them; returns how many
 * ran (fewer when the system refuses a thread: the others take its share). */
static int spawn(int workers, void *(*fn)(void *), void *arg)
{
    pthread_t *tid = workers > 1 ? malloc((size_t)(workers - 1) * sizeof *tid) : NULL;
    int started = 0;
    while (tid && started < workers - 1 && pthread_create(&tid[started], NULL, fn, arg) == 0)
        started++;
    fn(arg);
    for (int k = 0; k < started; k++) pthread_join(tid[k], NULL);
    free(tid);
    return started + 1;
}

/* ---- the parallel for ---- */

typedef struct {
    size_t n;
    acbb_batch_fn fn;
    void *ctx;
    const atomic_int *cancel;
    atomic_size_t next, ran;
} par;

static void *par_worker(void *arg)
{
    par *p = arg;
    for (size_t i; !acbb_cancelled(p->cancel) && (i = atomic_fetch_add(&p->next, 1)) < p->n;) {
        p->fn(p->ctx, i);
        atomic_fetch_add(&p->ran, 1);
    }
    return NULL;
}

size_t acbb_batch_for(size_t n, int jobs, acbb_batch_fn fn, void *ctx,
                      const atomic_int *cancel)
{
    par p = { .n = n, .fn = fn, .ctx = ctx, .cancel = cancel };
    atomic_init(&p.next, 0);
    atomic_init(&p.ran, 0);
    spawn(acbb_batch_workers(n, jobs), par_worker, &p);
    return atomic_load(&p.ran);
}

/* ---- Sim runs ---- */

typedef struct {
    size_t n;
    const acbb_batch_opts *o;
    int sim_threads;            /* acbb_sim_opts.threads: 1 when runs fill the cores */
    atomic_size_t next;
    pthread_mutex_t lock;       /* guards the counts below and every `done` call */
    size_t done, ran, not_run, failed, cancelled;
} pool;

typedef struct {
    acbb_scene scene;
    acbb_snapshot snap;
    char msg[520];
    acbb_simx_spare spare;      /* the last run's workspaces, renewed by the next */
} slot;

typedef struct {
    const acbb_batch_opts *o;
    size_t i;
} step_ctx;

static int step_hook(void *ctx, const acbb_sim *sim)
{
    const step_ctx *c = ctx;
    c->o->step(c->o->ctx, c->i, sim);
    return 0;
}

/* The mode is a scene edit: a fidelity preset is resolved first (it sets
 * thermal_mode itself), exactly as acbb_sim_create would resolve it. */
static void apply_mode(acbb_scene *s, acbb_batch_mode mode)
{
    if (mode == ACBB_BATCH_AS_SCENE) return;
    acbb_scene_resolve(s, s, NULL);
    s->thermal_mode = mode == ACBB_BATCH_STEADY ? ACBB_THERMAL_STEADY : ACBB_THERMAL_TRANSIENT;
}

/* Scene, set-up and run of point i into r (r->snap points into w). */
static void run_point(const pool *pl, slot *w, size_t i, acbb_batch_result *r)
{
    const acbb_batch_opts *o = pl->o;
    double t0 = acbb_now_ms();
    acbb_error err = { { 0 } };
    acbb_batch_mode mode = o->mode;
    acbb_sim *sim = NULL;
    const acbb_warm *from = NULL;
    acbb_status st = o->scene(o->ctx, i, &w->scene, &mode, &err);
    if (st == ACBB_OK) {
        apply_mode(&w->scene, mode);
        acbb_sim_opts so = { o->cancel, pl->sim_threads, o->skip_stiffness, o->skip_life,
                             o->skip_liftoff };
        /* a transient takes only the set-up (sim_priv.h), and keeps its own */
        from = o->warm ? o->warm(o->ctx, i) : NULL;
        acbb_simx_start start = { from, o->keep && !from, w->spare };
        w->spare = (acbb_simx_spare){ 0 }; /* the Sim's now */
        st = acbb_simx_create_from(&w->scene, &so, &start, &sim, &err);
    }
    if (st == ACBB_OK) {
        step_ctx sc = { o, i };
        acbb_run_ctl ctl = { .hook = o->step ? step_hook : NULL, .ctx = &sc, .cancel = o->cancel };
        st = acbb_sim_drive(sim, &ctl);
        acbb_snapshot *to = o->snap_to ? o->snap_to(o->ctx, i) : NULL;
        if (!to) to = &w->snap;
        acbb_sim_snapshot(sim, to);
        r->snap = to;
        /* a warm-started point's state starts nothing: its caller has one */
        acbb_warm *kept = o->keep && !from ? acbb_simx_warm_save(sim) : NULL;
        if (kept) o->keep(o->ctx, i, kept);
        snprintf(w->msg, sizeof w->msg, "%s", to->message);
    } else {
        snprintf(w->msg, sizeof w->msg, "%s", err.msg[0] ? err.msg : acbb_status_name(st));
    }
    if (sim) w->spare = acbb_simx_free_spare(sim); /* else the spare is still w's, or freed */
    r->status = st;
    r->wall_ms = acbb_now_ms() - t0;
}

void acbb_warm_free(acbb_warm *w) { acbb_simx_warm_free(w); }

static void report(pool *pl, acbb_batch_result *r)
{
    pthread_mutex_lock(&pl->lock);
    r->done = ++pl->done;
    r->total = pl->n;
    pl->ran += r->ran;
    pl->not_run += !r->ran;
    pl->failed += r->ran && r->status != ACBB_OK;
    pl->cancelled += r->status == ACBB_CANCELLED;
    if (pl->o->done) pl->o->done(pl->o->ctx, r);
    pthread_mutex_unlock(&pl->lock);
}

static void *pool_worker(void *arg)
{
    pool *pl = arg;
    slot *w = malloc(sizeof *w);
    if (w) w->spare = (acbb_simx_spare){ 0 };
    for (size_t i; (i = atomic_fetch_add(&pl->next, 1)) < pl->n;) {
        acbb_batch_result r = { .index = i, .ran = 1 };
        if (acbb_cancelled(pl->o->cancel)) {
            r = (acbb_batch_result){ .index = i, .status = ACBB_CANCELLED,
                                     .message = "not run: cancelled before it started" };
        } else if (!w) {
            r.status = ACBB_ENOMEM;
            r.message = "out of memory";
        } else {
            r.message = w->msg;
            run_point(pl, w, i, &r);
        }
        report(pl, &r);
    }
    if (w) acbb_simx_spare_free(w->spare);
    free(w);
    return NULL;
}

acbb_status acbb_batch_run(size_t n, const acbb_batch_opts *o, acbb_batch_stats *stats)
{
    if (!o || !o->scene) return ACBB_EINVAL;
    pool pl = { .n = n, .o = o };
    int workers = acbb_batch_workers(n, o->jobs);
    /* One worker on a one-CPU mask: no ball workers either (dynamic level). */
    pl.sim_threads = workers > 1 || acbb_batch_cpus() == 1 ? 1 : 0;
    atomic_init(&pl.next, 0);
    if (pthread_mutex_init(&pl.lock, NULL) != 0) return ACBB_ENOMEM;
    workers = n ? spawn(workers, pool_worker, &pl) : 1;
    pthread_mutex_destroy(&pl.lock);
    if (stats)
        *stats = (acbb_batch_stats){ .workers = workers, .ran = pl.ran, .not_run = pl.not_run,
                                     .failed = pl.failed };
    return pl.not_run || pl.cancelled ? ACBB_CANCELLED : ACBB_OK;
}
