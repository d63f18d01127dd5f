/* acbb TUI — the worker thread and its hand-off (see worker.h).
 *
 * The idea follows cmus's player_info: the worker fills a shared struct
 * under one mutex and pokes a pipe; the UI copies the struct out once per
 * frame. Everything the worker alone touches (the Sims, timing) lives in
 * a worker_ctx on the worker's own stack, so the shared part is exactly
 * what is behind the mutex.
 *
 * The main run advances only through the engine's one run loop,
 * acbb_sim_drive; the TE/WTE variants run on the engine's batch runner
 * (batch.h) from a comparison thread of their own, so the worker keeps
 * handling commands meanwhile. The main run's per-step hook publishes,
 * sleeps out the pace on the condition variable (so a command still wakes
 * it) and returns nonzero when a command is queued: the drive returns, the
 * loop below handles the command and drives again. STOP and QUIT also set
 * the cancel flag the drive and the Sim's set-up watch, so they end even a
 * long dynamic-level step at once with ACBB_CANCELLED and the last good
 * state (DESIGN.md "Threads in the TUI"). */
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "acbb/batch.h"
#include "acbb/tools/measure.h"
#include "worker.h"
#include "wake.h"

#define QUEUE_CAP 16
#define RATE_WINDOW_MS 250.0 /* steps/s is measured over windows this long */

typedef struct {
    acbb_worker_cmd cmd;
    int warm;
    int has_scene;
    unsigned long seq;
    acbb_scene scene;
} queued_cmd;

struct acbb_worker {
    pthread_t thread;
    pthread_mutex_t mu;        /* the ONE lock: guards queue, st, hist, next_seq */
    pthread_cond_t cv_cmd;     /* worker waits for a command or its pace timer */
    pthread_cond_t cv_done;    /* clients wait for cmd_done */
    queued_cmd q[QUEUE_CAP];
    int q_head, q_len;
    unsigned long next_seq;
    acbb_worker_state st;
    acbb_history hist;
    acbb_scene initial;        /* read by the worker once at start-up */
    _Atomic int pace;          /* simulated s per wall s, 0 = flat out */
    _Atomic int bearing;       /* the bearing of a set whose snapshot is published */
    /* Set by the posting thread (STOP: run; QUIT: both), cleared by the
     * worker when it begins the next run / comparison. */
    atomic_int cancel_run;     /* the main Sim's drive and set-up */
    atomic_int cancel_cmp;     /* the TE/WTE variants' */
    acbb_wake wake;            /* the UI's select() wakes on it */
    /* The comparison's own (worker_ctx starts and joins its thread):
     * cmp_scene is written before the thread starts, read-only after;
     * cmp_step[v] belongs to the batch worker running variant v. */
    acbb_scene cmp_scene;
    acbb_snapshot cmp_step[2];
};

/* Worker-private: only the worker thread touches these. */
typedef struct {
    acbb_sim *sim;
    acbb_scene scene;
    acbb_worker_phase phase;
    acbb_snapshot snap;
    acbb_snapshot other;       /* another bearing of a set, for its life (take_snapshot) */
    acbb_life set_life[ACBB_MAX_SET]; /* each bearing's life (a set; else unused) */
    double last_step;          /* acbb_now_ms of the last step (pacing) */
    double seg_start, wall_acc;/* running wall time (ms), pauses excluded */
    double rate_t0, rate;      /* steps/s measurement window (t0 in ms) */
    long rate_n;
    /* TE vs WTE comparison: its thread, started and joined here */
    pthread_t cmp_thread;
    int cmp_started;
} worker_ctx;

/* Copy a message, truncating to fit (strncpy warns and may not terminate). */
static void copy_text(char *dst, size_t n, const char *src)
{
    size_t len = strnlen(src, n - 1);
    memcpy(dst, src, len);
    dst[len] = '\0';
}

