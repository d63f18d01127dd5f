/* acbb — what the parts of a bearing set's stepper share (private to
 * src/run/sim_set*.c): the stepper's state (sim_set.c), its probes of the
 * converged state (sim_set_probe.c) and its snapshots (sim_set_view.c). */
#ifndef ACBB_SIM_SET_PRIV_H
#define ACBB_SIM_SET_PRIV_H

#include "sim_set.h"
#include "set_mech.h"
#include "network_set.h"
#include "stepper.h"

#define ACBB_SET_NMAX ACBB_SET_MAX_NODES

struct acbb_set_sim {
    acbb_scene s;
    int n;
    acbb_sim *b[ACBB_MAX_SET];
    acbb_mech_state *scratch[ACBB_MAX_SET]; /* member states kept across probes */
    acbb_set_mech sm, sm_keep;
    acbb_network_set ns;
    double T[ACBB_SET_NMAX], q[ACBB_SET_NMAX], T_keep[ACBB_SET_NMAX];
    acbb_stepper run;
    const atomic_int *cancel;
    double deadline_ms;        /* the run's fidelity.max_wall_s, monotonic ms; 0 none */
    int setting_up;            /* 1 while set_up evaluates the first state */
    acbb_set_mech_memo memo;   /* the nose probes' shared first evaluations */
    double total;
    double heat_in, heat_out, preload, liftoff, K_ax, K_rad, K_tilt, spacer;
    int preload_stale;         /* steady solve: preload not probed since the last iterate */
    /* the last lift-off search (sim_set_probe.c): its preload, speed, slope
     * of the squeeze (um/N) and where it ended (lift_sm.n 0: none yet) */
    double lift_preload, lift_speed, lift_slope;
    double lift_prev[2];       /* the search before: its preload and lift-off, N */
    double lift_rest;          /* the unloading side's axial reaction at lift-off, N */
    acbb_set_mech lift_sm;
    acbb_mech_state *lift_ms[ACBB_MAX_SET];
};

/* The members' workspaces and states as set_mech.h wants them. */
void acbb_set_members(acbb_set_sim *ss, acbb_set_member *mb);
/* The shaft equilibrium under the set's loads, from and into its state. */
acbb_status acbb_set_solve_shaft(acbb_set_sim *ss, acbb_error *err);

/* One evaluation in two halves, for a spindle (spindle_mech.c) to solve its
 * shaft in between: the joined temperatures to the members, their
 * expansions and the spacers' growth; then the set's shaft equilibrium
 * under sm's loads (with the ball speeds), the losses and the sources. */
void acbb_set_prepare(acbb_set_sim *ss, int transient, int polishing);
acbb_status acbb_set_finish(acbb_set_sim *ss, int transient, acbb_error *err);
/* The set as a plant of the stepper (a view); what a step leaves for the
 * snapshots (the heat flows, the live preload and lift-off, each member's
 * run state from ss->run). */
void acbb_set_plant(acbb_set_sim *ss, acbb_plant *p);
void acbb_set_publish(acbb_set_sim *ss);

/* Probes (sim_set_probe.c): the members and the set's solution are left as
 * they were. The preload with no external thrust, N; the lift-off thrust,
 * N (0: none, a tandem set; to rel_tol of it, at least 1e-4 of the
 * assembly preload; MODEL.md 14, sim_set_probe.c for what it is); the
 * radial and tilt stiffness at the nose into ss->K_rad, ss->K_tilt. */
double acbb_set_preload_now(acbb_set_sim *ss);
double acbb_set_liftoff(acbb_set_sim *ss, double rel_tol);
void acbb_set_nose_stiffness(acbb_set_sim *ss);

#endif
