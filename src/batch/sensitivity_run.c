/* acbb — sensitivity: the pool that runs a list of scenes and reads the
 * metric of each (sensitivity.h). Every task is one Sim, private to its
 * thread, driven by acbb_sim_drive; workers take tasks from an atomic
 * counter and take the lock only to count progress and note the first
 * failure. The result of a task does not depend on the thread count. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/sensitivity.h"

#define SENS_MAX_JOBS 64

typedef struct {
    const acbb_scene *scenes;
    const acbb_sens_opts *o;
    size_t n_tasks, per_scene;   /* per_scene 2 with delta_te: TE then WTE */
    double *val;                 /* per task, NAN on failure */
    atomic_size_t next;
    size_t done;
    char *first_fail;
    size_t fail_n;
    int sim_threads;             /* acbb_sim_opts.threads: 1 when runs fill the cores */
    pthread_mutex_t lock;
} sens_pool;

static int cancelled(const atomic_int *c)
{
    return c && atomic_load(c);
}

/* One Sim: the task's scene (TE or WTE), run to the end, its metric. */
static acbb_status run_task(const sens_pool *pl, size_t t, acbb_snapshot *snap, double *v,
                            acbb_error *err)
{
    acbb_scene sc = pl->scenes[t / pl->per_scene];
    if (pl->per_scene == 2) sc.thermal_expansion = (t % 2) == 0;
    acbb_sim *sim = NULL;
    acbb_status st = acbb_sim_create(&sc, &(acbb_sim_opts){ pl->o->cancel, pl->sim_threads },
                                     &sim, err);
    if (st == ACBB_OK) {
        acbb_run_ctl ctl = {.cancel = pl->o->cancel};
        st = acbb_sim_drive(sim, &ctl);
        acbb_sim_snapshot(sim, snap);
        if (st == ACBB_OK && snap->state != ACBB_RUN_CONVERGED) st = ACBB_NOT_CONVERGED;
        if (st != ACBB_OK)
            acbb_error_set(err, st, "%s", snap->message[0] ? snap->message : acbb_status_name(st));
        else
            st = acbb_metric_value(snap, pl->o->metric, v, err);
    }
    acbb_sim_free(sim);
    return st;
}

static void *worker(void *arg)
{
    sens_pool *pl = arg;
    acbb_snapshot *snap = malloc(sizeof *snap);
    if (!snap) return NULL;
    while (!cancelled(pl->o->cancel)) {
        size_t t = atomic_fetch_add(&pl->next, 1);
        if (t >= pl->n_tasks) break;
        acbb_error err = {{0}};
        double v = NAN;
        acbb_status st = run_task(pl, t, snap, &v, &err);
        if (st == ACBB_CANCELLED) break;
        pl->val[t] = st == ACBB_OK && isfinite(v) ? v : NAN;
        pthread_mutex_lock(&pl->lock);
        if (st != ACBB_OK && pl->first_fail && !pl->first_fail[0])
            snprintf(pl->first_fail, pl->fail_n, "%s", err.msg[0] ? err.msg : acbb_status_name(st));
        size_t done = ++pl->done;
        if (pl->o->progress) pl->o->progress(pl->o->ctx, done, pl->n_tasks);
        pthread_mutex_unlock(&pl->lock);
    }
    free(snap);
    return NULL;
}

static size_t n_threads(int jobs, size_t n_tasks)
{
    long n = jobs > 0 ? jobs : sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1) n = 1;
    if (n > SENS_MAX_JOBS) n = SENS_MAX_JOBS;
    return (size_t)n < n_tasks ? (size_t)n : n_tasks ? n_tasks : 1;
}

acbb_status acbb_sens_eval(const acbb_scene *scenes, size_t n, const acbb_sens_opts *o,
                           double *y, char *first_fail, size_t fail_n, size_t *runs)
{
    size_t per = o->delta_te ? 2 : 1;
    sens_pool pl = {.scenes = scenes, .o = o, .n_tasks = n * per, .per_scene = per,
                    .first_fail = first_fail, .fail_n = fail_n};
    pl.val = malloc((pl.n_tasks ? pl.n_tasks : 1) * sizeof *pl.val);
    if (!pl.val) return ACBB_ENOMEM;
    for (size_t t = 0; t < pl.n_tasks; t++) pl.val[t] = NAN;
    if (first_fail && fail_n) first_fail[0] = '\0';
    atomic_init(&pl.next, 0);
    pthread_mutex_init(&pl.lock, NULL);
    pthread_t tid[SENS_MAX_JOBS];
    size_t extra = n_threads(o->jobs, pl.n_tasks) - 1, started = 0;
    pl.sim_threads = extra > 0 ? 1 : 0;
    for (; started < extra; started++)
        if (pthread_create(&tid[started], NULL, worker, &pl) != 0) break;
    worker(&pl); /* the calling thread works too */
    for (size_t i = 0; i < started; i++) pthread_join(tid[i], NULL);
    pthread_mutex_destroy(&pl.lock);
    for (size_t i = 0; i < n; i++) {
        double te = pl.val[per * i], wte = per == 2 ? pl.val[2 * i + 1] : 0.0;
        y[i] = per == 1 ? te : o->delta_rel ? (te - wte) / fabs(wte) : te - wte;
    }
    if (runs) *runs += pl.done;
    free(pl.val);
    if (cancelled(o->cancel)) return ACBB_CANCELLED;
    return pl.done < pl.n_tasks ? ACBB_ENOMEM : ACBB_OK;
}
