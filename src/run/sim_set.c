/* acbb — a bearing set as a plant of the one stepper (MODEL.md section
 * 14; stepper.h, sim_set.h). Its evaluation: every bearing's expansions
 * from its own temperatures and the spacers' axial growth -> the shaft
 * equilibrium over all bearings (set_mech.h), at the quasi-dynamic and
 * dynamic levels alternated with each bearing's ball speeds -> each
 * bearing's losses -> the sources of the joined network, which the
 * stepper steps (stepper.c: step control, steady detection, the polish).
 * The probes of the converged state are in sim_set_probe.c, the
 * snapshots in sim_set_view.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "sim_set_priv.h"
#include "sim_struct.h"
#include "sim_priv.h"
#include "acbb/tools/set.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/lubricant.h"
#include "cancel.h"
#include "steady_polish.h"
#include "stepper.h"

#define SYNC_TOL 1e-2        /* transient steps: resistances lag below this move (network_set.h) */

/* ---- one evaluation at the joined temperatures T ---- */

void acbb_set_members(acbb_set_sim *ss, acbb_set_member *mb)
{
    for (int k = 0; k < ss->n; k++)
        mb[k] = (acbb_set_member){ ss->b[k]->mech, &ss->b[k]->ms,
                                   &ss->b[k]->exp };
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
        acbb_network_part_temps(&ss->b[k]->nw, ss->b[k]->T, &p[k]);
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
    int traction = (ss->b[0]->qd || ss->b[0]->dyn);
    int warm = traction && transient && ss->b[0]->ms.ball[0].traction_valid;
    acbb_status rc = warm ? ACBB_OK : acbb_set_solve_shaft(ss, err);
    if (rc != ACBB_OK || !traction) return rc;
    /* The steady solve's first state: one pass, as a bearing's (sim.c). */
    int start = ss->b[0]->qd && ss->setting_up && ss->s.heating
             && ss->s.thermal_mode == ACBB_THERMAL_STEADY;
    for (int pass = 0; pass < (transient || start ? 1 : QD_PASSES); pass++) {
        double change = 0.0;
        if ((rc = stop_check(ss, err)) != ACBB_OK) return rc;
        for (int k = 0; k < ss->n; k++) {
            double ch;
            if ((rc = acbb_simx_traction(ss->b[k], &ch, err)) != ACBB_OK) return rc;
            change = fmax(change, ch);
        }
        if ((rc = acbb_set_solve_shaft(ss, err)) != ACBB_OK || change < QD_TOL) return rc;
    }
    return ACBB_OK;
}

static void distribute(acbb_set_sim *ss)
{
    for (int k = 0; k < ss->n; k++)
        memcpy(ss->b[k]->T, ss->T + ss->ns.off[k],
               sizeof(double) * (size_t)ss->b[k]->nw.n);
}

static void gather_heat(acbb_set_sim *ss, double rel_tol)
{
    ss->heat_in = ss->total = 0.0;
    for (int k = 0; k < ss->n; k++) {
        const acbb_network *nw = &ss->b[k]->nw;
        memcpy(ss->q + ss->ns.off[k], ss->b[k]->q, sizeof(double) * (size_t)nw->n);
        for (int i = 0; i < nw->n; i++) ss->heat_in += ss->b[k]->q[i];
        ss->total += ss->b[k]->loss.total;
    }
    acbb_network_set_sync(&ss->ns, rel_tol);
}

void acbb_set_prepare(acbb_set_sim *ss, int transient, int polishing)
{
    distribute(ss);
    for (int k = 0; k < ss->n; k++) {
        ss->b[k]->transient_pass = transient;
        ss->b[k]->polishing = polishing;
        acbb_simx_expand(ss->b[k]);
    }
    spacer_growth(ss);
}

acbb_status acbb_set_finish(acbb_set_sim *ss, int transient, acbb_error *err)
{
    acbb_status rc = mechanics(ss, transient, err);
    for (int k = 0; k < ss->n && rc == ACBB_OK; k++) rc = acbb_simx_heat(ss->b[k], err);
    for (int k = 0; k < ss->n; k++) ss->b[k]->transient_pass = ss->b[k]->polishing = 0;
    if (rc != ACBB_OK) return rc;
    gather_heat(ss, transient ? SYNC_TOL : 0.0);
    return ACBB_OK;
}

static acbb_status evaluate(acbb_set_sim *ss, int transient, int polishing, acbb_error *err)
{
    acbb_set_prepare(ss, transient, polishing);
    return acbb_set_finish(ss, transient, err);
}

/* ---- run-in schedule (MODEL.md 14; schedule.h) ---- */

/* op's speed and loads into the set's scene, its shaft loads and every
 * bearing's speed (the members are prescribed: no loads of their own). */
static void operating_apply(acbb_set_sim *ss, const acbb_operating *op)
{
    acbb_schedule_apply(&ss->s, op);
    ss->sm.Fa = ss->s.axial_load;
    ss->sm.Fr = ss->s.radial_load;
    for (int k = 0; k < ss->n; k++)
        if (ss->b[k]) ss->b[k]->s.inner_speed = ss->s.inner_speed;
}

