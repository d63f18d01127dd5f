/* acbb — the coupled stepper of a bearing set (MODEL.md section 14;
 * sim_set.h). One step, as sim.c's for one bearing (MODEL.md 9): every
 * bearing's expansions from its own temperatures and the spacers' axial
 * growth -> the shaft equilibrium over all bearings (set_mech.h), at the
 * quasi-dynamic and dynamic levels alternated with each bearing's ball
 * speeds -> each bearing's losses -> one backward-Euler step of the joined
 * network. Step control, steady detection and the final direct steady
 * polish are sim.c's (same constants). The probes of the converged state
 * are in sim_set_probe.c, the snapshots in sim_set_view.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sim_set_priv.h"
#include "sim_priv.h"
#include "acbb/set.h"
#include "acbb/measure.h"
#include "acbb/fidelity.h"
#include "acbb/schedule.h"
#include "cancel.h"
#include "steady_polish.h"

#define DT_MIN 0.05
#define DT_MAX 30.0
#define DT_MAX_DT_K 2.0
#define STEADY_COUNT 20
#define PMAX_LIMIT 4.2e9
#define ISO_ITERS 60
#define QD_PASSES 4
#define QD_TOL 1e-9
#define SYNC_TOL 1e-2        /* transient steps: resistances lag below this move (network_set.h) */

/* ---- one evaluation at the joined temperatures T ---- */

void acbb_set_members(acbb_set_sim *ss, acbb_set_member *mb)
{
    for (int k = 0; k < ss->n; k++)
        mb[k] = (acbb_set_member){ acbb_simm_mech(ss->b[k]), acbb_simm_ms(ss->b[k]),
                                   acbb_simm_exp(ss->b[k]) };
}

acbb_status acbb_set_solve_shaft(acbb_set_sim *ss, acbb_error *err)
{
    acbb_set_member mb[ACBB_MAX_SET];
    acbb_set_members(ss, mb);
    return acbb_set_mech_solve(&ss->sm, mb, ss->s.inner_speed, err);
}

/* Axial growth of the inner path (inner spacer L_s of the spacer material,
 * the rest of the gap a shaft collar, inner-ring halves) minus the outer
 * path (outer spacer L_h, the rest housing, outer-ring halves) between
 * neighbouring centres moves the inner rings against the outer rings
 * (MODEL.md 14 Delta_ax; spacers at the shaft's / housing's mean
 * temperature); the set's centre is the reference (the shaft's dx takes
 * any common move). */
static double path_growth(double chi_sp, double chi_rest, double L_sp, double gap, double dT)
{
    return (chi_sp * L_sp + chi_rest * (gap - L_sp)) * dT;
}

static void spacer_growth(acbb_set_sim *ss)
{
    const acbb_scene *s = &ss->s;
    double u[ACBB_MAX_SET] = { 0 }, mean = 0.0, L_in, L_out;
    double gap = acbb_set_pitch(s) - s->width, h = 0.5 * s->width;
    acbb_set_spacers(s, &L_in, &L_out);
    double chi_in = s->set_spacer_chi > 0.0 ? s->set_spacer_chi : s->shaft.chi;
    double chi_out = s->set_spacer_chi > 0.0 ? s->set_spacer_chi : s->housing.chi;
    acbb_part_temps p[ACBB_MAX_SET];
    for (int k = 0; k < ss->n; k++)
        acbb_network_part_temps(acbb_simm_network(ss->b[k]), acbb_simm_T(ss->b[k]), &p[k]);
    for (int k = 1; k < ss->n && s->thermal_expansion; k++) {
        const acbb_part_temps *a = &p[k - 1], *c = &p[k];
        double T0 = s->ambient_C;
        double in = path_growth(chi_in, s->shaft.chi, L_in, gap, 0.5 * (a->shaft + c->shaft) - T0)
                  + s->ring.chi * (a->inner_ring + c->inner_ring - 2.0 * T0) * h;
        double out = path_growth(chi_out, s->housing.chi, L_out, gap,
                                 0.5 * (a->housing + c->housing) - T0)
                   + s->ring.chi * (a->outer_ring + c->outer_ring - 2.0 * T0) * h;
        u[k] = u[k - 1] + in - out;
    }
    for (int k = 0; k < ss->n; k++) mean += u[k] / ss->n;
    for (int k = 0; k < ss->n; k++) ss->sm.u[k] = u[k] - mean;
    ss->spacer = u[ss->n - 1];
}

