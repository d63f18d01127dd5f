/* acbb — the spindle's one thermal network: the spindle's own cells
 * (shaft_thermal.h, built from the scene) joined with the front and rear
 * bearing sets' networks (network_set.h) at each member's x
 * (docs/spindle.md "Joining the bearings' networks"). Build, joints and sync; the
 * solves are in spindle_net_solve.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "spindle_net_priv.h"
#include "acbb/tools/surroundings.h"

/* What a bearing network's node becomes in the spindle. */
typedef enum {
    J_KEEP,       /* itself */
    J_MATERIAL,   /* itself, without capacity: the spindle's cells hold that material */
    J_AMBIENT,    /* the spindle's air node (the same ambient) */
    J_HOUSING,    /* the spindle's housing cell at the member's x */
    J_BORE        /* the spindle's shaft cell at the member's x */
} join_role;

/* MODEL.md 8.1 (46 nodes): housing exterior 1, 3 (outer cylinder) and 32,
 * 33 (end faces); shaft bore 28, 30; housing body 2, 4, 36 and shaft under
 * the inner ring 27, 29. MODEL.md 8.3 (7 nodes): housing 1, shaft 5,
 * bore coolant 7. */
static join_role role_of(const acbb_network *m, int i)
{
    if (i == m->node_ambient) return J_AMBIENT;
    if (m->kind == ACBB_NET_46) {
        if (i == 1 || i == 3 || i == 32 || i == 33) return J_HOUSING;
        if (i == 28 || i == 30) return J_BORE;
        if (i == 2 || i == 4 || i == 36 || i == 27 || i == 29) return J_MATERIAL;
        return J_KEEP;
    }
    if (i == m->node_housing) return J_HOUSING;
    if (i == 7) return J_BORE;
    return i == m->node_shaft ? J_MATERIAL : J_KEEP;
}

/* The shaft and housing nodes the set joins between neighbours
 * (network_set.c side nodes): 46: 27, 29 and 2, 4; 7: shaft and housing. */
static int side_kind(const acbb_network *m, int i)
{
    if (m->kind == ACBB_NET_46) return (i == 27 || i == 29) ? 1 : ((i == 2 || i == 4) ? 2 : 0);
    return i == m->node_shaft ? 1 : (i == m->node_housing ? 2 : 0);
}

static acbb_shaft_seg seg_of(const acbb_segment *g, const acbb_material *m)
{
    acbb_shaft_seg s = {.L = g->length, .d_out = g->od, .d_bore = g->bore, .E = m->E,
                        .nu = m->nu, .rho = m->rho, .k = m->k, .c = m->cp, .alpha = m->chi};
    return s;
}

/* What the spindle's thermal build does not check itself. */
static acbb_status scene_checks(const acbb_scene *s, acbb_error *err)
{
    if (s->shaft_segments > ACBB_SPINDLE_MAX_SEG || s->housing_segments > ACBB_SPINDLE_MAX_SEG)
        return acbb_error_set(err, ACBB_EINVAL, "spindle: %d shaft and %d housing segments "
                              "(at most %d each)", s->shaft_segments, s->housing_segments,
                              ACBB_SPINDLE_MAX_SEG);
    if (!(isfinite(s->coolant_flow) && s->coolant_flow >= 0.0) ||
        (s->coolant_flow > 0.0 && s->coolant_cells < 1))
        return acbb_error_set(err, ACBB_EINVAL, "spindle: coolant flow %g l/min with %d coolant "
                              "cells (a flow >= 0, and at least one cell when it flows)",
                              s->coolant_flow * 60000.0, s->coolant_cells);
    return ACBB_OK;
}

/* The spindle's own network from the scene; two stand-in stations at the
 * sets' centres (their edges are not copied: the sets take their place). */
