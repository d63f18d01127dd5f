/* acbb — the spindle thermal network's private state, shared by
 * shaft_thermal.c (validation, build) and shaft_thermal_solve.c. */
#ifndef ACBB_SHAFT_THERMAL_PRIV_H
#define ACBB_SHAFT_THERMAL_PRIV_H

#include <gsl/gsl_linalg.h>
#include "shaft_thermal.h"
#include "axial_chain.h"
#include "thermal_network.h"

struct acbb_spindle_thermal {
    acbb_spindle_thermal_def def;     /* its arrays point at the copies below */
    acbb_shaft_seg *shaft, *housing;
    acbb_spindle_station *station;
    acbb_tnet *net;
    acbb_axial_chain sc, hc;          /* shaft and housing cells */
    int n;                            /* nodes */
    int st0, cool0, air;              /* first station node, first coolant node, air */
    double *T, *T_old, *q;            /* state, start of the step, heat vector */
    acbb_spindle_heat heat;           /* of the last solve */
    double storage_rate;              /* W, of the last step */
    gsl_matrix *A;                    /* n_cool x n_cool coolant balance */
    gsl_vector *b, *y;
    gsl_permutation *perm;
    double *Q0;                       /* coolant wall heat at the base state */
};

/* Coolant cell m's extent, m. */
void acbb_spindle_cool_cell(const acbb_spindle_thermal *sp, int m, double *x0, double *x1);

#endif
