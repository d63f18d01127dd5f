/* acbb — the one coupled stepper of the seed's Fig. 5 (MODEL.md section 9;
 * stepper.h). One step k: the thermal update from T^k with the sources of
 * the state at T^k (lagged coupling) -> the plant's evaluation at T^{k+1}
 * (expansions, mechanics, losses, sources). The time step adapts so that
 * no node that stores heat moves more than DT_MAX_DT_K per step and the
 * losses no more than 5 %; once quiet, the steady polish balances the
 * network to round-off (MODEL.md 8.2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "stepper.h"
#include "sim_priv.h"
#include "steady_polish.h"
#include "acbb/tools/schedule.h"

int acbb_follows_schedule(const acbb_scene *s)
{
    return s->schedule_n > 0 && s->thermal_mode == ACBB_THERMAL_TRANSIENT && s->heating;
}

acbb_status acbb_stepper_fail(acbb_stepper *r, const acbb_scene *s, acbb_status st,
                              const char *msg)
{
    r->state = ACBB_RUN_FAILED;
    r->status = st;
    if (st == ACBB_WALL_LIMIT) /* one text wherever inside a step the bound was met */
        snprintf(r->msg, sizeof r->msg, "wall-clock bound fidelity.max_wall_s = %g s "
                 "reached; last good state kept", s->max_wall_s);
    else
        snprintf(r->msg, sizeof r->msg, "%s", msg);
    return st;
}

static acbb_status fail(const acbb_plant *p, acbb_stepper *r, acbb_status st, const char *msg)
{
    return acbb_stepper_fail(r, p->s, st, msg);
}

/* ---- the schedule (schedule.h) ---- */

/* The transient does not step past a schedule row (a short ramp after a
 * long hold would be jumped), nor settle before the last row. */
static int schedule_done(const acbb_plant *p, acbb_stepper *r)
{
    if (!acbb_follows_schedule(p->s)) return 1;
    acbb_operating op;
    acbb_schedule_at(p->s, r->time, &op);
    if (op.finished) return 1;
    double next = p->s->schedule[op.row].t;
    r->dt = fmin(r->dt, fmax(next - r->time, DT_MIN));
    return 0;
}

/* ---- the thermal update ---- */

static double capacity(const acbb_plant *p, int i)
{
    return p->capacity ? p->capacity(p->ctx, i) : acbb_tnet_capacity(p->net, i);
}

/* The network solve: the plant's own, or its net's (stepper.h). */
static acbb_status net_solve(const acbb_plant *p, int steady, double dt, double *Tn)
{
    if (p->solve) return p->solve(p->ctx, p->q, steady ? 0.0 : dt, Tn);
    return steady ? acbb_tnet_steady(p->net, p->q, Tn) : acbb_tnet_step(p->net, p->q, dt, Tn);
}

/* Largest move of a node (stored: only of one that stores heat: zero-
 * capacity nodes such as the contact nodes jump to their new balance in
 * any step, so they must not drive the step-size control). */
static double max_change(const acbb_plant *p, const double *Tn, int stored)
{
    double m = 0.0;
    for (int i = 0; i < p->n; i++)
        if (!stored || capacity(p, i) > 0.0) m = fmax(m, fabs(Tn[i] - p->T[i]));
    return m;
}

/* Backward Euler from T into Tn, halving dt while a stored node moves more
 * than DT_MAX_DT_K; or (steady) the direct steady solve, under-relaxed by
 * `relax` (Picard, MODEL.md section 9). *dT, *dTs: the largest move, of
 * any node and of a node that stores heat. */
static acbb_status thermal(const acbb_plant *p, acbb_stepper *r, int steady, double relax,
                           double *Tn, double *dT, double *dTs)
{
    for (;;) {
        memcpy(Tn, p->T, sizeof(double) * (size_t)p->n);
        if (p->solves) (*p->solves)++;
        acbb_status rc = net_solve(p, steady, r->dt, Tn);
        if (rc != ACBB_OK) return rc;
        if (steady)
            for (int i = 0; i < p->n; i++) Tn[i] = p->T[i] + relax * (Tn[i] - p->T[i]);
        *dT = max_change(p, Tn, 0);
        *dTs = max_change(p, Tn, 1);
        if (steady || *dTs <= DT_MAX_DT_K || r->dt <= DT_MIN) return ACBB_OK;
        r->dt = fmax(0.5 * r->dt, DT_MIN);
    }
}

