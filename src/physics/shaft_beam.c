/* acbb — Timoshenko shaft on springs: assembly, banded Newton solve, nose
 * stiffness (docs/spindle.md "Mechanics").
 *
 * The bending element is the two-node element with interdependent
 * interpolation (Przemieniecki, Theory of Matrix Structural Analysis, 1968;
 * Reddy, Comput. Methods Appl. Mech. Eng. 149 (1997) 113-132):
 * its cubic/quadratic fields solve the homogeneous Timoshenko equations, so
 * nodal values under point loads are exact for any mesh and there is no
 * shear locking. The shear coefficient is Cowper's (shaft_section.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "shaft_beam.h"

#define BW 5                      /* half bandwidth with 3 DOF per node */
#define NB (2 * BW + 1)           /* stored band width of the structural K */
#define MAX_ITER 50
#define STEP_TOL 1e-11           /* the default convergence (docs/spindle.md) */
#define MAX_HALF 12              /* step halvings in the line search */

struct acbb_shaft_beam {
    int n_nodes, n_dof;
    double *x;                    /* node positions, m */
    double *Ks;                   /* structural K: Ks[i*NB + BW + j - i] = K(i,j) */
    double *d;                    /* displacements (3 per node) */
    double *d_old;                /* start of the current Newton step */
    double *diag_scale;           /* max diagonal per DOF kind (singularity test) */
    int n_sup;
    acbb_shaft_support sup[ACBB_SHAFT_MAX_SUPPORTS];
    int sup_node[ACBB_SHAFT_MAX_SUPPORTS];
    gsl_matrix *AB;               /* n_dof x (3 BW + 1) LU band storage */
    gsl_vector_uint *piv;
    gsl_vector *rhs, *dx;
    double tol;                   /* converged: step below tol of the displacements */
    double floor;                 /* ... or below this absolute step (m, rad); 0 none */
};

void acbb_timoshenko_element(double EI, double phi, double L, double k[16])
{
    double c = EI / ((1.0 + phi) * L * L * L), L2 = L * L;
    const double m[16] = {
        12.0, 6.0 * L, -12.0, 6.0 * L,
        6.0 * L, (4.0 + phi) * L2, -6.0 * L, (2.0 - phi) * L2,
        -12.0, -6.0 * L, 12.0, -6.0 * L,
        6.0 * L, (2.0 - phi) * L2, -6.0 * L, (4.0 + phi) * L2};
    for (int i = 0; i < 16; i++) k[i] = c * m[i];
}

static void ks_add(acbb_shaft_beam *b, int i, int j, double v)
{
    b->Ks[(size_t)i * NB + BW + j - i] += v;
}

/* Bar (u) and Timoshenko (w, theta) element between nodes e and e+1. */
static void add_element(acbb_shaft_beam *b, int e, const acbb_shaft_seg *s)
{
    double L = b->x[e + 1] - b->x[e];
    double A = acbb_seg_area(s), I = acbb_seg_inertia(s);
    double G = s->E / (2.0 * (1.0 + s->nu));
    double phi = 12.0 * s->E * I / (acbb_seg_shear_coeff(s) * G * A * L * L);
    double kb[16], ka = s->E * A / L;
    int u0 = 3 * e, u1 = 3 * e + 3;
    ks_add(b, u0, u0, ka);
    ks_add(b, u1, u1, ka);
    ks_add(b, u0, u1, -ka);
    ks_add(b, u1, u0, -ka);
    acbb_timoshenko_element(s->E * I, phi, L, kb);
    const int dof[4] = {3 * e + 1, 3 * e + 2, 3 * e + 4, 3 * e + 5};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) ks_add(b, dof[i], dof[j], kb[4 * i + j]);
}

static int node_at(const acbb_shaft_beam *b, double x)
{
    double tol = 1e-9 * b->x[b->n_nodes - 1];
    for (int i = 0; i < b->n_nodes; i++)
        if (fabs(b->x[i] - x) <= tol) return i;
    return -1;
}

