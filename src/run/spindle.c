/* acbb — a spindle as a plant of the one stepper (stepper.h, spindle.h;
 * docs/spindle.md "Integration"). Its evaluation: each set's temperatures,
 * expansions and spacer growth (sim_set.c acbb_set_prepare) -> the shaft
 * with both sets as supports (spindle_mech.c) -> each set's own shaft
 * equilibrium under its station's reaction, its ball speeds, losses and
 * sources (acbb_set_finish). The network is the spindle's one network
 * (spindle_net.h: both sets' networks joined to the shaft, housing, motor
 * and coolant), solved by its own solve (the coolant's Schur complement:
 * the plant's solve and capacity); its growth moves a fixed rear set. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "spindle_priv.h"
#include "sim_struct.h"
#include "sim_priv.h"
#include "cancel.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/lubricant.h"

#define SYNC_TOL 1e-2 /* transient steps: resistances lag below this move (sim_set.c's) */

static const char *const set_name[2] = { "front", "rear" };

/* ---- one evaluation ---- */

/* A set's failure named with the set ("spindle front set: ..."). */
static acbb_status named(acbb_status rc, int k, acbb_error *err)
{
    if (rc != ACBB_OK && err) {
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        acbb_error_set(err, rc, "spindle %s set: %s", set_name[k], msg);
    }
    return rc;
}

static void distribute(acbb_spindle_sim *sp)
{
    for (int k = 0; k < 2; k++) {
        acbb_set_sim *ss = sp->st[k].ss;
        memcpy(ss->T, sp->T + sp->off[k], sizeof(double) * (size_t)ss->ns.n);
    }
}

/* The sets' sources at their nodes (the motor's the network adds), their
 * resistances into the network (sync: the transient's lag, 0 none). */
static void gather(acbb_spindle_sim *sp, double sync)
{
    sp->total = sp->heat_in = 0.0;
    memset(sp->q, 0, sizeof(double) * (size_t)sp->n);
    for (int k = 0; k < 2; k++) {
        acbb_set_sim *ss = sp->st[k].ss;
        memcpy(sp->q + sp->off[k], ss->q, sizeof(double) * (size_t)ss->ns.n);
        sp->total += ss->total;
        sp->heat_in += ss->heat_in;
    }
    acbb_spindle_net_sync(sp->net, sync);
}

/* The shaft's growth against the housing between the sets, at T (none
 * without heating or with effects.thermal_expansion off: WTE). */
static void growth(acbb_spindle_sim *sp)
{
    acbb_spindle_growth g = { 0 };
    if (sp->s.heating && sp->s.thermal_expansion) acbb_spindle_net_growth(sp->net, sp->T, &g);
    sp->shift = g.shift_axial;
}

/* The set's own solve against the shaft's station (spindle_priv.h frames):
 * the largest difference, m or rad. */
static void landing(acbb_spindle_sim *sp)
{
    for (int k = 0; k < 2; k++) {
        acbb_spindle_station *t = &sp->st[k];
        t->landing = 0.0;
        if (k == ACBB_REAR && sp->one_support) continue;
        const double *q = t->ss->sm.q, *d = t->w.q; /* the support's last: the station's */
        for (int i = 0; i < 3; i++) t->landing = fmax(t->landing, fabs(q[i] - d[i]));
    }
}

static acbb_status evaluate(acbb_spindle_sim *sp, int transient, int polishing, acbb_error *err)
{
    sp->evaluations++;
    distribute(sp);
    growth(sp);
    for (int k = 0; k < 2; k++) acbb_set_prepare(sp->st[k].ss, transient, polishing);
    acbb_status rc = acbb_spindle_mechanics(sp, err);
    for (int k = 0; k < 2; k++) {
        acbb_set_sim *ss = sp->st[k].ss;
        if (rc == ACBB_OK) rc = named(acbb_set_finish(ss, transient, err), k, err);
        for (int b = 0; b < ss->n; b++) ss->b[b]->transient_pass = ss->b[b]->polishing = 0;
        ss->sm.hold[0] = 0; /* the set's probes see it free (spindle_mech.c set_loads) */
    }
    if (rc != ACBB_OK) return rc;
    landing(sp);
    gather(sp, transient ? SYNC_TOL : 0.0);
    return ACBB_OK;
}

/* ---- the plant (stepper.h) ---- */

