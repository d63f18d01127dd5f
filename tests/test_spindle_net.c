/* Tests for the spindle's joined thermal network (spindle_net.h,
 * docs/spindle.md "Joining the bearings"): the steady energy balance of the
 * whole network and the coolant's; every backward-Euler step conserving
 * energy; the transient reaching the steady state; a bearing inside the
 * spindle being exactly the bearing alone with its housing exterior and
 * shaft bore held at the temperatures of the spindle cells it joins (also
 * with a convective bore, whose film must go); a pair and a 7-node set
 * joined alike; sync bringing new contact resistances in; the growth of a
 * uniform rise against sum alpha dT L; the refusals. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "network.h"
#include "network_set.h"
#include "spindle_net.h"
#include "acbb/tools/set.h"

#define NMAX 512

/* A 360 mm spindle, through the [shaft] [housing] [motor] [spindle] keys:
 * shaft 40/45/40 mm over a 20 mm bore, a cast-iron housing 140 mm over the
 * 68 mm bore in three segments, the motor between the sets, a four-cell
 * jacket, the front set at 45 mm, the rear at 300 mm. */
static void spindle_scene(acbb_scene *s)
{
    static const char *const keys[] = {
        "shaft.segments=3", "shaft.seg1_length_mm=80", "shaft.seg1_od_mm=40",
        "shaft.seg1_bore_mm=20", "shaft.seg2_length_mm=200", "shaft.seg2_od_mm=45",
        "shaft.seg2_bore_mm=20", "shaft.seg3_length_mm=80", "shaft.seg3_od_mm=40",
        "shaft.seg3_bore_mm=20", "shaft.n_div=4", "shaft.end_film_W_m2K=30",
        "housing.segments=3", "housing.seg1_length_mm=120", "housing.seg1_od_mm=140",
        "housing.seg1_bore_mm=68", "housing.seg2_length_mm=120", "housing.seg2_od_mm=140",
        "housing.seg2_bore_mm=68", "housing.seg3_length_mm=120", "housing.seg3_od_mm=140",
        "housing.seg3_bore_mm=68", "housing.x0_mm=0", "housing.outer_film_W_m2K=10",
        "motor.rotor_loss_W=100", "motor.stator_loss_W=300", "motor.x0_mm=140",
        "motor.x1_mm=220", "motor.gap_conductance_W_K=2", "spindle.front_x_mm=45",
        "spindle.rear_x_mm=300", "spindle.coolant_flow_l_min=2", "spindle.coolant_inlet_dT_K=-2",
        "spindle.coolant_density_kg_m3=1000", "spindle.coolant_cp_J_kgK=4180",
        "spindle.jacket_x0_mm=100", "spindle.jacket_x1_mm=260", "spindle.jacket_hA_W_K=50",
        "spindle.coolant_cells=4", "spindle.rear_support=fixed", "spindle.rear_preload_N=100",
        "mounting.shaft_bore_mm=20", "surroundings.housing_outer_diameter_mm=140",
    };
    acbb_error err = {{0}};
    acbb_scene_default(s);
    if (acbb_scene_apply_edits(s, keys, sizeof keys / sizeof keys[0], &err) != ACBB_OK)
        ok(0, "spindle keys: %s", err.msg);
}

/* Two sets with their members' networks, joined in a spindle. */
typedef struct {
    acbb_scene s, part_scene[2];
    acbb_network mem[2][ACBB_MAX_SET];
    acbb_network_set set[2];
    acbb_spindle_net_part part[2];
    acbb_spindle_net *sn;
    double spot_scale;      /* contact semi-axes a (x 1.6 / 1.4 mm) */
    double q[NMAX], T[NMAX];
} fixture;

/* Contact spots and films of a running bearing (any plausible values:
 * the tests compare networks that hold the same ones). */
static void run_state(acbb_network *m, const acbb_scene *s, double scale)
{
    acbb_net_inputs in = {.a_i = 1.6e-3 * scale, .b_i = 0.2e-3, .a_o = 1.4e-3 * scale,
                          .b_o = 0.22e-3, .omega_i = 1571.0, .omega_m = 680.0,
                          .T_cavity_C = 35.0};
    acbb_network_update(m, s, &in);
}

