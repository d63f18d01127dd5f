/* acbb — sweeps in N dimensions: the worker pool (sweep.h).
 *
 * The points to run are listed up front (shard, skip list, max_points), so
 * the set is decided before any thread starts; workers take the next one
 * from an atomic counter. Each worker owns one result buffer (a snapshot is
 * tens of kilobytes: no per-point allocation on a shared heap beyond what
 * the Sim itself needs) and takes the lock only to hand it to `done`. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/measure.h"
#include "acbb/sweep.h"

#define SWEEP_MAX_JOBS 256

typedef struct {
    const acbb_sweep *grid;
    const acbb_scene *base;
    const acbb_sweep_opts *o;
    const size_t *todo;
    size_t n_todo;
    atomic_size_t next;
    atomic_size_t reported;
    int sim_threads;            /* acbb_sim_opts.threads: 1 when points fill the cores */
    pthread_mutex_t lock;
} sweep_pool;

static int cancelled(const atomic_int *cancel)
{
    return cancel && atomic_load(cancel);
}

/* Edits, set-up and the run of one point into r. */
static void run_one(const sweep_pool *pl, size_t index, acbb_sweep_result *r)
{
    double t0 = acbb_now_ms();
    acbb_error err = { { 0 } };
    acbb_scene *sc = malloc(sizeof *sc);
    acbb_sim *sim = NULL;
    r->index = index;
    r->have_snap = 0;
    r->message[0] = '\0';
    r->status = sc ? acbb_sweep_scene(pl->grid, pl->base, index, sc, &err) : ACBB_ENOMEM;
    acbb_sim_opts so = { pl->o->cancel, pl->sim_threads };
    if (r->status == ACBB_OK) r->status = acbb_sim_create(sc, &so, &sim, &err);
    if (r->status == ACBB_OK) {
        acbb_run_ctl ctl = { .cancel = pl->o->cancel };
        r->status = acbb_sim_drive(sim, &ctl);
        acbb_sim_snapshot(sim, &r->snap);
        r->have_snap = 1;
    } else {
        snprintf(r->message, sizeof r->message, "%s",
                 err.msg[0] ? err.msg : acbb_status_name(r->status));
    }
    acbb_sim_free(sim);
    free(sc);
    r->wall_ms = acbb_now_ms() - t0;
}

static void *worker(void *arg)
{
    sweep_pool *pl = arg;
    acbb_sweep_result *r = malloc(sizeof *r);
    if (!r) return NULL;
    while (!cancelled(pl->o->cancel)) {
        size_t i = atomic_fetch_add(&pl->next, 1);
        if (i >= pl->n_todo) break;
        run_one(pl, pl->todo[i], r);
        /* A cancelled point is not a result: a resumed sweep runs it. */
        if (r->status == ACBB_CANCELLED) break;
        pthread_mutex_lock(&pl->lock);
        if (pl->o->done) pl->o->done(pl->o->ctx, r);
        pthread_mutex_unlock(&pl->lock);
        atomic_fetch_add(&pl->reported, 1);
    }
    free(r);
    return NULL;
}

static size_t list_todo(const acbb_sweep *g, const acbb_sweep_opts *o, size_t *todo)
{
    size_t n = 0, total = acbb_sweep_n_points(g);
    for (size_t i = 0; i < total; i++) {
        if (o->max_points && n == o->max_points) break;
        if (!acbb_sweep_in_shard(i, o->shard_k, o->shard_n) || (o->skip && o->skip[i])) continue;
        if (todo) todo[n] = i;
        n++;
    }
    return n;
}

size_t acbb_sweep_n_todo(const acbb_sweep *g, const acbb_sweep_opts *o)
{
    return list_todo(g, o, NULL);
}

static size_t n_threads(int jobs, size_t n_todo)
{
    long n = jobs > 0 ? jobs : sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) n = 1;
    if (n > SWEEP_MAX_JOBS) n = SWEEP_MAX_JOBS;
    return (size_t)n < n_todo ? (size_t)n : n_todo ? n_todo : 1;
}

acbb_status acbb_sweep_run(const acbb_sweep *g, const acbb_scene *base,
                           const acbb_sweep_opts *o, size_t *n_run)
{
    size_t n_todo = list_todo(g, o, NULL);
    size_t *todo = malloc((n_todo ? n_todo : 1) * sizeof *todo);
    if (!todo) return ACBB_ENOMEM;
    list_todo(g, o, todo);
    sweep_pool pl = { .grid = g, .base = base, .o = o, .todo = todo, .n_todo = n_todo };
    atomic_init(&pl.next, 0);
    atomic_init(&pl.reported, 0);
    pthread_mutex_init(&pl.lock, NULL);
    pthread_t tid[SWEEP_MAX_JOBS];
    size_t extra = n_threads(o->jobs, n_todo) - 1, started = 0;
    pl.sim_threads = extra > 0 ? 1 : 0;
    for (; started < extra; started++)
        if (pthread_create(&tid[started], NULL, worker, &pl) != 0) break;
    worker(&pl); /* the calling thread works too */
    for (size_t i = 0; i < started; i++) pthread_join(tid[i], NULL);
    pthread_mutex_destroy(&pl.lock);
    free(todo);
    size_t reported = atomic_load(&pl.reported);
    if (n_run) *n_run = reported;
    if (cancelled(o->cancel) && reported < n_todo) return ACBB_CANCELLED;
    return reported < n_todo ? ACBB_ENOMEM : ACBB_OK;
}