static acbb_status build_spindle(acbb_spindle_net *sn, const acbb_scene *s, acbb_error *err)
{
    acbb_status st = scene_checks(s, err);
    if (st != ACBB_OK) return st;
    acbb_shaft_seg sh[ACBB_SPINDLE_MAX_SEG], ho[ACBB_SPINDLE_MAX_SEG];
    for (int i = 0; i < s->shaft_segments; i++) sh[i] = seg_of(&s->shaft_seg[i], &s->shaft);
    for (int i = 0; i < s->housing_segments; i++) ho[i] = seg_of(&s->housing_seg[i], &s->housing);
    acbb_spindle_station sta[2];
    for (int p = 0; p < 2; p++) sta[p] = (acbb_spindle_station){sn->x_set[p], 1.0, 1.0, 0.0};
    int cool = s->coolant_flow > 0.0;
    /* no motor (x1 = x0): a point at the housing's start keeps the spans valid */
    double m0 = s->motor_x1 > s->motor_x0 ? s->motor_x0 : s->housing_x0;
    double m1 = s->motor_x1 > s->motor_x0 ? s->motor_x1 : s->housing_x0;
    acbb_spindle_thermal_def d = {
        .shaft = sh, .n_shaft = s->shaft_segments, .housing = ho,
        .n_housing = s->housing_segments, .housing_x0 = s->housing_x0, .n_div = s->shaft_n_div,
        .station = sta, .n_station = 2, .fixed_station = 0, .rotor = {m0, m1},
        .stator = {m0, m1}, .G_gap = s->motor_gap_G, .jacket = {s->jacket_x0, s->jacket_x1},
        .n_cool = cool ? s->coolant_cells : 0, .m_dot = s->coolant_flow * s->coolant_rho,
        .c_p = s->coolant_cp, .T_in = s->ambient_C + s->coolant_inlet_dT, .hA = s->jacket_hA,
        .C_cool = 0.0,   /* coolant hold-up neglected (no scene key; docs/spindle.md) */
        .T_air = s->ambient_C, .h_housing = s->housing_h_outer, .h_shaft_end = s->shaft_h_end,
        .T_ref = s->ambient_C};
    return acbb_spindle_thermal_build(&d, &sn->sp, err);
}

/* Rotor and stator losses spread over their cells by overlap length. */
static acbb_status motor_heat(acbb_spindle_net *sn, const acbb_scene *s, acbb_error *err)
{
    const double Q[2] = {s->motor_rotor_loss, s->motor_stator_loss};
    const acbb_axial_chain *c[2] = {&sn->sp->sc, &sn->sp->hc};
    double L = s->motor_x1 - s->motor_x0;
    for (int j = 0; j < 2; j++) {
        if (!(isfinite(Q[j]) && Q[j] >= 0.0 && Q[j] <= 1e6))
            return acbb_error_set(err, ACBB_EINVAL, "spindle: motor %s loss = %g W (must be in "
                                  "[0, 1e6])", j ? "stator" : "rotor", Q[j]);
        if (Q[j] > 0.0 && !(L > 0.0))
            return acbb_error_set(err, ACBB_EINVAL, "spindle: the motor has %g W of losses but "
                                  "no length (x0 = %g m, x1 = %g m)", Q[j], s->motor_x0,
                                  s->motor_x1);
        for (int i = 0; Q[j] > 0.0 && i < c[j]->n; i++)
            sn->q_motor[c[j]->first + i] +=
                Q[j] * acbb_overlap(c[j]->x0[i], c[j]->x1[i], s->motor_x0, s->motor_x1) / L;
    }
    sn->Q_motor = Q[0] + Q[1];
    return ACBB_OK;
}

/* Bore film of a convective shaft bore (network.c r_face): the joint keeps
 * only the conduction through the shaft wall, the bore's coolant is gone. */
static double bore_film(const acbb_scene *s, const acbb_network *m)
{
    if (acbb_face_bc_kind(s, &s->bore_bc) != ACBB_BC_CONVECTIVE) return 0.0;
    acbb_surroundings u;
    acbb_scene_surroundings(s, &u);
    double L = m->kind == ACBB_NET_46 ? 0.5 * u.shaft_length : u.shaft_length;
    return 1.0 / (s->bore_bc.h * M_PI * u.shaft_bore * L);
}

static int member_of(const acbb_network_set *ns, int j)
{
    int k = 0;
    while (k + 1 < ns->n_members && j >= ns->off[k + 1]) k++;
    return k;
}

static acbb_status alloc_all(acbb_spindle_net *sn)
{
    size_t n = (size_t)sn->n, nc = (size_t)(sn->sp->def.n_cool > 0 ? sn->sp->def.n_cool : 1);
    sn->net = acbb_tnet_new(sn->n);
    sn->target = malloc(n * sizeof *sn->target);
    sn->q_motor = calloc(n, sizeof *sn->q_motor);
    sn->q = calloc(n, sizeof *sn->q);
    sn->T_old = calloc(n, sizeof *sn->T_old);
    sn->Q0 = calloc(nc, sizeof *sn->Q0);
    sn->Q1 = calloc(nc, sizeof *sn->Q1);
    sn->A = gsl_matrix_alloc(nc, nc);
    sn->b = gsl_vector_alloc(nc);
    sn->y = gsl_vector_alloc(nc);
    sn->perm = gsl_permutation_alloc(nc);
    int ok = sn->net && sn->target && sn->q_motor && sn->q && sn->T_old && sn->Q0 &&
             sn->Q1 && sn->A && sn->b && sn->y && sn->perm;
    for (int p = 0; p < 2 && ok; p++) {
        int ne = acbb_tnet_edge_count(sn->part[p].set->net);
        ok = (sn->emap[p] = malloc((size_t)(ne > 0 ? ne : 1) * sizeof *sn->emap[p])) != NULL;
    }
    return ok ? ACBB_OK : ACBB_ENOMEM;
}

