/* acbb — the joined thermal network of a bearing set (network_set.h,
 * MODEL.md section 14 "Thermal network"). Only the set's outer faces keep
 * the section 8 end boundaries: each end bearing's front (the end cap side,
 * MODEL.md 8.1 x > 0) points out of the set, and on a face that meets a
 * neighbour the end cap's cooled face and the housing's end face are
 * dropped; the radial boundaries (housing outside, shaft bore) stay, they
 * run along the whole set. Between neighbours the shaft and housing
 * segments conduct axially over the centre distance, the spacers (or, with
 * no spacer, the clamped faces: mounting.h_face_W_m2K) from ring face to
 * ring face, R = L / (k A) plus one face film per clamped interface. */
#include <math.h>
#include <string.h>
#include "network_set.h"
#include "acbb/tools/set.h"
#include "acbb/tools/surroundings.h"

/* Node numbers of the 46-node network (MODEL.md 8.1 table). */
enum { N_AMB = 0, N_HOUSING_REAR_FACE = 32, N_HOUSING_FRONT_FACE = 33, N_CAP_BODY = 41 };
/* Per side (front, rear): shaft under the IR, housing bore, IR and OR end face. */
static const int side46[2][4] = { { 27, 2, 25, 12 }, { 29, 4, 26, 11 } };

static double annulus(double d_out, double d_in)
{
    return 0.25 * M_PI * (d_out * d_out - d_in * d_in);
}

/* Member k's front points to -x (toward bearing 0) in the lower half of
 * the set, to +x in the upper half: the end bearings' caps face outwards. */
static int front_minus(int k, int n) { return 2 * k < n - 1; }

/* Does member k's front (side 0) / rear (side 1) meet a neighbour? */
int acbb_network_set_inner_face(const acbb_network_set *ns, int k, int side)
{
    int n = ns->n_members, minus_side = front_minus(k, n) ? 0 : 1;
    return side == minus_side ? k > 0 : k < n - 1;
}

static int pair_is(int a, int b, int p, int q) { return (a == p && b == q) || (a == q && b == p); }

/* 46-node edges that cool an end face: housing end face to ambient, the
 * cap body to its cooled outer face (nodes 38, 40, 42). */
static int face_edge46(int a, int b, int side)
{
    if (side == 1) return pair_is(a, b, N_AMB, N_HOUSING_REAR_FACE);
    if (pair_is(a, b, N_AMB, N_HOUSING_FRONT_FACE)) return 1;
    for (int c = 38; c <= 42; c += 2)
        if (pair_is(a, b, N_CAP_BODY, c)) return 1;
    return 0;
}

/* Is member k's edge a, b an end-face boundary on a face that meets a
 * neighbour? (46-node; the 7-node network lumps its end faces into the
 * exterior film, see exterior7.) */
static int dropped(const acbb_network_set *ns, int k, int a, int b)
{
    if (ns->mem[k]->kind != ACBB_NET_46) return 0;
    for (int side = 0; side < 2; side++)
        if (acbb_network_set_inner_face(ns, k, side) && face_edge46(a, b, side)) return 1;
    return 0;
}

/* A fixed housing end face (housing_bc = fixed) meeting a neighbour is
 * housing material inside the set, not a boundary: it stays free. */
static int released(const acbb_network_set *ns, int k, int i)
{
    if (ns->mem[k]->kind != ACBB_NET_46) return 0;
    return (i == N_HOUSING_FRONT_FACE && acbb_network_set_inner_face(ns, k, 0))
        || (i == N_HOUSING_REAR_FACE && acbb_network_set_inner_face(ns, k, 1));
}

/* 7-node: the housing's exterior film 0-1 covers its outer cylinder and
 * both end annuli (MODEL.md 8.3); the annuli that meet a neighbour go. */
static double exterior7(const acbb_network_set *ns, int k, const acbb_scene *s, double R)
{
    acbb_surroundings su;
    acbb_scene_surroundings(s, &su);
    int inner = acbb_network_set_inner_face(ns, k, 0) + acbb_network_set_inner_face(ns, k, 1);
    double G = 1.0 / R - inner * s->h_natural * annulus(su.housing_od, s->outer_diameter);
    return 1.0 / G;
}

static int copy_member(acbb_network_set *ns, int k, const acbb_scene *s)
{
    acbb_network *m = ns->mem[k];
    acbb_tnet *src = m->net;
    int n = acbb_tnet_node_count(src), off = ns->off[k];
    double T[ACBB_MAX_NODES], q[ACBB_MAX_NODES] = { 0 };
    /* Fixed nodes' values: a step sets them (thermal_network.h). */
    for (int i = 0; i < n; i++) T[i] = 0.0;
    if (acbb_tnet_step(src, q, 1.0, T) != ACBB_OK) return 0;
    for (int i = 0; i < n; i++) {
        if (acbb_tnet_is_fixed(src, i) && !released(ns, k, i)) {
            ns->T_fixed[off + i] = T[i];
            if (acbb_tnet_set_fixed(ns->net, off + i, T[i]) != ACBB_OK) return 0;
        } else if (acbb_tnet_set_capacity(ns->net, off + i, acbb_tnet_capacity(src, i))
                   != ACBB_OK)
            return 0;
    }
    int ne = acbb_tnet_edge_count(src);
    if (ne > ACBB_SET_MAX_MEMBER_EDGES) return 0;
    for (int e = 0; e < ne; e++) {
        int a, b;
        double R = acbb_tnet_resistance(src, e);
        acbb_tnet_edge_nodes(src, e, &a, &b);
        ns->edge_map[k][e] = -1;
        if (dropped(ns, k, a, b)) continue;
        if (m->kind == ACBB_NET_7 && pair_is(a, b, m->node_ambient, m->node_housing))
            R = exterior7(ns, k, s, R);
        if ((ns->edge_map[k][e] = acbb_tnet_add_edge(ns->net, off + a, off + b, R)) < 0) return 0;
    }
    return 1;
}

