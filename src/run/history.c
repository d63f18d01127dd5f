/* acbb — bounded run history (see history.h). */
#include <string.h>
#include "acbb/tools/history.h"

void acbb_history_init(acbb_history *h)
{
    h->n = 0;
    h->stride = 1;
    h->seen = 0;
}

void acbb_history_point_from(const acbb_snapshot *s, acbb_history_point *p)
{
    const acbb_ball_view *b = s->n_balls > 0 ? &s->balls[0] : NULL;
    p->iteration = s->iteration;
    p->time = s->time;
    p->T_outer_ring = s->T_outer_ring;
    p->T_inner_ring = s->T_inner_ring;
    p->T_ball = s->T_ball;
    p->T_housing = s->T_housing;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) p->loss[l] = s->losses.P[l];
    p->total = s->losses.total;
    p->Qi = b ? b->Qi : 0.0;
    p->Qo = b ? b->Qo : 0.0;
    p->alpha_i = b ? b->alpha_i : 0.0;
    p->alpha_o = b ? b->alpha_o : 0.0;
    p->exp_inner = s->exp_inner + s->exp_inner_cen;
    p->exp_outer = s->exp_outer;
    p->exp_ball = s->exp_ball;
    p->set_preload = s->set.preload_N;
    for (int k = 0; k < ACBB_MAX_SET; k++) p->T_outer_set[k] = s->set.T_outer_ring[k];
}

/* Drop every second stored point (keeping the first) and double the stride. */
static void decimate(acbb_history *h)
{
    size_t k = 0;
    for (size_t i = 0; i < h->n; i += 2) h->p[k++] = h->p[i];
    h->n = k;
    h->stride *= 2;
}

void acbb_history_push(acbb_history *h, const acbb_snapshot *s)
{
    acbb_history_point pt;
    acbb_history_point_from(s, &pt);
    long idx = h->seen++;
    /* The previous "last" entry is provisional unless it fell on the stride. */
    if (h->n > 0 && (idx - 1) % h->stride != 0)
        h->n--;
    if (h->n == ACBB_HISTORY_CAP)
        decimate(h);
    h->p[h->n++] = pt;
}
