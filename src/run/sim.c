/* acbb — one bearing: its set-up and the run loop around the one stepper
 * (stepper.c: wall-clock bound, cancel, hooks; a bearing set's too). The
 * bearing as a plant of that stepper is sim_plant.c, one evaluation of
 * its state sim_eval.c, the snapshot's views sim_snapshot.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <assert.h>
#include "acbb/sim.h"
#include "acbb/tools/life_eval.h"
#include "acbb/tools/measure.h"
#include "stiffness.h"
#include "mechanics.h"
#include "network.h"
#include "acbb/tools/fidelity.h"
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
#include "sim_set_priv.h"
#include "steady_polish.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/lubricant.h"
#include "stepper.h"


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
    double left = 1e3 * sim->s.max_wall_s - sim->setup_ms - sim->run.wall_ms;
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

/* A set steps in sim_set.c, a spindle in spindle.c; the run loop reads
 * their outcome here. */
static acbb_status set_step(acbb_sim *sim)
{
    acbb_status rc;
    if (sim->spindle) {
        rc = acbb_spindle_sim_step(sim->spindle);
        sim->run.state = acbb_spindle_sim_outcome(sim->spindle, &sim->run.status,
                                                  &sim->run.iter);
        return rc;
    }
    rc = acbb_set_sim_step(sim->set);
    sim->run.state = acbb_set_sim_outcome(sim->set, &sim->run.status, &sim->run.iter);
    return rc;
}

