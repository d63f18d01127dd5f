/* acbb TUI — the worker thread that owns the Sim (DESIGN.md "Threads in the TUI").
 *
 * One worker thread creates, steps and frees the acbb_sim; no other thread
 * touches engine state. The UI and the worker share only, behind ONE mutex:
 *   - a small FIFO of commands (start, pause, resume, stop, reset, apply,
 *     compare, quit), each numbered so a client can wait until it is done;
 *   - the published state: run phase, latest snapshot, a bounded history
 *     ring for the charts, and the TE-vs-WTE comparison result.
 * After every publication the worker writes one byte to a non-blocking
 * wake-up pipe (only if the previous byte was not yet drained) so the UI's
 * select() loop wakes and redraws. Publishing is a memcpy under the mutex;
 * the worker never waits for the UI. The pace (simulated seconds per wall
 * second, 0 = flat out) is an _Atomic the UI may change at any time.
 *
 * The worker advances every Sim only through the engine's run loop,
 * acbb_sim_drive, whose per-step hook publishes and paces. STOP and QUIT
 * also raise a cancel flag the moment they are posted, so they end a step
 * (or a Sim's set-up) in flight, e.g. a long dynamic-level window: the run
 * is then STOPPED with the snapshot status ACBB_CANCELLED ("cancelled")
 * and its last good state.
 *
 * The thread is created with SIGINT, SIGTERM, SIGHUP and SIGWINCH blocked
 * so those signals are always delivered to the UI thread.
 *
 * Ownership: acbb_worker_new copies the scene; acbb_worker_free stops and
 * joins the thread and frees everything. Copies handed out by
 * acbb_worker_read belong to the caller. */
#ifndef ACBB_UI_WORKER_H
#define ACBB_UI_WORKER_H

#include "acbb/tools/history.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/status.h"

typedef enum {
    ACBB_WORKER_IDLE,     /* a fresh Sim at ambient, not stepping (also after reset) */
    ACBB_WORKER_RUNNING,  /* stepping (flat out or paced) */
    ACBB_WORKER_PAUSED,   /* run in progress, not stepping */
    ACBB_WORKER_STOPPED,  /* run halted by the user (status "cancelled"); the last good state stays visible */
    ACBB_WORKER_DONE,     /* the run ended by itself: converged or a named failure */
    ACBB_WORKER_NO_SIM    /* the scene could not be compiled (message says why) */
} acbb_worker_phase;

typedef enum {
    ACBB_CMD_START,   /* cold run of the given scene from ambient */
    ACBB_CMD_PAUSE,
    ACBB_CMD_RESUME,
    ACBB_CMD_STOP,
    ACBB_CMD_RESET,   /* back to ambient with the current run's scene, IDLE */
    ACBB_CMD_APPLY,   /* restart with the given scene, warm or cold, and run */
    ACBB_CMD_COMPARE, /* run the scene with thermal expansion on and off */
    ACBB_CMD_QUIT,    /* used by acbb_worker_free */
    ACBB_CMD_SHOW     /* publish the chosen bearing's snapshot again (acbb_worker_set_bearing) */
} acbb_worker_cmd;

typedef enum { ACBB_CMP_NONE, ACBB_CMP_RUNNING, ACBB_CMP_DONE } acbb_compare_phase;

/* TE vs WTE: index 0 = thermal expansion on (TE), 1 = off (WTE). */
typedef struct {
    acbb_compare_phase phase;
    int done[2];                 /* variant finished (ok or not); both run at once */
    int ok[2];                   /* variant ran (its snapshot is valid) */
    acbb_snapshot snap[2];
    char message[256];           /* why a variant could not run */
} acbb_compare_result;

/* Everything the UI may read, copied out in one go. */
typedef struct {
    acbb_worker_phase phase;
    unsigned long cmd_done;      /* number of the last command handled */
    unsigned long publications;  /* bumped on every publication */
    unsigned long run_id;        /* bumped whenever a new run (or reset) begins */
    int pace;                    /* simulated s per wall s in force, 0 = flat out */
    double run_wall_s;           /* wall time spent running this run (pauses excluded) */
    double steps_per_s;          /* measured stepping rate (smoothed) */
    acbb_status last_error;      /* of the last failed command */
    unsigned long err_cmd;       /* its number (0: no command failed yet) */
    char message[256];           /* its message */
    acbb_scene scene;            /* the scene of the current run */
    int has_snapshot;
    acbb_snapshot snap;
    acbb_life set_life[ACBB_MAX_SET]; /* a set's: each bearing's life (snap.n_bearings of them) */
    acbb_compare_result compare;
} acbb_worker_state;

typedef struct acbb_worker acbb_worker;

/* Start the thread; it compiles `scene` into a Sim (phase IDLE, or NO_SIM
 * with the message if the scene is bad). `pace` as in acbb_worker_set_pace. */
acbb_status acbb_worker_new(const acbb_scene *scene, int pace, acbb_worker **out,
                            acbb_error *err);
/* Ask the thread to quit, join it, free everything. NULL is a no-op. */
void acbb_worker_free(acbb_worker *w);

/* Queue a command; `scene` is used by START, APPLY and COMPARE (NULL means
 * the current run's scene), `warm` by APPLY. Returns the command's number
 * (> 0), or 0 if the queue is full (the caller may retry). */
unsigned long acbb_worker_post(acbb_worker *w, acbb_worker_cmd cmd,
                               const acbb_scene *scene, int warm);

/* Simulated seconds per wall second (0 = flat out): after a step of dt
 * simulated seconds the worker waits dt / pace. Takes effect at once. */
void acbb_worker_set_pace(acbb_worker *w, int sim_s_per_s);
/* A bearing set (MODEL.md 14): publish bearing k's snapshot from now on
 * (acbb_sim_bearing_snapshot; 0 = the first, also for one bearing). */
void acbb_worker_set_bearing(acbb_worker *w, int k);
int acbb_worker_pace(const acbb_worker *w);
/* Wall ms a paced step of sim_dt simulated seconds is shown for at pace
 * `pace` (simulated s per wall s; 0: flat out, 0 ms): sim_dt / pace, but
 * at least ACBB_WORKER_STEP_FLOOR / pace (0.1 s at x200). Pure. */
#define ACBB_WORKER_STEP_FLOOR 20.0
double acbb_worker_step_ms(double sim_dt, int pace);

/* Copy the published state (and the history, if `hist` is not NULL). */
void acbb_worker_read(acbb_worker *w, acbb_worker_state *st, acbb_history *hist);

/* Fd that becomes readable after a publication; drain it with
 * acbb_worker_drain_wake before reading the state. */
int acbb_worker_wake_fd(const acbb_worker *w);
void acbb_worker_drain_wake(acbb_worker *w);

/* Block until command `seq` has been handled or `timeout_ms` passed.
 * Returns 1 when done, 0 on timeout. (For tests and for quitting.) When
 * it returns 1, the command's wake-ups are already on the wake fd. */
int acbb_worker_wait_done(acbb_worker *w, unsigned long seq, int timeout_ms);

const char *acbb_worker_phase_name(acbb_worker_phase p);

#endif
