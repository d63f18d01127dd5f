/* acbb — lubricant properties, EHL film and traction (MODEL.md section 5).
 * Pure functions of the scene's [lubricant] values. */
#include "lubrication.h"

#include <math.h>
#include <string.h>

#define KELVIN 273.15
/* Walther reference points (ASTM D341), C. */
#define WALTHER_T1_C 40.0
#define WALTHER_T2_C 100.0
/* Walther's additive constant for nu in mm^2/s. */
#define WALTHER_C 0.7
/* Density temperature coefficient, 1/K, reference 20 C (MODEL.md 5). */
#define RHO_COEF 6.5e-4
#define RHO_REF_C 20.0
/* Half step of the central difference for beta_T, K. */
#define BETA_T_STEP 0.5
/* Roelands constants (MODEL.md 5): p_R and the ln(eta_inf) = -9.67 pole. */
#define ROELANDS_PR 1.96e8
#define ROELANDS_LN_ETA_INF 9.67
#define ROELANDS_Z_SCALE 5.1e-9
/* Zero-speed guard and film floor (MODEL.md section 11). */
#define U_MIN 1e-6
#define H_FLOOR 1e-9
/* Lower bound for the composite roughness, m: keeps Lambda finite for
 * ideally smooth surfaces (below any real finish). */
#define SIGMA_FLOOR 1e-9
#define SRR_MAX 2.0
#define PHI_T_MIN 0.1

/* Walther line through (40 C, nu40) and (100 C, nu100):
 * log10 log10(nu + 0.7) = A - B log10(T), nu in mm^2/s, T in K. */
static void walther_constants(const acbb_scene *s, double *A, double *B)
{
    double y1 = log10(log10(s->oil_nu40 * 1e6 + WALTHER_C));
    double y2 = log10(log10(s->oil_nu100 * 1e6 + WALTHER_C));
    double x1 = log10(WALTHER_T1_C + KELVIN), x2 = log10(WALTHER_T2_C + KELVIN);
    *B = (y1 - y2) / (x2 - x1);
    *A = y1 + *B * x1;
}

/* Kinematic viscosity, m^2/s, from the Walther line. */
static double walther_nu(double A, double B, double T_C)
{
    double y = A - B * log10(T_C + KELVIN);
    return (pow(10.0, pow(10.0, y)) - WALTHER_C) * 1e-6;
}

static double oil_density(const acbb_scene *s, double T_C)
{
    return s->oil_density * (1.0 - RHO_COEF * (T_C - RHO_REF_C));
}

void acbb_oil_at(const acbb_scene *s, double T_C, acbb_oil_state *o)
{
    o->T_C = T_C;
    o->rho = oil_density(s, T_C);
    if (s->visc == ACBB_VISC_CONST) {
        /* The seed's constant viscosity (MODEL.md section 10): no
         * temperature dependence at all. */
        o->eta0 = s->oil_eta_const;
        o->nu = o->eta0 / o->rho;
        o->beta_T = 0.0;
        return;
    }
    double A, B;
    walther_constants(s, &A, &B);
    o->nu = walther_nu(A, B, T_C);
    o->eta0 = o->rho * o->nu;
    /* beta_T = -d ln(eta)/dT by central difference (MODEL.md 5); eta
     * includes the density law so it is the dynamic-viscosity slope. */
    double h = BETA_T_STEP;
    double eta_p = oil_density(s, T_C + h) * walther_nu(A, B, T_C + h);
    double eta_m = oil_density(s, T_C - h) * walther_nu(A, B, T_C - h);
    o->beta_T = -(log(eta_p) - log(eta_m)) / (2.0 * h);
}

void acbb_visc_law_init(const acbb_scene *s, const acbb_oil_state *o, acbb_visc_law *v)
{
    v->eta0 = o->eta0;
    v->alpha = s->oil_alpha_pv;
    v->lnv = v->Z = 0.0;
    v->kind = s->visc == ACBB_VISC_CONST ? ACBB_VISC_CONST : ACBB_VISC_BARUS;
    if (s->visc == ACBB_VISC_CONST || s->visc == ACBB_VISC_BARUS)
        return;
    /* Roelands is undefined at or below its asymptotic viscosity
     * (6.3e-5 Pa s); such thin fluids fall back to Barus. */
    double lnv = log(v->eta0) + ROELANDS_LN_ETA_INF;
    if (!(lnv > 0.0))
        return;
    v->kind = ACBB_VISC_ROELANDS;
    v->lnv = lnv;
    v->Z = v->alpha / (ROELANDS_Z_SCALE * lnv);
}

double acbb_visc_law_eval(const acbb_visc_law *v, double p)
{
    /* Negative gauge pressure (cavitated outlet) does not thin the oil. */
    p = acbb_nonneg(p);
    switch (v->kind) {
    case ACBB_VISC_CONST:
        return v->eta0;
    case ACBB_VISC_ROELANDS:
        return v->eta0 * exp(v->lnv * (-1.0 + pow(1.0 + p / ROELANDS_PR, v->Z)));
    default:
        return v->eta0 * exp(v->alpha * p);
    }
}

double acbb_viscosity_at_pressure(const acbb_scene *s, const acbb_oil_state *o, double p)
{
    acbb_visc_law v;
    acbb_visc_law_init(s, o, &v);
    return acbb_visc_law_eval(&v, p);
}