/* Thermal update to T^{k+1} and the evaluation there. A transient step whose
 * total loss moves more than 5 % is rejected and retried with half the step
 * (MODEL.md section 9); *dT, *dTs report the accepted move. */
static acbb_status advance(const acbb_plant *p, acbb_stepper *r, int steady, double *dT,
                           double *dTs, acbb_error *err)
{
    double Tn[ACBB_STEPPER_NMAX];
    p->save(p->ctx, ACBB_KEEP_LAST);
    double before = p->loss(p->ctx);
    for (;;) {
        /* each retry evaluates again (issue 26 item 7; the state is the kept one here) */
        acbb_status rc = p->stop(p->ctx, err);
        if (rc != ACBB_OK) return rc;
        /* The steady solve's relaxation is the polish's rule (steady_polish.h),
         * not MODEL.md's fixed 0.5: the map contracts about 25x per iteration
         * on the 7008C, so 0.5 only slowed it (33 -> 11 iterations undamped,
         * issue 30 lever 1); halving on a growing residual still damps an
         * overshooting map. */
        double w = r->relax.relax;
        rc = thermal(p, r, steady, w, Tn, dT, dTs);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "thermal network: %s", acbb_status_name(rc));
        if (!acbb_snap_all_finite(Tn, p->n))
            return acbb_error_set(err, ACBB_NONFINITE,
                                  "non-finite temperature caught; last good state kept");
        memcpy(p->T, Tn, sizeof(double) * (size_t)p->n);
        rc = acbb_follows_schedule(p->s)
                 ? p->operate(p->ctx, r->time + (steady ? 0.0 : r->dt), err) : ACBB_OK;
        if (rc == ACBB_OK)
            rc = p->evaluate(p->ctx, steady ? ACBB_PASS_STEADY : ACBB_PASS_TRANSIENT, 1.0, err);
        if (rc != ACBB_OK) {
            p->restore(p->ctx, ACBB_KEEP_LAST);
            if (steady && acbb_relax_reject(&r->relax, rc)) continue;
            return rc;
        }
        if (steady) acbb_relax_judge(&r->relax, w, *dT / w, 0.0);
        double dP = fabs(p->loss(p->ctx) - before) / fmax(p->loss(p->ctx), 1e-12);
        if (steady || dP <= 0.05 || r->dt <= DT_MIN) return ACBB_OK;
        p->restore(p->ctx, ACBB_KEEP_LAST);
        r->dt = fmax(0.5 * r->dt, DT_MIN);
    }
}

/* ---- the steady polish (steady_polish.h) ---- */

/* The polish's state: the plant, the iterate of smallest residual so far
 * (keeps_best) and the last undamped move (acbb_polish_turn). */
typedef struct {
    const acbb_plant *p;
    acbb_stepper *r;
    double best_res;
    double move[ACBB_STEPPER_NMAX];
} polish_ctx;

/* One polish iteration: the direct steady solve, the move by `relax`, the
 * evaluation there; a failed evaluation keeps the last evaluated iterate. */
