/* acbb — the coupled stepper of the seed's Fig. 5 (MODEL.md section 9).
 *
 * One step k: expansions from T^k -> mechanics (warm start) -> kinematics,
 * film and the five losses -> heat sources -> backward-Euler thermal step
 * to T^{k+1}. The coupling is lagged (mechanics at T^k); the time step
 * adapts so that no node moves more than 2 K per step. */
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
#include "cancel.h"
#include "gsl_quiet.h"
#include "sim_set.h"
#include "steady_polish.h"
#include "acbb/schedule.h"

#define DT_MIN 0.05            /* s, MODEL.md section 9 */
#define DT_MAX 30.0            /* s */
#define DT_MAX_DT_K 2.0        /* reject a step that moves a node more than this */
#define STEADY_COUNT 20        /* consecutive quiet steps for steady state */
#define PMAX_LIMIT 4.2e9       /* ISO static limit for ball bearings, Pa */
#define ISO_ITERS 60           /* mechanics passes of an isothermal run */
#define QD_PASSES 4            /* mechanics <-> Level-2 passes when converging a state */
#define QD_TOL 1e-9            /* relative change of omega_m that ends the passes */
#define QD_SKIP_TOL 3e-3       /* transient steps: Level-2 update skipped below this input move */
#define HERTZ_SKIP_TOL 1e-3    /* rad, transient steps: Hertz constants kept (Kc moves < 6e-5) */
#define LOSS_SKIP_TOL 3e-4     /* transient steps: a ball's loss quadrature kept below this move */
#define POLISH_SKIP_TOL ACBB_POLISH_REUSE_TOL /* steady polish: the same reuse (1e-9) */
#define DYN_WINDOW_COLD 4e-3   /* s of ball motion from the race-control start */
#define DYN_WINDOW_WARM 1e-3   /* s of ball motion per pass once warm */
#define DYN_SKIP_TOL 1e-2      /* transient steps: settled balls keep speeds below this input move */
#define DYN_THREADS 2          /* workers over the distinct balls (the answer does not depend on it) */

typedef struct {
    acbb_contact_loss in, out;
    double ref[ACBB_BALL_INPUTS]; /* the ball's inputs when in, out were computed */
    int ref_ok;
} ball_loss;

/* Everything a step changes, kept so a failed or rejected step can put the
 * last good state back exactly (not re-derived). */
typedef struct {
    acbb_mech_state ms;
    double T[ACBB_MAX_NODES];
    acbb_expansion exp;
    ball_loss bl[ACBB_MAX_BALLS];
    acbb_losses loss;
    acbb_heat_sources heat;
    double q[ACBB_MAX_NODES];
} checkpoint;

struct acbb_sim {
    acbb_scene s;
    acbb_mech *mech;
    acbb_qd *qd;               /* quasi-dynamic workspace (NULL below that level) */
    acbb_dyn *dyn;             /* dynamic workspace (dynamic level only) */
    acbb_mech_state ms;        /* last accepted mechanics */
    checkpoint *keep;          /* scratch for step rollback (owned) */
    acbb_network nw;
    acbb_quad quad;
    double T[ACBB_MAX_NODES];  /* T^k */
    acbb_expansion exp;
    ball_loss bl[ACBB_MAX_BALLS];
    acbb_losses loss;
    acbb_heat_sources heat;
    double q[ACBB_MAX_NODES];
    double heat_out;
    double dt, time, residual, wall_ms, prev_total, prev_Fx, prev_rate;
    int growth_count;
    int transient_pass;        /* 1 while evaluating inside a transient step */
    int polishing;             /* 1 while evaluating inside the steady polish */
    long iter;
    int quiet;
    acbb_run_state state;
    acbb_status status;
    char msg[256];
    const atomic_int *cancel;  /* caller's flag (acbb_run_ctl); not owned */
    acbb_work work;            /* per-part work counters */
    double K_axial;            /* axial stiffness at the converged state, N/m */
    acbb_stiffness K_ring;     /* radial and tilt stiffness at the converged state */
    int fixed_axial;           /* displacement preload: dx held at fixed_dx */
    int threads;               /* dynamic-level workers over the balls (acbb_sim_opts) */
    double fixed_dx;
    long reported;             /* last iteration handed to a drive hook; -1 none */
    acbb_set_sim *set;         /* a bearing set (sim_set.c, MODEL.md 14), else NULL */
    double bound_axial, bound_radial; /* loads sim->mech was built with (schedule) */
    double setup_ms;           /* computing time of the set-up (sim_init) */
    double deadline_ms;        /* fidelity.max_wall_s as a monotonic-clock deadline; 0 none */
};

