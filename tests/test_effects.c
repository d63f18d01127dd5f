/* Every effect is honest (issue "any bearing", part 4): a switched-off
 * effect does zero work, and the result is its analytic special case.
 * Work counters: acbb_snapshot.work (sim.h). */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "acbb/sim.h"
#include "acbb/units.h"
#include "acbb/tools/scene_inactive.h"
#include "hertz.h"
#include "mechanics.h"

static acbb_snapshot snap_a, snap_b; /* large structs off the stack */

static acbb_scene base(acbb_model_level model)
{
    acbb_scene s;
    acbb_scene_default(&s);
    s.model = model;
    return s;
}

static acbb_status run(const acbb_scene *s, acbb_snapshot *snap)
{
    acbb_sim *sim;
    acbb_error err = { "" };
    acbb_status rc = acbb_sim_create(s, NULL, &sim, &err);
    if (rc != ACBB_OK) {
        printf("# set-up failed: %s\n", err.msg);
        return rc;
    }
    rc = acbb_sim_run(sim);
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    return rc;
}

/* Without centrifugal force and gyroscopic moment, a ball under pure
 * thrust is a two-force body: inner angle = outer angle (MODEL.md 3). */
static void test_two_force_ball(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_STATIC);
    s.centrifugal = s.gyroscopic = false;
    ok(run(&s, &snap_a) == ACBB_OK, "quasi-static, no centrifugal/gyroscopic: converges");
    const acbb_ball_view *b = &snap_a.balls[0];
    is_close(b->alpha_i, b->alpha_o, 0, 1e-9, "alpha_i = alpha_o at 15000 rpm (two-force ball)");
    is_close(b->Qi, b->Qo, 1e-9, 0, "Qi = Qo (no body force)");
    s.centrifugal = true;
    run(&s, &snap_b);
    ok(snap_b.balls[0].alpha_i - snap_b.balls[0].alpha_o > 0.01,
       "centrifugal on: alpha_i - alpha_o = %.3f deg", acbb_rad_to_deg(snap_b.balls[0].alpha_i
                                                                        - snap_b.balls[0].alpha_o));
}

/* The gyroscopic switch acts at the quasi-dynamic level too (it used to be
 * ignored there: the same numbers to the last digit). */
static void test_gyroscopic_quasi_dynamic(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_DYNAMIC);
    run(&s, &snap_a);
    s.gyroscopic = false;
    run(&s, &snap_b);
    double wy_on = snap_a.balls[0].omega_y, wy_off = snap_b.balls[0].omega_y;
    ok(fabs(snap_a.balls[0].Qi - snap_b.balls[0].Qi) > 1e-6 * snap_a.balls[0].Qi,
       "quasi-dynamic: gyroscopic off changes Qi (%.6f vs %.6f N)", snap_a.balls[0].Qi,
       snap_b.balls[0].Qi);
    ok(fabs(wy_off) < 0.1 * fabs(wy_on) || fabs(wy_on) < 1e-9,
       "without the gyroscopic moment the pivoting speed omega_y' collapses (%.4g -> %.4g rad/s)",
       wy_on, wy_off);
}

/* All losses off: nothing heats, so the steady state is ambient
 * everywhere, and no loss integral was evaluated. */
static void test_no_losses(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_STATIC);
    s.loss_shear = s.loss_slip = s.loss_spin = s.loss_rolling = s.loss_drag = s.loss_cage = false;
    ok(run(&s, &snap_a) == ACBB_OK, "every loss off: converges");
    double dev = 0.0;
    for (int i = 0; i < snap_a.n_nodes; i++) dev = fmax(dev, fabs(snap_a.T[i] - s.ambient_C));
    ok(dev < 1e-9, "every node at ambient (max deviation %.3g K)", dev);
    ok(snap_a.losses.total == 0.0, "total loss exactly 0 W");
    ok(snap_a.work.loss_quadratures == 0, "no loss quadrature ran (%ld)",
       snap_a.work.loss_quadratures);
}

/* WTE: no expansion is ever evaluated. */
static void test_wte_no_expansion_work(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_STATIC);
    s.thermal_expansion = false;
    run(&s, &snap_a);
    ok(snap_a.work.expansion_updates == 0 && snap_a.exp_inner_cen == 0.0,
       "WTE: expansion updates = %ld, centrifugal growth %.3g m",
       snap_a.work.expansion_updates, snap_a.exp_inner_cen);
    s.thermal_expansion = true;
    run(&s, &snap_b);
    ok(snap_b.work.expansion_updates > 0, "TE: expansions evaluated (%ld)",
       snap_b.work.expansion_updates);
}

/* heating = off: isothermal at ambient, no network solve; with WTE it is
 * the WTE mechanics of a scene that makes no heat (every loss off, which
 * leaves the quasi-static mechanics unchanged). */