/* The spindle's nodes and edges, less the stand-in stations (held fixed,
 * with no edge). */
static acbb_status copy_spindle(acbb_spindle_net *sn)
{
    const acbb_spindle_thermal *sp = sn->sp;
    acbb_status st = ACBB_OK;
    for (int i = 0; i < sp->n && st == ACBB_OK; i++) {
        sn->target[i] = i;
        int cool = i >= sp->cool0 && i < sp->air;
        if (i >= sp->st0 && i < sp->cool0) st = acbb_tnet_set_fixed(sn->net, i, sn->T_ambient);
        else if (acbb_tnet_is_fixed(sp->net, i))
            st = acbb_tnet_set_fixed(sn->net, i, cool ? sp->def.T_in : sn->T_ambient);
        else st = acbb_tnet_set_capacity(sn->net, i, acbb_tnet_capacity(sp->net, i));
    }
    int ne = acbb_tnet_edge_count(sp->net);
    for (int e = 0; e < ne && st == ACBB_OK; e++) {
        int a, b;
        acbb_tnet_edge_nodes(sp->net, e, &a, &b);
        if ((a >= sp->st0 && a < sp->cool0) || (b >= sp->st0 && b < sp->cool0)) continue;
        int je = acbb_tnet_add_edge(sn->net, a, b, acbb_tnet_resistance(sp->net, e));
        if (je < 0) st = (acbb_status)je;
    }
    return st;
}

/* Part p's nodes: each keeps its set-network index at off + j, or reads
 * the spindle node it became (then it is held fixed, with no edge). */
static acbb_status map_part(acbb_spindle_net *sn, int p, acbb_error *err)
{
    const acbb_network_set *ns = sn->part[p].set;
    const acbb_spindle_thermal *sp = sn->sp;
    acbb_status st = ACBB_OK;
    for (int j = 0; j < ns->n && st == ACBB_OK; j++) {
        int k = member_of(ns, j), node = sn->off[p] + j;
        const acbb_network *m = ns->mem[k];
        double x = sn->part[p].x[k];
        int cs = acbb_axial_chain_cell_at(&sp->sc, x), ch = acbb_axial_chain_cell_at(&sp->hc, x);
        if (cs < 0 || ch < 0)   /* checked before (check_parts): round-off at an end */
            return acbb_error_set(err, ACBB_EINVAL, "spindle: bearing %d of the %s set at x = "
                                  "%g mm has no cell", k + 1, p ? "rear" : "front", x * 1e3);
        join_role r = role_of(m, j - ns->off[k]);
        sn->target[node] = r == J_AMBIENT ? sp->air : r == J_HOUSING ? sp->hc.first + ch
                         : r == J_BORE ? sp->sc.first + cs : node;
        if (sn->target[node] != node) st = acbb_tnet_set_fixed(sn->net, node, sn->T_ambient);
        else if (acbb_tnet_is_fixed(ns->net, j))
            st = acbb_tnet_set_fixed(sn->net, node, ns->T_fixed[j]);
        else if (r != J_MATERIAL)
            st = acbb_tnet_set_capacity(sn->net, node, acbb_tnet_capacity(ns->net, j));
    }
    return st;
}

/* Is the edge a-b one of the set's shaft or housing joints between
 * neighbours? The spindle's chains carry that conduction now. */
static int set_joint(const acbb_network_set *ns, int a, int b)
{
    int ka = member_of(ns, a), kb = member_of(ns, b);
    if (ka == kb) return 0;
    int sa = side_kind(ns->mem[ka], a - ns->off[ka]), sb = side_kind(ns->mem[kb], b - ns->off[kb]);
    return sa != 0 && sa == sb;
}

/* 7-node: the shaft's edge to the ambient (its bore at ambient) ends in
 * the spindle's shaft cell instead. */