static acbb_status polish_step(void *ctx, double relax, double *res, double *turn,
                               acbb_error *err)
{
    polish_ctx *c = ctx;
    const acbb_plant *p = c->p;
    double Tn[ACBB_STEPPER_NMAX], dT = 0.0, dTs;
    acbb_status rc = p->stop(p->ctx, err);
    if (rc != ACBB_OK) return rc;
    rc = thermal(p, c->r, 1, relax, Tn, &dT, &dTs);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "steady solve failed");
    if (!acbb_snap_all_finite(Tn, p->n)) /* fmax in the residual drops a NaN */
        return acbb_error_set(err, ACBB_NONFINITE, "non-finite temperature in the steady "
                              "solve; last good state kept");
    *res = dT / relax; /* the undamped move (relax is 1 or a power of 1/2) */
    *turn = acbb_polish_turn(c->move, p->T, Tn, relax, p->n);
    p->save(p->ctx, ACBB_KEEP_LAST);
    if (p->keeps_best && *res < c->best_res) { /* the residual of the state before the move */
        p->save(p->ctx, ACBB_KEEP_BEST);
        c->best_res = *res;
    }
    memcpy(p->T, Tn, sizeof(double) * (size_t)p->n);
    rc = p->evaluate(p->ctx, ACBB_PASS_POLISH, relax, err);
    if (rc != ACBB_OK) p->restore(p->ctx, ACBB_KEEP_LAST);
    return rc;
}

/* Damped where it overshoots (issue 18), never OK unconverged: a polish
 * that does not converge ends the run ACBB_DIVERGED with the iterate of
 * smallest residual (keeps_best) or the last. */
static acbb_status polish(const acbb_plant *p, acbb_stepper *r, acbb_error *err)
{
    polish_ctx c = { p, r, INFINITY, { 0 } };
    acbb_polish_result res;
    acbb_status rc = acbb_polish_iterate(polish_step, &c,
                                         acbb_polish_resolution(acbb_polish_loss_rtol(p->s),
                                                                p->T, p->n), &res, err);
    if (rc == ACBB_DIVERGED && res.iterations == ACBB_POLISH_ITERS) {
        size_t n = strlen(err->msg);
        if (!p->keeps_best) {
            snprintf(err->msg + n, sizeof err->msg - n, "; last state kept");
        } else if (c.best_res < INFINITY) {
            p->restore(p->ctx, ACBB_KEEP_BEST);
            snprintf(err->msg + n, sizeof err->msg - n, "; the iterate of smallest residual "
                     "(%.3g K) kept", c.best_res);
        }
    }
    return rc;
}

/* ---- the verdict ---- */

static void settle(const acbb_plant *p)
{
    if (p->settle) p->settle(p->ctx);
}

/* Temperature and pressure limits, and a rigid preload's force growing
 * ever faster: dF/dt > 0 and d2F/dt2 > 0 over 50 accepted steps is the
 * runaway of MODEL.md section 9 (rates, since dt varies). */
static acbb_status runaway(const acbb_plant *p, acbb_stepper *r, double step_dt)
{
    char d[200], msg[240];
    if (p->limits(p->ctx, r->time, d, sizeof d) != ACBB_OK) {
        snprintf(msg, sizeof msg, "thermal runaway: %s", d);
        return fail(p, r, ACBB_RUNAWAY, msg);
    }
    int rigid;
    double F = p->force(p->ctx, &rigid);
    if (rigid && r->iter > 0 && step_dt > 0.0) {
        double rate = (F - r->prev_F) / step_dt;
        r->growth = rate > 0.0 && rate > r->prev_rate ? r->growth + 1 : 0;
        r->prev_rate = rate;
        if (r->growth >= 50) {
            snprintf(msg, sizeof msg, "thermal runaway: %s grows ever faster (%.0f N at t = "
                     "%.0f s)", p->force_name, F, r->time);
            return fail(p, r, ACBB_RUNAWAY, msg);
        }
    }
    r->prev_F = F;
    return ACBB_OK;
}

/* A steady state is one whose network balances its sources (MODEL.md 12
 * item 18; `balanced` 0: heating off, no network solved): otherwise the
 * run fails with ACBB_UNBALANCED and keeps the state it reached. */
static acbb_status converge(const acbb_plant *p, acbb_stepper *r, int balanced,
                            const char *what)
{
    settle(p);
    acbb_error err = { "" };
    if (balanced && p->balance(p->ctx, &err) != ACBB_OK)
        return fail(p, r, ACBB_UNBALANCED, err.msg);
    p->converge(p->ctx);
    r->state = ACBB_RUN_CONVERGED;
    snprintf(r->msg, sizeof r->msg, "%s", what);
    return ACBB_OK;
}

