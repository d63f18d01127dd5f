/* acbb — traction resultants of one contact for the quasi-dynamic model
 * (MODEL.md section 4, Level 2): the local traction opposes the local slip
 * of ball against race, tau = -tau_mag s_t / sqrt(|s_t|^2 + s_reg^2), with
 * tau_mag = phi_a mu p + phi_f tau_lub (section 5). Resultant force and
 * moment about the ball centre, in the orbiting ball frame (x', y', z').
 *
 * Ownership: acbb_traction_contact_init allocates the point tables that
 * acbb_traction_contact_free releases; prepare fills them once per
 * mechanical state, eval is called many times by the kinematics solve. */
#ifndef ACBB_TRACTION_H
#define ACBB_TRACTION_H

#include "losses.h"
#include "lubrication.h"
#include "acbb/scene.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

typedef struct {
    double F[3];    /* force on the ball, N */
    double M[3];    /* moment on the ball about its centre, N m */
} acbb_traction;

typedef struct {
    int cap;                /* points allocated */
    int np;                 /* points in use (0: no contact) */
    double n[3], t[3];      /* contact normal (ball centre -> contact), major-axis tangent */
    double rm;              /* orbit radius, m */
    double H;               /* film thickness, m */
    double phi_a, phi_f;    /* load shares */
    double s_reg;           /* slip regularisation, m/s (1e-6 unless a solver continues in it) */
    double *P;              /* 3 np: point positions from the ball centre */
    double *w;              /* np: area weights dA */
    double *p;              /* np: Hertz pressure */
    double *eta;            /* np: viscosity at that pressure */
    double *tb;             /* np: asperity stress phi_a mu p */
    double *tlim;           /* np: limiting lubricant stress Lambda_L p */
} acbb_traction_contact;

acbb_status acbb_traction_contact_init(acbb_traction_contact *tc, int grid);
/* tc as acbb_traction_contact_init makes it for grid, in its own tables if
 * they are that size: every scalar cleared; the tables are written by
 * prepare before eval reads them (a batch's runs reuse one). On failure
 * tc is still the caller's to free. */
acbb_status acbb_traction_contact_renew(acbb_traction_contact *tc, int grid);
void acbb_traction_contact_free(acbb_traction_contact *tc);

/* asinh(x) for x > 0 by the identities a C library uses (W. Kahan's, in
 * fdlibm's s_asinh.c and glibc's): log(x) + ln 2 above 2^28, log(2x +
 * 1/(sqrt(x^2 + 1) + x)) above 2, log1p(x + x^2/(1 + sqrt(1 + x^2)))
 * below, x itself below 2^-28, split on the high word as there; inline,
 * without the call, the sign and special-value work of every Eyring
 * stress of Level 2 and the loss quadrature (issue 30). Finite x > 0. */
static inline double acbb_asinh_pos(double x)
{
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    uint32_t hi = (uint32_t)(bits >> 32);
    if (hi < 0x3e300000u) return x;
    if (hi > 0x41b00000u) return log(x) + 6.93147180559945286227e-01;
    if (hi > 0x40000000u) return log(2.0 * x + 1.0 / (sqrt(x * x + 1.0) + x));
    double t = x * x;
    return log1p(x + t / (1.0 + sqrt(1.0 + t)));
}

/* acbb_tau_lubricant's Eyring branch (tau_e > 0) with its film floor and
 * limiting stress taken from the tables: the same operations in the same
 * order, so the same bits, without a call and three fmax per point (the
 * innermost loops of Level 2 and of the loss quadrature). H must already
 * be floored at 1e-9 m and mag >= 0, eta > 0. */
static inline double acbb_eyring_capped(double tau_e, double eta, double mag, double H, double tlim)
{
    double tn = eta * (mag / H);
    if (!(tlim > 0.0) || !(tn > 0.0)) return 0.0;
    double tau = tau_e * acbb_asinh_pos(tn / tau_e);
    return tau < tlim ? tau : tlim;
}

/* The viscosity at node (i, j) of an n x n Gauss grid whose pressures p
 * and viscosities eta (row-major) are filled in order: the Hertz pressure
 * is even in both coordinates and Gauss nodes come in +-x pairs, so a
 * node whose mirror image (earlier in the order) has the same pressure,
 * bit for bit, has its viscosity too (a quarter of the law's evaluations;
 * issue 30). The pressure pmax sqrt(1 - x_i^2) sqrt(1 - x_j^2) is also
 * symmetric in i and j on the unit-square map, so the transposed node
 * (j, i) shares it when the rounding gave the same bits. */
static inline double acbb_visc_law_eval_mirror(const acbb_visc_law *v, const double *p,
                                               const double *eta, int n, int i, int j)
{
    int k = i * n + j, mi = (n - 1 - i) * n + j, mj = i * n + (n - 1 - j), mt = j * n + i;
    if (mi < k && p[mi] == p[k]) return eta[mi];
    if (mj < k && p[mj] == p[k]) return eta[mj];
    if (mt < k && p[mt] == p[k]) return eta[mt];
    return acbb_visc_law_eval(v, p[k]);
}

/* Point tables for contact c with film f and inlet oil o. */
acbb_status acbb_traction_prepare(const acbb_scene *s, const acbb_quad *q,
                                  const acbb_contact_in *c, const acbb_film *f,
                                  const acbb_oil_state *o, acbb_traction_contact *tc);

/* Resultants for ball angular velocity wb (orbiting frame, rad/s) and race
 * angular speed relative to the orbiting frame `race` (rad/s). */
void acbb_traction_eval(const acbb_scene *s, const acbb_traction_contact *tc,
                        const double wb[3], double race, acbb_traction *out);

/* The resultants as acbb_traction_eval and their derivatives with respect
 * to u = (wb[0], wb[1], wb[2], race): dF[i][j] = dF_i/du_j, dM likewise,
 * summed over the same points (about 1.5 evaluations of work instead of
 * the 4 more of forward differences). Returns 0 for a traction law without
 * an analytic derivative here (Bair-Winer, or Eyring with tau_eyring <= 0,
 * when the film carries load); the caller then differences instead. */
int acbb_traction_eval_jac(const acbb_scene *s, const acbb_traction_contact *tc,
                           const double wb[3], double race, acbb_traction *out,
                           double dF[3][4], double dM[3][4]);

#endif
