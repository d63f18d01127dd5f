/* The spindle as a plant of the one stepper (src/run/spindle*.c,
 * docs/spindle.md "Integration"): the shaft and both bearing sets solved
 * together. Scenes are built in C from the DB pair of 7008C
 * (presets/pair-DB-heated.ini) on a stepped hollow shaft; the mechanics
 * tests run isothermal (effects.heating = off: one converged state). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "acbb/sim.h"
#include "acbb/set.h"
#include "acbb/fidelity.h"
#include "spindle_priv.h"
#include "sim_struct.h"

#define FRONT_X 0.060   /* m from the nose */
#define REAR_X 0.300
#define FR 800.0        /* N, radial nose load */
#define FA 150.0        /* N, axial nose load */

/* The DB pair of 7008C (200 N rigid preload, 8000 rpm) as the front set,
 * a DB pair of the same bearing (200 N) as the rear, on a 0.36 m shaft of
 * two segments (40 mm bearing seats; 36 mm over the span), isothermal. */
static int spindle_scene(acbb_scene *s, const char *const *more, int n_more)
{
    acbb_error err = { "" };
    const char *edits[] = { "effects.heating=off" };
    if (acbb_scene_load("presets/pair-DB-heated.ini", s, &err) != ACBB_OK
        || acbb_scene_apply_edits(s, edits, 1, &err) != ACBB_OK
        || (n_more && acbb_scene_apply_edits(s, more, n_more, &err) != ACBB_OK)) {
        ok(0, "scene: %s", err.msg);
        return 0;
    }
    s->shaft_segments = 2;
    s->shaft_seg[0] = (acbb_segment){ 0.10, 0.040, 0.015 };
    s->shaft_seg[1] = (acbb_segment){ 0.26, 0.040, 0.015 };
    s->shaft_n_div = 4;
    s->spindle_front_x = FRONT_X;
    s->spindle_rear_x = REAR_X;
    s->spindle_rear_support = ACBB_REAR_FIXED;
    s->spindle_rear_arrangement = ACBB_SET_DB;
    s->spindle_rear_spacing = 0.0;
    s->spindle_rear_preload = 200.0;
    s->axial_load = FA;
    s->radial_load = FR;
    return 1;
}

/* is_close with the name formatted (a bearing's index). */
static int close_k(double got, double want, double rtol, double atol, const char *fmt, int k)
{
    char name[160];
    snprintf(name, sizeof name, fmt, k);
    return is_close(got, want, rtol, atol, name);
}

static int run_sim(acbb_sim *sim, acbb_snapshot *o)
{
    acbb_sim_run(sim);
    acbb_sim_snapshot(sim, o);
    return o->state == ACBB_RUN_CONVERGED;
}

static int run_spindle(acbb_spindle_sim *sp, acbb_snapshot *o)
{
    while (acbb_spindle_sim_step(sp) == ACBB_OK) {
        acbb_status st;
        long it;
        if (acbb_spindle_sim_outcome(sp, &st, &it) != ACBB_RUN_RUNNING) break;
    }
    acbb_spindle_sim_snapshot(sp, o);
    return o->state == ACBB_RUN_CONVERGED;
}

/* (a) A practically rigid shaft (E x 1e6) on the front set alone (the rear
 * carries nothing: one_support) is the front set under the nose loads
 * moved to its centre: the set run with set.load_offset_mm = -60 (the nose
 * 60 mm in front of the set's centre, set x along the shaft's). Its
 * bearings' most loaded balls, their contact angles, and the nose
 * displacement (the set's shaft move carried rigidly to the nose:
 * w = dz + tilt a, plus the overhang's own deflection) agree to the
 * solvers' tolerance (1e-6 relative for loads, 1e-5 deg for angles,
 * 1e-5 um for the displacement: the members solve to mech_tol 1e-8). */
