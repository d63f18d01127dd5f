/* Plausibility of a published snapshot, shared by test_sim and
 * test_levels. A finiteness check would be useless here: acbb_sim_snapshot
 * already replaces every non-finite value with 0. */
#ifndef ACBB_SNAPSHOT_CHECK_H
#define ACBB_SNAPSHOT_CHECK_H

#include <math.h>
#include "acbb/sim.h"

/* A published state must be physically plausible, not merely finite (the
 * engine ends a run on a non-finite value, and a NaN hidden as 0 would show
 * here as a zero film, angle or temperature): node temperatures between
 * ambient and the runaway limit, losses >= 0, loaded balls with angles in
 * (0, 90) deg and, at speed, a positive film and a positive total loss. */
static int snapshot_plausible(const acbb_snapshot *o, int film)
{
    if (o->status == ACBB_NONFINITE) return 0;
    for (int i = 0; i < o->n_nodes; i++)
        if (!(o->T[i] >= 26.0 - 1e-6 && o->T[i] <= 150.0)) return 0;
    const acbb_losses *L = &o->losses;
    for (int k = 0; k < ACBB_LOSS_KINDS; k++)
        if (!(L->P[k] >= 0)) return 0;
    for (int j = 0; j < o->n_balls; j++) {
        const acbb_ball_view *b = &o->balls[j];
        if (!(b->Qi >= 0 && b->Qo >= 0)) return 0;
        if (b->Qi > 1e-3 && !(b->alpha_i > 0 && b->alpha_i < M_PI / 2)) return 0;
        if (b->Qo > 1e-3 && !(b->alpha_o > -M_PI / 2 && b->alpha_o < M_PI / 2)) return 0;
        if (film && b->Qi > 1e-3 && b->omega_m > 1.0 && !(b->film_i > 0 && b->film_o > 0))
            return 0;
        if (b->omega_m > 1.0 && !(o->losses.total > 0)) return 0;
    }
    return 1;
}

#endif
