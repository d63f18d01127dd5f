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
#include "acbb/tools/set.h"
#include "acbb/tools/fidelity.h"
#include "spindle_priv.h"
#include "sim_struct.h"
#include "snapshot_check.h"

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
    s->housing_segments = 1; /* its bore the bearings' outer diameter (the seats) */
    s->housing_seg[0] = (acbb_segment){ 0.32, 0.120, s->outer_diameter };
    s->shaft_bore = 0.015; /* the bearings' own models: the spindle's at the front set */
    s->housing_od = 0.120;
    s->housing_x0 = 0.02;
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
    /* The front set's loads are its support's reaction at the shaft's
     * solution, a sum over its members' balls. Each ball is solved to a
     * force residual of mech_tol x its bearing's load per ball
     * (mechanics.c ball_force_scale); over the set's balls that is
     * mech_tol x sum(|Fx| + |Fz|) of the members, at most mech_tol x
     * sqrt(2) x the sum of their inner contact loads Qi (the set alone
     * carries the same balls' loads: asserted below to 1e-6). The shaft's
     * Newton takes its last step whole once it is below 100 mech_tol of the
     * displacements (spindle_mech.c) with a tangent good to 1e-4, which
     * leaves 1e-2 of that on top. The moment's error is those forces on
     * arms up to the pitch radius plus a member's offset from the set's
     * centre. A balance off by 1e-6 of the loads fails (3.8x on the thrust
     * here: 1.5e-4 N against 3.9e-5 N); 1e-9 of them (a different, equally
     * converged root: 48.00000006 N m once) does not. */
    acbb_set_sim *front = sp->st[ACBB_FRONT].ss;
    double sum_q = 0.0, arm = 0.0;
    for (int k = 0; k < 2; k++) {
        acbb_sim_bearing_snapshot(ref, k, &bb);
        for (int j = 0; j < bb.n_balls; j++) sum_q += bb.balls[j].Qi;
        arm = fmax(arm, fabs(sp->st[ACBB_FRONT].w.x[k]));
    }
    arm += 0.5 * acbb_mech_geometry(front->b[0]->mech)->dm;
    const double tol_F = r.mech_tol * M_SQRT2 * sum_q, tol_M = tol_F * arm;
    is_close(f->axial_N, FA, 0.0, tol_F, "(a) front set's thrust = the nose's");
    is_close(f->radial_N, FR, 0.0, tol_F, "(a) front set's radial load = the nose's");
    is_close(f->moment_Nm, FRONT_X * FR, 0.0, tol_M, "(a) front set's moment = F_r a");
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

/* Build and run a spindle through the public Sim (sim.c's hook). */
static acbb_sim *create_run(const acbb_scene *s, acbb_snapshot *o, const char *what)
{
    acbb_error err = { "" };
    acbb_sim *sim = NULL;
    if (!ok(acbb_sim_create(s, &(acbb_sim_opts){ 0 }, &sim, &err) == ACBB_OK,
            "%s: spindle builds: %s", what, err.msg))
        return NULL;
    acbb_sim_run(sim);
    acbb_sim_snapshot(sim, o);
    return sim;
}

/* ... and it converges, with the spindle's view. */
static acbb_sim *run_public(const acbb_scene *s, acbb_snapshot *o, const char *what)
{
    acbb_sim *sim = create_run(s, o, what);
    if (!sim) return NULL;
    ok(o->state == ACBB_RUN_CONVERGED, "%s: converged: %s", what, o->message);
    ok(o->spindle.n_sets == ACBB_SPINDLE_SETS, "%s: the snapshot has the spindle's view "
       "(n_sets = %d)", what, o->spindle.n_sets);
    return sim;
}

/* Each set's own shaft equilibrium under its station's reaction lands on
 * the shaft's station displacement (spindle.c landing()): it starts there
 * and moves only if the loads do not balance its members there to its own
 * tolerance, so this checks that the reactions the shaft used are the
 * set's equilibrium loads (at the state reached; inside a transient step
 * at the quasi-dynamic level the ball speeds lag one step and the set
 * moves by up to 0.1 um). */
static void check_landing(const acbb_sim *sim, const char *what)
{
    for (int k = 0; k < 2; k++)
        ok(sim->spindle->st[k].landing < 1e-10, "%s: the %s set's own solve lands on the "
           "shaft's station to 1e-10 m (%.2g)", what, k ? "rear" : "front",
           sim->spindle->st[k].landing);
}

/* (c) Force balance on the free shaft: the loads the sets carry equal the
 * nose loads (axial, radial, and moment about the nose: sum of M_k - x_k
 * F_r,k = the nose moment, 0 here, in the sets' frame, spindle_priv.h), to
 * 1e-9 of the radial load: the beam's Newton residual. */
static void test_balance(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    if (!spindle_scene(&s, NULL, 0)) return;
    acbb_sim *sim = run_public(&s, &o, "(c) two DB pairs, rear fixed");
    if (!sim) return;
    const acbb_spindle_set_view *v = o.spindle.sets;
    double Fx = v[0].axial_N + v[1].axial_N, Fr = v[0].radial_N + v[1].radial_N;
    double M = v[0].moment_Nm - v[0].x * v[0].radial_N + v[1].moment_Nm - v[1].x * v[1].radial_N;
    is_close(Fx, FA, 0.0, 1e-9 * FR, "(c) the sets' thrusts sum to the nose's");
    is_close(Fr, FR, 0.0, 1e-9 * FR, "(c) the sets' radial loads sum to the nose's");
    is_close(M, 0.0, 0.0, 1e-9 * FR * REAR_X, "(c) the moments about the nose balance, N m");
    ok(v[1].radial_N < 0.0 && v[0].radial_N > FR, "(c) the rear set pulls against the nose "
       "load, the front carries more than it (%.1f, %.1f N)", v[0].radial_N, v[1].radial_N);
    check_landing(sim, "(c)");
    ok(snapshot_plausible(&o, 1), "(c) the front set's snapshot is plausible");
    acbb_sim_free(sim);
}

/* Gaussian elimination with partial pivoting of an n x n system (n <= 9). */
static void solve_n(int n, double A[9][9], double *b)
{
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int r = c + 1; r < n; r++) if (fabs(A[r][c]) > fabs(A[p][c])) p = r;
        for (int k = 0; k < n; k++) { double t = A[c][k]; A[c][k] = A[p][k]; A[p][k] = t; }
        double t = b[c]; b[c] = b[p]; b[p] = t;
        for (int r = c + 1; r < n; r++) {
            double f = A[r][c] / A[c][c];
            for (int k = c; k < n; k++) A[r][k] -= f * A[c][k];
            b[r] -= f * b[c];
        }
    }
    for (int c = n - 1; c >= 0; c--) {
        for (int k = c + 1; k < n; k++) b[c] -= A[c][k] * b[k];
        b[c] /= A[c][c];
    }
}

