/* acbb — the seed study: planning and running its runs (see study.h).
 *
 * Every point is one Sim driven by acbb_sim_drive to steady state, exactly
 * as `acbb run PRESET --set ...` drives it (adding fidelity.thermal_mode =
 * steady where only the steady state is read, see point_scene); the run
 * hook copies step 0 and the last step and, for the TE load sweep, the
 * per-step trajectory the transient items (4, 5) read. Points run on the batch runner (batch.h):
 * results do not depend on the number of threads. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/batch.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/study.h"
#include "acbb/units.h"
#include "acbb/tools/scene_schema.h"
#include "study_priv.h"
#include "sim_priv.h"
#include "cancel.h"

#define BASE_RPM 15000.0

const double acbb_study_loads[ACBB_STUDY_NPTS] = { 50, 100, 150, 200, 400, 600, 800, 1000 };
const double acbb_study_speeds[ACBB_STUDY_NPTS] = { 2000, 4000, 6000, 8000,
                                                    10000, 12000, 14000, 16000 };


/* ---- one run ---- */

typedef struct {
    acbb_study_point *const *pts;
    size_t n, ran;
    int checks_only;             /* acbb_study_run_list's */
    acbb_study_progress_fn progress; /* may be NULL; called under the batch's lock */
    void *ctx;
} study_batch;

static void record(acbb_study_point *p, const acbb_snapshot *s)
{
    p->min_loss = fmin(p->min_loss, acbb_study_min_loss(s));
    if (!p->record) return;
    if (p->n_traj == p->cap_traj) {
        size_t cap = p->cap_traj ? 2 * p->cap_traj : 256;
        acbb_study_step *t = realloc(p->traj, cap * sizeof *t);
        if (!t) {
            p->oom = 1;
            return;
        }
        p->traj = t;
        p->cap_traj = cap;
    }
    p->traj[p->n_traj++] = (acbb_study_step){ s->time, s->exp_inner + s->exp_inner_cen,
                                              s->exp_outer, s->exp_ball, s->balls[0].Qi,
                                              s->balls[0].Qo, s->delta_x };
}

static int record_hook(void *ctx, const acbb_sim *sim)
{
    acbb_study_point *p = ctx;
    /* Every step's losses and loads; the rating life is read at the end
     * (the batch's final snapshot replaces p->last), so a step skips it. */
    acbb_simx_snapshot_step(sim, &p->last);
    if (p->last.iteration == 0) p->first = p->last;
    record(p, &p->last);
    return 0;
}

/* A point only the check table reads (a perturbed study's): no item reads
 * its step 0 (`first`), so from step 0 on only what record() reads is
 * made (issue 30: the whole step 0 and its copy, 0.1 G of `report
 * --sensitivity`). */
static void record_values(acbb_study_point *p, const acbb_sim *sim)
{
    acbb_simx_snapshot_values(sim, &p->last);
    record(p, &p->last);
}

/* Only the recorded points (the TE load sweep: items 4, 5 read its
 * trajectory) are looked at step by step; every other point is read at its
 * steady state (item 6's step 0 is the same initial state either way; item
 * 18d's "any step" covers the steps each run took), so it takes the steady
 * solve (batch.h: the same answer to ~5e-9, BENCHMARKS.md "Batch runner"). */
static acbb_status point_scene(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                               acbb_error *err)
{
    const acbb_study_point *p = ((const study_batch *)ctx)->pts[i];
    if (p->skip) return acbb_error_set(err, p->status, "%s", p->message);
    *out = p->scene;
    *mode = p->record ? ACBB_BATCH_AS_SCENE : ACBB_BATCH_STEADY;
    return ACBB_OK;
}

static const acbb_warm *point_warm(void *ctx, size_t i)
{
    return ((const study_batch *)ctx)->pts[i]->warm_from;
}

/* On the worker, point i's alone: a base point keeps its state (a
 * perturbed study's is given none: acbb_study_run_list checks_only). */