/* The caller's cancel flag, then fidelity.max_wall_s (the deadline the run
 * loop armed for this step, sim.c arm_bound), checked in every loop of a
 * step that can run long (issue 26 item 7). */
static acbb_status stop_check(const acbb_set_sim *ss, acbb_error *err)
{
    if (acbb_cancelled(ss->cancel))
        return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
    if (ss->deadline_ms > 0.0 && acbb_now_ms() >= ss->deadline_ms)
        return acbb_error_set(err, ACBB_WALL_LIMIT, "wall-clock bound fidelity.max_wall_s = "
                              "%g s reached; last good state kept", ss->s.max_wall_s);
    return ACBB_OK;
}

/* Shaft equilibrium, alternated with the ball speeds at the quasi-dynamic
 * and dynamic levels (sim.c mechanics(): one pass inside transient steps,
 * up to QD_PASSES otherwise). */
static acbb_status mechanics(acbb_set_sim *ss, int transient, acbb_error *err)
{
    int traction = acbb_simm_has_traction(ss->b[0]);
    int warm = traction && transient && acbb_simm_ms(ss->b[0])->ball[0].traction_valid;
    acbb_status rc = warm ? ACBB_OK : acbb_set_solve_shaft(ss, err);
    if (rc != ACBB_OK || !traction) return rc;
    for (int pass = 0; pass < (transient ? 1 : QD_PASSES); pass++) {
        double change = 0.0;
        if ((rc = stop_check(ss, err)) != ACBB_OK) return rc;
        for (int k = 0; k < ss->n; k++) {
            double ch;
            if ((rc = acbb_simm_traction(ss->b[k], &ch, err)) != ACBB_OK) return rc;
            change = fmax(change, ch);
        }
        if ((rc = acbb_set_solve_shaft(ss, err)) != ACBB_OK || change < QD_TOL) return rc;
    }
    return ACBB_OK;
}

static void distribute(acbb_set_sim *ss)
{
    for (int k = 0; k < ss->n; k++)
        memcpy(acbb_simm_T(ss->b[k]), ss->T + ss->ns.off[k],
               sizeof(double) * (size_t)acbb_simm_network(ss->b[k])->n);
}

static void gather_heat(acbb_set_sim *ss, double rel_tol)
{
    ss->heat_in = ss->total = 0.0;
    for (int k = 0; k < ss->n; k++) {
        const acbb_network *nw = acbb_simm_network(ss->b[k]);
        memcpy(ss->q + ss->ns.off[k], acbb_simm_q(ss->b[k]), sizeof(double) * (size_t)nw->n);
        for (int i = 0; i < nw->n; i++) ss->heat_in += acbb_simm_q(ss->b[k])[i];
        ss->total += acbb_simm_loss(ss->b[k]);
    }
    acbb_network_set_sync(&ss->ns, rel_tol);
}

static acbb_status evaluate(acbb_set_sim *ss, int transient, int polishing, acbb_error *err)
{
    distribute(ss);
    for (int k = 0; k < ss->n; k++) {
        acbb_simm_mode(ss->b[k], transient, polishing);
        acbb_simm_expand(ss->b[k]);
    }
    spacer_growth(ss);
    acbb_status rc = mechanics(ss, transient, err);
    for (int k = 0; k < ss->n && rc == ACBB_OK; k++) rc = acbb_simm_heat(ss->b[k], err);
    for (int k = 0; k < ss->n; k++) acbb_simm_mode(ss->b[k], 0, 0);
    if (rc != ACBB_OK) return rc;
    gather_heat(ss, transient ? SYNC_TOL : 0.0);
    return ACBB_OK;
}