static int outputs_finite(const acbb_sim *sim);


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
static acbb_status stop_check(const acbb_sim *sim, acbb_error *err)
{
    if (acbb_cancelled(sim->cancel))
        return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
    if (past_bound(sim) != ACBB_OK)
        return acbb_error_set(err, ACBB_WALL_LIMIT, "wall-clock bound fidelity.max_wall_s = "
                              "%g s reached", sim->s.max_wall_s);
    return ACBB_OK;
}

/* ---- one evaluation of the mechanical/tribological state at T^k ---- */

static void expansions(acbb_sim *sim)
{
    sim->work.expansion_updates++;
    acbb_part_temps pt;
    acbb_network_part_temps(&sim->nw, sim->T, &pt);
    acbb_expansion_compute(&sim->s, &pt, &sim->exp);
}

static void contact_input(const acbb_sim *sim, const acbb_ball_state *b, int inner,
                          acbb_contact_in *c)
{
    acbb_mech_contact_input(acbb_mech_geometry(sim->mech), b, inner, sim->s.inner_speed, c);
}

/* Oil at the two contact inlets and the oil-air mixture of the cavity. */
static void lubricant(const acbb_sim *sim, acbb_oil_state *oi, acbb_oil_state *oo,
                      acbb_oil_state *oc_out, acbb_mixture *mix)
{
    double Tin_i, Tin_o;
    acbb_oil_state oc;
    acbb_network_inlet_temps(&sim->nw, sim->T, &Tin_i, &Tin_o);
    acbb_oil_at(&sim->s, Tin_i, oi);
    acbb_oil_at(&sim->s, Tin_o, oo);
    acbb_oil_at(&sim->s, sim->T[sim->nw.node_cavity], &oc);
    acbb_mixture_at(&sim->s, &oc, mix);
    *oc_out = oc;
}

/* Contact heat of one contact, by where the table sends it. */
static void route_contact(const acbb_contact_loss *cl, double w, double *race, double *ball)
{
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        if (acbb_loss_table[l].sink == ACBB_HEAT_CONTACT) *race += w * cl->P[l];
        else if (acbb_loss_table[l].sink == ACBB_HEAT_BALL) *ball += w * cl->P[l];
    }
}

/* Whole-bearing losses (drag, cage) at the mean orbital speed. */
static void bearing_losses(const acbb_sim *sim, const acbb_mixture *mix,
                           const acbb_oil_state *oc, double wm, acbb_losses *L,
                           acbb_heat_sources *H)
{
    acbb_bearing_in in = { &sim->s, mix, wm, oc };
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        const acbb_loss_desc *d = &acbb_loss_table[l];
        if (!d->bearing || !acbb_loss_enabled(&sim->s, (acbb_loss_kind)l)) continue;
        L->P[l] = d->bearing(&in);
        if (d->sink == ACBB_HEAT_CAGE) H->cage += L->P[l];
        else H->cavity += L->P[l];
    }
}

/* The losses of ball b's two contacts into bl. Inside a transient step
 * (tol > 0) a ball whose inputs (acbb_ball_inputs: loads, angles, inlet
 * viscosities, speeds) moved less than tol since its losses were computed
 * keeps them; the steady polish recomputes every ball (MODEL.md section 9).
 * 3e-4, not the Level-2 skip's 3e-3: each recomputation makes the total
 * loss jump by up to about tol / Z, and at 3e-3 that broke the 1e-4 quiet
 * test of the steady detection (BENCHMARKS.md, "Speed beyond the axial
 * case", round 3). */