const char *acbb_worker_phase_name(acbb_worker_phase p)
{
    switch (p) {
    case ACBB_WORKER_IDLE: return "ready";
    case ACBB_WORKER_RUNNING: return "running";
    case ACBB_WORKER_PAUSED: return "paused";
    case ACBB_WORKER_STOPPED: return "stopped";
    case ACBB_WORKER_DONE: return "done";
    case ACBB_WORKER_NO_SIM: return "no sim";
    }
    return "?";
}

/* ---- publication (worker side) ---- */

/* Called with w->mu held, before the unlock that makes a publication
 * visible: whoever reads it (acbb_worker_read, acbb_worker_wait_done)
 * finds its wake-up byte already in the pipe, so a drain after the read
 * leaves no stale byte behind. (Written after the unlock, it could land
 * after such a drain: test_worker's quiet check failed so on a loaded
 * machine.) A byte on a non-blocking pipe: nothing waits under the lock. */
static void wake_ui(acbb_worker *w) { acbb_wake_signal(&w->wake); }

static double run_wall(const worker_ctx *c, double now)
{
    return 1e-3 * (c->wall_acc + (c->phase == ACBB_WORKER_RUNNING ? now - c->seg_start : 0.0));
}

/* Copy the worker's view into the shared state. Called with w->mu held. */
static void publish_locked(acbb_worker *w, const worker_ctx *c, int with_snapshot)
{
    w->st.phase = c->phase;
    w->st.pace = atomic_load(&w->pace);
    w->st.run_wall_s = run_wall(c, acbb_now_ms());
    w->st.steps_per_s = c->rate;
    if (with_snapshot && c->sim) {
        w->st.snap = c->snap;
        memcpy(w->st.set_life, c->set_life, sizeof w->st.set_life);
        w->st.has_snapshot = 1;
    }
    w->st.publications++;
}

static void publish(acbb_worker *w, const worker_ctx *c, int push_history)
{
    pthread_mutex_lock(&w->mu);
    publish_locked(w, c, 1);
    if (push_history) acbb_history_push(&w->hist, &c->snap);
    wake_ui(w);
    pthread_mutex_unlock(&w->mu);
}

/* ---- phase bookkeeping (worker side) ---- */

static void set_phase(worker_ctx *c, acbb_worker_phase p)
{
    double t = acbb_now_ms();
    if (c->phase == ACBB_WORKER_RUNNING && p != ACBB_WORKER_RUNNING)
        c->wall_acc += t - c->seg_start;
    if (c->phase != ACBB_WORKER_RUNNING && p == ACBB_WORKER_RUNNING) {
        c->seg_start = t;
        c->last_step = t - 1e12; /* first step is due at once */
        c->rate_t0 = t;
        c->rate_n = 0;
    }
    c->phase = p;
}

/* The snapshot of the bearing the UI chose (a set's; else the run's), and
 * of a set every bearing's life for the Set screen's table (each bearing's
 * own snapshot carries it: acbb_sim_bearing_snapshot). */
static void take_snapshot(acbb_worker *w, const acbb_sim *sim, worker_ctx *c)
{
    acbb_snapshot *s = &c->snap;
    int k = atomic_load(&w->bearing);
    if (k <= 0 || acbb_sim_bearing_snapshot(sim, k, s) != ACBB_OK) acbb_sim_snapshot(sim, s);
    for (int b = 0; b < s->n_bearings && b < ACBB_MAX_SET && s->n_bearings > 1; b++) {
        if (b == k) c->set_life[b] = s->life;
        else if (acbb_sim_bearing_snapshot(sim, b, &c->other) == ACBB_OK) c->set_life[b] = c->other.life;
    }
}

/* A new run (or a reset) begins: fresh history seeded with the initial state. */
static void begin_run(acbb_worker *w, worker_ctx *c, acbb_worker_phase p)
{
    c->phase = ACBB_WORKER_IDLE;
    c->wall_acc = 0.0;
    c->rate = 0.0;
    set_phase(c, p);
    take_snapshot(w, c->sim, c);
    /* Run id, scene, snapshot and history change together, so a reader
     * never sees the new run's id with the old run's numbers. */
    pthread_mutex_lock(&w->mu);
    acbb_history_init(&w->hist);
    acbb_history_push(&w->hist, &c->snap);
    w->st.run_id++;
    w->st.scene = c->scene;
    publish_locked(w, c, 1);
    pthread_mutex_unlock(&w->mu);
}