static void converge(acbb_set_sim *ss, const char *what)
{
    ss->K_ax = 0.0;
    for (int k = 0; k < ss->n; k++) {
        double K;
        acbb_simm_stiffness(ss->b[k], &K);
        if (!(ss->sm.spring && ss->sm.orient[k] < 0)) ss->K_ax += K; /* a spring side floats */
    }
    acbb_set_solve_shaft(ss, NULL); /* the stiffness probes moved the workspaces */
    acbb_set_nose_stiffness(ss);
    ss->preload = acbb_set_preload_now(ss);
    ss->liftoff = acbb_set_liftoff(ss, 0.0); /* from the live one (publish) */
    ss->run.state = ACBB_RUN_CONVERGED;
    snprintf(ss->run.msg, sizeof ss->run.msg, "%s", what);
}

/* ---- run-in schedule (MODEL.md 14; schedule.h), as sim.c's for one bearing ---- */

/* A transient with rows follows them; the steady solve and an isothermal
 * run take the last row once, at set-up. */
static int follows_schedule(const acbb_set_sim *ss)
{
    return ss->s.schedule_n > 0 && ss->s.thermal_mode == ACBB_THERMAL_TRANSIENT && ss->s.heating;
}

/* op's speed and loads into the set's scene, its shaft loads and every
 * bearing's speed (the members are prescribed: no loads of their own). */
static void operating_apply(acbb_set_sim *ss, const acbb_operating *op)
{
    acbb_schedule_apply(&ss->s, op);
    ss->sm.Fa = ss->s.axial_load;
    ss->sm.Fr = ss->s.radial_load;
    for (int k = 0; k < ss->n; k++)
        if (ss->b[k]) acbb_simm_speed(ss->b[k], ss->s.inner_speed);
}

/* The schedule's operating point at time t. */
static void schedule_point(acbb_set_sim *ss, double t)
{
    if (!follows_schedule(ss)) return;
    acbb_operating op;
    acbb_schedule_at(&ss->s, t, &op);
    operating_apply(ss, &op);
}

/* sim.c schedule_done: no step past a row, no settling before the last. */
static int schedule_done(acbb_set_sim *ss)
{
    if (!follows_schedule(ss)) return 1;
    acbb_operating op;
    acbb_schedule_at(&ss->s, ss->run.time, &op);
    if (op.finished) return 1;
    double next = ss->s.schedule[op.row].t;
    ss->run.dt = fmin(ss->run.dt, fmax(next - ss->run.time, DT_MIN));
    return 0;
}

/* ---- stepping ---- */

static acbb_status fail(acbb_set_sim *ss, acbb_status st, const char *msg)
{
    ss->run.state = ACBB_RUN_FAILED;
    ss->run.status = st;
    if (st == ACBB_WALL_LIMIT) /* one text wherever the bound was met (a member's or the set's) */
        snprintf(ss->run.msg, sizeof ss->run.msg, "wall-clock bound fidelity.max_wall_s = %g s "
                 "reached; last good state kept", ss->s.max_wall_s);
    else
        snprintf(ss->run.msg, sizeof ss->run.msg, "%s", msg);
    return st;
}

static void save(acbb_set_sim *ss)
{
    memcpy(ss->T_keep, ss->T, sizeof(double) * (size_t)ss->ns.n);
    ss->sm_keep = ss->sm;
    for (int k = 0; k < ss->n; k++) acbb_simm_save(ss->b[k]);
}

static void restore(acbb_set_sim *ss)
{
    memcpy(ss->T, ss->T_keep, sizeof(double) * (size_t)ss->ns.n);
    ss->sm = ss->sm_keep;
    for (int k = 0; k < ss->n; k++) acbb_simm_restore(ss->b[k]);
    schedule_point(ss, ss->run.time); /* the kept state's */
    distribute(ss);
    gather_heat(ss, 0.0);
}