/* The nose's radial compliance (m/N, the other nose loads zero) of a
 * uniform Timoshenko shaft, nose - support 1 - support 2 over a and l:
 * two exact elements (docs/spindle.md's element matrix, an axial bar EA/L
 * beside it), each support a 3 x 3 stiffness on (u, w, theta); the nine
 * displacements of the three nodes under a unit radial nose load. */
static double nose_compliance(double EA, double EI, double kGA, double a, double l,
                              const double K[2][9])
{
    double A[9][9] = { { 0 } }, b[9] = { 0, 1, 0, 0, 0, 0, 0, 0, 0 };
    const double L[2] = { a, l };
    for (int e = 0; e < 2; e++) {
        double phi = 12.0 * EI / (kGA * L[e] * L[e]), q = EI / ((1.0 + phi) * pow(L[e], 3));
        double x = L[e], m[4][4] = {
            { 12, 6 * x, -12, 6 * x }, { 6 * x, (4 + phi) * x * x, -6 * x, (2 - phi) * x * x },
            { -12, -6 * x, 12, -6 * x }, { 6 * x, (2 - phi) * x * x, -6 * x, (4 + phi) * x * x } };
        const int dof[4] = { 3 * e + 1, 3 * e + 2, 3 * e + 4, 3 * e + 5 };
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) A[dof[i]][dof[j]] += q * m[i][j];
        double ka = EA / x;
        A[3 * e][3 * e] += ka, A[3 * e + 3][3 * e + 3] += ka;
        A[3 * e][3 * e + 3] -= ka, A[3 * e + 3][3 * e] -= ka;
    }
    for (int s = 0; s < 2; s++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) A[3 + 3 * s + i][3 + 3 * s + j] += K[s][3 * i + j];
    solve_n(9, A, b);
    return b[1];
}

/* A support of uncoupled springs: axial, radial, tilt. */
static void springs(double k_axial, double k_radial, double k_tilt, double K[9])
{
    memset(K, 0, 9 * sizeof *K);
    K[0] = k_axial, K[4] = k_radial, K[8] = k_tilt;
}

/* (b) The nose's radial stiffness against docs/spindle.md's unit-load hand
 * calculation for a uniform shaft on two point supports (overhang a, span
 * l, EI and kGA of the shaft, each set's own radial stiffness k1, k2 at
 * that state: the set's K_rad, a radial force at its centre with its tilt
 * free). Those sets also resist tilting (a DB pair's contact lines spread
 * far apart), which point supports leave out: here that makes the spindle
 * 36 % stiffer than the hand calculation. So the hand calculation is done
 * twice: as written (the spindle must be stiffer, never softer), and with
 * each support's tilt spring c_i = the set's own K_tilt (a moment at its
 * centre, radial force free) in the same unit-load problem written as two
 * exact elements: within 3 % (2.6 % here), the supports' couplings
 * (radial-tilt-axial: a loaded angular contact set's stiffness has
 * off-diagonal terms), left out of uncoupled springs; with the supports'
 * own coupled 3 x 3 tangents, to 1e-6. */
static void test_nose_stiffness(void)
{
    static acbb_scene s;
    static acbb_snapshot o, rear;
    if (!spindle_scene(&s, NULL, 0)) return;
    acbb_sim *sim = run_public(&s, &o, "(b)");
    if (!sim) return;
    acbb_sim_bearing_snapshot(sim, 2, &rear);
    double k1 = o.set.stiffness_radial, k2 = rear.set.stiffness_radial;
    acbb_shaft_seg g = { 0.36, 0.040, 0.015, s.shaft.E, s.shaft.nu, 0, 0, 0, 0 };
    double EI = g.E * acbb_seg_inertia(&g);
    double kGA = acbb_seg_shear_coeff(&g) * g.E / (2.0 * (1.0 + g.nu)) * acbb_seg_area(&g);
    double a = FRONT_X, l = REAR_X - FRONT_X;
    double C = pow(a, 3) / (3.0 * EI) + a / kGA + a * a * l / (3.0 * EI) + a * a / (l * kGA)
             + pow(1.0 + a / l, 2) / k1 + pow(a / l, 2) / k2;
    double k = o.spindle.nose_k_radial, hand = 1.0 / C;
    ok(k1 > 0.0 && k2 > 0.0, "(b) the sets' radial stiffness %.4g, %.4g N/um", k1 * 1e-6,
       k2 * 1e-6);
    ok(k >= hand, "(b) nose radial stiffness %.5g N/um >= the point-support hand "
       "calculation's %.5g N/um (+%.1f %%: the sets' tilt stiffness)", k * 1e-6, hand * 1e-6,
       100.0 * (k / hand - 1.0));
    double EA = g.E * acbb_seg_area(&g), Ks[2][9];
    springs(o.set.stiffness_axial, k1, o.set.stiffness_tilt, Ks[0]);
    springs(rear.set.stiffness_axial, k2, rear.set.stiffness_tilt, Ks[1]);
    double tilt = 1.0 / nose_compliance(EA, EI, kGA, a, l, Ks);
    is_close(k * 1e-6, tilt * 1e-6, 0.03, 0.0, "(b) ... and within 3 % of it with each set's "
             "tilt stiffness as a tilt spring, N/um");
    springs(1.0, k1, 0.0, Ks[0]);
    springs(0.0, k2, 0.0, Ks[1]);
    is_close(1.0 / nose_compliance(EA, EI, kGA, a, l, Ks), hand, 1e-9, 0.0,
             "(b) the two-element problem with point supports is the hand calculation");
    /* With each support's own 3 x 3 tangent (couplings in), the two-element
     * problem is the spindle's shaft, to the elements' exactness: 1e-6 (the
     * tangents are the supports' last, at the state). */
    const acbb_spindle_sim *sp = sim->spindle;
    memcpy(Ks[0], sp->st[0].K, sizeof Ks[0]);
    memcpy(Ks[1], sp->st[1].K, sizeof Ks[1]);
    is_close(k, 1.0 / nose_compliance(EA, EI, kGA, a, l, Ks), 1e-6, 0.0,
             "(b) ... and with the supports' own tangents (couplings in) to 1e-6, N/m");
    acbb_sim_free(sim);
}