static void point_keep(void *ctx, size_t i, acbb_warm *w)
{
    acbb_study_point *p = ((study_batch *)ctx)->pts[i];
    if (p->warm) {
        acbb_warm_free(w);
        return;
    }
    p->warm = w;
}

static void point_step(void *ctx, size_t i, const acbb_sim *sim)
{
    const study_batch *b = ctx;
    if (b->checks_only) record_values(b->pts[i], sim);
    else record_hook(b->pts[i], sim);
}

/* The run's final snapshot is made in the point's record (batch.h). */
static acbb_snapshot *point_snap(void *ctx, size_t i)
{
    return &((study_batch *)ctx)->pts[i]->last;
}

static void point_done(void *ctx, const acbb_batch_result *r)
{
    study_batch *b = ctx;
    acbb_study_point *p = b->pts[r->index];
    if (p->skip) return;
    p->wall_ms = r->wall_ms;
    if (!r->ran || !r->snap) {
        p->status = r->status;
        snprintf(p->message, sizeof p->message, "%s", r->message);
        if (!r->ran) return; /* a cancel came first: not counted as run */
    } else {
        if (r->snap != &p->last) p->last = *r->snap;
        p->ok = p->last.state == ACBB_RUN_CONVERGED && !p->oom;
        if (p->oom) {
            p->status = ACBB_ENOMEM;
            snprintf(p->message, sizeof p->message, "out of memory recording the transient");
        } else if (!p->ok) {
            p->status = r->status != ACBB_OK ? r->status : p->last.status;
            snprintf(p->message, sizeof p->message, "%s", p->last.message);
        }
    }
    if (b->progress) b->progress(b->ctx, ++b->ran, b->n);
}

/* One batch over any list of points (the study's own, or every perturbed
 * study's at once: study_robust.c). */
void acbb_study_run_list(acbb_study_point *const *pts, size_t n, int jobs, int checks_only,
                         const atomic_int *cancel, acbb_study_progress_fn progress, void *ctx)
{
    study_batch b = { .pts = pts, .n = n, .checks_only = checks_only, .progress = progress,
                      .ctx = ctx };
    /* No study item reads a stiffness (issue 30 lever 2: skip the probes),
     * nor a set's preload or lift-off (the DB pair's study). */
    acbb_batch_opts o = { .jobs = jobs, .cancel = cancel, .scene = point_scene,
                          .step = point_step, .done = point_done, .ctx = &b,
                          .skip_stiffness = 1, .skip_life = checks_only, .skip_liftoff = 1,
                          .warm = point_warm, .keep = checks_only ? NULL : point_keep,
                          .snap_to = point_snap };
    acbb_batch_run(n, &o, NULL);
}

static void run_all(acbb_study_point *pts, size_t n, int jobs, const atomic_int *cancel)
{
    acbb_study_point **list = malloc((n ? n : 1) * sizeof *list);
    if (!list) {
        for (size_t i = 0; i < n; i++) {
            pts[i].status = ACBB_ENOMEM;
            snprintf(pts[i].message, sizeof pts[i].message, "out of memory");
        }
        return;
    }
    for (size_t i = 0; i < n; i++) list[i] = &pts[i];
    acbb_study_run_list(list, n, jobs, 0, cancel, NULL, NULL);
    free(list);
}

/* ---- planning ---- */

/* Edits go through the text `--set` would use and the cross-field rules
 * run once on the edited scene, as `acbb run PRESET --set ...` applies them
 * (acbb_scene_apply_edits), so a study point is bit-identical to that run.
 * Validating after each edit instead cost 3 % of a perturbed study of
 * `report --sensitivity` (issue 30). */
