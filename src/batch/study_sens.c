/* acbb — the seed study's sign statements against the plausible ranges
 * (study.h, "robustness"): each a TE - WTE difference at one point of the
 * study's sweeps, read from the same runs as the items (study_robust.c).
 * MODEL.md 13: the heavy-load TE/WTE signs rest on a sub-micron balance,
 * so a verdict is reported together with the single plausible changes that
 * would turn it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/study.h"
#include "study_priv.h"

/* Statements of MODEL.md 12 that are the sign of a TE - WTE difference, or
 * a threshold on its relative size, at one load and speed. Item 5's "final >
 * step 0 at large loads" is taken as Qi(TE) - Qi(WTE) of ball 0: the WTE
 * final state carries no expansion. */
static const acbb_study_sign k_signs[] = {
    {1, "P_T(TE) - P_T(WTE) > 0 at 1000 N", 1000, "losses_W.total", +1, 15000, 0, 0},
    {1, "P_T(TE) - P_T(WTE) < 0 at 50 N", 50, "losses_W.total", -1, 15000, 0, 0},
    {5, "Qi(TE) - Qi(WTE) > 0 at 1000 N (ball 0)", 1000, "balls[0].Qi_N", +1, 15000, 0, 0},
    {8, "T5(TE) - T5(WTE) > 0 at 1000 N", 1000, "temperature_C.outer_ring", +1, 15000, 0, 0},
    {8, "T5(TE) - T5(WTE) < 0 at 100 N", 100, "temperature_C.outer_ring", -1, 15000, 0, 0},
    {10, "P_L(TE) - P_L(WTE) > 0 at 1000 N", 1000, "losses_W.shear", +1, 15000, 0, 0},
    {10, "P_L(TE) - P_L(WTE) < 0 at 100 N", 100, "losses_W.shear", -1, 15000, 0, 0},
    {11, "P_t(TE) - P_t(WTE) > 0 at 1000 N", 1000, "losses_W.slip", +1, 15000, 0, 0},
    {11, "P_t(TE) - P_t(WTE) < 0 at 50 N", 50, "losses_W.slip", -1, 15000, 0, 0},
    {12, "P_s(TE) - P_s(WTE) > 0 at 1000 N", 1000, "losses_W.spin", +1, 15000, 0, 0},
    {13, "P_r(TE) - P_r(WTE) > 0 at 1000 N", 1000, "losses_W.rolling", +1, 15000, 0, 0},
    {15, "inner sliding TE - WTE < 0 at 100 N (ball 0)", 100, "balls[0].slide_i_mps", -1, 15000, 0, 0},
    {16, "inner spin TE - WTE < 0 at 100 N (ball 0)", 100, "balls[0].spin_i_radps", -1, 15000, 0, 0},
    /* Thresholds on the relative TE effect (MODEL.md 12; the numbers are
     * the proposed ones there). */
    {3, "|P_v(TE) - P_v(WTE)| / P_v(WTE) < 2 % at 1000 N", 1000, "losses_W.drag",
     -2, 15000, 1, 0.02},
    {3, "|P_v(TE) - P_v(WTE)| / P_v(WTE) < 2 % at 50 N", 50, "losses_W.drag",
     -2, 15000, 1, 0.02},
    {9, "|P_T(TE) - P_T(WTE)| / P_T(WTE) < 5 % at 2000 rpm, 100 N", 100, "losses_W.total",
     -2, 2000, 1, 0.05},
    {9, "|P_T(TE) - P_T(WTE)| / P_T(WTE) > 10 % at 16000 rpm, 1000 N", 1000, "losses_W.total",
     2, 16000, 1, 0.10},
    {14, "|hc(TE) - hc(WTE)| / hc(WTE) < 5 % at 1000 N (inner, ball 0)", 1000,
     "balls[0].film_i_um", -2, 15000, 1, 0.05},
    {14, "|hc(TE) - hc(WTE)| / hc(WTE) < 5 % at 100 N (inner, ball 0)", 100,
     "balls[0].film_i_um", -2, 15000, 1, 0.05},
};

const acbb_study_sign *acbb_study_signs(size_t *n)
{
    *n = sizeof k_signs / sizeof k_signs[0];
    return k_signs;
}

static int holds(double y, const acbb_study_sign *c)
{
    switch (c->want) {
    case 2: return fabs(y) > c->thr;
    case -2: return fabs(y) < c->thr;
    case 1: return y > c->thr;
    default: return y < c->thr;
    }
}

/* The point of the study's sweeps at the condition's load and speed (at
 * 15000 rpm: the load sweep; else the speed sweep at 100 N or 1000 N), TE
 * member; NULL if the condition is not on the sweeps. */
static const acbb_study_point *sign_point(const acbb_study_runs *r, const acbb_study_sign *c)
{
    int blk = c->speed_rpm == 15000.0 ? ACBB_STUDY_LOAD
              : c->load_N == 100.0    ? ACBB_STUDY_S100
              : c->load_N == 1000.0   ? ACBB_STUDY_S1000 : -1;
    const double *x = blk == ACBB_STUDY_LOAD ? acbb_study_loads : acbb_study_speeds;
    double want = blk == ACBB_STUDY_LOAD ? c->load_N : c->speed_rpm;
    for (int k = 0; blk >= 0 && k < ACBB_STUDY_NPTS; k++)
        if (x[k] == want) return &r->sweep[ACBB_STUDY_BASE][blk][2 * k + ACBB_STUDY_TE];
    return NULL;
}

/* TE - WTE (or its relative size) of the condition's metric from the
 * runs; 0 when a run failed or the number is undefined. */
static int sign_value(const acbb_study_runs *r, const acbb_study_sign *c, double *y)
{
    const acbb_study_point *te = sign_point(r, c);
    double a, b;
    if (!te || !te[0].ok || !te[1].ok) return 0;
    if (acbb_metric_value(&te[0].last, c->metric, &a, NULL) != ACBB_OK ||
        acbb_metric_value(&te[1].last, c->metric, &b, NULL) != ACBB_OK)
        return 0;
    *y = c->rel ? (a - b) / fabs(b) : a - b;
    return isfinite(*y);
}

void acbb_study_sign_base(const acbb_study_runs *r, acbb_study_robust *o)
{
    o->ok = sign_value(r, o->sign, &o->y);
    o->holds = o->ok && holds(o->y, o->sign);
    if (!o->ok) o->y = 0.0;
}

/* The end (key = value) with runs r: a turn if the condition's verdict
 * differs from the scene's; an end without a value counts as failed. */
void acbb_study_sign_end(const acbb_study_runs *r, const char *key, const char *value,
                         acbb_study_robust *o)
{
    double y;
    if (!o->ok) return;
    if (!sign_value(r, o->sign, &y)) {
        o->failed++;
        return;
    }
    if (holds(y, o->sign) == o->holds || o->n_turns >= 2 * ACBB_SENS_MAX) return;
    acbb_study_turn *t = &o->turns[o->n_turns++];
    snprintf(t->key, sizeof t->key, "%s", key);
    snprintf(t->value, sizeof t->value, "%s", value);
    t->y = y;
}