/* (d) A spring-loaded rear bearing (single) carries exactly the spring's
 * force; the front set carries the nose thrust less it. */
static void test_spring_rear(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    if (!spindle_scene(&s, NULL, 0)) return;
    s.spindle_rear_support = ACBB_REAR_SPRING;
    s.spindle_rear_arrangement = ACBB_SET_SINGLE;
    s.spindle_rear_spring = 300.0;
    acbb_sim *sim = run_public(&s, &o, "(d) spring rear");
    if (!sim) return;
    const acbb_spindle_set_view *v = o.spindle.sets;
    is_close(v[1].axial_N, 300.0, 0.0, 0.0, "(d) the rear set's axial force = rear_spring_N");
    const acbb_set_mech *sm = &sim->spindle->st[1].ss->sm;
    is_close(sm->Fx[0], 300.0, 1e-7, 0.0, "(d) ... and its bearing's balls carry it");
    is_close(v[0].axial_N, FA - 300.0, 0.0, 1e-9 * FR, "(d) the front set: the nose thrust "
             "less the spring's");
    ok(v[1].n_bearings == 1 && v[1].preload_N == 300.0 && v[0].preload_N > 0.0,
       "(d) the rear single bearing is preloaded by the spring (%.1f N)", v[1].preload_N);
    check_landing(sim, "(d)");
    acbb_sim_free(sim);
}

/* Every double of the view is finite. */
static int view_finite(const acbb_spindle_view *v)
{
    const double *p = (const double *)(const void *)&v->nose_drift_axial;
    const double *end = (const double *)(const void *)(v + 1);
    for (; p < end; p++) if (!isfinite(*p)) return 0;
    for (int k = 0; k < 2; k++) {
        const acbb_spindle_set_view *s = &v->sets[k];
        double f[] = { s->x, s->preload_N, s->axial_N, s->radial_N, s->moment_Nm, s->loss_W,
                       s->T_inner_C, s->T_outer_C, s->T_ball_C };
        for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) if (!isfinite(f[i])) return 0;
    }
    return 1;
}

/* (e) A heated steady spindle converges; its snapshot is plausible and its
 * view finite, the bearings warm and their heat balanced. */
static void test_steady(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const char *edits[] = { "fidelity.thermal_mode=steady" };
    if (!spindle_scene(&s, edits, 1)) return;
    s.heating = 1;
    acbb_sim *sim = run_public(&s, &o, "(e) steady, heated");
    if (!sim) return;
    ok(view_finite(&o.spindle), "(e) every value of the view is finite");
    ok(snapshot_plausible(&o, 1), "(e) the front set's snapshot is plausible");
    const acbb_spindle_set_view *v = o.spindle.sets;
    ok(v[0].T_inner_C > s.ambient_C + 1.0 && v[1].T_inner_C > s.ambient_C + 1.0,
       "(e) both sets warm (inner rings %.1f, %.1f C)", v[0].T_inner_C, v[1].T_inner_C);
    is_close(o.spindle.Q_bearings_W, v[0].loss_W + v[1].loss_W, 1e-9, 0.0,
             "(e) the bearings' heat is both sets' losses");
    is_close(o.heat_out, o.heat_in, 1e-9, 0.0, "(e) the network passes the bearings' heat "
             "to the air");
    const acbb_spindle_view *v2 = &o.spindle;
    /* A fixed rear set's rings move against each other by the shaft's u
     * plus the network's thermal shift between the sets (spindle_priv.h). */
    const acbb_spindle_sim *sp = sim->spindle;
    double x, d[3] = { 0, 0, 0 };
    for (int i = 0; i < acbb_shaft_beam_nodes(sp->beam); i++)
        if (acbb_shaft_beam_node(sp->beam, i, &x, d) == ACBB_OK && fabs(x - REAR_X) < 1e-12) break;
    ok(fabs(v2->rear_shift) > 1e-7, "(e) the shaft grows against the housing between the sets "
       "(%.3f um)", v2->rear_shift * 1e6);
    is_close(sp->st[1].ss->sm.q[0] * 1e6, (d[0] + v2->rear_shift) * 1e6, 0.0, 1e-6,
             "(e) the fixed rear set's rings move by the shaft's u plus the shift, um");
    check_landing(sim, "(e)");
    acbb_sim_free(sim);
}

/* Statuses: a spindle that cannot go on ends with a named status, its
 * message naming the set, the last good state kept and every value of the
 * view finite. A transient run whose bearings pass thermal.temp_limit_C
 * is a runaway named by set and node. */
static void test_runaway(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const char *edits[] = { "fidelity.thermal_mode=transient",
                            "surroundings.shaft_bore_coolant_dT_K=0" };
    if (!spindle_scene(&s, edits, 2)) return;
    s.heating = 1;
    s.temp_limit_C = s.ambient_C + 3.0;
    acbb_sim *sim = create_run(&s, &o, "runaway");
    if (!sim) return;
    ok(o.state == ACBB_RUN_FAILED && o.status == ACBB_RUNAWAY
       && strstr(o.message, "thermal runaway: front set: bearing 0 node"),
       "runaway: named, with the set and the node: %s", o.message);
    ok(view_finite(&o.spindle) && o.time > 0.0, "runaway: the last good state (t = %.0f s), "
       "finite", o.time);
    acbb_sim_free(sim);
}

/* A nose load past the bearings' static limit (4.2 GPa contact pressure,
 * MODEL.md 9) ends the run as a runaway named by the set and the bearing. */
static void test_overload(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const char *edits[] = { "fidelity.thermal_mode=transient" };
    if (!spindle_scene(&s, edits, 1)) return;
    s.heating = 1;
    s.radial_load = 30000.0;
    acbb_sim *sim = create_run(&s, &o, "overload");
    if (!sim) return;
    ok(o.state == ACBB_RUN_FAILED && o.status == ACBB_RUNAWAY
       && strstr(o.message, "front set: bearing ") && strstr(o.message, "static limit"),
       "overload: a runaway naming the set and the bearing: %s", o.message);
    ok(view_finite(&o.spindle), "overload: the view is finite");
    acbb_sim_free(sim);
}

/* A nose thrust far past the pairs' lift-off (about 3 x their 200 N
 * preload at rest): in each DB pair the bearing on the unloading side lifts off.
 * The run still converges (its partner carries the set, as a set alone
 * does), the view flags it and the message names the set and the bearing. */
