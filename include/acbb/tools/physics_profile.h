/* acbb — physics profiles (issue 25): `physics.profile = seed | reference`
 * names which physics a scene's loss keys default to.
 *
 * - seed: the seed paper's physics as printed (its five losses, the rolling
 *   hysteresis of its Eq. 18 on the contact ellipse's long axis): the seed
 *   presets and the seed study reproduce the paper with it. A preset
 *   without the key is `seed`, so an old preset does not move.
 * - reference: the best-founded physics acbb has for any other bearing
 *   (Johnson's rolling-direction hysteresis, EHL rolling resistance,
 *   churning / jet momentum by lubrication method, cage-land shear);
 *   `acbb new` and the shipped presets other than the seed's state it.
 *
 * A profile sets DEFAULTS only: a key given in the preset (or by
 * acbb_scene_set) keeps its value whatever the profile. The keys and their
 * values per profile are one table, src/scene/physics_profile.c. */
#ifndef ACBB_PHYSICS_PROFILE_H
#define ACBB_PHYSICS_PROFILE_H

#include <stddef.h>
#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* "seed" | "reference" (the preset key's choices); "?" out of range. */
const char *acbb_profile_name(acbb_physics_profile p);

/* The profile table: how many keys a profile sets, row k's key as
 * "section.key", and its value under profile p in preset text ("on"). */
size_t acbb_profile_row_count(void);
const char *acbb_profile_row_key(size_t k);
const char *acbb_profile_row_value(size_t k, acbb_physics_profile p);

/* Put s->profile's value into every row's key that was not given
 * explicitly (bit k of s->profile_given clear). */
void acbb_profile_apply(acbb_scene *s);

#ifdef __cplusplus
}
#endif

#endif