static void test_rigid_one_support(void)
{
    static acbb_scene s, set;
    if (!spindle_scene(&s, NULL, 0)) return;
    set = s;
    set.shaft_segments = 0;
    set.set_load_offset = -FRONT_X;
    acbb_error err = { "" };
    acbb_spindle_sim *sp = NULL;
    acbb_sim *ref = NULL;
    static acbb_snapshot a, b, bb;
    acbb_scene r;
    acbb_scene_resolve(&s, &r, NULL);
    if (!ok(acbb_spindle_sim_new(&r, &(acbb_sim_opts){ 0 }, 1, &sp, &err) == ACBB_OK,
            "(a) one-support spindle builds: %s", err.msg))
        return;
    /* The shaft rebuilt practically rigid: E = 1e13 Pa (the beam's largest,
     * 47 x steel's) and 400 mm outer diameter (1e4 x the bending
     * inertia): 5e5 x stiffer. The sets keep the steel shaft of their own
     * scene for their fits (materials.shaft stays a valid steel). */
    acbb_shaft_beam_free(sp->beam);
    sp->beam = NULL;
    acbb_scene keep = sp->s;
    sp->s.shaft.E = 1e13;
    for (int i = 0; i < sp->s.shaft_segments; i++) sp->s.shaft_seg[i].od = 0.4;
    ok(acbb_spindle_beam_build(sp, &err) == ACBB_OK, "(a) rigid shaft built: %s", err.msg);
    sp->s = keep;
    ok(run_spindle(sp, &a), "(a) spindle converged: %s", a.message);
    err.msg[0] = '\0';
    if (!ok(acbb_sim_create(&set, &(acbb_sim_opts){ 0 }, &ref, &err) == ACBB_OK,
            "(a) the set alone builds: %s", err.msg)) {
        acbb_spindle_sim_free(sp);
        return;
    }
    ok(run_sim(ref, &b), "(a) set converged: %s", b.message);
    const acbb_spindle_set_view *f = &a.spindle.sets[0];
    is_close(f->axial_N, FA, 1e-9, 1e-9, "(a) front set's thrust = the nose's");
    is_close(f->radial_N, FR, 1e-9, 1e-9, "(a) front set's radial load = the nose's");
    is_close(f->moment_Nm, FRONT_X * FR, 1e-9, 1e-9, "(a) front set's moment = F_r a");
    for (int k = 0; k < 2; k++) {
        acbb_sim_bearing_snapshot(ref, k, &bb);
        double Q = 0.0, ai = 0.0, ao = 0.0;
        int jm = 0;
        for (int j = 0; j < bb.n_balls; j++) {
            if (bb.balls[j].Qi > bb.balls[jm].Qi) jm = j;
            Q = fmax(Q, fmax(bb.balls[j].Qi, bb.balls[j].Qo));
        }
        ai = bb.balls[jm].alpha_i * 180.0 / M_PI;
        ao = bb.balls[jm].alpha_o * 180.0 / M_PI;
        close_k(f->Q_max_N[k], Q, 1e-6, 0.0, "(a) bearing %d: largest ball load, N", k);
        close_k(f->contact_angle_inner_deg[k], ai, 0.0, 1e-5,
                "(a) bearing %d: inner contact angle of the most loaded ball, deg", k);
        close_k(f->contact_angle_outer_deg[k], ao, 0.0, 1e-5,
                "(a) bearing %d: outer contact angle of the most loaded ball, deg", k);
    }
    /* The overhang's own bending and shear as a cantilever from the
     * station (Timoshenko, exact for a point load): P a^3/(3EI) + P a/(kGA),
     * 1.2e-4 um here, the shear term nearly all of it. */
    acbb_shaft_seg g = { 0.10, 0.4, 0.015, 1e13, s.shaft.nu, 0, 0, 0, 0 };
    double G = g.E / (2.0 * (1.0 + g.nu));
    double cant = FR * pow(FRONT_X, 3) / (3.0 * g.E * acbb_seg_inertia(&g))
                + FR * FRONT_X / (acbb_seg_shear_coeff(&g) * G * acbb_seg_area(&g));
    double w = b.set.shaft_dz + b.set.shaft_tilt * FRONT_X + cant;
    is_close(a.spindle.nose_w * 1e6, w * 1e6, 0.0, 1e-5, "(a) nose radial displacement, um "
             "(the set's, carried rigidly to the nose, plus the overhang as a cantilever)");
    is_close(a.spindle.nose_u * 1e6, b.set.shaft_dx * 1e6, 0.0, 1e-5,
             "(a) nose axial displacement, um");
    is_close(a.spindle.nose_theta, -b.set.shaft_tilt, 0.0, 1e-8, "(a) nose rotation, rad");
    acbb_spindle_sim_free(sp);
    acbb_sim_free(ref);
}

int main(void)
{
    test_rigid_one_support();
    return done_testing();
}
