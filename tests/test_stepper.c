/* The one stepper (src/run/stepper.h) on a plant of its own, as a third
 * plant (the spindle) will use it: one lumped node of capacity C behind a
 * resistance R to a fixed node at T_a, its loss P = P0 + k (T - T_a) (a
 * loss that grows with temperature, as a bearing's under a rigid
 * preload). Hand results: the steady rise is P0 R / (1 - k R) for k R < 1
 * (the fixed point of T - T_a = R P), and for k R > 1 there is none: the
 * temperature grows without bound (a runaway). */
#include <math.h>
#include <string.h>
#include "tap.h"
#include "acbb/scene.h"
#include "stepper.h"
#include "thermal_network.h"

typedef struct {
    acbb_scene s;
    acbb_tnet *net;
    double T[2], q[2], T_keep[2], q_keep[2], T_best[2], q_best[2];
    double P0, k, P, P_keep, P_best;
    int evaluations, converged_probes;
    int rigid;                 /* the growth detector watches the loss */
} toy;

static acbb_status toy_stop(void *ctx, acbb_error *err)
{
    (void)ctx;
    (void)err;
    return ACBB_OK;
}

static acbb_status toy_operate(void *ctx, double t, acbb_error *err)
{
    (void)ctx;
    (void)t;
    (void)err;
    return ACBB_OK;
}

static acbb_status toy_evaluate(void *ctx, acbb_pass pass, double relax, acbb_error *err)
{
    toy *y = ctx;
    (void)pass;
    (void)relax;
    (void)err;
    y->evaluations++;
    y->P = y->P0 + y->k * (y->T[0] - y->s.ambient_C);
    y->q[0] = y->P;
    return ACBB_OK;
}

static double toy_loss(void *ctx) { return ((toy *)ctx)->P; }

static void toy_save(void *ctx, int slot)
{
    toy *y = ctx;
    memcpy(slot ? y->T_best : y->T_keep, y->T, sizeof y->T);
    memcpy(slot ? y->q_best : y->q_keep, y->q, sizeof y->q);
    *(slot ? &y->P_best : &y->P_keep) = y->P;
}

static void toy_restore(void *ctx, int slot)
{
    toy *y = ctx;
    memcpy(y->T, slot ? y->T_best : y->T_keep, sizeof y->T);
    memcpy(y->q, slot ? y->q_best : y->q_keep, sizeof y->q);
    y->P = slot ? y->P_best : y->P_keep;
}

static acbb_status toy_limits(void *ctx, double t, char *what, size_t size)
{
    toy *y = ctx;
    if (y->T[0] <= y->s.temp_limit_C) return ACBB_OK;
    snprintf(what, size, "toy node reached %.1f C at t = %.0f s", y->T[0], t);
    return ACBB_RUNAWAY;
}

static double toy_force(void *ctx, int *rigid)
{
    toy *y = ctx;
    *rigid = y->rigid;
    return y->P; /* a rigid preload's reaction would grow with the loss */
}

static acbb_status toy_balance(void *ctx, acbb_error *err)
{
    toy *y = ctx;
    double out = acbb_tnet_heat_to_fixed(y->net, y->T);
    if (fabs(out - y->P) <= 1e-6 * y->P) return ACBB_OK;
    return acbb_error_set(err, ACBB_UNBALANCED, "toy: %g W in, %g W out", y->P, out);
}

static void toy_converge(void *ctx) { ((toy *)ctx)->converged_probes++; }

static void toy_init(toy *y, double P0, double k)
{
    memset(y, 0, sizeof *y);
    acbb_scene_default(&y->s);
    y->s.heating = 1;
    y->s.thermal_mode = ACBB_THERMAL_TRANSIENT;
    y->s.schedule_n = 0;
    y->net = acbb_tnet_new(2);
    acbb_tnet_set_capacity(y->net, 0, 100.0);     /* J/K */
    acbb_tnet_set_fixed(y->net, 1, y->s.ambient_C);
    acbb_tnet_add_edge(y->net, 0, 1, 1.0);        /* K/W */
    y->T[0] = y->T[1] = y->s.ambient_C;
    y->P0 = P0;
    y->k = k;
    y->rigid = 1;
    toy_evaluate(y, ACBB_PASS_STEADY, 1.0, NULL);
}

static void toy_plant(toy *y, acbb_plant *p)
{
    *p = (acbb_plant){
        .ctx = y, .s = &y->s, .net = y->net, .T = y->T, .q = y->q, .n = 2,
        .keeps_best = 1, .force_name = "the toy force", .stop = toy_stop,
        .operate = toy_operate, .evaluate = toy_evaluate, .loss = toy_loss, .save = toy_save,
        .restore = toy_restore, .limits = toy_limits, .force = toy_force,
        .balance = toy_balance, .converge = toy_converge,
    };
}