static acbb_status set_point(acbb_scene *s, double rpm, double load, int te, int l2,
                             acbb_error *err)
{
    char v[2][32];
    snprintf(v[0], sizeof v[0], "%g", rpm);
    snprintf(v[1], sizeof v[1], "%g", load);
    acbb_status st = acbb_scene_set_value(s, "operating.inner_speed_rpm", v[0], err);
    if (st == ACBB_OK) st = acbb_scene_set_value(s, "operating.axial_load_N", v[1], err);
    /* Rigid preload (MODEL.md 14): the sweep's thrust is the assembly preload
     * that sets the held axial offset (the axial load itself does not act). */
    if (st == ACBB_OK && s->preload == ACBB_PRELOAD_DISPLACEMENT && load > 0.0)
        st = acbb_scene_set_value(s, "mounting.preload_N", v[1], err);
    if (st == ACBB_OK)
        st = acbb_scene_set_value(s, "effects.thermal_expansion", te ? "on" : "off", err);
    if (st == ACBB_OK && l2) st = acbb_scene_set_value(s, "fidelity.model", "quasi-dynamic", err);
    /* on failure the point is skipped: its half-edited scene never runs */
    return st == ACBB_OK ? acbb_scene_validate(s, err) : st;
}

static void init_point(acbb_study_point *p, const acbb_scene *base, double rpm, double load,
                       int te, int l2, int rec)
{
    acbb_error err = { { 0 } };
    p->scene = *base;
    p->record = rec;
    p->min_loss = INFINITY;
    acbb_status st = set_point(&p->scene, rpm, load, te, l2, &err);
    snprintf(p->label, sizeof p->label, "%g rpm, %g N, %s, %s", rpm, load, te ? "TE" : "WTE",
             acbb_model_level_name(p->scene.model));
    if (st != ACBB_OK) {
        p->status = st;
        p->skip = 1;
        snprintf(p->message, sizeof p->message, "%s", err.msg);
    }
}

/* The one grid of the study and of the comparison table: point k of
 * sweep b, the load sweep at `load_rpm` (MODEL.md 12 "Conditions"). */
static void grid_at(int b, int k, double load_rpm, double *rpm, double *load)
{
    *rpm = b == ACBB_STUDY_LOAD ? load_rpm : acbb_study_speeds[k];
    *load = b == ACBB_STUDY_LOAD ? acbb_study_loads[k] : b == ACBB_STUDY_S100 ? 100.0 : 1000.0;
}

static size_t fill_level(acbb_study_point *pts, acbb_study_point *blk[ACBB_STUDY_NSWEEPS],
                         const acbb_scene *base, int l2)
{
    size_t i = 0;
    for (int b = 0; b < ACBB_STUDY_NSWEEPS; b++) {
        blk[b] = &pts[i];
        for (int k = 0; k < ACBB_STUDY_NPTS; k++)
            for (int m = 0; m < 2; m++) {
                double rpm, load;
                grid_at(b, k, BASE_RPM, &rpm, &load);
                init_point(&pts[i++], base, rpm, load, m == ACBB_STUDY_TE, l2,
                           !l2 && b == ACBB_STUDY_LOAD && m == ACBB_STUDY_TE);
            }
    }
    return i;
}

acbb_status acbb_study_plan_runs(acbb_study_runs *r, const acbb_scene *base)
{
    int l2_own = base->model != ACBB_MODEL_QUASI_DYNAMIC;
    size_t per_level = ACBB_STUDY_NSWEEPS * 2 * ACBB_STUDY_NPTS;
    r->model = base->model;
    r->n = (l2_own ? 2 : 1) * per_level + 1 + ACBB_STUDY_NLIGHT;
    r->all = calloc(r->n, sizeof *r->all);
    if (!r->all) return ACBB_ENOMEM;
    size_t i = 0;
    /* The slow quasi-dynamic points first, so the pool ends evenly. */
    if (l2_own) i += fill_level(r->all, r->sweep[ACBB_STUDY_L2], base, 1);
    i += fill_level(r->all + i, r->sweep[ACBB_STUDY_BASE], base, 0);
    if (!l2_own)
        for (int b = 0; b < ACBB_STUDY_NSWEEPS; b++)
            r->sweep[ACBB_STUDY_L2][b] = r->sweep[ACBB_STUDY_BASE][b];
    r->zero = &r->all[i++];
    init_point(r->zero, base, 0.0, base->axial_load, 1, 0, 0);
    r->statics = &r->all[i];
    for (int k = 0; k < ACBB_STUDY_NLIGHT; k++)
        init_point(&r->statics[k], base, 0.0, acbb_study_loads[k], 0, 0, 0);
    return ACBB_OK;
}

