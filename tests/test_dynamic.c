/* Tests of the dynamic ball model (dynamic.h). Its fixed point is the
 * Level-2 quasi-dynamic solution (MODEL.md section 4: at rest in the
 * orbiting frame the equations of motion reduce to the Level-2 balances),
 * so a ball started there stays there, and a ball started at race control
 * relaxes towards it. Unloaded balls are left alone (MODEL.md section 11),
 * and a cancel flag raised before the call ends it with ACBB_CANCELLED. */
#include <math.h>
#include <string.h>
#include <stdatomic.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "ball_fixture.h"
#include "dynamic.h"

#define GRID 8          /* the dynamic level's test grid, as in test_levels */
#define WINDOW 1e-3     /* s: the warm window of the coupled stepper */

static ball_fixture f;
static acbb_ball_state qd_ball, rc_ball; /* Level-2 solution, race-control start */

static int setup(void)
{
    acbb_scene_default(&f.s);
    f.s.contact_grid = GRID;
    if (!fixture_setup(&f, 15000, 1000)) return 0;
    rc_ball = f.st.ball[0];
    acbb_qd *qd;
    if (acbb_qd_new(GRID, &qd) != ACBB_OK) return 0;
    int passes = fixture_level2(&f, qd, 1e-12);
    acbb_qd_free(qd);
    qd_ball = f.st.ball[0];
    return passes > 0;
}

static acbb_status run(acbb_dyn *d, double window, double *change, acbb_error *err)
{
    return acbb_dyn_ball(d, f.m, &f.s, &f.q, f.wi, &f.oil, &f.oil, &f.mix, &f.st, 0, window,
                         change, err);
}

static void test_stays_at_fixed_point(acbb_dyn *d)
{
    double change;
    acbb_error err = { "" };
    f.st.ball[0] = qd_ball;
    ok(run(d, WINDOW, &change, &err) == ACBB_OK, "window from the Level-2 solution (%s)",
       err.msg);
    const acbb_ball_state *b = &f.st.ball[0];
    /* Stated tolerance: 1e-6 relative (the BDF tolerances are 1e-9). */
    is_close(b->qd_w[0], qd_ball.qd_w[0], 1e-6, 0, "time-averaged omega_m = Level 2 (1e-6)");
    is_close(b->qd_w[1], qd_ball.qd_w[1], 1e-6, 0, "time-averaged omega_x' = Level 2 (1e-6)");
    is_close(b->qd_w[2], qd_ball.qd_w[2], 0, 1e-6 * f.wi, "time-averaged omega_y' = Level 2");
    is_close(b->qd_w[3], qd_ball.qd_w[3], 1e-6, 0, "time-averaged omega_z' = Level 2 (1e-6)");
    is_close(b->tr_Qi, qd_ball.Qi, 1e-6, 0, "time-averaged inner load = equilibrium load");
    is_close(b->tr_Qo, qd_ball.Qo, 1e-6, 0, "time-averaged outer load = equilibrium load");
    is_close(b->tr_i[1] + b->tr_o[1], qd_ball.tr_i[1] + qd_ball.tr_o[1], 0,
             1e-6 * f.s.mu_bd * (qd_ball.Qi + qd_ball.Qo), "y' traction = Level 2 (balances drag)");
    ok(change < 1e-6, "*change = %.2e < 1e-6", change);
}

/* From race control the ball must move towards the Level-2 speeds: over a
 * 4 ms window (the cold window) the gap closes by at least 5x. */
