/* The joined thermal network of a bearing set (MODEL.md 14 "Thermal
 * network", network_set.h): only the set's outer faces keep the section 8
 * end boundaries (end cap, housing end face), inner faces have none; the
 * outer ones are the single bearing's, bit for bit; heat in = heat out at
 * steady state to round-off; a symmetric pair with the same heat per
 * bearing runs warmer everywhere than one bearing alone (which is what the
 * joined pair computed before its inner faces lost their boundaries: by
 * symmetry nothing crosses the joints). */
#include <math.h>
#include <string.h>
#include "tap.h"
#include "network.h"
#include "network_set.h"
#include "acbb/tools/set.h"
#include "acbb/tools/surroundings.h"

/* Conductance (W/K) of the edges between nodes a and b. */
static double g_between(const acbb_tnet *net, int a, int b)
{
    double g = 0.0;
    for (int e = 0; e < acbb_tnet_edge_count(net); e++) {
        int p, q;
        acbb_tnet_edge_nodes(net, e, &p, &q);
        if ((p == a && q == b) || (p == b && q == a)) g += 1.0 / acbb_tnet_resistance(net, e);
    }
    return g;
}

/* End-face boundary conductance of one face (MODEL.md 8.1 nodes): rear =
 * housing rear face 32 to ambient; front = housing front face 33 to
 * ambient plus the cap body 41 to its cooled face 38, 40, 42. */
static double g_face(const acbb_tnet *net, int off, int side)
{
    if (side == 1) return g_between(net, off, off + 32);
    return g_between(net, off, off + 33) + g_between(net, off + 41, off + 38)
         + g_between(net, off + 41, off + 40) + g_between(net, off + 41, off + 42);
}

typedef struct {
    acbb_scene s;
    acbb_network one, mem[ACBB_MAX_SET];
    acbb_network_set ns;
    int n;
} fixture;

static int setup(fixture *f, const char *const *edits, int n_edits)
{
    acbb_error err = { "" };
    memset(f, 0, sizeof *f);
    if (acbb_scene_load("presets/pair-DB-heated.ini", &f->s, &err) != ACBB_OK ||
        acbb_scene_apply_edits(&f->s, edits, n_edits, &err) != ACBB_OK ||
        acbb_network_build(&f->s, &f->one, &err) != ACBB_OK)
        return ok(0, "setup: %s", err.msg);
    f->n = acbb_set_layout(&f->s, NULL, NULL);
    acbb_network *p[ACBB_MAX_SET];
    for (int k = 0; k < f->n; k++) {
        if (acbb_network_build(&f->s, &f->mem[k], &err) != ACBB_OK) return ok(0, "%s", err.msg);
        p[k] = &f->mem[k];
    }
    return acbb_network_set_build(&f->ns, p, f->n, &f->s, acbb_set_pitch(&f->s), &err) == ACBB_OK
        || ok(0, "join: %s", err.msg);
}

static void teardown(fixture *f)
{
    acbb_network_set_free(&f->ns);
    for (int k = 0; k < f->n; k++) acbb_network_free(&f->mem[k]);
    acbb_network_free(&f->one);
}

/* Inner faces: no end boundary, the housing end face is not held; outer
 * faces: exactly the single bearing's. */
static void test_faces(const char *arr, const int expect_inner[][2])
{
    char e[64];
    snprintf(e, sizeof e, "set.arrangement=%s", arr);
    const char *edits[] = { e };
    fixture f;
    if (!setup(&f, edits, 1)) return;
    for (int k = 0; k < f.n; k++)
        for (int side = 0; side < 2; side++) {
            int inner = acbb_network_set_inner_face(&f.ns, k, side), off = f.ns.off[k];
            double g = g_face(f.ns.net, off, side), g1 = g_face(f.one.net, 0, side);
            int held = acbb_tnet_is_fixed(f.ns.net, off + (side ? 32 : 33));
            ok(inner == expect_inner[k][side], "%s bearing %d %s: %s face", arr, k,
               side ? "rear" : "front", inner ? "inner" : "outer");
            if (inner)
                ok(g == 0.0 && !held, "%s bearing %d %s (inner): end-face conductance %g W/K "
                   "(want 0), face node free", arr, k, side ? "rear" : "front", g);
            else
                ok(g == g1 && g1 > 0.0, "%s bearing %d %s (outer): %.17g W/K = one bearing's %.17g",
                   arr, k, side ? "rear" : "front", g, g1);
        }
    teardown(&f);
}

/* Steady state of a symmetric pair, 5 W at each contact of both bearings:
 * heat in = heat into the fixed nodes to round-off; every node at least as
 * warm as in one bearing alone with the same heat, the housing warmer. */
