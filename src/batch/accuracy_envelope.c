/* acbb — the accuracy envelope: every knob setting over the seed's 48
 * study points, steady state and transient path (include/acbb/tools/accuracy.h).
 *
 * Points run on the batch runner's parallel for (batch.h); each point runs
 * the one-knob plan and the fidelity ladder on a private Sim per run and
 * stores per-setting errors in its own slot, so the result does not depend
 * on the thread count. Aggregation (worst, median) happens once all points
 * are in. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/accuracy.h"
#include "acbb/batch.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/study.h"
#include "accuracy_priv.h"
#include "cancel.h"

/* What one setting gave at one point. */
typedef struct {
    int ok;                     /* it and its reference converged */
    double e_loss, e_T, e_path, path_K, work, wall_ms;
} cell;

typedef struct {
    const acbb_scene *base;
    acbb_accuracy_options plan;
    size_t n_plan, n_ladder, n_rows;
    size_t points[ACBB_ENVELOPE_POINTS], n_points;
    cell *cells;                /* n_points x n_rows */
    acbb_accuracy_row *proto;   /* the first point's rows (labels, flags) */
    _Atomic size_t next, done;
    _Atomic int oom;
    const _Atomic int *cancel;
    pthread_mutex_t lock;
    acbb_accuracy_progress progress;
    void *ctx;
} env;

void acbb_envelope_point(size_t i, double *rpm, double *load_N, int *te)
{
    size_t sweep = (i / 16) % ACBB_STUDY_NSWEEPS, k = (i % 16) / 2;
    *rpm = sweep == ACBB_STUDY_LOAD ? 15000.0 : acbb_study_speeds[k];
    *load_N = sweep == ACBB_STUDY_LOAD ? acbb_study_loads[k]
              : sweep == ACBB_STUDY_S100 ? 100.0 : 1000.0;
    *te = i % 2 == 0;
}

static size_t ladder_n(const acbb_envelope_options *o)
{
    size_t n = 0;
    acbb_fidelity_table(&n);
    return o && o->ladder ? n : 0;
}

size_t acbb_envelope_size(const acbb_envelope_options *o)
{
    acbb_accuracy_options p = { .knobs = o ? o->knobs : 0,
                                .model_levels = o ? o->model_levels : 0 };
    return acbb_accuracy_plan_size(&p) + ladder_n(o);
}

static acbb_status point_scene(const acbb_scene *base, size_t i, acbb_scene *sc,
                               acbb_error *err)
{
    double rpm, load;
    int te;
    acbb_envelope_point(i, &rpm, &load, &te);
    char v[2][32];
    snprintf(v[0], sizeof v[0], "%g", rpm);
    snprintf(v[1], sizeof v[1], "%g", load);
    /* Resolve a preset / target once: left in, it would override the
     * ladder's knobs when each Sim compiles its scene. */
    acbb_scene_resolve(base, sc, NULL);
    acbb_status st = acbb_scene_set(sc, "operating.inner_speed_rpm", v[0], err);
    if (st == ACBB_OK) st = acbb_scene_set(sc, "operating.axial_load_N", v[1], err);
    if (st == ACBB_OK) st = acbb_scene_set(sc, "effects.thermal_expansion", te ? "on" : "off", err);
    return st == ACBB_OK ? acbb_scene_validate(sc, err) : st;
}

/* ---- the transient path ---- */

/* y of path p at time t: linear between samples, held before the first
 * and after the last (a converged run stays at its steady state). */
static double path_at(const acbb_acc_path *p, double t)
{
    if (t <= p->t[0]) return p->y[0];
    if (t >= p->t[p->n - 1]) return p->y[p->n - 1];
    size_t lo = 0, hi = p->n - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (p->t[mid] <= t) lo = mid;
        else hi = mid;
    }
    double dt = p->t[hi] - p->t[lo];
    double w = dt > 0.0 ? (t - p->t[lo]) / dt : 1.0;
    return p->y[lo] + w * (p->y[hi] - p->y[lo]);
}

