/* acbb TUI — the sweep and the sensitivity analysis as background jobs
 * (see whatif.h). Each struct keeps what its job's thread works on
 * (`scene`, the grid or the options, the engine's result: written before
 * the start, read by the thread) and the published view behind the job's
 * lock. The engine calls the hand-offs below with its own lock held, one
 * at a time; they take the job's lock only to copy a few numbers. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "whatif.h"

/* ---- the sweep ---- */

struct acbb_sweepjob {
    acbb_job *job;
    acbb_sweep_view v;         /* published (job lock); v.job is filled on read */
    /* the job's thread, while it runs */
    acbb_scene scene;
    acbb_sweep *grid;
    int jobs;
    acbb_sweep_view next;      /* key, spec, metrics, total of the next start */
};

/* One finished point (engine's lock held): its metrics, then publish. */
static void sweep_done(void *ctx, const acbb_sweep_result *r)
{
    acbb_sweepjob *s = ctx;
    if (r->index >= ACBB_WHATIF_MAX_POINTS) return;
    acbb_whatif_point p = { .have = 1 };
    p.ok = r->have_snap && r->snap.state == ACBB_RUN_CONVERGED;
    p.x = strtod(acbb_sweep_value(s->grid, r->index, 0), NULL);
    for (size_t m = 0; m < s->next.n_metrics; m++)
        if (!p.ok || acbb_metric_value(&r->snap, s->next.metrics[m], &p.y[m], NULL) != ACBB_OK)
            p.y[m] = NAN;
    if (!p.ok)
        snprintf(p.why, sizeof p.why, "%.127s", r->have_snap ? r->snap.message : r->message);
    acbb_job_lock(s->job);
    s->v.pts[r->index] = p;
    s->v.done++;
    s->v.failed += !p.ok;
    acbb_job_unlock(s->job);
}

static acbb_status sweep_run(void *ctx, const atomic_int *cancel, acbb_error *err)
{
    acbb_sweepjob *s = ctx;
    acbb_sweep_opts o = { .jobs = s->jobs, .cancel = cancel, .done = sweep_done, .ctx = s };
    acbb_status rc = acbb_sweep_run(s->grid, &s->scene, &o, NULL);
    if (rc == ACBB_CANCELLED) return acbb_error_set(err, rc, "sweep cancelled");
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "sweep: %s", acbb_status_name(rc));
    return ACBB_OK;
}

static void sweep_begin(void *ctx)
{
    acbb_sweepjob *s = ctx;
    s->v = s->next;
}

acbb_status acbb_sweepjob_new(acbb_sweepjob **out, acbb_error *err)
{
    *out = NULL;
    acbb_sweepjob *s = calloc(1, sizeof *s);
    if (!s) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_status rc = acbb_job_new(&s->job, "sweep", err);
    if (rc != ACBB_OK) {
        free(s);
        return rc;
    }
    *out = s;
    return ACBB_OK;
}

void acbb_sweepjob_free(acbb_sweepjob *s)
{
    if (!s) return;
    acbb_job_free(s->job); /* joins: the grid is ours again */
    acbb_sweep_free(s->grid);
    free(s);
}

/* The grid of `spec` into s->grid and s->next (nothing running). */
static acbb_status sweep_plan(acbb_sweepjob *s, const char *spec, const char *const *metrics,
                              size_t n_metrics, acbb_error *err)
{
    if (n_metrics == 0 || n_metrics > ACBB_WHATIF_METRICS)
        return acbb_error_set(err, ACBB_EINVAL, "1..%d metrics per sweep", ACBB_WHATIF_METRICS);
    for (size_t m = 0; m < n_metrics; m++)
        if (acbb_metric_check(metrics[m], err) != ACBB_OK) return ACBB_EINVAL;
    acbb_sweep_free(s->grid);
    s->grid = NULL;
    acbb_status rc = acbb_sweep_new(&s->grid);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "out of memory");
    if ((rc = acbb_sweep_add(s->grid, spec, err)) != ACBB_OK) return rc;
    size_t n = acbb_sweep_n_points(s->grid);
    if (n > ACBB_WHATIF_MAX_POINTS)
        return acbb_error_set(err, ACBB_EINVAL, "%zu points: the TUI sweeps 1..%d (acbb sweep does more)",
                              n, ACBB_WHATIF_MAX_POINTS);
    memset(&s->next, 0, sizeof s->next);
    snprintf(s->next.key, sizeof s->next.key, "%s", acbb_sweep_key(s->grid, 0));
    snprintf(s->next.spec, sizeof s->next.spec, "%s", spec);
    s->next.n_metrics = n_metrics;
    for (size_t m = 0; m < n_metrics; m++)
        snprintf(s->next.metrics[m], sizeof s->next.metrics[m], "%s", metrics[m]);
    s->next.total = n;
    return ACBB_OK;
}