static void test_heating_off(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_STATIC);
    s.heating = false;
    s.thermal_expansion = false;
    ok(run(&s, &snap_a) == ACBB_OK && snap_a.state == ACBB_RUN_CONVERGED,
       "heating off: converges (%s)", snap_a.message);
    ok(snap_a.work.network_solves == 0, "heating off: no network solve (%ld)",
       snap_a.work.network_solves);
    ok(snap_a.T_outer_ring == s.ambient_C && snap_a.T_ball == s.ambient_C,
       "heating off: temperatures stay at ambient");
    ok(snap_a.losses.total > 0.0, "heating off: losses are still reported (%.3f W)",
       snap_a.losses.total);
    acbb_scene w = base(ACBB_MODEL_QUASI_STATIC);
    w.thermal_expansion = false;
    w.loss_shear = w.loss_slip = w.loss_spin = w.loss_rolling = w.loss_drag = false;
    run(&w, &snap_b);
    is_close(snap_a.balls[0].Qi, snap_b.balls[0].Qi, 1e-9, 0, "heating off = WTE mechanics: Qi");
    is_close(snap_a.balls[0].alpha_o, snap_b.balls[0].alpha_o, 1e-9, 0,
             "heating off = WTE mechanics: alpha_o");
    is_close(snap_a.delta_x, snap_b.delta_x, 1e-9, 0, "heating off = WTE mechanics: delta_x");
}

/* The squeeze decomposition adds up (MODEL.md 13) and the axial stiffness
 * matches a finite difference of two runs at slightly different loads. */
static void test_squeeze_and_stiffness(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_STATIC);
    s.heating = false;
    run(&s, &snap_a);
    const acbb_squeeze *q = &snap_a.squeeze;
    is_close(q->net, q->inner_thermal + q->inner_centrifugal + q->outer + q->ball, 1e-12, 0,
             "squeeze net = sum of its terms");
    is_close(q->inner_centrifugal, snap_a.exp_inner_cen, 1e-12, 0,
             "squeeze: inner centrifugal term = theta_icen");
    double K = snap_a.stiffness_axial;
    s.axial_load *= 1.001;
    run(&s, &snap_b);
    double K_fd = (snap_b.reaction_x - snap_a.reaction_x) / (snap_b.delta_x - snap_a.delta_x);
    is_close(K, K_fd, 2e-3, 0, "axial stiffness = dFx/d(delta_x) from two runs");
    ok(K > 1e7 && K < 1e9, "7008C axial stiffness %.1f N/um is of catalogue size (10..1000)",
       K * 1e-6);
}

/* Zero-speed thrust (Harris & Kotzalas, rigid rings): with the loaded angle
 * alpha from Fx = Z Kn A0^1.5 (cos a0 / cos a - 1)^1.5 sin a, the axial
 * deflection is delta_a = A0 sin(a - a0) / cos a. Kn from the Hertz
 * constants of both contacts at that angle (Kn^-2/3 = Ki^-2/3 + Ko^-2/3). */
static void test_thrust_deflection(void)
{
    acbb_scene s = base(ACBB_MODEL_STATIC);
    s.inner_speed = 0.0;
    s.heating = false;
    s.hertz = ACBB_HERTZ_EXACT;
    ok(run(&s, &snap_a) == ACBB_OK, "7008C at rest under 1000 N: converges");
    double D = s.ball_diameter, fi = s.inner_groove_radius / D, fo = s.outer_groove_radius / D;
    double A0 = s.inner_groove_radius + s.outer_groove_radius - D, a0 = s.contact_angle0;
    double E = acbb_effective_modulus(s.ball.E, s.ball.nu, s.ring.E, s.ring.nu);
    double a = snap_a.balls[0].alpha_i, K[2];
    for (int inner = 0; inner < 2; inner++) {
        double Rx, Ry;
        acbb_hertz_const hc;
        acbb_contact_radii(D, s.pitch_diameter, a, inner ? fi : fo, inner, &Rx, &Ry);
        acbb_hertz_const_compute(Rx, Ry, E, ACBB_HERTZ_EXACT, &hc);
        K[inner] = hc.Kc;
    }
    double Kn = pow(pow(K[0], -2.0 / 3.0) + pow(K[1], -2.0 / 3.0), -1.5);
    double a_cf = acbb_static_thrust_angle(s.axial_load, s.n_balls, Kn, A0, a0);
    is_close(a, a_cf, 1e-6, 0, "loaded angle = the closed-form thrust angle");
    is_close(snap_a.delta_x, A0 * sin(a_cf - a0) / cos(a_cf), 1e-6, 0,
             "axial deflection delta_x = A0 sin(a - a0) / cos a");
}

/* Radial and tilt stiffness (stiffness.h) against two full runs each, at
 * the quasi-static level without heating (the same race-control ball model).
 * The radial stiffness holds the tilt at the operating point's: the runs
 * compare with a held ring (tilt 0 there); the tilt stiffness (radial
 * free) with runs whose tilt is free (the default). */
