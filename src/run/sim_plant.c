/* acbb — one bearing as a plant of the one stepper (stepper.h; MODEL.md
 * section 9): its evaluation (sim_eval.c: expansions from T^k -> mechanics
 * (warm start) -> kinematics, film and the five losses -> heat sources),
 * its checkpoints, its schedule's operating point, its runaway limits and
 * the probes of its converged state (axial and ring stiffness). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sim_struct.h"
#include "sim_priv.h"
#include "stepper.h"
#include "steady_polish.h"
#include "acbb/tools/schedule.h"

/* A checkpoint holds the solved balls only (acbb_mech_distinct): every
 * evaluation leaves the others their images (acbb_mech_spread; losses()
 * copies their losses), so restore() makes them again, the same bits.
 * Copying every ball was 3.5 % of a perturbed study of `report
 * --sensitivity` (issue 30; pure thrust solves 1 ball of the 7008C's 21). */
static void save(acbb_sim *sim, checkpoint *k)
{
    size_t nd = (size_t)acbb_mech_distinct(&sim->ms);
    memcpy(&k->ms, &sim->ms, offsetof(acbb_mech_state, ball));
    memcpy(k->ms.ball, sim->ms.ball, sizeof sim->ms.ball[0] * nd);
    memcpy(k->T, sim->T, sizeof k->T);
    k->exp = sim->exp;
    memcpy(k->bl, sim->bl, sizeof sim->bl[0] * nd);
    k->loss = sim->loss;
    k->heat = sim->heat;
    memcpy(k->q, sim->q, sizeof k->q);
}

/* The schedule's operating point at time t into sim->s. */
static void schedule_point(acbb_sim *sim, double t)
{
    if (!acbb_follows_schedule(&sim->s)) return;
    acbb_operating op;
    acbb_schedule_at(&sim->s, t, &op);
    acbb_schedule_apply(&sim->s, &op);
}

static void restore(acbb_sim *sim, const checkpoint *k)
{
    int nd = acbb_mech_distinct(&k->ms);
    memcpy(&sim->ms, &k->ms, offsetof(acbb_mech_state, ball));
    memcpy(sim->ms.ball, k->ms.ball, sizeof sim->ms.ball[0] * (size_t)nd);
    acbb_mech_spread(&sim->ms); /* the azimuths stay: a ball's never changes */
    memcpy(sim->T, k->T, sizeof k->T);
    sim->exp = k->exp;
    memcpy(sim->bl, k->bl, sizeof sim->bl[0] * (size_t)nd);
    for (int j = nd; j < sim->ms.n; j++) sim->bl[j] = sim->bl[acbb_mech_source(&sim->ms, j)];
    sim->loss = k->loss;
    sim->heat = k->heat;
    memcpy(sim->q, k->q, sizeof k->q);
    schedule_point(sim, sim->run.time); /* the kept state's; the mechanics follow when evaluated */
    acbb_net_inputs in;
    acbb_simx_network_inputs(sim, &in);
    acbb_network_update(&sim->nw, &sim->s, &in); /* resistances of the kept state */
}

static void plant_save(void *ctx, int slot)
{
    acbb_sim *sim = ctx;
    save(sim, slot == ACBB_KEEP_BEST ? sim->best : sim->keep);
}

static void plant_restore(void *ctx, int slot)
{
    acbb_sim *sim = ctx;
    restore(sim, slot == ACBB_KEEP_BEST ? sim->best : sim->keep);
}

static acbb_status plant_stop(void *ctx, acbb_error *err)
{
    return acbb_simx_stop_check(ctx, err);
}

/* Run-in schedule (MODEL.md 14; schedule.h): the operating point at time t.
 * acbb_mech binds the loads when made, so new loads get a new workspace,
 * warm-started from the last state, the displacement preload's dx held. */
