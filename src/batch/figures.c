/* acbb — the seed's figures from the study's runs (figures.h): recording
 * the TE load-sweep trajectories, turning table rows into series, and
 * writing each panel's data file and PNG/SVG (src/io/plot_xy.c).
 *
 * The trajectories are re-driven on the batch runner (batch.h). Panels are
 * independent, so they are written in parallel (acbb_batch_for); each panel is
 * one gnuplot process (both formats), the cost that dominates the command
 * (BENCHMARKS.md "Seed figures"). Nothing here prints. */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/batch.h"
#include "acbb/tools/figures.h"
#include "acbb/tools/measure.h"

/* ---- recording the TE load sweep ---- */

static void push_step(acbb_fig_traj *tr, const acbb_snapshot *s, double ambient)
{
    if (tr->n == tr->cap) {
        size_t cap = tr->cap ? 2 * tr->cap : 256;
        acbb_fig_step *p = realloc(tr->p, cap * sizeof *p);
        if (!p) {
            tr->oom = 1;
            return;
        }
        tr->p = p;
        tr->cap = cap;
    }
    const acbb_ball_view *b = &s->balls[0];
    const acbb_squeeze *q = &s->squeeze;
    tr->p[tr->n++] = (acbb_fig_step){
        .iteration = (double)s->iteration, .t = s->time,
        .T5_rise = s->T_outer_ring - ambient,
        .exp_in = s->exp_inner + s->exp_inner_cen, .exp_out = s->exp_outer,
        .exp_ball = s->exp_ball, .dA1 = s->delta_x,
        /* MODEL.md 3 (CLEAN): Delta A2 = theta_i + theta_icen - theta_o. */
        .dA2 = q->inner_thermal + q->inner_centrifugal + q->outer,
        .Qi = b->Qi, .Qo = b->Qo, .alpha_i = b->alpha_i, .alpha_o = b->alpha_o,
        .wx = b->omega_x, .wy = b->omega_y, .wz = b->omega_z };
}

typedef struct {
    acbb_fig_input *in;
    acbb_snapshot *snap;        /* one per point: the step hook's scratch */
} rec_job;

static const acbb_study_point *te_point(const rec_job *j, size_t k)
{
    return &j->in->runs->sweep[ACBB_STUDY_BASE][ACBB_STUDY_LOAD][2 * k + ACBB_STUDY_TE];
}

/* The trajectory is the point of a figure: the scene's own transient. */
static acbb_status rec_scene(void *ctx, size_t k, acbb_scene *out, acbb_batch_mode *mode,
                             acbb_error *err)
{
    const acbb_study_point *pt = te_point(ctx, k);
    *mode = ACBB_BATCH_AS_SCENE;
    if (pt->skip) return acbb_error_set(err, pt->status, "%s", pt->message);
    *out = pt->scene;
    return ACBB_OK;
}

static void rec_step(void *ctx, size_t k, const acbb_sim *sim)
{
    rec_job *j = ctx;
    acbb_sim_snapshot(sim, &j->snap[k]);
    push_step(&j->in->traj[k], &j->snap[k], te_point(j, k)->scene.ambient_C);
}

static void rec_done(void *ctx, const acbb_batch_result *r)
{
    acbb_fig_traj *tr = &((rec_job *)ctx)->in->traj[r->index];
    tr->status = tr->oom ? ACBB_ENOMEM : r->status;
    snprintf(tr->message, sizeof tr->message, "%s", r->message);
}

