/* acbb — accuracy-versus-time benchmark (include/acbb/tools/accuracy.h).
 *
 * One knob at a time around the base scene (DESIGN.md "Fidelity and
 * effects": every fidelity setting against the finest one on the same
 * scene). Each setting is a copy of the base scene edited through
 * acbb_scene_set, so values are given and validated in preset units exactly
 * as a user's `--set` would be. */
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "acbb/tools/accuracy.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/measure.h"
#include "acbb/sim.h"
#include "acbb/tools/scene_schema.h"
#include "accuracy_priv.h"
#include "cancel.h"

/* One setting of the plan: the edit shown to the user (key = value) and an
 * optional second edit applied with it (the time-step rows force a transient
 * solve so that the base scene's thermal_mode cannot make them identical). */
typedef struct {
    acbb_accuracy_knob knob;
    const char *key, *value;
    const char *key2, *value2;
    int is_reference;   /* fixed reference; the model knob's is chosen at run time */
    int optional;       /* may be refused by acbb_sim_create (not implemented yet) */
    int level;          /* the model knob's acbb_model_level; -1 for other knobs */
} plan_entry;

#define E1(k, key, v, ref) { k, key, v, NULL, NULL, ref, 0, -1 }
#define LEVEL(v, m, opt) { ACBB_KNOB_MODEL, "fidelity.model", v, NULL, NULL, 0, opt, m }

static const plan_entry k_plan[] = {
    /* Model ladder, cheapest first; the highest accepted level is the reference. */
    LEVEL("static", ACBB_MODEL_STATIC, 0),
    LEVEL("quasi-static", ACBB_MODEL_QUASI_STATIC, 0),
    LEVEL("quasi-dynamic", ACBB_MODEL_QUASI_DYNAMIC, 0),
    LEVEL("dynamic", ACBB_MODEL_DYNAMIC, 1),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "4", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "6", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "8", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "12", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "16", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "24", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "32", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "48", 0),
    E1(ACBB_KNOB_CONTACT_GRID, "fidelity.contact_grid", "64", 1),
    E1(ACBB_KNOB_HERTZ, "fidelity.hertz", "hb83", 0),
    E1(ACBB_KNOB_HERTZ, "fidelity.hertz", "bh77", 0),
    E1(ACBB_KNOB_HERTZ, "fidelity.hertz", "exact", 1),
    E1(ACBB_KNOB_MECH_TOL, "fidelity.mech_tol", "1e-4", 0),
    E1(ACBB_KNOB_MECH_TOL, "fidelity.mech_tol", "1e-6", 0),
    E1(ACBB_KNOB_MECH_TOL, "fidelity.mech_tol", "1e-8", 0),
    E1(ACBB_KNOB_MECH_TOL, "fidelity.mech_tol", "1e-10", 0),
    E1(ACBB_KNOB_MECH_TOL, "fidelity.mech_tol", "1e-12", 1),
    E1(ACBB_KNOB_STEADY_TOL, "fidelity.steady_tol_K_s", "1e-2", 0),
    E1(ACBB_KNOB_STEADY_TOL, "fidelity.steady_tol_K_s", "1e-3", 0),
    E1(ACBB_KNOB_STEADY_TOL, "fidelity.steady_tol_K_s", "1e-4", 0),
    E1(ACBB_KNOB_STEADY_TOL, "fidelity.steady_tol_K_s", "1e-5", 1),
    { ACBB_KNOB_THERMAL, "fidelity.time_step_s", "1", "fidelity.thermal_mode", "transient", 1, 0, -1 },
    { ACBB_KNOB_THERMAL, "fidelity.time_step_s", "5", "fidelity.thermal_mode", "transient", 0, 0, -1 },
    { ACBB_KNOB_THERMAL, "fidelity.time_step_s", "30", "fidelity.thermal_mode", "transient", 0, 0, -1 },
    E1(ACBB_KNOB_THERMAL, "fidelity.thermal_mode", "steady", 0),
    E1(ACBB_KNOB_NETWORK, "fidelity.network", "7", 0),
    E1(ACBB_KNOB_NETWORK, "fidelity.network", "46", 1),
};

#define PLAN_N (sizeof k_plan / sizeof k_plan[0])

static const char *const k_knob_names[ACBB_KNOB_COUNT] = {
    "model", "contact_grid", "hertz", "mech_tol", "steady_tol", "thermal", "network",
};

const char *acbb_accuracy_knob_name(acbb_accuracy_knob k)
{
    return (unsigned)k < ACBB_KNOB_COUNT ? k_knob_names[k] : "unknown";
}

