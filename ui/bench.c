/* acbb TUI — the accuracy benchmark as a background job (see bench.h).
 *
 * The job (job.c) owns the thread, the lock and the wake-up pipe; this file
 * is what the benchmark adds: `scene`, `opt` and `work` are the thread's
 * while it runs (written before the start, read after the end), `st` is
 * the published copy behind the job's lock. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

struct acbb_bench {
    acbb_job *job;
    acbb_bench_state st;       /* published; job lock (its job fields are filled on read) */
    /* the job's thread only, while it runs */
    acbb_scene scene;
    acbb_accuracy_options opt;
    size_t total;
    acbb_accuracy_row work[ACBB_BENCH_MAX_ROWS];
    size_t n;
    long picks[ACBB_KNOB_COUNT];
};

const char *acbb_bench_phase_name(acbb_bench_phase p)
{
    return acbb_job_phase_name(p);
}

/* ---- the job's thread ---- */

/* The engine's progress callback, after each setting: publish the rows
 * finished since the last call (`work` is ours). */
static void on_progress(void *ctx, size_t done, size_t total)
{
    acbb_bench *b = ctx;
    acbb_job_lock(b->job);
    for (size_t i = b->st.n; i < done && i < ACBB_BENCH_MAX_ROWS; i++) b->st.rows[i] = b->work[i];
    b->st.n = done;
    b->st.done = done;
    b->st.total = total;
    acbb_job_unlock(b->job);
}

void acbb_bench_frontier(const acbb_accuracy_row *rows, size_t n, long picks[ACBB_KNOB_COUNT])
{
    acbb_accuracy_row *by_plan = malloc(n * sizeof *by_plan + 1);
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) picks[k] = -1;
    if (!by_plan) return;
    memcpy(by_plan, rows, n * sizeof *by_plan);
    for (size_t i = 0; i < n; i++)
        if (isfinite(by_plan[i].wall_ms)) by_plan[i].wall_ms = (double)i; /* plan order */
    acbb_accuracy_frontier(by_plan, n, ACBB_ACCURACY_FRONTIER_TOL, picks);
    free(by_plan);
}

static acbb_status run(void *ctx, const atomic_int *cancel, acbb_error *err)
{
    acbb_bench *b = ctx;
    b->opt.cancel = cancel;
    b->n = 0;
    acbb_status rc = acbb_accuracy_run(&b->scene, &b->opt, b->work, ACBB_BENCH_MAX_ROWS, &b->n,
                                       on_progress, b, err);
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) b->picks[k] = -1;
    if (rc == ACBB_OK) acbb_bench_frontier(b->work, b->n, b->picks);
    return rc;
}

static void begin(void *ctx)
{
    acbb_bench *b = ctx;
    b->st.done = 0;
    b->st.total = b->total;
    b->st.n = 0;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) b->st.picks[k] = -1;
    b->st.opt = b->opt;
    b->st.opt.cancel = NULL;
}

/* The final rows replace the published ones: only now are the errors known. */
static void end(void *ctx, acbb_status rc)
{
    acbb_bench *b = ctx;
    (void)rc;
    memcpy(b->st.rows, b->work, b->n * sizeof b->work[0]);
    b->st.n = b->n;
    memcpy(b->st.picks, b->picks, sizeof b->picks);
}

/* ---- client side ---- */

acbb_status acbb_bench_new(acbb_bench **out, acbb_error *err)
{
    *out = NULL;
    acbb_bench *b = calloc(1, sizeof *b);
    if (!b) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_status rc = acbb_job_new(&b->job, "benchmark", err);
    if (rc != ACBB_OK) {
        free(b);
        return rc;
    }
    b->st.phase = ACBB_BENCH_IDLE;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) b->st.picks[k] = -1;
    *out = b;
    return ACBB_OK;
}

acbb_status acbb_bench_start(acbb_bench *b, const acbb_scene *scene,
                             const acbb_accuracy_options *opt, acbb_error *err)
{
    if (!acbb_job_claim(b->job, err)) return ACBB_EINVAL;
    size_t total = acbb_accuracy_plan_size(opt);
    if (total == 0 || total > ACBB_BENCH_MAX_ROWS)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy plan of %zu settings: 1..%d supported",
                              total, ACBB_BENCH_MAX_ROWS);
    b->scene = *scene;
    b->opt = *opt;
    b->total = total;
    static const acbb_job_fns fns = { .run = run, .begin = begin, .end = end };
    return acbb_job_start(b->job, &fns, b, err);
}

int acbb_bench_cancel(acbb_bench *b)
{
    return acbb_job_cancel(b->job);
}

void acbb_bench_read(acbb_bench *b, acbb_bench_state *st)
{
    acbb_job_info info;
    acbb_job_read(b->job, &info, st, &b->st, sizeof *st);
    st->phase = info.phase;
    st->cancel_requested = info.cancel_requested;
    st->run_id = info.run_id;
    st->publications = info.publications;
    st->started_s = info.started_s;
    st->ended_s = info.ended_s;
    memcpy(st->message, info.message, sizeof st->message);
}

int acbb_bench_wait(acbb_bench *b, int timeout_ms)
{
    return acbb_job_wait(b->job, timeout_ms);
}

int acbb_bench_wake_fd(const acbb_bench *b)
{
    return acbb_job_wake_fd(b->job);
}

void acbb_bench_drain_wake(acbb_bench *b)
{
    acbb_job_drain_wake(b->job);
}

void acbb_bench_free(acbb_bench *b)
{
    if (!b) return;
    acbb_job_free(b->job);
    free(b);
}
