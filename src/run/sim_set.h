/* acbb — the coupled stepper of a bearing set (MODEL.md section 14):
 * private to src/run. sim.c dispatches to it when a scene's
 * set.arrangement is not single; each bearing is an acbb_sim of its own
 * (its mechanics, ball speeds, losses and network) that this stepper
 * drives through the acbb_simm_* calls below, over one joined thermal
 * network (network_set.h) and one shaft equilibrium (set_mech.h).
 *
 * Ownership: acbb_set_sim_new allocates; acbb_set_sim_free releases it and
 * its member Sims. */
#ifndef ACBB_SIM_SET_H
#define ACBB_SIM_SET_H

#include <stdatomic.h>
#include "acbb/sim.h"
#include "mechanics.h"
#include "network.h"
#include "expansion.h"

typedef struct acbb_set_sim acbb_set_sim;

acbb_status acbb_set_sim_new(const acbb_scene *s, const acbb_sim_opts *o, acbb_set_sim **out,
                             acbb_error *err);
void acbb_set_sim_free(acbb_set_sim *ss);
acbb_status acbb_set_sim_step(acbb_set_sim *ss);
/* The run state, with its status and step count. */
acbb_run_state acbb_set_sim_outcome(const acbb_set_sim *ss, acbb_status *status, long *iter);
void acbb_set_sim_cancel(acbb_set_sim *ss, const atomic_int *cancel);
/* The run's wall-clock deadline (acbb_now_ms; 0 none), read by every loop
 * inside a set's step that can run long (the step-size retries, the ball
 * speed passes, the isothermal iterations, the steady polish) and handed
 * to every member's own inner loops. */
void acbb_set_sim_deadline(acbb_set_sim *ss, double deadline_ms);
void acbb_set_sim_snapshot(const acbb_set_sim *ss, acbb_snapshot *o);
acbb_status acbb_set_sim_bearing_snapshot(const acbb_set_sim *ss, int k, acbb_snapshot *o);

/* ---- a bearing of a set: the parts of sim.c's step it needs ---- */
typedef struct {
    acbb_run_state state;
    acbb_status status;
    long iter;
    double time, dt, residual, wall_ms;
    char msg[256];
} acbb_set_run;

acbb_mech *acbb_simm_mech(acbb_sim *b);
acbb_mech_state *acbb_simm_ms(acbb_sim *b);
const acbb_expansion *acbb_simm_exp(const acbb_sim *b);
double *acbb_simm_T(acbb_sim *b);                 /* b's node temperatures (its slice) */
acbb_network *acbb_simm_network(acbb_sim *b);
const double *acbb_simm_q(const acbb_sim *b);     /* b's heat vector, its node order */
int acbb_simm_has_traction(const acbb_sim *b);    /* quasi-dynamic or dynamic level */
double acbb_simm_loss(const acbb_sim *b);         /* total loss, W */
void acbb_simm_speed(acbb_sim *b, double inner_speed); /* rad/s, the set's schedule */
void acbb_simm_expand(acbb_sim *b);               /* expansions at b's temperatures */
void acbb_simm_mode(acbb_sim *b, int transient, int polishing);
/* b's wall-clock deadline (acbb_now_ms; 0 none): the set's, so that b's
 * own inner loops (its ball-speed passes, every right-hand side of the
 * dynamic level) stop at the set's fidelity.max_wall_s (issue 26 item 7). */
void acbb_simm_deadline(acbb_sim *b, double deadline_ms);
acbb_status acbb_simm_traction(acbb_sim *b, double *change, acbb_error *err);
acbb_status acbb_simm_heat(acbb_sim *b, acbb_error *err);
void acbb_simm_save(acbb_sim *b);
void acbb_simm_restore(acbb_sim *b);
void acbb_simm_publish(acbb_sim *b, const acbb_set_run *r);
void acbb_simm_stiffness(acbb_sim *b, double *K_axial);

#endif