int acbb_accuracy_knob_from_name(const char *name)
{
    for (int k = 0; k < ACBB_KNOB_COUNT; k++)
        if (name && strcmp(name, k_knob_names[k]) == 0) return k;
    return -1;
}

/* The options with defaults filled in; ACBB_EINVAL for a bad value. */
acbb_status acbb_acc_resolve(const acbb_accuracy_options *opt, acbb_accuracy_options *o,
                             acbb_error *err)
{
    acbb_accuracy_options zero = { 0 };
    *o = opt ? *opt : zero;
    if (o->knobs == 0) o->knobs = ACBB_ACCURACY_ALL_KNOBS;
    if (o->model_levels == 0) o->model_levels = ACBB_ACCURACY_ALL_LEVELS;
    if (o->repeats == 0) o->repeats = ACBB_ACCURACY_DEFAULT_REPEATS;
    if (o->knobs & ~ACBB_ACCURACY_ALL_KNOBS)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy: knob mask 0x%x: unknown bits", o->knobs);
    if (o->model_levels & ~ACBB_ACCURACY_ALL_LEVELS)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy: model level mask 0x%x: unknown bits",
                              o->model_levels);
    if (o->repeats < 1 || o->repeats > ACBB_ACCURACY_MAX_REPEATS)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy: repeats = %d: 1..%d", o->repeats,
                              ACBB_ACCURACY_MAX_REPEATS);
    return ACBB_OK;
}

static int planned(const acbb_accuracy_options *o, const plan_entry *p)
{
    if (!(o->knobs & ACBB_ACCURACY_KNOB_BIT(p->knob))) return 0;
    return p->level < 0 || (o->model_levels & ACBB_ACCURACY_LEVEL_BIT(p->level)) != 0;
}

static size_t plan_count(const acbb_accuracy_options *o)
{
    size_t n = 0;
    for (size_t i = 0; i < PLAN_N; i++) n += (size_t)planned(o, &k_plan[i]);
    return n;
}

size_t acbb_accuracy_plan_size(const acbb_accuracy_options *opt)
{
    acbb_accuracy_options o;
    if (acbb_acc_resolve(opt, &o, NULL) != ACBB_OK) return 0;
    return plan_count(&o);
}

/* ---- one setting ---- */

/* True when every schema field of `a` formats like the same field of `b`:
 * compares what a user can set, not padding bytes or derived values. */
static int same_scene(const acbb_scene *a, const acbb_scene *b)
{
    char fa[96], fb[96];
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        acbb_scene_field_format(a, i, fa, sizeof fa);
        acbb_scene_field_format(b, i, fb, sizeof fb);
        if (strcmp(fa, fb) != 0) return 0;
    }
    return 1;
}

static void row_init(acbb_accuracy_row *r, const plan_entry *p)
{
    memset(r, 0, sizeof *r);
    r->knob = p->knob;
    snprintf(r->key, sizeof r->key, "%s", p->key);
    snprintf(r->value, sizeof r->value, "%s", p->value);
    r->is_reference = p->is_reference;
    r->status = ACBB_OK;
    r->wall_ms = r->work = r->loss = r->dT_outer = r->Qi = r->alpha_i = r->slide_i = NAN;
    r->e_loss = r->e_T = r->e_Qi = r->e_alpha = r->e_slide = NAN;
}

void acbb_acc_path_free(acbb_acc_path *p)
{
    if (!p) return;
    free(p->t);
    free(p->y);
    memset(p, 0, sizeof *p);
}

/* Step hook: append (time, outer-ring rise). The snapshot is large, so it
 * lives in the recorder, not on the stack of every call. */
typedef struct {
    acbb_acc_path *path;
    double ambient;
    acbb_snapshot snap;
} path_rec;

static int record_step(void *ctx, const acbb_sim *sim)
{
    path_rec *pr = ctx;
    acbb_acc_path *p = pr->path;
    if (p->oom) return 0;
    if (p->n == p->cap) {
        size_t cap = p->cap ? 2 * p->cap : 256;
        double *t = realloc(p->t, cap * sizeof *t);
        if (t) p->t = t;
        double *y = t ? realloc(p->y, cap * sizeof *y) : NULL;
        if (y) p->y = y;
        if (!t || !y) {
            p->oom = 1;
            return 0;
        }
        p->cap = cap;
    }
    acbb_sim_snapshot(sim, &pr->snap);
    p->t[p->n] = pr->snap.time;
    p->y[p->n] = pr->snap.T_outer_ring - pr->ambient;
    p->n++;
    return 0;
}