static acbb_status ball_losses(acbb_sim *sim, const acbb_ball_state *b,
                               const acbb_oil_state *oil_i, const acbb_oil_state *oil_o,
                               double tol, ball_loss *bl)
{
    double ref[ACBB_BALL_INPUTS];
    acbb_ball_inputs(b, oil_i->eta0, oil_o->eta0, sim->s.inner_speed, ref);
    if (tol > 0.0 && bl->ref_ok && acbb_ball_moved(bl->ref, ref, acbb_ball_loss_weights) < tol)
        return ACBB_OK;
    acbb_contact_in ci, co;
    contact_input(sim, b, 1, &ci);
    contact_input(sim, b, 0, &co);
    acbb_status rc = acbb_contact_losses(&sim->s, &sim->quad, &ci, oil_i, &bl->in);
    if (rc == ACBB_OK)
        rc = acbb_contact_losses(&sim->s, &sim->quad, &co, oil_o, &bl->out);
    bl->ref_ok = rc == ACBB_OK;
    memcpy(bl->ref, ref, sizeof ref);
    sim->work.loss_quadratures += bl->in.integrated + bl->out.integrated;
    return rc;
}

/* Tolerance of the per-ball reuse of Level-2 speeds and losses: `transient`
 * in transient steps of non-symmetric scenes, POLISH_SKIP_TOL in the steady
 * polish (a ball whose inputs moved less than the equilibrium resolves
 * keeps its results; MODEL.md section 9), 0 for pure thrust (one ball,
 * nothing to gain; its results stay bit for bit) and the set-up. */
static double skip_tol(const acbb_sim *sim, double transient)
{
    if (sim->ms.symmetric) return 0.0;
    return sim->transient_pass ? transient : sim->polishing ? POLISH_SKIP_TOL : 0.0;
}

/* Every loss of the table at the current mechanics; fills sim->loss and heat. */
static acbb_status losses(acbb_sim *sim)
{
    acbb_oil_state oil_i, oil_o, oil_c;
    acbb_mixture mix;
    lubricant(sim, &oil_i, &oil_o, &oil_c, &mix);
    int nb = acbb_mech_distinct(&sim->ms);
    /* As the Level-2 skip (mechanics()): transient steps of non-symmetric
     * scenes only, so pure thrust and the steady polish compute every ball. */
    double tol = skip_tol(sim, LOSS_SKIP_TOL);
    acbb_losses L = { 0 };
    acbb_heat_sources H = { 0 };
    double wm_sum = 0.0;
    for (int j = 0; j < nb; j++) {
        const acbb_ball_state *b = &sim->ms.ball[j];
        double w = acbb_mech_weight(&sim->ms, j);
        ball_loss *bl = &sim->bl[j];
        acbb_status rc = ball_losses(sim, b, &oil_i, &oil_o, tol, bl);
        if (rc != ACBB_OK)
            return rc;
        for (int l = 0; l < ACBB_LOSS_KINDS; l++)
            L.P[l] += w * (bl->in.P[l] + bl->out.P[l]);
        route_contact(&bl->in, w, &H.inner_contact, &H.ball);
        route_contact(&bl->out, w, &H.outer_contact, &H.ball);
        wm_sum += w * b->kin.omega_m;
    }
    for (int j = nb; j < sim->ms.n; j++) sim->bl[j] = sim->bl[acbb_mech_source(&sim->ms, j)];
    bearing_losses(sim, &mix, &oil_c, wm_sum / sim->ms.n, &L, &H);
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) L.total += L.P[l];
    L.inner = H.inner_contact;
    L.outer = H.outer_contact;
    if (!isfinite(L.total))
        return ACBB_NONFINITE;
    sim->loss = L;
    sim->heat = H;
    return ACBB_OK;
}

static void network_inputs(const acbb_sim *sim, acbb_net_inputs *in)
{
    /* Mean spot size over the balls in contact at each race, and how many
     * there are (the rest carry no heat across a contact spot). */
    *in = (acbb_net_inputs){ 0 };
    double wm = 0.0;
    for (int j = 0; j < sim->ms.n; j++) {
        const acbb_ball_state *b = &sim->ms.ball[j];
        wm += b->kin.omega_m;
        if (b->ct_i.a > 0.0 && b->Qi > 1e-6) {
            in->a_i += b->ct_i.a; in->b_i += b->ct_i.b;
            in->n_loaded_i++;
        }
        if (b->ct_o.a > 0.0 && b->Qo > 1e-6) {
            in->a_o += b->ct_o.a; in->b_o += b->ct_o.b;
            in->n_loaded_o++;
        }
    }
    if (in->n_loaded_i > 0) { in->a_i /= in->n_loaded_i; in->b_i /= in->n_loaded_i; }
    if (in->n_loaded_o > 0) { in->a_o /= in->n_loaded_o; in->b_o /= in->n_loaded_o; }
    in->omega_i = sim->s.inner_speed;
    in->omega_m = wm / sim->ms.n;
    in->T_cavity_C = sim->T[sim->nw.node_cavity];
}