static const acbb_heat_sources heat = {.inner_contact = 20.0, .outer_contact = 15.0,
                                       .ball = 10.0, .cavity = 5.0, .cage = 2.0};

static int set_up(fixture *f, acbb_error *err)
{
    double centre[2] = {f->s.spindle_front_x, f->s.spindle_rear_x};
    for (int p = 0; p < 2; p++) {
        const acbb_scene *ps = &f->part_scene[p];
        double x[ACBB_MAX_SET];
        int n = acbb_set_layout(ps, NULL, x);
        acbb_network *ptr[ACBB_MAX_SET];
        for (int k = 0; k < n; k++) {
            if (acbb_network_build(ps, &f->mem[p][k], err) != ACBB_OK) return 0;
            run_state(&f->mem[p][k], ps, f->spot_scale);
            ptr[k] = &f->mem[p][k];
            f->part[p].x[k] = centre[p] + x[k];
        }
        if (acbb_network_set_build(&f->set[p], ptr, n, ps, acbb_set_pitch(ps), err) != ACBB_OK)
            return 0;
        f->part[p].set = &f->set[p];
        f->part[p].scene = ps;
    }
    if (acbb_spindle_net_build(&f->s, f->part, &f->sn, err) != ACBB_OK) return 0;
    memset(f->q, 0, sizeof f->q);
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < f->set[p].n_members; k++) {
            double qk[ACBB_MAX_NODES];
            acbb_network_heat(&f->mem[p][k], &f->part_scene[p], &heat, qk);
            int off = acbb_spindle_net_part_offset(f->sn, p) + f->set[p].off[k];
            for (int i = 0; i < f->mem[p][k].n; i++) f->q[off + i] = qk[i];
        }
    acbb_spindle_net_init(f->sn, f->T);
    return 1;
}

/* Build with both sets as in s (edit the part scenes before, if wanted). */
static int make(fixture *f, const acbb_scene *s)
{
    acbb_error err = {{0}};
    memset(f, 0, sizeof *f);
    f->spot_scale = 1.0;
    f->s = *s;
    f->part_scene[0] = f->part_scene[1] = *s;
    return ok(set_up(f, &err), "spindle network built (%s)", err.msg[0] ? err.msg : "ok");
}

static int make_parts(fixture *f, const acbb_scene *s, const acbb_scene *front,
                      const acbb_scene *rear)
{
    acbb_error err = {{0}};
    memset(f, 0, sizeof *f);
    f->spot_scale = 1.0;
    f->s = *s;
    f->part_scene[0] = *front;
    f->part_scene[1] = *rear;
    return ok(set_up(f, &err), "spindle network built (%s)", err.msg[0] ? err.msg : "ok");
}

static void tear_down(fixture *f)
{
    acbb_spindle_net_free(f->sn);
    for (int p = 0; p < 2; p++) {
        acbb_network_set_free(&f->set[p]);
        for (int k = 0; k < f->set[p].n_members; k++) acbb_network_free(&f->mem[p][k]);
    }
}

static double sum_q(const fixture *f)
{
    double s = 0.0;
    for (int i = 0; i < acbb_spindle_net_nodes(f->sn); i++) s += f->q[i];
    return s;
}

/* Steady: bearing sources + motor = air + coolant wall, the wall heat =
 * m_dot c_p (T_out - T_in); the coolant warms cell by cell. */
static void check_steady_balance(fixture *f, const char *what)
{
    acbb_error err = {{0}};
    ok(acbb_spindle_net_solve(f->sn, f->q, 0.0, f->T, &err) == ACBB_OK, "%s: steady solve (%s)",
       what, err.msg);
    acbb_spindle_flows fl;
    acbb_spindle_net_flows(f->sn, f->T, &fl);
    double in = fl.Q_parts + fl.Q_motor;
    is_close(fl.Q_parts, sum_q(f), 1e-12, 0.0, "steady: the parts' sources are all applied");
    is_close(fl.Q_air + fl.Q_coolant_wall, in, 1e-9, 0.0, "steady: sources = air + coolant");
    is_close(fl.Q_advected, fl.Q_coolant_wall, 1e-9, 0.0,
             "steady: coolant wall heat = m_dot c_p (T_out - T_in)");
    ok(fl.Q_coolant_wall > 0.1 * in && fl.Q_air > 0.0, "%s: both the coolant (%.1f W) and the "
       "air (%.1f W) take a share of %.1f W", what, fl.Q_coolant_wall, fl.Q_air, in);
}