static acbb_status stop_check(const acbb_spindle_sim *sp, acbb_error *err)
{
    if (acbb_cancelled(sp->cancel))
        return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
    if (sp->deadline_ms > 0.0 && acbb_now_ms() >= sp->deadline_ms)
        return acbb_error_set(err, ACBB_WALL_LIMIT, "wall-clock bound fidelity.max_wall_s = "
                              "%g s reached; last good state kept", sp->s.max_wall_s);
    return ACBB_OK;
}

static acbb_status plant_stop(void *ctx, acbb_error *err) { return stop_check(ctx, err); }

/* The schedule's speed and nose loads at time t (the sets follow the
 * spindle: their scenes have no rows). */
static void schedule_point(acbb_spindle_sim *sp, double t)
{
    if (!acbb_follows_schedule(&sp->s)) return;
    acbb_operating op;
    acbb_schedule_at(&sp->s, t, &op);
    acbb_schedule_apply(&sp->s, &op);
    for (int k = 0; k < 2; k++) {
        acbb_set_sim *ss = sp->st[k].ss;
        ss->s.inner_speed = sp->s.inner_speed;
        for (int b = 0; b < ss->n; b++) ss->b[b]->s.inner_speed = sp->s.inner_speed;
    }
}

static acbb_status plant_operate(void *ctx, double t, acbb_error *err)
{
    (void)err;
    schedule_point(ctx, t);
    return ACBB_OK;
}

static acbb_status plant_evaluate(void *ctx, acbb_pass pass, double relax, acbb_error *err)
{
    (void)relax;
    return evaluate(ctx, pass == ACBB_PASS_TRANSIENT, pass == ACBB_PASS_POLISH, err);
}

static double plant_loss(void *ctx) { return ((acbb_spindle_sim *)ctx)->total; }

static void set_plant(acbb_spindle_sim *sp, int k, acbb_plant *p)
{
    acbb_set_plant(sp->st[k].ss, p);
}

/* Each slot its own checkpoint (acbb_spindle_keep). The sleeve's rest
 * position follows the state saved or restored: the next evaluation's
 * sleeve starts there (spindle_mech.c). */
static void plant_save(void *ctx, int slot)
{
    acbb_spindle_sim *sp = ctx;
    acbb_spindle_keep *c = &sp->keep[slot == ACBB_KEEP_BEST];
    acbb_spindle_station *rear = &sp->st[ACBB_REAR];
    memcpy(c->T, sp->T, sizeof(double) * (size_t)sp->n);
    c->res = sp->res;
    c->slip = rear->slip_rest = rear->slip;
    c->slide = rear->slide_rest = rear->slide;
    for (int k = 0; k < 2; k++) {
        acbb_plant p;
        set_plant(sp, k, &p);
        p.save(p.ctx, slot);
    }
}

static void plant_restore(void *ctx, int slot)
{
    acbb_spindle_sim *sp = ctx;
    const acbb_spindle_keep *c = &sp->keep[slot == ACBB_KEEP_BEST];
    acbb_spindle_station *rear = &sp->st[ACBB_REAR];
    memcpy(sp->T, c->T, sizeof(double) * (size_t)sp->n);
    sp->res = c->res;
    rear->slip = rear->slip_rest = c->slip;
    rear->slide = rear->slide_rest = c->slide;
    schedule_point(sp, sp->run.time);
    for (int k = 0; k < 2; k++) {
        acbb_plant p;
        set_plant(sp, k, &p);
        p.restore(p.ctx, slot);
        sp->st[k].load[0] = sp->st[k].ss->sm.Fa;
        sp->st[k].load[1] = sp->st[k].ss->sm.Fr;
        sp->st[k].load[2] = sp->st[k].ss->sm.M;
    }
    growth(sp);
    gather(sp, 0.0);
}

/* The hottest node over thermal.temp_limit_C: a spindle cell (named by
 * its part and x) or a set's bearing node (named by set, bearing and
 * node, as a set names it); *T_max its temperature. 0: none over. A
 * bearing node that became a spindle cell reads the cell's temperature
 * and is not hotter than it: the cell is named. */