/* A new run or comparison begins: forget an earlier STOP/QUIT unless one
 * is still queued behind this command (then the set-up is cut short and
 * that command handled next). `quit_only`: only QUIT counts (comparisons
 * ignore STOP, which is about the main run). */
static void rearm_cancel(acbb_worker *w, atomic_int *flag, int quit_only)
{
    pthread_mutex_lock(&w->mu);
    int pending = 0;
    for (int i = 0; i < w->q_len; i++) {
        acbb_worker_cmd k = w->q[(w->q_head + i) % QUEUE_CAP].cmd;
        pending |= k == ACBB_CMD_QUIT || (!quit_only && k == ACBB_CMD_STOP);
    }
    if (!pending) atomic_store(flag, 0);
    pthread_mutex_unlock(&w->mu);
}

/* (Re)build the Sim for `s`: restart in place when one exists so a failure
 * leaves the current run untouched (acbb_sim_restart's contract). The Sim
 * keeps the cancel flag it was made with, so a stop or quit also cuts a
 * long set-up (the initial dynamic-level window) short. */
static acbb_status load_scene(acbb_worker *w, worker_ctx *c, const acbb_scene *s, int warm,
                              acbb_error *err)
{
    acbb_status rc;
    rearm_cancel(w, &w->cancel_run, 0);
    if (c->sim)
        rc = acbb_sim_restart(c->sim, s, warm, err);
    else
        rc = acbb_sim_create(s, &(acbb_sim_opts){ .cancel = &w->cancel_run }, &c->sim, err);
    if (rc == ACBB_CANCELLED)
        acbb_error_set(err, rc, "run set-up cancelled by stop/quit; the previous state is kept");
    if (rc == ACBB_OK) c->scene = *s;
    return rc;
}

/* ---- the drive hook's pace (worker side) ---- */

typedef struct {
    acbb_worker *w;
    worker_ctx *c;
} hook_ctx;

double acbb_worker_step_ms(double sim_dt, int pace)
{
    if (pace <= 0 || !(sim_dt > 0)) return 0.0;
    /* At least ACBB_WORKER_STEP_FLOOR simulated-second-equivalents per step:
     * a run that ends after a few simulated seconds (the runaway, 24 s in
     * 78 steps) stays on screen long enough to watch (issue 21 item 7). */
    double by_time = 1e3 * sim_dt / pace, floor = 1e3 * ACBB_WORKER_STEP_FLOOR / pace;
    return by_time > floor ? by_time : floor;
}

/* Sleep until the next step is due: `sim_dt` simulated seconds (the step
 * just taken) after `last_step` (ms), at the pace in force; on the
 * condition variable so a command or a pace change wakes it at once.
 * Returns 1 as soon as a command is queued (the hook then pauses the
 * drive so the command is handled), 0 when the next step is due. */
static int wait_step_due(acbb_worker *w, double last_step, double sim_dt)
{
    int paced = sim_dt > 0;
    int cmd;
    pthread_mutex_lock(&w->mu);
    for (;;) {
        if ((cmd = w->q_len > 0)) break;
        int pace = paced ? atomic_load(&w->pace) : 0;
        if (pace <= 0) break;
        double due = last_step + acbb_worker_step_ms(sim_dt, pace);
        if (acbb_now_ms() >= due) break;
        struct timespec ts = acbb_wake_abstime(due);
        pthread_cond_timedwait(&w->cv_cmd, &w->mu, &ts);
    }
    pthread_mutex_unlock(&w->mu);
    return cmd;
}

/* ---- comparison (its own thread, on the batch runner) ---- */

