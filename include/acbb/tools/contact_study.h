/* acbb — which branch the runaway case reaches under each contact heat
 * model (issue 25 item 3; docs/contact_heat.md).
 *
 * The runaway case of a scene: the scene's bearing jumped from cold to
 * 16000 rpm under rigid preload (mounting.preload = displacement) set at
 * rest by 1000 N, 1000 N axial, alone (no set, no schedule): for the
 * 7008C exactly presets/runaway-rigid-preload.ini, and the top corner of
 * the report's speed and load sweeps (a spindle scene's front bearing, its
 * shaft dropped). It is run (transient, as the preset)
 * under thermal.contact_model = stationary and moving, each at the
 * race-side multipliers acbb_contact_multipliers. Pure: the caller owns
 * `out`. */
#ifndef ACBB_CONTACT_STUDY_H
#define ACBB_CONTACT_STUDY_H

#include "acbb/cancel_flag.h"
#include "acbb/tools/branches.h"
#include "acbb/scene.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_CONTACT_N_MULT 4
#define ACBB_CONTACT_N_CASES (2 * ACBB_CONTACT_N_MULT)
#define ACBB_CONTACT_RPM 16000.0
#define ACBB_CONTACT_PRELOAD_N 1000.0

/* c_mv = 0.25, 0.5, 1, 2: the plausible range x/2..x2 of
 * thermal.contact_multiplier and one step past its low end. */
extern const double acbb_contact_multipliers[ACBB_CONTACT_N_MULT];

typedef struct {
    acbb_contact_model model;
    double multiplier;           /* thermal.contact_multiplier */
    acbb_branch_state end;       /* how the transient run ended */
} acbb_contact_case;

typedef struct {
    acbb_contact_case cases[ACBB_CONTACT_N_CASES]; /* model-major, multipliers ascending */
    double wall_ms;
} acbb_contact_study;

/* The runaway case of s (above), contact keys as s has them. */
void acbb_contact_case_scene(const acbb_scene *s, acbb_scene *out);

/* Run every case. ACBB_OK (a failed run says so in its status);
 * ACBB_CANCELLED when `cancel` (may be NULL) stopped one; ACBB_ENOMEM. */
acbb_status acbb_contact_study_run(const acbb_scene *s, const acbb_atomic_int *cancel,
                                   acbb_contact_study *out, acbb_error *err);

/* "stationary" / "moving" */
const char *acbb_contact_model_name(acbb_contact_model m);

#ifdef __cplusplus
}
#endif

#endif