static int hottest(const acbb_spindle_sim *sp, char *name, size_t size, double *T_max)
{
    int found = 0;
    *T_max = sp->s.temp_limit_C;
    for (int i = 0; i < acbb_spindle_net_own_nodes(sp->net); i++)
        if (sp->T[i] > *T_max) {
            *T_max = sp->T[i];
            acbb_spindle_net_node_name(sp->net, i, name, size);
            found = 1;
        }
    for (int k = 0; k < 2; k++) {
        const acbb_set_sim *ss = sp->st[k].ss;
        for (int b = 0; b < ss->n; b++) {
            const acbb_network *nw = &ss->b[b]->nw;
            for (int i = 0; i < nw->n; i++)
                if (ss->b[b]->T[i] > *T_max) {
                    *T_max = ss->b[b]->T[i];
                    snprintf(name, size, "%s set: bearing %d node %s", set_name[k], b,
                             nw->names[i]);
                    found = 1;
                }
        }
    }
    return found;
}

/* The hottest node over the temperature limit, then the sets' other
 * limits (contact pressure). */
static acbb_status plant_limits(void *ctx, double t, char *what, size_t size)
{
    acbb_spindle_sim *sp = ctx;
    char name[160];
    double T;
    if (hottest(sp, name, sizeof name, &T)) {
        snprintf(what, size, "%s reached %.1f C (limit thermal.temp_limit_C = %.0f C) at t = "
                 "%.0f s", name, T, sp->s.temp_limit_C, t);
        return ACBB_RUNAWAY;
    }
    for (int k = 0; k < 2; k++) {
        acbb_plant p;
        char d[200];
        set_plant(sp, k, &p);
        if (p.limits(p.ctx, t, d, sizeof d) != ACBB_OK) {
            snprintf(what, size, "%s set: %s", set_name[k], d);
            return ACBB_RUNAWAY;
        }
    }
    return ACBB_OK;
}

/* Both sets' preloads, summed, when either is rigid (the growth of a
 * rigid preload is the runaway of MODEL.md 9: the front set's, or a rigid
 * rear pair's, as its rings heat; the stepper watches one force, and the
 * sum of a runaway preload and a bounded one grows ever faster too; a
 * spring's or a sleeve's share is bounded), else not watched. */
static double plant_force(void *ctx, int *rigid)
{
    acbb_spindle_sim *sp = ctx;
    double F = 0.0;
    *rigid = 0;
    for (int k = 0; k < 2; k++) {
        acbb_plant p;
        int r;
        set_plant(sp, k, &p);
        F += p.force(p.ctx, &r);
        *rigid |= r;
    }
    return F;
}

/* Every source (the bearings' and the motor's) and what leaves: to the air
 * and the bearings' fixed boundaries, and with the coolant. */
static double heat_sources(const acbb_spindle_sim *sp)
{
    return sp->heat_in + sp->s.motor_rotor_loss + sp->s.motor_stator_loss;
}

static double heat_to_fixed(const acbb_spindle_sim *sp)
{
    acbb_spindle_flows f;
    acbb_spindle_net_flows(sp->net, sp->T, &f);
    return f.Q_air + f.Q_advected;
}

static acbb_status plant_balance(void *ctx, acbb_error *err)
{
    acbb_spindle_sim *sp = ctx;
    if (!sp->s.heating) return ACBB_OK;
    return acbb_balance_check(heat_sources(sp), heat_to_fixed(sp), err);
}

static void plant_converge(void *ctx)
{
    acbb_spindle_sim *sp = ctx;
    for (int k = 0; k < 2; k++) {
        acbb_plant p;
        set_plant(sp, k, &p);
        p.converge(p.ctx);
    }
}

/* The spindle's network: a backward-Euler step or the steady state. */
static acbb_status plant_solve(void *ctx, const double *q, double dt, double *Tn)
{
    acbb_spindle_sim *sp = ctx;
    return acbb_spindle_net_solve(sp->net, q, dt, Tn, NULL);
}

static double plant_capacity(void *ctx, int i)
{
    return acbb_spindle_net_capacity(((acbb_spindle_sim *)ctx)->net, i);
}

void acbb_spindle_plant(acbb_spindle_sim *sp, acbb_plant *p)
{
    *p = (acbb_plant){
        .ctx = sp, .s = &sp->s, .net = NULL, .T = sp->T, .q = sp->q, .n = sp->n,
        .force_name = "the sum of the sets' preloads (front + rear)", .stop = plant_stop, .operate = plant_operate,
        .evaluate = plant_evaluate, .loss = plant_loss, .save = plant_save,
        .restore = plant_restore, .limits = plant_limits, .force = plant_force,
        .balance = plant_balance, .converge = plant_converge, .solve = plant_solve,
        .capacity = plant_capacity,
    };
}

