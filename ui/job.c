/* acbb TUI — the background job thread and its hand-off (see job.h).
 *
 * The same shape as worker.c (one mutex, a wake-up pipe), but simpler: the
 * thread lives for one job only, so there is no command queue. The client
 * (the UI thread) owns `thread`/`has_thread`; `fns` and `ctx` are written
 * before the thread is created and read by it; `info` is behind `mu`. */
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "acbb/tools/measure.h"
#include "job.h"
#include "wake.h"

struct acbb_job {
    pthread_mutex_t mu;        /* guards info and the owner's published copy */
    pthread_cond_t cv_end;     /* a job ended (acbb_job_wait) */
    acbb_job_info info;
    atomic_int cancel;         /* the engine's cancel hook */
    acbb_wake wake;            /* the UI's select() wakes on it */
    const char *what;
    /* client thread only */
    pthread_t thread;
    int has_thread;            /* created and not yet joined */
    /* read by the job's thread */
    acbb_job_fns fns;
    void *ctx;
};

const char *acbb_job_phase_name(acbb_job_phase p)
{
    switch (p) {
    case ACBB_JOB_IDLE: return "idle";
    case ACBB_JOB_RUNNING: return "running";
    case ACBB_JOB_DONE: return "done";
    case ACBB_JOB_CANCELLED: return "cancelled";
    case ACBB_JOB_FAILED: return "failed";
    }
    return "?";
}

/* ---- the job's thread ---- */

void acbb_job_lock(acbb_job *j)
{
    pthread_mutex_lock(&j->mu);
}

/* The wake-up before the unlock that makes the publication visible: whoever
 * reads it (acbb_job_wait, a read) finds its byte already in the pipe, and
 * a drain after the read leaves no stale byte (as worker.c's wake_ui). */
void acbb_job_unlock(acbb_job *j)
{
    j->info.publications++;
    acbb_wake_signal(&j->wake);
    pthread_mutex_unlock(&j->mu);
}

static void *job_main(void *p)
{
    acbb_job *j = p;
    acbb_error err = { { 0 } };
    acbb_status rc = j->fns.run(j->ctx, &j->cancel, &err);
    acbb_job_lock(j);
    if (j->fns.end) j->fns.end(j->ctx, rc);
    if (rc == ACBB_OK) j->info.phase = ACBB_JOB_DONE;
    else j->info.phase = atomic_load(&j->cancel) ? ACBB_JOB_CANCELLED : ACBB_JOB_FAILED;
    memcpy(j->info.message, err.msg, sizeof j->info.message);
    j->info.ended_s = 1e-3 * acbb_now_ms();
    pthread_cond_broadcast(&j->cv_end);
    acbb_job_unlock(j);
    return NULL;
}

/* ---- client side ---- */

/* Non-blocking, close-on-exec pipe (as worker.c's: a full pipe must never
 * block the job's thread, and gnuplot children must not inherit it). */
acbb_status acbb_job_new(acbb_job **out, const char *what, acbb_error *err)
{
    *out = NULL;
    acbb_job *j = calloc(1, sizeof *j);
    if (!j) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (acbb_wake_init(&j->wake) != 0) {
        free(j);
        return acbb_error_set(err, ACBB_EIO, "cannot create the wake-up pipe: %s", strerror(errno));
    }
    pthread_condattr_t ca;
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    int rc = pthread_mutex_init(&j->mu, NULL) | pthread_cond_init(&j->cv_end, &ca);
    pthread_condattr_destroy(&ca);
    if (rc != 0) {
        acbb_wake_close(&j->wake);
        free(j);
        return acbb_error_set(err, ACBB_ENOMEM, "cannot initialise the %s's lock", what);
    }
    atomic_init(&j->cancel, 0);
    j->what = what;
    j->info.phase = ACBB_JOB_IDLE;
    *out = j;
    return ACBB_OK;
}

int acbb_job_claim(acbb_job *j, acbb_error *err)
{
    pthread_mutex_lock(&j->mu);
    int running = j->info.phase == ACBB_JOB_RUNNING;
    pthread_mutex_unlock(&j->mu);
    if (running) {
        acbb_error_set(err, ACBB_EINVAL, "a %s is already running (x cancels it)", j->what);
        return 0;
    }
    if (j->has_thread) { /* the last job's thread has published its end: reap it */
        pthread_join(j->thread, NULL);
        j->has_thread = 0;
    }
    return 1;
}

static void begin(acbb_job *j)
{
    pthread_mutex_lock(&j->mu);
    j->info.phase = ACBB_JOB_RUNNING;
    j->info.cancel_requested = 0;
    j->info.run_id++;
    j->info.publications++;
    j->info.started_s = 1e-3 * acbb_now_ms();
    j->info.ended_s = 0.0;
    j->info.message[0] = '\0';
    if (j->fns.begin) j->fns.begin(j->ctx);
    pthread_mutex_unlock(&j->mu);
}

acbb_status acbb_job_start(acbb_job *j, const acbb_job_fns *fns, void *ctx, acbb_error *err)
{
    if (!acbb_job_claim(j, err)) return ACBB_EINVAL;
    j->fns = *fns;
    j->ctx = ctx;
    atomic_store(&j->cancel, 0);
    begin(j);
    /* Terminal signals go to the UI thread (blocked in this one). */
    int rc = acbb_thread_start(&j->thread, job_main, j);
    if (rc != 0) {
        pthread_mutex_lock(&j->mu);
        j->info.phase = ACBB_JOB_FAILED;
        j->info.ended_s = 1e-3 * acbb_now_ms();
        pthread_mutex_unlock(&j->mu);
        return acbb_error_set(err, ACBB_ENOMEM, "cannot start the %s thread: %s", j->what,
                              strerror(rc));
    }
    j->has_thread = 1;
    return ACBB_OK;
}

int acbb_job_cancel(acbb_job *j)
{
    pthread_mutex_lock(&j->mu);
    int r = j->info.phase == ACBB_JOB_RUNNING;
    if (r) {
        atomic_store(&j->cancel, 1);
        j->info.cancel_requested = 1;
        acbb_job_unlock(j);
    } else {
        pthread_mutex_unlock(&j->mu);
    }
    return r;
}

void acbb_job_read(acbb_job *j, acbb_job_info *info, void *dst, const void *src, size_t n)
{
    pthread_mutex_lock(&j->mu);
    *info = j->info;
    memcpy(dst, src, n);
    pthread_mutex_unlock(&j->mu);
}

int acbb_job_wait(acbb_job *j, int timeout_ms)
{
    struct timespec ts = acbb_wake_abstime(acbb_now_ms() + timeout_ms);
    pthread_mutex_lock(&j->mu);
    while (j->info.phase == ACBB_JOB_RUNNING)
        if (pthread_cond_timedwait(&j->cv_end, &j->mu, &ts) == ETIMEDOUT) break;
    int idle = j->info.phase != ACBB_JOB_RUNNING;
    pthread_mutex_unlock(&j->mu);
    return idle;
}

int acbb_job_wake_fd(const acbb_job *j)
{
    return j->wake.rd;
}

void acbb_job_drain_wake(acbb_job *j)
{
    acbb_wake_drain(&j->wake);
}

void acbb_job_free(acbb_job *j)
{
    if (!j) return;
    acbb_job_cancel(j);
    if (j->has_thread) pthread_join(j->thread, NULL);
    acbb_wake_close(&j->wake);
    pthread_mutex_destroy(&j->mu);
    pthread_cond_destroy(&j->cv_end);
    free(j);
}