acbb_status acbb_figures_record(const acbb_study_runs *runs, int jobs, const atomic_int *cancel,
                                acbb_fig_input **out, acbb_error *err)
{
    *out = NULL;
    acbb_fig_input *in = calloc(1, sizeof *in);
    rec_job j = { in, malloc(ACBB_STUDY_NPTS * sizeof *j.snap) };
    if (!in || !j.snap) {
        free(in);
        free(j.snap);
        return acbb_error_set(err, ACBB_ENOMEM, "figures: out of memory");
    }
    in->runs = runs;
    double t0 = acbb_now_ms();
    acbb_batch_opts o = { .jobs = jobs, .cancel = cancel, .scene = rec_scene, .step = rec_step,
                          .done = rec_done, .ctx = &j, .skip_stiffness = 1 }; /* none plotted */
    acbb_status st = acbb_batch_run(ACBB_STUDY_NPTS, &o, NULL);
    free(j.snap);
    in->wall_ms = acbb_now_ms() - t0;
    *out = in;
    if (st == ACBB_CANCELLED) return acbb_error_set(err, ACBB_CANCELLED, "figures: cancelled");
    return ACBB_OK;
}

void acbb_figures_input_free(acbb_fig_input *in)
{
    if (!in) return;
    for (int k = 0; k < ACBB_STUDY_NPTS; k++) free(in->traj[k].p);
    free(in);
}

/* ---- series ---- */

