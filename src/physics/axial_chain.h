/* acbb — a stepped cylinder along the axis as a chain of thermal cells in
 * an acbb_tnet: capacities, axial conduction between neighbours, surface
 * convection, and the free thermal growth of the chain (docs/spindle.md
 * "Heat"; internal header).
 *
 * Each segment is cut into n_div equal cells; a cell's node sits at its
 * centre, so the resistance between neighbours is the two half-cells in
 * series, (L1/2)/(k1 A1) + (L2/2)/(k2 A2) (finite volumes: the profile of
 * a rod between two fixed temperatures is exact, a fin's converges as h^2).
 *
 * Ownership: acbb_axial_chain_make fills a caller-owned struct whose arrays
 * acbb_axial_chain_free releases. */
#ifndef ACBB_AXIAL_CHAIN_H
#define ACBB_AXIAL_CHAIN_H

#include "acbb/status.h"
#include "shaft_section.h"
#include "thermal_network.h"

typedef struct {
    int first;              /* tnet index of the first cell */
    int n;                  /* cells */
    double *x0, *x1;        /* cell extents, m (absolute axial positions) */
    const acbb_shaft_seg **seg; /* each cell's segment (the caller's array) */
} acbb_axial_chain;

/* Cells for segments starting at x_start, nodes first .. first + n - 1. */
acbb_status acbb_axial_chain_make(const acbb_shaft_seg *s, int n_seg, double x_start,
                                  int n_div, int first, acbb_axial_chain *c, acbb_error *err);
void acbb_axial_chain_free(acbb_axial_chain *c);

/* Capacities rho c A L and the axial conduction edges into net. */
acbb_status acbb_axial_chain_add(acbb_tnet *net, const acbb_axial_chain *c);

/* Resistance from an end cell's node to its end face (end 0 = front, 1 = rear), K/W. */
double acbb_axial_chain_end_resistance(const acbb_axial_chain *c, int end);

/* Outer-surface convection h (W/(m2 K)) of every cell to node `to`. */
acbb_status acbb_axial_chain_convect(acbb_tnet *net, const acbb_axial_chain *c, double h,
                                     int to);

/* Index (0-based within the chain) of the cell holding x; -1 outside. */
int acbb_axial_chain_cell_at(const acbb_axial_chain *c, double x);

/* Length of [a0, a1] inside [b0, b1] (0 if disjoint), m. */
double acbb_overlap(double a0, double a1, double b0, double b1);

/* Free axial growth of the part of the chain inside [xa, xb]:
 * sum over cells of alpha (T - T_ref) * (cell length inside), m. T is the
 * network's temperature vector. */
double acbb_axial_chain_growth(const acbb_axial_chain *c, const double *T, double T_ref,
                               double xa, double xb);

#endif
