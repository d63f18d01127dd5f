/* Tests of the Level-2 quasi-dynamic ball kinematics (quasi_dynamic.h,
 * MODEL.md section 4 "Level 2"): the returned speeds satisfy the y'-force
 * and moment balances, recomputed here from the public traction API; in
 * the pure-rolling limit (equal contact angles, heavy load, low speed) the
 * orbital speed is the rolling kinematics of section 4 Level 1; balls
 * without load and a stopped ring are left alone (section 11). */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "ball_fixture.h"

/* Level-2 residual of ball b0's contacts (tables and film as the solver
 * built them from b0) at speeds w = (omega_m, wx, wy, wz): r[0] the
 * y'-force balance over mu (Qi + Qo), r[1..3] the moment balance over
 * mu (Qi + Qo) D/2. Returns max |r|. */
static double residual(const ball_fixture *f, const acbb_ball_state *b0, const double w[4])
{
    acbb_traction tr[2];
    for (int inner = 0; inner < 2; inner++) {
        acbb_contact_in c;
        acbb_film film;
        acbb_traction_contact tc;
        acbb_mech_contact_input(f->g, b0, inner, f->wi, &c);
        double u = fabs(c.u);
        double srr = u > 1e-6 ? fmin(acbb_slip_speed(&c, 0.0) / u, 2.0) : 0.0;
        acbb_film_compute(&f->s, &f->oil, u, c.Q, c.Rx, c.kappa, c.E_eff, c.pmax, srr, &film);
        if (acbb_traction_contact_init(&tc, f->q.n) != ACBB_OK
            || acbb_traction_prepare(&f->s, &f->q, &c, &film, &f->oil, &tc) != ACBB_OK)
            return INFINITY;
        acbb_traction_eval(&f->s, &tc, w + 1, inner ? f->wi - w[0] : -w[0], &tr[inner]);
        acbb_traction_contact_free(&tc);
    }
    double Fv = f->s.loss_drag ? acbb_drag_force(&f->s, &f->mix, w[0]) : 0.0;
    double J = f->g->J, Fs = f->s.mu_bd * (b0->Qi + b0->Qo), Ms = 0.5 * f->g->D * Fs;
    /* Required moment in the orbiting frame: J omega_m (0, -wz, wy). */
    double Mreq[3] = { 0.0, -J * w[0] * w[3], J * w[0] * w[2] };
    double r = fabs(tr[0].F[1] + tr[1].F[1] + Fv) / Fs;
    for (int d = 0; d < 3; d++)
        r = fmax(r, fabs(tr[0].M[d] + tr[1].M[d] - Mreq[d]) / Ms);
    return r;
}

static void test_residual(double rpm, double Fx)
{
    ball_fixture f;
    acbb_scene_default(&f.s);
    if (!ok(fixture_setup(&f, rpm, Fx), "%.0f rpm, %.0f N: quasi-static start", rpm, Fx)) return;
    acbb_qd *qd;
    ok(acbb_qd_new(f.s.contact_grid, &qd) == ACBB_OK, "workspace");
    acbb_ball_state b0 = f.st.ball[0];
    double change;
    acbb_error err = { "" };
    acbb_status rc = acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st,
                                    &change, &err);
    const acbb_ball_state *b = &f.st.ball[0];
    ok(rc == ACBB_OK && b->traction_valid, "Level 2 solved (%s)", err.msg);
    double w1[4] = { b0.kin.omega_m, b0.kin.wx, b0.kin.wy, b0.kin.wz };
    double r1 = residual(&f, &b0, w1), r2 = residual(&f, &b0, b->qd_w);
    ok(r2 < 1e-6, "residual at the Level-2 speeds %.2e < 1e-6 of mu Q (MODEL 4)", r2);
    ok(r1 > 1e3 * r2, "the race-control start is not a solution (residual %.2e)", r1);
    ok(fabs(change - fabs(b->qd_w[0] - w1[0]) / w1[0]) < 1e-12,
       "*change = relative move of omega_m (%.3g)", change);
    /* The stored meridional tractions are those at the solution: the y'
     * components balance the drag (force on the ball along +y'). */
    double Fv = acbb_drag_force(&f.s, &f.mix, b->qd_w[0]);
    is_close(b->tr_i[1] + b->tr_o[1], -Fv, 0, 1e-6 * f.s.mu_bd * (b->Qi + b->Qo),
             "stored tractions: F_i,y' + F_o,y' = -F_drag");
    ok(b->tr_Qi == b0.Qi && b->tr_Qo == b0.Qo, "stored loads are the loads solved at");
    int same = 1;
    for (int j = 1; j < f.st.n; j++)
        same &= memcmp(f.st.ball[j].qd_w, b->qd_w, sizeof b->qd_w) == 0;
    ok(f.st.symmetric && same, "symmetric thrust: every ball takes ball 1's speeds");
    acbb_qd_free(qd);
    acbb_mech_free(f.m);
}