static acbb_status check_supports(const acbb_shaft_support *sup, int n_sup, double Ltot,
                                  acbb_error *err)
{
    if (n_sup < 0 || n_sup > ACBB_SHAFT_MAX_SUPPORTS || (n_sup > 0 && !sup))
        return acbb_error_set(err, ACBB_EINVAL, "shaft: %d supports (must be in [0, %d])",
                              n_sup, ACBB_SHAFT_MAX_SUPPORTS);
    for (int k = 0; k < n_sup; k++) {
        const acbb_shaft_support *s = &sup[k];
        if (!isfinite(s->x) || s->x < 0.0 || s->x > Ltot)
            return acbb_error_set(err, ACBB_EINVAL,
                                  "shaft support %d: x = %g m (must be in [0, %g])", k + 1,
                                  s->x, Ltot);
        int bad = !(s->k_axial >= 0.0 && s->k_radial >= 0.0 && s->k_tilt >= 0.0 &&
                    s->k_axial < 1e15 && s->k_radial < 1e15 && s->k_tilt < 1e15);
        if (!s->fn && bad)
            return acbb_error_set(err, ACBB_EINVAL,
                                  "shaft support %d: stiffness (%g N/m, %g N/m, %g N m/rad) "
                                  "(each must be in [0, 1e15))",
                                  k + 1, s->k_axial, s->k_radial, s->k_tilt);
    }
    return ACBB_OK;
}

static acbb_status alloc_beam(acbb_shaft_beam *b, int n_nodes)
{
    size_t nd = 3 * (size_t)n_nodes;
    b->n_nodes = n_nodes;
    b->n_dof = (int)nd;
    b->Ks = calloc(nd * NB, sizeof *b->Ks);
    b->d = calloc(nd, sizeof *b->d);
    b->d_old = calloc(nd, sizeof *b->d_old);
    b->diag_scale = calloc(3, sizeof *b->diag_scale);
    b->AB = gsl_matrix_alloc(nd, 3 * BW + 1);
    b->piv = gsl_vector_uint_alloc(nd);
    b->rhs = gsl_vector_alloc(nd);
    b->dx = gsl_vector_alloc(nd);
    return (b->Ks && b->d && b->d_old && b->diag_scale && b->AB && b->piv && b->rhs && b->dx)
               ? ACBB_OK : ACBB_ENOMEM;
}

static acbb_status assemble(acbb_shaft_beam *b, const acbb_shaft_seg *seg, int n_seg)
{
    for (int e = 0; e + 1 < b->n_nodes; e++) {
        int k = acbb_shaft_segs_locate(seg, n_seg, 0.5 * (b->x[e] + b->x[e + 1]));
        if (k < 0) return ACBB_EINVAL;
        add_element(b, e, &seg[k]);
    }
    for (int i = 0; i < b->n_dof; i++) {
        double kii = b->Ks[(size_t)i * NB + BW];
        if (kii > b->diag_scale[i % 3]) b->diag_scale[i % 3] = kii;
    }
    return ACBB_OK;
}

