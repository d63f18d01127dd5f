/* acbb — the preload window (preload_map.h, issue 19 item 4). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/batch.h"
#include "acbb/tools/preload_map.h"
#include "acbb/sim.h"
#include "acbb/units.h"

typedef struct {
    const acbb_scene *base;
    const acbb_pmap_opts *o;
    acbb_pmap_cell *cells;
    unsigned char *set_done;   /* per cell: a set's worst bearing already judged (set_final) */
} pmap_ctx;

double acbb_pmap_axis(double lo, double hi, int n, int k)
{
    return n > 1 ? lo + (hi - lo) * k / (n - 1) : lo;
}

static acbb_status cell_scene(void *vctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                              acbb_error *err)
{
    (void)err;
    const pmap_ctx *c = vctx;
    *out = *c->base;
    out->preload = c->o->spring ? ACBB_PRELOAD_FORCE : ACBB_PRELOAD_DISPLACEMENT;
    out->preload_force = c->cells[i].preload_N;
    if (c->o->spring) out->axial_load = c->cells[i].preload_N;
    out->inner_speed = c->cells[i].speed_rpm * ACBB_RPM;
    *mode = ACBB_BATCH_TRANSIENT; /* only the transient catches a runaway (batch.h) */
    return ACBB_OK;
}

/* The skid ratio of preload_map.h: gyroscopic moment over the friction
 * moment the driving inner contact can hold, worst ball. */
static double skid_ratio(const acbb_scene *s, const acbb_snapshot *sn)
{
    double D = s->ball_diameter, m = s->ball.rho * ACBB_PI * D * D * D / 6.0;
    double J = 0.1 * m * D * D, worst = 0.0;
    for (int j = 0; j < sn->n_balls; j++) {
        const acbb_ball_view *b = &sn->balls[j];
        double Mg = J * fabs(b->omega_m) * hypot(b->omega_y, b->omega_z);
        double hold = s->lambda_lim * b->Qi * 0.5 * D;
        worst = fmax(worst, hold > 0.0 ? Mg / hold : (Mg > 0.0 ? 1e6 : 0.0));
    }
    return fmin(worst, 1e6);
}

static unsigned judge(const acbb_pmap_opts *o, const acbb_pmap_cell *c)
{
    unsigned f = 0;
    if (c->status == ACBB_RUNAWAY) f |= ACBB_PMAP_RUNAWAY;
    else if (c->status != ACBB_OK) f |= ACBB_PMAP_FAILED;
    if (!c->have) return f | ACBB_PMAP_FAILED;
    if (c->skid > 1.0) f |= ACBB_PMAP_SKID;
    if (o->max_rise_K > 0.0 && c->rise_K > o->max_rise_K) f |= ACBB_PMAP_HOT;
    if (o->min_life_h > 0.0 && c->Lnmr_h < o->min_life_h) f |= ACBB_PMAP_SHORT_LIFE;
    if (o->min_s0 > 0.0 && c->s0_min < o->min_s0) f |= ACBB_PMAP_LOW_S0;
    return f;
}

/* One state's limit values into cell (the snapshot of one bearing). */
static void cell_values(const acbb_scene *base, const acbb_snapshot *s, acbb_pmap_cell *cell)
{
    cell->have = 1;
    cell->skid = skid_ratio(base, s);
    cell->rise_K = fmax(fmax(s->T_outer_ring, s->T_inner_ring), s->T_ball) - base->ambient_C;
    cell->Lnmr_h = s->life.Lnmr_h;
    cell->s0_min = s->life.s0_min;
}

/* A bearing set (MODEL.md 14) is judged by its worst bearing: the
 * batch's snapshot is bearing 0's, so at the run's last state every
 * bearing's own snapshot is read here (batch.h step hook: on the worker,
 * only cell i touched). The unloaded side of a heated pair is the one that
 * skids, the loaded one the one that runs hot and short. */
static void set_final(void *vctx, size_t i, const acbb_sim *sim)
{
    const pmap_ctx *c = vctx;
    if (acbb_sim_state(sim) == ACBB_RUN_RUNNING) return;
    acbb_snapshot *s = malloc(sizeof *s);
    if (!s) return;
    acbb_pmap_cell worst = c->cells[i], one;
    int k = 0;
    for (; acbb_sim_bearing_snapshot(sim, k, s) == ACBB_OK && s->n_bearings > 1; k++) {
        cell_values(c->base, s, &one);
        worst.skid = k ? fmax(worst.skid, one.skid) : one.skid;
        worst.rise_K = k ? fmax(worst.rise_K, one.rise_K) : one.rise_K;
        worst.Lnmr_h = k ? fmin(worst.Lnmr_h, one.Lnmr_h) : one.Lnmr_h;
        worst.s0_min = k ? fmin(worst.s0_min, one.s0_min) : one.s0_min;
    }
    free(s);
    if (k < 2) return;
    worst.have = 1;
    c->cells[i] = worst;
    c->set_done[i] = 1;
}

static void cell_done(void *vctx, const acbb_batch_result *r)
{
    const pmap_ctx *c = vctx;
    acbb_pmap_cell *cell = &c->cells[r->index];
    cell->status = r->ran ? r->status : ACBB_CANCELLED;
    snprintf(cell->status_name, sizeof cell->status_name, "%s",
             r->snap ? acbb_run_status_name(r->snap) : acbb_status_name(cell->status));
    if (r->snap && !c->set_done[r->index]) cell_values(c->base, r->snap, cell);
    cell->flags = judge(c->o, cell);
}

