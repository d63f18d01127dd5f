/* acbb TUI — the accuracy benchmark thread and its hand-off (see bench.h).
 *
 * The same shape as worker.c (one mutex, a wake-up pipe), but simpler: the
 * thread lives for one plan only, so there is no command queue. The client
 * (the UI thread) owns `thread`/`has_thread`; the bench thread owns `scene`,
 * `opt` and `work` while it runs (written before pthread_create, read after
 * pthread_join); everything in `st` is behind `mu`. */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "acbb/measure.h"
#include "bench.h"
#include "wake.h"

struct acbb_bench {
    pthread_mutex_t mu;        /* guards st */
    pthread_cond_t cv_end;     /* a plan ended (acbb_bench_wait) */
    acbb_bench_state st;
    _Atomic int cancel;        /* the engine's cancel hook */
    acbb_wake wake;            /* the UI's select() wakes on it */
    /* client thread only */
    pthread_t thread;
    int has_thread;            /* created and not yet joined */
    /* bench thread only, while it runs */
    acbb_scene scene;
    acbb_accuracy_options opt;
    acbb_accuracy_row work[ACBB_BENCH_MAX_ROWS];
};

const char *acbb_bench_phase_name(acbb_bench_phase p)
{
    switch (p) {
    case ACBB_BENCH_IDLE: return "idle";
    case ACBB_BENCH_RUNNING: return "running";
    case ACBB_BENCH_DONE: return "done";
    case ACBB_BENCH_CANCELLED: return "cancelled";
    case ACBB_BENCH_FAILED: return "failed";
    }
    return "?";
}

/* ---- bench thread ---- */

static void wake_ui(acbb_bench *b) { acbb_wake_signal(&b->wake); }

/* The engine's progress callback, on the bench thread after each setting:
 * publish the rows finished since the last call (`work` is ours). */
static void on_progress(void *ctx, size_t done, size_t total)
{
    acbb_bench *b = ctx;
    pthread_mutex_lock(&b->mu);
    for (size_t i = b->st.n; i < done && i < ACBB_BENCH_MAX_ROWS; i++) b->st.rows[i] = b->work[i];
    b->st.n = done;
    b->st.done = done;
    b->st.total = total;
    b->st.publications++;
    pthread_mutex_unlock(&b->mu);
    wake_ui(b);
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

static void *bench_main(void *p)
{
    acbb_bench *b = p;
    acbb_error err = { { 0 } };
    size_t n = 0;
    long picks[ACBB_KNOB_COUNT];
    acbb_status rc = acbb_accuracy_run(&b->scene, &b->opt, b->work, ACBB_BENCH_MAX_ROWS, &n,
                                       on_progress, b, &err);
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) picks[k] = -1;
    if (rc == ACBB_OK) acbb_bench_frontier(b->work, n, picks);

    pthread_mutex_lock(&b->mu);
    /* The final rows replace the published ones: only now are the errors known. */
    memcpy(b->st.rows, b->work, n * sizeof b->work[0]);
    b->st.n = n;
    memcpy(b->st.picks, picks, sizeof picks);
    if (rc == ACBB_OK) b->st.phase = ACBB_BENCH_DONE;
    else b->st.phase = atomic_load(&b->cancel) ? ACBB_BENCH_CANCELLED : ACBB_BENCH_FAILED;
    memcpy(b->st.message, err.msg, sizeof b->st.message);
    b->st.ended_s = 1e-3 * acbb_now_ms();
    b->st.publications++;
    pthread_cond_broadcast(&b->cv_end);
    pthread_mutex_unlock(&b->mu);
    wake_ui(b);
    return NULL;
}

/* ---- client side ---- */

/* Non-blocking, close-on-exec pipe (as worker.c's: a full pipe must never
 * block the bench thread, and gnuplot children must not inherit it). */
acbb_status acbb_bench_new(acbb_bench **out, acbb_error *err)
{
    *out = NULL;
    acbb_bench *b = calloc(1, sizeof *b);
    if (!b) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (acbb_wake_init(&b->wake) != 0) {
        free(b);
        return acbb_error_set(err, ACBB_EIO, "cannot create the wake-up pipe: %s", strerror(errno));
    }
    pthread_condattr_t ca;
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    int rc = pthread_mutex_init(&b->mu, NULL) | pthread_cond_init(&b->cv_end, &ca);
    pthread_condattr_destroy(&ca);
    if (rc != 0) {
        acbb_wake_close(&b->wake);
        free(b);
        return acbb_error_set(err, ACBB_ENOMEM, "cannot initialise the benchmark's lock");
    }
    atomic_init(&b->cancel, 0);
    b->st.phase = ACBB_BENCH_IDLE;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) b->st.picks[k] = -1;
    *out = b;
    return ACBB_OK;
}

