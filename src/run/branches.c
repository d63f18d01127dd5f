/* acbb — the steady solve and the transient compared (branches.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/branches.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/measure.h"
#include "acbb/units.h"

/* One branch when the two polish to the same steady state: the transient
 * ends with the direct steady iteration (stepper.c, polish), so both meet to
 * ~1e-8 (README "Batch runner": 5e-9 on 7008C); another branch differs by
 * kelvins and watts. The bounds sit far from both. */
#define AGREE_DT_K 0.01
#define AGREE_LOSS_REL 1e-4
static const char k_criterion[] =
    "both converged, nodes within 0.01 K, total loss within 1e-4 relative";

bool acbb_branches_wanted(const acbb_scene *s)
{
    return s->heating && (s->schedule_n > 0 || s->preload == ACBB_PRELOAD_DISPLACEMENT);
}

void acbb_branch_summarize(const acbb_snapshot *r, acbb_branch_state *b)
{
    memset(b, 0, sizeof *b);
    snprintf(b->status, sizeof b->status, "%s", acbb_run_status_name(r));
    snprintf(b->message, sizeof b->message, "%s", r->message);
    b->iterations = r->iteration;
    b->time_s = r->time;
    int k = 0;
    for (int j = 1; j < r->n_balls; j++)
        if (r->balls[j].Qi > r->balls[k].Qi) k = j;
    if (r->n_balls > 0) {
        b->Qi_N = r->balls[k].Qi;
        b->Qo_N = r->balls[k].Qo;
        b->alpha_i_deg = acbb_rad_to_deg(r->balls[k].alpha_i);
    }
    b->reaction_x_N = r->reaction_x;
    b->loss_total_W = r->losses.total;
    b->T_outer_ring_C = r->T_outer_ring;
    b->T_inner_ring_C = r->T_inner_ring;
    b->T_ball_C = r->T_ball;
}

static void compare(const acbb_snapshot *st, const acbb_snapshot *tr, acbb_branches *out)
{
    double dT = 0.0;
    int n = st->n_nodes == tr->n_nodes ? st->n_nodes : 0;
    for (int i = 0; i < n; i++) dT = fmax(dT, fabs(st->T[i] - tr->T[i]));
    double P = st->losses.total;
    out->max_dT_K = n ? dT : 0.0;
    out->loss_rel = P > 0.0 ? fabs(P - tr->losses.total) / P : 0.0;
    out->agree = n && st->state == ACBB_RUN_CONVERGED && tr->state == ACBB_RUN_CONVERGED
                 && dT <= AGREE_DT_K && out->loss_rel <= AGREE_LOSS_REL;
}

/* The branch's status is `rc`, with a message, and no state. */
static void not_run(acbb_snapshot *snap, acbb_status rc, const char *msg)
{
    memset(snap, 0, sizeof *snap);
    snap->state = ACBB_RUN_FAILED;
    snap->status = rc;
    snprintf(snap->message, sizeof snap->message, "%s", msg);
}

/* The one text of the shared bound, naming the user's value (the other
 * branch's own scene holds only what was left of it). */
static void bound_text(acbb_snapshot *snap, double max_wall_s, const char *when)
{
    snprintf(snap->message, sizeof snap->message, "wall-clock bound fidelity.max_wall_s = %g s "
             "(the run and the other branch together) reached %s", max_wall_s, when);
}

acbb_status acbb_branch_run(const acbb_scene *o, const acbb_atomic_int *cancel, acbb_snapshot *snap)
{
    acbb_sim *sim = NULL;
    acbb_error e = { "" };
    /* a summary (and compare()) reads neither stiffness nor life: about a
     * tenth of a run's work, and the contact study's eight runs (issue 30) */
    acbb_sim_opts so = { .cancel = cancel, .skip_stiffness = 1, .skip_life = 1 };
    acbb_status rc = acbb_sim_create(o, &so, &sim, &e);
    if (rc != ACBB_OK) {
        not_run(snap, rc, e.msg); /* never started */
        return rc == ACBB_ENOMEM || rc == ACBB_CANCELLED ? rc : ACBB_OK;
    }
    rc = acbb_sim_drive(sim, &(acbb_run_ctl){ .cancel = cancel });
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    return rc == ACBB_CANCELLED ? rc : ACBB_OK;
}

/* The scene in the other thermal mode, run to its end into `snap`, within
 * what the shared bound left (acbb_branches_compare). */
static acbb_status run_other(const acbb_scene *s, const acbb_atomic_int *cancel, double deadline_ms,
                             acbb_snapshot *snap)
{
    acbb_scene o = *s; /* resolved by the caller (acbb_sim_scene) */
    o.thermal_mode = o.thermal_mode == ACBB_THERMAL_STEADY ? ACBB_THERMAL_TRANSIENT
                                                           : ACBB_THERMAL_STEADY;
    int shared = o.max_wall_s > 0.0 && deadline_ms > 0.0;
    if (shared) {
        o.max_wall_s = 1e-3 * (deadline_ms - acbb_now_ms());
        if (!(o.max_wall_s > 0.0)) {
            not_run(snap, ACBB_WALL_LIMIT, "");
            bound_text(snap, s->max_wall_s, "before the other branch started");
            return ACBB_OK;
        }
    }
    acbb_status rc = acbb_branch_run(&o, cancel, snap);
    if (shared && snap->status == ACBB_WALL_LIMIT)
        bound_text(snap, s->max_wall_s, snap->state == ACBB_RUN_FAILED && snap->iteration == 0
                   ? "during the other branch's set-up"
                   : "in the other branch; last good state kept");
    return rc;
}

acbb_status acbb_branches_compare(const acbb_scene *s, const acbb_snapshot *run,
                                  const acbb_atomic_int *cancel, double deadline_ms,
                                  acbb_branches *out, acbb_error *err)
{
    acbb_snapshot *other = malloc(sizeof *other);
    if (!other) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_status rc = run_other(s, cancel, deadline_ms, other);
    if (rc != ACBB_OK) {
        free(other);
        return acbb_error_set(err, rc, "%s", rc == ACBB_CANCELLED
                              ? "cancelled before the second branch was solved" : "out of memory");
    }
    int run_steady = s->thermal_mode == ACBB_THERMAL_STEADY;
    const acbb_snapshot *st = run_steady ? run : other, *tr = run_steady ? other : run;
    acbb_branch_summarize(st, &out->steady);
    acbb_branch_summarize(tr, &out->transient);
    compare(st, tr, out);
    out->criterion = k_criterion;
    free(other);
    return ACBB_OK;
}