static acbb_status run(toy *y, acbb_stepper *r)
{
    acbb_plant p;
    toy_plant(y, &p);
    *r = (acbb_stepper){ .state = ACBB_RUN_RUNNING, .dt = y->s.time_step, .prev_F = y->P };
    acbb_status rc = ACBB_OK;
    for (int i = 0; i < 100000 && r->state == ACBB_RUN_RUNNING; i++)
        rc = acbb_stepper_step(&p, r);
    return rc;
}

/* Transient and steady solve both land on the hand fixed point. */
static void test_steady_rise(int mode)
{
    toy y;
    acbb_stepper r;
    toy_init(&y, 10.0, 0.5); /* 10 W, 0.5 W/K, R = 1 K/W: rise 20 K */
    y.s.thermal_mode = mode;
    acbb_status rc = run(&y, &r);
    const char *m = mode == ACBB_THERMAL_STEADY ? "steady" : "transient";
    ok(rc == ACBB_OK && r.state == ACBB_RUN_CONVERGED
       && strstr(r.msg, "thermal steady state after") == r.msg,
       "%s: converged (%s, %ld steps)", m, r.msg, r.iter);
    is_close(y.T[0] - y.s.ambient_C, 20.0, 0, 1e-6, "... the rise is P0 R / (1 - k R) = 20 K");
    ok(y.converged_probes == 1, "... the plant's probes ran once (%d)", y.converged_probes);
    if (mode == ACBB_THERMAL_TRANSIENT)
        ok(r.time > 0.0 && r.dt <= DT_MAX, "... %.0f s simulated, dt %.2f s within 30 s",
           r.time, r.dt);
    acbb_tnet_free(y.net);
}

/* k R > 1: no fixed point; the node passes thermal.temp_limit_C (the
 * growth detector off: a force preload). */
static void test_runaway_limit(void)
{
    toy y;
    acbb_stepper r;
    toy_init(&y, 10.0, 2.0);
    y.rigid = 0;
    y.s.temp_limit_C = 150.0;
    acbb_status rc = run(&y, &r);
    ok(rc == ACBB_RUNAWAY && r.state == ACBB_RUN_FAILED
       && strstr(r.msg, "thermal runaway: toy node reached") == r.msg,
       "k R = 2: runaway at the temperature limit (%s)", r.msg);
    ok(y.T[0] > 150.0 && y.T[0] < 150.0 + 2.0 * DT_MAX_DT_K,
       "... the state that passed it is kept, within a step (%.2f C)", y.T[0]);
    acbb_tnet_free(y.net);
}

/* Without a temperature limit in reach, the force grows ever faster for
 * 50 steps: the runaway of MODEL.md 9. */
static void test_runaway_growth(void)
{
    toy y;
    acbb_stepper r;
    toy_init(&y, 10.0, 2.0);
    y.s.temp_limit_C = 1e12;
    y.s.max_time = 1e12;
    acbb_status rc = run(&y, &r);
    ok(rc == ACBB_RUNAWAY && strstr(r.msg, "thermal runaway: the toy force grows ever faster"),
       "k R = 2, no limit near: the growth detector ends it (%s, step %ld)", r.msg, r.iter);
    ok(r.iter >= 50, "... after at least 50 growing steps (%ld)", r.iter);
    acbb_tnet_free(y.net);
}

/* The verdicts without a network step: heating off, and out of steps. */
static void test_verdicts(void)
{
    toy y;
    acbb_stepper r;
    toy_init(&y, 10.0, 0.5);
    y.s.heating = false;
    acbb_status rc = run(&y, &r);
    ok(rc == ACBB_OK && r.state == ACBB_RUN_CONVERGED && y.T[0] == y.s.ambient_C
       && !strcmp(r.msg, "isothermal mechanics at ambient (effects.heating = off)"),
       "heating off: converged at ambient in %ld evaluations (%s)", r.iter, r.msg);
    acbb_tnet_free(y.net);
    toy_init(&y, 10.0, 0.5);
    y.s.max_steps = 3;
    rc = run(&y, &r);
    ok(rc == ACBB_NOT_CONVERGED && r.iter == 3
       && strstr(r.msg, "no steady state within the limits (3 steps"),
       "max_steps 3: not converged after 3 steps (%s)", r.msg);
    acbb_tnet_free(y.net);
}

int main(void)
{
    test_steady_rise(ACBB_THERMAL_TRANSIENT);
    test_steady_rise(ACBB_THERMAL_STEADY);
    test_runaway_limit();
    test_runaway_growth();
    test_verdicts();
    return done_testing();
}
