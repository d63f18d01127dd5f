/* acbb — a compact record of one coupled step, for charts and plots, and
 * a bounded history that keeps the whole run by halving its resolution
 * when full (the charts always show the run from step 0).
 *
 * Ownership: acbb_history is a caller-owned plain value (fixed capacity,
 * no allocation); it is not thread-safe by itself. */
#ifndef ACBB_HISTORY_H
#define ACBB_HISTORY_H

#include <stddef.h>
#include "acbb/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_HISTORY_CAP 2048

typedef struct {
    long iteration;
    double time;                    /* s */
    double T_outer_ring, T_inner_ring, T_ball, T_housing; /* C */
    double loss[ACBB_LOSS_KINDS], total;                  /* W, by acbb_loss_kind */
    double Qi, Qo;                  /* ball 0, N */
    double alpha_i, alpha_o;        /* ball 0, rad */
    double exp_inner, exp_outer, exp_ball; /* m (exp_inner includes centrifugal) */
    double set_preload;             /* a set's preload now, N (0: one bearing) */
    double T_outer_set[ACBB_MAX_SET]; /* each bearing's outer ring, C (a set) */
} acbb_history_point;

typedef struct {
    acbb_history_point p[ACBB_HISTORY_CAP];
    size_t n;                       /* points stored */
    long stride;                    /* keep every stride-th step */
    long seen;                      /* steps offered so far */
} acbb_history;

void acbb_history_init(acbb_history *h);
void acbb_history_point_from(const acbb_snapshot *s, acbb_history_point *p);
/* Offer one step; stored if it falls on the stride. When full, every
 * second point is dropped and the stride doubles. The last point offered
 * is always kept as the final entry (replacing a stride point if needed). */
void acbb_history_push(acbb_history *h, const acbb_snapshot *s);

#ifdef __cplusplus
}
#endif

#endif