static double max_change(const acbb_set_sim *ss, const double *Tn, int stored)
{
    double m = 0.0;
    for (int i = 0; i < ss->ns.n; i++)
        if (!stored || acbb_tnet_capacity(ss->ns.net, i) > 0.0) m = fmax(m, fabs(Tn[i] - ss->T[i]));
    return m;
}

static acbb_status thermal(acbb_set_sim *ss, int steady, double relax, double *Tn, double *dT,
                           double *dTs)
{
    for (;;) {
        memcpy(Tn, ss->T, sizeof(double) * (size_t)ss->ns.n);
        acbb_status rc = steady ? acbb_tnet_steady(ss->ns.net, ss->q, Tn)
                                : acbb_tnet_step(ss->ns.net, ss->q, ss->run.dt, Tn);
        if (rc != ACBB_OK) return rc;
        if (steady)
            for (int i = 0; i < ss->ns.n; i++) Tn[i] = ss->T[i] + relax * (Tn[i] - ss->T[i]);
        *dT = max_change(ss, Tn, 0);
        *dTs = max_change(ss, Tn, 1);
        if (steady || *dTs <= DT_MAX_DT_K || ss->run.dt <= DT_MIN) return ACBB_OK;
        ss->run.dt = fmax(0.5 * ss->run.dt, DT_MIN);
    }
}

/* sim.c advance(): a transient step whose total loss moves > 5 % is
 * retried with half the step. */
static acbb_status advance(acbb_set_sim *ss, int steady, double *dT, double *dTs,
                           acbb_error *err)
{
    double Tn[ACBB_SET_NMAX];
    save(ss);
    for (;;) {
        /* each retry evaluates the whole set again (the state is the kept one here) */
        acbb_status rc = stop_check(ss, err);
        if (rc != ACBB_OK) return rc;
        double w = ss->steady_relax.relax;
        rc = thermal(ss, steady, w, Tn, dT, dTs);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "thermal network: %s", acbb_status_name(rc));
        if (!acbb_snap_all_finite(Tn, ss->ns.n))
            return acbb_error_set(err, ACBB_NONFINITE,
                                  "non-finite temperature caught; last good state kept");
        memcpy(ss->T, Tn, sizeof(double) * (size_t)ss->ns.n);
        double before = ss->total;
        schedule_point(ss, ss->run.time + (steady ? 0.0 : ss->run.dt));
        rc = evaluate(ss, !steady, 0, err);
        if (rc != ACBB_OK) {
            restore(ss);
            if (steady && acbb_relax_reject(&ss->steady_relax, rc)) continue;
            return rc;
        }
        if (steady) acbb_relax_judge(&ss->steady_relax, w, *dT / w, 0.0);
        double dP = fabs(ss->total - before) / fmax(ss->total, 1e-12);
        if (steady || dP <= 0.05 || ss->run.dt <= DT_MIN) return ACBB_OK;
        restore(ss);
        ss->run.dt = fmax(0.5 * ss->run.dt, DT_MIN);
    }
}

/* The set's polish: the set and its last undamped move (acbb_polish_turn). */
typedef struct {
    acbb_set_sim *ss;
    double move[ACBB_SET_NMAX];
} polish_ctx;

/* One polish iteration (steady_polish.h), as sim.c's for one bearing. */
static acbb_status polish_step(void *ctx, double relax, double *res, double *turn,
                               acbb_error *err)
{
    acbb_set_sim *ss = ((polish_ctx *)ctx)->ss;
    double Tn[ACBB_SET_NMAX], dT, dTs;
    acbb_status rc = stop_check(ss, err);
    if (rc != ACBB_OK) return rc;
    rc = thermal(ss, 1, relax, Tn, &dT, &dTs);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "steady solve failed");
    if (!acbb_snap_all_finite(Tn, ss->ns.n)) /* fmax in the residual drops a NaN */
        return acbb_error_set(err, ACBB_NONFINITE, "non-finite temperature in the steady "
                              "solve; last good state kept");
    *res = dT / relax; /* the undamped move (relax is 1 or a power of 1/2) */
    *turn = acbb_polish_turn(((polish_ctx *)ctx)->move, ss->T, Tn, relax, ss->ns.n);
    save(ss);
    memcpy(ss->T, Tn, sizeof(double) * (size_t)ss->ns.n);
    if ((rc = evaluate(ss, 0, 1, err)) != ACBB_OK) restore(ss);
    return rc;
}