/* The engine's run loop; a cancel ends it inside a step too. With a path,
 * every step's outer-ring rise is recorded. */
static acbb_status run_sim(acbb_sim *sim, const acbb_scene *sc, const _Atomic int *cancel,
                           acbb_acc_path *path)
{
    acbb_run_ctl ctl = { .cancel = cancel };
    path_rec *pr = path ? malloc(sizeof *pr) : NULL;
    if (pr) {
        pr->path = path;
        pr->ambient = sc->ambient_C;
        ctl.hook = record_step;
        ctl.ctx = pr;
    } else if (path) {
        path->oom = 1;
    }
    acbb_status st = acbb_sim_drive(sim, &ctl);
    free(pr);
    return st;
}

/* One timed run: acbb_sim_create + acbb_sim_run + acbb_sim_free on the clock,
 * the snapshot copy off it. Returns the run's status; a run that ended
 * without converging is reported as such even if the last step said OK. */
static acbb_status timed_run(const acbb_scene *sc, const _Atomic int *cancel, int threads,
                             acbb_acc_path *path, acbb_snapshot *snap, int *have_snap, double *ms,
                             acbb_error *err)
{
    acbb_sim *sim = NULL;
    double t0 = acbb_now_ms();
    acbb_status st = acbb_sim_create(sc, &(acbb_sim_opts){ .cancel = cancel, .threads = threads }, &sim, err);
    if (st != ACBB_OK) {
        *ms = acbb_now_ms() - t0;
        *have_snap = 0;
        return st;
    }
    st = run_sim(sim, sc, cancel, path);
    double t1 = acbb_now_ms();
    acbb_sim_snapshot(sim, snap);
    double t2 = acbb_now_ms();
    acbb_sim_free(sim);
    *ms = (t1 - t0) + (acbb_now_ms() - t2);
    *have_snap = 1;
    if (st == ACBB_OK && snap->state != ACBB_RUN_CONVERGED) st = ACBB_NOT_CONVERGED;
    if (st != ACBB_OK) acbb_error_set(err, st, "%s", snap->message);
    return st;
}

static void record_results(acbb_accuracy_row *r, const acbb_scene *sc, const acbb_snapshot *snap)
{
    r->work = acbb_accuracy_work_units(sc, &snap->work);
    r->loss = snap->losses.total;
    r->dT_outer = snap->T_outer_ring - sc->ambient_C;
    if (snap->n_balls > 0) {
        r->Qi = snap->balls[0].Qi;
        r->alpha_i = snap->balls[0].alpha_i;
        r->slide_i = snap->balls[0].slide_i;
    }
}

/* Apply the entry's edits to a copy of the base scene. */
static acbb_status make_scene(const acbb_scene *base, const plan_entry *p, acbb_scene *sc,
                              acbb_error *err)
{
    *sc = *base;
    if (!p->key[0]) return acbb_scene_validate(sc, err); /* the scene as given */
    acbb_status st = acbb_scene_set(sc, p->key, p->value, err);
    if (st == ACBB_OK && p->key2) st = acbb_scene_set(sc, p->key2, p->value2, err);
    if (st == ACBB_OK) st = acbb_scene_validate(sc, err);
    return st;
}

/* Run one setting `repeats` times. The engine is deterministic, so the
 * results are those of the first run; later runs only add timing samples.
 * A failure ends the repeats (the same failure would recur). */
static void run_entry(const acbb_scene *base, const plan_entry *p, int repeats,
                      const _Atomic int *cancel, int threads, acbb_accuracy_row *r,
                      acbb_acc_path *path)
{
    row_init(r, p);
    acbb_error e = { { 0 } };
    acbb_scene sc;
    acbb_status st = make_scene(base, p, &sc, &e);
    if (st != ACBB_OK) {
        r->status = st;
        r->skipped = p->optional;
        snprintf(r->message, sizeof r->message, "%s", e.msg);
        return;
    }
    r->is_default = same_scene(base, &sc);
    acbb_snapshot snap;
    memset(&snap, 0, sizeof snap);
    double times[ACBB_ACCURACY_MAX_REPEATS];
    int done = 0;
    for (; done < repeats && !acbb_cancelled(cancel); done++) {
        int have_snap = 0;
        st = timed_run(&sc, cancel, threads, done == 0 ? path : NULL, &snap, &have_snap,
                       &times[done], &e);
        if (done == 0 && have_snap) r->iterations = snap.iteration;
        if (st != ACBB_OK) {
            done++;
            break;
        }
        if (done == 0) record_results(r, &sc, &snap);
    }
    if (done == 0) return; /* cancelled before the first run: the caller drops the row */
    r->wall_ms = acbb_median(times, (size_t)done);
    if (st == ACBB_OK) return;
    r->status = st;
    snprintf(r->message, sizeof r->message, "%s", e.msg);
    r->work = r->loss = r->dT_outer = r->Qi = r->alpha_i = r->slide_i = NAN;
    /* An optional level that the engine refuses as input is "not available". */
    if (p->optional && st == ACBB_EINVAL) r->skipped = 1;
}