static void test_steady(void)
{
    acbb_scene s;
    spindle_scene(&s);
    fixture f;
    if (!make(&f, &s)) return;
    check_steady_balance(&f, "single bearings");
    ok(f.sn != NULL && acbb_spindle_net_nodes(f.sn) ==
       acbb_spindle_net_part_offset(f.sn, 1) + f.set[1].n, "the rear part's nodes are the last");
    tear_down(&f);
}

/* Every backward-Euler step: sources = air + advected + storage (no
 * coolant hold-up: its wall heat is advected at once); 400 steps of
 * 10 min reach the steady state. */
static void test_transient(void)
{
    acbb_scene s;
    spindle_scene(&s);
    fixture f;
    if (!make(&f, &s)) return;
    int n = acbb_spindle_net_nodes(f.sn), good = 1;
    acbb_error err = {{0}};
    double worst = 0.0, T_steady[NMAX];
    for (int step = 0; step < 400 && good; step++) {
        good = acbb_spindle_net_solve(f.sn, f.q, step < 5 ? 30.0 : 600.0, f.T, &err) == ACBB_OK;
        acbb_spindle_flows fl;
        acbb_spindle_net_flows(f.sn, f.T, &fl);
        double in = fl.Q_parts + fl.Q_motor, out = fl.Q_air + fl.Q_advected + fl.storage_rate;
        worst = fmax(worst, fabs(out - in) / in + fabs(fl.Q_advected - fl.Q_coolant_wall) / in);
        if (step == 0) ok(fl.storage_rate > 0.5 * in, "the first step stores most of the heat "
                          "(%.1f of %.1f W)", fl.storage_rate, in);
    }
    ok(good, "400 backward-Euler steps (%s)", err.msg);
    ok(worst < 1e-9, "every step: sources = air + coolant + storage (worst %.2g relative)", worst);
    memcpy(T_steady, f.T, sizeof T_steady);
    ok(acbb_spindle_net_solve(f.sn, f.q, 0.0, T_steady, &err) == ACBB_OK, "steady solve");
    double d = 0.0;
    for (int i = 0; i < n; i++) d = fmax(d, fabs(f.T[i] - T_steady[i]));
    ok(d < 1e-6, "the transient reaches the steady state (max difference %.2g K)", d);
    tear_down(&f);
}

/* Temperature of the view's cell whose centre lies within 10 mm of x. */
static double cell_T(const double *xs, const double *Ts, int n, double x)
{
    for (int i = 0; i < n; i++)
        if (fabs(xs[i] - x) < 0.01) return Ts[i];
    return NAN;
}

/* The front bearing in the spindle against the bearing alone (scene
 * `alone`: housing exterior and shaft bore fixed) held at the spindle's
 * housing and shaft cell temperatures at its x: node by node, exactly. */
static void compare_alone(fixture *f, acbb_scene *alone, const char *what)
{
    acbb_error err = {{0}};
    acbb_spindle_view v;
    memset(&v, 0, sizeof v);
    acbb_spindle_net_view(f->sn, f->T, &v);
    double x = f->part[0].x[0];
    double Th = cell_T(v.housing_x, v.housing_T_C, v.n_housing, x);
    double Ts = cell_T(v.shaft_x, v.shaft_T_C, v.n_shaft, x);
    acbb_network one;
    if (!ok(acbb_network_build(alone, &one, &err) == ACBB_OK, "%s: bearing alone (%s)", what,
            err.msg))
        return;
    run_state(&one, alone, 1.0);
    const int h46[] = {1, 3, 32, 33}, b46[] = {28, 30}, h7[] = {1}, b7[] = {7};
    int is46 = one.kind == ACBB_NET_46;
    for (int i = 0; i < (is46 ? 4 : 1); i++) acbb_tnet_set_fixed(one.net, (is46 ? h46 : h7)[i], Th);
    for (int i = 0; i < (is46 ? 2 : 1); i++) acbb_tnet_set_fixed(one.net, (is46 ? b46 : b7)[i], Ts);
    double q[ACBB_MAX_NODES], T[ACBB_MAX_NODES];
    acbb_network_heat(&one, alone, &heat, q);
    ok(acbb_tnet_steady(one.net, q, T) == ACBB_OK, "%s: bearing alone solved", what);
    const double *Tm = acbb_spindle_net_member_T(f->sn, f->T, 0, 0);
    int worst = 0;
    double d = 0.0;
    for (int i = 1; i < f->mem[0][0].n; i++) {
        if (acbb_tnet_is_fixed(one.net, i)) continue;
        if (fabs(Tm[i] - T[i]) > d) { d = fabs(Tm[i] - T[i]); worst = i; }
    }
    ok(isfinite(Th + Ts) && d < 1e-9, "%s: every bearing node as the bearing alone held at the "
       "spindle's housing %.3f C and shaft %.3f C (max difference %.2g K at node %d; ball %.3f C)",
       what, Th, Ts, d, worst, T[one.node_ball]);
    acbb_network_free(&one);
}

