/* acbb — sensitivity of a metric to the uncertain inputs: one at a time
 * over each plausible range, and Morris elementary effects
 * (sensitivity.h). The runs go through the pool of sensitivity_run.c. */
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gsl_quiet.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/sensitivity.h"
#include "acbb/tools/scene_schema.h"

size_t acbb_sens_inputs(const acbb_scene *s, acbb_sens_input *out, size_t cap)
{
    size_t k = 0, n = acbb_scene_field_count();
    for (size_t i = 0; i < n && k < cap; i++) {
        const acbb_field_info *f = acbb_scene_field(i);
        if (!f->plaus_src || (f->type != ACBB_FIELD_REAL && f->type != ACBB_FIELD_ENUM)) continue;
        if (acbb_scene_field_unused(s, i)) continue; /* a spindle key with no spindle, ... */
        acbb_sens_input *in = &out[k++];
        in->field = i;
        in->src = f->plaus_src;
        snprintf(in->key, sizeof in->key, "%s.%s", f->section, f->key);
        acbb_scene_field_format(s, i, in->base, sizeof in->base);
        if (f->type == ACBB_FIELD_ENUM) {
            snprintf(in->lo, sizeof in->lo, "%s", f->choices[(int)f->plaus_lo]);
            snprintf(in->hi, sizeof in->hi, "%s", f->choices[(int)f->plaus_hi]);
        } else {
            snprintf(in->lo, sizeof in->lo, "%.15g", f->plaus_lo);
            snprintf(in->hi, sizeof in->hi, "%.15g", f->plaus_hi);
        }
    }
    return k;
}

acbb_status acbb_sens_apply(acbb_scene *s, const acbb_sens_input *in, double x, acbb_error *err)
{
    const acbb_field_info *f = acbb_scene_field(in->field);
    char text[64];
    if (f->type == ACBB_FIELD_ENUM)
        snprintf(text, sizeof text, "%s", x < 0.5 ? in->lo : in->hi);
    else if (x == 0.0 || x == 1.0)   /* the ends exactly as the schema writes them */
        snprintf(text, sizeof text, "%s", x == 0.0 ? in->lo : in->hi);
    else
        snprintf(text, sizeof text, "%.17g", f->plaus_lo + x * (f->plaus_hi - f->plaus_lo));
    return acbb_scene_set_value(s, in->key, text, err);
}

/* ---- progress over the phases (OAT, then Morris) ---- */

typedef struct {
    const acbb_sens_opts *o;
    size_t offset, total;
} phase_ctx;

static void phase_progress(void *ctx, size_t done, size_t total)
{
    (void)total;
    const phase_ctx *p = ctx;
    p->o->progress(p->o->ctx, p->offset + done, p->total);
}

/* Run n scenes into y; `fail` (may be NULL, 256 bytes) gets the first failure. */
static acbb_status eval_phase(const acbb_scene *sc, size_t n, const acbb_sens_opts *o,
                              phase_ctx *ph, double *y, acbb_sens_result *r, char *fail)
{
    acbb_sens_opts po = *o;
    if (o->progress) {
        po.progress = phase_progress;
        po.ctx = ph;
    }
    size_t before = r->runs;
    acbb_status st = acbb_sens_eval(sc, n, &po, y, fail, fail ? 256 : 0, &r->runs);
    ph->offset += (r->runs - before);
    for (size_t i = 0; i < n; i++) r->failed += !isfinite(y[i]);
    return st;
}

/* ---- one at a time ---- */

static int row_cmp(const void *a, const void *b)
{
    const acbb_sens_row *x = a, *y = b;
    return (x->effect < y->effect) - (x->effect > y->effect);
}

static int row_cmp_mu(const void *a, const void *b)
{
    const acbb_sens_row *x = a, *y = b;
    return (x->mu_star < y->mu_star) - (x->mu_star > y->mu_star);
}

static void oat_row(acbb_sens_row *row, double y0, int ok0, double ylo, double yhi)
{
    row->ok_lo = isfinite(ylo);
    row->ok_hi = isfinite(yhi);
    row->y_lo = row->ok_lo ? ylo : 0.0;
    row->y_hi = row->ok_hi ? yhi : 0.0;
    row->effect = 0.0;
    row->flips = 0;
    row->ok_effect = ok0 ? row->ok_lo || row->ok_hi : row->ok_lo && row->ok_hi;
    if (!ok0) {
        if (row->ok_lo && row->ok_hi) row->effect = fabs(yhi - ylo);
        return;
    }
    if (row->ok_lo) row->effect = fabs(ylo - y0);
    if (row->ok_hi && fabs(yhi - y0) > row->effect) row->effect = fabs(yhi - y0);
    row->flips = (row->ok_lo && ylo * y0 < 0) || (row->ok_hi && yhi * y0 < 0);
}

