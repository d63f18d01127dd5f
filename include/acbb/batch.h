/* acbb — the batch runner: many independent runs on a pool of threads
 * (DESIGN.md "Batch runs", issue 16). Study, sweep, sensitivity,
 * robustness, the accuracy envelope, figures, the CLI's `study` and
 * `bench` and the TUI's TE/WTE compare all run their scenes here; this is
 * the only engine code that starts threads for runs.
 *
 * Each point is one Sim built from the scene the caller's `scene`
 * callback fills, driven by acbb_sim_drive on one worker, private to it.
 * The engine keeps no global mutable state that a result depends on (the
 * one it keeps, GSL's error handler, is off while any call works), so a
 * point's result does not depend on the number of workers or on which
 * worker ran it (tested bit for bit in tests/test_batch.c). Workers take
 * the next index from one atomic counter; the caller's thread works too.
 *
 * Jobs: 0 means acbb_batch_cpus(), the CPUs this process may run on (its
 * affinity mask: under `taskset -c 0` one worker), never more workers
 * than points. With more than one worker each Sim gets
 * acbb_sim_opts.threads = 1 (the pool already fills the cores).
 *
 * Steady or transient: a point whose transient nobody looks at can be
 * solved with the steady solve (fidelity.thermal_mode = steady): the same
 * steady state to about 5e-9 at a fraction of the cost for the scenes
 * that converge (BENCHMARKS.md "Batch runner"). It is NOT equivalent for
 * a scene the transient ends as `runaway`: the steady solve may find a
 * steady branch the run from ambient never reaches (the
 * runaway-rigid-preload preset converges at 59.7 W steady). Callers that
 * must catch a runaway ask for the transient.
 *
 * Ownership: nothing is kept after acbb_batch_run returns; the snapshot
 * handed to `done` belongs to the worker and is valid during the call. */
#ifndef ACBB_BATCH_H
#define ACBB_BATCH_H

#include "acbb/cancel_flag.h"
#include <stddef.h>
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CPUs the process may use (sched_getaffinity; sysconf when that fails), >= 1. */
int acbb_batch_cpus(void);

/* Workers a batch of n points with `jobs` (0: acbb_batch_cpus()) starts,
 * the caller's thread included: min(jobs, n), at least 1. */
int acbb_batch_workers(size_t n, int jobs);

/* ---- a parallel for, for work that is not one Sim run ---- */

typedef void (*acbb_batch_fn)(void *ctx, size_t i);

/* fn(ctx, i) once for each i < n, in any order, on acbb_batch_workers(n,
 * jobs) threads. Once `cancel` is set no further index starts. Returns how
 * many indices ran. */
size_t acbb_batch_for(size_t n, int jobs, acbb_batch_fn fn, void *ctx,
                      const acbb_atomic_int *cancel);

/* ---- Sim runs ---- */

/* A converged single bearing's temperatures and mechanics, kept to start
 * another run whose scene differs in values only (the same network,
 * balls, model and heating; else that run starts cold). A warm-started
 * steady solve converges to the same state to its tolerance (issue 30:
 * within 1e-8 relative where measured), by fewer iterations and without
 * the set-up's continuation in speed. Free with acbb_warm_free. */
typedef struct acbb_warm acbb_warm;
void acbb_warm_free(acbb_warm *w);

/* Point i's start (NULL: from ambient, as always); read on the worker
 * while the point sets up. Used for steady points: a transient's path
 * starts from ambient whatever is given; of a state kept by a transient
 * it takes the set-up's room-temperature mechanics at speed when its own
 * mechanics are built the same at the same speed (the same bits, issue
 * 30: the perturbed studies' transients). */
typedef const acbb_warm *(*acbb_batch_warm_fn)(void *ctx, size_t i);
/* Point i converged as a single bearing from no warm start: its state
 * (a transient's with its set-up's mechanics), now the callee's (a point
 * started from one keeps none). */
