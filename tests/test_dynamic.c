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
#include "acbb/dynamic.h"

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
    acbb_dyn_free(d);
    acbb_mech_free(f.m);
    return done_testing();
}