/* Damped where it overshoots, never OK unconverged (issue 18; sim.c). */
static acbb_status polish(acbb_set_sim *ss, acbb_error *err)
{
    acbb_polish_result r;
    double resolution = acbb_polish_resolution(acbb_polish_loss_rtol(&ss->s), ss->T, ss->ns.n);
    polish_ctx p = { ss, { 0 } };
    acbb_status rc = acbb_polish_iterate(polish_step, &p, resolution, &r, err);
    if (rc == ACBB_DIVERGED && r.iterations == ACBB_POLISH_ITERS) {
        size_t n = strlen(err->msg);
        snprintf(err->msg + n, sizeof err->msg - n, "; last state kept");
    }
    if (rc != ACBB_OK) return rc;
    return acbb_balance_check(ss->heat_in, acbb_tnet_heat_to_fixed(ss->ns.net, ss->T), err);
}

/* Temperature and pressure limits, and a rigid set's preload growing ever
 * faster (sim.c check_runaway, on the set's preload). */
static acbb_status runaway(acbb_set_sim *ss, double step_dt)
{
    char d[200];
    for (int k = 0; k < ss->n; k++) {
        const acbb_network *nw = acbb_simm_network(ss->b[k]);
        const double *T = acbb_simm_T(ss->b[k]);
        for (int i = 0; i < nw->n; i++)
            if (T[i] > ss->s.temp_limit_C) {
                snprintf(d, sizeof d, "thermal runaway: bearing %d node %s reached %.1f C (limit "
                         "thermal.temp_limit_C = %.0f C) at t = %.0f s", k, nw->names[i], T[i],
                         ss->s.temp_limit_C, ss->run.time);
                return fail(ss, ACBB_RUNAWAY, d);
            }
        double p = acbb_snap_max_pmax(acbb_simm_ms(ss->b[k]));
        if (p > PMAX_LIMIT) {
            snprintf(d, sizeof d, "thermal runaway: bearing %d contact pressure %.2f GPa exceeds "
                     "the 4.2 GPa static limit at t = %.0f s", k, p * 1e-9, ss->run.time);
            return fail(ss, ACBB_RUNAWAY, d);
        }
    }
    double F = acbb_set_mech_preload(&ss->sm);
    if (!ss->sm.spring && ss->run.iter > 0 && step_dt > 0.0) {
        double rate = (F - ss->prev_F) / step_dt;
        ss->growth = rate > 0.0 && rate > ss->prev_rate ? ss->growth + 1 : 0;
        ss->prev_rate = rate;
        if (ss->growth >= 50) {
            snprintf(d, sizeof d, "thermal runaway: the set's preload grows ever faster (%.0f N "
                     "at t = %.0f s)", F, ss->run.time);
            return fail(ss, ACBB_RUNAWAY, d);
        }
    }
    ss->prev_F = F;
    return ACBB_OK;
}

/* The lift-off thrust while the set runs (issues 25, 29: the Set screen
 * showed 0 until the end): searched again, from the last one, when the
 * preload or the speed (a schedule) has moved LIFT_MOVE since, to
 * LIFT_TOL of it; the ratio to the preload barely moves, and a search
 * costs two or three shaft solves, a step about two (BENCHMARKS.md). The
 * converged state's is searched once more, to 1e-4 of the preload. */