/* Pure rolling limit: with the centrifugal force off the two contact angles
 * are equal, and rolling without gross slip at both contact centres gives
 * (MODEL 4, Level 1, any beta) omega_m / omega_i = (1 - gamma') / 2,
 * gamma' = D cos(alpha) / dm. At 1000 rpm and 1000 N the slip of the
 * Level-2 solution is micro-slip (Heathcote): omega_m matches to 1e-3 and
 * the slip at the contact centres stays under 0.5 % of the entrainment speed. */
static void test_pure_rolling(void)
{
    ball_fixture f;
    acbb_scene_default(&f.s);
    f.s.centrifugal = false;
    f.s.loss_drag = false;
    if (!ok(fixture_setup(&f, 1000, 1000), "1000 rpm, 1000 N, no centrifugal force")) return;
    acbb_qd *qd;
    acbb_qd_new(f.s.contact_grid, &qd);
    int passes = fixture_level2(&f, qd, 1e-10);
    ok(passes > 0, "Level 1 <-> Level 2 iteration converges (%d passes)", passes);
    const acbb_ball_state *b = &f.st.ball[0];
    is_close(b->alpha_i, b->alpha_o, 0, 1e-6, "no centrifugal force: alpha_i = alpha_o");
    double gam = f.g->D * cos(b->alpha_o) / f.g->dm, want = 0.5 * (1.0 - gam) * f.wi;
    acbb_kin k1;
    acbb_kinematics_race_control(b->alpha_i, b->alpha_o, f.g->D, f.g->dm, f.wi,
                                 ACBB_CONTROL_OUTER, &k1);
    is_close(k1.omega_m, want, 1e-6, 0, "race control omega_m = omega_i (1 - gamma')/2 (1e-6)");
    is_close(b->qd_w[0], want, 1e-3, 0, "Level-2 omega_m = omega_i (1 - gamma')/2 (1e-3)");
    /* Gross slip at the contact centres, relative to the entrainment speed. */
    double rm = 0.5 * f.g->dm, h = 0.5 * f.g->D;
    double so = h * b->kin.roll_o - b->kin.omega_m * (rm + h * cos(b->alpha_o));
    double si = h * b->kin.roll_i - (f.wi - b->kin.omega_m) * (rm - h * cos(b->alpha_i));
    ok(fabs(so) < 5e-3 * b->kin.u_o && fabs(si) < 5e-3 * b->kin.u_i,
       "centre slip < 0.5 %% of entrainment (outer %.2e, inner %.2e m/s)", so, si);
    acbb_qd_free(qd);
    acbb_mech_free(f.m);
}

/* MODEL 11: unloaded balls keep race-control speeds; a stopped ring has no
 * kinematics to solve. */