static void test_relaxes(acbb_dyn *d)
{
    double change;
    acbb_error err = { "" };
    f.st.ball[0] = rc_ball;
    ok(f.st.ball[0].traction_valid == 0, "race-control start");
    ok(run(d, 4 * WINDOW, &change, &err) == ACBB_OK, "window from race control (%s)", err.msg);
    const acbb_ball_state *b = &f.st.ball[0];
    double gm0 = fabs(rc_ball.kin.omega_m - qd_ball.qd_w[0]), gm = fabs(b->qd_w[0] - qd_ball.qd_w[0]);
    double gz0 = fabs(rc_ball.kin.wz - qd_ball.qd_w[3]), gz = fabs(b->qd_w[3] - qd_ball.qd_w[3]);
    ok(gm < 0.2 * gm0, "omega_m gap to Level 2: %.3g -> %.3g rad/s", gm0, gm);
    ok(gz < 0.2 * gz0, "omega_z' gap to Level 2: %.3g -> %.3g rad/s", gz0, gz);
    is_close(change, fabs(b->qd_w[0] - rc_ball.kin.omega_m) / rc_ball.kin.omega_m, 1e-12, 0,
             "*change = relative move of omega_m");
}

static void test_unloaded(acbb_dyn *d)
{
    double change = -1;
    acbb_error err = { "" };
    f.st.ball[0] = qd_ball;
    f.st.ball[0].Qi = 0.0;
    acbb_ball_state before = f.st.ball[0];
    ok(run(d, WINDOW, &change, &err) == ACBB_OK && change == 0.0,
       "ball without inner load: OK, no change");
    ok(memcmp(&before, &f.st.ball[0], sizeof before) == 0, "ball without load returns unchanged");
}

static void test_cancel(acbb_dyn *d)
{
    atomic_int flag = 1;
    double change;
    acbb_error err = { "" };
    f.st.ball[0] = qd_ball;
    f.st.ball[0].qd_w[0] *= 1.01; /* a start that would move, to see it is not written */
    acbb_ball_state before = f.st.ball[0];
    acbb_dyn_set_cancel(d, &flag);
    ok(run(d, WINDOW, &change, &err) == ACBB_CANCELLED, "flag set before the call: CANCELLED");
    ok(memcmp(before.qd_w, f.st.ball[0].qd_w, sizeof before.qd_w) == 0,
       "cancelled: the ball keeps its last good speeds");
    atomic_store(&flag, 0);
    ok(run(d, WINDOW, &change, &err) == ACBB_OK, "flag cleared: the same workspace runs again");
    acbb_dyn_set_cancel(d, NULL);
}

/* Several distinct balls (the symmetric state unfolded, each started a
 * little off the Level-2 speeds by a different amount) run on 1, 2 and 3
 * workers: every ball is integrated alone on one worker's tables, so the
 * states must agree bit for bit, and *change is the largest ball's. */
static int balls_on(int threads, acbb_mech_state *out, double *change)
{
    acbb_dyn *d;
    if (acbb_dyn_new(GRID, &d) != ACBB_OK || acbb_dyn_set_threads(d, threads) != ACBB_OK)
        return 0;
    *out = f.st;
    out->symmetric = out->mirror = 0;
    for (int j = 0; j < out->n; j++) {
        out->ball[j] = qd_ball;
        out->ball[j].qd_w[0] *= 1.0 + 1e-3 * j;
    }
    acbb_dyn_env env = { f.m, &f.s, &f.q, f.wi, &f.oil, &f.oil, &f.mix };
    acbb_error err = { "" };
    acbb_status rc = acbb_dyn_balls(d, &env, out, 4 * WINDOW, WINDOW, change, &err);
    long windows = acbb_dyn_windows(d);
    acbb_dyn_free(d);
    if (rc != ACBB_OK) printf("# %s\n", err.msg);
    return rc == ACBB_OK && windows == out->n;
}