#define LIFT_MOVE 0.05
#define LIFT_TOL 2e-3
static void live_liftoff(acbb_set_sim *ss)
{
    double F = ss->preload > 0.0 ? ss->preload : ss->sm.Fp;
    if (ss->lift_preload > 0.0 && fabs(F - ss->lift_preload) <= LIFT_MOVE * ss->lift_preload
        && fabs(ss->s.inner_speed - ss->lift_speed) <= LIFT_MOVE * ss->lift_speed)
        return;
    ss->liftoff = acbb_set_liftoff(ss, LIFT_TOL);
}

static void publish(acbb_set_sim *ss)
{
    /* heating off solves no network: no heat flows (issue 18) */
    ss->heat_out = ss->s.heating ? acbb_tnet_heat_to_fixed(ss->ns.net, ss->T) : 0.0;
    if (ss->run.state == ACBB_RUN_RUNNING) {
        ss->preload = acbb_set_preload_now(ss);
        live_liftoff(ss);
    }
    for (int k = 0; k < ss->n; k++) acbb_simm_publish(ss->b[k], &ss->run);
}

static acbb_status isothermal(acbb_set_sim *ss)
{
    acbb_error err = { "" };
    for (int it = 0; it < ISO_ITERS; it++) {
        double prev = ss->total;
        acbb_status rc = stop_check(ss, &err);
        if (rc == ACBB_OK) rc = evaluate(ss, 0, 0, &err);
        if (rc != ACBB_OK) return fail(ss, rc, err.msg[0] ? err.msg : acbb_status_name(rc));
        ss->run.iter++;
        if (fabs(ss->total - prev) <= 1e-12 * fmax(ss->total, 1e-12)) break;
    }
    converge(ss, "isothermal mechanics at ambient (effects.heating = off)");
    return ACBB_OK;
}

static acbb_status step(acbb_set_sim *ss)
{
    if (!ss->s.heating) return isothermal(ss);
    acbb_error err = { "" };
    double dT = 0.0, dTs = 0.0, before = ss->total;
    int steady = ss->s.thermal_mode == ACBB_THERMAL_STEADY;
    int scheduled = !schedule_done(ss);
    acbb_status rc = advance(ss, steady, &dT, &dTs, &err);
    if (rc != ACBB_OK) return fail(ss, rc, err.msg[0] ? err.msg : acbb_status_name(rc));
    double step_dt = steady ? 1.0 : ss->run.dt;
    ss->run.iter++;
    if (!steady) ss->run.time += ss->run.dt;
    ss->run.residual = dT / step_dt;
    /* While a schedule moves the operating point the preload grows by design
     * (sim.c: the temperature and pressure limits stay on). */
    if (scheduled) ss->growth = 0;
    if ((rc = runaway(ss, steady ? 0.0 : step_dt)) != ACBB_OK) return rc;
    double dP = fabs(ss->total - before) / fmax(ss->total, 1e-12);
    int quiet = steady ? dT < 1e-7 && dP < 1e-9 : ss->run.residual < ss->s.steady_tol && dP < 1e-4;
    ss->quiet = quiet && !scheduled ? ss->quiet + 1 : 0;
    if (!steady && dP < 0.005 && dTs < 0.25 * DT_MAX_DT_K)
        ss->run.dt = fmin(1.5 * ss->run.dt, DT_MAX);
    if (ss->quiet >= (steady ? 3 : STEADY_COUNT)) {
        if ((rc = polish(ss, &err)) != ACBB_OK) return fail(ss, rc, err.msg);
        char what[64];
        snprintf(what, sizeof what, "thermal steady state after %ld steps", ss->run.iter);
        converge(ss, what);
    } else if (ss->run.iter >= ss->s.max_steps || ss->run.time >= ss->s.max_time) {
        snprintf(err.msg, sizeof err.msg, "no steady state within the limits (%ld steps, %.0f s "
                 "simulated); raise thermal.max_steps or thermal.max_time_s", ss->run.iter,
                 ss->run.time);
        return fail(ss, ACBB_NOT_CONVERGED, err.msg);
    }
    return ACBB_OK;
}

