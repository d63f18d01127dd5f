/* acbb — a spindle (docs/spindle.md "Integration"), the third plant of the
 * one stepper (stepper.h): a shaft (shaft_beam.h) on a front and a rear
 * bearing set, each an acbb_set_sim of its own (sim_set.h) driven only
 * through the spindle's plant, solved together: the shaft with both sets
 * as nonlinear supports, then each set's own evaluation under its
 * station's reaction. Private to src/run: sim.c builds one for a scene
 * with shaft_segments > 0, as it builds a set for a set scene.
 *
 * Ownership: acbb_spindle_sim_new allocates; acbb_spindle_sim_free
 * releases it and its sets. */
#ifndef ACBB_SPINDLE_SIM_H
#define ACBB_SPINDLE_SIM_H

#include <stdatomic.h>
#include "acbb/sim.h"

typedef struct acbb_spindle_sim acbb_spindle_sim;

/* `s` resolved (acbb_scene_resolve). one_support: the rear set carries no
 * load (it is no support of the shaft; its own evaluation runs unloaded),
 * for tests that compare with a set alone (tests/test_spindle.c). */
acbb_status acbb_spindle_sim_new(const acbb_scene *s, const acbb_sim_opts *o, int one_support,
                                 acbb_spindle_sim **out, acbb_error *err);
void acbb_spindle_sim_free(acbb_spindle_sim *sp);
acbb_status acbb_spindle_sim_step(acbb_spindle_sim *sp);
acbb_run_state acbb_spindle_sim_outcome(const acbb_spindle_sim *sp, acbb_status *status,
                                        long *iter);
void acbb_spindle_sim_cancel(acbb_spindle_sim *sp, const atomic_int *cancel);
void acbb_spindle_sim_deadline(acbb_spindle_sim *sp, double deadline_ms);
/* The front set's snapshot (its n_bearings and set view the front set's)
 * with the spindle's view (acbb_snapshot.spindle) and the run's state;
 * bearing k: the front set's bearings, then the rear's (each with its own
 * set's view). */
void acbb_spindle_sim_snapshot(const acbb_spindle_sim *sp, acbb_snapshot *o);
acbb_status acbb_spindle_sim_bearing_snapshot(const acbb_spindle_sim *sp, int k,
                                              acbb_snapshot *o);

#endif
