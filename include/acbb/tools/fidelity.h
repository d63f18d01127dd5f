/* acbb — named fidelity settings and "ask for an accuracy, get the cheapest
 * settings" (DESIGN.md "Fidelity and effects").
 *
 * The stored frontier is a small table of measured combinations of the
 * [fidelity] knobs, cheapest first. Each entry carries what the accuracy
 * envelope measured for it (`acbb bench accuracy --envelope`, 7008C over
 * the seed's 48 study points, against the `reference` entry): worst and
 * median relative error of the steady state (max of total loss and
 * outer-ring temperature rise) and of the transient path (max |T(t) -
 * T_ref(t)| of the outer ring over the history), both temperature errors
 * over max(reference rise, ACBB_ACCURACY_T_FLOOR_K = 1 K), the worst path
 * difference in K, and the median cost per point in work units
 * (accuracy.h).
 *
 * Scene keys: fidelity.preset = custom | fast | balanced | reference, and
 * fidelity.target_error_pct (0 = off). When either is set, the Sim applies
 * the chosen entry's knob values over the scene's individual knobs when it
 * compiles the scene (acbb_sim_create, through acbb_scene_resolve); clients print acbb_fidelity_resolve's
 * note so users see what was chosen and why. A target wins over a preset.
 *
 * Everything here is constant data or pure functions (no state). */
#ifndef ACBB_FIDELITY_H
#define ACBB_FIDELITY_H

#include <stddef.h>
#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const char *name;             /* "fast", "balanced", "reference", or a ladder label */
    acbb_fidelity_preset preset;  /* its preset name, or ACBB_FIDELITY_CUSTOM (unnamed) */
    acbb_model_level model;
    int contact_grid;
    acbb_hertz_mode hertz;
    double mech_tol;
    double steady_tol;            /* K/s */
    acbb_thermal_mode thermal_mode;
    double time_step;             /* s */
    acbb_network_kind network;
    /* Measured over the envelope (relative errors, not %). */
    double worst_steady, median_steady;
    double worst_path, median_path;
    double worst_path_K;          /* the largest max |T(t) - T_ref(t)|, K */
    double work;                  /* median work units per point (accuracy.h) */
} acbb_fidelity_point;

/* The stored frontier, cheapest first; *n entries. The last is `reference`. */
const acbb_fidelity_point *acbb_fidelity_table(size_t *n);
/* The case the table was measured on (one line). */
const char *acbb_fidelity_case(void);
/* Name of a preset ("custom", "fast", ...). */
const char *acbb_fidelity_preset_name(acbb_fidelity_preset p);
/* The entry's worst error (steady or path, whichever is larger). */
double acbb_fidelity_worst(const acbb_fidelity_point *p);

/* Write the entry's knob values into `s`. */
void acbb_fidelity_set(acbb_scene *s, const acbb_fidelity_point *p);

typedef struct {
    const acbb_fidelity_point *point; /* NULL: custom, the scene's own knobs */
    int target_met;                   /* target given and a stored entry meets it */
    char note[640];                   /* what was chosen and why ("" when custom) */
} acbb_fidelity_choice;

/* What the scene's preset / target_error_pct choose. Returns 1 when an
 * entry overrides the knobs, 0 for custom (choice->point NULL). */
int acbb_fidelity_resolve(const acbb_scene *s, acbb_fidelity_choice *c);

/* Resolve and apply in place; then clear preset and target so that the
 * result is an ordinary custom scene (applying twice changes nothing).
 * `c` may be NULL. Returns 1 when knobs were overridden. */
int acbb_fidelity_apply(acbb_scene *s, acbb_fidelity_choice *c);

/* The scene as a run uses it, resolved once: the fidelity preset / target
 * applied (acbb_fidelity_apply) and a graded oil's viscosities and
 * pressure-viscosity coefficient derived (MODEL.md 16). `out` may be `in`;
 * resolving a resolved scene changes nothing. The Sim's constructor calls
 * it (acbb_sim_scene is its result); callers that build no Sim call it.
 * `fc` may be NULL. Returns 1 when a preset / target chose the knobs. */
int acbb_scene_resolve(const acbb_scene *in, acbb_scene *out, acbb_fidelity_choice *fc);

#ifdef __cplusplus
}
#endif

#endif