static double max_gap(const acbb_acc_path *a, const acbb_acc_path *b)
{
    double m = 0.0;
    for (size_t i = 0; i < a->n; i++) m = fmax(m, fabs(a->y[i] - path_at(b, a->t[i])));
    return m;
}

double acbb_acc_path_gap(const acbb_acc_path *a, const acbb_acc_path *ref)
{
    if (!a || !ref || a->oom || ref->oom || a->n < 2 || ref->n < 2) return NAN;
    if (!(a->t[a->n - 1] > 0.0) || !(ref->t[ref->n - 1] > 0.0)) return NAN;
    return fmax(max_gap(a, ref), max_gap(ref, a));
}

/* On the scale of the steady temperature error (accuracy.h,
 * ACBB_ACCURACY_T_FLOOR_K): a 13 mK lag on a 0.047 K rise is not 27 %. */
double acbb_acc_path_err(const acbb_acc_path *a, const acbb_acc_path *ref)
{
    double gap = acbb_acc_path_gap(a, ref);
    if (!isfinite(gap) || !isfinite(ref->y[ref->n - 1])) return NAN;
    return gap / fmax(fabs(ref->y[ref->n - 1]), ACBB_ACCURACY_T_FLOOR_K);
}

/* ---- one point ---- */

static void fill_cell(cell *c, const acbb_accuracy_row *r, const acbb_accuracy_row *ref,
                      const acbb_acc_path *p, const acbb_acc_path *pref)
{
    c->ok = r->status == ACBB_OK && ref->status == ACBB_OK;
    c->e_loss = acbb_acc_rel_err(r->loss, ref->loss);
    c->e_T = acbb_acc_temp_err(r->dT_outer, ref->dT_outer);
    c->e_path = c->ok ? acbb_acc_path_err(p, pref) : NAN;
    c->path_K = c->ok ? acbb_acc_path_gap(p, pref) : NAN;
    c->ok = c->ok && isfinite(c->e_loss) && isfinite(c->e_T);
    c->work = r->work;
    c->wall_ms = r->wall_ms;
}

/* The ladder at one scene: rows[j] and paths[j] per entry. */
static void run_ladder(env *E, const acbb_scene *sc, acbb_accuracy_row *rows,
                       acbb_acc_path *paths)
{
    const acbb_fidelity_point *lad = acbb_fidelity_table(NULL);
    for (size_t j = 0; j < E->n_ladder; j++) {
        acbb_scene s = *sc;
        acbb_fidelity_set(&s, &lad[j]);
        memset(&rows[j], 0, sizeof rows[j]);
        rows[j].knob = ACBB_KNOB_COUNT;
        rows[j].is_reference = lad[j].preset == ACBB_FIDELITY_REFERENCE;
        snprintf(rows[j].key, sizeof rows[j].key, "ladder");
        snprintf(rows[j].value, sizeof rows[j].value, "%s", lad[j].name);
        acbb_acc_run_one(&s, E->cancel, E->plan.sim_threads, &rows[j], &paths[j]);
        rows[j].is_default = 0; /* run_one compared the scene with itself */
    }
}

static void score_point(env *E, size_t pi, const acbb_accuracy_row *rows,
                        const acbb_acc_path *paths)
{
    cell *c = &E->cells[pi * E->n_rows];
    for (size_t i = 0; i < E->n_plan; i++) {
        long ref = acbb_accuracy_reference(rows, E->n_plan, rows[i].knob);
        if (ref < 0) continue;
        fill_cell(&c[i], &rows[i], &rows[ref], &paths[i], &paths[ref]);
    }
    size_t lref = E->n_plan;
    for (size_t j = E->n_plan; j < E->n_rows; j++)
        if (rows[j].is_reference) lref = j;
    for (size_t j = E->n_plan; j < E->n_rows && lref < E->n_rows; j++)
        fill_cell(&c[j], &rows[j], &rows[lref], &paths[j], &paths[lref]);
}