static void test_guards(void)
{
    ball_fixture f;
    acbb_scene_default(&f.s);
    if (!ok(fixture_setup(&f, 8000, 200), "8000 rpm, 200 N")) return;
    acbb_qd *qd;
    acbb_qd_new(f.s.contact_grid, &qd);
    static acbb_mech_state before;
    before = f.st;
    double change = -1;
    acbb_error err = { "" };
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, 0.0, &f.oil, &f.oil, &f.mix, &f.st, &change, &err)
           == ACBB_OK && change == 0.0 && memcmp(&before, &f.st, sizeof before) == 0,
       "omega_i = 0: OK, no change, state untouched");
    f.st.ball[0].Qo = 0.5e-3;
    f.st.ball[0].traction_valid = 1;
    before = f.st;
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err)
           == ACBB_OK && change == 0.0,
       "outer load 0.5 mN (< 1 mN): OK, no change");
    ok(f.st.ball[0].traction_valid == 0
           && memcmp(&before.ball[0].kin, &f.st.ball[0].kin, sizeof before.ball[0].kin) == 0,
       "unloaded ball: traction dropped, race-control speeds kept");
    acbb_qd_free(qd);
    acbb_mech_free(f.m);
}

/* Transient steps may skip a ball whose inputs moved less than the skip
 * tolerance (acbb_qd_set_skip); a larger move, or tolerance 0 as in the
 * steady polish, solves it again. */
static void test_skip(void)
{
    ball_fixture f;
    acbb_scene_default(&f.s);
    if (!ok(fixture_setup(&f, 15000, 1000), "15000 rpm, 1000 N")) return;
    acbb_qd *qd;
    acbb_qd_new(f.s.contact_grid, &qd);
    double change, w0[4], w1[4];
    acbb_error err = { "" };
    acbb_ball_state *b = &f.st.ball[0];
    acbb_qd_set_skip(qd, 3e-3);
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    memcpy(w0, b->qd_w, sizeof w0);
    b->Qi *= 1.001; /* 0.1 % < 0.3 %: kept */
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err)
           == ACBB_OK && change == 0.0 && memcmp(w0, b->qd_w, sizeof w0) == 0,
       "inner load +0.1 %% with skip 3e-3: speeds kept bit for bit");
    acbb_oil_state hot = f.oil;
    hot.eta0 *= 0.995; /* 0.5 % thinner oil, weighted 0.3: 0.15 % < 0.3 %, kept */
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &hot, &hot, &f.mix, &f.st, &change, &err)
           == ACBB_OK && change == 0.0 && memcmp(w0, b->qd_w, sizeof w0) == 0,
       "inlet viscosity -0.5 %% (weight 0.3): speeds kept");
    hot.eta0 = 0.98 * f.oil.eta0; /* 2 % thinner: 0.6 % > 0.3 %, solved again */
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &hot, &hot, &f.mix, &f.st, &change, &err)
           == ACBB_OK && memcmp(w0, b->qd_w, sizeof w0) != 0,
       "inlet viscosity -2 %%: solved again");
    memcpy(w1, b->qd_w, sizeof w1);
    b->Qi *= 1.001;
    acbb_qd_set_skip(qd, 0.0);
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &hot, &hot, &f.mix, &f.st, &change, &err)
           == ACBB_OK && memcmp(w1, b->qd_w, sizeof w1) != 0,
       "skip 0 (steady polish): a 0.1 %% load move is solved");
    acbb_qd_free(qd);
    acbb_mech_free(f.m);
}

/* A damped steady polish step under-relaxes an update (acbb_qd_relax):
 * speeds halfway at w = 0.5, tractions halfway per unit load (the ring
 * equilibrium scales them with the load), kept at the new load; a ball
 * without Level-2 results before is left as solved. */
