/* acbb — private helpers shared by the stepper (stepper.c, sim.c) and its snapshot
 * views (sim_snapshot.c); not part of the public API. */
#ifndef ACBB_SIM_PRIV_H
#define ACBB_SIM_PRIV_H

#include "acbb/sim.h"
#include "acbb/batch.h"
#include "mechanics.h"
#include "quasi_dynamic.h"
#include "expansion.h"
#include "losses.h"

/* v if finite, else 0: the last guard before a value reaches a client. */
double acbb_snap_fin(double v);

/* Ball b's view with the losses of its inner and outer contact. */
void acbb_snap_ball_view(const acbb_ball_state *b, const acbb_contact_loss *in,
                         const acbb_contact_loss *out, acbb_ball_view *v);

/* MODEL.md 13: the radial squeeze of the expansions e at ball b's angles. */
void acbb_snap_squeeze(const acbb_expansion *e, const acbb_ball_state *b, acbb_squeeze *q);

/* Checks the stepper makes before a value is published: every loss, the
 * slide and the film of one contact finite; every entry of v[0..n) finite;
 * the largest contact pressure of a mechanics state, Pa. */
int acbb_snap_contact_finite(const acbb_contact_loss *c);
int acbb_snap_all_finite(const double *v, int n);
double acbb_snap_max_pmax(const acbb_mech_state *ms);

/* acbb_sim_snapshot for a drive hook (sim.h), which sees iteration 0
 * first: there the whole snapshot; after a step o holds this Sim's and
 * only the state, status, iteration, time, losses, expansions, delta_x and
 * each ball's Qi, Qo and loss are refreshed (a set's whole but its rating
 * life). For a hook that reads every step's losses and loads (the
 * study's, study.c). */
void acbb_simx_snapshot_step(const acbb_sim *sim, acbb_snapshot *o);
/* The same values at every iteration, 0 included (a single bearing's;
 * a set's and a spindle's as acbb_simx_snapshot_step): for a hook that
 * reads no step whole (a perturbed study's, study.c). */
void acbb_simx_snapshot_values(const acbb_sim *sim, acbb_snapshot *o);

/* A converged single bearing's temperatures and mechanics (batch.h
 * acbb_warm), the start of a run of a scene that differs in values only:
 * the same network, balls, model and heating, or it is not used. */
/* A transient single bearing's set-up up to its first state: the
 * room-temperature mechanics at speed (sim.c initial_mechanics) with the
 * workspace it was solved in, as built (`built`) and as the continuation
 * left it (`ran`). Another scene whose workspace is built the same
 * (acbb_mech_same) at the same speed reaches the same bits (issue 30:
 * the perturbed studies' transients, whose inputs the mechanics mostly
 * does not read). */
typedef struct acbb_sim_first acbb_sim_first;
typedef struct {
    acbb_mech *built, *ran;
    double omega;
    acbb_mech_state ms;
    acbb_sim_first *first;       /* owned: its first state's passes (sim_first.c); NULL none */
} acbb_sim_setup;

struct acbb_warm {
    acbb_network_kind network;
    acbb_model_level model;
    bool heating;
    int n_balls, n_nodes;
    double T[ACBB_MAX_NODES];
    acbb_mech_state ms;
    acbb_sim_setup *setup;       /* owned; NULL: the run kept none */
};
/* NULL when sim is not a converged single bearing (or out of memory); the
 * set-up sim kept (keep_setup) goes with it. */
acbb_warm *acbb_simx_warm_save(acbb_sim *sim);
void acbb_simx_warm_free(acbb_warm *w);
/* A batch worker's workspaces from its last run, renewed by the next
 * instead of new ones (acbb_mech_renew, acbb_qd_renew); each NULL if none. */
typedef struct {
    acbb_mech *mech;
    acbb_qd *qd;                 /* Level 2: a run at another level keeps it for later */
} acbb_simx_spare;
void acbb_simx_spare_free(acbb_simx_spare sp);

/* How a batch run starts (acbb_simx_create_from). */
typedef struct {
    /* NULL: cold. A steady solve starts from its state when it fits (a
     * warm start that fails starts again cold); a transient from ambient,
     * taking only its set-up when its mechanics are the same (bit for bit
     * the run's own). */
    const acbb_warm *warm;
    int keep_setup;              /* a transient keeps its set-up for acbb_simx_warm_save */
    /* Workspaces to renew instead of new ones; the Sim's from here on,
     * even on failure. */
    acbb_simx_spare spare;
} acbb_simx_start;
acbb_status acbb_simx_create_from(const acbb_scene *s, const acbb_sim_opts *o,
                                  const acbb_simx_start *st, acbb_sim **out, acbb_error *err);
/* acbb_sim_free, but the Sim's mechanics and Level-2 workspaces (or the
 * spare it kept) are returned to start another (acbb_simx_start.spare). */
acbb_simx_spare acbb_simx_free_spare(acbb_sim *sim);

/* acbb_sim_create of a member of a steady set (sim_set.c): its first state
 * at ambient is not evaluated (the set's set-up evaluates every member's,
 * under the shaft's displacements); the caller brackets GSL. */
acbb_status acbb_simx_create_member(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                                    acbb_error *err);

#endif
