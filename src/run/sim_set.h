/* acbb — a bearing set, a plant of the one stepper (MODEL.md section 14):
 * private to src/run. sim.c dispatches to it when a scene's
 * set.arrangement is not single; each bearing is an acbb_sim of its own
 * (its mechanics, ball speeds, losses and network) that the set
 * drives as plants of their own (stepper.h: save, restore, the probes of
 * a converged state) and through the parts of one evaluation
 * (sim_struct.h acbb_simx_*), over one joined thermal network
 * (network_set.h) and one shaft equilibrium (set_mech.h); the set itself
 * is the plant the one stepper drives.
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

/* `s` is resolved (acbb_scene_resolve, fidelity.h): sim.c set_init passes
 * the Sim's acbb_sim_scene. */
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

#endif
