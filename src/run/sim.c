/* acbb — the coupled stepper of the seed's Fig. 5 (MODEL.md section 9).
 *
 * One step k: expansions from T^k -> mechanics (warm start) -> kinematics,
 * film and the five losses -> heat sources -> backward-Euler thermal step
 * to T^{k+1}. The coupling is lagged (mechanics at T^k); the time step
 * adapts so that no node moves more than 2 K per step. This file is the
 * stepper and the set-up; one evaluation of the state is sim_eval.c, the
 * steady polish steady_polish.c, the snapshot's views sim_snapshot.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <assert.h>
#include "acbb/sim.h"
#include "acbb/life_eval.h"
#include "acbb/measure.h"
#include "stiffness.h"
#include "mechanics.h"
#include "network.h"
#include "acbb/fidelity.h"
#include "losses.h"
#include "lubrication.h"
#include "expansion.h"
#include "quasi_dynamic.h"
#include "dynamic.h"
#include "sim_priv.h"
#include "sim_struct.h"
#include "cancel.h"
#include "gsl_quiet.h"
#include "sim_set.h"
#include "steady_polish.h"
#include "acbb/schedule.h"


static acbb_status fail(acbb_sim *sim, acbb_status st, const char *fmt, const char *detail)
{
    sim->state = ACBB_RUN_FAILED;
    sim->status = st;
    snprintf(sim->msg, sizeof sim->msg, fmt, detail);
    if (st == ACBB_WALL_LIMIT) /* one text wherever inside a step the bound was met */
        snprintf(sim->msg, sizeof sim->msg, "wall-clock bound fidelity.max_wall_s = %g s "
                 "reached; last good state kept", sim->s.max_wall_s);
    return st;
}

/* fidelity.max_wall_s (issue 20 item 8) bounds the whole run, set-up
 * included: the computing time still allowed becomes a deadline on the
 * monotonic clock, armed for the set-up and re-armed at each step (so
 * hooks and pauses between steps do not count). Read by the solver's
 * inner loops and, at the dynamic level, in every ball's right-hand side
 * (a window can take seconds), so no single step or set-up overruns. */
static acbb_status past_bound(const void *ctx)
{
    const acbb_sim *sim = ctx;
    return sim->deadline_ms > 0.0 && acbb_now_ms() >= sim->deadline_ms ? ACBB_WALL_LIMIT
                                                                         : ACBB_OK;
}

static void arm_bound(acbb_sim *sim)
{
    double left = 1e3 * sim->s.max_wall_s - sim->setup_ms - sim->wall_ms;
    sim->deadline_ms = sim->s.max_wall_s > 0.0 ? acbb_now_ms() + fmax(left, 0.0) : 0.0;
    if (sim->dyn) acbb_dyn_set_stop(sim->dyn, sim->deadline_ms > 0.0 ? past_bound : NULL, sim);
}

/* The caller's cancel flag, then the wall-clock bound. */
acbb_status acbb_simx_stop_check(const acbb_sim *sim, acbb_error *err)
{
    if (acbb_cancelled(sim->cancel))
        return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
    if (past_bound(sim) != ACBB_OK)
        return acbb_error_set(err, ACBB_WALL_LIMIT, "wall-clock bound fidelity.max_wall_s = "
                              "%g s reached", sim->s.max_wall_s);
    return ACBB_OK;
}

/* ---- checks ---- */

static acbb_status check_runaway(acbb_sim *sim, const double *T, double step_dt)
{
    char d[160];
    for (int i = 0; i < sim->nw.n; i++)
        if (T[i] > sim->s.temp_limit_C) {
            snprintf(d, sizeof d, "node %s reached %.1f C (limit thermal.temp_limit_C = %.0f C) at t = %.0f s",
                     sim->nw.names[i], T[i], sim->s.temp_limit_C, sim->time);
            return fail(sim, ACBB_RUNAWAY, "thermal runaway: %s", d);
        }
    double p = acbb_snap_max_pmax(&sim->ms);
    if (p > PMAX_LIMIT) {
        snprintf(d, sizeof d, "contact pressure %.2f GPa exceeds the 4.2 GPa static limit at t = %.0f s",
                 p * 1e-9, sim->time);
        return fail(sim, ACBB_RUNAWAY, "thermal runaway: %s", d);
    }
    if (sim->s.preload == ACBB_PRELOAD_DISPLACEMENT && sim->iter > 0 && step_dt > 0.0) {
        /* Rigid preload: dF/dt > 0 and d2F/dt2 > 0 over 50 accepted steps is
         * the runaway of MODEL.md section 9 (rates, since dt varies). */
        double rate = (sim->ms.Fx - sim->prev_Fx) / step_dt;
        sim->growth_count = (rate > 0.0 && rate > sim->prev_rate) ? sim->growth_count + 1 : 0;
        sim->prev_rate = rate;
        if (sim->growth_count >= 50) {
            snprintf(d, sizeof d, "axial reaction grows ever faster (%.0f N at t = %.0f s)",
                     sim->ms.Fx, sim->time);
            return fail(sim, ACBB_RUNAWAY, "thermal runaway: %s", d);
        }
    }
    sim->prev_Fx = sim->ms.Fx;
    return ACBB_OK;
}

/* ---- stepping ---- */