acbb_status acbb_shaft_beam_build(const acbb_shaft_seg *seg, int n_seg,
                                  const acbb_shaft_support *sup, int n_sup, int n_div,
                                  const double *load_x, int n_lx,
                                  acbb_shaft_beam **out, acbb_error *err)
{
    *out = NULL;
    acbb_status st = acbb_shaft_segs_check("shaft", seg, n_seg, ACBB_SEG_MECH, err);
    if (st == ACBB_OK) st = check_supports(sup, n_sup, acbb_shaft_segs_length(seg, n_seg), err);
    if (st != ACBB_OK) return st;
    if (n_lx < 0 || n_lx > 64 || (n_lx > 0 && !load_x))
        return acbb_error_set(err, ACBB_EINVAL, "shaft: %d load stations (must be in [0, 64])",
                              n_lx);
    double extra[ACBB_SHAFT_MAX_SUPPORTS + 64];
    for (int k = 0; k < n_sup; k++) extra[k] = sup[k].x;
    for (int k = 0; k < n_lx; k++) extra[n_sup + k] = load_x[k];
    acbb_shaft_beam *b = calloc(1, sizeof *b);
    if (b) b->tol = STEP_TOL;
    if (!b) return acbb_error_set(err, ACBB_ENOMEM, "shaft: out of memory");
    int n_nodes = 0;
    st = acbb_shaft_mesh(seg, n_seg, n_div, extra, n_sup + n_lx, &b->x, &n_nodes, err);
    if (st == ACBB_OK && alloc_beam(b, n_nodes) != ACBB_OK)
        st = acbb_error_set(err, ACBB_ENOMEM, "shaft: out of memory");
    if (st == ACBB_OK && assemble(b, seg, n_seg) != ACBB_OK)
        st = acbb_error_set(err, ACBB_EINVAL, "shaft: an element lies outside the segments");
    if (st != ACBB_OK) {
        acbb_shaft_beam_free(b);
        return st;
    }
    b->n_sup = n_sup;
    for (int k = 0; k < n_sup; k++) {
        b->sup[k] = sup[k];
        b->sup_node[k] = node_at(b, sup[k].x);
    }
    *out = b;
    return ACBB_OK;
}

void acbb_shaft_beam_free(acbb_shaft_beam *b)
{
    if (!b) return;
    free(b->x);
    free(b->Ks);
    free(b->d);
    free(b->d_old);
    free(b->diag_scale);
    if (b->AB) gsl_matrix_free(b->AB);
    if (b->piv) gsl_vector_uint_free(b->piv);
    if (b->rhs) gsl_vector_free(b->rhs);
    if (b->dx) gsl_vector_free(b->dx);
    free(b);
}

/* Reaction f and tangent K of support k at the current displacements. */
static acbb_status support_eval(const acbb_shaft_beam *b, int k, double f[3], double K[9])
{
    const acbb_shaft_support *s = &b->sup[k];
    const double *d = &b->d[3 * b->sup_node[k]];
    if (s->fn) {
        acbb_status st = s->fn(s->ctx, d, f, K);
        for (int i = 0; i < 9 && st == ACBB_OK; i++)
            if (!isfinite(K[i]) || (i < 3 && !isfinite(f[i]))) st = ACBB_NONFINITE;
        return st;
    }
    const double kd[3] = {s->k_axial, s->k_radial, s->k_tilt};
    memset(K, 0, 9 * sizeof *K);
    for (int i = 0; i < 3; i++) {
        f[i] = -kd[i] * d[i];
        K[4 * i] = kd[i];
    }
    return ACBB_OK;
}

/* AB(j, 2 BW + i - j) = A(i, j): GSL's band LU layout (lb = ub = BW). */
static void ab_add(gsl_matrix *AB, int i, int j, double v)
{
    double *p = gsl_matrix_ptr(AB, (size_t)j, (size_t)(2 * BW + i - j));
    *p += v;
}

/* Tangent matrix into AB and residual F - K d + sum f into rhs. */
static acbb_status linearise(acbb_shaft_beam *b, const double *F)
{
    gsl_matrix_set_zero(b->AB);
    for (int i = 0; i < b->n_dof; i++) {
        double r = F[i];
        for (int j = (i - BW > 0 ? i - BW : 0); j <= i + BW && j < b->n_dof; j++) {
            double kij = b->Ks[(size_t)i * NB + BW + j - i];
            r -= kij * b->d[j];
            ab_add(b->AB, i, j, kij);
        }
        gsl_vector_set(b->rhs, (size_t)i, r);
    }
    for (int k = 0; k < b->n_sup; k++) {
        double f[3], K[9];
        acbb_status st = support_eval(b, k, f, K);
        if (st != ACBB_OK) return st;
        int n0 = 3 * b->sup_node[k];
        for (int i = 0; i < 3; i++) {
            *gsl_vector_ptr(b->rhs, (size_t)(n0 + i)) += f[i];
            for (int j = 0; j < 3; j++) ab_add(b->AB, n0 + i, n0 + j, K[3 * i + j]);
        }
    }
    return ACBB_OK;
}

