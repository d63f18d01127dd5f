/* acbb — Hertz point contact (MODEL.md section 2). Pure functions. */
#ifndef ACBB_HERTZ_H
#define ACBB_HERTZ_H

#include "acbb/scene.h"
#include "acbb/status.h"

/* Load-independent constants of one contact. */
typedef struct {
    double Rx, Ry;      /* principal radii, rolling / transverse plane, m */
    double R;           /* 1 / curvature sum, m */
    double F_rho;       /* curvature difference */
    double kappa;       /* ellipticity a/b */
    double K, E;        /* complete elliptic integrals of 1st / 2nd kind */
    double E_eff;       /* effective modulus E', Pa */
    double Kc;          /* load-deflection constant, N/m^1.5 */
} acbb_hertz_const;

/* One loaded contact. Q = 0 gives a = b = pmax = 0. */
typedef struct {
    double Q;           /* normal load, N */
    double delta;       /* deflection, m */
    double a, b;        /* semi-major / semi-minor axes, m */
    double pmax;        /* maximum pressure, Pa */
} acbb_hertz_contact;

/* E' = 2 / [(1-nu1^2)/E1 + (1-nu2^2)/E2]. */
double acbb_effective_modulus(double E1, double nu1, double E2, double nu2);

/* Principal radii for a ball of diameter D on a groove of factor f, pitch
 * diameter dm, operating angle alpha; inner != 0 for the inner race. */
void acbb_contact_radii(double D, double dm, double alpha, double f, int inner,
                        double *Rx, double *Ry);

/* Constants for radii (Rx, Ry) and modulus E_eff with the chosen fidelity:
 * EXACT solves the ellipticity equation with GSL Brent and GSL complete
 * elliptic integrals; BH77 / HB83 use the closed-form fits. */
acbb_status acbb_hertz_const_compute(double Rx, double Ry, double E_eff,
                                     acbb_hertz_mode mode, acbb_hertz_const *out);

/* Contact from a given normal load / from a given deflection (<= 0: none). */
void acbb_hertz_from_load(const acbb_hertz_const *c, double Q, acbb_hertz_contact *out);
void acbb_hertz_from_deflection(const acbb_hertz_const *c, double delta,
                                acbb_hertz_contact *out);

#endif