typedef void (*acbb_batch_keep_fn)(void *ctx, size_t i, acbb_warm *w);

typedef enum {
    ACBB_BATCH_AS_SCENE = 0,    /* fidelity.thermal_mode as the scene says */
    ACBB_BATCH_STEADY,          /* the steady solve (no transient to look at) */
    ACBB_BATCH_TRANSIENT        /* the time-marching transient from ambient */
} acbb_batch_mode;

/* Fill point i's scene into *out. *mode arrives as acbb_batch_opts.mode and
 * may be changed for this point. A failure (err set) is that point's
 * result; nothing runs for it. Called on a worker, without the lock. */
typedef acbb_status (*acbb_batch_scene_fn)(void *ctx, size_t i, acbb_scene *out,
                                           acbb_batch_mode *mode, acbb_error *err);

/* After point i's initial state and after every step (acbb_sim_drive's
 * hook), on the worker, without the lock: only point i's data may be
 * touched. */
typedef void (*acbb_batch_step_fn)(void *ctx, size_t i, const acbb_sim *sim);

/* Where point i's final snapshot is made (on the worker, without the
 * lock; only point i's data): the caller's record instead of the
 * worker's, so `done` need not copy it (a study point's, 21 kB). NULL:
 * the worker's. */
typedef acbb_snapshot *(*acbb_batch_snap_fn)(void *ctx, size_t i);

typedef struct {
    size_t index;
    int ran;                    /* 0: never started (a cancel came first: status ACBB_CANCELLED) */
    acbb_status status;         /* ACBB_OK: converged; else why not */
    const char *message;        /* why it failed or how it ended */
    const acbb_snapshot *snap;  /* final state (NULL when no Sim was built) */
    double wall_ms;             /* scene, set-up and run, CLOCK_MONOTONIC */
    size_t done, total;         /* points reported so far, this one included; n */
} acbb_batch_result;

/* Under the batch's one lock, one point at a time, in completion order;
 * every index is reported exactly once (ran or not). */
typedef void (*acbb_batch_done_fn)(void *ctx, const acbb_batch_result *r);

typedef struct {
    int jobs;                   /* workers (0: acbb_batch_cpus()) */
    const acbb_atomic_int *cancel;   /* set: stop (runs end ACBB_CANCELLED, the rest do not start) */
    acbb_batch_mode mode;       /* default for every point (the scene callback may change it) */
    acbb_batch_scene_fn scene;  /* required */
    acbb_batch_step_fn step;    /* may be NULL */
    acbb_batch_done_fn done;    /* may be NULL */
    void *ctx;                  /* passed to scene, step and done */
    int skip_stiffness;         /* acbb_sim_opts.skip_stiffness of every run */
    int skip_life;              /* acbb_sim_opts.skip_life of every run */
    int skip_liftoff;           /* acbb_sim_opts.skip_liftoff of every run */
    acbb_batch_warm_fn warm;    /* may be NULL: every point from ambient */
    acbb_batch_keep_fn keep;    /* may be NULL: no state kept */
    acbb_batch_snap_fn snap_to; /* may be NULL: the final snapshot is the worker's */
} acbb_batch_opts;

typedef struct {
    int workers;                /* threads that ran points, the caller's included */
    size_t ran, not_run;        /* ran + not_run = n */
    size_t failed;              /* ran and did not converge (cancelled ones included) */
} acbb_batch_stats;

/* Run points 0..n-1. Returns ACBB_CANCELLED when `cancel` was set before
 * every point had finished, else ACBB_OK (failed points are results, not
 * errors), ACBB_EINVAL without `scene`, ACBB_ENOMEM when the lock cannot be
 * made (nothing ran). `stats` may be NULL. */
acbb_status acbb_batch_run(size_t n, const acbb_batch_opts *o, acbb_batch_stats *stats);

#ifdef __cplusplus
}
#endif

#endif