/* The schedule's operating point at time t. */
static void schedule_point(acbb_set_sim *ss, double t)
{
    if (!acbb_follows_schedule(&ss->s)) return;
    acbb_operating op;
    acbb_schedule_at(&ss->s, t, &op);
    operating_apply(ss, &op);
}

/* ---- the set as a plant of the stepper (stepper.h) ---- */

static acbb_status plant_stop(void *ctx, acbb_error *err) { return stop_check(ctx, err); }

static acbb_status plant_operate(void *ctx, double t, acbb_error *err)
{
    (void)err;
    schedule_point(ctx, t);
    return ACBB_OK;
}

/* The members keep their own relaxation (1) in the polish. */
static acbb_status plant_evaluate(void *ctx, acbb_pass pass, double relax, acbb_error *err)
{
    (void)relax;
    return evaluate(ctx, pass == ACBB_PASS_TRANSIENT, pass == ACBB_PASS_POLISH, err);
}

static double plant_loss(void *ctx) { return ((acbb_set_sim *)ctx)->total; }

/* Every member's last accepted state into its checkpoint, or back (a
 * member is a plant of its own: stepper.h). */
static void members(acbb_set_sim *ss, int slot, int back)
{
    for (int k = 0; k < ss->n; k++) {
        acbb_plant m;
        acbb_simx_plant(ss->b[k], &m);
        if (back) m.restore(m.ctx, slot);
        else m.save(m.ctx, slot);
    }
}

/* One checkpoint: the set keeps no best iterate (keeps_best 0). */
static void plant_save(void *ctx, int slot)
{
    acbb_set_sim *ss = ctx;
    (void)slot;
    memcpy(ss->T_keep, ss->T, sizeof(double) * (size_t)ss->ns.n);
    ss->sm_keep = ss->sm;
    members(ss, ACBB_KEEP_LAST, 0);
}

static void plant_restore(void *ctx, int slot)
{
    acbb_set_sim *ss = ctx;
    (void)slot;
    memcpy(ss->T, ss->T_keep, sizeof(double) * (size_t)ss->ns.n);
    ss->sm = ss->sm_keep;
    members(ss, ACBB_KEEP_LAST, 1);
    schedule_point(ss, ss->run.time); /* the kept state's */
    distribute(ss);
    gather_heat(ss, 0.0);
}

/* Every bearing's temperature and pressure limits. */
static acbb_status plant_limits(void *ctx, double t, char *what, size_t size)
{
    acbb_set_sim *ss = ctx;
    for (int k = 0; k < ss->n; k++) {
        const acbb_network *nw = &ss->b[k]->nw;
        const double *T = ss->b[k]->T;
        for (int i = 0; i < nw->n; i++)
            if (T[i] > ss->s.temp_limit_C) {
                snprintf(what, size, "bearing %d node %s reached %.1f C (limit "
                         "thermal.temp_limit_C = %.0f C) at t = %.0f s", k, nw->names[i], T[i],
                         ss->s.temp_limit_C, t);
                return ACBB_RUNAWAY;
            }
        double p = acbb_snap_max_pmax(&ss->b[k]->ms);
        if (p > PMAX_LIMIT) {
            snprintf(what, size, "bearing %d contact pressure %.2f GPa exceeds the 4.2 GPa "
                     "static limit at t = %.0f s", k, p * 1e-9, t);
            return ACBB_RUNAWAY;
        }
    }
    return ACBB_OK;
}

/* A rigid set's preload (a spring's is held). */
static double plant_force(void *ctx, int *rigid)
{
    acbb_set_sim *ss = ctx;
    *rigid = !ss->sm.spring;
    return acbb_set_mech_preload(&ss->sm);
}

static acbb_status plant_balance(void *ctx, acbb_error *err)
{
    acbb_set_sim *ss = ctx;
    if (!ss->s.heating) return ACBB_OK;
    return acbb_balance_check(ss->heat_in, acbb_tnet_heat_to_fixed(ss->ns.net, ss->T), err);
}

static void plant_converge(void *ctx)
{
    acbb_set_sim *ss = ctx;
    ss->K_ax = 0.0;
    for (int k = 0; k < ss->n; k++) {
        acbb_plant m;
        acbb_simx_plant(ss->b[k], &m);
        m.converge(m.ctx); /* the member's axial, radial and tilt stiffness */
        if (!(ss->sm.spring && ss->sm.orient[k] < 0)) /* a spring side floats */
            ss->K_ax += ss->b[k]->K_axial;
    }
    acbb_set_solve_shaft(ss, NULL); /* the stiffness probes moved the workspaces */
    /* The caller asked for no stiffness (acbb_sim_opts.skip_stiffness: the
     * members skipped theirs): the nose probes' four shaft solves too. */
    if (ss->b[0]->skip_stiffness)
        ss->K_rad = ss->K_tilt = NAN;
    else
        acbb_set_nose_stiffness(ss);
    if (ss->b[0]->skip_liftoff) return; /* none read (acbb_sim_opts.skip_liftoff) */
    ss->preload = acbb_set_preload_now(ss);
    ss->preload_stale = 0;
    ss->liftoff = acbb_set_liftoff(ss, 0.0); /* from the live one (publish) */
}