/* Called with w->mu held: count the publication, wake the UI, unlock
 * (the wake-up first: see wake_ui). */
static void compare_publish_unlock(acbb_worker *w)
{
    w->st.publications++;
    wake_ui(w);
    pthread_mutex_unlock(&w->mu);
}

static acbb_status compare_scene(void *ctx, size_t v, acbb_scene *out, acbb_batch_mode *mode,
                                 acbb_error *err)
{
    (void)err;
    *mode = ACBB_BATCH_AS_SCENE; /* what the main run of this scene shows */
    *out = ((const acbb_worker *)ctx)->cmp_scene;
    out->thermal_expansion = v == 0;
    return ACBB_OK;
}

/* After each step of variant v, on its batch worker: progress every so
 * often (cmp_step[v] is that worker's alone). */
static void compare_step(void *ctx, size_t v, const acbb_sim *sim)
{
    acbb_worker *w = ctx;
    acbb_sim_snapshot(sim, &w->cmp_step[v]);
    if (w->cmp_step[v].iteration % 16 != 0) return;
    pthread_mutex_lock(&w->mu);
    w->st.compare.snap[v] = w->cmp_step[v];
    compare_publish_unlock(w);
}

static void compare_done(void *ctx, const acbb_batch_result *r)
{
    acbb_worker *w = ctx;
    acbb_compare_result *c = &w->st.compare;
    pthread_mutex_lock(&w->mu);
    c->done[r->index] = 1;
    c->ok[r->index] = r->snap != NULL;
    if (r->snap) c->snap[r->index] = *r->snap;
    else copy_text(c->message, sizeof c->message, r->message);
    compare_publish_unlock(w);
}

/* Both variants side by side (as many at once as the CPUs allow), on a
 * thread of their own so the worker keeps handling commands. */
static void *compare_main(void *arg)
{
    acbb_worker *w = arg;
    acbb_batch_opts o = { .cancel = &w->cancel_cmp, .scene = compare_scene,
                          .step = compare_step, .done = compare_done, .ctx = w };
    acbb_batch_run(2, &o, NULL);
    pthread_mutex_lock(&w->mu);
    w->st.compare.phase = ACBB_CMP_DONE;
    compare_publish_unlock(w);
    return NULL;
}

/* End a comparison in flight (worker side). */
static void compare_join(acbb_worker *w, worker_ctx *c)
{
    if (!c->cmp_started) return;
    atomic_store(&w->cancel_cmp, 1);
    pthread_join(c->cmp_thread, NULL);
    c->cmp_started = 0;
}

static void compare_begin(acbb_worker *w, worker_ctx *c, const acbb_scene *s)
{
    compare_join(w, c);
    rearm_cancel(w, &w->cancel_cmp, 1);
    w->cmp_scene = *s; /* read by the comparison thread, started below */
    pthread_mutex_lock(&w->mu);
    memset(&w->st.compare, 0, sizeof w->st.compare);
    w->st.compare.phase = ACBB_CMP_RUNNING;
    pthread_mutex_unlock(&w->mu);
    c->cmp_started = acbb_thread_start(&c->cmp_thread, compare_main, w) == 0;
    if (c->cmp_started) return;
    pthread_mutex_lock(&w->mu);
    w->st.compare.phase = ACBB_CMP_DONE;
    copy_text(w->st.compare.message, sizeof w->st.compare.message,
              "could not start the comparison's thread");
    pthread_mutex_unlock(&w->mu);
}

/* ---- the main run (worker side) ---- */

static void measure_rate(worker_ctx *c, double t)
{
    c->rate_n++;
    if (t - c->rate_t0 >= RATE_WINDOW_MS) {
        c->rate = 1e3 * (double)c->rate_n / (t - c->rate_t0);
        c->rate_t0 = t;
        c->rate_n = 0;
    }
}

/* After each step of the main run (and once at iteration 0): publish the
 * new state with its history point, then wait out the pace. */