static void test_contact_lost(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    if (!spindle_scene(&s, NULL, 0)) return;
    s.axial_load = 4000.0;
    s.radial_load = 0.0; /* else the radial load keeps some balls of every bearing loaded */
    s.inner_speed = 0.0; /* at rest: at speed the centrifugal force keeps the balls on both
                            races far longer (MODEL.md 14; 1 mN at 100 rpm) */
    acbb_sim *sim = run_public(&s, &o, "lift-off");
    if (!sim) return;
    ok(o.spindle.sets[0].contact_lost && o.spindle.sets[1].contact_lost,
       "lift-off: both sets flag a lost contact (Q_max of the bearings %g %g, %g %g N)",
       o.spindle.sets[0].Q_max_N[0], o.spindle.sets[0].Q_max_N[1], o.spindle.sets[1].Q_max_N[0],
       o.spindle.sets[1].Q_max_N[1]);
    ok(strstr(o.message, "; front set bearing 1: contact_lost (lifted off)")
       && strstr(o.message, "; rear set bearing 1: contact_lost (lifted off)"),
       "lift-off: the message names the sets and bearings: %s", o.message);
    is_close(o.spindle.sets[0].axial_N + o.spindle.sets[1].axial_N, 4000.0, 0.0, 1e-6,
             "lift-off: the sets still carry the thrust, N");
    acbb_sim_free(sim);
}

/* A schedule's rows move the nose loads: a transient whose radial load
 * ramps from 400 to 1200 N ends with the sets carrying the last row's. */
static void test_schedule(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const char *edits[] = { "fidelity.thermal_mode=transient" };
    if (!spindle_scene(&s, edits, 1)) return;
    s.heating = 1;
    s.schedule_n = 2;
    s.schedule[0] = (acbb_schedule_row){ 0.0, s.inner_speed, FA, 400.0 };
    s.schedule[1] = (acbb_schedule_row){ 120.0, s.inner_speed, FA, 1200.0 };
    acbb_sim *sim = run_public(&s, &o, "schedule");
    if (!sim) return;
    const acbb_spindle_set_view *v = o.spindle.sets;
    ok(o.time > 120.0, "schedule: the run went past the last row (t = %.0f s)", o.time);
    is_close(v[0].radial_N + v[1].radial_N, 1200.0, 0.0, 1e-9 * 1200.0,
             "schedule: the sets carry the last row's radial load, N");
    acbb_sim_free(sim);
}

/* A restart (the TUI's edit) builds the spindle again from the new scene;
 * one to a bearing set leaves no spindle behind. */
static void test_restart(void)
{
    static acbb_scene s, t;
    static acbb_snapshot o;
    if (!spindle_scene(&s, NULL, 0)) return;
    acbb_sim *sim = run_public(&s, &o, "restart");
    if (!sim) return;
    acbb_error err = { "" };
    t = s;
    t.radial_load = 2.0 * FR;
    ok(acbb_sim_restart(sim, &t, 1, &err) == ACBB_OK && run_sim(sim, &o),
       "restart: a new spindle scene runs: %s %s", err.msg, o.message);
    is_close(o.spindle.sets[0].radial_N + o.spindle.sets[1].radial_N, 2.0 * FR, 0.0, 1e-6,
             "restart: with the new nose load, N");
    t.shaft_segments = 0;
    t.housing_segments = 0;
    ok(acbb_sim_restart(sim, &t, 1, &err) == ACBB_OK && run_sim(sim, &o)
       && o.spindle.n_sets == 0 && !sim->spindle && sim->set,
       "restart: to the front set alone: no spindle view (%s %s)", err.msg, o.message);
    acbb_sim_free(sim);
}

/* (f) The coupled steady state's energy balance: with a motor (100 W on
 * the rotor, 150 W on the stator) and a cooling jacket, every source (both
 * sets' losses and the motor's) leaves to the air or with the coolant,
 * m_dot c_p (T_out - T_in), to 1e-9. */
static void test_energy(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const char *edits[] = { "fidelity.thermal_mode=steady" };
    if (!spindle_scene(&s, edits, 1)) return;
    s.heating = 1;
    s.spindle_rear_support = ACBB_REAR_SPRING; /* a fixed rear runs away: the rotor heats
                                                  the shaft 60 K above the housing */
    s.spindle_rear_arrangement = ACBB_SET_SINGLE;
    s.spindle_rear_spring = 300.0;
    s.motor_rotor_loss = 100.0;
    s.motor_stator_loss = 150.0;
    s.motor_x0 = 0.12, s.motor_x1 = 0.24;
    s.motor_gap_G = 2.0;
    s.coolant_flow = 2.0 / 60000.0; /* 2 l/min */
    s.coolant_inlet_dT = 0.0;
    s.jacket_x0 = 0.10, s.jacket_x1 = 0.26;
    s.jacket_hA = 40.0;
    s.coolant_cells = 8;
    acbb_sim *sim = run_public(&s, &o, "(f) motor and coolant, steady");
    if (!sim) return;
    const acbb_spindle_view *v = &o.spindle;
    double losses = v->sets[0].loss_W + v->sets[1].loss_W;
    is_close(v->Q_motor_W, 250.0, 1e-12, 0.0, "(f) the motor's heat, W");
    is_close(v->Q_bearings_W, losses, 1e-9, 0.0, "(f) the bearings' heat is both sets' losses");
    is_close(o.heat_in, losses + 250.0, 1e-9, 0.0, "(f) the run's heat in: bearings + motor, W");
    is_close(v->Q_air_W + v->Q_coolant_W, o.heat_in, 1e-9, 0.0,
             "(f) air + coolant carry every source away, W");
    ok(v->Q_coolant_W > 0.0 && v->T_coolant_out_C > v->T_coolant_in_C,
       "(f) the coolant warms (%.2f -> %.2f C, %.1f W)", v->T_coolant_in_C, v->T_coolant_out_C,
       v->Q_coolant_W);
    ok(view_finite(v) && v->n_shaft > 0 && v->n_housing > 0, "(f) the view is finite, with %d "
       "shaft and %d housing cells", v->n_shaft, v->n_housing);
    check_landing(sim, "(f)");
    acbb_sim_free(sim);
}

/* A floating rear (a single bearing in a sleeve with Coulomb friction):
 * at 8000 rpm the balls' centrifugal force pushes the held bearing with
 * about 56 N of thrust. With 40 N of friction the sleeve slides (while it
 * slides the set carries the friction force; where it stops, at most
 * that: the ball speeds of the next pass ease it); with 200 N it sticks
 * where it was assembled and carries what the shaft asks, less than the
 * friction. */