static double max_change(const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

/* Largest move of a node that stores heat: zero-capacity (algebraic) nodes
 * such as the contact nodes jump to their new balance in any step, so they
 * must not drive the step-size control. */
static double max_change_stored(const acbb_tnet *net, const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++)
        if (acbb_tnet_capacity(net, i) > 0.0) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

/* Backward-Euler step with step rejection on large temperature moves. */
static acbb_status thermal_step(acbb_sim *sim, double *Tn, double *dT, double *dTs)
{
    int n = sim->nw.n;
    for (;;) {
        memcpy(Tn, sim->T, sizeof(double) * n);
        sim->work.network_solves++;
        acbb_status rc = acbb_tnet_step(sim->nw.net, sim->q, sim->dt, Tn);
        if (rc != ACBB_OK) return rc;
        *dT = max_change(Tn, sim->T, n);
        *dTs = max_change_stored(sim->nw.net, Tn, sim->T, n);
        if (*dTs <= DT_MAX_DT_K || sim->dt <= DT_MIN) return ACBB_OK;
        sim->dt = fmax(0.5 * sim->dt, DT_MIN);
    }
}

static acbb_status steady_step(acbb_sim *sim, double relax, double *Tn, double *dT)
{
    int n = sim->nw.n;
    sim->work.network_solves++;
    acbb_status rc = acbb_tnet_steady(sim->nw.net, sim->q, Tn);
    if (rc != ACBB_OK) return rc;
    /* Relaxed Picard (MODEL.md section 9). The steady solve's relaxation
     * is the polish's rule (steady_polish.h), not MODEL.md's fixed 0.5:
     * the map contracts about 25x per iteration on the 7008C, so 0.5
     * only slowed it (33 -> 11 iterations undamped, issue 30 lever 1),
     * and halving on a growing residual still damps an overshooting map. */
    for (int i = 0; i < n; i++) Tn[i] = sim->T[i] + relax * (Tn[i] - sim->T[i]);
    *dT = max_change(Tn, sim->T, n);
    return ACBB_OK;
}

/* After the transient has settled, iterate the direct steady solve so the
 * reported state balances energy to round-off (MODEL.md section 8.2). */
static void save(acbb_sim *sim, checkpoint *k);
static void restore(acbb_sim *sim, const checkpoint *k);

/* A transient with a [schedule] follows its rows (schedule.h); the steady
 * solve and an isothermal run take the last row once, in sim_init. */
static int follows_schedule(const acbb_sim *sim)
{
    return sim->s.schedule_n > 0 && sim->s.thermal_mode == ACBB_THERMAL_TRANSIENT
           && sim->s.heating;
}

/* The schedule's operating point at time t into sim->s. */
static void schedule_point(acbb_sim *sim, double t)
{
    if (!follows_schedule(sim)) return;
    acbb_operating op;
    acbb_schedule_at(&sim->s, t, &op);
    acbb_schedule_apply(&sim->s, &op);
}

/* The polish's state: the Sim, and the iterate of smallest residual so far
 * (kept when the polish does not converge). */
typedef struct {
    acbb_sim *sim;
    checkpoint *best;
    double best_res;
    double move[ACBB_MAX_NODES]; /* the last undamped move (acbb_polish_turn) */
} polish_ctx;

/* One polish iteration (steady_polish.h): the direct steady solve, the
 * move by `relax`, the evaluation there; a failed evaluation keeps the
 * last evaluated iterate. */
static acbb_status polish_step(void *ctx, double relax, double *res, double *turn,
                               acbb_error *err)
{
    polish_ctx *p = ctx;
    acbb_sim *sim = p->sim;
    double Tn[ACBB_MAX_NODES], dT = 0.0;
    acbb_status rc = acbb_simx_stop_check(sim, err);
    if (rc != ACBB_OK) return rc;
    rc = steady_step(sim, relax, Tn, &dT);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "steady solve failed");
    if (!acbb_snap_all_finite(Tn, sim->nw.n)) /* fmax in the residual drops a NaN */
        return acbb_error_set(err, ACBB_NONFINITE, "non-finite temperature in the steady "
                              "solve; last good state kept");
    *res = dT / relax; /* the undamped move (relax is 1 or a power of 1/2) */
    *turn = acbb_polish_turn(p->move, sim->T, Tn, relax, sim->nw.n);
    save(sim, sim->keep);
    if (*res < p->best_res) { /* *res is the residual of the state before the move */
        save(sim, p->best);
        p->best_res = *res;
    }
    memcpy(sim->T, Tn, sizeof(double) * sim->nw.n);
    sim->polishing = 1;
    sim->polish_relax = relax;
    rc = acbb_simx_evaluate(sim, err);
    sim->polishing = 0;
    sim->polish_relax = 1.0;
    if (rc != ACBB_OK) restore(sim, sim->keep);
    return rc;
}

/* Damped where it overshoots (issue 18), never OK unconverged: a polish
 * that does not converge ends the run ACBB_DIVERGED with the iterate of
 * smallest residual. */
static acbb_status polish(acbb_sim *sim, acbb_error *err)
{
    polish_ctx p = { sim, malloc(sizeof(checkpoint)), INFINITY, { 0 } };
    if (!p.best) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_polish_result r;
    acbb_status rc = acbb_polish_iterate(polish_step, &p,
                                         acbb_polish_resolution(acbb_polish_loss_rtol(&sim->s),
                                                                sim->T, sim->nw.n), &r, err);
    if (rc == ACBB_DIVERGED && r.iterations == ACBB_POLISH_ITERS && p.best_res < INFINITY) {
        restore(sim, p.best);
        size_t n = strlen(err->msg);
        snprintf(err->msg + n, sizeof err->msg - n, "; the iterate of smallest residual "
                 "(%.3g K) kept", p.best_res);
    }
    free(p.best);
    return rc;
}

