/* acbb TUI — the worker thread and its hand-off (see worker.h).
 *
 * The idea follows cmus's player_info: the worker fills a shared struct
 * under one mutex and pokes a pipe; the UI copies the struct out once per
 * frame. Everything the worker alone touches (the Sims, timing) lives in
 * a worker_ctx on the worker's own stack, so the shared part is exactly
 * what is behind the mutex. */
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "worker.h"
#include "wake.h"

#define QUEUE_CAP 16
#define RATE_WINDOW_S 0.25  /* steps/s is measured over windows this long */

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
    _Atomic int pace;          /* steps per second, 0 = flat out */
    acbb_wake wake;            /* the UI's select() wakes on it */
};

/* Worker-private: only the worker thread touches these. */
typedef struct {
    acbb_sim *sim;
    acbb_scene scene;
    acbb_worker_phase phase;
    acbb_snapshot snap;
    double last_step;          /* monotonic s of the last step (pacing) */
    double seg_start, wall_acc;/* running wall time, pauses excluded */
    double rate_t0, rate;      /* steps/s measurement window */
    long rate_n;
    /* TE vs WTE comparison */
    int cmp_active, cmp_variant;
    acbb_sim *cmp_sim;
    acbb_scene cmp_scene;
} worker_ctx;

/* Copy a message, truncating to fit (strncpy warns and may not terminate). */
static void copy_text(char *dst, size_t n, const char *src)
{
    size_t len = strnlen(src, n - 1);
    memcpy(dst, src, len);
    dst[len] = '\0';
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static struct timespec abs_time(double t)
{
    struct timespec ts;
    ts.tv_sec = (time_t)t;
    ts.tv_nsec = (long)((t - (double)ts.tv_sec) * 1e9);
    if (ts.tv_nsec >= 1000000000L) { ts.tv_sec++; ts.tv_nsec -= 1000000000L; }
    if (ts.tv_nsec < 0) ts.tv_nsec = 0;
    return ts;
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

static void wake_ui(acbb_worker *w) { acbb_wake_signal(&w->wake); }

static double run_wall(const worker_ctx *c, double now)
{
    return c->wall_acc + (c->phase == ACBB_WORKER_RUNNING ? now - c->seg_start : 0.0);
}

/* Copy the worker's view into the shared state. Called with w->mu held. */
static void publish_locked(acbb_worker *w, const worker_ctx *c, int with_snapshot)
{
    w->st.phase = c->phase;
    w->st.pace = atomic_load(&w->pace);
    w->st.run_wall_s = run_wall(c, now_s());
    w->st.steps_per_s = c->rate;
    if (with_snapshot && c->sim) {
        w->st.snap = c->snap;
        w->st.has_snapshot = 1;
    }
    w->st.publications++;
}

static void publish(acbb_worker *w, const worker_ctx *c, int push_history)
{
    pthread_mutex_lock(&w->mu);
    publish_locked(w, c, 1);
    if (push_history) acbb_history_push(&w->hist, &c->snap);
    pthread_mutex_unlock(&w->mu);
    wake_ui(w);
}

/* ---- phase bookkeeping (worker side) ---- */

static void set_phase(worker_ctx *c, acbb_worker_phase p)
{
    double t = now_s();
    if (c->phase == ACBB_WORKER_RUNNING && p != ACBB_WORKER_RUNNING)
        c->wall_acc += t - c->seg_start;
    if (c->phase != ACBB_WORKER_RUNNING && p == ACBB_WORKER_RUNNING) {
        c->seg_start = t;
        c->last_step = t - 1e9; /* first step is due at once */
        c->rate_t0 = t;
        c->rate_n = 0;
    }
    c->phase = p;
}

/* A new run (or a reset) begins: fresh history seeded with the initial state. */
static void begin_run(acbb_worker *w, worker_ctx *c, acbb_worker_phase p)
{
    c->phase = ACBB_WORKER_IDLE;
    c->wall_acc = 0.0;
    c->rate = 0.0;
    set_phase(c, p);
    acbb_sim_snapshot(c->sim, &c->snap);
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

/* (Re)build the Sim for `s`: restart in place when one exists so a failure
 * leaves the current run untouched (acbb_sim_restart's contract). */
static acbb_status load_scene(worker_ctx *c, const acbb_scene *s, int warm, acbb_error *err)
{
    acbb_status rc;
    if (c->sim)
        rc = acbb_sim_restart(c->sim, s, warm, err);
    else
        rc = acbb_sim_new(s, &c->sim, err);
    if (rc == ACBB_OK) c->scene = *s;
    return rc;
}

/* ---- comparison (worker side) ---- */

static void compare_finish_variant(acbb_worker *w, worker_ctx *c)
{
    int v = c->cmp_variant;
    pthread_mutex_lock(&w->mu);
    w->st.compare.ok[v] = 1;
    acbb_sim_snapshot(c->cmp_sim, &w->st.compare.snap[v]);
    if (v == 1) w->st.compare.phase = ACBB_CMP_DONE;
    else w->st.compare.variant = 1;
    publish_locked(w, c, 0);
    pthread_mutex_unlock(&w->mu);
    wake_ui(w);
    acbb_sim_free(c->cmp_sim);
    c->cmp_sim = NULL;
    c->cmp_variant++;
    if (c->cmp_variant > 1) c->cmp_active = 0;
}

/* One step of the comparison: build the variant's Sim on its first step,
 * step it, and publish progress every so often. */
static void compare_step(acbb_worker *w, worker_ctx *c)
{
    acbb_error err = { { 0 } };
    if (!c->cmp_sim) {
        acbb_scene s = c->cmp_scene;
        s.thermal_expansion = c->cmp_variant == 0;
        if (acbb_sim_new(&s, &c->cmp_sim, &err) != ACBB_OK) {
            c->cmp_sim = NULL;
            int v = c->cmp_variant;
            pthread_mutex_lock(&w->mu);
            w->st.compare.ok[v] = 0;
            copy_text(w->st.compare.message, sizeof w->st.compare.message, err.msg);
            if (v == 1) w->st.compare.phase = ACBB_CMP_DONE;
            else w->st.compare.variant = 1;
            pthread_mutex_unlock(&w->mu);
            wake_ui(w);
            if (++c->cmp_variant > 1) c->cmp_active = 0;
            return;
        }
    }
    acbb_sim_step(c->cmp_sim);
    if (acbb_sim_state(c->cmp_sim) != ACBB_RUN_RUNNING) {
        compare_finish_variant(w, c);
        return;
    }
    acbb_snapshot snap;
    acbb_sim_snapshot(c->cmp_sim, &snap);
    if (snap.iteration % 16 == 0) {
        pthread_mutex_lock(&w->mu);
        w->st.compare.snap[c->cmp_variant] = snap;
        publish_locked(w, c, 0);
        pthread_mutex_unlock(&w->mu);
        wake_ui(w);
    }
}

static void compare_begin(acbb_worker *w, worker_ctx *c, const acbb_scene *s)
{
    acbb_sim_free(c->cmp_sim);
    c->cmp_sim = NULL;
    c->cmp_scene = *s;
    c->cmp_active = 1;
    c->cmp_variant = 0;
    pthread_mutex_lock(&w->mu);
    memset(&w->st.compare, 0, sizeof w->st.compare);
    w->st.compare.phase = ACBB_CMP_RUNNING;
    pthread_mutex_unlock(&w->mu);
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
        rc = load_scene(c, s, warm, &err);
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
        if (c->phase == ACBB_WORKER_RUNNING || c->phase == ACBB_WORKER_PAUSED)
            set_phase(c, ACBB_WORKER_STOPPED);
        break;
    case ACBB_CMD_COMPARE:
        compare_begin(w, c, s);
        break;
    case ACBB_CMD_QUIT:
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
    pthread_cond_broadcast(&w->cv_done);
    pthread_mutex_unlock(&w->mu);
    wake_ui(w);
}

/* ---- stepping (worker side) ---- */

static void measure_rate(worker_ctx *c, double t)
{
    c->rate_n++;
    if (t - c->rate_t0 >= RATE_WINDOW_S) {
        c->rate = (double)c->rate_n / (t - c->rate_t0);
        c->rate_t0 = t;
        c->rate_n = 0;
    }
}

static void step_run(acbb_worker *w, worker_ctx *c)
{
    acbb_status rc = acbb_sim_step(c->sim);
    double t = now_s();
    c->last_step = t;
    measure_rate(c, t);
    acbb_sim_snapshot(c->sim, &c->snap);
    if (rc != ACBB_OK || acbb_sim_state(c->sim) != ACBB_RUN_RUNNING) {
        /* A run shorter than one window still reports its rate. */
        if (c->rate == 0.0 && t > c->rate_t0) c->rate = (double)c->rate_n / (t - c->rate_t0);
        set_phase(c, ACBB_WORKER_DONE);
    }
    publish(w, c, 1);
}

/* Wait until there is a command (returns 1 with it in *out) or a step is
 * due (returns 0). Paced runs sleep on the condition variable so a command
 * or a pace change wakes them at once. */
static int next_action(acbb_worker *w, const worker_ctx *c, queued_cmd *out)
{
    pthread_mutex_lock(&w->mu);
    for (;;) {
        if (w->q_len > 0) {
            *out = w->q[w->q_head];
            w->q_head = (w->q_head + 1) % QUEUE_CAP;
            w->q_len--;
            pthread_mutex_unlock(&w->mu);
            return 1;
        }
        if (c->cmp_active) break;
        if (c->phase != ACBB_WORKER_RUNNING) {
            pthread_cond_wait(&w->cv_cmd, &w->mu);
            continue;
        }
        int pace = atomic_load(&w->pace);
        if (pace <= 0) break;
        double due = c->last_step + 1.0 / pace;
        if (now_s() >= due) break;
        struct timespec ts = abs_time(due);
        pthread_cond_timedwait(&w->cv_cmd, &w->mu, &ts);
    }
    pthread_mutex_unlock(&w->mu);
    return 0;
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
        } else if (c.cmp_active) {
            compare_step(w, &c);
        } else {
            step_run(w, &c);
        }
    }
    acbb_sim_free(c.cmp_sim);
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

    /* The worker inherits this mask: terminal signals go to the UI thread. */
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigaddset(&block, SIGWINCH);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    int rc = pthread_create(&w->thread, NULL, worker_main, w);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
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

void acbb_worker_set_pace(acbb_worker *w, int steps_per_s)
{
    atomic_store(&w->pace, steps_per_s < 0 ? 0 : steps_per_s);
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
    struct timespec ts = abs_time(now_s() + timeout_ms / 1000.0);
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
