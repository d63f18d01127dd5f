/* acbb TUI — one background job at a time on its own thread, handed over
 * to the UI under one mutex (no curses here).
 *
 * The long analyses (the accuracy benchmark, a sweep, a sensitivity run)
 * take seconds to minutes, so they never run on the UI thread, nor on the
 * Sim worker (that would freeze the run screens). Each start creates one
 * short-lived thread; its owner keeps the data the thread fills (private to
 * the thread while it runs) and the published copy the UI reads, which is
 * guarded by the job's mutex: the owner's callbacks below run with it held,
 * and acbb_job_lock / acbb_job_unlock take it for a publication. Each
 * publication writes one byte to a non-blocking wake-up pipe so the UI's
 * select() loop redraws. Cancelling stores into the _Atomic the engine
 * polls (within one coupled step, acbb_sim_drive's cancel).
 *
 * The thread is created with SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGWINCH
 * blocked so those signals stay with the UI thread. acbb_job_free cancels
 * and joins. */
#ifndef ACBB_UI_JOB_H
#define ACBB_UI_JOB_H

#include <stdatomic.h>
#include <stddef.h>
#include "acbb/status.h"

typedef enum {
    ACBB_JOB_IDLE,       /* never started */
    ACBB_JOB_RUNNING,
    ACBB_JOB_DONE,       /* it ran (single points may have failed) */
    ACBB_JOB_CANCELLED,  /* stopped by acbb_job_cancel */
    ACBB_JOB_FAILED      /* refused or broke off (message says why) */
} acbb_job_phase;

/* What every job publishes. */
typedef struct {
    acbb_job_phase phase;
    int cancel_requested;        /* RUNNING, but a cancel is on its way */
    unsigned long run_id;        /* bumped by every start */
    unsigned long publications;  /* bumped by every publication */
    double started_s, ended_s;   /* CLOCK_MONOTONIC; ended_s = 0 while running */
    char message[512];           /* why it failed */
} acbb_job_info;

typedef struct {
    /* On the job's thread: the work. Returns ACBB_OK, or an error with err
     * set (ACBB_CANCELLED when `cancel` stopped it). */
    acbb_status (*run)(void *ctx, const atomic_int *cancel, acbb_error *err);
    /* Lock held, on the starting thread: reset the published copy. NULL: none. */
    void (*begin)(void *ctx);
    /* Lock held, on the job's thread, after run: publish the final result
     * (in the same critical section as the phase change). NULL: none. */
    void (*end)(void *ctx, acbb_status rc);
} acbb_job_fns;

typedef struct acbb_job acbb_job;

/* `what` names the job in messages ("benchmark", "sweep"): a static string. */
acbb_status acbb_job_new(acbb_job **out, const char *what, acbb_error *err);
/* Cancel a running job, join its thread, free everything. NULL is a no-op. */
void acbb_job_free(acbb_job *j);

/* 1 if no job is running; the last one's thread is joined, so the owner
 * may refill its thread-private data. 0 (err set) while one runs. */
int acbb_job_claim(acbb_job *j, acbb_error *err);
/* Start fns->run(ctx) on a new thread (call acbb_job_claim first). */
acbb_status acbb_job_start(acbb_job *j, const acbb_job_fns *fns, void *ctx, acbb_error *err);
/* Ask the running job to stop; returns 1 if one was running. */
int acbb_job_cancel(acbb_job *j);
/* Block until no job is running or timeout_ms passed; 1 if idle. */
int acbb_job_wait(acbb_job *j, int timeout_ms);

/* A publication from the job's thread: lock, write the owner's published
 * copy, unlock (which counts it and wakes the UI). */
void acbb_job_lock(acbb_job *j);
void acbb_job_unlock(acbb_job *j);
/* The UI's read: *info gets the job's part and dst the owner's published
 * copy at src (n bytes), both under the lock. */
void acbb_job_read(acbb_job *j, acbb_job_info *info, void *dst, const void *src, size_t n);

/* Fd that becomes readable after a publication; drain it before reading. */
int acbb_job_wake_fd(const acbb_job *j);
void acbb_job_drain_wake(acbb_job *j);

const char *acbb_job_phase_name(acbb_job_phase p);

#endif
