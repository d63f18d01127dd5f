/* acbb — the one coupled stepper (MODEL.md section 9; internal) and the
 * plant it drives.
 *
 * A plant is whatever owns temperatures on a thermal network and can
 * evaluate its mechanics, losses and heat sources at them: one bearing
 * (sim.c) or a bearing set (sim_set.c), later a spindle. The stepper owns
 * the loop: the backward-Euler step with its step-size control (a node
 * moving more than DT_MAX_DT_K, the losses more than 5 %, halves the
 * step), the schedule's rows, the runaway limits, steady detection, the
 * steady polish (steady_polish.h) and the verdict. The caller's run loop
 * (sim.c) owns the wall-clock bound's deadline, cancel and the hooks; the
 * plant's stop() reads them inside a step.
 *
 * The plant is rebuilt for each step (acbb_plant is a view: pointers into
 * its owner), so nothing here outlives a restart of its owner. */
#ifndef ACBB_STEPPER_H
#define ACBB_STEPPER_H

#include "acbb/sim.h"
#include "acbb/limits.h"
#include "acbb/spindle.h"
#include "thermal_network.h"
#include "steady_polish.h"

#define DT_MIN 0.05            /* s, MODEL.md section 9 */
#define DT_MAX 30.0            /* s */
#define DT_MAX_DT_K 2.0        /* reject a step that moves a node more than this */
#define STEADY_COUNT 20        /* consecutive quiet steps for steady state */
#define PMAX_LIMIT 4.2e9       /* ISO static limit for ball bearings, Pa */
#define ISO_ITERS 60           /* mechanics passes of an isothermal run */
/* A plant's nodes, at most: a spindle's two sets and its shaft, housing
 * and coolant cells (spindle_priv.h); the stepper's scratch arrays
 * (three on the stack, 5 kB each) are this long. */
#define ACBB_STEPPER_NMAX (2 * ACBB_MAX_SET * ACBB_MAX_NODES + 2 * ACBB_SPINDLE_MAX_CELLS + 64)

/* The run as the stepper keeps it (each owner embeds one). */
typedef struct {
    acbb_run_state state;
    acbb_status status;
    long iter;
    double time, dt, residual, wall_ms;
    char msg[256];
    double prev_F, prev_rate;  /* the growth detector's last force and rate (MODEL.md 9) */
    int growth, quiet;         /* steps of growing growth; consecutive quiet steps */
    acbb_relax_ctl relax;      /* the steady solve's relaxation (steady_polish.h; start it
                                  with acbb_relax_start where the run is set up) */
} acbb_stepper;

/* What an evaluation is for: the plant's shortcuts differ (sim_eval.c). */
typedef enum { ACBB_PASS_STEADY, ACBB_PASS_TRANSIENT, ACBB_PASS_POLISH } acbb_pass;

/* The checkpoints a plant keeps: the last accepted state, and (keeps_best)
 * the polish's iterate of smallest residual. */
enum { ACBB_KEEP_LAST, ACBB_KEEP_BEST };

typedef struct {
    void *ctx;
    const acbb_scene *s;       /* the scene that sets the loop (mode, schedule, limits) */
    acbb_tnet *net;            /* the network over T[0..n), sources q (unless solve) */
    double *T, *q;
    int n;
    long *solves;              /* network solves counter, or NULL */
    int keeps_best;            /* a diverged polish ends at its best iterate */
    const char *force_name;    /* what the growth detector watches, for its message */
    /* cancel and the wall-clock deadline, as an error; ACBB_OK to go on */
    acbb_status (*stop)(void *ctx, acbb_error *err);
    /* the schedule's operating point at time t (only when it has rows) */
    acbb_status (*operate)(void *ctx, double t, acbb_error *err);
    /* mechanics, losses and sources q at T (relax: the polish step's) */
    acbb_status (*evaluate)(void *ctx, acbb_pass pass, double relax, acbb_error *err);
    double (*loss)(void *ctx); /* total loss of the last evaluation, W */
    void (*save)(void *ctx, int slot);
    void (*restore)(void *ctx, int slot); /* at the run's current time */
    /* temperature and pressure limits: ACBB_OK, or ACBB_RUNAWAY with what */
    acbb_status (*limits)(void *ctx, double t, char *what, size_t size);
    /* the force whose ever faster growth is a runaway; *rigid 0: not watched */
    double (*force)(void *ctx, int *rigid);
    void (*settle)(void *ctx); /* the heat flows of the state reached (NULL: none) */
    /* the network balances its sources (MODEL.md 12 item 18) */
    acbb_status (*balance)(void *ctx, acbb_error *err);
    void (*converge)(void *ctx); /* the probes of a converged state (stiffness) */
    /* The plant's own network solve (a spindle's, with its coolant): from T
     * (Tn holds a copy of it on entry) with sources q into Tn, a backward-
     * Euler step of dt or (dt = 0) the steady state; and the heat capacity
     * of node i (J/K; 0: a node that stores none). Both NULL: net with
     * acbb_tnet_step / acbb_tnet_steady / acbb_tnet_capacity. */
    acbb_status (*solve)(void *ctx, const double *q, double dt, double *Tn);
    double (*capacity)(void *ctx, int i);
} acbb_plant;

/* A transient with schedule rows follows them; the steady solve and an
 * isothermal run take the last row once, at set-up (schedule.h). */
int acbb_follows_schedule(const acbb_scene *s);

/* Ends the run: ACBB_RUN_FAILED with st and the message (a wall-clock
 * bound has one text wherever it was met). Returns st. */
acbb_status acbb_stepper_fail(acbb_stepper *r, const acbb_scene *s, acbb_status st,
                              const char *msg);

/* One step of the run (nothing once it has ended): its status. */
acbb_status acbb_stepper_step(const acbb_plant *p, acbb_stepper *r);

#endif
