/* acbb — a bearing's static rating basis, computed once per scene (C0 takes
 * two exact Hertz solves, about 30 us; a Sim keeps it instead of solving
 * them again at every snapshot: life_eval.c). Internal to the engine. */
#ifndef ACBB_LIFE_STATIC_H
#define ACBB_LIFE_STATIC_H

#include <stdbool.h>
#include "acbb/life.h"
#include "acbb/scene.h"
#include "acbb/sim.h"

typedef struct {
    double C0;                   /* ISO 76 static radial rating, N (life.C0_N) */
    double C0_stress;            /* the 4200 MPa load with the real grooves, N */
    bool C0_table;               /* C0 is ISO 76 Table 1's (its grooves and steel) */
} acbb_life_static;

/* The basis of scene s (geometry and materials only). */
void acbb_life_static_basis(const acbb_scene *s, acbb_life_static *b);

/* acbb_life_compute with the scene's basis given (acbb_life_static_basis
 * of the same scene): the same result. */
void acbb_life_compute_with(const acbb_scene *s, const acbb_snapshot *sn,
                            const acbb_life_static *basis, acbb_life *L);

#endif
