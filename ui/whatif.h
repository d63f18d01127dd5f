/* acbb TUI — what-if at scale in the background: a sweep of one scene key
 * (acbb_sweep_run) and the sensitivity analysis (acbb_sensitivity_run),
 * each a background job (job.h) on a copy of the open scene. No curses
 * here.
 *
 * The sweep publishes each point as the engine hands it over (in
 * completion order, not index order): the value of the key, and the value
 * of each asked-for metric (acbb_metric_value), so the screen can switch
 * metrics without running again. A point fails when the edit or set-up
 * fails or the run does not reach steady state (as `acbb sweep` counts
 * them); it is recorded, with its reason, and not plotted.
 *
 * The sensitivity job publishes "k of n runs" from the engine's progress
 * callback and, at the end, the whole result. */
#ifndef ACBB_UI_WHATIF_H
#define ACBB_UI_WHATIF_H

#include <stddef.h>
#include "acbb/scene.h"
#include "acbb/tools/sensitivity.h"
#include "acbb/status.h"
#include "acbb/tools/sweep.h"
#include "job.h"

#define ACBB_WHATIF_MAX_POINTS 200  /* a sweep from the TUI: one curve, on a chart */
#define ACBB_WHATIF_METRICS 8       /* metrics recorded per point */

/* ---- the sweep ---- */

typedef struct {
    int have;                    /* finished (failed or not) */
    int ok;                      /* converged */
    double x;                    /* the key's value, preset units */
    double y[ACBB_WHATIF_METRICS]; /* NAN when the metric is not defined */
    char why[128];               /* a failed point's reason */
} acbb_whatif_point;

typedef struct {
    acbb_job_info job;
    char key[ACBB_SWEEP_KEY];
    char spec[128];              /* "key=lo:hi:n" as started */
    size_t n_metrics;
    char metrics[ACBB_WHATIF_METRICS][ACBB_SENS_METRIC];
    size_t total, done, failed;
    acbb_whatif_point pts[ACBB_WHATIF_MAX_POINTS]; /* by point index */
} acbb_sweep_view;

typedef struct acbb_sweepjob acbb_sweepjob;

acbb_status acbb_sweepjob_new(acbb_sweepjob **out, acbb_error *err);
void acbb_sweepjob_free(acbb_sweepjob *s);
/* Sweep `spec` ("section.key=lo:hi:n" or "section.key=v1,v2,...", one
 * dimension, at most ACBB_WHATIF_MAX_POINTS values) on a copy of `scene`,
 * recording metrics[0..n_metrics) per point, on `jobs` threads (<= 0: one
 * per CPU). Errors (nothing started): a bad spec or metric, too many
 * points, one already running. */
acbb_status acbb_sweepjob_start(acbb_sweepjob *s, const acbb_scene *scene, const char *spec,
                                const char *const *metrics, size_t n_metrics, int jobs,
                                acbb_error *err);
void acbb_sweepjob_read(acbb_sweepjob *s, acbb_sweep_view *v);
/* Its job: cancel, wait, the wake-up fd (job.h). */
acbb_job *acbb_sweepjob_job(acbb_sweepjob *s);

/* ---- the sensitivity analysis ---- */

typedef struct {
    acbb_job_info job;
    size_t done, total;          /* runs */
    int have_result;             /* DONE: res is the engine's result */
    acbb_sens_result res;
} acbb_sens_view;

typedef struct acbb_sensjob acbb_sensjob;

acbb_status acbb_sensjob_new(acbb_sensjob **out, acbb_error *err);
void acbb_sensjob_free(acbb_sensjob *s);
/* acbb_sensitivity_run(scene, opt) in the background (opt's cancel,
 * progress and ctx are the job's). Errors: a bad metric, one running. */
acbb_status acbb_sensjob_start(acbb_sensjob *s, const acbb_scene *scene, const acbb_sens_opts *opt,
                               acbb_error *err);
void acbb_sensjob_read(acbb_sensjob *s, acbb_sens_view *v);
/* Its job: cancel, wait, the wake-up fd (job.h). */
acbb_job *acbb_sensjob_job(acbb_sensjob *s);

#endif