static void test_alone(void)
{
    acbb_scene s, part, alone;
    acbb_error err = {{0}};
    spindle_scene(&s);
    /* 46 nodes, the seed's fixed bore; then a convective bore (its film goes) */
    for (int conv = 0; conv < 2; conv++) {
        part = s;
        if (conv) part.bore_bc = (acbb_face_bc){.kind = ACBB_BC_CONVECTIVE, .h = 800.0};
        fixture f;
        if (!make_parts(&f, &s, &part, &s)) return;
        acbb_spindle_net_solve(f.sn, f.q, 0.0, f.T, &err);
        alone = part;
        alone.housing_bc = ACBB_BC_FIXED;
        alone.bore_bc = (acbb_face_bc){.kind = ACBB_BC_FIXED};
        compare_alone(&f, &alone, conv ? "46 nodes, convective bore" : "46 nodes");
        tear_down(&f);
    }
    /* 7 nodes: the shaft's edge to the ambient now ends in the shaft cell */
    part = s;
    part.network = ACBB_NET_7;
    fixture f;
    if (!make_parts(&f, &s, &part, &part)) return;
    check_steady_balance(&f, "7-node sets");
    alone = part;
    alone.housing_bc = ACBB_BC_FIXED;
    alone.bore_bc = (acbb_face_bc){.kind = ACBB_BC_FIXED, .dT = 1.0};   /* node 7: the bore */
    compare_alone(&f, &alone, "7 nodes");
    tear_down(&f);
}

/* The limit: a shaft and housing so conductive and so strongly cooled
 * (jacket and rotor-stator gap over the whole length, coolant at the
 * ambient, no motor loss) that their cells sit at the ambient: the front
 * bearing approaches the seed's rig alone (housing exterior and shaft bore
 * held at the ambient). Returns the largest difference, K. */
static double limit_error(double level)
{
    acbb_scene s, alone;
    acbb_error err = {{0}};
    spindle_scene(&s);
    s.shaft.k = s.housing.k = 5.0 * level;
    s.motor_rotor_loss = s.motor_stator_loss = 0.0;
    s.motor_x0 = s.jacket_x0 = 0.0;
    s.motor_x1 = s.jacket_x1 = 0.36;
    s.motor_gap_G = 1e2 * level;
    s.jacket_hA = 1e3 * level;
    s.coolant_flow = 1e-4 * level;
    s.coolant_inlet_dT = 0.0;
    fixture f;
    acbb_scene steel;
    spindle_scene(&steel);   /* the bearings keep their own materials */
    if (!make_parts(&f, &s, &steel, &steel)) return NAN;
    acbb_spindle_net_solve(f.sn, f.q, 0.0, f.T, &err);
    alone = steel;
    alone.housing_bc = ACBB_BC_FIXED;
    alone.bore_bc = (acbb_face_bc){.kind = ACBB_BC_FIXED};
    acbb_network one;
    double q[ACBB_MAX_NODES], T[ACBB_MAX_NODES], d = 0.0;
    acbb_network_build(&alone, &one, &err);
    run_state(&one, &alone, 1.0);
    acbb_network_heat(&one, &alone, &heat, q);
    acbb_tnet_steady(one.net, q, T);
    const double *Tm = acbb_spindle_net_member_T(f.sn, f.T, 0, 0);
    for (int i = 0; i < one.n; i++)
        if (!acbb_tnet_is_fixed(one.net, i)) d = fmax(d, fabs(Tm[i] - T[i]));
    acbb_network_free(&one);
    tear_down(&f);
    return d;
}