/* Gupta et al. 1992 inlet shear heating factor (MODEL.md 5), clamped. */
static double thermal_factor(const acbb_oil_state *o, const acbb_scene *s, double u,
                             double pmax, double E_eff, double srr)
{
    if (!(o->beta_T > 0.0) || !(s->oil_k > 0.0))
        return 1.0;
    double L = o->beta_T * o->eta0 * u * u / s->oil_k;
    double S = fmin(fabs(srr), SRR_MAX);
    double num = 1.0 - 13.2 * (pmax / E_eff) * pow(L, 0.42);
    double den = 1.0 + 0.213 * (1.0 + 2.23 * pow(S, 0.83)) * pow(L, 0.64);
    return fmin(1.0, fmax(PHI_T_MIN, num / den));
}

/* Zhou-Hoeprich fluid load share (MODEL.md 5). The printed fit
 * 1.21 L^0.64 / (1 + 0.37 L^1.26) peaks at 1.003 near L = 2.26 and then
 * falls back towards 0, so a thicker film would give *more* asperity
 * load. It is used up to its maximum and held there (then min(1, .) = 1),
 * which keeps the share monotone: L_peak solves d ln(fit)/dL = 0. */
static double fluid_share(double lambda)
{
    static const double c1 = 1.21, e1 = 0.64, c2 = 0.37, e2 = 1.26;
    double L_peak = pow(e1 / (c2 * (e2 - e1)), 1.0 / e2);
    double L = fmin(fmax(lambda, 0.0), L_peak);
    return fmin(1.0, c1 * pow(L, e1) / (1.0 + c2 * pow(L, e2)));
}

void acbb_film_compute(const acbb_scene *s, const acbb_oil_state *o, double u,
                       double Q, double Rx, double kappa, double E_eff,
                       double pmax, double srr, acbb_film *f)
{
    memset(f, 0, sizeof *f);
    f->phi_T = 1.0;
    f->phi_a = 1.0;
    if (!s->ehl_film || !(u >= U_MIN) || !(Q > 0.0) || !(Rx > 0.0) || !(E_eff > 0.0))
        return; /* boundary lubrication (MODEL.md section 11) */

    /* Hamrock-Dowson 1977 dimensionless groups (MODEL.md 5). */
    double U = o->eta0 * u / (E_eff * Rx);
    double G = s->oil_alpha_pv * E_eff;
    double W = Q / (E_eff * Rx * Rx);
    double hc = Rx * 2.69 * pow(U, 0.67) * pow(G, 0.53) * pow(W, -0.067) *
                (1.0 - 0.61 * exp(-0.73 * kappa));
    double hmin = Rx * 3.63 * pow(U, 0.68) * pow(G, 0.49) * pow(W, -0.073) *
                  (1.0 - exp(-0.68 * kappa));

    f->phi_T = thermal_factor(o, s, u, pmax, E_eff, srr);
    f->hc = f->phi_T * hc;
    f->hmin = f->phi_T * hmin;

    double sigma = hypot(s->roughness_race, s->roughness_ball);
    f->lambda = f->hc / fmax(sigma, SIGMA_FLOOR);
    f->phi_f = fluid_share(f->lambda);
    f->phi_a = 1.0 - f->phi_f;
}

double acbb_tau_lubricant(const acbb_scene *s, double eta, double du, double H, double p)
{
    double gdot = fabs(du) / fmax(H, H_FLOOR);
    double tau_lim = s->lambda_lim * fmax(p, 0.0);
    double tau_newton = fmax(eta, 0.0) * gdot;
    if (!(tau_lim > 0.0) || !(tau_newton > 0.0))
        return 0.0;
    if (s->traction == ACBB_TRACTION_BAIR_WINER)
        return tau_lim * -expm1(-tau_newton / tau_lim);
    /* Eyring [JT] capped by the limiting stress [BW]. A non-positive Eyring
     * stress means a Newtonian fluid up to the cap. */
    double tau_e = s->tau_eyring;
    double tau = tau_e > 0.0 ? tau_e * asinh(tau_newton / tau_e) : tau_newton;
    return fmin(tau, tau_lim);
}

/* Oil-air mixture (MODEL.md section 6 note ii): volume-fraction weighted
 * density and viscosity, mass-weighted specific heat. The oil fraction is
 * the flow ratio for oil-air and oil-jet; grease and an oil bath put no
 * oil mist in the cavity's air (MODEL.md 16: the bath's drag is churning). */
void acbb_mixture_at(const acbb_scene *s, const acbb_oil_state *o, acbb_mixture *m)
{
    double q = s->q_oil + s->q_air;
    int mist = s->lub_method == ACBB_LUB_OIL_AIR || s->lub_method == ACBB_LUB_OIL_JET;
    double X = mist && q > 0.0 ? s->q_oil / q : 0.0;
    double m_oil = X * o->rho, m_air = (1.0 - X) * s->air_density;
    m->X = X;
    m->rho = m_oil + m_air;
    m->eta = X * o->eta0 + (1.0 - X) * s->air_eta;
    m->cp = m->rho > 0.0 ? (m_oil * s->oil_cp + m_air * s->air_cp) / m->rho : 0.0;
}
