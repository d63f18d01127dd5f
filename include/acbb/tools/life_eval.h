/* acbb — the rating life of a bearing's computed state (life.h, MODEL.md 15).
 *
 * acbb_life_compute reads the scene (geometry, speed, oil, [life] inputs)
 * and one single-bearing snapshot (its balls' loads, angles, pressures,
 * ellipses and its ring temperatures); it writes every field of `out` with
 * finite values. Pure: no state, callable from any thread. */
#ifndef ACBB_LIFE_EVAL_H
#define ACBB_LIFE_EVAL_H

#include "acbb/life.h"
#include "acbb/scene.h"
#include "acbb/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

void acbb_life_compute(const acbb_scene *s, const acbb_snapshot *snap, acbb_life *out);

/* "inner ball 3", "outer ball 0" or "none" into buf (for messages, JSON). */
void acbb_life_contact_name(int ball, acbb_life_race race, char *buf, unsigned long n);

#ifdef __cplusplus
}
#endif

#endif