static int shaft_to_ambient7(const acbb_network_set *ns, int a, int b)
{
    int k = member_of(ns, a);
    const acbb_network *m = ns->mem[k];
    return m->kind == ACBB_NET_7 && member_of(ns, b) == k && a - ns->off[k] == m->node_shaft &&
           b - ns->off[k] == m->node_ambient;
}

/* One edge of part p's set network with its ends mapped into *je (-1:
 * dropped): the set's own shaft and housing joints, edges inside one cell
 * and the housing's films to the ambient go (the spindle's housing has its
 * own film); an edge into the shaft bore ends in the shaft cell. */
static acbb_status join_edge(acbb_spindle_net *sn, int p, int e, int *je)
{
    const acbb_network_set *ns = sn->part[p].set;
    const acbb_spindle_thermal *sp = sn->sp;
    int a, b;
    acbb_tnet_edge_nodes(ns->net, e, &a, &b);
    *je = -1;
    if (set_joint(ns, a, b)) return ACBB_OK;
    int ta = sn->target[sn->off[p] + a], tb = sn->target[sn->off[p] + b];
    int cell = sp->sc.first + acbb_axial_chain_cell_at(&sp->sc, sn->part[p].x[member_of(ns, a)]);
    if (shaft_to_ambient7(ns, a, b)) tb = cell;
    if (shaft_to_ambient7(ns, b, a)) ta = cell;
    int sc0 = sp->sc.first, sc1 = sp->sc.first + sp->sc.n;
    int hc0 = sp->hc.first, hc1 = sp->hc.first + sp->hc.n;
    int bore = (ta >= sc0 && ta < sc1) || (tb >= sc0 && tb < sc1);
    int exterior = (ta == sp->air && tb >= hc0 && tb < hc1) ||
                   (tb == sp->air && ta >= hc0 && ta < hc1);
    if (ta == tb || exterior) return ACBB_OK;
    double R = acbb_tnet_resistance(ns->net, e);
    if (bore) R -= bore_film(sn->part[p].scene, ns->mem[member_of(ns, a)]);
    int r = acbb_tnet_add_edge(sn->net, ta, tb, R);
    if (r < 0) return (acbb_status)r;
    *je = r;
    return ACBB_OK;
}

static acbb_status join_part(acbb_spindle_net *sn, int p, acbb_error *err)
{
    acbb_status st = map_part(sn, p, err);
    if (st != ACBB_OK) return st;
    int ne = acbb_tnet_edge_count(sn->part[p].set->net);
    for (int e = 0; e < ne; e++) {
        st = join_edge(sn, p, e, &sn->emap[p][e]);
        if (st != ACBB_OK)
            return acbb_error_set(err, st, "spindle: edge %d of the %s set's network could not "
                                  "be joined (%s)", e, p ? "rear" : "front", acbb_status_name(st));
    }
    return ACBB_OK;
}

static double segs_length(const acbb_segment *g, int n)
{
    double L = 0.0;
    for (int i = 0; i < n && i < ACBB_SPINDLE_MAX_SEG; i++) L += g[i].length;
    return L;
}

/* Every member inside the shaft and the housing. */
static acbb_status check_parts(const acbb_scene *s, const acbb_spindle_net_part part[2],
                               acbb_error *err)
{
    double Ls = segs_length(s->shaft_seg, s->shaft_segments);
    double h0 = s->housing_x0, h1 = h0 + segs_length(s->housing_seg, s->housing_segments);
    for (int p = 0; p < 2; p++) {
        const acbb_network_set *ns = part[p].set;
        if (!ns || !ns->net || !part[p].scene || ns->n_members < 1 || ns->n_members > ACBB_MAX_SET)
            return acbb_error_set(err, ACBB_EINVAL, "spindle: the %s set has no thermal network "
                                  "or no scene", p ? "rear" : "front");
        for (int k = 0; k < ns->n_members; k++) {
            double x = part[p].x[k];
            int on_shaft = x >= 0.0 && x <= Ls;
            if (!on_shaft || !(x >= h0 && x <= h1))
                return acbb_error_set(err, ACBB_EINVAL, "spindle: bearing %d of the %s set at "
                                      "x = %g mm lies off the %s (%g to %g mm)", k + 1,
                                      p ? "rear" : "front", x * 1e3, on_shaft ? "housing" : "shaft",
                                      (on_shaft ? h0 : 0.0) * 1e3, (on_shaft ? h1 : Ls) * 1e3);
        }
    }
    return ACBB_OK;
}

