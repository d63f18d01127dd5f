/* acbb — a stepped hollow spindle shaft as Timoshenko beam elements in one
 * bending plane plus axial bar elements, on springs at its bearing
 * stations; a static (Newton) solve and the nose stiffness (docs/spindle.md
 * "Mechanics"; internal header).
 *
 * Degrees of freedom per node, in this order: u axial (m, +x towards the
 * rear), w radial deflection (m), theta rotation (rad, positive for w
 * growing with x). A load (F_axial N, F_radial N, M N m) acts along the
 * same three. The nose is the node at x = 0.
 *
 * A support is either linear (k_axial, k_radial, k_tilt: a diagonal spring)
 * or a callback giving the reaction f the support exerts on the shaft for
 * the station's displacement d = (u, w, theta) and its tangent stiffness
 * K = -df/dd (3x3, row-major); a bearing's nonlinear 5-DOF reaction
 * restricted to this plane plugs in there. The global matrix is banded
 * (bandwidth 5 with the node-wise ordering) and solved by GSL's banded LU
 * with partial pivoting (gsl_linalg_LU_band_decomp): O(n) work, and a
 * callback's tangent need not be symmetric.
 *
 * Ownership: acbb_shaft_beam_build returns a beam the caller releases with
 * acbb_shaft_beam_free; the segments and supports are copied. */
#ifndef ACBB_SHAFT_BEAM_H
#define ACBB_SHAFT_BEAM_H

#include "acbb/status.h"
#include "shaft_section.h"

#define ACBB_SHAFT_MAX_SUPPORTS 8

typedef acbb_status (*acbb_shaft_support_fn)(void *ctx, const double d[3], double f[3],
                                             double K[9]);

typedef struct {
    double x;                            /* station, m from the nose */
    double k_axial, k_radial, k_tilt;    /* N/m, N/m, N m/rad (when fn is NULL) */
    acbb_shaft_support_fn fn;            /* nonlinear reaction, or NULL */
    void *ctx;
} acbb_shaft_support;

typedef struct {
    double x;                            /* m from the nose; must be a mesh node */
    double F_axial, F_radial, M;         /* N, N, N m */
} acbb_shaft_load;

typedef struct {
    double nose[3];                      /* u, w, theta at x = 0 (m, m, rad) */
    double compliance[9];                /* nose tangent compliance, (u,w,theta) rows */
    double k_axial, k_radial, k_tilt;    /* nose static stiffness N/m, N/m, N m/rad */
    double reaction[ACBB_SHAFT_MAX_SUPPORTS][3]; /* on the shaft: N, N, N m */
    int n_support;
    int iterations;                      /* Newton iterations taken */
} acbb_shaft_result;

typedef struct acbb_shaft_beam acbb_shaft_beam;

/* Mesh: every segment cut into n_div elements, plus a node at each support
 * and at each of the n_lx load stations load_x (the nose is always one). */
acbb_status acbb_shaft_beam_build(const acbb_shaft_seg *seg, int n_seg,
                                  const acbb_shaft_support *sup, int n_sup, int n_div,
                                  const double *load_x, int n_lx,
                                  acbb_shaft_beam **out, acbb_error *err);
void acbb_shaft_beam_free(acbb_shaft_beam *b);

/* Static equilibrium under the loads, Newton (steps halved until the
 * residual does not grow) from the last solution (zero after build or a
 * failed solve);
 * ACBB_DIVERGED after 50 iterations, ACBB_SINGULAR when the supports leave
 * a rigid-body motion free. */
acbb_status acbb_shaft_beam_solve(acbb_shaft_beam *b, const acbb_shaft_load *loads,
                                  int n_loads, acbb_shaft_result *res, acbb_error *err);

/* The Newton step (relative to the displacements) below which a solve has
 * converged: 1e-11 unless set larger here. A callback support whose
 * reaction comes from an iterative solve (a bearing's, to its own relative
 * tolerance) is smooth only to that tolerance, so the step cannot fall
 * below it (spindle_mech.c). */
void acbb_shaft_beam_set_tol(acbb_shaft_beam *b, double tol);
/* ... and an absolute floor of that step (the largest of m and rad; 0, the
 * default, none): at a solution of zero displacements (a symmetric shaft
 * under no load) the relative test compares the supports' noise with
 * itself and never passes; a step below the supports' own accuracy has
 * converged. */
void acbb_shaft_beam_set_floor(acbb_shaft_beam *b, double floor);

int acbb_shaft_beam_nodes(const acbb_shaft_beam *b);
/* The displacements the next solve starts from (3 per node), copied out
 * (put 0) or in (put 1): a probe's solve under other loads gives the
 * run's warm start back afterwards (spindle_mech.c). */
void acbb_shaft_beam_start(acbb_shaft_beam *b, double *d, int put);
/* Position (m) and displacement (u, w, theta) of node i after a solve. */
acbb_status acbb_shaft_beam_node(const acbb_shaft_beam *b, int i, double *x, double d[3]);

/* The element stiffness (w1, theta1, w2, theta2) of a Timoshenko element of
 * length L: EI/((1+phi)L^3) [12, 6L, -12, 6L; 6L, (4+phi)L^2, -6L,
 * (2-phi)L^2; ...], phi = 12 EI/(kappa G A L^2); phi = 0 is Euler-Bernoulli.
 * Exported for the tests. */
void acbb_timoshenko_element(double EI, double phi, double L, double k[16]);

#endif