static int run_hook(void *ctx, const acbb_sim *sim)
{
    hook_ctx *h = ctx;
    worker_ctx *c = h->c;
    long before = c->snap.iteration;
    double t_before = c->snap.time, sim_dt = 0.0;
    take_snapshot(h->w, sim, c);
    if (c->snap.iteration != before) { /* iteration 0 was published by begin_run */
        sim_dt = c->snap.time - t_before;
        double t = acbb_now_ms();
        c->last_step = t;
        measure_rate(c, t);
        publish(h->w, c, 1);
    }
    return wait_step_due(h->w, c->last_step, sim_dt);
}

/* Drive the main run until it ends or a command is queued. A cancelled
 * run (STOP or QUIT arrived mid-step) is STOPPED with its last good state. */
static void run_drive(acbb_worker *w, worker_ctx *c)
{
    hook_ctx h = { w, c };
    const acbb_run_ctl ctl = { run_hook, &h, &w->cancel_run };
    acbb_status rc = acbb_sim_drive(c->sim, &ctl);
    if (acbb_sim_state(c->sim) == ACBB_RUN_RUNNING) return; /* a command waits */
    double t = acbb_now_ms();
    /* A run shorter than one window still reports its rate. */
    if (c->rate == 0.0 && t > c->rate_t0) c->rate = 1e3 * (double)c->rate_n / (t - c->rate_t0);
    take_snapshot(w, c->sim, c);
    set_phase(c, rc == ACBB_CANCELLED ? ACBB_WORKER_STOPPED : ACBB_WORKER_DONE);
    publish(w, c, 0);
}

/* The user's stop between steps: the drive ends the run as cancelled
 * before stepping, so every stop leaves the same named status whether or
 * not it caught a step in flight. */
static void stop_run(acbb_worker *w, worker_ctx *c)
{
    atomic_store(&w->cancel_run, 1);
    const acbb_run_ctl ctl = { NULL, NULL, &w->cancel_run };
    acbb_sim_drive(c->sim, &ctl);
    take_snapshot(w, c->sim, c);
    set_phase(c, ACBB_WORKER_STOPPED);
}

/* ---- commands (worker side) ---- */

static void handle_cmd(acbb_worker *w, worker_ctx *c, const queued_cmd *q)
{
    acbb_error err = { { 0 } };
    acbb_status rc = ACBB_OK;
    const acbb_scene *s = q->has_scene ? &q->scene : &c->scene;

    switch (q->cmd) {
    case ACBB_CMD_START:
    case ACBB_CMD_APPLY:
    case ACBB_CMD_RESET: {
        int warm = q->cmd == ACBB_CMD_APPLY && q->warm;
        rc = load_scene(w, c, s, warm, &err);
        if (rc == ACBB_OK)
            begin_run(w, c, q->cmd == ACBB_CMD_RESET ? ACBB_WORKER_IDLE : ACBB_WORKER_RUNNING);
        else if (!c->sim)
            c->phase = ACBB_WORKER_NO_SIM;
        break;
    }
    case ACBB_CMD_PAUSE:
        if (c->phase == ACBB_WORKER_RUNNING) set_phase(c, ACBB_WORKER_PAUSED);
        break;
    case ACBB_CMD_RESUME:
        if (c->phase == ACBB_WORKER_PAUSED) set_phase(c, ACBB_WORKER_RUNNING);
        break;
    case ACBB_CMD_STOP:
        if (c->phase == ACBB_WORKER_RUNNING || c->phase == ACBB_WORKER_PAUSED) stop_run(w, c);
        break;
    case ACBB_CMD_COMPARE:
        compare_begin(w, c, s);
        break;
    case ACBB_CMD_QUIT:
        break;
    case ACBB_CMD_SHOW:
        if (c->sim) take_snapshot(w, c->sim, c);
        break;
    }

    pthread_mutex_lock(&w->mu);
    if (rc != ACBB_OK) {
        w->st.last_error = rc;
        w->st.err_cmd = q->seq;
        copy_text(w->st.message, sizeof w->st.message, err.msg);
    }
    w->st.cmd_done = q->seq;
    publish_locked(w, c, 1);
    wake_ui(w); /* before the command reads as done (see wake_ui) */
    pthread_cond_broadcast(&w->cv_done);
    pthread_mutex_unlock(&w->mu);
}