static acbb_status step_body(acbb_sim *sim)
{
    if (sim->run.state != ACBB_RUN_RUNNING)
        return sim->run.status;
    arm_bound(sim);
    if (sim->set) acbb_set_sim_deadline(sim->set, sim->deadline_ms);
    if (sim->spindle) acbb_spindle_sim_deadline(sim->spindle, sim->deadline_ms);
    double t0 = acbb_now_ms();
    acbb_plant p;
    acbb_status rc;
    if (sim->set || sim->spindle) {
        rc = set_step(sim);
    } else {
        acbb_simx_plant(sim, &p);
        rc = acbb_stepper_step(&p, &sim->run);
    }
    sim->run.wall_ms += acbb_now_ms() - t0; /* for wall_limit; a set reports its own */
    return rc;
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

acbb_run_state acbb_sim_state(const acbb_sim *sim) { return sim->run.state; }

acbb_status acbb_sim_run(acbb_sim *sim)
{
    return acbb_sim_drive(sim, NULL);
}

static int call_hook(acbb_sim *sim, const acbb_run_ctl *ctl)
{
    if (!ctl || !ctl->hook || sim->run.iter == sim->reported) return 0;
    sim->reported = sim->run.iter;
    return ctl->hook(ctl->ctx, sim);
}

/* fidelity.max_wall_s (issue 20 item 8): the set-up's and the steps' own
 * computing time (hooks and pauses excluded) past the bound ends the run
 * with the last step's state (a step cut short inside rolls back to it).
 * Read only when a bound is set, so without one nothing depends on timing. */
static int wall_limit(acbb_sim *sim)
{
    if (sim->s.max_wall_s <= 0 || sim->run.state != ACBB_RUN_RUNNING ||
        sim->setup_ms + sim->run.wall_ms < 1e3 * sim->s.max_wall_s)
        return 0;
    acbb_stepper_fail(&sim->run, &sim->s, ACBB_WALL_LIMIT, "");
    return 1;
}

static acbb_status drive_body(acbb_sim *sim, const acbb_run_ctl *ctl)
{
    if (ctl && ctl->cancel) {
        sim->cancel = ctl->cancel;
        if (sim->dyn) acbb_dyn_set_cancel(sim->dyn, sim->cancel);
        if (sim->set) acbb_set_sim_cancel(sim->set, sim->cancel);
        if (sim->spindle) acbb_spindle_sim_cancel(sim->spindle, sim->cancel);
    }
    if (call_hook(sim, ctl)) return sim->run.status;
    while (sim->run.state == ACBB_RUN_RUNNING) {
        if (acbb_cancelled(sim->cancel))
            return acbb_stepper_fail(&sim->run, &sim->s, ACBB_CANCELLED,
                                     "cancelled; last good state kept");
        step_body(sim);
        if (wall_limit(sim)) break;
        if (call_hook(sim, ctl)) break;
    }
    return sim->run.status;
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
static acbb_status initial_mechanics(acbb_sim *sim, const acbb_mech_state *warm,
                                     acbb_error *err)
{
    if (warm) { /* a converged state of a scene that differs in values only */
        acbb_mech_state_copy(&sim->ms, warm);
        acbb_mech_adopt_state(sim->mech, &sim->ms);
        return ACBB_OK;
    }
    acbb_status rc = acbb_mech_init_state(sim->mech, &sim->ms, err);
    if (rc != ACBB_OK) return rc;
    for (int k = 1; k <= 4 && sim->s.inner_speed > 0.0; k++) {
        sim->work.mechanics_solves++;
        rc = acbb_mech_solve(sim->mech, sim->s.inner_speed * k / 4.0, NULL, &sim->ms, err);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

/* The set-up's mechanics of a transient from another run's (acbb_sim_setup)
 * when this workspace is built the same at the same speed, else solved
 * here; a run that keeps its own (keep_setup) copies the workspace as
 * built and as left. The work counters count the solves made here only. */
static int setup_fits(const acbb_sim *sim, const acbb_sim_setup *from)
{
    return from && memcmp(&from->omega, &sim->s.inner_speed, sizeof from->omega) == 0
        && from->ms.n == sim->s.n_balls && acbb_mech_same(sim->mech, from->built);
}

static void setup_free(acbb_sim_setup *u)
{
    if (!u) return;
    acbb_simx_first_free(u->first);
    acbb_mech_free(u->built);
    acbb_mech_free(u->ran);
    free(u);
}

static acbb_status transient_mechanics(acbb_sim *sim, const acbb_sim_setup *from,
                                       acbb_error *err)
{
    if (setup_fits(sim, from)) {
        acbb_mech_adopt(sim->mech, from->ran);
        acbb_mech_state_copy(&sim->ms, &from->ms);
        sim->setup_from = from; /* its first state too, if the same (sim_first.c) */
        return ACBB_OK;
    }
    acbb_sim_setup *u = sim->keep_setup ? calloc(1, sizeof *u) : NULL;
    if (u && !(u->built = acbb_mech_keep(sim->mech))) {
        free(u);
        u = NULL;
    }
    acbb_status rc = initial_mechanics(sim, NULL, err);
    if (u && (rc != ACBB_OK || !(u->ran = acbb_mech_keep(sim->mech)))) {
        setup_free(u);
        u = NULL;
    }
    if (u) {
        u->omega = sim->s.inner_speed;
        acbb_mech_state_copy(&u->ms, &sim->ms);
        sim->setup = u;
    }
    return rc;
}

/* The bound met in the set-up: no state yet, nothing to keep (one text for
 * a bearing and a spindle; a set's is sim_set.c setup_wall's, the same). */
static acbb_status setup_wall(const acbb_scene *s, acbb_error *err)
{
    return acbb_error_set(err, ACBB_WALL_LIMIT, "wall-clock bound fidelity.max_wall_s = %g s "
                          "reached during the set-up, before the first state", s->max_wall_s);
}

/* Clear the ball records [from, to) of sim's mechanics and losses. */
static void clear_balls(acbb_sim *sim, int from, int to)
{
    to = to < ACBB_MAX_BALLS ? to : ACBB_MAX_BALLS;
    if (from >= to) return;
    memset(&sim->ms.ball[from], 0, (size_t)(to - from) * sizeof sim->ms.ball[0]);
    memset(&sim->bl[from], 0, (size_t)(to - from) * sizeof sim->bl[0]);
}

/* A new Sim, all zero but the ball records past the scene's n balls in
 * its mechanics and losses (60 % of it: issue 30, 0.08 G of `report
 * --sensitivity`): no code reads a ball past ms.n (every loop over the
 * balls ends at ms.n, or the solved ones before it; the checkpoints keep
 * and best are malloc'd the same way, and tests/test_study.c runs with
 * those records poisoned); sim_init clears more if the resolved scene
 * has more balls (a designation's count). */
static acbb_sim *sim_alloc(int n)
{
    acbb_sim *sim = malloc(sizeof *sim);
    if (!sim) return NULL;
    n = n < 0 ? 0 : n < ACBB_MAX_BALLS ? n : ACBB_MAX_BALLS;
    char *p = (char *)sim, *ms_tail = (char *)&sim->ms.ball[n], *bl = (char *)sim->bl,
         *bl_tail = (char *)&sim->bl[n];
    char *ms_end = (char *)(&sim->ms + 1), *bl_end = (char *)(sim->bl + ACBB_MAX_BALLS);
    memset(p, 0, (size_t)(ms_tail - p));
    memset(ms_end, 0, (size_t)(bl - ms_end));
    memset(bl, 0, (size_t)(bl_tail - bl));
    memset(bl_end, 0, (size_t)(p + sizeof *sim - bl_end));
    sim->cleared_balls = n;
    return sim;
}

/* The Level-2 workspace: a batch's spare renewed, else a new one. */
static acbb_status qd_make(acbb_sim *sim, int grid)
{
    if (!sim->qd_idle) return acbb_qd_new(grid, &sim->qd);
    sim->qd = sim->qd_idle; /* freed with the Sim even if the renewal fails */
    sim->qd_idle = NULL;
    return acbb_qd_renew(sim->qd, grid);
}

static acbb_status sim_init(acbb_sim *sim, const acbb_scene *s, const double *T_warm,
                            const acbb_warm *w, acbb_error *err)
{
    /* The scene resolved once (fidelity.h acbb_scene_resolve); the run
     * then applies its operating point to its own copy. */
    acbb_scene_resolve(s, &sim->resolved, NULL);
    sim->s = sim->resolved;
    s = &sim->s;
    clear_balls(sim, sim->cleared_balls, s->n_balls);
    sim->cleared_balls = s->n_balls > sim->cleared_balls ? s->n_balls : sim->cleared_balls;
    if (!sim->skip_life) /* once per scene, not per snapshot */
        acbb_life_static_basis(s, &sim->life_basis);
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
    rc = sim->mech ? acbb_mech_renew(s, sim->mech, err) : acbb_mech_new(s, &sim->mech, err);
    if (rc != ACBB_OK) return rc;
    if (s->model == ACBB_MODEL_QUASI_DYNAMIC && qd_make(sim, s->contact_grid) != ACBB_OK)
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (s->model == ACBB_MODEL_DYNAMIC && (acbb_dyn_new(s->contact_grid, &sim->dyn) != ACBB_OK
                                           || acbb_dyn_set_threads(sim->dyn, sim->threads)
                                                  != ACBB_OK))
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (sim->dyn) acbb_dyn_set_cancel(sim->dyn, sim->cancel);
    arm_bound(sim); /* now that the dynamic workspace exists */
    if (s->preload == ACBB_PRELOAD_DISPLACEMENT && (rc = fix_preload(sim, err)) != ACBB_OK)
        return rc;
    /* A transient starts from ambient: of w only its set-up (above). */
    int transient = s->thermal_mode != ACBB_THERMAL_STEADY;
    const acbb_sim_setup *from = w && transient ? w->setup : NULL;
    if (transient || (w && w->n_nodes != sim->nw.n)) w = NULL;
    sim->warm_started = w != NULL;
    if (w) T_warm = w->T;
    for (int i = 0; i < sim->nw.n; i++)
        sim->T[i] = T_warm ? T_warm[i] : s->ambient_C;
    sim->setting_up = 1;
    rc = w || T_warm || !transient ? initial_mechanics(sim, w ? &w->ms : NULL, err)
                                   : transient_mechanics(sim, from, err);
    if (rc == ACBB_OK && !sim->no_first_state)
        rc = acbb_simx_evaluate(sim, err);
    sim->setting_up = 0;
    sim->setup_from = NULL; /* the caller's */
    sim->setup_ms = acbb_now_ms() - t0;
    if (rc == ACBB_WALL_LIMIT) return setup_wall(s, err);
    if (rc != ACBB_OK) return rc;
    sim->run.dt = s->time_step;
    acbb_relax_start(&sim->run.relax);
    sim->reported = -1;
    sim->run.state = ACBB_RUN_RUNNING;
    sim->run.status = ACBB_OK;
        sim->run.prev_F = sim->ms.Fx;
    acbb_simx_energy(sim);
    snprintf(sim->run.msg, sizeof sim->run.msg, "running");
    return ACBB_OK;
}

static void sim_release(acbb_sim *sim)
{
    acbb_mech_free(sim->mech);
    sim->mech = NULL;
    acbb_qd_free(sim->qd);
    sim->qd = NULL;
    acbb_qd_free(sim->qd_idle);
    sim->qd_idle = NULL;
    acbb_dyn_free(sim->dyn);
    sim->dyn = NULL;
    if (sim->nw.net) acbb_network_free(&sim->nw);
    sim->nw.net = NULL;
}

/* A bearing set: its members and stepper live in sim_set.c. */
static acbb_status set_init(acbb_sim *sim, const acbb_scene *s, acbb_error *err)
{
    acbb_scene_resolve(s, &sim->resolved, NULL);
    sim->s = *s;
    acbb_life_static_basis(s, &sim->life_basis);
    acbb_sim_opts o = { .cancel = sim->cancel, .threads = sim->threads,
                        .skip_stiffness = sim->skip_stiffness,
                        .skip_liftoff = sim->skip_liftoff };
    acbb_status rc = acbb_set_sim_new(&sim->resolved, &o, &sim->set, err);
    if (rc != ACBB_OK) return rc;
    sim->run.state = acbb_set_sim_outcome(sim->set, &sim->run.status, &sim->run.iter);
    sim->reported = -1;
    return ACBB_OK;
}

/* A spindle: its sets, shaft and stepper live in spindle.c. */
static acbb_status spindle_init(acbb_sim *sim, const acbb_scene *s, acbb_error *err)
{
    acbb_scene_resolve(s, &sim->resolved, NULL);
    sim->s = *s;
    acbb_life_static_basis(s, &sim->life_basis);
    acbb_sim_opts o = { .cancel = sim->cancel, .threads = sim->threads,
                        .skip_stiffness = sim->skip_stiffness };
    acbb_status rc = acbb_spindle_sim_new(&sim->resolved, &o, 0, &sim->spindle, err);
    if (rc == ACBB_WALL_LIMIT) return setup_wall(s, err); /* not "a set: ...; kept" */
    if (rc != ACBB_OK) return rc;
    sim->run.state = acbb_spindle_sim_outcome(sim->spindle, &sim->run.status, &sim->run.iter);
    sim->reported = -1;
    return ACBB_OK;
}

/* w can start a Sim of scene s: saved from a converged single bearing with
 * the same network, balls, model and heating (acbb_simx_warm_save). */
static int warm_fits(const acbb_warm *w, const acbb_scene *s)
{
    return w && s->set_arrangement == ACBB_SET_SINGLE && s->network == w->network
        && s->n_balls == w->n_balls && s->model == w->model && s->heating == w->heating;
}

static acbb_status create_body(const acbb_scene *s, const acbb_sim_opts *o, int member,
                               const acbb_simx_start *start, acbb_sim **out, acbb_error *err)
{
    static const acbb_simx_start cold;
    if (!start) start = &cold;
    const acbb_warm *w = warm_fits(start->warm, s) ? start->warm : NULL;
    acbb_sim *sim = sim_alloc(s->n_balls);
    if (!sim || !(sim->keep = malloc(sizeof *sim->keep))
        || !(sim->best = malloc(sizeof *sim->best))) {
        if (sim) free(sim->keep);
        free(sim);
        acbb_simx_spare_free(start->spare);
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    }
    sim->mech = start->spare.mech; /* renewed by sim_init; freed with the Sim */
    sim->qd_idle = start->spare.qd; /* taken by sim_init at Level 2 (qd_make) */
    sim->cancel = o->cancel;
    sim->polish_relax = 1.0;
    sim->threads = o->threads > 0 ? o->threads : DYN_THREADS;
    sim->skip_stiffness = o->skip_stiffness;
    sim->skip_life = o->skip_life;
    sim->skip_liftoff = o->skip_liftoff;
    sim->no_first_state = member;
    sim->keep_setup = start->keep_setup;
    double t0 = acbb_now_ms();
    acbb_status rc = s->shaft_segments > 0 ? spindle_init(sim, s, err)
                   : s->set_arrangement != ACBB_SET_SINGLE ? set_init(sim, s, err)
                   : sim_init(sim, s, NULL, w, err);
    if (sim->set || sim->spindle) sim->setup_ms = acbb_now_ms() - t0; /* sim_init times its own */
    if (rc != ACBB_OK) {
        int warm = sim->warm_started;
        acbb_sim_free(sim);
        /* A warm start that failed starts again cold (unless stopped). */
        if (warm && rc != ACBB_CANCELLED && rc != ACBB_WALL_LIMIT) {
            if (err) *err = (acbb_error){ 0 };
            acbb_simx_start again = { .keep_setup = start->keep_setup };
            return create_body(s, o, member, &again, out, err);
        }
        return rc;
    }
    *out = sim;
    return ACBB_OK;
}

const acbb_scene *acbb_sim_scene(const acbb_sim *sim)
{
    return &sim->resolved;
}

acbb_status acbb_sim_create(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                            acbb_error *err)
{
    static const acbb_sim_opts defaults; /* o == NULL: all zero */
    acbb_gsl_enter();
    acbb_status rc = create_body(s, o ? o : &defaults, 0, NULL, out, err);
    acbb_gsl_leave();
    return rc;
}

acbb_status acbb_simx_create_member(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                                    acbb_error *err)
{
    return create_body(s, o, 1, NULL, out, err);
}

acbb_status acbb_simx_create_from(const acbb_scene *s, const acbb_sim_opts *o,
                                  const acbb_simx_start *st, acbb_sim **out, acbb_error *err)
{
    acbb_gsl_enter();
    acbb_status rc = create_body(s, o, 0, st, out, err);
    acbb_gsl_leave();
    return rc;
}

acbb_warm *acbb_simx_warm_save(acbb_sim *sim)
{
    if (sim->set || sim->run.state != ACBB_RUN_CONVERGED) return NULL;
    acbb_warm *w = malloc(sizeof *w);
    if (!w) return NULL;
    *w = (acbb_warm){ .network = sim->s.network, .model = sim->s.model,
                      .n_balls = sim->s.n_balls, .heating = sim->s.heating,
                      .n_nodes = sim->nw.n, .setup = sim->setup };
    sim->setup = NULL;
    memcpy(w->T, sim->T, sizeof w->T);
    acbb_mech_state_copy(&w->ms, &sim->ms);
    return w;
}

void acbb_simx_warm_free(acbb_warm *w)
{
    if (w) setup_free(w->setup);
    free(w);
}

acbb_simx_spare acbb_simx_free_spare(acbb_sim *sim)
{
    acbb_simx_spare sp = { 0 };
    if (!sim) return sp;
    acbb_qd **q = sim->qd ? &sim->qd : &sim->qd_idle;
    sp = (acbb_simx_spare){ sim->mech, *q };
    sim->mech = NULL;
    *q = NULL;
    acbb_sim_free(sim);
    return sp;
}

void acbb_simx_spare_free(acbb_simx_spare sp)
{
    acbb_mech_free(sp.mech);
    acbb_qd_free(sp.qd);
}

void acbb_sim_free(acbb_sim *sim)
{
    if (!sim) return;
    setup_free(sim->setup);
    acbb_set_sim_free(sim->set);
    acbb_spindle_sim_free(sim->spindle);
    sim_release(sim);
    free(sim->keep);
    free(sim->best);
    free(sim);
}

/* A set, or a change to or from one, restarts cold with a new Sim. */
static acbb_status set_restart(acbb_sim *sim, const acbb_scene *s, acbb_error *err)
{
    acbb_sim *fresh;
    acbb_sim_opts o = { sim->cancel, sim->threads, sim->skip_stiffness, sim->skip_life,
                        sim->skip_liftoff };
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
    if (sim->set || sim->spindle || s->set_arrangement != ACBB_SET_SINGLE
        || s->shaft_segments > 0)
        return set_restart(sim, s, err);
    double T[ACBB_MAX_NODES];
    int keep = warm && s->network == sim->s.network;
    memcpy(T, sim->T, sizeof T);
    acbb_sim *fresh = calloc(1, sizeof *fresh);
    if (!fresh) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    fresh->cleared_balls = ACBB_MAX_BALLS;
    fresh->cancel = sim->cancel;
    fresh->threads = sim->threads;
    fresh->skip_stiffness = sim->skip_stiffness;
    fresh->skip_life = sim->skip_life;
    fresh->skip_liftoff = sim->skip_liftoff;
    acbb_status rc = sim_init(fresh, s, keep ? T : NULL, NULL, err);
    if (rc != ACBB_OK) {
        sim_release(fresh);
        free(fresh);
        return rc; /* the running sim is untouched */
    }
    sim_release(sim);
    fresh->keep = sim->keep; /* the rollback scratch stays with the Sim */
    fresh->best = sim->best;
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

/* The snapshot's losses, expansions and axial displacement. */
static void losses_expansions(const acbb_sim *sim, acbb_snapshot *o)
{
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
}

/* A step's values for a hook that reads the losses and loads
 * (acbb_simx_snapshot_step), each as snapshot() makes it; of each ball the
 * loads and the loss only, as acbb_snap_ball_view makes them. The whole
 * snapshot (ball views 70 % of it) every step cost a study 4 % (issue 30). */
static void step_snapshot(const acbb_sim *sim, int every_ball, acbb_snapshot *o)
{
    o->state = sim->run.state;
    o->status = sim->run.status;
    o->iteration = sim->run.iter;
    o->time = sim->run.time;
    losses_expansions(sim, o);
    o->n_balls = sim->ms.n;
    int nd = every_ball ? sim->ms.n : acbb_mech_distinct(&sim->ms);
    for (int j = 0; j < nd; j++) {
        const acbb_contact_loss *in = &sim->bl[j].in, *out = &sim->bl[j].out;
        acbb_ball_view *v = &o->balls[j];
        v->Qi = acbb_snap_fin(sim->ms.ball[j].Qi);
        v->Qo = acbb_snap_fin(sim->ms.ball[j].Qo);
        v->loss = 0.0;
        for (int l = 0; l < ACBB_LOSS_KINDS; l++) v->loss += in->P[l] + out->P[l];
        v->loss = acbb_snap_fin(v->loss);
    }
    /* the other balls are the solved ones' images (acbb_mech_spread; their
     * losses copied by the evaluation), the same values */
    for (int j = nd; j < sim->ms.n; j++) {
        const acbb_ball_view *src = &o->balls[acbb_mech_source(&sim->ms, j)];
        o->balls[j].Qi = src->Qi;
        o->balls[j].Qo = src->Qo;
        o->balls[j].loss = src->loss;
    }
}

/* full 0: o holds this Sim's snapshot already; the rating life (40 % of
 * a snapshot) and the clearing of the whole record (30 %) are left out. */
static void snapshot(const acbb_sim *sim, acbb_snapshot *o, int full)
{
    const acbb_network *nw = &sim->nw;
    if (sim->set || sim->spindle) {
        if (sim->spindle) acbb_spindle_sim_snapshot(sim->spindle, o);
        else acbb_set_sim_snapshot(sim->set, o);
        if ((sim->run.status == ACBB_CANCELLED || sim->run.status == ACBB_WALL_LIMIT)
            && o->state == ACBB_RUN_RUNNING) {
            /* ended by the run loop (cancel, wall-clock bound), not the set */
            o->state = sim->run.state;
            o->status = sim->run.status;
            snprintf(o->message, sizeof o->message, "%s", sim->run.msg);
        }
        return;
    }
    if (full) memset(o, 0, sizeof *o);
    o->state = sim->run.state;
    o->status = sim->run.status;
    /* snprintf's "%s", truncation included, without its formatting (a
     * study's hook takes a snapshot every step) */
    size_t len = strnlen(sim->run.msg, sizeof o->message - 1);
    memcpy(o->message, sim->run.msg, len);
    o->message[len] = '\0';
    o->iteration = sim->run.iter;
    o->time = sim->run.time;
    o->dt = sim->run.dt;
    o->residual = acbb_snap_fin(sim->run.residual);
    o->wall_ms = sim->run.wall_ms;
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
    losses_expansions(sim, o);
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
                                : 0.0; /* no network: no heat flows (acbb_simx_energy) */
    o->heat_out = acbb_snap_fin(sim->heat_out);
    o->n_balls = sim->ms.n;
    for (int j = 0; j < sim->ms.n; j++)
        acbb_snap_ball_view(&sim->ms.ball[j], &sim->bl[j].in, &sim->bl[j].out, &o->balls[j]);
    if (full && !sim->skip_life) acbb_life_compute_with(&sim->s, o, &sim->life_basis, &o->life);
    o->n_bearings = 1;
}

void acbb_sim_snapshot(const acbb_sim *sim, acbb_snapshot *o) { snapshot(sim, o, 1); }

/* A set's step: its snapshot is bearing 0's (sim_set_view.c), whose run
 * the set publishes after every step; every ball made from its own values
 * (no reliance on a member's balls being images). Bearing 0's whole
 * snapshot every step (rating life, ball views, clearing) was 92 M of
 * the `report` proxy's 3.32 G, all in the DB pair's study (issue 30). */
static void set_step_snapshot(const acbb_sim *sim, acbb_snapshot *o)
{
    step_snapshot(sim->set->b[0], 1, o);
    if ((sim->run.status == ACBB_CANCELLED || sim->run.status == ACBB_WALL_LIMIT)
        && o->state == ACBB_RUN_RUNNING) { /* as snapshot() */
        o->state = sim->run.state;
        o->status = sim->run.status;
    }
}

void acbb_simx_snapshot_step(const acbb_sim *sim, acbb_snapshot *o)
{
    if (sim->run.iter == 0 || sim->spindle) snapshot(sim, o, sim->run.iter == 0);
    else if (sim->set) set_step_snapshot(sim, o);
    else step_snapshot(sim, 0, o);
}

void acbb_simx_snapshot_values(const acbb_sim *sim, acbb_snapshot *o)
{
    if (sim->set || sim->spindle) acbb_simx_snapshot_step(sim, o);
    else step_snapshot(sim, 0, o);
}

acbb_status acbb_sim_bearing_snapshot(const acbb_sim *sim, int k, acbb_snapshot *out)
{
    if (sim->set) return acbb_set_sim_bearing_snapshot(sim->set, k, out);
    if (sim->spindle) return acbb_spindle_sim_bearing_snapshot(sim->spindle, k, out);
    if (k != 0) return ACBB_EINVAL;
    acbb_sim_snapshot(sim, out);
    return ACBB_OK;
}

/* ---- a bearing of a set (sim_set.c drives it; MODEL.md 14) ---- */

/* b's wall-clock deadline: the set's (sim_struct.h). */
void acbb_simx_deadline(acbb_sim *b, double deadline_ms)
{
    b->deadline_ms = deadline_ms;
    if (b->dyn) acbb_dyn_set_stop(b->dyn, deadline_ms > 0.0 ? past_bound : NULL, b);
}
