/* acbb — the coupled stepper of a bearing set (MODEL.md section 14;
 * sim_set.h). One step, as sim.c's for one bearing (MODEL.md 9): every
 * bearing's expansions from its own temperatures and the spacers' axial
 * growth -> the shaft equilibrium over all bearings (set_mech.h), at the
 * quasi-dynamic and dynamic levels alternated with each bearing's ball
 * speeds -> each bearing's losses -> one backward-Euler step of the joined
 * network. Step control, steady detection and the final direct steady
 * polish are sim.c's (same constants). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sim_set.h"
#include "sim_priv.h"
#include "set_mech.h"
#include "network_set.h"
#include "acbb/set.h"
#include "acbb/measure.h"
#include "cancel.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include "acbb/fidelity.h"

#define DT_MIN 0.05
#define DT_MAX 30.0
#define DT_MAX_DT_K 2.0
#define STEADY_COUNT 20
#define PMAX_LIMIT 4.2e9
#define POLISH_ITERS 60
#define QD_PASSES 4
#define QD_TOL 1e-9
#define NMAX ACBB_SET_MAX_NODES
#define SYNC_TOL 1e-2        /* transient steps: resistances lag below this move (network_set.h) */

struct acbb_set_sim {
    acbb_scene s;
    int n;
    acbb_sim *b[ACBB_MAX_SET];
    acbb_mech_state *scratch[ACBB_MAX_SET]; /* member states kept across probes */
    acbb_set_mech sm, sm_keep;
    acbb_network_set ns;
    double T[NMAX], q[NMAX], T_keep[NMAX];
    acbb_set_run run;
    const atomic_int *cancel;
    double prev_total, prev_F, prev_rate, total;
    int growth, quiet;
    double heat_in, heat_out, preload, liftoff, K_ax, K_rad, K_tilt, spacer;
};

/* ---- one evaluation at the joined temperatures T ---- */

static void members(acbb_set_sim *ss, acbb_set_member *mb)
{
    for (int k = 0; k < ss->n; k++)
        mb[k] = (acbb_set_member){ acbb_simm_mech(ss->b[k]), acbb_simm_ms(ss->b[k]),
                                   acbb_simm_exp(ss->b[k]) };
}

static acbb_status solve_shaft(acbb_set_sim *ss, acbb_error *err)
{
    acbb_set_member mb[ACBB_MAX_SET];
    members(ss, mb);
    return acbb_set_mech_solve(&ss->sm, mb, ss->s.inner_speed, err);
}

/* Axial growth of the inner path (shaft spacer, inner-ring halves) minus
 * the outer path (housing spacer, outer-ring halves) between neighbouring
 * centres moves the inner rings against the outer rings (MODEL.md 14); the
 * set's centre is the reference (the shaft's dx takes any common move). */
static void spacer_growth(acbb_set_sim *ss)
{
    const acbb_scene *s = &ss->s;
    double u[ACBB_MAX_SET] = { 0 }, mean = 0.0;
    double L = acbb_set_pitch(s) - s->width, h = 0.5 * s->width;
    acbb_part_temps p[ACBB_MAX_SET];
    for (int k = 0; k < ss->n; k++)
        acbb_network_part_temps(acbb_simm_network(ss->b[k]), acbb_simm_T(ss->b[k]), &p[k]);
    for (int k = 1; k < ss->n && s->thermal_expansion; k++) {
        const acbb_part_temps *a = &p[k - 1], *c = &p[k];
        double T0 = s->ambient_C;
        double in = s->shaft.chi * (0.5 * (a->shaft + c->shaft) - T0) * L
                  + s->ring.chi * (a->inner_ring + c->inner_ring - 2.0 * T0) * h;
        double out = s->housing.chi * (0.5 * (a->housing + c->housing) - T0) * L
                   + s->ring.chi * (a->outer_ring + c->outer_ring - 2.0 * T0) * h;
        u[k] = u[k - 1] + in - out;
    }
    for (int k = 0; k < ss->n; k++) mean += u[k] / ss->n;
    for (int k = 0; k < ss->n; k++) ss->sm.u[k] = u[k] - mean;
    ss->spacer = u[ss->n - 1];
}

