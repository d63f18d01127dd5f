/* acbb — the spindle's joined network's private state, shared by
 * spindle_net.c (build, joints, sync) and spindle_net_solve.c (solves,
 * flows, growth, view). */
#ifndef ACBB_SPINDLE_NET_PRIV_H
#define ACBB_SPINDLE_NET_PRIV_H

#include <gsl/gsl_linalg.h>
#include "spindle_net.h"
#include "shaft_thermal_priv.h"

struct acbb_spindle_net {
    acbb_spindle_thermal *sp;     /* the spindle's own network: definition, chains and
                                   * node layout (nodes 0 .. sp->n - 1 here too), owned */
    acbb_spindle_net_part part[2];
    double x_set[2];              /* each set's centre (mean of its members), m */
    double T_ambient;             /* the air, and the growth's reference, C */
    acbb_tnet *net;
    int n, off[2];
    int *target;                  /* node -> the node whose temperature it reads */
    int *emap[2];                 /* part p's set-network edge -> joined edge, -1: none */
    double *q_motor;              /* rotor and stator losses on their cells, W */
    double *q, *T_old;            /* the solve's heat vector and starting temperatures */
    double Q_parts, Q_motor;      /* sources of the last solve, W */
    double dt;                    /* of the last solve (0: steady) */
    /* coolant: balance matrix, its right side and solution, wall heats */
    gsl_matrix *A;
    gsl_vector *b, *y;
    gsl_permutation *perm;
    double *Q0, *Q1;
};

#endif
