/* acbb TUI — the accuracy benchmark in a background job (job.h; no curses
 * here).
 *
 * acbb_accuracy_run takes seconds to minutes. The job's thread owns the
 * rows it fills; the UI sees only the published state below: the phase,
 * "k of n settings" from the engine's progress callback, the rows finished
 * so far (their errors appear when the plan ends: they need the knob's
 * reference), and at the end the frontier. acbb_bench_free cancels and
 * joins. */
#ifndef ACBB_UI_BENCH_H
#define ACBB_UI_BENCH_H

#include "acbb/tools/accuracy.h"
#include "acbb/scene.h"
#include "acbb/status.h"
#include "job.h"

/* Every plan fits: 31 settings today (accuracy.c's plan table). */
#define ACBB_BENCH_MAX_ROWS 48

/* The job's phases under the benchmark's names. */
typedef acbb_job_phase acbb_bench_phase;
#define ACBB_BENCH_IDLE ACBB_JOB_IDLE           /* never started */
#define ACBB_BENCH_RUNNING ACBB_JOB_RUNNING
#define ACBB_BENCH_DONE ACBB_JOB_DONE           /* the plan ran (single settings may have failed) */
#define ACBB_BENCH_CANCELLED ACBB_JOB_CANCELLED /* stopped by acbb_bench_cancel */
#define ACBB_BENCH_FAILED ACBB_JOB_FAILED       /* refused before running (bad scene or options) */

/* Everything the UI may read, copied out in one go. */
typedef struct {
    acbb_bench_phase phase;
    int cancel_requested;        /* RUNNING, but a cancel is on its way */
    unsigned long run_id;        /* bumped by every start */
    unsigned long publications;  /* bumped by every publication */
    size_t done, total;          /* settings finished / planned */
    size_t n;                    /* rows[0..n) are valid */
    acbb_accuracy_row rows[ACBB_BENCH_MAX_ROWS];
    long picks[ACBB_KNOB_COUNT]; /* frontier (DONE only; else all -1) */
    acbb_accuracy_options opt;   /* what was asked (cancel hook cleared) */
    double started_s, ended_s;   /* CLOCK_MONOTONIC; ended_s = 0 while running */
    char message[512];           /* why it failed / "cancelled after ..." */
} acbb_bench_state;

typedef struct acbb_bench acbb_bench;

/* The frontier the screen recommends: acbb_accuracy_frontier with each
 * setting's cost taken as its place in the plan (cheapest-first by
 * design), not its measured wall time, so repeated runs of the same plan
 * recommend the same settings (two settings a few ms apart swapped with
 * timing noise). rows[0..n) are left unchanged. */
void acbb_bench_frontier(const acbb_accuracy_row *rows, size_t n, long picks[ACBB_KNOB_COUNT]);

/* Create the hand-off (no thread yet). */
acbb_status acbb_bench_new(acbb_bench **out, acbb_error *err);
/* Cancel a running benchmark, join its thread, free everything. NULL is a no-op. */
void acbb_bench_free(acbb_bench *b);

/* Start the plan of `opt` (its cancel field is ignored: the bench supplies
 * its own) on a copy of `scene`. ACBB_EINVAL while one is running, or for a
 * plan that does not fit; nothing changes then. */
acbb_status acbb_bench_start(acbb_bench *b, const acbb_scene *scene,
                             const acbb_accuracy_options *opt, acbb_error *err);
/* Ask the running benchmark to stop (it ends within one coupled step).
 * Returns 1 if one was running. */
int acbb_bench_cancel(acbb_bench *b);

/* Copy the published state. */
void acbb_bench_read(acbb_bench *b, acbb_bench_state *st);
/* Block until no benchmark is running or timeout_ms passed; 1 if idle. */
int acbb_bench_wait(acbb_bench *b, int timeout_ms);

/* Fd that becomes readable after a publication; drain it with
 * acbb_bench_drain_wake before reading the state. */
int acbb_bench_wake_fd(const acbb_bench *b);
void acbb_bench_drain_wake(acbb_bench *b);

const char *acbb_bench_phase_name(acbb_bench_phase p);

#endif