/* ---- the loop (worker side) ---- */

/* Wait until there is a command (returns 1 with it in *out) or something
 * to drive (returns 0): a comparison, or the main run while RUNNING. */
static int next_action(acbb_worker *w, const worker_ctx *c, queued_cmd *out)
{
    pthread_mutex_lock(&w->mu);
    while (w->q_len == 0 && c->phase != ACBB_WORKER_RUNNING)
        pthread_cond_wait(&w->cv_cmd, &w->mu);
    int got = w->q_len > 0;
    if (got) {
        *out = w->q[w->q_head];
        w->q_head = (w->q_head + 1) % QUEUE_CAP;
        w->q_len--;
    }
    pthread_mutex_unlock(&w->mu);
    return got;
}

static void *worker_main(void *arg)
{
    acbb_worker *w = arg;
    worker_ctx c;
    memset(&c, 0, sizeof c);
    c.phase = ACBB_WORKER_NO_SIM;

    queued_cmd first = { .cmd = ACBB_CMD_RESET, .has_scene = 1, .seq = 0 };
    first.scene = w->initial;
    handle_cmd(w, &c, &first);

    for (;;) {
        queued_cmd q;
        if (next_action(w, &c, &q)) {
            handle_cmd(w, &c, &q);
            if (q.cmd == ACBB_CMD_QUIT) break;
        } else {
            run_drive(w, &c);
        }
    }
    compare_join(w, &c);
    acbb_sim_free(c.sim);
    return NULL;
}

/* ---- client side ---- */


static int init_sync(acbb_worker *w)
{
    pthread_condattr_t ca;
    if (pthread_mutex_init(&w->mu, NULL) != 0) return -1;
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    int rc = pthread_cond_init(&w->cv_cmd, &ca) | pthread_cond_init(&w->cv_done, &ca);
    pthread_condattr_destroy(&ca);
    return rc ? -1 : 0;
}

acbb_status acbb_worker_new(const acbb_scene *scene, int pace, acbb_worker **out,
                            acbb_error *err)
{
    *out = NULL;
    acbb_worker *w = calloc(1, sizeof *w);
    if (!w) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    w->initial = *scene;
    w->st.phase = ACBB_WORKER_NO_SIM; /* until the thread has built the Sim */
    atomic_init(&w->pace, pace < 0 ? 0 : pace);
    atomic_init(&w->cancel_run, 0);
    atomic_init(&w->cancel_cmp, 0);
    acbb_history_init(&w->hist);
    if (acbb_wake_init(&w->wake) != 0) {
        free(w);
        return acbb_error_set(err, ACBB_EIO, "cannot create the wake-up pipe: %s", strerror(errno));
    }
    if (init_sync(w) != 0) {
        acbb_wake_close(&w->wake);
        free(w);
        return acbb_error_set(err, ACBB_ENOMEM, "cannot initialise the worker's lock");
    }
    /* Terminal signals go to the UI thread (blocked in this one). */
    int rc = acbb_thread_start(&w->thread, worker_main, w);
    if (rc != 0) {
        acbb_wake_close(&w->wake);
        pthread_mutex_destroy(&w->mu);
        pthread_cond_destroy(&w->cv_cmd);
        pthread_cond_destroy(&w->cv_done);
        free(w);
        return acbb_error_set(err, ACBB_ENOMEM, "cannot start the worker thread: %s", strerror(rc));
    }
    *out = w;
    return ACBB_OK;
}