acbb_status acbb_study_plan(const acbb_scene *base, acbb_study **out, acbb_error *err)
{
    size_t n_rows;
    acbb_study_table(&n_rows);
    acbb_study *s = calloc(1, sizeof *s);
    if (s) s->items = calloc(n_rows, sizeof *s->items);
    if (!s || !s->items || acbb_study_plan_runs(&s->runs, base) != ACBB_OK) {
        acbb_study_free(s);
        if (err) snprintf(err->msg, sizeof err->msg, "study: out of memory");
        *out = NULL;
        return ACBB_ENOMEM;
    }
    s->base = *base;
    s->n_items = n_rows;
    acbb_study_evaluate(s);
    *out = s;
    return ACBB_OK;
}

/* MODEL.md 14: under rigid preload a cold step start can run away where the
 * steady solve finds a benign state (two branches). A recorded point whose
 * transient ran away keeps that finding (runaway_t, its message) and takes
 * its steady values from the steady solve; the transient items (4, 5) name
 * it instead of reading it. Nothing runs away under a constant force. */
static void steady_branch(acbb_study_runs *r, int jobs, const atomic_int *cancel)
{
    acbb_study_point *list[ACBB_STUDY_NPTS];
    double t[ACBB_STUDY_NPTS];
    size_t n = 0;
    for (size_t i = 0; i < r->n && n < ACBB_STUDY_NPTS; i++) {
        acbb_study_point *p = &r->all[i];
        if (!p->record || p->ok || p->status != ACBB_RUNAWAY) continue;
        t[n] = p->last.time;
        p->record = 0;   /* the steady solve (point_scene) */
        list[n++] = p;
    }
    acbb_study_run_list(list, n, jobs, 0, cancel, NULL, NULL);
    for (size_t k = 0; k < n; k++) {
        list[k]->runaway_t = t[k];
        list[k]->record = 1;
    }
}

acbb_status acbb_study_run(acbb_study *s, int jobs, const atomic_int *cancel)
{
    double t0 = acbb_now_ms();
    run_all(s->runs.all, s->runs.n, jobs, cancel);
    if (!acbb_cancelled(cancel)) steady_branch(&s->runs, jobs, cancel);
    s->runs.wall_ms = acbb_now_ms() - t0;
    acbb_study_evaluate(s);
    if (acbb_cancelled(cancel)) return ACBB_CANCELLED;
    for (size_t i = 0; i < s->runs.n; i++)
        if (!s->runs.all[i].ok) return s->runs.all[i].status != ACBB_OK ? s->runs.all[i].status
                                                                         : ACBB_NOT_CONVERGED;
    return ACBB_OK;
}

/* ---- the TE/WTE comparison table ---- */

/* The scene is a plain value in SI units: the table edits it directly
 * (the speed through rpm, as the table shows it). */