static void test_floating_rear(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const double mu[2] = { 40.0, 200.0 };
    for (int i = 0; i < 2; i++) {
        if (!spindle_scene(&s, NULL, 0)) return;
        s.spindle_rear_support = ACBB_REAR_FLOATING;
        s.spindle_rear_arrangement = ACBB_SET_SINGLE;
        s.spindle_rear_friction = mu[i];
        s.radial_load = 0.0; /* a single bearing held by no thrust carries no radial load */
        acbb_sim *sim = run_public(&s, &o, i ? "floating, sticks" : "floating, slides");
        if (!sim) return;
        const acbb_spindle_set_view *v = o.spindle.sets;
        double slip = sim->spindle->st[ACBB_REAR].slip;
        if (i == 0)
            ok(slip > 1e-6 && v[1].axial_N > 0.0 && v[1].axial_N <= 40.0 + 1e-9,
               "floating: the sleeve slid (%.3f um: its balls push its outer rings rearwards) and the rear set "
               "carries at most the friction (%.3f N)", slip * 1e6, v[1].axial_N);
        else
            ok(fabs(v[1].axial_N) < 200.0 && v[1].axial_N > 40.0 && slip == 0.0,
               "floating: the sleeve sticks, the rear set carries %.2f N < 200 N", v[1].axial_N);
        is_close(v[0].axial_N + v[1].axial_N, FA, 0.0, 1e-9 * FR, "floating: the front set "
                 "carries the nose thrust less the rear's, N");
        acbb_sim_free(sim);
    }
}

/* The test spindle heated, in the thermal mode `mode` (an edit), built
 * as a spindle sim (not yet run); NULL when it does not build. */
static acbb_spindle_sim *heated_spindle(const char *mode, const char *what)
{
    static acbb_scene s, r;
    const char *edits[] = { mode };
    if (!spindle_scene(&s, edits, 1)) return NULL;
    s.heating = 1;
    acbb_scene_resolve(&s, &r, NULL);
    acbb_error err = { "" };
    acbb_spindle_sim *sp = NULL;
    ok(acbb_spindle_sim_new(&r, &(acbb_sim_opts){ 0 }, 0, &sp, &err) == ACBB_OK,
       "%s: spindle builds: %s", what, err.msg);
    return sp;
}

/* A nose load far past anything the bearings can take (5 MN, put in
 * between two steps: a set's ball speeds find no solution there) ends the
 * run with a named status whose message names the set; the state before
 * the step is kept (the loads the sets carried, the view finite). */
static void test_no_equilibrium(void)
{
    static acbb_snapshot o, before;
    acbb_spindle_sim *sp = heated_spindle("fidelity.thermal_mode=transient", "no equilibrium");
    if (!sp) return;
    acbb_spindle_sim_step(sp);
    acbb_spindle_sim_snapshot(sp, &before);
    sp->s.radial_load = 5e6;
    acbb_status st = acbb_spindle_sim_step(sp);
    acbb_spindle_sim_snapshot(sp, &o);
    ok(o.state == ACBB_RUN_FAILED && st == o.status && st != ACBB_OK
       && strncmp(o.message, "spindle", 7) == 0, "no equilibrium: ends %s: %s",
       acbb_status_name(st), o.message);
    ok(view_finite(&o.spindle) && o.spindle.sets[0].radial_N == before.spindle.sets[0].radial_N
       && o.spindle.sets[1].radial_N == before.spindle.sets[1].radial_N,
       "no equilibrium: the last good state kept (radial loads %.1f, %.1f N)",
       o.spindle.sets[0].radial_N, o.spindle.sets[1].radial_N);
    acbb_spindle_sim_free(sp);
}

/* Two opposed pairs, each axially held (a fixed rear, or a floating one
 * whose sleeve sticks), under no nose load: by symmetry (each DB pair
 * pushes equally both ways at the station) the solution is zero
 * displacement. The shaft's Newton then compares the supports' noise
 * (1e-18 m) with the displacements themselves (the same noise): a purely
 * relative test never passes. It stops at the absolute floor 100
 * mech_tol x 1 um (1e-12 m: the relative tolerance at the set solve's
 * unit of displacement, set_mech.c), so the nose's u, w and theta are 0
 * to that floor. */
static void test_zero_load(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const double mu[2] = { 0.0, 40.0 };
    for (int i = 0; i < 3; i++) {
        if (!spindle_scene(&s, NULL, 0)) return;
        s.axial_load = s.radial_load = 0.0;
        if (i > 0) {
            s.spindle_rear_support = ACBB_REAR_FLOATING;
            s.spindle_rear_friction = mu[i - 1];
        }
        char what[80];
        snprintf(what, sizeof what, "zero load, rear %s (friction %g N)",
                 i ? "floating DB" : "fixed DB", i ? mu[i - 1] : 0.0);
        acbb_sim *sim = run_public(&s, &o, what);
        if (!sim) continue;
        const double floor = 100.0 * s.mech_tol * 1e-6;
        ok(fabs(o.spindle.nose_u) <= floor && fabs(o.spindle.nose_w) <= floor
           && fabs(o.spindle.nose_theta) <= floor, "%s: the nose at 0 to 1e-12 (u %.2g m, w "
           "%.2g m, theta %.2g rad)", what, o.spindle.nose_u, o.spindle.nose_w,
           o.spindle.nose_theta);
        acbb_sim_free(sim);
    }
}

/* A single front bearing with a fixed single rear: the rear set is
 * mirrored (docs/spindle.md "Rear set"), so the two make an "O" pair
 * across the spindle preloaded by rear_preload_N (100 N): under no nose
 * thrust each carries thrust of opposite sign, about the preload; under
 * 300 N the front's thrust grows, the rear's falls, of opposite signs
 * still, and they sum to the nose thrust (the free body of the shaft).
 * Before, both faced the same way: at 300 N they shared it as a tandem
 * (+151/+149 N), at 0 every ball unloaded. */