acbb_status acbb_set_sim_step(acbb_set_sim *ss)
{
    if (ss->run.state != ACBB_RUN_RUNNING) return ss->run.status;
    double t0 = acbb_now_ms();
    acbb_status rc = step(ss);
    ss->run.wall_ms += acbb_now_ms() - t0;
    publish(ss);
    return rc;
}

/* ---- set-up ---- */

/* The member scene: one bearing of the set, its axial position held
 * (acbb_mech_prescribe replaces the held value); no loads of its own. */
static void member_scene(const acbb_scene *s, double share, acbb_scene *m)
{
    *m = *s;
    m->set_arrangement = ACBB_SET_SINGLE;
    m->set_n_bearings = 0;
    m->preload = ACBB_PRELOAD_DISPLACEMENT;
    m->preload_force = share > 0.0 ? share : 1.0;
    m->axial_load = m->preload_force;
    m->radial_load = m->moment_load = 0.0;
    m->schedule_n = 0; /* the set follows the rows (schedule_point) */
}

/* Axial displacement of one bearing under thrust F at rest, 20 C, no
 * expansion (sim.c fix_preload's solve). */
static double static_dx(double F, void *ctx)
{
    acbb_scene s0 = *(const acbb_scene *)ctx;
    s0.axial_load = F;
    s0.radial_load = s0.moment_load = s0.inner_speed = 0.0;
    s0.preload = ACBB_PRELOAD_FORCE;
    acbb_mech *m;
    acbb_mech_state *st = malloc(sizeof *st);
    double dx = NAN;
    if (st && acbb_mech_new(&s0, &m, NULL) == ACBB_OK) {
        if (acbb_mech_init_state(m, st, NULL) == ACBB_OK) dx = st->dx;
        acbb_mech_free(m);
    }
    free(st);
    return dx;
}

/* The set-up met the user's bound (not a member's share of it). */
static acbb_status setup_wall(const acbb_scene *s, acbb_error *err)
{
    return acbb_error_set(err, ACBB_WALL_LIMIT, "wall-clock bound fidelity.max_wall_s = %g s "
                          "reached during the set-up, before the first state", s->max_wall_s);
}

/* fidelity.max_wall_s bounds the set's whole set-up (issue 20 item 8), not
 * each member's: member k's own set-up gets what its predecessors left. */
static acbb_status member_bound(const acbb_scene *s, double t0, acbb_scene *m, acbb_error *err)
{
    if (!(s->max_wall_s > 0.0)) return ACBB_OK;
    double left = s->max_wall_s - 1e-3 * (acbb_now_ms() - t0);
    if (left <= 0.0)
        return setup_wall(s, err);
    m->max_wall_s = left;
    return ACBB_OK;
}