/* What the snapshots read: each set's run state, heat flows and preload. */
static void publish(acbb_spindle_sim *sp)
{
    for (int k = 0; k < 2; k++) {
        sp->st[k].ss->run = sp->run;
        acbb_set_publish(sp->st[k].ss);
    }
    acbb_spindle_preloads(sp);
    sp->heat_out = sp->s.heating ? heat_to_fixed(sp) : 0.0;
    sp->heat_all = sp->s.heating ? heat_sources(sp) : 0.0;
}

acbb_status acbb_spindle_sim_step(acbb_spindle_sim *sp)
{
    if (sp->run.state != ACBB_RUN_RUNNING) return sp->run.status;
    double t0 = acbb_now_ms();
    acbb_plant p;
    acbb_spindle_plant(sp, &p);
    acbb_status rc = acbb_stepper_step(&p, &sp->run);
    sp->run.wall_ms += acbb_now_ms() - t0;
    publish(sp);
    return rc;
}

/* ---- set-up ---- */

/* The front set: the scene without its shaft, loads at its centre (for
 * its first state only, and only those of the signs a scene takes: the
 * spindle's first evaluation puts the shaft's on it). */
static void front_scene(const acbb_scene *s, const double L[3], acbb_scene *f)
{
    *f = *s;
    f->shaft_segments = 0;
    f->housing_segments = 0;
    f->set_load_offset = 0.0;
    f->axial_load = fmax(L[0], 0.0);
    f->radial_load = fmax(L[1], 0.0);
    f->moment_load = f->radial_load > 0.0 ? L[2] : 0.0;
    f->schedule_n = 0; /* the spindle follows the rows */
}

/* The rear set: the same bearing in the rear arrangement, a pair held by
 * its rigid (spacer) preload. A fixed rear set is mirrored (read from the
 * rear end: docs/spindle.md "Rear set"): with the front set it makes an
 * "O" spindle that locates the shaft both ways; a one-way rear set so
 * turned is preloaded against the front by rear_preload_N. */
static void rear_scene(const acbb_scene *s, const double L[3], acbb_scene *r)
{
    front_scene(s, L, r);
    r->set_arrangement = s->spindle_rear_arrangement;
    r->set_n_bearings = 0;
    r->set_spacing = s->spindle_rear_spacing;
    r->set_inner_spacer = r->set_outer_spacer = 0.0;
    r->preload = ACBB_PRELOAD_DISPLACEMENT;
    if (s->spindle_rear_preload > 0.0) r->preload_force = s->spindle_rear_preload;
    r->set_mirrored = s->spindle_rear_support == ACBB_REAR_FIXED;
}

static acbb_status make_set(const acbb_scene *m, const acbb_sim_opts *o, int k,
                            acbb_set_sim **out, acbb_error *err)
{
    return named(acbb_set_sim_new(m, o, out, err), k, err);
}

/* The one network over both sets (each member at its own x), every node
 * at the ambient and the coolant at its inlet. */
static acbb_status network(acbb_spindle_sim *sp, acbb_error *err)
{
    acbb_spindle_net_part part[2];
    const double x[2] = { sp->s.spindle_front_x, sp->s.spindle_rear_x };
    for (int k = 0; k < 2; k++) {
        acbb_set_sim *ss = sp->st[k].ss;
        part[k] = (acbb_spindle_net_part){ .set = &ss->ns, .scene = &ss->s };
        for (int b = 0; b < ss->n; b++) part[k].x[b] = x[k] + ss->sm.x[b];
    }
    acbb_status rc = acbb_spindle_net_build(&sp->s, part, &sp->net, err);
    if (rc != ACBB_OK) return rc;
    sp->n = acbb_spindle_net_nodes(sp->net);
    if (sp->n > ACBB_SPINDLE_NMAX)
        return acbb_error_set(err, ACBB_EINVAL, "spindle: %d thermal nodes, at most %d",
                              sp->n, ACBB_SPINDLE_NMAX);
    for (int k = 0; k < 2; k++) sp->off[k] = acbb_spindle_net_part_offset(sp->net, k);
    acbb_spindle_net_init(sp->net, sp->T);
    return ACBB_OK;
}

/* The first state, cold (every node at the ambient): evaluated again
 * until the nose stops moving (each evaluation's ball speeds are the one
 * before's: the first is a start), to COLD_TOL or COLD_MAX evaluations;
 * its nose_u is the nose drift's reference (spindle_view.c). */