static void test_ring_stiffness(void)
{
    acbb_scene s = base(ACBB_MODEL_QUASI_STATIC);
    s.heating = false;
    s.radial_load = 500.0;
    s.tilt = ACBB_TILT_HELD;
    ok(run(&s, &snap_a) == ACBB_OK, "1000 N axial + 500 N radial, isothermal: converges");
    double Kr = snap_a.stiffness_radial, h = 10.0;
    s.radial_load = 500.0 + h;
    run(&s, &snap_b);
    double dz1 = snap_b.delta_z;
    s.radial_load = 500.0 - h;
    run(&s, &snap_b);
    is_close(Kr, 2.0 * h / (dz1 - snap_b.delta_z), 0.02, 0,
             "radial stiffness = dFz/d(delta_z) from two runs (+-10 N)");
    s.radial_load = 500.0;
    s.tilt = ACBB_TILT_AUTO;
    run(&s, &snap_b);
    double Kt = snap_b.stiffness_tilt;
    s.moment_load = 0.27;
    run(&s, &snap_b);
    double t1 = snap_b.tilt_y;
    s.moment_load = -0.27;
    run(&s, &snap_b);
    is_close(Kt, 0.54 / (t1 - snap_b.tilt_y), 0.02, 0,
             "tilt stiffness = dMy/d(theta_y) from two runs (+-0.27 N m)");
    ok(Kr > snap_a.stiffness_axial, "a 15 deg bearing is stiffer radially (%.0f N/um) than axially "
       "(%.0f N/um)", Kr * 1e-6, snap_a.stiffness_axial * 1e-6);
}

/* Inputs the scene as set cannot feel are named with the key that makes
 * them act (issue 29 item 1): a single bearing's preload_N under a force
 * preload, its axial load under a displacement preload; and the per-key
 * query a what-if line asks (acbb_scene_key_inactive), names listed after
 * a sectioned first one and wildcards included. */
static void test_inactive_keys(void)
{
    acbb_scene s;
    acbb_inactive_effect e = { "", "", "" };
    bool off;
    acbb_scene_default(&s);
    ok(!acbb_scene_key_inactive(&s, "mounting.preload_N", NULL),
       "force preload, default preload_N: nothing to say");
    s.preload_force = 600.0;
    off = acbb_scene_key_inactive(&s, "mounting.preload_N", &e);
    ok(off && strstr(e.why, "mounting.preload = displacement"),
       "force preload, preload_N = 600: no effect, and says what makes it act (%s)", e.why);
    ok(!acbb_scene_key_inactive(&s, "operating.axial_load_N", NULL),
       "force preload: the axial load acts");
    s.preload = ACBB_PRELOAD_DISPLACEMENT;
    s.axial_load = 1000.0;
    off = acbb_scene_key_inactive(&s, "operating.axial_load_N", &e);
    ok(off && strstr(e.why, "mounting.preload = force")
           && !acbb_scene_key_inactive(&s, "mounting.preload_N", NULL),
       "displacement preload: the axial load has none, preload_N has (%s)", e.why);
    s.set_arrangement = ACBB_SET_DB;
    ok(!acbb_scene_key_inactive(&s, "operating.axial_load_N", NULL),
       "a DB pair under displacement preload carries the axial load");
    acbb_scene_default(&s);
    s.schedule_n = 1;
    ok(acbb_scene_key_inactive(&s, "operating.radial_load_N", NULL)
           && acbb_scene_key_inactive(&s, "operating.inner_speed_rpm", NULL)
           && !acbb_scene_key_inactive(&s, "operating.moment_load_Nm", NULL),
       "a schedule: speed and loads named in one row (sectioned first, then bare names)");
    acbb_scene_default(&s);
    s.network = ACBB_NET_7;
    s.cap_thickness = 5e-3;
    ok(acbb_scene_key_inactive(&s, "surroundings.cap_outer_diameter_mm", NULL)
           && acbb_scene_key_inactive(&s, "surroundings.cap_thickness_mm", NULL)
           && !acbb_scene_key_inactive(&s, "surroundings.housing_outer_diameter_mm", NULL),
       "a wildcard row (surroundings.cap_*) names each cap key, no other");
    s.model = ACBB_MODEL_STATIC;
    ok(acbb_scene_key_inactive(&s, "effects.centrifugal", NULL),
       "an effect switch row (\"effects.centrifugal = on\") names its key");
}

int main(void)
{
    test_inactive_keys();
    gsl_set_error_handler_off();
    test_ring_stiffness();
    test_thrust_deflection();
    test_two_force_ball();
    test_gyroscopic_quasi_dynamic();
    test_no_losses();
    test_wte_no_expansion_work();
    test_heating_off();
    test_squeeze_and_stiffness();
    return done_testing();
}