/* Scenes: [0] the base, then each input at its low and high end; an end
 * equal to the scene's value is the base run again and is not rerun. */
static acbb_status run_oat(const acbb_scene *base, const acbb_sens_opts *o, phase_ctx *ph,
                           acbb_sens_result *r, acbb_error *err)
{
    size_t n = 1 + 2 * r->n;
    acbb_scene *sc = malloc(n * sizeof *sc);
    double *y = malloc(n * sizeof *y);
    size_t *map = malloc(n * sizeof *map), m = 1;
    acbb_status st = sc && y && map ? ACBB_OK : ACBB_ENOMEM;
    if (st == ACBB_OK) sc[0] = *base, map[0] = 0;
    for (size_t j = 0; st == ACBB_OK && j < 2 * r->n; j++) {
        const acbb_sens_input *in = &r->rows[j / 2].in;
        char now[64];
        acbb_scene t = *base;
        st = acbb_sens_apply(&t, in, j % 2 ? 1.0 : 0.0, err);
        acbb_scene_field_format(&t, in->field, now, sizeof now);
        if (strcmp(now, in->base) == 0) map[1 + j] = 0;
        else sc[m] = t, map[1 + j] = m++;
    }
    ph->total -= (o->delta_te ? 2 : 1) * (n - m);
    /* the base alone first, so that its failure message is its own */
    if (st == ACBB_OK) st = eval_phase(sc, 1, o, ph, y, r, r->fail0);
    if (st == ACBB_OK) {
        r->ok0 = isfinite(y[0]);
        r->y0 = r->ok0 ? y[0] : 0.0;
        if (!r->ok0 && !r->fail0[0]) snprintf(r->fail0, sizeof r->fail0, "failed");
        if (r->ok0) r->fail0[0] = '\0';
        st = eval_phase(sc + 1, m - 1, o, ph, y + 1, r, NULL);
    }
    if (st == ACBB_OK) {
        for (size_t i = 0; i < r->n; i++)
            oat_row(&r->rows[i], y[0], r->ok0, y[map[1 + 2 * i]], y[map[2 + 2 * i]]);
    }
    free(sc);
    free(y);
    free(map);
    return st;
}

/* ---- Morris ---- */

/* Trajectory t's k + 1 points into x (row-major, k per point) and, for
 * step s, the input moved (who[s]). */
static void morris_design(gsl_rng *rng, size_t k, int p, double delta, double *x, size_t *who)
{
    size_t order[ACBB_SENS_MAX];
    for (size_t j = 0; j < k; j++) {
        order[j] = j;
        x[j] = (double)gsl_rng_uniform_int(rng, (unsigned long)p) / (p - 1);
    }
    gsl_ran_shuffle(rng, order, k, sizeof order[0]);
    for (size_t s = 0; s < k; s++) {
        double *prev = x + s * k, *cur = x + (s + 1) * k;
        memcpy(cur, prev, k * sizeof *cur);
        size_t j = order[s];
        cur[j] = prev[j] + delta <= 1.0 + 1e-12 ? prev[j] + delta : prev[j] - delta;
        who[s] = j;
    }
}

/* Elementary effects of every trajectory into the rows. */
static void morris_effects(acbb_sens_result *r, const double *x, const size_t *who,
                           const double *y)
{
    size_t k = r->n, per = k + 1;
    double sum[ACBB_SENS_MAX] = {0}, sabs[ACBB_SENS_MAX] = {0}, sq[ACBB_SENS_MAX] = {0};
    int cnt[ACBB_SENS_MAX] = {0};
    for (int t = 0; t < r->morris_r; t++)
        for (size_t s = 0; s < k; s++) {
            size_t a = t * per + s, j = who[t * k + s];
            if (!isfinite(y[a]) || !isfinite(y[a + 1])) continue;
            double ee = (y[a + 1] - y[a]) / (x[(a + 1) * k + j] - x[a * k + j]);
            sum[j] += ee, sabs[j] += fabs(ee), sq[j] += ee * ee, cnt[j]++;
        }
    for (size_t j = 0; j < k; j++) {
        acbb_sens_row *row = &r->rows[j];
        row->n_ee = cnt[j];
        if (!cnt[j]) continue;
        row->mu = sum[j] / cnt[j];
        row->mu_star = sabs[j] / cnt[j];
        double var = cnt[j] > 1 ? (sq[j] - cnt[j] * row->mu * row->mu) / (cnt[j] - 1) : 0.0;
        row->sigma = var > 0 ? sqrt(var) : 0.0;
    }
}