/* Dynamic level: integrate every distinct ball over a window (longer from
 * the race-control start, short once warm) and keep its time average;
 * inside transient steps settled balls whose inputs barely moved keep
 * theirs (acbb_dyn_set_skip), the steady polish integrates every ball. */
static acbb_status ball_dynamics(acbb_sim *sim, const acbb_oil_state *oi,
                                 const acbb_oil_state *oo, const acbb_mixture *mix,
                                 double *change, acbb_error *err)
{
    acbb_dyn_env env = { sim->mech, &sim->s, &sim->quad, sim->s.inner_speed, oi, oo, mix };
    acbb_dyn_set_skip(sim->dyn, sim->transient_pass ? DYN_SKIP_TOL : 0.0);
    long before = acbb_dyn_windows(sim->dyn);
    acbb_status rc = acbb_dyn_balls(sim->dyn, &env, &sim->ms, DYN_WINDOW_COLD, DYN_WINDOW_WARM,
                                    change, err);
    sim->work.traction_solves += acbb_dyn_windows(sim->dyn) - before;
    if (rc != ACBB_OK) return rc;
    acbb_mech_spread(&sim->ms);
    return ACBB_OK;
}

static acbb_status mech_solve(acbb_sim *sim, acbb_error *err)
{
    sim->work.mechanics_solves++;
    /* As the Level-2 and loss skips: transient steps of non-symmetric
     * scenes only (pure thrust stays as it was, bit for bit). */
    int skip = sim->transient_pass && !sim->ms.symmetric;
    acbb_mech_set_transient(sim->mech, skip ? HERTZ_SKIP_TOL : 0.0);
    return acbb_mech_solve(sim->mech, sim->s.inner_speed, &sim->exp, &sim->ms, err);
}

/* Equilibrium, and at the quasi-dynamic level the ball speeds from
 * traction equilibrium, iterated a few passes (the remaining mismatch
 * shrinks over the thermal steps; the final polish converges it). */
static acbb_status mechanics(acbb_sim *sim, acbb_error *err)
{
    /* Inside a transient step with warm ball speeds the Level-2 pass below
     * re-solves the equilibrium anyway, so the first solve is skipped (the
     * loads it would refresh lag one step, like the rest of the coupling). */
    int warm = (sim->qd || sim->dyn) && sim->transient_pass && sim->ms.ball[0].traction_valid;
    acbb_status rc = warm ? ACBB_OK : mech_solve(sim, err);
    if (rc != ACBB_OK || (!sim->qd && !sim->dyn)) return rc;
    acbb_oil_state oi, oo, oc;
    acbb_mixture mix;
    lubricant(sim, &oi, &oo, &oc, &mix);
    /* One pass per transient step: the thermal steps iterate the coupling
     * anyway; the set-up converges it fully. So does the steady polish,
     * whose Picard iterations (to 1e-9 K) also carry the coupling when
     * many balls are solved at Level 2: one pass each there (the steady
     * state moves < 4e-7, BENCHMARKS.md round 4; pure thrust and the
     * dynamic level stay as they were). */
    int many = sim->qd && sim->polishing && !sim->ms.symmetric;
    int passes = sim->transient_pass || many ? 1 : QD_PASSES;
    for (int pass = 0; pass < passes; pass++) {
        double change = 0.0;
        if ((rc = stop_check(sim, err)) != ACBB_OK) return rc;
        if (sim->dyn)
            rc = ball_dynamics(sim, &oi, &oo, &mix, &change, err);
        else {
            sim->work.traction_solves++;
            /* Skipping pays only when many distinct balls are solved; with
             * one (pure thrust) it would only perturb the transient path. */
            acbb_qd_set_skip(sim->qd, skip_tol(sim, QD_SKIP_TOL));
            rc = acbb_qd_update(sim->qd, &sim->s, &sim->quad, acbb_mech_geometry(sim->mech),
                                sim->s.inner_speed, &oi, &oo, &mix, &sim->ms, &change, err);
        }
        if (rc != ACBB_OK) return rc;
        rc = mech_solve(sim, err);
        if (rc != ACBB_OK || change < QD_TOL) return rc;
    }
    return ACBB_OK;
}