static acbb_status set_up(acbb_set_sim *ss, const acbb_sim_opts *o, acbb_error *err)
{
    const acbb_scene *s = &ss->s;
    acbb_set_mech_init(&ss->sm, s);
    ss->n = ss->sm.n;
    acbb_scene m;
    int np = 0;
    for (int k = 0; k < ss->n; k++) np += ss->sm.orient[k] > 0;
    member_scene(s, s->preload_force / (np > 0 ? np : 1), &m);
    acbb_network *nw[ACBB_MAX_SET];
    double t0 = acbb_now_ms();
    for (int k = 0; k < ss->n; k++) {
        acbb_status rc = member_bound(s, t0, &m, err);
        if (rc == ACBB_OK) rc = acbb_sim_create(&m, o, &ss->b[k], err);
        if (rc == ACBB_WALL_LIMIT) /* the user's bound, not the member's share of it */
            return setup_wall(s, err);
        if (rc != ACBB_OK) return rc;
        acbb_simm_deadline(ss->b[k], 0.0); /* the set's steps hand theirs down */
        nw[k] = acbb_simm_network(ss->b[k]);
        if (!(ss->scratch[k] = malloc(sizeof *ss->scratch[k]))
            || !(ss->lift_ms[k] = malloc(sizeof *ss->lift_ms[k])))
            return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    }
    if (s->preload == ACBB_PRELOAD_DISPLACEMENT) {
        acbb_scene s0 = *s;
        acbb_set_mech_assemble(&ss->sm, static_dx, &s0);
        for (int k = 0; k < ss->n; k++)
            if (!isfinite(ss->sm.e[k]))
                return acbb_error_set(err, ACBB_DIVERGED, "bearing set: the assembly preload "
                                      "mounting.preload_N could not be solved");
    }
    acbb_status rc = acbb_network_set_build(&ss->ns, nw, ss->n, s, acbb_set_pitch(s), err);
    if (rc != ACBB_OK) return rc;
    for (int i = 0; i < ss->ns.n; i++)
        ss->T[i] = acbb_tnet_is_fixed(ss->ns.net, i) ? ss->ns.T_fixed[i] : s->ambient_C;
    /* The first evaluation (at the dynamic level seconds of ball motion)
     * within what the members' set-ups left of the bound (issue 26 item 7). */
    acbb_set_sim_deadline(ss, s->max_wall_s > 0.0 ? t0 + 1e3 * s->max_wall_s : 0.0);
    rc = evaluate(ss, 0, 0, err);
    acbb_set_sim_deadline(ss, 0.0); /* the run loop arms each step's */
    if (rc == ACBB_WALL_LIMIT)
        return setup_wall(s, err);
    return rc;
}

acbb_status acbb_set_sim_new(const acbb_scene *s, const acbb_sim_opts *o, acbb_set_sim **out,
                             acbb_error *err)
{
    acbb_error e2 = { "" };
    if (!err) err = &e2;
    acbb_status rc = acbb_scene_validate(s, err);
    if (rc != ACBB_OK) return rc;
    acbb_set_sim *ss = calloc(1, sizeof *ss);
    if (!ss) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    ss->s = *s;
    acbb_fidelity_apply(&ss->s, NULL); /* as every member's (sim.c sim_init) */
    acbb_operating op; /* the first row, or the last for the steady solve (sim.c sim_init) */
    if (ss->s.thermal_mode == ACBB_THERMAL_STEADY || !ss->s.heating)
        acbb_schedule_final(&ss->s, &op);
    else
        acbb_schedule_at(&ss->s, 0.0, &op);
    acbb_schedule_apply(&ss->s, &op);
    ss->cancel = o->cancel;
    if ((rc = set_up(ss, o, err)) != ACBB_OK) {
        acbb_set_sim_free(ss);
        return rc;
    }
    ss->run.state = ACBB_RUN_RUNNING;
    ss->run.dt = s->time_step;
    acbb_relax_start(&ss->steady_relax);
    snprintf(ss->run.msg, sizeof ss->run.msg, "running");
    ss->prev_F = acbb_set_mech_preload(&ss->sm);
    publish(ss);
    *out = ss;
    return ACBB_OK;
}

void acbb_set_sim_free(acbb_set_sim *ss)
{
    if (!ss) return;
    acbb_network_set_free(&ss->ns);
    for (int k = 0; k < ACBB_MAX_SET; k++) {
        acbb_sim_free(ss->b[k]);
        free(ss->scratch[k]);
        free(ss->lift_ms[k]);
    }
    free(ss);
}

acbb_run_state acbb_set_sim_outcome(const acbb_set_sim *ss, acbb_status *status, long *iter)
{
    *status = ss->run.status;
    *iter = ss->run.iter;
    return ss->run.state;
}

void acbb_set_sim_cancel(acbb_set_sim *ss, const atomic_int *cancel) { ss->cancel = cancel; }
void acbb_set_sim_deadline(acbb_set_sim *ss, double deadline_ms)
{
    ss->deadline_ms = deadline_ms;
    for (int k = 0; k < ss->n; k++) acbb_simm_deadline(ss->b[k], deadline_ms);
}