/* ---- errors against the reference ---- */

double acbb_acc_rel_err(double x, double ref)
{
    if (!isfinite(x) || !isfinite(ref)) return NAN;
    if (ref == 0.0) return x == 0.0 ? 0.0 : NAN;
    return fabs(x - ref) / fabs(ref);
}

/* A rise below the floor is within thermocouple tolerance (accuracy.h,
 * ACBB_ACCURACY_T_FLOOR_K): relative to it the error would mean nothing. */
double acbb_acc_temp_err(double dT, double dT_ref)
{
    if (!isfinite(dT) || !isfinite(dT_ref)) return NAN;
    return fabs(dT - dT_ref) / fmax(fabs(dT_ref), ACBB_ACCURACY_T_FLOOR_K);
}

long acbb_accuracy_reference(const acbb_accuracy_row *rows, size_t n, acbb_accuracy_knob k)
{
    for (size_t i = 0; i < n; i++)
        if (rows[i].knob == k && rows[i].is_reference) return (long)i;
    return -1;
}

/* The model knob's reference: the highest level the engine accepted. The
 * plan lists levels in increasing order, so it is the last row not skipped. */
static void mark_model_reference(acbb_accuracy_row *rows, size_t n)
{
    long ref = -1;
    for (size_t i = 0; i < n; i++)
        if (rows[i].knob == ACBB_KNOB_MODEL && !rows[i].skipped) ref = (long)i;
    if (ref >= 0) rows[ref].is_reference = 1;
}

static void fill_errors(acbb_accuracy_row *rows, size_t n)
{
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        long ref = acbb_accuracy_reference(rows, n, (acbb_accuracy_knob)k);
        if (ref < 0 || rows[ref].status != ACBB_OK) continue;
        const acbb_accuracy_row *R = &rows[ref];
        for (size_t i = 0; i < n; i++) {
            acbb_accuracy_row *r = &rows[i];
            if (r->knob != (acbb_accuracy_knob)k || r->status != ACBB_OK) continue;
            r->e_loss = acbb_acc_rel_err(r->loss, R->loss);
            r->e_T = acbb_acc_temp_err(r->dT_outer, R->dT_outer);
            r->e_Qi = acbb_acc_rel_err(r->Qi, R->Qi);
            r->e_alpha = acbb_acc_rel_err(r->alpha_i, R->alpha_i);
            r->e_slide = acbb_acc_rel_err(r->slide_i, R->slide_i);
        }
    }
}

acbb_status acbb_acc_run_plan(const acbb_scene *base_in, const acbb_accuracy_options *o,
                              acbb_accuracy_row *rows, acbb_acc_path *paths, size_t *n,
                              acbb_accuracy_progress progress, void *ctx)
{
    /* A preset or target in the base would override every edit below:
     * resolve it once, then vary the knobs it chose. */
    acbb_scene base;
    acbb_scene_resolve(base_in, &base, NULL);
    size_t total = plan_count(o), done = 0;
    for (size_t i = 0; i < PLAN_N; i++) {
        if (!planned(o, &k_plan[i])) continue;
        if (acbb_cancelled(o->cancel)) break;
        run_entry(&base, &k_plan[i], o->repeats, o->cancel, o->sim_threads, &rows[done],
                  paths ? &paths[done] : NULL);
        /* A cancel during the row may have cut its run short: drop it. */
        if (acbb_cancelled(o->cancel)) break;
        done++;
        if (progress) progress(ctx, done, total);
    }
    *n = done;
    if (done < total) return ACBB_CANCELLED; /* only a cancel stops the loop early */
    mark_model_reference(rows, done);
    fill_errors(rows, done);
    return ACBB_OK;
}