static void finish_energy(acbb_sim *sim)
{
    sim->heat_out = sim->s.heating ? acbb_tnet_heat_to_fixed(sim->nw.net, sim->T) : 0.0;
}

static void save(acbb_sim *sim, checkpoint *k)
{
    acbb_mech_state_copy(&k->ms, &sim->ms);
    memcpy(k->T, sim->T, sizeof k->T);
    k->exp = sim->exp;
    memcpy(k->bl, sim->bl, sizeof sim->bl[0] * (size_t)sim->ms.n);
    k->loss = sim->loss;
    k->heat = sim->heat;
    memcpy(k->q, sim->q, sizeof k->q);
}

static void restore(acbb_sim *sim, const checkpoint *k)
{
    acbb_mech_state_copy(&sim->ms, &k->ms);
    memcpy(sim->T, k->T, sizeof k->T);
    sim->exp = k->exp;
    memcpy(sim->bl, k->bl, sizeof sim->bl[0] * (size_t)sim->ms.n);
    sim->loss = k->loss;
    sim->heat = k->heat;
    memcpy(sim->q, k->q, sizeof k->q);
    schedule_point(sim, sim->time); /* the kept state's; the mechanics follow when evaluated */
    acbb_net_inputs in;
    acbb_simx_network_inputs(sim, &in);
    acbb_network_update(&sim->nw, &sim->s, &in); /* resistances of the kept state */
}

/* Run-in schedule (MODEL.md 14; schedule.h): the operating point at time t.
 * acbb_mech binds the loads when made, so new loads get a new workspace,
 * warm-started from the last state, the displacement preload's dx held. */
static acbb_status follow_schedule(acbb_sim *sim, double t, acbb_error *err)
{
    if (!follows_schedule(sim)) return ACBB_OK;
    schedule_point(sim, t);
    const acbb_scene *s = &sim->s;
    if (s->axial_load == sim->bound_axial && s->radial_load == sim->bound_radial) return ACBB_OK;
    acbb_mech *m;
    acbb_status rc = acbb_mech_new(&sim->s, &m, err);
    if (rc != ACBB_OK) return rc;
    if (sim->s.preload == ACBB_PRELOAD_DISPLACEMENT) acbb_mech_fix_axial(m, 1, sim->ms.dx);
    acbb_mech_adopt_state(m, &sim->ms);
    acbb_mech_free(sim->mech);
    sim->mech = m;
    sim->bound_axial = s->axial_load;
    sim->bound_radial = s->radial_load;
    return ACBB_OK;
}

/* The transient does not step past a schedule row (a short ramp after a
 * long hold would be jumped), nor settle before the last row. */
static int schedule_done(acbb_sim *sim)
{
    if (!follows_schedule(sim)) return 1;
    acbb_operating op;
    acbb_schedule_at(&sim->s, sim->time, &op);
    if (op.finished) return 1;
    double next = sim->s.schedule[op.row].t;
    sim->dt = fmin(sim->dt, fmax(next - sim->time, DT_MIN));
    return 0;
}

/* Thermal update to T^{k+1} and the evaluation there. A transient step whose
 * total loss moves more than 5 % is rejected and retried with half the step
 * (MODEL.md section 9); *dT, *dTs report the accepted move. */
static acbb_status advance(acbb_sim *sim, int steady_mode, double *dT, double *dTs,
                           acbb_error *err)
{
    double Tn[ACBB_MAX_NODES];
    save(sim, sim->keep);
    for (;;) {
        /* each retry evaluates again (issue 26 item 7; the state is the kept one here) */
        acbb_status rc = acbb_simx_stop_check(sim, err);
        if (rc != ACBB_OK) return rc;
        double w = sim->steady_relax.relax;
        rc = steady_mode ? steady_step(sim, w, Tn, dT) : thermal_step(sim, Tn, dT, dTs);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "thermal network: %s", acbb_status_name(rc));
        if (!acbb_snap_all_finite(Tn, sim->nw.n))
            return acbb_error_set(err, ACBB_NONFINITE,
                                  "non-finite temperature caught; last good state kept");
        memcpy(sim->T, Tn, sizeof(double) * sim->nw.n);
        sim->transient_pass = !steady_mode;
        rc = follow_schedule(sim, sim->time + (steady_mode ? 0.0 : sim->dt), err);
        if (rc == ACBB_OK) rc = acbb_simx_evaluate(sim, err);
        sim->transient_pass = 0;
        if (rc != ACBB_OK) {
            restore(sim, sim->keep);
            if (steady_mode && acbb_relax_reject(&sim->steady_relax, rc)) continue;
            return rc;
        }
        if (steady_mode) acbb_relax_judge(&sim->steady_relax, w, *dT / w, 0.0);
        double dP = fabs(sim->loss.total - sim->keep->loss.total) / fmax(sim->loss.total, 1e-12);
        if (steady_mode || dP <= 0.05 || sim->dt <= DT_MIN)
            return ACBB_OK;
        restore(sim, sim->keep);
        sim->dt = fmax(0.5 * sim->dt, DT_MIN);
    }
}