static acbb_status build_all(acbb_spindle_net *sn, const acbb_scene *s, acbb_error *err)
{
    acbb_status st = build_spindle(sn, s, err);
    if (st != ACBB_OK) return st;
    sn->n = sn->sp->n;
    for (int p = 0; p < 2; p++) {
        sn->off[p] = sn->n;
        sn->n += sn->part[p].set->n;
    }
    if (alloc_all(sn) != ACBB_OK) return acbb_error_set(err, ACBB_ENOMEM, "spindle: out of memory");
    st = motor_heat(sn, s, err);
    if (st != ACBB_OK) return st;
    st = copy_spindle(sn);
    if (st != ACBB_OK)
        return acbb_error_set(err, st, "spindle: the spindle's own network could not be copied "
                              "(%s)", acbb_status_name(st));
    for (int p = 0; p < 2 && st == ACBB_OK; p++) st = join_part(sn, p, err);
    return st;
}

acbb_status acbb_spindle_net_build(const acbb_scene *s, const acbb_spindle_net_part part[2],
                                   acbb_spindle_net **out, acbb_error *err)
{
    *out = NULL;
    if (!s || !part) return acbb_error_set(err, ACBB_EINVAL, "spindle: no scene or no sets");
    acbb_status st = check_parts(s, part, err);
    if (st != ACBB_OK) return st;
    acbb_spindle_net *sn = calloc(1, sizeof *sn);
    if (!sn) return acbb_error_set(err, ACBB_ENOMEM, "spindle: out of memory");
    sn->T_ambient = s->ambient_C;
    for (int p = 0; p < 2; p++) {
        sn->part[p] = part[p];
        double sum = 0.0;
        for (int k = 0; k < part[p].set->n_members; k++) sum += part[p].x[k];
        sn->x_set[p] = sum / part[p].set->n_members;
    }
    st = build_all(sn, s, err);
    if (st != ACBB_OK) {
        acbb_spindle_net_free(sn);
        return st;
    }
    *out = sn;
    return ACBB_OK;
}

void acbb_spindle_net_free(acbb_spindle_net *sn)
{
    if (!sn) return;
    acbb_spindle_thermal_free(sn->sp);
    acbb_tnet_free(sn->net);
    free(sn->target);
    for (int p = 0; p < 2; p++) free(sn->emap[p]);
    free(sn->q_motor);
    free(sn->q);
    free(sn->T_old);
    free(sn->Q0);
    free(sn->Q1);
    if (sn->A) gsl_matrix_free(sn->A);
    if (sn->b) gsl_vector_free(sn->b);
    if (sn->y) gsl_vector_free(sn->y);
    if (sn->perm) gsl_permutation_free(sn->perm);
    free(sn);
}

int acbb_spindle_net_nodes(const acbb_spindle_net *sn) { return sn->n; }

int acbb_spindle_net_part_offset(const acbb_spindle_net *sn, int p)
{
    return p >= 0 && p < 2 ? sn->off[p] : -1;
}

const double *acbb_spindle_net_member_T(const acbb_spindle_net *sn, const double *T, int p, int k)
{
    if (p < 0 || p > 1 || k < 0 || k >= sn->part[p].set->n_members) return NULL;
    return T + sn->off[p] + sn->part[p].set->off[k];
}

double acbb_spindle_net_capacity(const acbb_spindle_net *sn, int node)
{
    return acbb_tnet_is_fixed(sn->net, node) ? 0.0 : acbb_tnet_capacity(sn->net, node);
}

/* One member edge's resistance into the joined network, when it moved. */
static void sync_edge(acbb_spindle_net *sn, int p, int k, int e, double rel_tol)
{
    const acbb_network_set *ns = sn->part[p].set;
    if (e < 0 || ns->edge_map[k][e] < 0) return;
    int je = sn->emap[p][ns->edge_map[k][e]];
    if (je < 0) return;
    double R = acbb_tnet_resistance(ns->mem[k]->net, e), R0 = acbb_tnet_resistance(sn->net, je);
    if (fabs(R - R0) > rel_tol * R0) acbb_tnet_set_resistance(sn->net, je, R);
}

void acbb_spindle_net_sync(acbb_spindle_net *sn, double rel_tol)
{
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < sn->part[p].set->n_members; k++) {
            const acbb_network *m = sn->part[p].set->mem[k];
            const int spot[4] = {m->edge_sp_race_i, m->edge_sp_ball_i, m->edge_sp_race_o,
                                 m->edge_sp_ball_o};
            for (int i = 0; i < 4; i++) sync_edge(sn, p, k, spot[i], rel_tol);
            for (int i = 0; i < m->n_edge_cv; i++) sync_edge(sn, p, k, m->edge_cv[i], rel_tol);
        }
}