/* Shaft equilibrium, alternated with the ball speeds at the quasi-dynamic
 * and dynamic levels (sim.c mechanics(): one pass inside transient steps,
 * up to QD_PASSES otherwise). */
static acbb_status mechanics(acbb_set_sim *ss, int transient, acbb_error *err)
{
    int traction = acbb_simm_has_traction(ss->b[0]);
    int warm = traction && transient && acbb_simm_ms(ss->b[0])->ball[0].traction_valid;
    acbb_status rc = warm ? ACBB_OK : solve_shaft(ss, err);
    if (rc != ACBB_OK || !traction) return rc;
    for (int pass = 0; pass < (transient ? 1 : QD_PASSES); pass++) {
        double change = 0.0;
        if (acbb_cancelled(ss->cancel))
            return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
        for (int k = 0; k < ss->n; k++) {
            double ch;
            if ((rc = acbb_simm_traction(ss->b[k], &ch, err)) != ACBB_OK) return rc;
            change = fmax(change, ch);
        }
        if ((rc = solve_shaft(ss, err)) != ACBB_OK || change < QD_TOL) return rc;
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

/* ---- probes of the converged state: other loads, same temperatures ---- */

typedef struct { double Fa, Fr, M; } loads;

/* Solve the shaft under other external loads in *w (its q the warm
 * start), leaving the members there. */
static acbb_status solve_loads(acbb_set_sim *ss, loads L, acbb_set_mech *w)
{
    w->Fa = L.Fa;
    w->Fr = L.Fr;
    w->M = L.M;
    acbb_set_member mb[ACBB_MAX_SET];
    members(ss, mb);
    return acbb_set_mech_solve(w, mb, ss->s.inner_speed, NULL);
}

static void keep_members(acbb_set_sim *ss, int back)
{
    for (int k = 0; k < ss->n; k++)
        if (back) acbb_mech_state_copy(acbb_simm_ms(ss->b[k]), ss->scratch[k]);
        else acbb_mech_state_copy(ss->scratch[k], acbb_simm_ms(ss->b[k]));
}

/* Solve the shaft under other external loads into *out; the members and
 * the set's own solution are put back afterwards. */
static acbb_status probe(acbb_set_sim *ss, loads L, acbb_set_mech *out)
{
    keep_members(ss, 0);
    *out = ss->sm;
    acbb_status rc = solve_loads(ss, L, out);
    keep_members(ss, 1);
    return rc;
}

static int side_of_floating(const acbb_set_sim *ss)
{
    return ss->sm.spring ? -1 : 0;
}

static int has_side(const acbb_set_mech *sm, int s)
{
    for (int k = 0; k < sm->n; k++) if (sm->orient[k] == s) return 1;
    return 0;
}

/* The axial force through the set with no external thrust (MODEL.md 14:
 * assembly preload plus the thermally induced part). */
static double preload_now(acbb_set_sim *ss)
{
    double F = 0.0;
    if (!has_side(&ss->sm, 1) || !has_side(&ss->sm, -1)) /* tandem: only a spring preloads */
        return ss->sm.spring ? ss->sm.Fp : 0.0;
    if (side_of_floating(ss)) {
        for (int k = 0; k < ss->n; k++) if (ss->sm.orient[k] < 0) F += ss->sm.Fx[k];
        return F;
    }
    if (ss->sm.Fa == 0.0) return acbb_set_mech_preload(&ss->sm);
    acbb_set_mech p;
    if (probe(ss, (loads){ 0.0, ss->sm.Fr, ss->sm.M }, &p) != ACBB_OK) return 0.0;
    return acbb_set_mech_preload(&p);
}

/* Load left on `side` under thrust Fa, solved in *w from its last
 * solution (the lift-off search walks the thrust: each solve starts from
 * the previous one, not from the run's state). */
static double unloading_side(acbb_set_sim *ss, acbb_set_mech *w, double Fa, int side, int *ok)
{
    *ok = solve_loads(ss, (loads){ Fa, 0.0, 0.0 }, w) == ACBB_OK;
    double F = 0.0;
    for (int k = 0; k < w->n; k++) if (w->orient[k] == side) F += w->Fx[k];
    return F;
}

/* External thrust at which the unloading side's balls all unload, at the
 * current temperatures and speed, the radial load and moment set aside (a
 * bearing that carries radial load keeps balls loaded at any thrust; the
 * lift-off thrust is the axial preload's, as [HK-EC] states it): GSL's Brent on F^(2/3) - eps^(2/3) of the side's
 * load F, which near lift-off falls as (Fa_lift - Fa)^1.5 (Hertz), so its
 * 2/3 power is nearly linear there; to 1e-4 of the preload. A rigid
 * opposed set unloads its -1 side under +x thrust; a spring set's floating
 * side keeps the spring force, so thrust the other way unloads the +1 side
 * at the spring force. A tandem set has no opposite side: 0. */
typedef struct { acbb_set_sim *ss; acbb_set_mech w; int side, dir; double eps; } lift_ctx;

/* A thrust the set cannot carry (no shaft equilibrium: past lift-off the
 * remaining side alone may hold no moment, and a spring set's shaft is then
 * free axially) counts as lifted off; the next solve starts again from the
 * run's state. */
static double lift_fn(double Fa, void *p)
{
    lift_ctx *c = p;
    int ok;
    double F = unloading_side(c->ss, &c->w, Fa * c->dir, c->side, &ok);
    if (!ok) { /* again from the run's state before calling it lifted off */
        keep_members(c->ss, 1);
        c->w = c->ss->sm;
        F = unloading_side(c->ss, &c->w, Fa * c->dir, c->side, &ok);
    }
    if (!ok) {
        keep_members(c->ss, 1);
        c->w = c->ss->sm;
        F = 0.0;
    }
    return cbrt(F * F) - cbrt(c->eps * c->eps);
}

static double search_liftoff(lift_ctx *cp)
{
    lift_ctx c = *cp;
    acbb_set_sim *ss = c.ss;
    double lo = ss->sm.Fa * c.dir, hi = fmax(lo, 0.0) + ss->sm.Fp;
    double flo = lift_fn(lo, &c), fhi = lift_fn(hi, &c);
    if (flo <= 0.0) return 0.0;
    for (int i = 0; i < 20 && fhi > 0.0; i++) {
        lo = hi;
        hi *= 2.0;
        fhi = lift_fn(hi, &c);
    }
    gsl_function F = { lift_fn, &c };
    gsl_root_fsolver *b = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double root = 0.0;
    if (b && fhi <= 0.0 && gsl_root_fsolver_set(b, &F, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < 60; it++) {
            if (gsl_root_fsolver_iterate(b) != GSL_SUCCESS) break;
            root = gsl_root_fsolver_root(b);
            if (gsl_root_fsolver_x_upper(b) - gsl_root_fsolver_x_lower(b) < 1e-4 * ss->sm.Fp)
                break;
        }
    }
    if (b) gsl_root_fsolver_free(b);
    return root;
}

static double liftoff(acbb_set_sim *ss)
{
    if (!has_side(&ss->sm, 1) || !has_side(&ss->sm, -1)) return 0.0;
    int side = ss->sm.spring ? 1 : -1;
    lift_ctx c = { ss, ss->sm, side, -side, 1e-6 * ss->sm.Fp };
    keep_members(ss, 0);
    double root = search_liftoff(&c);
    keep_members(ss, 1);
    return root;
}

/* Radial and tilt stiffness at the nose: central differences of the shaft
 * equilibrium in the radial force and the moment there. */
static void nose_stiffness(acbb_set_sim *ss)
{
    double R = 0.5 * ss->s.pitch_diameter;
    double h = fmax(1e-3 * (fabs(ss->sm.Fr) + ss->sm.Fp + fabs(ss->sm.Fa)), 1.0);
    acbb_set_mech p[2];
    loads base = { ss->sm.Fa, ss->sm.Fr, ss->sm.M };
    ss->K_rad = ss->K_tilt = 0.0;
    if (probe(ss, (loads){ base.Fa, base.Fr + h, base.M }, &p[0]) == ACBB_OK
        && probe(ss, (loads){ base.Fa, base.Fr - h, base.M }, &p[1]) == ACBB_OK) {
        double xn = ss->sm.x_nose;
        double d = (p[0].q[1] - p[0].q[2] * xn) - (p[1].q[1] - p[1].q[2] * xn);
        ss->K_rad = d != 0.0 ? 2.0 * h / d : 0.0;
    }
    if (probe(ss, (loads){ base.Fa, base.Fr, base.M + h * R }, &p[0]) == ACBB_OK
        && probe(ss, (loads){ base.Fa, base.Fr, base.M - h * R }, &p[1]) == ACBB_OK) {
        double d = p[0].q[2] - p[1].q[2];
        ss->K_tilt = d != 0.0 ? 2.0 * h * R / d : 0.0;
    }
}

static void converge(acbb_set_sim *ss, const char *what)
{
    ss->K_ax = 0.0;
    for (int k = 0; k < ss->n; k++) {
        double K;
        acbb_simm_stiffness(ss->b[k], &K);
        if (!(ss->sm.spring && ss->sm.orient[k] < 0)) ss->K_ax += K; /* a spring side floats */
    }
    solve_shaft(ss, NULL); /* the stiffness probes moved the workspaces */
    nose_stiffness(ss);
    ss->liftoff = liftoff(ss);
    ss->preload = preload_now(ss);
    ss->run.state = ACBB_RUN_CONVERGED;
    snprintf(ss->run.msg, sizeof ss->run.msg, "%s", what);
}

/* ---- stepping ---- */

static acbb_status fail(acbb_set_sim *ss, acbb_status st, const char *msg)
{
    ss->run.state = ACBB_RUN_FAILED;
    ss->run.status = st;
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
    double Tn[NMAX];
    save(ss);
    for (;;) {
        acbb_status rc = thermal(ss, steady, 0.5, Tn, dT, dTs);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "thermal network: %s", acbb_status_name(rc));
        if (!acbb_snap_all_finite(Tn, ss->ns.n))
            return acbb_error_set(err, ACBB_NONFINITE,
                                  "non-finite temperature caught; last good state kept");
        memcpy(ss->T, Tn, sizeof(double) * (size_t)ss->ns.n);
        double before = ss->total;
        rc = evaluate(ss, !steady, 0, err);
        if (rc != ACBB_OK) {
            restore(ss);
            return rc;
        }
        double dP = fabs(ss->total - before) / fmax(ss->total, 1e-12);
        if (steady || dP <= 0.05 || ss->run.dt <= DT_MIN) return ACBB_OK;
        restore(ss);
        ss->run.dt = fmax(0.5 * ss->run.dt, DT_MIN);
    }
}

static acbb_status polish(acbb_set_sim *ss, acbb_error *err)
{
    double Tn[NMAX], dT, dTs;
    for (int it = 0; it < POLISH_ITERS; it++) {
        if (acbb_cancelled(ss->cancel))
            return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
        acbb_status rc = thermal(ss, 1, 1.0, Tn, &dT, &dTs);
        if (rc != ACBB_OK) return acbb_error_set(err, rc, "steady solve failed");
        save(ss);
        memcpy(ss->T, Tn, sizeof(double) * (size_t)ss->ns.n);
        if ((rc = evaluate(ss, 0, 1, err)) != ACBB_OK) {
            restore(ss);
            return rc;
        }
        if (dT < 1e-9) break;
    }
    return ACBB_OK;
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

static void publish(acbb_set_sim *ss)
{
    ss->heat_out = acbb_tnet_heat_to_fixed(ss->ns.net, ss->T);
    if (ss->run.state == ACBB_RUN_RUNNING) ss->preload = preload_now(ss);
    for (int k = 0; k < ss->n; k++) acbb_simm_publish(ss->b[k], &ss->run);
}

static acbb_status isothermal(acbb_set_sim *ss)
{
    acbb_error err = { "" };
    for (int it = 0; it < POLISH_ITERS; it++) {
        double prev = ss->total;
        acbb_status rc = evaluate(ss, 0, 0, &err);
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
    acbb_status rc = advance(ss, steady, &dT, &dTs, &err);
    if (rc != ACBB_OK) return fail(ss, rc, err.msg[0] ? err.msg : acbb_status_name(rc));
    double step_dt = steady ? 1.0 : ss->run.dt;
    ss->run.iter++;
    if (!steady) ss->run.time += ss->run.dt;
    ss->run.residual = dT / step_dt;
    if ((rc = runaway(ss, steady ? 0.0 : step_dt)) != ACBB_OK) return rc;
    double dP = fabs(ss->total - before) / fmax(ss->total, 1e-12);
    int quiet = steady ? dT < 1e-7 && dP < 1e-9 : ss->run.residual < ss->s.steady_tol && dP < 1e-4;
    ss->quiet = quiet ? ss->quiet + 1 : 0;
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
    for (int k = 0; k < ss->n; k++) {
        acbb_status rc = acbb_sim_create(&m, o, &ss->b[k], err);
        if (rc != ACBB_OK) return rc;
        nw[k] = acbb_simm_network(ss->b[k]);
        if (!(ss->scratch[k] = malloc(sizeof *ss->scratch[k])))
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
    return evaluate(ss, 0, 0, err);
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
    ss->cancel = o->cancel;
    if ((rc = set_up(ss, o, err)) != ACBB_OK) {
        acbb_set_sim_free(ss);
        return rc;
    }
    ss->run.state = ACBB_RUN_RUNNING;
    ss->run.dt = s->time_step;
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

/* ---- snapshots ---- */

static void set_view(const acbb_set_sim *ss, acbb_set_view *v)
{
    const acbb_set_mech *sm = &ss->sm;
    v->preload_N = acbb_snap_fin(ss->preload);
    v->preload_assembly_N = ss->s.preload_force;
    v->liftoff_thrust_N = acbb_snap_fin(ss->liftoff);
    v->stiffness_axial = acbb_snap_fin(ss->K_ax);
    v->stiffness_radial = acbb_snap_fin(ss->K_rad);
    v->stiffness_tilt = acbb_snap_fin(ss->K_tilt);
    v->shaft_dx = acbb_snap_fin(sm->q[0]);
    v->shaft_dz = acbb_snap_fin(sm->q[1]);
    v->shaft_tilt = acbb_snap_fin(sm->q[2]);
    v->spacer_growth = acbb_snap_fin(ss->spacer);
    for (int k = 0; k < ss->n; k++) {
        acbb_part_temps p;
        acbb_network_part_temps(acbb_simm_network(ss->b[k]), acbb_simm_T(ss->b[k]), &p);
        v->orientation[k] = sm->orient[k];
        v->axial_force[k] = acbb_snap_fin(sm->Fx[k]);
        v->contact_lost[k] = sm->lost[k];
        v->T_outer_ring[k] = acbb_snap_fin(acbb_simm_T(ss->b[k])[acbb_simm_network(ss->b[k])->node_outer_ring]);
        v->T_inner_ring[k] = acbb_snap_fin(p.inner_ring);
        v->loss_total[k] = acbb_snap_fin(acbb_simm_loss(ss->b[k]));
    }
}

acbb_status acbb_set_sim_bearing_snapshot(const acbb_set_sim *ss, int k, acbb_snapshot *o)
{
    if (k < 0 || k >= ss->n) return ACBB_EINVAL;
    acbb_sim_snapshot(ss->b[k], o);
    o->n_bearings = ss->n;
    set_view(ss, &o->set);
    return ACBB_OK;
}

void acbb_set_sim_snapshot(const acbb_set_sim *ss, acbb_snapshot *o)
{
    acbb_set_sim_bearing_snapshot(ss, 0, o);
    o->work.mechanics_solves += ss->sm.solves; /* the shaft equilibrium's member solves */
    o->heat_in = acbb_snap_fin(ss->heat_in);
    o->heat_out = acbb_snap_fin(ss->heat_out);
    int lost = 0;
    for (int k = 0; k < ss->n; k++) lost |= ss->sm.lost[k];
    if (lost && o->state != ACBB_RUN_FAILED) {
        size_t len = strlen(o->message);
        for (int k = 0; k < ss->n && len < sizeof o->message; k++)
            if (ss->sm.lost[k])
                len += (size_t)snprintf(o->message + len, sizeof o->message - len,
                                        "; bearing %d: contact_lost (lifted off)", k);
    }
}