/* Per speed: the skid-free floor, the upper limits' ceiling, the window. */
static void rows_of(const acbb_pmap_opts *o, const acbb_pmap_cell *cells, acbb_pmap_row *rows)
{
    const unsigned upper = ~(unsigned)ACBB_PMAP_SKID;
    for (int s = 0; s < o->n_speeds; s++) {
        const acbb_pmap_cell *row = &cells[(size_t)s * o->n_preloads];
        acbb_pmap_row *r = &rows[s];
        *r = (acbb_pmap_row){ row[0].speed_rpm, -1, -1, -1, -1 };
        for (int p = 0; p < o->n_preloads; p++) {
            if (r->skid_free_N < 0 && row[p].have && !(row[p].flags & ACBB_PMAP_SKID))
                r->skid_free_N = row[p].preload_N;
            if (!(row[p].flags & upper)) r->upper_N = row[p].preload_N;
            if (row[p].flags == 0 && r->lo_N < 0) r->lo_N = r->hi_N = row[p].preload_N;
            else if (row[p].flags == 0 && r->hi_N == row[p - 1].preload_N) r->hi_N = row[p].preload_N;
        }
    }
}

static acbb_status check(const acbb_pmap_opts *o, int set, acbb_error *err)
{
    if (o->n_speeds < 1 || o->n_speeds > ACBB_PMAP_MAX_AXIS || o->n_preloads < 1 ||
        o->n_preloads > ACBB_PMAP_MAX_AXIS)
        return acbb_error_set(err, ACBB_EINVAL, "grid: 1..%d speeds and preloads (got %d x %d)",
                              ACBB_PMAP_MAX_AXIS, o->n_speeds, o->n_preloads);
    if (!(o->speed_lo > 0.0 && o->speed_hi >= o->speed_lo && isfinite(o->speed_hi)))
        return acbb_error_set(err, ACBB_EINVAL, "speeds %g..%g rpm: need 0 < low <= high",
                              o->speed_lo, o->speed_hi);
    if (!(o->preload_lo > 0.0 && o->preload_hi >= o->preload_lo && isfinite(o->preload_hi)))
        return acbb_error_set(err, ACBB_EINVAL, "preloads %g..%g N: need 0 < low <= high",
                              o->preload_lo, o->preload_hi);
    if (o->spring && set)
        return acbb_error_set(err, ACBB_EINVAL, "a spring preload maps a single bearing "
                              "(a set's preload is its own, set.*)");
    if (!(o->max_rise_K >= 0.0 && o->min_life_h >= 0.0 && o->min_s0 >= 0.0))
        return acbb_error_set(err, ACBB_EINVAL, "limits must be >= 0 (0 = not checked)");
    return ACBB_OK;
}

/* The grid's corners as scenes, checked before anything runs: a speed or
 * preload outside its key's range is bad input, not a map of failed cells
 * (issue 26 item 11). Each key is monotonic over the grid, so the corners
 * bound every cell. */
static acbb_status corners_valid(const pmap_ctx *c, size_t n, acbb_error *err)
{
    size_t np = (size_t)c->o->n_preloads, corner[4] = { 0, np - 1, n - np, n - 1 };
    for (int k = 0; k < 4; k++) {
        acbb_scene sc;
        acbb_batch_mode mode;
        acbb_error e;
        cell_scene((void *)c, corner[k], &sc, &mode, &e);
        acbb_status rc = acbb_scene_validate(&sc, &e);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "the cell at %g rpm, %g N: %s",
                                  c->cells[corner[k]].speed_rpm, c->cells[corner[k]].preload_N,
                                  e.msg);
    }
    return ACBB_OK;
}

acbb_status acbb_preload_map(const acbb_scene *base, const acbb_pmap_opts *o,
                             acbb_pmap_cell *cells, acbb_pmap_row *rows, acbb_error *err)
{
    int set = base->set_arrangement != ACBB_SET_SINGLE;
    acbb_status rc = check(o, set, err);
    if (rc != ACBB_OK) return rc;
    size_t n = (size_t)o->n_speeds * o->n_preloads;
    for (size_t i = 0; i < n; i++) {
        int s = (int)(i / o->n_preloads), p = (int)(i % o->n_preloads);
        cells[i] = (acbb_pmap_cell){ .speed_rpm = acbb_pmap_axis(o->speed_lo, o->speed_hi,
                                                                 o->n_speeds, s),
                                     .preload_N = acbb_pmap_axis(o->preload_lo, o->preload_hi,
                                                                 o->n_preloads, p),
                                     .status = ACBB_CANCELLED };
    }
    pmap_ctx c = { base, o, cells, calloc(n, 1) };
    if (!c.set_done) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if ((rc = corners_valid(&c, n, err)) != ACBB_OK) {
        free(c.set_done);
        return rc;
    }
    acbb_batch_opts bo = { .jobs = o->jobs, .cancel = o->cancel, .mode = ACBB_BATCH_TRANSIENT,
                           .scene = cell_scene, .step = set ? set_final : NULL,
                           .done = cell_done, .ctx = &c, .skip_stiffness = 1 }; /* none read */
    rc = acbb_batch_run(n, &bo, NULL);
    free(c.set_done);
    rows_of(o, cells, rows);
    if (rc == ACBB_CANCELLED) return acbb_error_set(err, rc, "preload map cancelled");
    return rc == ACBB_OK ? ACBB_OK : acbb_error_set(err, rc, "preload map: the batch failed");
}

const char *acbb_pmap_verdict(const acbb_pmap_cell *c)
{
    static const char *const names[] = { "skid", "hot", "short_life", "low_s0", "runaway",
                                         "failed" };
    for (int b = 5; b >= 4; b--)
        if (c->flags & (1u << b)) return names[b];
    for (int b = 0; b < 4; b++)
        if (c->flags & (1u << b)) return names[b];
    return "ok";
}