static unsigned long post_locked(acbb_worker *w, acbb_worker_cmd cmd, const acbb_scene *scene,
                                 int warm)
{
    if (w->q_len == QUEUE_CAP) return 0;
    queued_cmd *q = &w->q[(w->q_head + w->q_len) % QUEUE_CAP];
    q->cmd = cmd;
    q->warm = warm;
    q->has_scene = scene != NULL;
    if (scene) q->scene = *scene;
    q->seq = ++w->next_seq;
    /* Set now, not when the worker gets to the command: the flag is what
     * ends a step (or a set-up) already in flight. */
    if (cmd == ACBB_CMD_STOP || cmd == ACBB_CMD_QUIT) atomic_store(&w->cancel_run, 1);
    if (cmd == ACBB_CMD_QUIT) atomic_store(&w->cancel_cmp, 1);
    w->q_len++;
    pthread_cond_signal(&w->cv_cmd);
    return q->seq;
}

unsigned long acbb_worker_post(acbb_worker *w, acbb_worker_cmd cmd, const acbb_scene *scene,
                               int warm)
{
    pthread_mutex_lock(&w->mu);
    unsigned long seq = post_locked(w, cmd, scene, warm);
    pthread_mutex_unlock(&w->mu);
    return seq;
}

void acbb_worker_free(acbb_worker *w)
{
    if (!w) return;
    unsigned long seq;
    /* End a step in flight now, even before QUIT finds room in the queue. */
    atomic_store(&w->cancel_run, 1);
    atomic_store(&w->cancel_cmp, 1);
    /* QUIT must get in even if the queue is full: wait for room. */
    while ((seq = acbb_worker_post(w, ACBB_CMD_QUIT, NULL, 0)) == 0) {
        struct timespec ts = { 0, 1000000L };
        nanosleep(&ts, NULL);
    }
    pthread_join(w->thread, NULL);
    acbb_wake_close(&w->wake);
    pthread_mutex_destroy(&w->mu);
    pthread_cond_destroy(&w->cv_cmd);
    pthread_cond_destroy(&w->cv_done);
    free(w);
}

void acbb_worker_set_pace(acbb_worker *w, int sim_s_per_s)
{
    atomic_store(&w->pace, sim_s_per_s < 0 ? 0 : sim_s_per_s);
    pthread_mutex_lock(&w->mu);
    pthread_cond_signal(&w->cv_cmd); /* re-evaluate a paced sleep */
    pthread_mutex_unlock(&w->mu);
}

int acbb_worker_pace(const acbb_worker *w)
{
    return atomic_load(&w->pace);
}

static void copy_history(acbb_history *dst, const acbb_history *src)
{
    /* Only the stored points: the ring is large and mostly empty early on. */
    dst->n = src->n;
    dst->stride = src->stride;
    dst->seen = src->seen;
    memcpy(dst->p, src->p, src->n * sizeof src->p[0]);
}

void acbb_worker_read(acbb_worker *w, acbb_worker_state *st, acbb_history *hist)
{
    pthread_mutex_lock(&w->mu);
    *st = w->st;
    if (hist) copy_history(hist, &w->hist);
    pthread_mutex_unlock(&w->mu);
}

int acbb_worker_wake_fd(const acbb_worker *w)
{
    return w->wake.rd;
}

void acbb_worker_drain_wake(acbb_worker *w)
{
    acbb_wake_drain(&w->wake);
}

int acbb_worker_wait_done(acbb_worker *w, unsigned long seq, int timeout_ms)
{
    struct timespec ts = acbb_wake_abstime(acbb_now_ms() + timeout_ms);
    int done;
    pthread_mutex_lock(&w->mu);
    while (!(done = w->st.cmd_done >= seq))
        if (pthread_cond_timedwait(&w->cv_done, &w->mu, &ts) == ETIMEDOUT) {
            done = w->st.cmd_done >= seq;
            break;
        }
    pthread_mutex_unlock(&w->mu);
    return done;
}

void acbb_worker_set_bearing(acbb_worker *w, int k)
{
    atomic_store(&w->bearing, k > 0 ? k : 0);
    acbb_worker_post(w, ACBB_CMD_SHOW, NULL, 0);
}