void acbb_set_plant(acbb_set_sim *ss, acbb_plant *p)
{
    *p = (acbb_plant){
        .ctx = ss, .s = &ss->s, .net = ss->ns.net, .T = ss->T, .q = ss->q, .n = ss->ns.n,
        .force_name = "the set's preload", .stop = plant_stop, .operate = plant_operate,
        .evaluate = plant_evaluate, .loss = plant_loss, .save = plant_save,
        .restore = plant_restore, .limits = plant_limits, .force = plant_force,
        .balance = plant_balance, .converge = plant_converge,
    };
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

/* The snapshot's flows, preload and lift-off. A steady solve's iterates
 * are no states the set passes through: after a steady iteration
 * (`iterate`) its preload (a shaft solve at zero thrust) waits for the
 * converged state (plant_converge) or the state the run ends in, and its
 * lift-off is searched once, at the converged state (issue 30). */
static void publish(acbb_set_sim *ss, int iterate)
{
    /* heating off solves no network: no heat flows (issue 18) */
    ss->heat_out = ss->s.heating ? acbb_tnet_heat_to_fixed(ss->ns.net, ss->T) : 0.0;
    int steady = ss->s.thermal_mode == ACBB_THERMAL_STEADY;
    if (ss->run.state == ACBB_RUN_RUNNING && iterate && steady) {
        ss->preload_stale = 1;
    } else if (!ss->b[0]->skip_liftoff /* none read (acbb_sim_opts.skip_liftoff) */
               && (ss->run.state == ACBB_RUN_RUNNING || ss->preload_stale)) {
        ss->preload = acbb_set_preload_now(ss);
        ss->preload_stale = 0;
        if (ss->run.state == ACBB_RUN_RUNNING && !steady) live_liftoff(ss);
    }
    for (int k = 0; k < ss->n; k++) { /* the run's outcome, for each member's own snapshot */
        ss->b[k]->run = ss->run;
        ss->b[k]->heat_out = acbb_tnet_heat_to_fixed(ss->b[k]->nw.net, ss->b[k]->T);
    }
}

void acbb_set_publish(acbb_set_sim *ss)
{
    publish(ss, 0);
}

acbb_status acbb_set_sim_step(acbb_set_sim *ss)
{
    if (ss->run.state != ACBB_RUN_RUNNING) return ss->run.status;
    double t0 = acbb_now_ms();
    acbb_plant p;
    acbb_set_plant(ss, &p);
    acbb_status rc = acbb_stepper_step(&p, &ss->run);
    ss->run.wall_ms += acbb_now_ms() - t0;
    publish(ss, 1);
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
    m->shaft_segments = 0;   /* one bearing, not a spindle (its rules are the whole's) */
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
        /* A steady solve's first state only starts it (sim.c): the set's
         * evaluates it, so a member skips its own (issue 30). */
        int steady = s->heating && s->thermal_mode == ACBB_THERMAL_STEADY;
        if (rc == ACBB_OK)
            rc = steady ? acbb_simx_create_member(&m, o, &ss->b[k], err)
                        : acbb_sim_create(&m, o, &ss->b[k], err);
        if (rc == ACBB_WALL_LIMIT) /* the user's bound, not the member's share of it */
            return setup_wall(s, err);
        if (rc != ACBB_OK) return rc;
        acbb_simx_deadline(ss->b[k], 0.0); /* the set's steps hand theirs down */
        nw[k] = &ss->b[k]->nw;
        if (!(ss->scratch[k] = malloc(sizeof *ss->scratch[k]))
            || !(ss->lift_ms[k] = malloc(sizeof *ss->lift_ms[k]))
            || !(ss->memo.ms[k] = malloc(sizeof *ss->memo.ms[k])))
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
    ss->setting_up = 1;
    rc = evaluate(ss, 0, 0, err);
    ss->setting_up = 0;
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
    /* a graded oil's derived values named as sim.c sim_init names them */
    acbb_status rc = acbb_lubricant_explain(s, acbb_scene_validate(s, err), err);
    if (rc != ACBB_OK) return rc;
    acbb_set_sim *ss = calloc(1, sizeof *ss);
    if (!ss) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    ss->s = *s; /* resolved by the caller (sim_set.h) */
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
    acbb_relax_start(&ss->run.relax);
    snprintf(ss->run.msg, sizeof ss->run.msg, "running");
    ss->run.prev_F = acbb_set_mech_preload(&ss->sm);
    acbb_set_publish(ss);
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
        free(ss->memo.ms[k]);
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
    for (int k = 0; k < ss->n; k++) acbb_simx_deadline(ss->b[k], deadline_ms);
}