static acbb_status plant_operate(void *ctx, double t, acbb_error *err)
{
    acbb_sim *sim = ctx;
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

static acbb_status plant_evaluate(void *ctx, acbb_pass pass, double relax, acbb_error *err)
{
    acbb_sim *sim = ctx;
    sim->transient_pass = pass == ACBB_PASS_TRANSIENT;
    sim->polishing = pass == ACBB_PASS_POLISH;
    sim->polish_relax = relax;
    acbb_status rc = acbb_simx_evaluate(sim, err);
    sim->transient_pass = 0;
    sim->polishing = 0;
    sim->polish_relax = 1.0;
    return rc;
}

static double plant_loss(void *ctx) { return ((acbb_sim *)ctx)->loss.total; }

static acbb_status plant_limits(void *ctx, double t, char *what, size_t size)
{
    acbb_sim *sim = ctx;
    for (int i = 0; i < sim->nw.n; i++)
        if (sim->T[i] > sim->s.temp_limit_C) {
            snprintf(what, size, "node %s reached %.1f C (limit thermal.temp_limit_C = %.0f C) "
                     "at t = %.0f s", sim->nw.names[i], sim->T[i], sim->s.temp_limit_C, t);
            return ACBB_RUNAWAY;
        }
    double p = acbb_snap_max_pmax(&sim->ms);
    if (p > PMAX_LIMIT) {
        snprintf(what, size, "contact pressure %.2f GPa exceeds the 4.2 GPa static limit at "
                 "t = %.0f s", p * 1e-9, t);
        return ACBB_RUNAWAY;
    }
    return ACBB_OK;
}

/* Rigid preload: the axial reaction (MODEL.md section 9). */
static double plant_force(void *ctx, int *rigid)
{
    acbb_sim *sim = ctx;
    *rigid = sim->s.preload == ACBB_PRELOAD_DISPLACEMENT;
    return sim->ms.Fx;
}

void acbb_simx_energy(acbb_sim *sim)
{
    sim->heat_out = sim->s.heating ? acbb_tnet_heat_to_fixed(sim->nw.net, sim->T) : 0.0;
}

static void plant_settle(void *ctx) { acbb_simx_energy(ctx); }

/* Heating off solves no network: no heat flows. */
static acbb_status plant_balance(void *ctx, acbb_error *err)
{
    acbb_sim *sim = ctx;
    if (!sim->s.heating) return ACBB_OK;
    double in = sim->heat.inner_contact + sim->heat.outer_contact + sim->heat.ball
              + sim->heat.cavity + sim->heat.cage;
    return acbb_balance_check(in, sim->heat_out, err);
}

/* The end-of-run stiffness, unless the caller asked for none (then
 * reported missing: acbb_sim_opts.skip_stiffness; a set's members too). */
static void plant_converge(void *ctx)
{
    acbb_sim *sim = ctx;
    if (sim->skip_stiffness) {
        sim->K_axial = NAN;
        sim->K_ring = (acbb_stiffness){ NAN, NAN, NAN };
        return;
    }
    int held = sim->s.preload == ACBB_PRELOAD_DISPLACEMENT;
    sim->K_axial = acbb_axial_stiffness(sim->mech, sim->s.inner_speed, &sim->exp, &sim->ms, held);
    acbb_ring_stiffness(&sim->s, &sim->exp, sim->ms.dx, &sim->ms, &sim->K_ring);
}

void acbb_simx_plant(acbb_sim *sim, acbb_plant *p)
{
    *p = (acbb_plant){
        .ctx = sim, .s = &sim->s, .net = sim->nw.net, .T = sim->T, .q = sim->q,
        .n = sim->nw.n, .solves = &sim->work.network_solves, .keeps_best = 1,
        .force_name = "axial reaction", .stop = plant_stop, .operate = plant_operate,
        .evaluate = plant_evaluate, .loss = plant_loss, .save = plant_save,
        .restore = plant_restore, .limits = plant_limits, .force = plant_force,
        .settle = plant_settle, .balance = plant_balance, .converge = plant_converge,
    };
}