static void test_single_pair(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const double Fa[2] = { 0.0, 300.0 };
    double front0 = 0.0;
    acbb_error err = { "" };
    if (!spindle_scene(&s, NULL, 0)) return;
    s.set_arrangement = s.spindle_rear_arrangement = ACBB_SET_SINGLE;
    s.spindle_rear_preload = 0.0;
    ok(acbb_scene_validate(&s, &err) == ACBB_EINVAL && strstr(err.msg, "rear_preload_N > 0 N"),
       "single front, fixed single rear, no preload: refused: %s", err.msg);
    for (int i = 0; i < 2; i++) {
        if (!spindle_scene(&s, NULL, 0)) return;
        s.set_arrangement = ACBB_SET_SINGLE;
        s.spindle_rear_arrangement = ACBB_SET_SINGLE;
        s.spindle_rear_preload = 100.0;
        s.axial_load = Fa[i];
        s.radial_load = 0.0;
        char what[80];
        snprintf(what, sizeof what, "single front, fixed single rear, %g N thrust", Fa[i]);
        acbb_sim *sim = run_public(&s, &o, what);
        if (!sim) continue;
        const acbb_spindle_set_view *v = o.spindle.sets;
        const acbb_set_mech *r = &sim->spindle->st[ACBB_REAR].ss->sm;
        ok(r->orient[0] == -1, "%s: the rear bearing faces the other way (%+d)", what,
           r->orient[0]);
        ok(v[0].axial_N > 0.0 && v[1].axial_N < 0.0, "%s: the sets' thrusts have opposite "
           "signs (%.2f, %.2f N)", what, v[0].axial_N, v[1].axial_N);
        ok(fabs(v[0].axial_N + v[1].axial_N - Fa[i]) <= 1e-9 * 300.0, "%s: ... and sum to "
           "the nose thrust (%.9g N)", what, v[0].axial_N + v[1].axial_N);
        if (i == 0) {
            front0 = v[0].axial_N;
            ok(front0 > 50.0 && front0 < 100.0, "%s: each carries the preload, less what "
               "the speed's centrifugal force and both sets' compliance take (%.2f N of "
               "100 N)", what, front0);
        } else
            ok(v[0].axial_N > front0 && v[0].axial_N < front0 + 300.0, "%s: the front "
               "carries more than at no thrust, less than the preload plus the thrust "
               "(%.2f N)", what, v[0].axial_N);
        acbb_sim_free(sim);
    }
}

/* A floating single rear over the whole range of sleeve friction: every
 * run converges and the rear set carries min(needed, friction) by
 * magnitude, "needed" the thrust it carries stuck where it was assembled
 * (friction 1e5 N: it never slides); a sleeve that slides carries the
 * friction (to 1e-9: each pass decides stick or slide again from the
 * last state kept, so the converged pass's ball speeds decide it; before,
 * a slide decided on the ball speeds of an early pass stuck there and
 * carried 75 % of the friction once the speeds settled). Before, a
 * sleeve starting to slide from where it carried the centrifugal thrust
 * (56 N) towards 10 to 30 N failed: the set's Newton step
 * overshot to where every ball unloads ("lost contact"). */
static void test_friction_sweep(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const double mu[] = { 1e5, 0.0, 2.0, 5.0, 10.0, 20.0, 30.0, 40.0, 100.0, 400.0 };
    double need = 0.0;
    for (size_t i = 0; i < sizeof mu / sizeof mu[0]; i++) {
        if (!spindle_scene(&s, NULL, 0)) return;
        s.spindle_rear_support = ACBB_REAR_FLOATING;
        s.spindle_rear_arrangement = ACBB_SET_SINGLE;
        s.spindle_rear_friction = mu[i];
        s.radial_load = 0.0;
        char what[80];
        snprintf(what, sizeof what, "floating rear, friction %g N", mu[i]);
        acbb_sim *sim = run_public(&s, &o, what);
        if (!sim) continue;
        double F = fabs(o.spindle.sets[1].axial_N);
        if (i == 0) {
            need = F;
            ok(need > 40.0 && need < 400.0, "%s: the stuck set needs %.2f N", what, need);
        } else
            is_close(F, fmin(need, mu[i]), 1e-9, 0.0, what);
        acbb_sim_free(sim);
    }
}

/* A steady runaway names the hottest node over the limit: with 2 kW on
 * the rotor and no coolant the shaft under the motor is far hotter than
 * any bearing node, and the message names that shaft cell by its x (was:
 * the first set node over the limit, a housing node at a fraction of
 * it). The spindle's own cells are named by part and x: the shaft's
 * first cell (0 to 25 mm), a housing cell, a coolant cell. */
static void test_runaway_names(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    const char *edits[] = { "fidelity.thermal_mode=steady" };
    if (!spindle_scene(&s, edits, 1)) return;
    s.heating = 1;
    s.motor_rotor_loss = 2000.0;
    s.motor_x0 = 0.12, s.motor_x1 = 0.24;
    s.coolant_flow = 2.0 / 60000.0;
    s.coolant_inlet_dT = 0.0;
    s.jacket_x0 = 0.10, s.jacket_x1 = 0.26;
    s.jacket_hA = 1.0;
    s.coolant_cells = 8;
    acbb_sim *sim = create_run(&s, &o, "runaway, steady");
    if (!sim) return;
    double x = 0.0, T = 0.0;
    const char *m = strstr(o.message, "thermal runaway: shaft cell at x = ");
    ok(o.status == ACBB_RUNAWAY && m && sscanf(m, "thermal runaway: shaft cell at x = %lf mm "
       "reached %lf C", &x, &T) == 2 && x > 120.0 && x < 240.0, "runaway, steady: the "
       "shaft cell under the motor is named: %s", o.message);
    char name[80];
    const acbb_spindle_net *net = sim->spindle->net;
    acbb_spindle_net_node_name(net, 0, name, sizeof name);
    ok(strcmp(name, "shaft cell at x = 12.5 mm") == 0, "the shaft's first cell: %s", name);
    int n_own = acbb_spindle_net_own_nodes(net), housing = 0, coolant = 0;
    for (int i = 0; i < n_own; i++) {
        acbb_spindle_net_node_name(net, i, name, sizeof name);
        housing |= strncmp(name, "housing cell at x = ", 20) == 0;
        coolant |= strcmp(name, "coolant cell at x = 100-120 mm") == 0;
    }
    ok(housing && coolant, "housing and coolant cells named (the first coolant cell: 100-120 "
       "mm)");
    acbb_sim_free(sim);
}

/* The preload growth the stepper watches for a runaway (MODEL.md 9) is
 * both sets' (front + rear), the rear DB pair's rigid preload too: the
 * plant's force at the first state is the sum of the sets' preloads. */
static void test_watched_force(void)
{
    acbb_spindle_sim *sp = heated_spindle("fidelity.thermal_mode=transient", "watched force");
    if (!sp) return;
    double F[2];
    for (int k = 0; k < 2; k++) F[k] = acbb_set_mech_preload(&sp->st[k].ss->sm);
    ok(F[1] > 100.0, "watched force: the rear pair is preloaded (%.1f N)", F[1]);
    is_close(sp->run.prev_F, F[0] + F[1], 1e-15, 0.0, "watched force: front + rear preload, N");
    acbb_spindle_sim_free(sp);
}