static int running(acbb_bench *b)
{
    pthread_mutex_lock(&b->mu);
    int r = b->st.phase == ACBB_BENCH_RUNNING;
    pthread_mutex_unlock(&b->mu);
    return r;
}

/* Reset the published state for a new plan of `total` settings. */
static void begin(acbb_bench *b, const acbb_accuracy_options *opt, size_t total)
{
    pthread_mutex_lock(&b->mu);
    b->st.phase = ACBB_BENCH_RUNNING;
    b->st.cancel_requested = 0;
    b->st.run_id++;
    b->st.publications++;
    b->st.done = 0;
    b->st.total = total;
    b->st.n = 0;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) b->st.picks[k] = -1;
    b->st.opt = *opt;
    b->st.opt.cancel = NULL;
    b->st.started_s = 1e-3 * acbb_now_ms();
    b->st.ended_s = 0.0;
    b->st.message[0] = '\0';
    pthread_mutex_unlock(&b->mu);
}

acbb_status acbb_bench_start(acbb_bench *b, const acbb_scene *scene,
                             const acbb_accuracy_options *opt, acbb_error *err)
{
    if (running(b))
        return acbb_error_set(err, ACBB_EINVAL, "a benchmark is already running (x cancels it)");
    if (b->has_thread) { /* the last plan's thread has published its end: reap it */
        pthread_join(b->thread, NULL);
        b->has_thread = 0;
    }
    size_t total = acbb_accuracy_plan_size(opt);
    if (total == 0 || total > ACBB_BENCH_MAX_ROWS)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy plan of %zu settings: 1..%d supported",
                              total, ACBB_BENCH_MAX_ROWS);
    b->scene = *scene;
    b->opt = *opt;
    b->opt.cancel = &b->cancel;
    atomic_store(&b->cancel, 0);
    begin(b, opt, total);

    /* The thread inherits this mask: terminal signals go to the UI thread. */
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigaddset(&block, SIGQUIT);
    sigaddset(&block, SIGWINCH);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    int rc = pthread_create(&b->thread, NULL, bench_main, b);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (rc != 0) {
        pthread_mutex_lock(&b->mu);
        b->st.phase = ACBB_BENCH_FAILED;
        b->st.ended_s = 1e-3 * acbb_now_ms();
        pthread_mutex_unlock(&b->mu);
        return acbb_error_set(err, ACBB_ENOMEM, "cannot start the benchmark thread: %s",
                              strerror(rc));
    }
    b->has_thread = 1;
    return ACBB_OK;
}

int acbb_bench_cancel(acbb_bench *b)
{
    pthread_mutex_lock(&b->mu);
    int r = b->st.phase == ACBB_BENCH_RUNNING;
    if (r) {
        atomic_store(&b->cancel, 1);
        b->st.cancel_requested = 1;
        b->st.publications++;
    }
    pthread_mutex_unlock(&b->mu);
    if (r) wake_ui(b);
    return r;
}

void acbb_bench_read(acbb_bench *b, acbb_bench_state *st)
{
    pthread_mutex_lock(&b->mu);
    *st = b->st;
    pthread_mutex_unlock(&b->mu);
}

int acbb_bench_wait(acbb_bench *b, int timeout_ms)
{
    struct timespec ts = acbb_wake_abstime(acbb_now_ms() + timeout_ms);
    pthread_mutex_lock(&b->mu);
    while (b->st.phase == ACBB_BENCH_RUNNING)
        if (pthread_cond_timedwait(&b->cv_end, &b->mu, &ts) == ETIMEDOUT) break;
    int idle = b->st.phase != ACBB_BENCH_RUNNING;
    pthread_mutex_unlock(&b->mu);
    return idle;
}

int acbb_bench_wake_fd(const acbb_bench *b)
{
    return b->wake.rd;
}

void acbb_bench_drain_wake(acbb_bench *b)
{
    acbb_wake_drain(&b->wake);
}

void acbb_bench_free(acbb_bench *b)
{
    if (!b) return;
    acbb_bench_cancel(b);
    if (b->has_thread) pthread_join(b->thread, NULL);
    acbb_wake_close(&b->wake);
    pthread_mutex_destroy(&b->mu);
    pthread_cond_destroy(&b->cv_end);
    free(b);
}