static void test_limit(void)
{
    double e1 = limit_error(10.0), e2 = limit_error(1000.0);
    ok(e2 < 0.01 && e2 < 0.02 * e1, "limit: the bearing approaches the seed's rig alone as the "
       "spindle's cells approach the ambient (%.3g K, then %.3g K)", e1, e2);
}

/* A DB pair in front (its members on their own cells, the set's shaft and
 * housing joints replaced by the chains) and a single rear bearing. */
static void test_pair(void)
{
    acbb_scene s, front;
    spindle_scene(&s);
    front = s;
    front.set_arrangement = ACBB_SET_DB;
    front.set_spacing = 0.030;
    fixture f;
    if (!make_parts(&f, &s, &front, &s)) return;
    ok(f.set[0].n_members == 2 && fabs(f.part[0].x[1] - f.part[0].x[0] - 0.030) < 1e-12,
       "front pair at %.1f and %.1f mm", f.part[0].x[0] * 1e3, f.part[0].x[1] * 1e3);
    ok(acbb_spindle_net_member_T(f.sn, f.T, 0, 1) == f.T + acbb_spindle_net_part_offset(f.sn, 0) +
       f.mem[0][0].n && !acbb_spindle_net_member_T(f.sn, f.T, 1, 1),
       "the second member's nodes follow the first's; the rear set has one");
    check_steady_balance(&f, "DB pair + single");
    tear_down(&f);
}

/* New contact sizes reach the joined network through sync, and only then:
 * the solve equals a fresh build from the updated members. */
static void test_sync(void)
{
    acbb_scene s;
    acbb_error err = {{0}};
    spindle_scene(&s);
    fixture f, g;
    if (!make(&f, &s)) return;
    g.spot_scale = 0.0;
    double T0[NMAX], d0 = 0.0, d1 = 0.0;
    for (int p = 0; p < 2; p++) run_state(&f.mem[p][0], &s, 0.3);
    acbb_spindle_net_solve(f.sn, f.q, 0.0, f.T, &err);
    memcpy(T0, f.T, sizeof T0);
    acbb_spindle_net_sync(f.sn, 0.0);
    acbb_spindle_net_solve(f.sn, f.q, 0.0, f.T, &err);
    memset(&g, 0, sizeof g);
    g.s = g.part_scene[0] = g.part_scene[1] = s;
    g.spot_scale = 0.3;
    if (!ok(set_up(&g, &err), "fresh build with the smaller contacts (%s)", err.msg)) return;
    acbb_spindle_net_solve(g.sn, g.q, 0.0, g.T, &err);
    for (int i = 0; i < acbb_spindle_net_nodes(f.sn); i++) {
        d0 = fmax(d0, fabs(T0[i] - g.T[i]));
        d1 = fmax(d1, fabs(f.T[i] - g.T[i]));
    }
    ok(d0 > 1e-3 && d1 < 1e-9, "sync: before, %.2g K from a fresh build; after, %.2g K", d0, d1);
    tear_down(&f);
    tear_down(&g);
}