/* The nose drift (docs/spindle.md "Nose drift"): the nose's axial move
 * against the housing from the cold first state, the shaft's thermal
 * growth in front of the front set (nose_drift_thermal) less the change
 * of the nose's elastic displacement u since then (the front set's
 * contacts stiffen as its rings warm: u moves). Checked against its
 * components in a heated steady run, where the two differ by more than
 * 1 %; at the first state (cold) the drift is 0 and nose_u_cold is nose_u;
 * isothermal, the drift is the elastic part alone. */
static void test_nose_drift(void)
{
    static acbb_scene s;
    static acbb_snapshot o;
    acbb_spindle_sim *sp = heated_spindle("fidelity.thermal_mode=steady", "nose drift");
    if (!sp) return;
    acbb_spindle_sim_snapshot(sp, &o);
    const acbb_spindle_view *v = &o.spindle;
    ok(v->nose_u_cold == v->nose_u && v->nose_drift_axial == v->nose_drift_thermal,
       "nose drift: the first state is the cold reference (u %.4f um, drift %.4f um)",
       v->nose_u * 1e6, v->nose_drift_axial * 1e6);
    ok(run_spindle(sp, &o), "nose drift: steady converged: %s", o.message);
    double elastic = v->nose_u - v->nose_u_cold;
    is_close(v->nose_drift_axial, v->nose_drift_thermal - elastic, 1e-12, 0.0,
             "nose drift = thermal growth less the change of nose_u, m");
    ok(v->nose_drift_thermal > 0.0 && fabs(elastic) > 0.01 * v->nose_drift_thermal,
       "nose drift: thermal %.4f um, elastic %.4f um (more than 1 %% of it), drift %.4f um",
       v->nose_drift_thermal * 1e6, elastic * 1e6, v->nose_drift_axial * 1e6);
    acbb_spindle_sim_free(sp);
    /* isothermal: no growth; the first state is the converged one */
    if (!spindle_scene(&s, NULL, 0)) return;
    acbb_sim *sim = run_public(&s, &o, "nose drift, isothermal");
    if (!sim) return;
    ok(v->nose_drift_thermal == 0.0 && fabs(v->nose_drift_axial) < 1e-12, "nose drift, "
       "isothermal: 0 (%.3g m)", v->nose_drift_axial);
    acbb_sim_free(sim);
}

/* The test spindle heated, transient, on a floating single rear with 40 N
 * of sleeve friction (the heated shaft's growth makes it slide), built
 * (not yet run); NULL when it does not build. */
static acbb_spindle_sim *sliding_spindle(const char *what)
{
    static acbb_scene s, r;
    const char *edits[] = { "fidelity.thermal_mode=transient" };
    if (!spindle_scene(&s, edits, 1)) return NULL;
    s.heating = 1;
    s.spindle_rear_support = ACBB_REAR_FLOATING;
    s.spindle_rear_arrangement = ACBB_SET_SINGLE;
    s.spindle_rear_friction = 40.0;
    s.radial_load = 0.0;
    acbb_scene_resolve(&s, &r, NULL);
    acbb_error err = { "" };
    acbb_spindle_sim *sp = NULL;
    ok(acbb_spindle_sim_new(&r, &(acbb_sim_opts){ 0 }, 0, &sp, &err) == ACBB_OK,
       "%s: spindle builds: %s", what, err.msg);
    return sp;
}

/* The stepper's two checkpoints (stepper.h: the last state, the polish's
 * best) are each the spindle's own: a floating rear's sleeve slides
 * while the heated shaft grows, so two states a step apart have their
 * sleeves at different places; a restore gives back the saved state's
 * slip, temperatures and nose, whichever slot was saved last (the slip
 * was one value shared by both: restoring the last state after saving
 * the best gave the best's slip). The next evaluation's sleeve starts at
 * the restored state's. */
static void test_keep_slots(void)
{
    acbb_spindle_sim *sp = sliding_spindle("slots");
    if (!sp) return;
    acbb_plant p;
    acbb_spindle_plant(sp, &p);
    acbb_spindle_station *rear = &sp->st[ACBB_REAR];
    for (int i = 0; i < 3; i++) acbb_spindle_sim_step(sp);
    p.save(p.ctx, ACBB_KEEP_LAST);
    double slip_a = rear->slip, T_a = sp->T[0], u_a = sp->res.nose[0];
    acbb_spindle_sim_step(sp); /* saves the state before it (A) as the last: B follows */
    p.save(p.ctx, ACBB_KEEP_BEST);
    double slip_b = rear->slip, T_b = sp->T[0], u_b = sp->res.nose[0];
    ok(sp->run.state == ACBB_RUN_RUNNING && slip_a > 0.0 && slip_b != slip_a && T_b != T_a,
       "slots: the sleeve slides from %.6f to %.6f um between two states", slip_a * 1e6,
       slip_b * 1e6);
    p.restore(p.ctx, ACBB_KEEP_LAST);
    ok(rear->slip == slip_a && rear->slip_rest == slip_a && sp->T[0] == T_a
       && sp->res.nose[0] == u_a, "slots: the last state restored after the best was saved: "
       "its slip %.6f um (got %.6f), temperature, nose", slip_a * 1e6, rear->slip * 1e6);
    p.restore(p.ctx, ACBB_KEEP_BEST);
    ok(rear->slip == slip_b && rear->slip_rest == slip_b && sp->T[0] == T_b
       && sp->res.nose[0] == u_b, "slots: the best state restored: its slip %.6f um (got "
       "%.6f), temperature, nose", slip_b * 1e6, rear->slip * 1e6);
    acbb_spindle_sim_free(sp);
}

/* A one-way set's preload (spindle_view.c): an "O" pair of single
 * bearings (front "+", the fixed rear turned round and set in at
 * assembly by the approach e_r its bearing takes under rear_preload_N =
 * 100 N at rest). On a practically rigid shaft the two bearings are
 * springs in series across the set-in: each approaches by e_r / 2 and
 * carries the same thrust P. Hand calculations: (1) P is the thrust under
 * which the bearing alone, at the same speed, approaches by e_r / 2;
 * (2) at rest (10 rpm) Hertz's approach ~ P^(2/3) at a fixed contact
 * angle gives P = 100 / 2^1.5 = 35.36 N (to 5 %: the contact angle grows
 * with the load, 33.86 N here). Each set reports P as its preload_N (was
 * 0); under no nose thrust it is the state's thrust, under 300 N the
 * shaft probed at zero nose thrust gives the zero-thrust run's P, and the
 * probe puts the state back. At the quasi-static level (ball speeds by
 * race control) the probe and the run agree to the solvers' tolerance;
 * at the quasi-dynamic level the probe keeps the state's ball speeds, as
 * a set's own preload does. */