static int run_point(env *E, size_t pi, acbb_accuracy_row *rows, acbb_acc_path *paths)
{
    acbb_scene sc;
    acbb_error err = { { 0 } };
    size_t n = 0;
    memset(paths, 0, E->n_rows * sizeof *paths);
    int ok = point_scene(E->base, E->points[pi], &sc, &err) == ACBB_OK &&
             acbb_acc_run_plan(&sc, &E->plan, rows, paths, &n, NULL, NULL) == ACBB_OK;
    if (ok) run_ladder(E, &sc, rows + E->n_plan, paths + E->n_plan);
    for (size_t i = 0; i < E->n_rows; i++) {
        if (paths[i].oom) atomic_store(&E->oom, 1);
        if (ok) continue;
        memset(&rows[i], 0, sizeof rows[i]); /* a bad point: every cell not ok */
        rows[i].status = ACBB_EINVAL;
    }
    if (ok) score_point(E, pi, rows, paths);
    for (size_t i = 0; i < E->n_rows; i++) acbb_acc_path_free(&paths[i]);
    return ok;
}

/* One point on a batch worker; rows and paths are private to the call. */
static void point_fn(void *ctx, size_t pi)
{
    env *E = ctx;
    acbb_accuracy_row *rows = calloc(E->n_rows, sizeof *rows);
    acbb_acc_path *paths = calloc(E->n_rows, sizeof *paths);
    if (rows && paths) {
        int ok = run_point(E, pi, rows, paths);
        pthread_mutex_lock(&E->lock);
        if (ok && !E->proto[0].key[0]) memcpy(E->proto, rows, E->n_rows * sizeof *rows);
        size_t d = atomic_fetch_add(&E->done, 1) + 1;
        if (E->progress) E->progress(E->ctx, d, E->n_points);
        pthread_mutex_unlock(&E->lock);
    } else {
        atomic_store(&E->oom, 1);
    }
    free(rows);
    free(paths);
}

/* ---- aggregation ---- */

/* Worst and median of the finite values among v[0..n); NaN if none. */
static void worst_median(double *v, size_t n, double *worst, double *med)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(v[i])) v[m++] = v[i];
    *worst = *med = NAN;
    if (m == 0) return;
    *med = acbb_median(v, m); /* sorts v */
    *worst = v[m - 1];
}

static void aggregate(const env *E, size_t j, double *buf, acbb_envelope_row *out)
{
    const acbb_accuracy_row *p = &E->proto[j];
    memset(out, 0, sizeof *out);
    out->knob = p->knob;
    memcpy(out->key, p->key, sizeof out->key);
    memcpy(out->value, p->value, sizeof out->value);
    out->is_reference = p->is_reference;
    out->is_default = p->is_default;
    out->n_points = (int)E->n_points;
    double *col[7];
    for (int k = 0; k < 7; k++) col[k] = buf + (size_t)k * E->n_points;
    size_t m = 0;
    for (size_t pi = 0; pi < E->n_points; pi++) {
        const cell *c = &E->cells[pi * E->n_rows + j];
        if (!c->ok) continue;
        col[0][m] = c->e_loss;
        col[1][m] = c->e_T;
        col[2][m] = fmax(c->e_loss, c->e_T);
        col[3][m] = c->e_path;
        col[4][m] = c->work;
        col[5][m] = c->wall_ms;
        col[6][m] = c->path_K;
        m++;
    }
    out->n_ok = (int)m;
    double unused;
    worst_median(col[0], m, &out->worst_loss, &out->median_loss);
    worst_median(col[1], m, &out->worst_T, &out->median_T);
    worst_median(col[2], m, &out->worst_steady, &out->median_steady);
    worst_median(col[3], m, &out->worst_path, &out->median_path);
    worst_median(col[4], m, &unused, &out->work);
    worst_median(col[5], m, &unused, &out->wall_ms);
    worst_median(col[6], m, &out->worst_path_K, &unused);
}