static void test_relax(void)
{
    ball_fixture f;
    acbb_scene_default(&f.s);
    if (!ok(fixture_setup(&f, 15000, 1000), "15000 rpm, 1000 N")) return;
    acbb_qd *qd;
    acbb_qd_new(f.s.contact_grid, &qd);
    double change;
    acbb_error err = { "" };
    acbb_ball_state *b = &f.st.ball[0];
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    acbb_ball_state b0 = *b;
    acbb_qd_kept kept[ACBB_MAX_BALLS];
    acbb_qd_keep(&f.st, kept);
    b->Qi *= 1.2;
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    acbb_ball_state b1 = *b;
    acbb_qd_relax(&f.st, kept, 0.5);
    double dw = 0.0, dt = 0.0;
    for (int d = 0; d < 4; d++)
        dw = fmax(dw, fabs(b->qd_w[d] - 0.5 * (b0.qd_w[d] + b1.qd_w[d])) / f.wi);
    for (int d = 0; d < 3; d++) {
        double ti = 0.5 * b1.tr_Qi * (b0.tr_i[d] / b0.tr_Qi + b1.tr_i[d] / b1.tr_Qi);
        double to = 0.5 * b1.tr_Qo * (b0.tr_o[d] / b0.tr_Qo + b1.tr_o[d] / b1.tr_Qo);
        dt = fmax(dt, fmax(fabs(b->tr_i[d] - ti), fabs(b->tr_o[d] - to)) / b1.tr_Qi);
    }
    ok(b1.qd_w[0] != b0.qd_w[0] && dw < 1e-15 && dt < 1e-15 && b->tr_Qi == b1.tr_Qi,
       "relax 0.5: speeds (%.2g of omega_i off) and tractions per load (%.2g) halfway", dw, dt);
    kept[0].valid = 0;
    acbb_ball_state bs = *b;
    acbb_qd_relax(&f.st, kept, 0.5);
    ok(memcmp(bs.qd_w, b->qd_w, sizeof bs.qd_w) == 0, "a ball kept without results: as solved");
    acbb_qd_free(qd);
    acbb_mech_free(f.m);
}

/* Combined load: balls without a Jacobian of their own (the set-up's
 * first pass) start from their neighbour's root; every distinct ball
 * still satisfies its balances, and ball 3 has the speeds a cold solve of
 * it alone finds (the root is unique, MODEL.md section 4). */
static void test_neighbour_start(void)
{
    static ball_fixture f;
    acbb_scene_default(&f.s);
    f.s.radial_load = 500.0;
    if (!ok(fixture_setup(&f, 15000, 1000), "15000 rpm, 1000 N + 500 N radial")) return;
    acbb_qd *qd, *q1;
    acbb_qd_new(f.s.contact_grid, &qd);
    acbb_qd_new(f.s.contact_grid, &q1);
    static acbb_mech_state st0, one;
    acbb_mech_state_copy(&st0, &f.st);
    double change, worst = 0.0;
    acbb_error err = { "" };
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err)
           == ACBB_OK, "Level 2 of %d distinct balls (%s)", acbb_mech_distinct(&f.st), err.msg);
    for (int j = 0; j < acbb_mech_distinct(&f.st); j++)
        worst = fmax(worst, residual(&f, &st0.ball[j], f.st.ball[j].qd_w));
    ok(worst < 1e-6, "worst residual over the balls %.2e < 1e-6 of mu Q", worst);
    acbb_mech_state_copy(&one, &st0);
    one.ball[0] = st0.ball[3];
    one.symmetric = 1; /* ball 0 (ball 3's state) alone, cold */
    acbb_qd_update(q1, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &one, &change, &err);
    double d = 0.0;
    for (int k = 0; k < 4; k++)
        d = fmax(d, fabs(one.ball[0].qd_w[k] - f.st.ball[3].qd_w[k]) / f.wi);
    ok(d < 1e-9, "ball 3 from its neighbour = ball 3 cold (%.1e of the ring speed)", d);
    acbb_qd_free(qd);
    acbb_qd_free(q1);
    acbb_mech_free(f.m);
}

/* The set-up's second pass (issue 30): the first equilibrium moved every
 * load, a Broyden solve from the ball's own Jacobian fails and Newton with
 * the analytic Jacobian takes over from the old root; it reaches the root
 * a cold solve of the new state finds, to 1e-9 of the ring speed. */
