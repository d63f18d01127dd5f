/* acbb — sensitivity: a list of scenes run on the batch runner (batch.h)
 * and the metric of each (sensitivity.h). A metric is read at the steady
 * state, so each run is the steady solve unless o->transient; the value
 * of a task does not depend on the thread count. */
#include <math.h>
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#include "acbb/batch.h"
#include "acbb/tools/sensitivity.h"
#include "cancel.h"

typedef struct {
    const acbb_scene *scenes;
    const acbb_sens_opts *o;
    size_t n_tasks, per_scene;   /* per_scene 2 with delta_te: TE then WTE */
    double *val;                 /* per task, NAN on failure */
    size_t done;
    char *first_fail;
    size_t fail_n;
} sens_batch;

/* Task t: its scene, TE or WTE. */
static acbb_status task_scene(void *ctx, size_t t, acbb_scene *out, acbb_batch_mode *mode,
                              acbb_error *err)
{
    const sens_batch *b = ctx;
    (void)err;
    *out = b->scenes[t / b->per_scene];
    if (b->per_scene == 2) out->thermal_expansion = (t % 2) == 0;
    *mode = b->o->transient ? ACBB_BATCH_AS_SCENE : ACBB_BATCH_STEADY;
    return ACBB_OK;
}

/* Under the batch's lock: the task's metric, or why it has none. */
static void task_done(void *ctx, const acbb_batch_result *r)
{
    sens_batch *b = ctx;
    if (r->status == ACBB_CANCELLED) return; /* not a result */
    acbb_error err = { { 0 } };
    acbb_status st = r->status;
    double v = NAN;
    /* A failed run says its status first, as every named ending does
     * ("wall_limit: wall-clock bound ..."). */
    if (st == ACBB_OK) st = acbb_metric_value(r->snap, b->o->metric, &v, &err);
    else if (r->message[0]) acbb_error_set(&err, st, "%s: %s", acbb_status_name(st), r->message);
    b->val[r->index] = st == ACBB_OK && isfinite(v) ? v : NAN;
    if (st != ACBB_OK && b->first_fail && !b->first_fail[0])
        snprintf(b->first_fail, b->fail_n, "%s", err.msg[0] ? err.msg : acbb_status_name(st));
    b->done++;
    if (b->o->progress) b->o->progress(b->o->ctx, b->done, b->n_tasks);
}

acbb_status acbb_sens_eval(const acbb_scene *scenes, size_t n, const acbb_sens_opts *o,
                           double *y, char *first_fail, size_t fail_n, size_t *runs)
{
    size_t per = o->delta_te ? 2 : 1;
    sens_batch b = { .scenes = scenes, .o = o, .n_tasks = n * per, .per_scene = per,
                     .first_fail = first_fail, .fail_n = fail_n };
    b.val = malloc((b.n_tasks ? b.n_tasks : 1) * sizeof *b.val);
    if (!b.val) return ACBB_ENOMEM;
    for (size_t t = 0; t < b.n_tasks; t++) b.val[t] = NAN;
    if (first_fail && fail_n) first_fail[0] = '\0';
    /* Every stiffness metric's name says so (acbb metrics): the others
     * skip the stiffness probes (issue 30 lever 2). */
    acbb_batch_opts bo = { .jobs = o->jobs, .cancel = o->cancel, .scene = task_scene,
                           .done = task_done, .ctx = &b,
                           .skip_stiffness = !strstr(o->metric, "stiffness") };
    acbb_batch_run(b.n_tasks, &bo, NULL);
    for (size_t i = 0; i < n; i++) {
        double te = b.val[per * i], wte = per == 2 ? b.val[2 * i + 1] : 0.0;
        y[i] = per == 1 ? te : o->delta_rel ? (te - wte) / fabs(wte) : te - wte;
    }
    if (runs) *runs += b.done;
    free(b.val);
    if (acbb_cancelled(o->cancel)) return ACBB_CANCELLED;
    return b.done < b.n_tasks ? ACBB_ENOMEM : ACBB_OK;
}
