/* acbb — the run JSON's `life` object (life_json.c). Internal. */
#ifndef ACBB_LIFE_JSON_H
#define ACBB_LIFE_JSON_H

#include "acbb/tools/json.h"
#include "acbb/sim.h"

/* Write "life": {...} for one single-bearing snapshot into the open object. */
void acbb_json_write_life(acbb_json *j, const acbb_snapshot *s);

#endif
