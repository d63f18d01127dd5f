/* acbb — the joined thermal network of a bearing set (network_set.h,
 * MODEL.md section 14). The joints are axial conduction R = L / (k A)
 * over the centre distance (shaft, housing) or the spacer length (rings);
 * with no spacer, adjacent rings touch through their clamped faces
 * (mounting.h_face_W_m2K over the ring's face). */
#include <math.h>
#include <string.h>
#include "network_set.h"

static double annulus(double d_out, double d_in)
{
    return 0.25 * M_PI * (d_out * d_out - d_in * d_in);
}

static int copy_member(acbb_network_set *ns, int k)
{
    acbb_tnet *src = ns->mem[k]->net;
    int n = acbb_tnet_node_count(src), off = ns->off[k];
    double T[ACBB_MAX_NODES], q[ACBB_MAX_NODES] = { 0 };
    /* Fixed nodes' values: a step sets them (thermal_network.h). */
    for (int i = 0; i < n; i++) T[i] = 0.0;
    if (acbb_tnet_step(src, q, 1.0, T) != ACBB_OK) return 0;
    for (int i = 0; i < n; i++) {
        if (acbb_tnet_is_fixed(src, i)) {
            ns->T_fixed[off + i] = T[i];
            if (acbb_tnet_set_fixed(ns->net, off + i, T[i]) != ACBB_OK) return 0;
        } else if (acbb_tnet_set_capacity(ns->net, off + i, acbb_tnet_capacity(src, i))
                   != ACBB_OK)
            return 0;
    }
    ns->edge_off[k] = acbb_tnet_edge_count(ns->net);
    for (int e = 0; e < acbb_tnet_edge_count(src); e++) {
        int a, b;
        acbb_tnet_edge_nodes(src, e, &a, &b);
        if (acbb_tnet_add_edge(ns->net, off + a, off + b, acbb_tnet_resistance(src, e)) < 0)
            return 0;
    }
    return 1;
}

/* Conduction joints between members k and k+1. */
static int join(acbb_network_set *ns, int k, const acbb_scene *s, double pitch)
{
    acbb_surroundings su;
    acbb_scene_surroundings(s, &su);
    const acbb_network *a = ns->mem[k], *b = ns->mem[k + 1];
    int oa = ns->off[k], ob = ns->off[k + 1];
    double L_sp = pitch - s->width;
    double A_ir = annulus(s->inner_land_diameter, s->bore);
    double A_or = annulus(s->outer_diameter, s->outer_land_diameter);
    double R_shaft = pitch / (s->shaft.k * annulus(s->bore, su.shaft_bore));
    double R_house = pitch / (s->housing.k * annulus(su.housing_od, s->outer_diameter));
    /* Spacers: shaft / housing material (MODEL.md 14 chi_s, chi_h). */
    double R_ir = L_sp > 0.0 ? L_sp / (s->shaft.k * A_ir) : 1.0 / (s->h_face * A_ir);
    double R_or = L_sp > 0.0 ? L_sp / (s->housing.k * A_or) : 1.0 / (s->h_face * A_or);
    return acbb_tnet_add_edge(ns->net, oa + a->node_shaft, ob + b->node_shaft, R_shaft) >= 0
        && acbb_tnet_add_edge(ns->net, oa + a->node_housing, ob + b->node_housing, R_house) >= 0
        && acbb_tnet_add_edge(ns->net, oa + a->node_inner_ring, ob + b->node_inner_ring, R_ir) >= 0
        && acbb_tnet_add_edge(ns->net, oa + a->node_outer_ring, ob + b->node_outer_ring, R_or) >= 0;
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
    for (int k = 0; ok && k < n; k++) ok = copy_member(ns, k);
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

void acbb_network_set_sync(acbb_network_set *ns, double rel_tol)
{
    for (int k = 0; k < ns->n_members; k++) {
        const acbb_tnet *src = ns->mem[k]->net;
        for (int e = 0; e < acbb_tnet_edge_count(src); e++) {
            int je = ns->edge_off[k] + e;
            double R = acbb_tnet_resistance(src, e), R0 = acbb_tnet_resistance(ns->net, je);
            if (fabs(R - R0) > rel_tol * R0) acbb_tnet_set_resistance(ns->net, je, R);
        }
    }
}