/* The node of member k on its side facing +x (up = 1) or -x: j = 0 shaft,
 * 1 housing, 2 inner ring, 3 outer ring. */
static int side_node(const acbb_network_set *ns, int k, int up, int j)
{
    const acbb_network *m = ns->mem[k];
    if (m->kind == ACBB_NET_46) {
        int side = front_minus(k, ns->n_members) == up;   /* front faces the other way: rear */
        return ns->off[k] + side46[side][j];
    }
    const int key[4] = { m->node_shaft, m->node_housing, m->node_inner_ring, m->node_outer_ring };
    return ns->off[k] + key[j];
}

/* Ring to ring through a spacer of length L (two clamped faces) or, with
 * no spacer, one clamped face. */
static double r_spacer(double L, double k, double h_face, double A)
{
    return L > 0.0 ? L / (k * A) + 2.0 / (h_face * A) : 1.0 / (h_face * A);
}

/* Conduction joints between members k and k+1. */
static int join(acbb_network_set *ns, int k, const acbb_scene *s, double pitch)
{
    acbb_surroundings su;
    acbb_scene_surroundings(s, &su);
    double L_in, L_out;
    acbb_set_spacers(s, &L_in, &L_out);
    double gap = pitch - s->width;
    double A_ir = annulus(s->inner_land_diameter, s->bore);
    double A_or = annulus(s->outer_diameter, s->outer_land_diameter);
    const double R[4] = {
        pitch / (s->shaft.k * annulus(s->bore, su.shaft_bore)),
        pitch / (s->housing.k * annulus(su.housing_od, s->outer_diameter)),
        /* spacers of the shaft / housing conductivity; the rest of the gap
         * is a collar / shoulder of the same material (scene_rules.c) */
        r_spacer(L_in, s->shaft.k, s->h_face, A_ir) + (gap - L_in) / (s->shaft.k * A_ir),
        r_spacer(L_out, s->housing.k, s->h_face, A_or) + (gap - L_out) / (s->housing.k * A_or),
    };
    for (int j = 0; j < 4; j++)
        if (acbb_tnet_add_edge(ns->net, side_node(ns, k, 1, j), side_node(ns, k + 1, 0, j), R[j])
            < 0)
            return 0;
    return 1;
}

acbb_status acbb_network_set_build(acbb_network_set *ns, acbb_network *const *mem, int n,
                                   const acbb_scene *s, double pitch, acbb_error *err)
{
    memset(ns, 0, sizeof *ns);
    ns->n_members = n;
    for (int k = 0; k < n; k++) {
        ns->mem[k] = mem[k];
        ns->off[k] = ns->n;
        ns->n += mem[k]->n;
    }
    ns->net = acbb_tnet_new(ns->n);
    int ok = ns->net != NULL;
    for (int k = 0; ok && k < n; k++) ok = copy_member(ns, k, s);
    for (int k = 0; ok && k + 1 < n; k++) ok = join(ns, k, s, pitch);
    if (!ok) {
        acbb_network_set_free(ns);
        return acbb_error_set(err, ACBB_ENOMEM, "bearing set: thermal network could not be built");
    }
    return ACBB_OK;
}

void acbb_network_set_free(acbb_network_set *ns)
{
    if (ns->net) acbb_tnet_free(ns->net);
    ns->net = NULL;
}

/* Only the state-dependent edges move (network.h: contact spots, films,
 * advection); the others were set at build, some changed on purpose. */
static void sync_edge(acbb_network_set *ns, int k, int e, double rel_tol)
{
    if (e < 0 || ns->edge_map[k][e] < 0) return;
    int je = ns->edge_map[k][e];
    double R = acbb_tnet_resistance(ns->mem[k]->net, e), R0 = acbb_tnet_resistance(ns->net, je);
    if (fabs(R - R0) > rel_tol * R0) acbb_tnet_set_resistance(ns->net, je, R);
}

void acbb_network_set_sync(acbb_network_set *ns, double rel_tol)
{
    for (int k = 0; k < ns->n_members; k++) {
        const acbb_network *m = ns->mem[k];
        const int sp[4] = { m->edge_sp_race_i, m->edge_sp_ball_i, m->edge_sp_race_o,
                            m->edge_sp_ball_o };
        for (int i = 0; i < 4; i++) sync_edge(ns, k, sp[i], rel_tol);
        for (int i = 0; i < m->n_edge_cv; i++) sync_edge(ns, k, m->edge_cv[i], rel_tol);
    }
}
