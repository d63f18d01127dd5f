/* acbb — one evaluation of the coupled state at T^k (MODEL.md section 9,
 * the inner part of the seed's Fig. 5): expansions from the temperatures,
 * the mechanics (warm start; Level 2 or the dynamic balls where the scene
 * asks), kinematics, film and losses per contact, the network's inputs and
 * the heat sources. The stepper (stepper.c) decides when; this file
 * computes. A bearing of a set (sim_set.c) uses the same pieces:
 * acbb_simx_expand, _traction and _heat at the end. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/measure.h"
#include "lubrication.h"
#include "sim_priv.h"
#include "sim_struct.h"

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

/* The oil at the two contact inlets and the oil-air mixture of the cavity
 * at T^k: made once per evaluation, for the Level-2 passes and the losses
 * alike (they read the same temperatures; 2.4 % of a perturbed study of
 * `report --sensitivity` when made twice, issue 30). */
typedef struct {
    acbb_oil_state i, o, c;
    acbb_mixture mix;
} oil_env;

static void lubricant(const acbb_sim *sim, oil_env *e)
{
    double Tin_i, Tin_o;
    acbb_network_inlet_temps(&sim->nw, sim->T, &Tin_i, &Tin_o);
    acbb_oil_at(&sim->s, Tin_i, &e->i);
    acbb_oil_at(&sim->s, Tin_o, &e->o);
    acbb_oil_at(&sim->s, sim->T[sim->nw.node_cavity], &e->c);
    acbb_mixture_at(&sim->s, &e->c, &e->mix);
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
static acbb_status losses(acbb_sim *sim, const oil_env *oil)
{
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
        acbb_status rc = ball_losses(sim, b, &oil->i, &oil->o, tol, bl);
        if (rc != ACBB_OK)
            return rc;
        for (int l = 0; l < ACBB_LOSS_KINDS; l++)
            L.P[l] += w * (bl->in.P[l] + bl->out.P[l]);
        route_contact(&bl->in, w, &H.inner_contact, &H.ball);
        route_contact(&bl->out, w, &H.outer_contact, &H.ball);
        wm_sum += w * b->kin.omega_m;
    }
    for (int j = nb; j < sim->ms.n; j++) sim->bl[j] = sim->bl[acbb_mech_source(&sim->ms, j)];
    bearing_losses(sim, &oil->mix, &oil->c, wm_sum / sim->ms.n, &L, &H);
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) L.total += L.P[l];
    L.inner = H.inner_contact;
    L.outer = H.outer_contact;
    if (!isfinite(L.total))
        return ACBB_NONFINITE;
    sim->loss = L;
    sim->heat = H;
    return ACBB_OK;
}