/* effects.heating = off: temperatures stay at ambient, so one converged
 * mechanics (and Level-2) state is the answer; no network is solved. */
static acbb_status isothermal(const acbb_plant *p, acbb_stepper *r)
{
    acbb_error err = { "" };
    for (int it = 0; it < ISO_ITERS; it++) {
        double prev = p->loss(p->ctx);
        acbb_status rc = p->stop(p->ctx, &err);
        if (rc == ACBB_OK) rc = p->evaluate(p->ctx, ACBB_PASS_STEADY, 1.0, &err);
        if (rc != ACBB_OK) return fail(p, r, rc, err.msg[0] ? err.msg : acbb_status_name(rc));
        r->iter++;
        double total = p->loss(p->ctx);
        if (fabs(total - prev) <= 1e-12 * fmax(total, 1e-12)) break;
    }
    return converge(p, r, 0, "isothermal mechanics at ambient (effects.heating = off)");
}

/* Quiet, polished, or out of steps. */
static acbb_status verdict(const acbb_plant *p, acbb_stepper *r, int steady)
{
    acbb_error err = { "" };
    if (r->quiet >= (steady ? 3 : STEADY_COUNT)) {
        acbb_status rc = polish(p, r, &err);
        if (rc != ACBB_OK) {
            settle(p); /* the heat flows of the state kept */
            return fail(p, r, rc, err.msg);
        }
        char what[64];
        snprintf(what, sizeof what, "thermal steady state after %ld steps", r->iter);
        if ((rc = converge(p, r, 1, what)) != ACBB_OK) return rc;
    } else if (r->iter >= p->s->max_steps || r->time >= p->s->max_time) {
        settle(p);
        snprintf(err.msg, sizeof err.msg, "no steady state within the limits (%ld steps, %.0f s "
                 "simulated); raise thermal.max_steps or thermal.max_time_s", r->iter, r->time);
        return fail(p, r, ACBB_NOT_CONVERGED, err.msg);
    }
    settle(p);
    return ACBB_OK;
}

acbb_status acbb_stepper_step(const acbb_plant *p, acbb_stepper *r)
{
    if (r->state != ACBB_RUN_RUNNING) return r->status;
    if (!p->s->heating) return isothermal(p, r);
    acbb_error err = { "" };
    double dT = 0.0, dTs = 0.0, before = p->loss(p->ctx);
    int steady = p->s->thermal_mode == ACBB_THERMAL_STEADY;
    int scheduled = !schedule_done(p, r);
    acbb_status rc = advance(p, r, steady, &dT, &dTs, &err);
    if (rc != ACBB_OK) return fail(p, r, rc, err.msg[0] ? err.msg : acbb_status_name(rc));
    double step_dt = steady ? 1.0 : r->dt;
    r->iter++;
    if (!steady) r->time += r->dt;
    r->residual = dT / step_dt;
    /* The growth detector of MODEL.md 9 is for a fixed operating point; while
     * a schedule moves it the force grows by design (the temperature and
     * pressure limits stay on). */
    if (scheduled) r->growth = 0;
    if ((rc = runaway(p, r, steady ? 0.0 : step_dt)) != ACBB_OK) return rc;
    double total = p->loss(p->ctx), dP = fabs(total - before) / fmax(total, 1e-12);
    int quiet = steady ? dT < ACBB_STEADY_QUIET_K && dP < 1e-9
                       : r->residual < p->s->steady_tol && dP < 1e-4;
    r->quiet = quiet && !scheduled ? r->quiet + 1 : 0;
    /* Grow while the losses barely move and nodes move < 0.5 K. */
    if (!steady && dP < 0.005 && dTs < 0.25 * DT_MAX_DT_K)
        r->dt = fmin(1.5 * r->dt, DT_MAX);
    return verdict(p, r, steady);
}