/* Axial stiffness dFx/d(delta_x) at the converged state: central
 * difference with the axial displacement held, the other ring freedoms
 * free, ball speeds and tractions as converged. NAN if a solve fails (the
 * snapshot reports it missing: acbb_snap_stiffness). */
static double axial_stiffness(acbb_sim *sim)
{
    acbb_mech_state *st = malloc(sizeof *st);
    if (!st) return NAN;
    double dx = sim->ms.dx, h = fmax(1e-9, 1e-4 * fabs(dx)), F[2] = { 0, 0 };
    acbb_status rc = ACBB_OK;
    for (int k = 0; k < 2 && rc == ACBB_OK; k++) {
        acbb_mech_state_copy(st, &sim->ms);
        acbb_mech_fix_axial(sim->mech, 1, dx + (k ? -h : h));
        rc = acbb_mech_solve(sim->mech, sim->s.inner_speed, &sim->exp, st, NULL);
        F[k] = st->Fx;
    }
    int held = sim->s.preload == ACBB_PRELOAD_DISPLACEMENT;
    acbb_mech_fix_axial(sim->mech, held, held ? dx : 0.0);
    free(st);
    double K = (F[0] - F[1]) / (2.0 * h);
    return rc == ACBB_OK && isfinite(K) ? K : NAN;
}

/* A steady state is one whose network balances its sources (MODEL.md 12
 * item 18): otherwise the run fails with ACBB_UNBALANCED and keeps the
 * state it reached. Heating off solves no network: no heat flows. */
static int unbalanced(acbb_sim *sim)
{
    if (!sim->s.heating) return 0;
    double in = sim->heat.inner_contact + sim->heat.outer_contact + sim->heat.ball
              + sim->heat.cavity + sim->heat.cage;
    acbb_error err = { "" };
    if (acbb_balance_check(in, sim->heat_out, &err) == ACBB_OK) return 0;
    fail(sim, ACBB_UNBALANCED, "%s", err.msg);
    return 1;
}

/* The end-of-run stiffness, unless the caller asked for none (then
 * reported missing: acbb_sim_opts.skip_stiffness). */
static void stiffness(acbb_sim *sim)
{
    if (sim->skip_stiffness) {
        sim->K_axial = NAN;
        sim->K_ring = (acbb_stiffness){ NAN, NAN, NAN };
        return;
    }
    sim->K_axial = axial_stiffness(sim);
    acbb_ring_stiffness(&sim->s, &sim->exp, sim->ms.dx, &sim->ms, &sim->K_ring);
}

static void converge(acbb_sim *sim, const char *what)
{
    finish_energy(sim);
    if (unbalanced(sim)) return;
    stiffness(sim);
    sim->state = ACBB_RUN_CONVERGED;
    snprintf(sim->msg, sizeof sim->msg, "%s", what);
}

/* effects.heating = off: temperatures stay at ambient, so one converged
 * mechanics (and Level-2) state is the answer; no network is solved. */
static acbb_status isothermal(acbb_sim *sim)
{
    acbb_error err = { "" };
    for (int it = 0; it < ISO_ITERS; it++) {
        double prev = sim->loss.total;
        acbb_status rc = acbb_simx_evaluate(sim, &err);
        if (rc != ACBB_OK)
            return fail(sim, rc, "%s", err.msg[0] ? err.msg : acbb_status_name(rc));
        sim->iter++;
        if (fabs(sim->loss.total - prev) <= 1e-12 * fmax(sim->loss.total, 1e-12)) break;
    }
    converge(sim, "isothermal mechanics at ambient (effects.heating = off)");
    return ACBB_OK;
}

/* A set steps in sim_set.c; the run loop reads its outcome here. */
static acbb_status set_step(acbb_sim *sim)
{
    acbb_status rc = acbb_set_sim_step(sim->set);
    sim->state = acbb_set_sim_outcome(sim->set, &sim->status, &sim->iter);
    return rc;
}