static acbb_fig_series *add_series(acbb_fig_data *d, size_t cap, int color, int dash,
                                   int points, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
static acbb_fig_series *add_series(acbb_fig_data *d, size_t cap, int color, int dash,
                                   int points, const char *fmt, ...)
{
    if (d->n >= ACBB_FIG_MAX_SERIES || cap == 0) return NULL;
    acbb_fig_series *s = &d->s[d->n];
    *s = (acbb_fig_series){ .color = color, .dash = dash, .points = points };
    s->x = malloc(cap * sizeof *s->x);
    s->y = malloc(cap * sizeof *s->y);
    if (!s->x || !s->y) {
        free(s->x);
        free(s->y);
        d->oom = 1;
        return NULL;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->label, sizeof s->label, fmt, ap);
    va_end(ap);
    d->n++;
    return s;
}

/* Keep a point only when both coordinates are finite. */
static void put(acbb_fig_series *s, double x, double y)
{
    if (isfinite(x) && isfinite(y)) {
        s->x[s->n] = x;
        s->y[s->n++] = y;
    }
}

static void why(acbb_fig_data *d, const char *what, const char *status, const char *msg)
{
    if (!d->why[0])
        snprintf(d->why, sizeof d->why, "%s: %s%s%s", what, status, msg[0] ? ": " : "", msg);
}

/* A key entry: a label and a style, no points. */
static void key_entry(acbb_fig_data *d, int color, int dash, int points, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
static void key_entry(acbb_fig_data *d, int color, int dash, int points, const char *fmt, ...)
{
    if (d->n_key >= ACBB_FIG_MAX_KEY) return;
    acbb_fig_series *k = &d->key[d->n_key++];
    *k = (acbb_fig_series){ .color = color, .dash = dash, .points = points };
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(k->label, sizeof k->label, fmt, ap);
    va_end(ap);
}

/* Loads by colour and marker (issue 29 item 9: by colour alone 7 of 8
 * lines looked the same in grey), quantities by dash. */
static void eval_traj(const acbb_figure_row *row, const acbb_fig_input *in, acbb_fig_data *d)
{
    int a = row->sel == ACBB_FIG_LARGE ? ACBB_STUDY_NLIGHT : 0;
    int z = row->sel == ACBB_FIG_LIGHT ? ACBB_STUDY_NLIGHT : ACBB_STUDY_NPTS;
    size_t xoff = row->kind == ACBB_FIG_TRAJ_TIME ? offsetof(acbb_fig_step, t)
                                                   : offsetof(acbb_fig_step, iteration);
    for (int qi = 0; qi < row->nq; qi++)
        for (int k = a; k < z; k++) {
            const acbb_fig_traj *tr = &in->traj[k];
            const acbb_fig_quantity *q = &row->q[qi];
            if (tr->status != ACBB_OK) {
                char what[64];
                snprintf(what, sizeof what, "TE run at %g N", acbb_study_loads[k]);
                why(d, what, acbb_status_name(tr->status), tr->message);
                continue;
            }
            if (row->nq > 1 && qi == 0) key_entry(d, k - a + 1, 1, 1, "%g N", acbb_study_loads[k]);
            acbb_fig_series *s = add_series(d, tr->n, k - a + 1, qi + 1, 1, "%s%s%g N",
                                            row->nq > 1 ? q->label : "",
                                            row->nq > 1 ? " at " : "", acbb_study_loads[k]);
            for (size_t i = 0; s && i < tr->n; i++) {
                const char *step = (const char *)&tr->p[i];
                double x, y;
                memcpy(&x, step + xoff, sizeof x);
                memcpy(&y, step + q->off, sizeof y);
                put(s, x, q->scale * y);
            }
        }
    for (int qi = 0; row->nq > 1 && qi < row->nq; qi++)
        key_entry(d, 0, qi + 1, 0, "%s", row->q[qi].label);
}

static void eval_sweep(const acbb_figure_row *row, const acbb_fig_input *in, acbb_fig_data *d)
{
    bool both = row->sel == ACBB_FIG_SPEED_SWEEPS;
    int blks[2] = { both ? ACBB_STUDY_S100 : row->sel, ACBB_STUDY_S1000 };
    int lv = row->l2 ? ACBB_STUDY_L2 : ACBB_STUDY_BASE;
    for (int bi = 0; bi < (both ? 2 : 1); bi++)
        for (int qi = 0; qi < row->nq; qi++)
            for (int m = 0; m < 2; m++) {
                const acbb_study_point *pts = in->runs->sweep[lv][blks[bi]];
                const double *xs = blks[bi] == ACBB_STUDY_LOAD ? acbb_study_loads
                                                                : acbb_study_speeds;
                int fam = 1 + bi * row->nq + qi;
                if (m == 0 && (both || row->nq > 1))
                    key_entry(d, fam, 1, 1, "%s%s%s", row->nq > 1 ? row->q[qi].label : "",
                              !both ? "" : row->nq > 1 ? ", " : "F_x = ",
                              !both ? "" : bi ? "1000 N" : "100 N");
                /* a family by colour and marker shape; TE solid and
                 * filled, WTE dashed and open (issue 29 item 9) */
                acbb_fig_series *s = add_series(
                    d, ACBB_STUDY_NPTS, fam, m == ACBB_STUDY_TE ? 1 : 2, 1,
                    "%s %s%s", row->q[qi].label, m == ACBB_STUDY_TE ? "TE" : "WTE",
                    !both ? "" : bi ? " at 1000 N" : " at 100 N");
                for (int k = 0; s && k < ACBB_STUDY_NPTS; k++) {
                    const acbb_study_point *p = &pts[2 * k + m];
                    if (!p->ok) {
                        why(d, p->label, acbb_status_name(p->status), p->message);
                        continue;
                    }
                    put(s, xs[k], row->q[qi].scale * row->q[qi].get(&p->last));
                }
            }
    key_entry(d, 0, 1, 1, "TE: with expansion");
    key_entry(d, 0, 2, 1, "WTE: without");
}

void acbb_figure_eval(const acbb_figure_row *row, const acbb_fig_input *in, acbb_fig_data *out)
{
    memset(out, 0, sizeof *out);
    if (row->kind == ACBB_FIG_SWEEP) eval_sweep(row, in, out);
    else eval_traj(row, in, out);
    /* A series with fewer than two points draws nothing a reader can use. */
    int w = 0;
    for (int i = 0; i < out->n; i++) {
        if (out->s[i].n >= 2) {
            out->s[w++] = out->s[i];
            continue;
        }
        free(out->s[i].x);
        free(out->s[i].y);
    }
    out->n = w;
}

void acbb_fig_data_free(acbb_fig_data *d)
{
    for (int i = 0; i < d->n; i++) {
        free(d->s[i].x);
        free(d->s[i].y);
    }
    d->n = 0;
}