/* A uniform rise dT: growth sum alpha dT L, exactly. */
static void test_growth(void)
{
    acbb_scene s;
    spindle_scene(&s);
    fixture f;
    if (!make(&f, &s)) return;
    const double dT = 10.0, as = s.shaft.chi, ah = s.housing.chi;
    double xf = s.spindle_front_x, xr = s.spindle_rear_x;
    for (int i = 0; i < acbb_spindle_net_nodes(f.sn); i++) f.T[i] = s.ambient_C + dT;
    acbb_spindle_growth g;
    acbb_spindle_net_growth(f.sn, f.T, &g);
    is_close(g.nose_axial, as * dT * xf, 1e-12, 0.0, "nose: alpha_s dT x_front");
    is_close(g.shift_axial, (as - ah) * dT * (xr - xf), 1e-12, 0.0,
             "rear shift: (alpha_s - alpha_h) dT (x_rear - x_front)");
    is_close(g.radial_shaft[0], as * dT * 0.020, 1e-12, 0.0, "front: shaft radius 20 mm grows");
    is_close(g.radial_shaft[1], as * dT * 0.020, 1e-12, 0.0, "rear: shaft radius 20 mm grows");
    is_close(g.radial_housing[1], ah * dT * 0.034, 1e-12, 0.0, "rear: housing bore 34 mm grows");
    is_close(g.nose_radial, as * dT * 0.020, 1e-12, 0.0, "nose: shaft radius grows");
    tear_down(&f);
}

/* Material counted once: the joined network's capacity is the shaft's and
 * the housing's rho c V (by hand) plus each bearing's own parts (rings,
 * balls, cage, oil-air, end cap), not its piece of housing (1, 2, 3, 4,
 * 36) and shaft (27, 29), which are the spindle's. */
static void test_capacity(void)
{
    acbb_scene s;
    spindle_scene(&s);
    fixture f;
    if (!make(&f, &s)) return;
    double a1 = M_PI / 4 * (0.040 * 0.040 - 0.020 * 0.020);
    double a2 = M_PI / 4 * (0.045 * 0.045 - 0.020 * 0.020);
    double want = s.shaft.rho * s.shaft.cp * (a1 * 0.16 + a2 * 0.20)
                + s.housing.rho * s.housing.cp * M_PI / 4 * (0.14 * 0.14 - 0.068 * 0.068) * 0.36;
    for (int p = 0; p < 2; p++)
        for (int i = 0; i < f.mem[p][0].n; i++) {
            int piece = i == 1 || i == 2 || i == 3 || i == 4 || i == 36 || i == 27 || i == 29;
            if (!piece && !acbb_tnet_is_fixed(f.mem[p][0].net, i))
                want += acbb_tnet_capacity(f.mem[p][0].net, i);
        }
    double got = 0.0;
    for (int i = 0; i < acbb_spindle_net_nodes(f.sn); i++)
        got += acbb_spindle_net_capacity(f.sn, i);
    is_close(got, want, 1e-12, 0.0, "capacity: shaft and housing rho c V + the bearings' parts");
    tear_down(&f);
}

/* Refusals: a bearing off the housing; heat on a node held fixed leaves T
 * as it was. */
static void test_refusals(void)
{
    acbb_scene s;
    spindle_scene(&s);
    s.spindle_rear_x = 0.5;
    fixture f;
    memset(&f, 0, sizeof f);
    f.spot_scale = 1.0;
    f.s = f.part_scene[0] = f.part_scene[1] = s;
    acbb_error err = {{0}};
    ok(!set_up(&f, &err) && strstr(err.msg, "bearing 1 of the rear set at x = 500 mm lies off "
                                   "the shaft (0 to 360 mm)"), "refused: %s", err.msg);
    acbb_spindle_net_free(f.sn);
    f.sn = NULL;
    tear_down(&f);
    spindle_scene(&s);
    s.coolant_cells = 0;
    memset(&f, 0, sizeof f);
    f.spot_scale = 1.0;
    f.s = f.part_scene[0] = f.part_scene[1] = s;
    ok(!set_up(&f, &err) && strstr(err.msg, "coolant flow 2 l/min with 0 coolant cells"),
       "refused: %s", err.msg);
    tear_down(&f);
    spindle_scene(&s);
    if (!make(&f, &s)) return;
    double T0 = f.T[5];
    f.q[acbb_spindle_net_part_offset(f.sn, 1)] = 1.0;   /* the rear bearing's ambient node */
    ok(acbb_spindle_net_solve(f.sn, f.q, 10.0, f.T, &err) == ACBB_EINVAL && f.T[5] == T0 &&
       strstr(err.msg, "fixed temperature"), "refused: %s", err.msg);
    tear_down(&f);
}

int main(void)
{
    test_steady();
    test_transient();
    test_alone();
    test_limit();
    test_pair();
    test_sync();
    test_growth();
    test_capacity();
    test_refusals();
    return done_testing();
}