static acbb_status step_body(acbb_sim *sim)
{
    if (sim->state != ACBB_RUN_RUNNING)
        return sim->status;
    if (sim->set) {
        arm_bound(sim);
        acbb_set_sim_deadline(sim->set, sim->deadline_ms);
        double t0 = acbb_now_ms();
        acbb_status rc = set_step(sim);
        sim->wall_ms += acbb_now_ms() - t0; /* for wall_limit; the set reports its own */
        return rc;
    }
    arm_bound(sim);
    double t0 = acbb_now_ms();
    if (!sim->s.heating) {
        acbb_status rc = isothermal(sim);
        sim->wall_ms += acbb_now_ms() - t0;
        return rc;
    }
    acbb_error err = { "" };
    double dT = 0.0, dTs = 0.0;
    int steady_mode = sim->s.thermal_mode == ACBB_THERMAL_STEADY;
    int scheduled = !schedule_done(sim);
    acbb_status rc = advance(sim, steady_mode, &dT, &dTs, &err);
    if (rc != ACBB_OK) {
        sim->wall_ms += acbb_now_ms() - t0;
        return fail(sim, rc, "%s", err.msg[0] ? err.msg : acbb_status_name(rc));
    }
    double step_dt = steady_mode ? 1.0 : sim->dt;
    sim->iter++;
    if (!steady_mode) sim->time += sim->dt;
    sim->residual = dT / step_dt;
    /* The growth detector of MODEL.md 9 is for a fixed operating point; while
     * a schedule moves it the reaction grows by design (the temperature and
     * pressure limits stay on). */
    if (scheduled) sim->growth_count = 0;
    if ((rc = check_runaway(sim, sim->T, steady_mode ? 0.0 : step_dt)) != ACBB_OK) {
        sim->wall_ms += acbb_now_ms() - t0;
        return rc;
    }
    double dP = fabs(sim->loss.total - sim->prev_total) / fmax(sim->loss.total, 1e-12);
    sim->prev_total = sim->loss.total;
    int quiet = steady_mode ? dT < ACBB_STEADY_QUIET_K && dP < 1e-9
                            : sim->residual < sim->s.steady_tol && dP < 1e-4;
    sim->quiet = quiet && !scheduled ? sim->quiet + 1 : 0;
    /* Grow while the losses barely move and nodes move < 0.5 K. */
    if (!steady_mode && dP < 0.005 && dTs < 0.25 * DT_MAX_DT_K)
        sim->dt = fmin(1.5 * sim->dt, DT_MAX);
    if (sim->quiet >= (steady_mode ? 3 : STEADY_COUNT)) {
        rc = polish(sim, &err);
        if (rc != ACBB_OK) {
            finish_energy(sim); /* energy_W of the state kept */
            sim->wall_ms += acbb_now_ms() - t0;
            return fail(sim, rc, "%s", err.msg);
        }
        char what[64];
        snprintf(what, sizeof what, "thermal steady state after %ld steps", sim->iter);
        converge(sim, what);
    } else if (sim->iter >= sim->s.max_steps || sim->time >= sim->s.max_time) {
        finish_energy(sim);
        sim->wall_ms += acbb_now_ms() - t0;
        char d[96];
        snprintf(d, sizeof d, "%ld steps, %.0f s simulated", sim->iter, sim->time);
        return fail(sim, ACBB_NOT_CONVERGED,
                    "no steady state within the limits (%s); raise thermal.max_steps or thermal.max_time_s", d);
    }
    finish_energy(sim);
    sim->wall_ms += acbb_now_ms() - t0;
    return ACBB_OK;
}

/* The public entry points bracket GSL (gsl_quiet.h): the handler is off
 * while they work and the host's again when they return. */
acbb_status acbb_sim_step(acbb_sim *sim)
{
    acbb_gsl_enter();
    acbb_status rc = step_body(sim);
    acbb_gsl_leave();
    return rc;
}

acbb_run_state acbb_sim_state(const acbb_sim *sim) { return sim->state; }

acbb_status acbb_sim_run(acbb_sim *sim)
{
    return acbb_sim_drive(sim, NULL);
}

static int call_hook(acbb_sim *sim, const acbb_run_ctl *ctl)
{
    if (!ctl || !ctl->hook || sim->iter == sim->reported) return 0;
    sim->reported = sim->iter;
    return ctl->hook(ctl->ctx, sim);
}

/* fidelity.max_wall_s (issue 20 item 8): the set-up's and the steps' own
 * computing time (hooks and pauses excluded) past the bound ends the run
 * with the last step's state (a step cut short inside rolls back to it).
 * Read only when a bound is set, so without one nothing depends on timing. */
static int wall_limit(acbb_sim *sim)
{
    if (sim->s.max_wall_s <= 0 || sim->state != ACBB_RUN_RUNNING ||
        sim->setup_ms + sim->wall_ms < 1e3 * sim->s.max_wall_s)
        return 0;
    fail(sim, ACBB_WALL_LIMIT, "%s", "");
    return 1;
}

static acbb_status drive_body(acbb_sim *sim, const acbb_run_ctl *ctl)
{
    if (ctl && ctl->cancel) {
        sim->cancel = ctl->cancel;
        if (sim->dyn) acbb_dyn_set_cancel(sim->dyn, sim->cancel);
        if (sim->set) acbb_set_sim_cancel(sim->set, sim->cancel);
    }
    if (call_hook(sim, ctl)) return sim->status;
    while (sim->state == ACBB_RUN_RUNNING) {
        if (acbb_cancelled(sim->cancel))
            return fail(sim, ACBB_CANCELLED, "%s", "cancelled; last good state kept");
        step_body(sim);
        if (wall_limit(sim)) break;
        if (call_hook(sim, ctl)) break;
    }
    return sim->status;
}

acbb_status acbb_sim_drive(acbb_sim *sim, const acbb_run_ctl *ctl)
{
    acbb_gsl_enter();
    acbb_status rc = drive_body(sim, ctl);
    acbb_gsl_leave();
    return rc;
}

/* ---- set-up ---- */

static acbb_status check_supported(const acbb_scene *s, acbb_error *err)
{
    if (s->n_balls > ACBB_MAX_BALLS)
        return acbb_error_set(err, ACBB_EINVAL, "bearing.n_balls = %d: at most %d supported",
                              s->n_balls, ACBB_MAX_BALLS);
    return ACBB_OK;
}

/* Displacement preload: fix dx at the value the preload force gives at
 * zero speed and room temperature (MODEL.md section 1), from the preload
 * alone: the radial load and moment come on afterwards, against the
 * fixed ring. */