/* LU of AB; ACBB_SINGULAR when a pivot vanishes against its DOF kind's
 * largest structural diagonal (a free rigid-body motion). */
static acbb_status factor(acbb_shaft_beam *b, acbb_error *err)
{
    static const char *const kind[3] = {"axial", "radial", "tilt"};
    if (gsl_linalg_LU_band_decomp((size_t)b->n_dof, BW, BW, b->AB, b->piv) != GSL_SUCCESS)
        return acbb_error_set(err, ACBB_SINGULAR, "shaft: band LU failed");
    for (int i = 0; i < b->n_dof; i++) {
        double u = fabs(gsl_matrix_get(b->AB, (size_t)i, 2 * BW));
        if (!(u > 1e-12 * b->diag_scale[i % 3]))
            return acbb_error_set(err, ACBB_SINGULAR,
                                  "shaft: the supports leave the shaft free (%s, near x = %g m)",
                                  kind[i % 3], b->x[i / 3]);
    }
    return ACBB_OK;
}

static double inf_norm(const double *v, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}

static acbb_status load_vector(const acbb_shaft_beam *b, const acbb_shaft_load *loads,
                               int n_loads, double *F, acbb_error *err)
{
    memset(F, 0, (size_t)b->n_dof * sizeof *F);
    for (int k = 0; k < n_loads; k++) {
        int n = node_at(b, loads[k].x);
        const double v[3] = {loads[k].F_axial, loads[k].F_radial, loads[k].M};
        if (n < 0 || !isfinite(v[0] + v[1] + v[2]))
            return acbb_error_set(err, ACBB_EINVAL,
                                  "shaft load %d: x = %g m is not a load station of the mesh "
                                  "or a value is not finite", k + 1, loads[k].x);
        for (int i = 0; i < 3; i++) F[3 * n + i] += v[i];
    }
    return ACBB_OK;
}

/* Backtracking along the Newton step dx from d_old: halve until the
 * residual (max norm, from linearise, which also leaves the next tangent)
 * does not grow, at most MAX_HALF times. Plain Newton overshoots from the
 * flat part of a softening support. When no fraction lowers the residual
 * (round-off next to the solution) the full step is taken, as plain Newton. */
static acbb_status line_search(acbb_shaft_beam *b, const double *F, double r0)
{
    const double *dx = gsl_vector_const_ptr(b->dx, 0);
    double lam = 1.0;
    for (int h = 0; h <= MAX_HALF; h++, lam *= 0.5) {
        for (int i = 0; i < b->n_dof; i++) b->d[i] = b->d_old[i] + lam * dx[i];
        acbb_status st = linearise(b, F);
        double r1 = inf_norm(gsl_vector_const_ptr(b->rhs, 0), b->n_dof);
        if (st == ACBB_OK && isfinite(r1) && r1 <= r0) return ACBB_OK;
    }
    for (int i = 0; i < b->n_dof; i++) b->d[i] = b->d_old[i] + dx[i];
    return linearise(b, F);
}

static acbb_status newton(acbb_shaft_beam *b, const double *F, int *iters, acbb_error *err)
{
    acbb_status st = linearise(b, F);
    for (int it = 1; it <= MAX_ITER && st == ACBB_OK; it++) {
        if ((st = factor(b, err)) != ACBB_OK) return st;
        double r0 = inf_norm(gsl_vector_const_ptr(b->rhs, 0), b->n_dof);
        gsl_linalg_LU_band_solve(BW, BW, b->AB, b->piv, b->rhs, b->dx);
        const double *dx = gsl_vector_const_ptr(b->dx, 0);
        memcpy(b->d_old, b->d, (size_t)b->n_dof * sizeof *b->d);
        double step = inf_norm(dx, b->n_dof), size = inf_norm(b->d, b->n_dof);
        *iters = it;
        if (!isfinite(step))
            return acbb_error_set(err, ACBB_NONFINITE, "shaft: displacements not finite");
        /* converged: take the last full step */
        if (step <= b->tol * fmax(size, step) || step <= b->floor) {
            for (int i = 0; i < b->n_dof; i++) b->d[i] += dx[i];
            return ACBB_OK;
        }
        st = line_search(b, F, r0);
    }
    if (st != ACBB_OK)
        return acbb_error_set(err, st, "shaft: a support's reaction failed (%s)",
                              acbb_status_name(st));
    return acbb_error_set(err, ACBB_DIVERGED, "shaft: no static equilibrium after %d Newton "
                          "iterations", MAX_ITER);
}