/* Mechanics + losses + network resistances at T^k. */
static acbb_status evaluate(acbb_sim *sim, acbb_error *err)
{
    if (sim->s.thermal_expansion)
        expansions(sim);
    else
        sim->exp = (acbb_expansion){ 0 };
    acbb_status rc = mechanics(sim, err);
    if (rc != ACBB_OK) return rc;
    rc = losses(sim);
    if (rc == ACBB_OK && !outputs_finite(sim)) rc = ACBB_NONFINITE;
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "non-finite loss, film or kinematics value caught; "
                              "last good state kept");
    if (!sim->s.heating) return ACBB_OK; /* isothermal: no network at all */
    acbb_net_inputs in;
    network_inputs(sim, &in);
    sim->work.network_solves++;
    rc = acbb_network_update(&sim->nw, &sim->s, &in);
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "thermal network: update failed");
    acbb_network_heat(&sim->nw, &sim->s, &sim->heat, sim->q);
    return ACBB_OK;
}

/* ---- checks ---- */

/* Every value a snapshot publishes, checked where it is made, so that a
 * NaN ends the run with ACBB_NONFINITE instead of reaching a screen. */
static int outputs_finite(const acbb_sim *sim)
{
    const acbb_expansion *e = &sim->exp;
    if (!isfinite(e->ball) || !isfinite(e->inner) || !isfinite(e->inner_cen)
        || !isfinite(e->outer) || !isfinite(sim->loss.total) || !isfinite(sim->heat.inner_contact)
        || !isfinite(sim->heat.outer_contact) || !isfinite(sim->ms.Fx))
        return 0;
    for (int j = 0; j < sim->ms.n; j++) {
        const acbb_ball_state *b = &sim->ms.ball[j];
        if (!acbb_snap_contact_finite(&sim->bl[j].in) || !acbb_snap_contact_finite(&sim->bl[j].out)
            || !isfinite(b->ct_i.pmax) || !isfinite(b->ct_o.pmax) || !isfinite(b->kin.spin_i)
            || !isfinite(b->kin.spin_o) || !isfinite(b->kin.wx) || !isfinite(b->kin.wz))
            return 0;
    }
    return 1;
}

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
    /* Under-relaxed Picard (MODEL.md section 9, 0.5 in steady mode). */
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
} polish_ctx;

/* One polish iteration (steady_polish.h): the direct steady solve, the
 * move by `relax`, the evaluation there; a failed evaluation keeps the
 * last evaluated iterate. */
static acbb_status polish_step(void *ctx, double relax, double *res, acbb_error *err)
{
    polish_ctx *p = ctx;
    acbb_sim *sim = p->sim;
    double Tn[ACBB_MAX_NODES], dT = 0.0;
    acbb_status rc = stop_check(sim, err);
    if (rc != ACBB_OK) return rc;
    rc = steady_step(sim, relax, Tn, &dT);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "steady solve failed");
    *res = dT / relax; /* the undamped move (relax is 1 or a power of 1/2) */
    save(sim, sim->keep);
    if (*res < p->best_res) { /* *res is the residual of the state before the move */
        save(sim, p->best);
        p->best_res = *res;
    }
    memcpy(sim->T, Tn, sizeof(double) * sim->nw.n);
    sim->polishing = 1;
    rc = evaluate(sim, err);
    sim->polishing = 0;
    if (rc != ACBB_OK) restore(sim, sim->keep);
    return rc;
}

/* Damped where it overshoots (issue 18), never OK unconverged: a polish
 * that does not converge ends the run ACBB_DIVERGED with the iterate of
 * smallest residual. */