static acbb_status fix_preload(acbb_sim *sim, acbb_error *err)
{
    acbb_scene s0 = sim->s;
    s0.axial_load = s0.preload_force;
    s0.radial_load = 0.0;
    s0.moment_load = 0.0;
    s0.inner_speed = 0.0;
    s0.preload = ACBB_PRELOAD_FORCE;
    acbb_mech *m0;
    acbb_status rc = acbb_mech_new(&s0, &m0, err);
    if (rc != ACBB_OK) return rc;
    acbb_mech_state st;
    rc = acbb_mech_init_state(m0, &st, err);
    acbb_mech_free(m0);
    if (rc != ACBB_OK) return rc;
    acbb_mech_fix_axial(sim->mech, 1, st.dx);
    return ACBB_OK;
}

/* Room-temperature mechanics at speed, reached by continuation in speed. */
static acbb_status initial_mechanics(acbb_sim *sim, acbb_error *err)
{
    acbb_status rc = acbb_mech_init_state(sim->mech, &sim->ms, err);
    if (rc != ACBB_OK) return rc;
    for (int k = 1; k <= 4 && sim->s.inner_speed > 0.0; k++) {
        sim->work.mechanics_solves++;
        rc = acbb_mech_solve(sim->mech, sim->s.inner_speed * k / 4.0, NULL, &sim->ms, err);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

static acbb_status sim_init(acbb_sim *sim, const acbb_scene *s, const double *T_warm,
                            acbb_error *err)
{
    sim->s = *s;
    /* fidelity.preset / target_error_pct override the knobs (fidelity.h). */
    acbb_fidelity_apply(&sim->s, NULL);
    acbb_lubricant_apply(&sim->s);
    s = &sim->s;
    acbb_life_static_basis(s, &sim->life_basis); /* once per scene, not per snapshot */
    double t0 = acbb_now_ms();
    arm_bound(sim); /* the set-up counts against fidelity.max_wall_s */
    acbb_operating op; /* schedule.h: the first row, or the last for the steady solve */
    if (s->thermal_mode == ACBB_THERMAL_STEADY || !s->heating) acbb_schedule_final(s, &op);
    else acbb_schedule_at(s, 0.0, &op);
    acbb_schedule_apply(&sim->s, &op);
    sim->bound_axial = op.axial_load;
    sim->bound_radial = op.radial_load;
    acbb_status rc = acbb_lubricant_explain(s, acbb_scene_validate(s, err), err);
    if (rc != ACBB_OK) return rc;
    if ((rc = check_supported(s, err)) != ACBB_OK) return rc;
    if ((rc = acbb_quad_init(&sim->quad, s->contact_grid)) != ACBB_OK)
        return acbb_error_set(err, rc, "fidelity.contact_grid = %d: 1..%d", s->contact_grid,
                              ACBB_QUAD_MAX);
    if ((rc = acbb_network_build(s, &sim->nw, err)) != ACBB_OK) return rc;
    if ((rc = acbb_mech_new(s, &sim->mech, err)) != ACBB_OK) return rc;
    if (s->model == ACBB_MODEL_QUASI_DYNAMIC && acbb_qd_new(s->contact_grid, &sim->qd) != ACBB_OK)
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (s->model == ACBB_MODEL_DYNAMIC && (acbb_dyn_new(s->contact_grid, &sim->dyn) != ACBB_OK
                                           || acbb_dyn_set_threads(sim->dyn, sim->threads)
                                                  != ACBB_OK))
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (sim->dyn) acbb_dyn_set_cancel(sim->dyn, sim->cancel);
    arm_bound(sim); /* now that the dynamic workspace exists */
    if (s->preload == ACBB_PRELOAD_DISPLACEMENT && (rc = fix_preload(sim, err)) != ACBB_OK)
        return rc;
    for (int i = 0; i < sim->nw.n; i++)
        sim->T[i] = T_warm ? T_warm[i] : s->ambient_C;
    if ((rc = initial_mechanics(sim, err)) == ACBB_OK) rc = acbb_simx_evaluate(sim, err);
    sim->setup_ms = acbb_now_ms() - t0;
    if (rc == ACBB_WALL_LIMIT) /* no state yet: nothing to keep */
        return acbb_error_set(err, rc, "wall-clock bound fidelity.max_wall_s = %g s reached "
                              "during the set-up, before the first state", s->max_wall_s);
    if (rc != ACBB_OK) return rc;
    sim->dt = s->time_step;
    acbb_relax_start(&sim->steady_relax);
    sim->reported = -1;
    sim->state = ACBB_RUN_RUNNING;
    sim->status = ACBB_OK;
    sim->prev_total = sim->loss.total;
    sim->prev_Fx = sim->ms.Fx;
    finish_energy(sim);
    snprintf(sim->msg, sizeof sim->msg, "running");
    return ACBB_OK;
}

static void sim_release(acbb_sim *sim)
{
    acbb_mech_free(sim->mech);
    sim->mech = NULL;
    acbb_qd_free(sim->qd);
    sim->qd = NULL;
    acbb_dyn_free(sim->dyn);
    sim->dyn = NULL;
    if (sim->nw.net) acbb_network_free(&sim->nw);
    sim->nw.net = NULL;
}

acbb_status acbb_sim_new(const acbb_scene *s, acbb_sim **out, acbb_error *err)
{
    return acbb_sim_new_ctl(s, NULL, out, err);
}

acbb_status acbb_sim_new_ctl(const acbb_scene *s, const atomic_int *cancel, acbb_sim **out,
                             acbb_error *err)
{
    return acbb_sim_create(s, &(acbb_sim_opts){ .cancel = cancel }, out, err);
}

/* A bearing set: its members and stepper live in sim_set.c. */
static acbb_status set_init(acbb_sim *sim, const acbb_scene *s, acbb_error *err)
{
    sim->s = *s;
    acbb_life_static_basis(s, &sim->life_basis);
    acbb_sim_opts o = { sim->cancel, sim->threads, sim->skip_stiffness };
    acbb_status rc = acbb_set_sim_new(s, &o, &sim->set, err);
    if (rc != ACBB_OK) return rc;
    sim->state = acbb_set_sim_outcome(sim->set, &sim->status, &sim->iter);
    sim->reported = -1;
    return ACBB_OK;
}

static acbb_status create_body(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                               acbb_error *err)
{
    acbb_sim *sim = calloc(1, sizeof *sim);
    if (!sim || !(sim->keep = malloc(sizeof *sim->keep))) {
        free(sim);
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    }
    sim->cancel = o->cancel;
    sim->polish_relax = 1.0;
    sim->threads = o->threads > 0 ? o->threads : DYN_THREADS;
    sim->skip_stiffness = o->skip_stiffness;
    double t0 = acbb_now_ms();
    acbb_status rc = s->set_arrangement != ACBB_SET_SINGLE ? set_init(sim, s, err)
                                                           : sim_init(sim, s, NULL, err);
    if (sim->set) sim->setup_ms = acbb_now_ms() - t0; /* sim_init times its own */
    if (rc != ACBB_OK) {
        acbb_sim_free(sim);
        return rc;
    }
    *out = sim;
    return ACBB_OK;
}

acbb_status acbb_sim_create(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                            acbb_error *err)
{
    acbb_gsl_enter();
    acbb_status rc = create_body(s, o, out, err);
    acbb_gsl_leave();
    return rc;
}

void acbb_sim_free(acbb_sim *sim)
{
    if (!sim) return;
    acbb_set_sim_free(sim->set);
    sim_release(sim);
    free(sim->keep);
    free(sim);
}

/* A set, or a change to or from one, restarts cold with a new Sim. */
static acbb_status set_restart(acbb_sim *sim, const acbb_scene *s, acbb_error *err)
{
    acbb_sim *fresh;
    acbb_sim_opts o = { sim->cancel, sim->threads, sim->skip_stiffness };
    acbb_status rc = acbb_sim_create(s, &o, &fresh, err);
    if (rc != ACBB_OK) return rc; /* the running sim is untouched */
    acbb_sim old = *sim;
    *sim = *fresh;
    *fresh = old;
    acbb_sim_free(fresh);
    arm_bound(sim); /* as in acbb_sim_restart */
    return ACBB_OK;
}

static acbb_status restart_body(acbb_sim *sim, const acbb_scene *s, int warm, acbb_error *err)
{
    if (sim->set || s->set_arrangement != ACBB_SET_SINGLE) return set_restart(sim, s, err);
    double T[ACBB_MAX_NODES];
    int keep = warm && s->network == sim->s.network;
    memcpy(T, sim->T, sizeof T);
    acbb_sim *fresh = calloc(1, sizeof *fresh);
    if (!fresh) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    fresh->cancel = sim->cancel;
    fresh->threads = sim->threads;
    fresh->skip_stiffness = sim->skip_stiffness;
    acbb_status rc = sim_init(fresh, s, keep ? T : NULL, err);
    if (rc != ACBB_OK) {
        sim_release(fresh);
        free(fresh);
        return rc; /* the running sim is untouched */
    }
    sim_release(sim);
    fresh->keep = sim->keep; /* the rollback scratch stays with the Sim */
    *sim = *fresh;
    free(fresh);
    arm_bound(sim); /* the dynamic workspace's bound reads this Sim, not `fresh` */
    return ACBB_OK;
}

acbb_status acbb_sim_restart(acbb_sim *sim, const acbb_scene *s, int warm, acbb_error *err)
{
    acbb_gsl_enter();
    acbb_status rc = restart_body(sim, s, warm, err);
    acbb_gsl_leave();
    return rc;
}

/* ---- snapshot (the per-ball and squeeze views: sim_snapshot.c) ---- */

void acbb_sim_snapshot(const acbb_sim *sim, acbb_snapshot *o)
{
    const acbb_network *nw = &sim->nw;
    if (sim->set) {
        acbb_set_sim_snapshot(sim->set, o);
        if ((sim->status == ACBB_CANCELLED || sim->status == ACBB_WALL_LIMIT)
            && o->state == ACBB_RUN_RUNNING) {
            /* ended by the run loop (cancel, wall-clock bound), not the set */
            o->state = sim->state;
            o->status = sim->status;
            snprintf(o->message, sizeof o->message, "%s", sim->msg);
        }
        return;
    }
    memset(o, 0, sizeof *o);
    o->state = sim->state;
    o->status = sim->status;
    snprintf(o->message, sizeof o->message, "%s", sim->msg);
    o->iteration = sim->iter;
    o->time = sim->time;
    o->dt = sim->dt;
    o->residual = acbb_snap_fin(sim->residual);
    o->wall_ms = sim->wall_ms;
    o->n_nodes = nw->n;
    o->node_names = nw->names;
    for (int i = 0; i < nw->n; i++) o->T[i] = acbb_snap_fin(sim->T[i]);
    acbb_part_temps pt;
    acbb_network_part_temps(nw, sim->T, &pt);
    o->T_outer_ring = acbb_snap_fin(sim->T[nw->node_outer_ring]);
    o->T_inner_ring = acbb_snap_fin(pt.inner_ring);
    o->T_ball = acbb_snap_fin(pt.ball);
    o->T_housing = acbb_snap_fin(pt.housing);
    o->T_shaft = acbb_snap_fin(pt.shaft);
    o->T_cavity = acbb_snap_fin(sim->T[nw->node_cavity]);
    const acbb_losses *L = &sim->loss;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) o->losses.P[l] = acbb_snap_fin(L->P[l]);
    o->losses.total = acbb_snap_fin(L->total);
    o->losses.inner = acbb_snap_fin(L->inner);
    o->losses.outer = acbb_snap_fin(L->outer);
    o->exp_ball = acbb_snap_fin(sim->exp.ball);
    o->exp_inner = acbb_snap_fin(sim->exp.inner);
    o->exp_inner_cen = acbb_snap_fin(sim->exp.inner_cen);
    o->exp_outer = acbb_snap_fin(sim->exp.outer);
    o->delta_x = acbb_snap_fin(sim->ms.dx);
    o->delta_z = acbb_snap_fin(sim->ms.dz);
    o->tilt_y = acbb_snap_fin(sim->ms.thy);
    o->stiffness_axial = acbb_snap_fin(sim->K_axial);
    o->stiffness_radial = acbb_snap_fin(sim->K_ring.radial);
    o->stiffness_tilt = acbb_snap_fin(sim->K_ring.tilt);
    o->stiffness_tilt_held = acbb_snap_fin(sim->K_ring.tilt_held);
    o->stiffness_failed = (isnan(sim->K_axial) ? ACBB_STIFF_AXIAL : 0u)
                        | (isnan(sim->K_ring.radial) ? ACBB_STIFF_RADIAL : 0u)
                        | (isnan(sim->K_ring.tilt) ? ACBB_STIFF_TILT : 0u)
                        | (isnan(sim->K_ring.tilt_held) ? ACBB_STIFF_TILT_HELD : 0u);
    o->work = sim->work;
    acbb_snap_squeeze(&sim->exp, &sim->ms.ball[0], &o->squeeze);
    o->reaction_x = acbb_snap_fin(sim->ms.Fx);
    o->heat_in = sim->s.heating ? acbb_snap_fin(sim->heat.inner_contact + sim->heat.outer_contact
                                                + sim->heat.ball + sim->heat.cavity + sim->heat.cage)
                                : 0.0; /* no network: no heat flows (finish_energy) */
    o->heat_out = acbb_snap_fin(sim->heat_out);
    o->n_balls = sim->ms.n;
    for (int j = 0; j < sim->ms.n; j++)
        acbb_snap_ball_view(&sim->ms.ball[j], &sim->bl[j].in, &sim->bl[j].out, &o->balls[j]);
    acbb_life_compute_with(&sim->s, o, &sim->life_basis, &o->life);
    o->n_bearings = 1;
}

acbb_status acbb_sim_bearing_snapshot(const acbb_sim *sim, int k, acbb_snapshot *out)
{
    if (sim->set) return acbb_set_sim_bearing_snapshot(sim->set, k, out);
    if (k != 0) return ACBB_EINVAL;
    acbb_sim_snapshot(sim, out);
    return ACBB_OK;
}

/* ---- a bearing of a set (sim_set.c drives it; MODEL.md 14) ---- */

acbb_mech *acbb_simm_mech(acbb_sim *b) { return b->mech; }
acbb_mech_state *acbb_simm_ms(acbb_sim *b) { return &b->ms; }
const acbb_expansion *acbb_simm_exp(const acbb_sim *b) { return &b->exp; }
double *acbb_simm_T(acbb_sim *b) { return b->T; }
acbb_network *acbb_simm_network(acbb_sim *b) { return &b->nw; }
const double *acbb_simm_q(const acbb_sim *b) { return b->q; }
int acbb_simm_has_traction(const acbb_sim *b) { return b->qd || b->dyn; }
double acbb_simm_loss(const acbb_sim *b) { return b->loss.total; }
/* The set's operating point (its schedule, sim_set.c): b's inner-ring speed. */
void acbb_simm_speed(acbb_sim *b, double inner_speed) { b->s.inner_speed = inner_speed; }

void acbb_simm_deadline(acbb_sim *b, double deadline_ms)
{
    b->deadline_ms = deadline_ms;
    if (b->dyn) acbb_dyn_set_stop(b->dyn, deadline_ms > 0.0 ? past_bound : NULL, b);
}

void acbb_simm_mode(acbb_sim *b, int transient, int polishing)
{
    b->transient_pass = transient;
    b->polishing = polishing;
}

void acbb_simm_save(acbb_sim *b) { save(b, b->keep); }
void acbb_simm_restore(acbb_sim *b) { restore(b, b->keep); }

/* The run's outcome and b's stiffness, for b's own snapshot. */
void acbb_simm_publish(acbb_sim *b, const acbb_set_run *r)
{
    b->state = r->state;
    b->status = r->status;
    b->iter = r->iter;
    b->time = r->time;
    b->dt = r->dt;
    b->residual = r->residual;
    b->wall_ms = r->wall_ms;
    snprintf(b->msg, sizeof b->msg, "%s", r->msg);
    b->heat_out = acbb_tnet_heat_to_fixed(b->nw.net, b->T);
}

void acbb_simm_stiffness(acbb_sim *b, double *K_axial)
{
    stiffness(b);
    *K_axial = b->K_axial;
}
