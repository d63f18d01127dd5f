/* acbb — a general lumped thermal network (MODEL.md section 8.2).
 *
 * Nodes carry a heat capacity C (J/K, 0 allowed: algebraic node) or a fixed
 * temperature (Dirichlet). Edges carry a thermal resistance R (K/W).
 * The transient step is backward Euler (seed eq 21, cleaned):
 *     (C/dt + G) T^{k+1} = C/dt T^k + q + G_D T_D
 * over the free nodes only (Dirichlet nodes are eliminated, never imposed by
 * penalty). The matrix is LU-factorised with GSL and refactorised only when
 * a resistance, a capacity, a fixed node or dt changed since the last
 * factorisation. Temperatures are in C (only differences matter).
 *
 * Ownership: acbb_tnet_new returns a network the caller frees with
 * acbb_tnet_free. Arrays passed in are read only during the call. */
#ifndef ACBB_THERMAL_NETWORK_H
#define ACBB_THERMAL_NETWORK_H

#include <stddef.h>
#include "acbb/status.h"

typedef struct acbb_tnet acbb_tnet;

acbb_tnet *acbb_tnet_new(int n_nodes);
void acbb_tnet_free(acbb_tnet *net);

int acbb_tnet_node_count(const acbb_tnet *net);
int acbb_tnet_edge_count(const acbb_tnet *net);

/* Capacity C >= 0 (J/K). */
acbb_status acbb_tnet_set_capacity(acbb_tnet *net, int node, double C);
/* Capacity of `node` (J/K); NAN for a bad index. */
double acbb_tnet_capacity(const acbb_tnet *net, int node);
/* Make `node` a fixed-temperature node at T (C). */
acbb_status acbb_tnet_set_fixed(acbb_tnet *net, int node, double T);
int acbb_tnet_is_fixed(const acbb_tnet *net, int node);

/* Add an edge a-b with resistance R > 0 (K/W); returns the edge index >= 0
 * or a negative acbb_status. */
int acbb_tnet_add_edge(acbb_tnet *net, int a, int b, double R);
/* Change an edge's resistance; marks the factorisation stale only if the
 * value actually changed. */
acbb_status acbb_tnet_set_resistance(acbb_tnet *net, int edge, double R);
double acbb_tnet_resistance(const acbb_tnet *net, int edge);
/* End nodes of an edge (for display and tests). */
acbb_status acbb_tnet_edge_nodes(const acbb_tnet *net, int edge, int *a, int *b);

/* One backward-Euler step of length dt > 0 with node heat inputs q (W, length
 * n_nodes; entries at fixed nodes are ignored). T (length n_nodes) holds T^k
 * on entry and T^{k+1} on return; fixed nodes are set to their value. */
acbb_status acbb_tnet_step(acbb_tnet *net, const double *q, double dt, double *T);

/* Steady state G T = q + G_D T_D (every free component must touch a fixed
 * node, else ACBB_SINGULAR). T is written in full. */
acbb_status acbb_tnet_steady(acbb_tnet *net, const double *q, double *T);

/* Heat flowing into the fixed nodes (W) for temperatures T: at steady state
 * it equals the sum of q over the free nodes. */
double acbb_tnet_heat_to_fixed(const acbb_tnet *net, const double *T);

/* Number of LU factorisations done so far (for tests and benchmarks). */
long acbb_tnet_factorisations(const acbb_tnet *net);

#endif