void acbb_simx_network_inputs(const acbb_sim *sim, acbb_net_inputs *in)
{
    /* Mean spot size over the balls in contact at each race, and how many
     * there are (the rest carry no heat across a contact spot). */
    *in = (acbb_net_inputs){ 0 };
    double wm = 0.0;
    for (int j = 0; j < sim->ms.n; j++) {
        const acbb_ball_state *b = &sim->ms.ball[j];
        wm += b->kin.omega_m;
        bool moving = sim->s.contact_model == ACBB_CONTACT_MOVING;
        if (b->ct_i.a > 0.0 && b->Qi > 1e-6) {
            in->a_i += b->ct_i.a; in->b_i += b->ct_i.b;
            in->v_race_i += b->kin.v_race_i; in->v_ball_i += b->kin.v_ball_i;
            in->n_loaded_i++;
            if (moving)
                acbb_network_spot_add(in, &sim->s, 1, b->ct_i.a, b->ct_i.b, b->kin.v_race_i,
                                      b->kin.v_ball_i);
        }
        if (b->ct_o.a > 0.0 && b->Qo > 1e-6) {
            in->a_o += b->ct_o.a; in->b_o += b->ct_o.b;
            in->v_race_o += b->kin.v_race_o; in->v_ball_o += b->kin.v_ball_o;
            in->n_loaded_o++;
            if (moving)
                acbb_network_spot_add(in, &sim->s, 0, b->ct_o.a, b->ct_o.b, b->kin.v_race_o,
                                      b->kin.v_ball_o);
        }
    }
    if (in->n_loaded_i > 0) {
        in->a_i /= in->n_loaded_i; in->b_i /= in->n_loaded_i;
        in->v_race_i /= in->n_loaded_i; in->v_ball_i /= in->n_loaded_i;
    }
    if (in->n_loaded_o > 0) {
        in->a_o /= in->n_loaded_o; in->b_o /= in->n_loaded_o;
        in->v_race_o /= in->n_loaded_o; in->v_ball_o /= in->n_loaded_o;
    }
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

/* One Level-2 pass over the distinct balls, its update under-relaxed by
 * `relax`: a damped polish step (steady_polish.h) moves the speeds and
 * tractions it carries from one evaluation to the next (one pass each, as
 * below) by its relaxation, as it moves the temperatures; undamped, speeds
 * a pass behind are an undamped part of the iterate (acbb new 6232: two
 * balls at the load zone's edge swing about -0.94 a pass, and kept the
 * polish reversing every step at any relaxation of the temperatures). */
static acbb_status level2_pass(acbb_sim *sim, const acbb_oil_state *oi, const acbb_oil_state *oo,
                               const acbb_mixture *mix, double relax, double *change,
                               acbb_error *err)
{
    acbb_qd_kept kept[ACBB_MAX_BALLS];
    sim->work.traction_solves++;
    /* Skipping pays only when many distinct balls are solved; with
     * one (pure thrust) it would only perturb the transient path. */
    acbb_qd_set_skip(sim->qd, skip_tol(sim, QD_SKIP_TOL));
    acbb_qd_set_path(sim->qd, sim->transient_pass);
    if (relax < 1.0) acbb_qd_keep(&sim->ms, kept);
    acbb_status rc = acbb_qd_update(sim->qd, &sim->s, &sim->quad, acbb_mech_geometry(sim->mech),
                                    sim->s.inner_speed, oi, oo, mix, &sim->ms, change, err);
    if (rc == ACBB_OK && relax < 1.0) acbb_qd_relax(&sim->ms, kept, relax);
    return rc;
}

/* Equilibrium, and at the quasi-dynamic level the ball speeds from
 * traction equilibrium, iterated a few passes (the remaining mismatch
 * shrinks over the thermal steps; the final polish converges it). */
static acbb_status converge(acbb_sim *sim, const oil_env *oil, acbb_error *err)
{
    /* Inside a transient step with warm ball speeds the Level-2 pass below
     * re-solves the equilibrium anyway, so the first solve is skipped (the
     * loads it would refresh lag one step, like the rest of the coupling). */
    int warm = (sim->qd || sim->dyn) && sim->transient_pass && sim->ms.ball[0].traction_valid;
    acbb_status rc = warm ? ACBB_OK : mech_solve(sim, err);
    if (rc != ACBB_OK || (!sim->qd && !sim->dyn)) return rc;
    /* One pass per transient step: the thermal steps iterate the coupling
     * anyway; the set-up converges it fully. So does the steady polish,
     * whose Picard iterations (to 1e-9 K) also carry the coupling when
     * many balls are solved at Level 2: one pass each there (the steady
     * state moves < 4e-7, BENCHMARKS.md round 4; pure thrust and the
     * dynamic level stay as they were). */
    int many = sim->qd && sim->polishing && !sim->ms.symmetric;
    /* The steady solve's first state (at ambient, far from the answer)
     * only starts its iterations, each of which converges the passes at
     * its own temperatures: one pass there (issue 30; the steady states
     * move < 1e-7, BENCHMARKS.md). */
    int start = sim->qd && sim->setting_up && sim->s.heating
             && sim->s.thermal_mode == ACBB_THERMAL_STEADY;
    int passes = sim->transient_pass || many || start ? 1 : QD_PASSES;
    for (int pass = 0; pass < passes; pass++) {
        double change = 0.0;
        if ((rc = acbb_simx_stop_check(sim, err)) != ACBB_OK) return rc;
        if (sim->dyn)
            rc = ball_dynamics(sim, &oil->i, &oil->o, &oil->mix, &change, err);
        else
            rc = level2_pass(sim, &oil->i, &oil->o, &oil->mix, many ? sim->polish_relax : 1.0,
                             &change, err);
        if (rc != ACBB_OK) return rc;
        rc = mech_solve(sim, err);
        if (rc != ACBB_OK || change < QD_TOL) return rc;
    }
    return ACBB_OK;
}

/* The set-up's first state takes its passes from a run that made them
 * with the same inputs, or keeps its own for others (sim_first.c). */
static acbb_status mechanics(acbb_sim *sim, const oil_env *oil, acbb_error *err)
{
    if (sim->setting_up && acbb_simx_first_take(sim, &oil->i, &oil->o, &oil->mix))
        return ACBB_OK;
    acbb_status rc = converge(sim, oil, err);
    if (rc == ACBB_OK && sim->setting_up)
        acbb_simx_first_keep(sim, &oil->i, &oil->o, &oil->mix);
    return rc;
}

/* Mechanics + losses + network resistances at T^k. */
acbb_status acbb_simx_evaluate(acbb_sim *sim, acbb_error *err)
{
    if (sim->s.thermal_expansion)
        expansions(sim);
    else
        sim->exp = (acbb_expansion){ 0 };
    oil_env oil;
    lubricant(sim, &oil);
    acbb_status rc = mechanics(sim, &oil, err);
    if (rc != ACBB_OK) return rc;
    rc = losses(sim, &oil);
    if (rc == ACBB_OK && !acbb_simx_outputs_finite(sim)) rc = ACBB_NONFINITE;
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "non-finite loss, film or kinematics value caught; "
                              "last good state kept");
    if (!sim->s.heating) return ACBB_OK; /* isothermal: no network at all */
    acbb_net_inputs in;
    acbb_simx_network_inputs(sim, &in);
    sim->work.network_solves++;
    rc = acbb_network_update(&sim->nw, &sim->s, &in);
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "thermal network: update failed");
    acbb_network_heat(&sim->nw, &sim->s, &sim->heat, sim->q);
    return ACBB_OK;
}