static void test_balance_and_warmer(void)
{
    const char *edits[] = { "set.arrangement=DB" };
    fixture f;
    if (!setup(&f, edits, 1)) return;
    double q[ACBB_SET_MAX_NODES] = { 0 }, T[ACBB_SET_MAX_NODES], q1[ACBB_MAX_NODES] = { 0 },
           T1[ACBB_MAX_NODES];
    q1[f.one.heat_inner] = q1[f.one.heat_outer] = 5.0;
    for (int k = 0; k < 2; k++) q[f.ns.off[k] + f.one.heat_inner] = q[f.ns.off[k] + f.one.heat_outer] = 5.0;
    ok(acbb_tnet_steady(f.ns.net, q, T) == ACBB_OK && acbb_tnet_steady(f.one.net, q1, T1) == ACBB_OK,
       "steady solves");
    double out = acbb_tnet_heat_to_fixed(f.ns.net, T);
    ok(fabs(out - 20.0) < 1e-12 * 20.0, "joined pair: heat in 20 W = heat out %.17g W", out);
    int warmer = 1;
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < f.one.n; i++) warmer &= T[f.ns.off[k] + i] >= T1[i] - 1e-12;
    ok(warmer, "joined pair: no node cooler than in one bearing alone");
    double dh = T[f.ns.off[0] + f.one.node_housing] - T1[f.one.node_housing];
    double d32 = T[f.ns.off[0] + 32] - T1[32];
    ok(dh > 0.0 && d32 > dh, "joined pair: housing bore warmer by %.4g K, its inner end face by "
       "%.4g K (no longer cooled)", dh, d32);
    teardown(&f);
}

/* 7-node members: the exterior film 0-1 loses the end annuli that meet a
 * neighbour (MODEL.md 8.3 lumps cylinder and both annuli). */
static void test_seven_node(void)
{
    const char *edits[] = { "set.arrangement=DBT", "fidelity.network=7" };
    fixture f;
    if (!setup(&f, edits, 2)) return;
    acbb_surroundings su;
    acbb_scene_surroundings(&f.s, &su);
    double A = 0.25 * M_PI * (su.housing_od * su.housing_od - f.s.outer_diameter * f.s.outer_diameter);
    double g1 = g_between(f.one.net, 0, 1), hn = f.s.h_natural;
    for (int k = 0; k < 3; k++) {
        int inner = (k > 0) + (k < 2), off = f.ns.off[k];
        double g = g_between(f.ns.net, off, off + 1), want = g1 - inner * hn * A;
        ok(fabs(g - want) < 1e-12 * g1, "DBT 7-node bearing %d: exterior %.6g W/K = one bearing's "
           "%.6g minus %d end annuli", k, g, g1, inner);
    }
    double q[ACBB_SET_MAX_NODES] = { 0 }, T[ACBB_SET_MAX_NODES];
    for (int k = 0; k < 3; k++) q[f.ns.off[k] + f.one.heat_inner] = 3.0;
    ok(acbb_tnet_steady(f.ns.net, q, T) == ACBB_OK &&
       fabs(acbb_tnet_heat_to_fixed(f.ns.net, T) - 9.0) < 1e-12 * 9.0,
       "DBT 7-node: heat in 9 W = heat out to round-off");
    teardown(&f);
}

/* A fixed housing exterior: the inner end faces are housing material
 * inside the set, no longer held at ambient; the outer ones still are. */
static void test_fixed_housing(void)
{
    const char *edits[] = { "set.arrangement=DB", "surroundings.housing_exterior=fixed" };
    fixture f;
    if (!setup(&f, edits, 2)) return;
    for (int k = 0; k < 2; k++) {
        int off = f.ns.off[k];
        ok(!acbb_tnet_is_fixed(f.ns.net, off + 32) && acbb_tnet_is_fixed(f.ns.net, off + 33) &&
           acbb_tnet_is_fixed(f.one.net, 32), "fixed housing, bearing %d: inner (rear) end face "
           "free, outer (front) held", k);
    }
    double q[ACBB_SET_MAX_NODES] = { 0 }, T[ACBB_SET_MAX_NODES];
    q[f.one.heat_inner] = 4.0;
    ok(acbb_tnet_steady(f.ns.net, q, T) == ACBB_OK &&
       fabs(acbb_tnet_heat_to_fixed(f.ns.net, T) - 4.0) < 1e-12 * 4.0,
       "fixed housing: heat in 4 W (bearing 0 only) = heat out to round-off");
    teardown(&f);
}

int main(void)
{
    static const int pair[2][2] = { { 0, 1 }, { 0, 1 } };
    static const int triple[3][2] = { { 0, 1 }, { 1, 1 }, { 0, 1 } };
    static const int quad[4][2] = { { 0, 1 }, { 1, 1 }, { 1, 1 }, { 0, 1 } };
    test_faces("DB", pair);
    test_faces("DF", pair);
    test_faces("DBT", triple);
    test_faces("QBC", quad);
    test_balance_and_warmer();
    test_seven_node();
    test_fixed_housing();
    return done_testing();
}