static acbb_status polish(acbb_sim *sim, acbb_error *err)
{
    polish_ctx p = { sim, malloc(sizeof(checkpoint)), INFINITY };
    if (!p.best) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_polish_result r;
    acbb_status rc = acbb_polish_iterate(polish_step, &p,
                                         acbb_polish_resolution(sim->s.mech_tol, sim->T,
                                                                sim->nw.n), &r, err);
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
    network_inputs(sim, &in);
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
        acbb_status rc = steady_mode ? steady_step(sim, 0.5, Tn, dT)
                                     : thermal_step(sim, Tn, dT, dTs);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "thermal network: %s", acbb_status_name(rc));
        if (!acbb_snap_all_finite(Tn, sim->nw.n))
            return acbb_error_set(err, ACBB_NONFINITE,
                                  "non-finite temperature caught; last good state kept");
        memcpy(sim->T, Tn, sizeof(double) * sim->nw.n);
        sim->transient_pass = !steady_mode;
        rc = follow_schedule(sim, sim->time + (steady_mode ? 0.0 : sim->dt), err);
        if (rc == ACBB_OK) rc = evaluate(sim, err);
        sim->transient_pass = 0;
        if (rc != ACBB_OK) {
            restore(sim, sim->keep);
            return rc;
        }
        double dP = fabs(sim->loss.total - sim->keep->loss.total) / fmax(sim->loss.total, 1e-12);
        if (steady_mode || dP <= 0.05 || sim->dt <= DT_MIN)
            return ACBB_OK;
        restore(sim, sim->keep);
        sim->dt = fmax(0.5 * sim->dt, DT_MIN);
    }
}

/* Axial stiffness dFx/d(delta_x) at the converged state: central
 * difference with the axial displacement held, the other ring freedoms
 * free, ball speeds and tractions as converged. 0 if a solve fails. */