static void test_own_restart(void)
{
    static ball_fixture f;
    acbb_scene_default(&f.s);
    if (!ok(fixture_setup(&f, 15000, 1000), "15000 rpm, 1000 N")) return;
    acbb_qd *qd, *q1;
    acbb_qd_new(f.s.contact_grid, &qd);
    acbb_qd_new(f.s.contact_grid, &q1);
    double change;
    acbb_error err = { "" };
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    acbb_ball_state *b = &f.st.ball[0];
    b->Qi *= 3.0;
    b->Qo *= 2.5;
    b->alpha_i += 0.05;
    static acbb_mech_state cold;
    acbb_mech_state_copy(&cold, &f.st);
    ok(acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err)
           == ACBB_OK, "loads x3 / x2.5, inner angle +0.05 rad: solved from the old root (%s)",
       err.msg);
    ok(acbb_qd_update(q1, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &cold, &change, &err)
           == ACBB_OK, "the same state solved cold");
    double d = 0.0;
    for (int k = 0; k < 4; k++)
        d = fmax(d, fabs(cold.ball[0].qd_w[k] - b->qd_w[k]) / f.wi);
    ok(d < 1e-9, "the same root as the cold solve (%.1e of the ring speed)", d);
    acbb_qd_free(qd);
    acbb_qd_free(q1);
    acbb_mech_free(f.m);
}

/* A transient step of many balls (skip and path on) ends a ball's solve
 * at a residual sum of 1e-4 (its skip keeps far staler speeds); the steady
 * polish (skip 1e-9, no path) solves that ball again though its inputs did
 * not move, to the root a tight cold solve finds; a tight root is kept by
 * the next step. */
static void test_path_tol(void)
{
    ball_fixture f;
    acbb_scene_default(&f.s);
    if (!ok(fixture_setup(&f, 15000, 1000), "15000 rpm, 1000 N")) return;
    acbb_qd *qd, *q1;
    acbb_qd_new(f.s.contact_grid, &qd);
    acbb_qd_new(f.s.contact_grid, &q1);
    static acbb_mech_state cold;
    acbb_ball_state b0 = f.st.ball[0], *b = &f.st.ball[0];
    double change, w[4];
    acbb_error err = { "" };
    acbb_qd_set_skip(qd, 3e-3);
    acbb_qd_set_path(qd, 1);
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    double rl = residual(&f, &b0, b->qd_w);
    ok(rl < 1e-4 && rl > 1e-9, "a transient step's solve: residual %.2e in (1e-9, 1e-4)", rl);
    /* The film and tables follow the ball's speeds: the polish's residual
     * is the one at the step's state, solved cold to compare. */
    acbb_mech_state_copy(&cold, &f.st);
    acbb_ball_state b1 = *b;
    acbb_qd_update(q1, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &cold, &change, &err);
    acbb_qd_set_skip(qd, 1e-9);
    acbb_qd_set_path(qd, 0);
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    double d = 0.0, rt = residual(&f, &b1, b->qd_w);
    for (int k = 0; k < 4; k++)
        d = fmax(d, fabs(cold.ball[0].qd_w[k] - b->qd_w[k]) / f.wi);
    ok(rt < 1e-9 && d < 1e-9, "the polish solves it again: residual %.2e, %.1e of the ring "
       "speed from a cold solve", rt, d);
    memcpy(w, b->qd_w, sizeof w);
    acbb_qd_set_skip(qd, 3e-3);
    acbb_qd_set_path(qd, 1);
    acbb_qd_update(qd, &f.s, &f.q, f.g, f.wi, &f.oil, &f.oil, &f.mix, &f.st, &change, &err);
    ok(memcmp(w, b->qd_w, sizeof w) == 0, "the next step keeps the tight root");
    acbb_qd_free(qd);
    acbb_qd_free(q1);
    acbb_mech_free(f.m);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_residual(15000, 1000);
    test_residual(15000, 100);  /* light load: skidding regime (MODEL 11) */
    test_pure_rolling();
    test_guards();
    test_skip();
    test_neighbour_start();
    test_relax();
    test_own_restart();
    test_path_tol();
    return done_testing();
}