static acbb_status run_morris(const acbb_scene *base, const acbb_sens_opts *o, phase_ctx *ph,
                              acbb_sens_result *r, acbb_error *err)
{
    size_t k = r->n, per = k + 1, n = (size_t)r->morris_r * per;
    double *x = malloc(n * k * sizeof *x), *y = malloc(n * sizeof *y);
    size_t *who = malloc((size_t)r->morris_r * k * sizeof *who);
    acbb_scene *sc = malloc(n * sizeof *sc);
    acbb_gsl_enter(); /* the generator's allocation can reach GSL's handler (gsl_quiet.h) */
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    acbb_status st = x && y && who && sc && rng ? ACBB_OK : ACBB_ENOMEM;
    if (rng) gsl_rng_set(rng, o->seed ? o->seed : 1);
    for (int t = 0; st == ACBB_OK && t < r->morris_r; t++)
        morris_design(rng, k, r->morris_p, r->morris_delta, x + t * per * k, who + t * k);
    acbb_gsl_leave();
    for (size_t i = 0; st == ACBB_OK && i < n; i++) {
        sc[i] = *base;
        for (size_t j = 0; st == ACBB_OK && j < k; j++)
            st = acbb_sens_apply(&sc[i], &r->rows[j].in, x[i * k + j], err);
    }
    if (st == ACBB_OK) st = eval_phase(sc, n, o, ph, y, r, NULL);
    if (st == ACBB_OK) morris_effects(r, x, who, y);
    gsl_rng_free(rng);
    free(x), free(y), free(who), free(sc);
    return st;
}

static acbb_status check_opts(const acbb_sens_opts *o, acbb_error *err)
{
    acbb_status st = acbb_metric_check(o->metric, err);
    if (st != ACBB_OK) return st;
    if (o->morris_r < 0 || o->morris_r > ACBB_SENS_MORRIS_MAX)
        return acbb_error_set(err, ACBB_EINVAL, "Morris trajectories must be 0..%d, got %d",
                              ACBB_SENS_MORRIS_MAX, o->morris_r);
    int p = o->morris_p ? o->morris_p : 4;
    if (p < 2 || p > 20 || p % 2)
        return acbb_error_set(err, ACBB_EINVAL, "Morris levels must be even, 2..20, got %d", p);
    if (!o->oat && !o->morris_r)
        return acbb_error_set(err, ACBB_EINVAL, "nothing to do: neither one-at-a-time nor Morris");
    return ACBB_OK;
}

acbb_status acbb_sensitivity_run(const acbb_scene *base, const acbb_sens_opts *o,
                                 acbb_sens_result *r, acbb_error *err)
{
    double t0 = acbb_now_ms();
    memset(r, 0, sizeof *r);
    acbb_status st = check_opts(o, err);
    if (st != ACBB_OK) return st;
    snprintf(r->metric, sizeof r->metric, "%s", o->metric);
    r->delta_te = o->delta_te;
    acbb_sens_input in[ACBB_SENS_MAX];
    r->n = acbb_sens_inputs(base, in, ACBB_SENS_MAX);
    for (size_t i = 0; i < r->n; i++) r->rows[i].in = in[i];
    r->morris_r = o->morris_r;
    r->morris_p = o->morris_p ? o->morris_p : 4;
    r->morris_delta = r->morris_p / (2.0 * (r->morris_p - 1));
    size_t per = o->delta_te ? 2 : 1;
    phase_ctx ph = {.o = o, .total = per * ((o->oat ? 1 + 2 * r->n : 0)
                                            + (size_t)r->morris_r * (r->n + 1))};
    if (o->oat) st = run_oat(base, o, &ph, r, err);
    if (st == ACBB_OK && r->morris_r) st = run_morris(base, o, &ph, r, err);
    if (st == ACBB_OK) qsort(r->rows, r->n, sizeof r->rows[0], o->oat ? row_cmp : row_cmp_mu);
    if (st == ACBB_CANCELLED) acbb_error_set(err, st, "cancelled");
    r->wall_ms = acbb_now_ms() - t0;
    return st;
}