static double axial_stiffness(acbb_sim *sim)
{
    acbb_mech_state *st = malloc(sizeof *st);
    if (!st) return 0.0;
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
    return rc == ACBB_OK && isfinite(K) ? K : 0.0;
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

static void converge(acbb_sim *sim, const char *what)
{
    finish_energy(sim);
    if (unbalanced(sim)) return;
    sim->K_axial = axial_stiffness(sim);
    acbb_ring_stiffness(&sim->s, &sim->exp, sim->ms.dx, &sim->ms, &sim->K_ring);
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
        acbb_status rc = evaluate(sim, &err);
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

acbb_status acbb_sim_step(acbb_sim *sim)
{
    if (sim->state != ACBB_RUN_RUNNING)
        return sim->status;
    if (sim->set) {
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
    int quiet = steady_mode ? dT < 1e-7 && dP < 1e-9
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

acbb_status acbb_sim_drive(acbb_sim *sim, const acbb_run_ctl *ctl)
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
        acbb_sim_step(sim);
        if (wall_limit(sim)) break;
        if (call_hook(sim, ctl)) break;
    }
    return sim->status;
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
    double t0 = acbb_now_ms();
    arm_bound(sim); /* the set-up counts against fidelity.max_wall_s */
    acbb_operating op; /* schedule.h: the first row, or the last for the steady solve */
    if (s->thermal_mode == ACBB_THERMAL_STEADY || !s->heating) acbb_schedule_final(s, &op);
    else acbb_schedule_at(s, 0.0, &op);
    acbb_schedule_apply(&sim->s, &op);
    sim->bound_axial = op.axial_load;
    sim->bound_radial = op.radial_load;
    acbb_status rc = acbb_scene_validate(s, err);
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
    if ((rc = initial_mechanics(sim, err)) == ACBB_OK) rc = evaluate(sim, err);
    sim->setup_ms = acbb_now_ms() - t0;
    if (rc == ACBB_WALL_LIMIT) /* no state yet: nothing to keep */
        return acbb_error_set(err, rc, "wall-clock bound fidelity.max_wall_s = %g s reached "
                              "during the set-up, before the first state", s->max_wall_s);
    if (rc != ACBB_OK) return rc;
    sim->dt = s->time_step;
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
    acbb_sim_opts o = { sim->cancel, sim->threads };
    acbb_status rc = acbb_set_sim_new(s, &o, &sim->set, err);
    if (rc != ACBB_OK) return rc;
    sim->state = acbb_set_sim_outcome(sim->set, &sim->status, &sim->iter);
    sim->reported = -1;
    return ACBB_OK;
}

acbb_status acbb_sim_create(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                            acbb_error *err)
{
    acbb_gsl_quiet();
    acbb_sim *sim = calloc(1, sizeof *sim);
    if (!sim || !(sim->keep = malloc(sizeof *sim->keep))) {
        free(sim);
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    }
    sim->cancel = o->cancel;
    sim->threads = o->threads > 0 ? o->threads : DYN_THREADS;
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
    acbb_sim_opts o = { sim->cancel, sim->threads };
    acbb_status rc = acbb_sim_create(s, &o, &fresh, err);
    if (rc != ACBB_OK) return rc; /* the running sim is untouched */
    acbb_sim old = *sim;
    *sim = *fresh;
    *fresh = old;
    acbb_sim_free(fresh);
    arm_bound(sim); /* as in acbb_sim_restart */
    return ACBB_OK;
}

acbb_status acbb_sim_restart(acbb_sim *sim, const acbb_scene *s, int warm, acbb_error *err)
{
    if (sim->set || s->set_arrangement != ACBB_SET_SINGLE) return set_restart(sim, s, err);
    double T[ACBB_MAX_NODES];
    int keep = warm && s->network == sim->s.network;
    memcpy(T, sim->T, sizeof T);
    acbb_sim *fresh = calloc(1, sizeof *fresh);
    if (!fresh) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    fresh->cancel = sim->cancel;
    fresh->threads = sim->threads;
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

/* ---- snapshot (the per-ball and squeeze views: sim_snapshot.c) ---- */

void acbb_sim_snapshot(const acbb_sim *sim, acbb_snapshot *o)
{
    const acbb_network *nw = &sim->nw;
    if (sim->set) {
        acbb_set_sim_snapshot(sim->set, o);
        if (sim->status == ACBB_CANCELLED || sim->status == ACBB_WALL_LIMIT) {
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
    acbb_life_compute(&sim->s, o, &o->life);
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

void acbb_simm_expand(acbb_sim *b)
{
    if (b->s.thermal_expansion) expansions(b);
    else b->exp = (acbb_expansion){ 0 };
}

void acbb_simm_unbound(acbb_sim *b)
{
    b->deadline_ms = 0.0;
    if (b->dyn) acbb_dyn_set_stop(b->dyn, NULL, NULL);
}

void acbb_simm_mode(acbb_sim *b, int transient, int polishing)
{
    b->transient_pass = transient;
    b->polishing = polishing;
}

/* One Level-2 or dynamic pass over b's balls at its current mechanics
 * (mechanics() without the equilibrium solves: the set solves those). */
acbb_status acbb_simm_traction(acbb_sim *b, double *change, acbb_error *err)
{
    acbb_oil_state oi, oo, oc;
    acbb_mixture mix;
    lubricant(b, &oi, &oo, &oc, &mix);
    *change = 0.0;
    if (b->dyn) return ball_dynamics(b, &oi, &oo, &mix, change, err);
    b->work.traction_solves++;
    acbb_qd_set_skip(b->qd, skip_tol(b, QD_SKIP_TOL));
    return acbb_qd_update(b->qd, &b->s, &b->quad, acbb_mech_geometry(b->mech), b->s.inner_speed,
                          &oi, &oo, &mix, &b->ms, change, err);
}

/* evaluate() after the mechanics: losses, network resistances, heat. */
acbb_status acbb_simm_heat(acbb_sim *b, acbb_error *err)
{
    acbb_status rc = losses(b);
    if (rc == ACBB_OK && !outputs_finite(b)) rc = ACBB_NONFINITE;
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "non-finite loss, film or kinematics value caught; "
                              "last good state kept");
    if (!b->s.heating) return ACBB_OK;
    acbb_net_inputs in;
    network_inputs(b, &in);
    b->work.network_solves++;
    if ((rc = acbb_network_update(&b->nw, &b->s, &in)) != ACBB_OK)
        return acbb_error_set(err, rc, "thermal network: update failed");
    acbb_network_heat(&b->nw, &b->s, &b->heat, b->q);
    return ACBB_OK;
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
    b->K_axial = axial_stiffness(b);
    acbb_ring_stiffness(&b->s, &b->exp, b->ms.dx, &b->ms, &b->K_ring);
    *K_axial = b->K_axial;
}
