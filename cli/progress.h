/* acbb CLI — watching and stopping a long run (issue "Nothing lost,
 * nothing overwritten, nothing hangs").
 *
 * Interrupts (issue 16: every long command cancels the same way):
 * acbb_cli_interrupt_begin installs one SIGINT+SIGTERM handler that sets
 * one flag, passed to the engine as its cancel flag (acbb_run_ctl.cancel,
 * acbb_sweep_opts.cancel, ...), so runs end within a step as
 * ACBB_CANCELLED. The first signal also restores the default actions: a
 * second one (either) kills at once. The handler is installed by the
 * command's first long phase and stays until the process ends (a signal
 * between two phases is a cancel, not a kill); acbb_cli_interrupt_end marks
 * a phase's end only. acbb_cli_cancelled then prints "acbb: CMD: cancelled
 * by SIGINT; <what was kept>" and returns ACBB_EXIT_CANCELLED (3).
 *
 * Progress: one line on stderr, rewritten in place (\r) at most four times a
 * second and erased at the end: step, residual vs the steady target,
 * simulated time and an ETA from a log-linear fit of the residual over wall
 * time. Shown when stderr is a terminal; ACBB_PROGRESS=1 forces it on (for
 * tests and logs), ACBB_PROGRESS=0 off. */
#ifndef ACBB_CLI_PROGRESS_H
#define ACBB_CLI_PROGRESS_H

#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include "acbb/sim.h"

/* Install the handlers (once); returns the flag they set, never cleared. */
const atomic_int *acbb_cli_interrupt_begin(void);
void acbb_cli_interrupt_end(void);
/* The flag itself (set or not), for a caller that did not begin. */
const atomic_int *acbb_cli_interrupt_flag(void);
/* Stop the engine through the same flag for the command's own reason (an
 * output it can no longer write): acbb_cli_interrupted() stays false and
 * acbb_cli_cancelled() silent; the command says why itself. */
void acbb_cli_interrupt_stop(void);
/* A signal set the flag. */
bool acbb_cli_interrupted(void);
/* "SIGINT" or "SIGTERM": the signal that set the flag. */
const char *acbb_cli_interrupt_name(void);
/* When a signal set the flag: the message on stderr (`kept`, may be NULL,
 * says what was written) and ACBB_EXIT_CANCELLED; else 0, silent. */
int acbb_cli_cancelled(const char *cmd, const char *kept);
/* {"status": "cancelled", "command", "signal", "message"} on f, for the
 * commands that print JSON. `cmd` and `kept` are plain text (no quotes). */
void acbb_cli_cancelled_json(FILE *f, const char *cmd, const char *kept);
/* Progress on f: it is a terminal, or ACBB_PROGRESS=1 (0 turns it off). */
bool acbb_cli_progress_wanted(FILE *f);

/* Weighted least squares of ln(residual) against wall seconds, older
 * points fading (the decay rate changes as the run settles). */
typedef struct {
    double s0, sx, sy, sxx, sxy;
    int n;
} acbb_cli_decay_fit;

typedef struct {
    FILE *f;
    bool on;
    double t0_ms, last_ms;
    double target;             /* fidelity steady_tol, K/s */
    int shown;                 /* length of the line on screen */
    const acbb_scene *schedule; /* a transient following a [schedule] (NULL: none): its row and speed shown */
    acbb_cli_decay_fit fit;
} acbb_cli_progress;

/* Whether to show progress on `f` (terminal or ACBB_PROGRESS). */
void acbb_cli_progress_init(acbb_cli_progress *p, FILE *f, double steady_tol);
/* Feed one step (every step: the fit uses them all); draws when due. */
void acbb_cli_progress_step(acbb_cli_progress *p, const acbb_snapshot *snap);
/* A one-off line (e.g. "setting up"), shown at once when progress is on. */
void acbb_cli_progress_note(acbb_cli_progress *p, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/* Erase the line. */
void acbb_cli_progress_end(acbb_cli_progress *p);

/* A batch's count on stderr when progress is wanted: "NAME: 12/48 runs,
 * 3.1 runs/s, ETA 12 s", the time left at the rate so far; redrawn at most
 * five times a second, the last call (done == total) ends the line
 * (issue 28 item 13: study showed nothing, sensitivity no ETA). */
typedef struct {
    bool show;
    double t0_ms, last_ms;
    const char *name;
} acbb_cli_counter;

/* Draw on the progress line (stderr, flushed): a command's own counter
 * (sweep, bench accuracy). Only progress.c and say.c write to stderr
 * (say.h). */
void acbb_cli_progress_draw(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

void acbb_cli_counter_init(acbb_cli_counter *c, const char *name);
void acbb_cli_counter_step(acbb_cli_counter *c, size_t done, size_t total);

/* Seconds until the residual reaches `target` at the fitted decay rate,
 * measured from wall second `now`; < 0 while not estimable (too few
 * points, or not decaying). */
double acbb_cli_decay_eta(const acbb_cli_decay_fit *fit, double now, double target);
void acbb_cli_decay_add(acbb_cli_decay_fit *fit, double t, double residual);

#endif
