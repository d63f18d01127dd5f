/* acbb — lubricant properties, EHL film and traction (MODEL.md section 5).
 * Pure functions of the scene's [lubricant] values. */
#ifndef ACBB_LUBRICATION_H
#define ACBB_LUBRICATION_H

#include "acbb/scene.h"

/* fmax(x, 0.0) without the library call, for the per-node tables of the
 * contact integrals: the same value for every x (glibc's fmax returns its
 * second operand, +0, for -0 and for NaN, as this does). */
static inline double acbb_nonneg(double x) { return x > 0.0 ? x : 0.0; }

/* Oil properties at one temperature (ambient pressure). */
typedef struct {
    double T_C;         /* temperature, C */
    double rho;         /* density, kg/m^3 */
    double nu;          /* kinematic viscosity, m^2/s */
    double eta0;        /* dynamic viscosity at ambient pressure, Pa s */
    double beta_T;      /* temperature-viscosity coefficient -dln(eta)/dT, 1/K */
} acbb_oil_state;

/* Walther (ASTM D341) through (40 C, nu40) and (100 C, nu100), or the
 * constant viscosity when s->visc == ACBB_VISC_CONST. */
void acbb_oil_at(const acbb_scene *s, double T_C, acbb_oil_state *o);

/* Viscosity at pressure p (Pa): Roelands (default) or Barus; const model
 * returns eta0 unchanged. */
double acbb_viscosity_at_pressure(const acbb_scene *s, const acbb_oil_state *o, double p);

/* The same law with its pressure-independent terms (log eta0, the Roelands
 * exponent) evaluated once: for the many points of one contact. Gives the
 * bit-identical value of acbb_viscosity_at_pressure. */
typedef struct {
    int kind;           /* acbb_visc_model actually used (Roelands may fall back to Barus) */
    double eta0, alpha, lnv, Z;
} acbb_visc_law;
void acbb_visc_law_init(const acbb_scene *s, const acbb_oil_state *o, acbb_visc_law *v);
double acbb_visc_law_eval(const acbb_visc_law *v, double p);

/* Film and load sharing of one contact. */
typedef struct {
    double hc;          /* central film thickness (with thermal factor), m */
    double hmin;        /* minimum film thickness, m */
    double phi_T;       /* inlet-shear thermal reduction factor, [0.1, 1] */
    double lambda;      /* film parameter hc / sigma */
    double phi_f;       /* fluid load share */
    double phi_a;       /* asperity load share = 1 - phi_f */
} acbb_film;

/* Hamrock-Dowson 1977 film for entrainment speed u (m/s), load Q (N),
 * Rx (m), ellipticity kappa, effective modulus E_eff (Pa), pmax (Pa) and
 * slide-to-roll ratio srr; Gupta 1992 thermal factor; Zhou-Hoeprich share.
 * u < 1e-6 m/s or !s->ehl_film gives hc = 0, phi_a = 1 (boundary). */
void acbb_film_compute(const acbb_scene *s, const acbb_oil_state *o, double u,
                       double Q, double Rx, double kappa, double E_eff,
                       double pmax, double srr, acbb_film *f);

/* Lubricant shear stress for sliding speed du (m/s), film H (m, floored at
 * 1e-9), local pressure p (Pa) and local viscosity eta (Pa s):
 * Eyring capped by the limiting stress Lambda_L p, or Bair-Winer. >= 0. */
double acbb_tau_lubricant(const acbb_scene *s, double eta, double du, double H, double p);


/* Oil-air mixture used for drag and cavity convection. */
typedef struct {
    double X;           /* oil volume fraction */
    double rho, eta;    /* effective density (kg/m^3), viscosity (Pa s) */
    double cp;          /* mass-weighted specific heat, J/(kg K) */
} acbb_mixture;
void acbb_mixture_at(const acbb_scene *s, const acbb_oil_state *o, acbb_mixture *m);

#endif
