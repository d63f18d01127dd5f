/* acbb — one thermal network for a bearing set (MODEL.md section 14):
 * every bearing's own network (network.h, its surroundings included) side
 * by side, joined between neighbours through the shaft and the housing
 * segments between their centres and through the inner and outer spacers
 * (ring to ring; adjacent rings through their clamped faces). Only the
 * set's outer faces keep the end boundaries of MODEL.md 8 (end cap, housing
 * end face); the end bearings' fronts (cap side) face outwards.
 *
 * The members' networks stay the place where the state-dependent
 * resistances are computed (acbb_network_update); acbb_network_set_sync
 * copies them into the joined network before each solve.
 *
 * Ownership: acbb_network_set_build fills a caller-owned struct that
 * refers to the members (not owned, they must outlive it) and owns `net`;
 * release it with acbb_network_set_free. */
#ifndef ACBB_NETWORK_SET_H
#define ACBB_NETWORK_SET_H

#include "acbb/limits.h"
#include "acbb/scene.h"
#include "acbb/status.h"
#include "network.h"
#include "thermal_network.h"

#define ACBB_SET_MAX_NODES (ACBB_MAX_SET * ACBB_MAX_NODES)
#define ACBB_SET_MAX_MEMBER_EDGES 160   /* a member's edges (46-node: under 100) */

typedef struct {
    acbb_tnet *net;
    int n;                                  /* nodes of the joined network */
    int n_members;
    acbb_network *mem[ACBB_MAX_SET];
    int off[ACBB_MAX_SET];                  /* member k's node i is node off[k] + i */
    int edge_map[ACBB_MAX_SET][ACBB_SET_MAX_MEMBER_EDGES]; /* member k's edge e -> joined
                                            * edge, -1 = dropped (an end face between neighbours) */
    double T_fixed[ACBB_SET_MAX_NODES];     /* fixed nodes' temperatures, C */
} acbb_network_set;

/* Join n members (each built from the set's scene s) whose centres are
 * `pitch` apart. */
acbb_status acbb_network_set_build(acbb_network_set *ns, acbb_network *const *mem, int n,
                                   const acbb_scene *s, double pitch, acbb_error *err);
void acbb_network_set_free(acbb_network_set *ns);

/* 1 if member k's front (side 0, the end cap side of MODEL.md 8.1) or rear
 * (side 1) meets a neighbour: its end boundaries are dropped there. */
int acbb_network_set_inner_face(const acbb_network_set *ns, int k, int side);

/* Copy the members' state-dependent edge resistances (contact spots,
 * films, advection: network.h) into the joined network, each that moved
 * more than rel_tol (relative) since it was last copied:
 * a joined network twice the size costs 8 times as much to factorise, and
 * the contact-spot resistances move a little every transient step
 * (BENCHMARKS.md "Bearing sets"). 0: every change, as the steady polish
 * needs for the reported state. */
void acbb_network_set_sync(acbb_network_set *ns, double rel_tol);

#endif
