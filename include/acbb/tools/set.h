/* acbb — spindle bearing sets (MODEL.md section 14): where each bearing of
 * a scene's [set] sits on the shaft and which way it carries thrust.
 * Plain functions of a Scene; nothing is allocated. */
#ifndef ACBB_SET_H
#define ACBB_SET_H

#include "acbb/limits.h"
#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The bearings of s's set: orient[k] = +1 or -1, the direction of the
 * thrust bearing k's inner ring carries (MODEL.md 14 s_k), x[k] its centre
 * relative to the set's centre (m), bearings by increasing x. Returns the
 * number of bearings the scene asks for (1 for a single bearing); a count
 * above ACBB_MAX_SET is returned as it is (the validation refuses it) with
 * only ACBB_MAX_SET entries written. Either array may be NULL. */
int acbb_set_layout(const acbb_scene *s, int orient[ACBB_MAX_SET], double x[ACBB_MAX_SET]);

/* Centre distance of neighbouring bearings, m (set.spacing_mm, 0 = one width). */
double acbb_set_pitch(const acbb_scene *s);

/* Lengths of the inner (shaft side) and outer (housing side) spacers
 * between neighbours, m (MODEL.md 14 L_s, L_h): set.inner_spacer_mm and
 * set.outer_spacer_mm, 0 = the gap between the rings (centre distance minus
 * one width: matched spacers). Either pointer may be NULL. */
void acbb_set_spacers(const acbb_scene *s, double *L_inner, double *L_outer);

/* One arrangement (a row of ACBB_SET_ARRANGEMENT_TABLE, acbb/scene.h). */
typedef struct {
    const char *name;   /* "single", "DB", ... (the key's value) */
    int n;              /* bearings it has */
    int n_max;          /* most bearings set.n_bearings may ask for (DT: ACBB_MAX_SET) */
    const char *orient; /* '+' / '-' per bearing by increasing x, the last repeated */
} acbb_set_kind;

/* The arrangements, indexed by acbb_set_arrangement. */
extern const acbb_set_kind acbb_set_kinds[ACBB_SET_ARRANGEMENTS];
/* Their names, NULL-ended (the [set] arrangement key's choices). */
extern const char *const acbb_set_arrangement_names[ACBB_SET_ARRANGEMENTS + 1];

/* Short name of an arrangement ("single", "DB", ...; "?" outside the table). */
const char *acbb_set_arrangement_name(acbb_set_arrangement a);

#ifdef __cplusplus
}
#endif

#endif