acbb_status acbb_accuracy_run(const acbb_scene *base, const acbb_accuracy_options *opt,
                              acbb_accuracy_row *rows, size_t cap, size_t *n,
                              acbb_accuracy_progress progress, void *ctx,
                              acbb_error *err)
{
    if (n) *n = 0;
    if (!base || !rows || !n)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy: base, rows and n are required");
    acbb_accuracy_options o;
    acbb_status st = acbb_acc_resolve(opt, &o, err);
    if (st != ACBB_OK) return st;
    size_t total = plan_count(&o);
    if (cap < total)
        return acbb_error_set(err, ACBB_EINVAL, "accuracy: %zu rows needed, room for %zu",
                              total, cap);
    if ((st = acbb_scene_validate(base, err)) != ACBB_OK) return st;
    st = acbb_acc_run_plan(base, &o, rows, NULL, n, progress, ctx);
    if (st == ACBB_CANCELLED)
        acbb_error_set(err, ACBB_CANCELLED, "accuracy: cancelled after %zu of %zu settings",
                       *n, total);
    return st;
}

/* One run of a finished scene (the envelope's ladder entries). */
void acbb_acc_run_one(const acbb_scene *sc, const _Atomic int *cancel, int threads,
                      acbb_accuracy_row *r, acbb_acc_path *path)
{
    plan_entry p = { r->knob, "", "", NULL, NULL, r->is_reference, 0, -1 };
    acbb_accuracy_row keep = *r;
    run_entry(sc, &p, 1, cancel, threads, r, path);
    memcpy(r->key, keep.key, sizeof r->key);
    memcpy(r->value, keep.value, sizeof r->value);
}

/* ---- frontier ---- */

void acbb_accuracy_frontier(const acbb_accuracy_row *rows, size_t n, double tol,
                            long picks[ACBB_KNOB_COUNT])
{
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        long ref = acbb_accuracy_reference(rows, n, (acbb_accuracy_knob)k), best = -1;
        picks[k] = -1;
        if (ref < 0 || rows[ref].status != ACBB_OK) continue;
        /* Rows in plan order (coarsest first), so on equal work the coarser
         * setting wins: a deterministic tie rule. */
        for (size_t i = 0; i < n; i++) {
            const acbb_accuracy_row *r = &rows[i];
            if (r->knob != (acbb_accuracy_knob)k || r->status != ACBB_OK) continue;
            /* NaN errors compare false, so undefined errors never qualify. */
            if ((long)i != ref && !(r->e_loss <= tol && r->e_T <= tol)) continue;
            if (best < 0 || r->work < rows[best].work) best = (long)i;
        }
        picks[k] = best;
    }
}

/* ---- cost in work units ---- */

/* Instructions per unit of work (millions), measured once with callgrind
 * on the 7008C default point and its one-knob variants (BENCHMARKS.md
 * "Cost in work units"): a mechanics solve 0.20 (bh77/hb83) or 0.30
 * (exact Hertz); a Level-2 ball-speed update 0.0103 per Gauss point of the
 * n x n contact grid; a dynamic-level window 3.9 per grid point (from the
 * wall-time ratio to the quasi-dynamic run, too slow for callgrind); a
 * loss quadrature 0.0009 per grid point; a network update + solve with the
 * rest of its step 0.108 (46 nodes) or 0.019 (7 nodes). */
#define MI_MECH 0.20
#define MI_MECH_EXACT 0.30
#define MI_QD_PER_POINT 0.0103
#define MI_DYN_PER_POINT 3.9
#define MI_LOSS_PER_POINT 0.0009
#define MI_NET46 0.108
#define MI_NET7 0.019

double acbb_accuracy_work_units(const acbb_scene *sc, const acbb_work *w)
{
    double g2 = (double)sc->contact_grid * (double)sc->contact_grid;
    double mech = sc->hertz == ACBB_HERTZ_EXACT ? MI_MECH_EXACT : MI_MECH;
    double tr = sc->model == ACBB_MODEL_DYNAMIC ? MI_DYN_PER_POINT : MI_QD_PER_POINT;
    double net = sc->network == ACBB_NET_7 ? MI_NET7 : MI_NET46;
    return mech * (double)w->mechanics_solves + tr * g2 * (double)w->traction_solves +
           MI_LOSS_PER_POINT * g2 * (double)w->loss_quadratures +
           net * (double)w->network_solves;
}

void acbb_accuracy_format_pct(double e, char *buf, size_t n)
{
    double p = 100.0 * e;
    if (!isfinite(p)) snprintf(buf, n, "-");
    else if (p == 0.0) snprintf(buf, n, "0");
    else if (p < 0.01) snprintf(buf, n, "%.0e", p);
    else if (p < 1000.0) snprintf(buf, n, "%.2f", p);
    else snprintf(buf, n, "%.0e", p);
}