static acbb_status setup(env *E, const acbb_scene *base, const acbb_envelope_options *o,
                         acbb_error *err)
{
    memset(E, 0, sizeof *E);
    acbb_accuracy_options p = { .knobs = o->knobs, .model_levels = o->model_levels,
                                .repeats = 1, .cancel = o->cancel };
    acbb_status st = acbb_acc_resolve(&p, &E->plan, err);
    if (st != ACBB_OK) return st;
    if (o->points < 0 || o->points > ACBB_ENVELOPE_POINTS)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy envelope: points = %d: 1..%d",
                              o->points, ACBB_ENVELOPE_POINTS);
    if ((st = acbb_scene_validate(base, err)) != ACBB_OK) return st;
    E->base = base;
    E->cancel = o->cancel;
    E->n_points = o->points ? (size_t)o->points : ACBB_ENVELOPE_POINTS;
    for (size_t k = 0; k < E->n_points; k++)
        E->points[k] = k * ACBB_ENVELOPE_POINTS / E->n_points;
    E->n_plan = acbb_accuracy_plan_size(&E->plan);
    E->n_ladder = ladder_n(o);
    E->n_rows = E->n_plan + E->n_ladder;
    E->cells = calloc(E->n_points * E->n_rows, sizeof *E->cells);
    E->proto = calloc(E->n_rows, sizeof *E->proto);
    if (!E->cells || !E->proto)
        return acbb_error_set(err, ACBB_ENOMEM, "accuracy envelope: out of memory");
    return ACBB_OK;
}

acbb_status acbb_accuracy_envelope(const acbb_scene *base, const acbb_envelope_options *o,
                                   acbb_envelope_row *rows, size_t cap, size_t *n,
                                   double *wall_ms, acbb_accuracy_progress progress, void *ctx,
                                   acbb_error *err)
{
    acbb_envelope_options zero = { 0 };
    env E;
    double t0 = acbb_now_ms();
    if (n) *n = 0;
    if (!base || !rows || !n)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy envelope: base, rows and n required");
    acbb_status st = setup(&E, base, o ? o : &zero, err);
    if (st == ACBB_OK && cap < E.n_rows)
        st = acbb_error_set(err, ACBB_EINVAL, "accuracy envelope: %zu rows needed, room for %zu",
                            E.n_rows, cap);
    double *buf = st == ACBB_OK ? calloc(7 * E.n_points, sizeof *buf) : NULL;
    if (st == ACBB_OK && !buf) st = acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (st == ACBB_OK) {
        E.progress = progress;
        E.ctx = ctx;
        pthread_mutex_init(&E.lock, NULL);
        int jobs = o ? o->jobs : 0;
        /* Points fill the cores: each run keeps to its thread (batch.h). */
        E.plan.sim_threads = acbb_batch_workers(E.n_points, jobs) > 1 ? 1 : 0;
        acbb_batch_for(E.n_points, jobs, point_fn, &E, E.cancel);
        pthread_mutex_destroy(&E.lock);
        if (acbb_cancelled(E.cancel))
            st = acbb_error_set(err, ACBB_CANCELLED, "accuracy envelope: cancelled");
        else if (atomic_load(&E.oom))
            st = acbb_error_set(err, ACBB_ENOMEM, "accuracy envelope: out of memory");
    }
    if (st == ACBB_OK) {
        for (size_t j = 0; j < E.n_rows; j++) aggregate(&E, j, buf, &rows[j]);
        *n = E.n_rows;
    }
    free(buf);
    free(E.cells);
    free(E.proto);
    if (wall_ms) *wall_ms = acbb_now_ms() - t0;
    return st;
}

void acbb_envelope_frontier(const acbb_envelope_row *rows, size_t n, double tol,
                            long picks[ACBB_KNOB_COUNT])
{
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        long best = -1, ref = -1;
        picks[k] = -1;
        for (size_t i = 0; i < n; i++)
            if (rows[i].knob == (acbb_accuracy_knob)k && rows[i].is_reference) ref = (long)i;
        if (ref < 0 || rows[ref].n_ok < rows[ref].n_points || rows[ref].n_ok == 0) continue;
        for (size_t i = 0; i < n; i++) {
            const acbb_envelope_row *r = &rows[i];
            if (r->knob != (acbb_accuracy_knob)k || r->n_ok < r->n_points) continue;
            /* The TUI shows the path: it must be followed too (NaN: no path). */
            if ((long)i != ref && !(r->worst_steady <= tol && r->worst_path <= tol)) continue;
            if (best < 0 || r->work < rows[best].work) best = (long)i;
        }
        picks[k] = best;
    }
}