acbb_status acbb_sweepjob_start(acbb_sweepjob *s, const acbb_scene *scene, const char *spec,
                                const char *const *metrics, size_t n_metrics, int jobs,
                                acbb_error *err)
{
    if (!acbb_job_claim(s->job, err)) return ACBB_EINVAL;
    acbb_status rc = sweep_plan(s, spec, metrics, n_metrics, err);
    if (rc != ACBB_OK) return rc;
    s->scene = *scene;
    s->jobs = jobs;
    static const acbb_job_fns fns = { .run = sweep_run, .begin = sweep_begin };
    return acbb_job_start(s->job, &fns, s, err);
}

void acbb_sweepjob_read(acbb_sweepjob *s, acbb_sweep_view *v)
{
    acbb_job_info info;
    acbb_job_read(s->job, &info, v, &s->v, sizeof *v);
    v->job = info;
}

acbb_job *acbb_sweepjob_job(acbb_sweepjob *s)
{
    return s->job;
}

/* ---- the sensitivity analysis ---- */

struct acbb_sensjob {
    acbb_job *job;
    acbb_sens_view v;          /* published (job lock); v.job is filled on read */
    /* the job's thread, while it runs */
    acbb_scene scene;
    acbb_sens_opts opt;
    acbb_sens_result res;
};

/* The engine's progress (its lock held): publish the count. */
static void sens_progress(void *ctx, size_t done, size_t total)
{
    acbb_sensjob *s = ctx;
    acbb_job_lock(s->job);
    s->v.done = done;
    s->v.total = total;
    acbb_job_unlock(s->job);
}

static acbb_status sens_run(void *ctx, const atomic_int *cancel, acbb_error *err)
{
    acbb_sensjob *s = ctx;
    s->opt.cancel = cancel;
    s->opt.progress = sens_progress;
    s->opt.ctx = s;
    return acbb_sensitivity_run(&s->scene, &s->opt, &s->res, err);
}

static void sens_begin(void *ctx)
{
    acbb_sensjob *s = ctx;
    s->v.done = s->v.total = 0;
    s->v.have_result = 0;
}

static void sens_end(void *ctx, acbb_status rc)
{
    acbb_sensjob *s = ctx;
    if (rc != ACBB_OK) return;
    s->v.res = s->res;
    s->v.have_result = 1;
}

acbb_status acbb_sensjob_new(acbb_sensjob **out, acbb_error *err)
{
    *out = NULL;
    acbb_sensjob *s = calloc(1, sizeof *s);
    if (!s) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_status rc = acbb_job_new(&s->job, "sensitivity run", err);
    if (rc != ACBB_OK) {
        free(s);
        return rc;
    }
    *out = s;
    return ACBB_OK;
}

void acbb_sensjob_free(acbb_sensjob *s)
{
    if (!s) return;
    acbb_job_free(s->job);
    free(s);
}

acbb_status acbb_sensjob_start(acbb_sensjob *s, const acbb_scene *scene, const acbb_sens_opts *opt,
                               acbb_error *err)
{
    if (!acbb_job_claim(s->job, err)) return ACBB_EINVAL;
    if (acbb_metric_check(opt->metric, err) != ACBB_OK) return ACBB_EINVAL;
    s->scene = *scene;
    s->opt = *opt;
    static const acbb_job_fns fns = { .run = sens_run, .begin = sens_begin, .end = sens_end };
    return acbb_job_start(s->job, &fns, s, err);
}

void acbb_sensjob_read(acbb_sensjob *s, acbb_sens_view *v)
{
    acbb_job_info info;
    acbb_job_read(s->job, &info, v, &s->v, sizeof *v);
    v->job = info;
}

acbb_job *acbb_sensjob_job(acbb_sensjob *s)
{
    return s->job;
}