/* Reactions and the nose compliance (tangent at the solution). */
static acbb_status results(acbb_shaft_beam *b, acbb_shaft_result *res, acbb_error *err)
{
    for (int k = 0; k < b->n_sup; k++) {
        double K[9];
        if (support_eval(b, k, res->reaction[k], K) != ACBB_OK)
            return acbb_error_set(err, ACBB_NONFINITE, "shaft: support %d failed", k + 1);
    }
    res->n_support = b->n_sup;
    memcpy(res->nose, b->d, 3 * sizeof *b->d);
    double *F = calloc((size_t)b->n_dof, sizeof *F);
    if (!F) return acbb_error_set(err, ACBB_ENOMEM, "shaft: out of memory");
    acbb_status st = linearise(b, F);
    free(F);
    if (st == ACBB_OK) st = factor(b, err);
    for (int j = 0; j < 3 && st == ACBB_OK; j++) {
        gsl_vector_set_zero(b->rhs);
        gsl_vector_set(b->rhs, (size_t)j, 1.0);
        gsl_linalg_LU_band_solve(BW, BW, b->AB, b->piv, b->rhs, b->dx);
        for (int i = 0; i < 3; i++) res->compliance[3 * i + j] = gsl_vector_get(b->dx, (size_t)i);
    }
    if (st != ACBB_OK) return st;
    res->k_axial = 1.0 / res->compliance[0];
    res->k_radial = 1.0 / res->compliance[4];
    res->k_tilt = 1.0 / res->compliance[8];
    return ACBB_OK;
}

acbb_status acbb_shaft_beam_solve(acbb_shaft_beam *b, const acbb_shaft_load *loads,
                                  int n_loads, acbb_shaft_result *res, acbb_error *err)
{
    if (!b || !res || n_loads < 0 || (n_loads > 0 && !loads))
        return acbb_error_set(err, ACBB_EINVAL, "shaft: bad solve arguments");
    memset(res, 0, sizeof *res);
    double *F = malloc((size_t)b->n_dof * sizeof *F);
    if (!F) return acbb_error_set(err, ACBB_ENOMEM, "shaft: out of memory");
    acbb_status st = load_vector(b, loads, n_loads, F, err);
    if (st == ACBB_OK) st = newton(b, F, &res->iterations, err);
    free(F);
    if (st != ACBB_OK)   /* no failed trial as the next warm start */
        memset(b->d, 0, (size_t)b->n_dof * sizeof *b->d);
    if (st == ACBB_OK) st = results(b, res, err);
    return st;
}

void acbb_shaft_beam_set_tol(acbb_shaft_beam *b, double tol)
{
    if (b && tol > 0.0) b->tol = fmax(tol, STEP_TOL);
}

void acbb_shaft_beam_set_floor(acbb_shaft_beam *b, double floor)
{
    if (b && floor >= 0.0 && isfinite(floor)) b->floor = floor;
}

int acbb_shaft_beam_nodes(const acbb_shaft_beam *b) { return b ? b->n_nodes : 0; }

void acbb_shaft_beam_start(acbb_shaft_beam *b, double *d, int put)
{
    size_t n = (size_t)b->n_dof * sizeof *b->d;
    if (put) memcpy(b->d, d, n);
    else memcpy(d, b->d, n);
}

acbb_status acbb_shaft_beam_node(const acbb_shaft_beam *b, int i, double *x, double d[3])
{
    if (!b || i < 0 || i >= b->n_nodes) return ACBB_EINVAL;
    if (x) *x = b->x[i];
    if (d) memcpy(d, &b->d[3 * i], 3 * sizeof *d);
    return ACBB_OK;
}