static void test_oneway_preload(void)
{
    static acbb_scene s, r, alone;
    static acbb_snapshot o, a;
    const char *edits[] = { "fidelity.model=quasi-static" };
    const double rpm[3] = { 10.0, 8000.0, 8000.0 }, thrust[3] = { 0.0, 0.0, 300.0 };
    double P0 = 0.0;
    for (int i = 0; i < 3; i++) {
        if (!spindle_scene(&s, edits, 1)) return;
        s.set_arrangement = s.spindle_rear_arrangement = ACBB_SET_SINGLE;
        s.spindle_rear_preload = 100.0;
        s.inner_speed = rpm[i] * M_PI / 30.0;
        s.axial_load = thrust[i];
        s.radial_load = 0.0;
        acbb_scene_resolve(&s, &r, NULL);
        acbb_error err = { "" };
        acbb_spindle_sim *sp = NULL;
        char what[80];
        snprintf(what, sizeof what, "one-way preload, %g rpm, %g N thrust", rpm[i], thrust[i]);
        if (!ok(acbb_spindle_sim_new(&r, &(acbb_sim_opts){ 0 }, 0, &sp, &err) == ACBB_OK,
                "%s: spindle builds: %s", what, err.msg))
            return;
        acbb_shaft_beam_free(sp->beam); /* practically rigid (test (a)'s) */
        sp->beam = NULL;
        acbb_scene keep = sp->s;
        sp->s.shaft.E = 1e13;
        for (int g = 0; g < sp->s.shaft_segments; g++) sp->s.shaft_seg[g].od = 0.4;
        ok(acbb_spindle_beam_build(sp, &err) == ACBB_OK, "%s: rigid shaft: %s", what, err.msg);
        sp->s = keep;
        ok(run_spindle(sp, &o), "%s: converged: %s", what, o.message);
        const acbb_spindle_set_view *v = o.spindle.sets;
        double P = v[0].preload_N, e_r = sp->st[ACBB_REAR].ss->sm.e[0];
        if (i < 2) {
            P0 = P;
            ok(P > 0.0 && P == v[0].axial_N && v[1].preload_N == -v[1].axial_N,
               "%s: each set's preload is its thrust (%.4f N, %.4f N)", what, P,
               v[1].preload_N);
            is_close(v[1].preload_N, P, 1e-8, 0.0, "front and rear carry the same (to the "
                     "members' mech_tol), N");
            alone = s;
            alone.shaft_segments = alone.housing_segments = 0;
            alone.axial_load = P;
            alone.preload = ACBB_PRELOAD_FORCE; /* a thrust, not a held position */
            acbb_sim *sim = NULL;
            if (ok(acbb_sim_create(&alone, &(acbb_sim_opts){ 0 }, &sim, &err) == ACBB_OK
                   && run_sim(sim, &a), "%s: the bearing alone under %.4f N: %s", what, P,
                   a.message))
                is_close(2.0 * sim->ms.dx * 1e6, e_r * 1e6, 1e-5, 0.0, "two bearings in "
                         "series across the set-in: 2 x the lone bearing's approach under "
                         "P = e_r, um");
            acbb_sim_free(sim);
            if (i == 0)
                is_close(P, 100.0 / pow(2.0, 1.5), 0.05, 0.0, "at rest: Hertz in series, "
                         "100 / 2^1.5 N");
        } else {
            double d0 = sp->st[0].ss->b[0]->ms.dx, u0 = o.spindle.nose_u, Fa[2];
            ok(v[0].axial_N > P0 + 50.0, "%s: the front carries %.2f N", what, v[0].axial_N);
            is_close(P, P0, 1e-6, 0.0, "under thrust: the front's preload is the zero-thrust "
                     "one, N");
            is_close(v[1].preload_N, P0, 1e-6, 0.0, "under thrust: the rear's, N");
            ok(acbb_spindle_zero_thrust(sp, Fa) == ACBB_OK && sp->st[0].ss->b[0]->ms.dx == d0
               && sp->res.nose[0] == u0, "%s: the probe puts the state back", what);
        }
        acbb_spindle_sim_free(sp);
    }
}

/* While the floating rear's sleeve goes on sliding the same way (the
 * heated shaft's growth pushes it through the warm-up), each evaluation
 * solves the shaft once, sliding from the start (spindle_mech.c
 * slide_on); it solved it twice, stuck and then sliding (the belt
 * spindle's warm-up: 2.0 shaft solves an evaluation). The slide still
 * carries the friction exactly and moves the sleeve on. */
static void test_slide_on(void)
{
    static acbb_snapshot o;
    acbb_spindle_sim *sp = sliding_spindle("slide on");
    if (!sp) return;
    for (int i = 0; i < 3; i++) acbb_spindle_sim_step(sp);
    long solves = sp->beam_solves, evals = sp->evaluations;
    double slip = sp->st[ACBB_REAR].slip;
    for (int i = 0; i < 20; i++) acbb_spindle_sim_step(sp);
    acbb_spindle_sim_snapshot(sp, &o);
    solves = sp->beam_solves - solves;
    evals = sp->evaluations - evals;
    ok(o.state == ACBB_RUN_RUNNING && evals >= 20 && solves == evals,
       "slide on: 20 steps, one shaft solve an evaluation (%ld in %ld)", solves, evals);
    ok(sp->st[ACBB_REAR].slide == 1 && sp->st[ACBB_REAR].slip > slip, "slide on: the sleeve "
       "slides on rearwards (%.4f to %.4f um)", slip * 1e6, sp->st[ACBB_REAR].slip * 1e6);
    is_close(o.spindle.sets[1].axial_N, 40.0, 1e-12, 0.0, "slide on: the rear carries the "
             "friction, N");
    acbb_spindle_sim_free(sp);
}

int main(void)
{
    test_slide_on();
    test_oneway_preload();
    test_keep_slots();
    test_watched_force();
    test_nose_drift();
    test_runaway_names();
    test_friction_sweep();
    test_single_pair();
    test_zero_load();
    test_rigid_one_support();
    test_balance();
    test_nose_stiffness();
    test_spring_rear();
    test_floating_rear();
    test_steady();
    test_energy();
    test_contact_lost();
    test_runaway();
    test_schedule();
    test_restart();
    test_overload();
    test_no_equilibrium();
    return done_testing();
}