#define COLD_TOL 1e-12 /* m: the shaft solve's floor (spindle_mech.c) */
#define COLD_MAX 20
static acbb_status cold_state(acbb_spindle_sim *sp, acbb_error *err)
{
    acbb_status rc = evaluate(sp, 0, 0, err);
    double u = sp->res.nose[0];
    for (int i = 0; i < COLD_MAX && rc == ACBB_OK; i++) {
        rc = evaluate(sp, 0, 0, err);
        double du = sp->res.nose[0] - u;
        u = sp->res.nose[0];
        if (fabs(du) <= COLD_TOL) break;
    }
    sp->nose_u_cold = u;
    return rc;
}

static acbb_status set_up(acbb_spindle_sim *sp, const acbb_sim_opts *o, acbb_error *err)
{
    const acbb_scene *s = &sp->s;
    double L[2][3];
    acbb_scene m;
    acbb_spindle_initial_loads(s, sp->one_support, L);
    for (int k = 0; k < 2; k++) {
        if (k == ACBB_FRONT) front_scene(s, L[k], &m);
        else rear_scene(s, L[k], &m);
        sp->st[k] = (acbb_spindle_station){ .sp = sp, .k = k };
        acbb_status rc = make_set(&m, o, k, &sp->st[k].ss, err);
        if (rc != ACBB_OK) return rc;
    }
    acbb_status rc = network(sp, err);
    if (rc == ACBB_OK) rc = acbb_spindle_beam_build(sp, err);
    if (rc != ACBB_OK) return rc;
    acbb_spindle_sim_deadline(sp, s->max_wall_s > 0.0 ? acbb_now_ms() + 1e3 * s->max_wall_s
                                                      : 0.0);
    rc = cold_state(sp, err);
    acbb_spindle_sim_deadline(sp, 0.0); /* the run loop arms each step's */
    return rc;
}

acbb_status acbb_spindle_sim_new(const acbb_scene *s, const acbb_sim_opts *o, int one_support,
                                 acbb_spindle_sim **out, acbb_error *err)
{
    acbb_error e2 = { "" };
    if (!err) err = &e2;
    /* a graded oil's derived values named as sim.c sim_init names them */
    acbb_status rc = acbb_lubricant_explain(s, acbb_scene_validate(s, err), err);
    if (rc != ACBB_OK) return rc;
    acbb_spindle_sim *sp = calloc(1, sizeof *sp);
    if (!sp) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    sp->s = *s;
    sp->one_support = one_support;
    acbb_operating op; /* the first row, or the last for the steady solve (sim.c sim_init) */
    if (sp->s.thermal_mode == ACBB_THERMAL_STEADY || !sp->s.heating)
        acbb_schedule_final(&sp->s, &op);
    else
        acbb_schedule_at(&sp->s, 0.0, &op);
    acbb_schedule_apply(&sp->s, &op);
    sp->cancel = o->cancel;
    rc = set_up(sp, o, err);
    if (rc != ACBB_OK) {
        acbb_spindle_sim_free(sp);
        return rc;
    }
    sp->run.state = ACBB_RUN_RUNNING;
    sp->run.dt = s->time_step;
    acbb_relax_start(&sp->run.relax);
    snprintf(sp->run.msg, sizeof sp->run.msg, "running");
    int rigid;
    sp->run.prev_F = plant_force(sp, &rigid);
    publish(sp);
    *out = sp;
    return ACBB_OK;
}

void acbb_spindle_sim_free(acbb_spindle_sim *sp)
{
    if (!sp) return;
    acbb_shaft_beam_free(sp->beam);
    free(sp->beam_start);
    acbb_spindle_net_free(sp->net); /* before the sets it refers to */
    for (int k = 0; k < 2; k++) acbb_set_sim_free(sp->st[k].ss);
    free(sp);
}

acbb_run_state acbb_spindle_sim_outcome(const acbb_spindle_sim *sp, acbb_status *status,
                                        long *iter)
{
    *status = sp->run.status;
    *iter = sp->run.iter;
    return sp->run.state;
}

void acbb_spindle_sim_cancel(acbb_spindle_sim *sp, const atomic_int *cancel)
{
    sp->cancel = cancel;
    for (int k = 0; k < 2; k++) acbb_set_sim_cancel(sp->st[k].ss, cancel);
}

void acbb_spindle_sim_deadline(acbb_spindle_sim *sp, double deadline_ms)
{
    sp->deadline_ms = deadline_ms;
    for (int k = 0; k < 2; k++)
        if (sp->st[k].ss) acbb_set_sim_deadline(sp->st[k].ss, deadline_ms);
}
