/* acbb — the seed study's sign statements against the plausible ranges
 * (study.h, "robustness"): one one-at-a-time sensitivity per condition.
 * MODEL.md 13: the heavy-load TE/WTE signs rest on a sub-micron balance,
 * so a verdict is reported together with the single plausible changes that
 * would turn it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/study.h"
#include "acbb/units.h"

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

static void add_turn(acbb_study_robust *o, const acbb_sens_row *w, const char *end, double y)
{
    acbb_study_turn *t = &o->turns[o->n_turns++];
    snprintf(t->key, sizeof t->key, "%s", w->in.key);
    snprintf(t->value, sizeof t->value, "%s", end);
    t->y = y;
}

/* The single changes whose end turns the condition, largest effect first. */
static void collect(const acbb_sens_result *r, acbb_study_robust *o)
{
    o->ok = r->ok0;
    o->y = r->y0;
    o->holds = r->ok0 && holds(r->y0, o->sign);
    o->n_inputs = r->n;
    o->failed = r->failed;
    o->n_turns = 0;
    for (size_t i = 0; r->ok0 && i < r->n; i++) {
        const acbb_sens_row *w = &r->rows[i];
        if (w->ok_lo && holds(w->y_lo, o->sign) != o->holds) add_turn(o, w, w->in.lo, w->y_lo);
        if (w->ok_hi && holds(w->y_hi, o->sign) != o->holds) add_turn(o, w, w->in.hi, w->y_hi);
    }
}

acbb_status acbb_study_robustness(const acbb_scene *base, int jobs, const atomic_int *cancel,
                                  acbb_study_robust *out, acbb_error *err)
{
    static const size_t n = sizeof k_signs / sizeof k_signs[0];
    acbb_sens_result *r = malloc(sizeof *r);
    if (!r) return ACBB_ENOMEM;
    acbb_status st = ACBB_OK;
    for (size_t k = 0; k < n && st == ACBB_OK; k++) {
        acbb_scene sc = *base;
        sc.axial_load = k_signs[k].load_N;
        sc.inner_speed = k_signs[k].speed_rpm * ACBB_RPM;
        acbb_sens_opts o = {.delta_te = 1, .delta_rel = k_signs[k].rel, .oat = 1, .jobs = jobs,
                            .cancel = cancel};
        snprintf(o.metric, sizeof o.metric, "%s", k_signs[k].metric);
        out[k].sign = &k_signs[k];
        st = acbb_sensitivity_run(&sc, &o, r, err);
        if (st == ACBB_OK) collect(r, &out[k]);
    }
    free(r);
    return st;
}