static void test_threads(void)
{
    static acbb_mech_state one, two, three;
    double c1, c2, c3;
    int n = f.st.n;
    ok(balls_on(1, &one, &c1), "%d distinct balls on 1 worker: one window each", n);
    ok(balls_on(2, &two, &c2), "on 2 workers");
    ok(balls_on(3, &three, &c3), "on 3 workers");
    ok(memcmp(one.ball, two.ball, sizeof one.ball[0] * (size_t)n) == 0
       && memcmp(one.ball, three.ball, sizeof one.ball[0] * (size_t)n) == 0,
       "ball states identical bit for bit with 1, 2 and 3 workers");
    ok(c1 == c2 && c1 == c3, "*change identical (%.3e)", c1);
    /* *change is measured from each ball's kinematics omega_m (here Level
     * 2's, for every ball): the largest relative move over the balls. */
    double cmax = 0.0, wm = qd_ball.kin.omega_m;
    for (int j = 0; j < n; j++) cmax = fmax(cmax, fabs(one.ball[j].qd_w[0] - wm) / wm);
    ok(c1 == cmax && c1 > 0.0, "*change is the largest ball's move (%.3e)", c1);
    ok(one.ball[n - 1].qd_w[0] != one.ball[0].qd_w[0], "the balls really were distinct");
}

static void test_threads_range(acbb_dyn *d)
{
    ok(acbb_dyn_set_threads(d, 0) == ACBB_EINVAL, "0 workers: EINVAL");
    ok(acbb_dyn_set_threads(d, ACBB_DYN_MAX_THREADS + 1) == ACBB_EINVAL,
       "%d workers: EINVAL", ACBB_DYN_MAX_THREADS + 1);
    ok(acbb_dyn_threads(d) == 1, "workspace keeps its 1 worker");
}

/* Skip (transient steps): a settled ball whose inputs did not move keeps
 * its speeds without a window; a load moved past the tolerance, or a
 * ball that has not settled, gets a window; tolerance 0 always integrates. */
static void test_skip(acbb_dyn *d)
{
    double change;
    acbb_error err = { "" };
    f.st.ball[0] = qd_ball;
    acbb_dyn_set_skip(d, 1e-2);
    long w0 = acbb_dyn_windows(d);
    run(d, WINDOW, &change, &err);
    ok(acbb_dyn_windows(d) == w0 + 1 && change < 1e-6, "first call integrates (settled: %.1e)",
       change);
    acbb_ball_state before = f.st.ball[0];
    ok(run(d, WINDOW, &change, &err) == ACBB_OK && acbb_dyn_windows(d) == w0 + 1
       && change == 0.0 && memcmp(&before, &f.st.ball[0], sizeof before) == 0,
       "same inputs, settled: skipped, ball unchanged");
    f.st.ball[0].Qi *= 1.02;
    run(d, WINDOW, &change, &err);
    ok(acbb_dyn_windows(d) == w0 + 2, "inner load moved 2 %% > 1 %%: integrated");
    f.st.ball[0] = rc_ball;
    f.st.ball[0].traction_valid = 1;
    memcpy(f.st.ball[0].qd_w, qd_ball.qd_w, sizeof qd_ball.qd_w);
    f.st.ball[0].qd_w[0] *= 1.01;
    run(d, WINDOW, &change, &err);
    run(d, WINDOW, &change, &err);
    ok(acbb_dyn_windows(d) == w0 + 4, "not settled (last move %.1e): integrated again", change);
    acbb_dyn_set_skip(d, 0.0);
    f.st.ball[0] = qd_ball;
    run(d, WINDOW, &change, &err);
    run(d, WINDOW, &change, &err);
    ok(acbb_dyn_windows(d) == w0 + 6, "tolerance 0: every call integrates");
}

int main(void)
{
    gsl_set_error_handler_off();
    if (!ok(setup(), "15000 rpm, 1000 N: Level-2 solution (grid %d)", GRID)) return done_testing();
    acbb_dyn *d;
    ok(acbb_dyn_new(GRID, &d) == ACBB_OK, "workspace");
    test_stays_at_fixed_point(d);
    test_relaxes(d);
    test_unloaded(d);
    test_cancel(d);
    test_threads_range(d);
    test_skip(d);
    acbb_dyn_free(d);
    test_threads();
    acbb_mech_free(f.m);
    return done_testing();
}
