/* acbb — sweeps in N dimensions: running the points (sweep.h) on the batch
 * runner (batch.h).
 *
 * The points to run are listed up front (shard, skip list, max_points), so
 * the set is decided before any thread starts. A sweep reads each point at
 * its steady state, so points take the steady solve unless the caller asks
 * for the transient (o->transient) or the grid itself varies the thermal
 * mode (a fidelity preset or target sets it too). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/batch.h"
#include "acbb/tools/sweep.h"

typedef struct {
    const acbb_sweep *grid;
    const acbb_scene *base;
    const acbb_sweep_opts *o;
    const size_t *todo;
    acbb_batch_mode mode;
    size_t reported;
    acbb_sweep_result *r;       /* filled under the batch's lock for `done` */
} sweep_batch;

static acbb_status point_scene(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                               acbb_error *err)
{
    const sweep_batch *b = ctx;
    *mode = b->mode;
    return acbb_sweep_scene(b->grid, b->base, b->todo[i], out, err);
}

static void point_done(void *ctx, const acbb_batch_result *br)
{
    sweep_batch *b = ctx;
    /* A cancelled point is not a result: a resumed sweep runs it. */
    if (br->status == ACBB_CANCELLED) return;
    acbb_sweep_result *r = b->r;
    r->index = b->todo[br->index];
    r->status = br->status;
    r->have_snap = br->snap != NULL;
    r->wall_ms = br->wall_ms;
    r->message[0] = '\0';
    if (br->snap) r->snap = *br->snap;
    else snprintf(r->message, sizeof r->message, "%s", br->message);
    b->reported++;
    if (b->o->done) b->o->done(b->o->ctx, r);
}

static size_t list_todo(const acbb_sweep *g, const acbb_sweep_opts *o, size_t *todo)
{
    size_t n = 0, total = acbb_sweep_n_points(g);
    for (size_t i = 0; i < total; i++) {
        if (o->max_points && n == o->max_points) break;
        if (!acbb_sweep_in_shard(i, o->shard_k, o->shard_n) || (o->skip && o->skip[i])) continue;
        if (todo) todo[n] = i;
        n++;
    }
    return n;
}

size_t acbb_sweep_n_todo(const acbb_sweep *g, const acbb_sweep_opts *o)
{
    return list_todo(g, o, NULL);
}

/* The grid varies the thermal mode (directly or through a fidelity choice). */
static int grid_sets_mode(const acbb_sweep *g)
{
    for (size_t d = 0; d < acbb_sweep_n_dims(g); d++) {
        const char *k = acbb_sweep_key(g, d);
        if (strcmp(k, "fidelity.thermal_mode") == 0 || strcmp(k, "fidelity.preset") == 0 ||
            strcmp(k, "fidelity.target_error_pct") == 0)
            return 1;
    }
    return 0;
}

acbb_status acbb_sweep_run(const acbb_sweep *g, const acbb_scene *base,
                           const acbb_sweep_opts *o, size_t *n_run)
{
    size_t n_todo = list_todo(g, o, NULL);
    size_t *todo = malloc((n_todo ? n_todo : 1) * sizeof *todo);
    acbb_sweep_result *r = malloc(sizeof *r);
    if (n_run) *n_run = 0;
    if (!todo || !r) {
        free(todo);
        free(r);
        return ACBB_ENOMEM;
    }
    list_todo(g, o, todo);
    sweep_batch b = { .grid = g, .base = base, .o = o, .todo = todo, .r = r,
                      .mode = o->transient || grid_sets_mode(g) ? ACBB_BATCH_AS_SCENE
                                                                : ACBB_BATCH_STEADY };
    acbb_batch_opts bo = { .jobs = o->jobs, .cancel = o->cancel, .scene = point_scene,
                           .done = point_done, .ctx = &b, .skip_stiffness = o->skip_stiffness };
    acbb_status st = acbb_batch_run(n_todo, &bo, NULL);
    free(todo);
    free(r);
    if (n_run) *n_run = b.reported;
    if (st == ACBB_CANCELLED && b.reported < n_todo) return ACBB_CANCELLED;
    return b.reported < n_todo ? ACBB_ENOMEM : ACBB_OK;
}