void acbb_study_compare_plan(const acbb_scene *base, acbb_study_compare *out)
{
    static const char *const names[ACBB_STUDY_NSWEEPS] = { "load", "speed_100N",
                                                           "speed_1000N" };
    double base_rpm = acbb_rads_to_rpm(base->inner_speed);
    size_t i = 0;
    for (int b = 0; b < ACBB_STUDY_NSWEEPS; b++) {
        acbb_study_compare_block *blk = &out->blocks[b];
        blk->sweep = b;
        blk->name = names[b];
        blk->first = (size_t)b * ACBB_STUDY_NPTS;
        blk->count = ACBB_STUDY_NPTS;
        if (b == ACBB_STUDY_LOAD)
            snprintf(blk->title, sizeof blk->title, "load sweep at %.0f rpm", base_rpm);
        else
            snprintf(blk->title, sizeof blk->title, "speed sweep at %.0f N",
                     b == ACBB_STUDY_S100 ? 100.0 : 1000.0);
        for (int k = 0; k < ACBB_STUDY_NPTS; k++)
            for (int m = ACBB_STUDY_TE; m <= ACBB_STUDY_WTE; m++) {
                acbb_study_compare_point *p = &out->pts[i++];
                double rpm, load;
                grid_at(b, k, base_rpm, &rpm, &load);
                p->scene = *base;
                p->scene.inner_speed = acbb_rpm_to_rads(rpm);
                p->scene.axial_load = load;
                p->scene.thermal_expansion = m == ACBB_STUDY_TE;
                p->sweep = b;
                p->k = k;
                p->mode = m;
                p->x = b == ACBB_STUDY_LOAD ? load : rpm;
            }
    }
}

typedef struct {
    const acbb_study_compare *c;
    acbb_batch_done_fn done;
    void *ctx;
} compare_run;

/* Each point runs as its scene says: the table publishes the iterations
 * of the transient to steady state (study.h). */
static acbb_status compare_scene(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                                 acbb_error *err)
{
    (void)err;
    *out = ((const compare_run *)ctx)->c->pts[i].scene;
    *mode = ACBB_BATCH_AS_SCENE;
    return ACBB_OK;
}

static void compare_done(void *ctx, const acbb_batch_result *res)
{
    const compare_run *r = ctx;
    r->done(r->ctx, res);
}

acbb_status acbb_study_compare_run(const acbb_study_compare *c, int jobs,
                                   const atomic_int *cancel, acbb_batch_done_fn done,
                                   void *ctx, acbb_batch_stats *stats)
{
    compare_run r = { c, done, ctx };
    acbb_batch_opts o = { .jobs = jobs, .cancel = cancel, .scene = compare_scene,
                          .done = done ? compare_done : NULL, .ctx = &r };
    return acbb_batch_run(ACBB_STUDY_COMPARE_N, &o, stats);
}

/* ---- results ---- */

void acbb_study_evaluate(acbb_study *s)
{
    size_t n;
    const acbb_study_row *rows = acbb_study_table(&n);
    for (size_t i = 0; i < n && i < s->n_items; i++)
        acbb_study_eval_row(&rows[i], &s->runs, &s->items[i]);
}

acbb_study_runs *acbb_study_results(acbb_study *s) { return &s->runs; }

size_t acbb_study_n_failed(const acbb_study *s)
{
    size_t n = 0;
    for (size_t i = 0; i < s->runs.n; i++) n += !s->runs.all[i].ok;
    return n;
}

size_t acbb_study_n_items(const acbb_study *s) { return s->n_items; }

const acbb_study_item *acbb_study_item_at(const acbb_study *s, size_t i)
{
    return i < s->n_items ? &s->items[i] : NULL;
}

const acbb_study_check *acbb_study_find_check(const acbb_study *s, const char *id)
{
    for (size_t i = 0; i < s->n_items; i++)
        for (int k = 0; k < s->items[i].n_checks; k++)
            if (strcmp(s->items[i].checks[k].id, id) == 0) return &s->items[i].checks[k];
    return NULL;
}

void acbb_study_counts(const acbb_study *s, int counts[3])
{
    counts[0] = counts[1] = counts[2] = 0;
    for (size_t i = 0; i < s->n_items; i++) counts[s->items[i].verdict]++;
}

const acbb_scene *acbb_study_scene(const acbb_study *s) { return &s->base; }

void acbb_study_free_runs(acbb_study_runs *r)
{
    for (size_t i = 0; r->all && i < r->n; i++) {
        free(r->all[i].traj);
        acbb_warm_free(r->all[i].warm);
    }
    free(r->all);
    r->all = NULL;
    r->n = 0;
}

void acbb_study_free(acbb_study *s)
{
    if (!s) return;
    acbb_study_free_runs(&s->runs);
    free(s->items);
    free(s);
}