/* Every value a snapshot publishes, checked where it is made, so that a
 * NaN ends the run with ACBB_NONFINITE instead of reaching a screen. The
 * solved balls only: the others are their images (acbb_mech_spread; their
 * losses copied by losses()), the same values. */
int acbb_simx_outputs_finite(const acbb_sim *sim)
{
    const acbb_expansion *e = &sim->exp;
    if (!isfinite(e->ball) || !isfinite(e->inner) || !isfinite(e->inner_cen)
        || !isfinite(e->outer) || !isfinite(sim->loss.total) || !isfinite(sim->heat.inner_contact)
        || !isfinite(sim->heat.outer_contact) || !isfinite(sim->ms.Fx))
        return 0;
    for (int j = 0; j < acbb_mech_distinct(&sim->ms); j++) {
        const acbb_ball_state *b = &sim->ms.ball[j];
        if (!acbb_snap_contact_finite(&sim->bl[j].in) || !acbb_snap_contact_finite(&sim->bl[j].out)
            || !isfinite(b->ct_i.pmax) || !isfinite(b->ct_o.pmax) || !isfinite(b->kin.spin_i)
            || !isfinite(b->kin.spin_o) || !isfinite(b->kin.wx) || !isfinite(b->kin.wz))
            return 0;
    }
    return 1;
}

void acbb_simx_expand(acbb_sim *b)
{
    if (b->s.thermal_expansion) expansions(b);
    else b->exp = (acbb_expansion){ 0 };
}

/* One Level-2 or dynamic pass over b's balls at its current mechanics
 * (mechanics() without the equilibrium solves: the set solves those). */
acbb_status acbb_simx_traction(acbb_sim *b, double *change, acbb_error *err)
{
    oil_env oil;
    lubricant(b, &oil);
    *change = 0.0;
    if (b->dyn) return ball_dynamics(b, &oil.i, &oil.o, &oil.mix, change, err);
    b->work.traction_solves++;
    acbb_qd_set_skip(b->qd, skip_tol(b, QD_SKIP_TOL));
    acbb_qd_set_path(b->qd, b->transient_pass);
    return acbb_qd_update(b->qd, &b->s, &b->quad, acbb_mech_geometry(b->mech), b->s.inner_speed,
                          &oil.i, &oil.o, &oil.mix, &b->ms, change, err);
}

/* acbb_simx_evaluate() after the mechanics: losses, network resistances, heat. */
acbb_status acbb_simx_heat(acbb_sim *b, acbb_error *err)
{
    oil_env oil;
    lubricant(b, &oil);
    acbb_status rc = losses(b, &oil);
    if (rc == ACBB_OK && !acbb_simx_outputs_finite(b)) rc = ACBB_NONFINITE;
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "non-finite loss, film or kinematics value caught; "
                              "last good state kept");
    if (!b->s.heating) return ACBB_OK;
    acbb_net_inputs in;
    acbb_simx_network_inputs(b, &in);
    b->work.network_solves++;
    if ((rc = acbb_network_update(&b->nw, &b->s, &in)) != ACBB_OK)
        return acbb_error_set(err, rc, "thermal network: update failed");
    acbb_network_heat(&b->nw, &b->s, &b->heat, b->q);
    return ACBB_OK;
}
