/* acbb — ISO rating-life and static-safety formulas (life.h, MODEL.md 15). */
#include <math.h>
#include "hertz.h"
#include "life.h"

#define ISO76_PMAX 4200e6      /* Pa: ISO 76 clause 3, ball bearings other than self-aligning */
#define ISO76_STRIBECK 5.0     /* Q_max = 5 F_r / (Z cos alpha), ISO 76's radial load zone */
/* ISO 76 Table 1's basis: grooves 0.52 / 0.53 D_w, steel (207 GPa, 0.3). */
#define TABLE_FI 0.52
#define TABLE_FO 0.53
#define TABLE_TOL 1e-6
/* m: half the 1 um the presets write groove radii in (3.3655 mm rounds
 * either way), and the binary rounding of such a radius over D_w. */
#define TABLE_GRID (0.5e-6 * (1.0 + 1e-9))

/* Linear interpolation in a table on gamma = 0, step, 2 step, ...; held at
 * the ends. Hand-written: a fixed 25-41 point lookup, where gsl_interp
 * would need an allocation per call. */
static double table(const double *v, int n, double step, double g)
{
    double x = g / step;
    if (x <= 0.0) return v[0];
    if (x >= n - 1) return v[n - 1];
    int i = (int)x;
    return v[i] + (x - i) * (v[i + 1] - v[i]);
}

/* ISO 281:2007 Table 2, single-row radial ball bearings: rows every 0.01
 * of gamma up to 0.10, every 0.02 from 0.10 to 0.40. */
double acbb_iso_fc(double gamma)
{
    static const double fine[] = { 0.0, 29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3,
                                   55.5 };
    static const double coarse[] = { 55.5, 57.5, 58.8, 59.6, 59.9, 59.9, 59.6, 59.0, 58.2,
                                     57.1, 56.0, 54.6, 53.2, 51.7, 50.0, 48.4 };
    if (gamma < 0.10) return table(fine, 11, 0.01, gamma);
    return table(coarse, 16, 0.02, gamma - 0.10);
}

/* ISO 76:2006 Table 1, radial ball bearings, gamma 0..0.40 step 0.01. */
double acbb_iso_f0(double gamma)
{
    static const double f0[] = { 14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,
                                 16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,
                                 14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
                                 11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4 };
    return table(f0, 41, 0.01, gamma);
}

/* The inner/outer split term of Lundberg-Palmgren (ISO/TS 16281 eq. 19). */
static double split(double gamma, double fi, double fo)
{
    return 1.044 * pow((1.0 - gamma) / (1.0 + gamma), 1.72) *
           pow(fi / fo * (2.0 * fo - 1.0) / (2.0 * fi - 1.0), 0.41);
}

/* f_c's conformity-dependent part: (2f_i/(2f_i-1))^0.41 [1 + s^(10/3)]^-0.3. */
static double fc_conf(double gamma, double fi, double fo)
{
    return pow(2.0 * fi / (2.0 * fi - 1.0), 0.41) *
           pow(1.0 + pow(split(gamma, fi, fo), 10.0 / 3.0), -0.3);
}

double acbb_iso_fc_conformity(double gamma, double fi, double fo)
{
    return fmin(1.0, fc_conf(gamma, fi, fo) / fc_conf(gamma, 0.52, 0.53));
}

double acbb_iso_C(double Dw, int Z, double alpha, double dpw, double fi, double fo)
{
    double mm = Dw * 1e3, gamma = Dw * cos(alpha) / dpw;
    double fc = acbb_iso_fc(gamma) * acbb_iso_fc_conformity(gamma, fi, fo);
    return 1.3 * fc * pow(cos(alpha), 0.7) * pow((double)Z, 2.0 / 3.0) * pow(mm, 1.8);
}

/* Ball load putting p_max = 1 Pa on one raceway at the nominal angle:
 * p_max grows as Q^(1/3) at fixed radii (MODEL.md 2), so the load at any
 * stress p is this times p^3. 0 when the Hertz solve fails. */
static double unit_load(double Dw, double dpw, double alpha, double f, int inner, double E_eff)
{
    double Rx, Ry;
    acbb_hertz_const c;
    acbb_hertz_contact h;
    acbb_contact_radii(Dw, dpw, alpha, f, inner, &Rx, &Ry);
    if (acbb_hertz_const_compute(Rx, Ry, E_eff, ACBB_HERTZ_EXACT, &c) != ACBB_OK) return 0.0;
    acbb_hertz_from_load(&c, 1.0, &h);
    return h.pmax > 0.0 ? 1.0 / (h.pmax * h.pmax * h.pmax) : 0.0;
}

/* The two exact Hertz solves cost about 30 us against the 4 us of the
 * rest of a life (BENCHMARKS.md): a Sim computes them once for its scene
 * (acbb_life_static_basis) instead of at every snapshot. */
static void unit_loads(double Dw, double dpw, double alpha, double fi, double fo, double E_eff,
                       double *qi, double *qo)
{
    *qi = unit_load(Dw, dpw, alpha, fi, 1, E_eff);
    *qo = unit_load(Dw, dpw, alpha, fo, 0, E_eff);
}

double acbb_iso_Q_at_stress(double p, double Dw, double dpw, double alpha, double fi, double fo,
                            double E_eff, acbb_life_race *race)
{
    double qi, qo;
    unit_loads(Dw, dpw, alpha, fi, fo, E_eff, &qi, &qo);
    if (!(qi > 0.0) || !(qo > 0.0)) return 0.0;
    if (race) *race = qi <= qo ? ACBB_RACE_IN : ACBB_RACE_OUT;
    return fmin(qi, qo) * p * p * p;
}

double acbb_iso_C0_stress(double Dw, int Z, double alpha, double dpw, double fi, double fo,
                          double E_eff)
{
    double Q = acbb_iso_Q_at_stress(ISO76_PMAX, Dw, dpw, alpha, fi, fo, E_eff, NULL);
    return Q * Z * cos(alpha) / ISO76_STRIBECK;
}

bool acbb_iso_table_basis(double Dw, double fi, double fo, double E_eff)
{
    double steel = acbb_effective_modulus(207e9, 0.3, 207e9, 0.3), tol = TABLE_GRID / Dw;
    return fabs(fi - TABLE_FI) <= tol && fabs(fo - TABLE_FO) <= tol &&
           fabs(E_eff / steel - 1.0) <= TABLE_TOL;
}

double acbb_iso_C0_table(double Dw, int Z, double alpha, double dpw)
{
    double mm = Dw * 1e3;
    return acbb_iso_f0(Dw * cos(alpha) / dpw) * Z * mm * mm * cos(alpha);
}

/* The table where the grooves and steel are its own (it is the 4200 MPa
 * load rounded to f_0's 0.1, test_life.c), the stress definition
 * elsewhere; the table also if the Hertz solve fails (it cannot for
 * grooves f > 0.5, which the presets validate). */
double acbb_iso_C0(double Dw, int Z, double alpha, double dpw, double fi, double fo,
                   double E_eff)
{
    double t = acbb_iso_C0_table(Dw, Z, alpha, dpw);
    if (acbb_iso_table_basis(Dw, fi, fo, E_eff)) return t;
    double h = acbb_iso_C0_stress(Dw, Z, alpha, dpw, fi, fo, E_eff);
    return h > 0.0 ? h : t;
}

void acbb_iso_raceway_ratings(double C, int Z, double alpha, double gamma, double fi, double fo,
                              double *Qci, double *Qce)
{
    double s = pow(split(gamma, fi, fo), 10.0 / 3.0), zc = Z * cos(alpha);
    *Qci = C / (0.407 * zc) * pow(1.0 + s, 0.3);
    *Qce = C / (0.389 * zc) * pow(1.0 + 1.0 / s, 0.3);
}

double acbb_iso_equiv_load(const double *Q, int Z, double p)
{
    double sum = 0.0;
    for (int j = 0; j < Z; j++) sum += pow(fmax(Q[j], 0.0), p);
    return Z > 0 ? pow(sum / Z, 1.0 / p) : 0.0;
}

double acbb_iso_L10r(double Qci, double Qei, double Qce, double Qee)
{
    double d = pow(Qei / Qci, 10.0 / 3.0) + pow(Qee / Qce, 10.0 / 3.0);
    return d > 0.0 ? pow(d, -0.9) : INFINITY;
}

/* ISO 281 9.2: a_1 = 0.95 (ln(100/R) / ln(100/90))^(2/3) + 0.05, which
 * Table 12 tabulates (0.64 at 95 %, 0.25 at 99 %, 0.077 at 99.95 %). */
double acbb_iso_a1(double R)
{
    if (R <= 90.0) return 1.0;
    return 0.95 * pow(log(100.0 / R) / log(100.0 / 90.0), 2.0 / 3.0) + 0.05;
}

double acbb_iso_nu1(double n, double dpw)
{
    if (!(n > 0.0)) return INFINITY;
    double d = dpw * 1e3, mm2 = n < 1000.0 ? 45000.0 * pow(n, -0.83) / sqrt(d)
                                           : 4500.0 / sqrt(n * d);
    return mm2 * 1e-6;
}

double acbb_iso_a_iso(double kappa, double ecp)
{
    double k = fmin(fmax(kappa, 0.1), 4.0), c;
    if (k < 0.4) c = 2.5671 - 2.2649 / pow(k, 0.054381);
    else if (k < 1.0) c = 2.5671 - 1.9987 / pow(k, 0.19087);
    else c = 2.5671 - 1.9987 / pow(k, 0.071739);
    double base = 1.0 - pow(c, 0.83) * cbrt(fmax(ecp, 0.0));
    if (base <= 0.0) return 50.0;
    return fmin(50.0, 0.1 * pow(base, -9.3));
}

bool acbb_iso_kappa_clamped(double kappa) { return kappa < 0.1; }

/* 22 = (4200 / 1500)^3 = 21.95 rounded: the load at which the most loaded
 * contact reaches the fatigue-limit stress 1500 MPa is C0 (1500/4200)^3,
 * since p_max grows as Q^(1/3); so C_u follows whichever basis C0 has. */
double acbb_iso_Cu(double C0, double dpw)
{
    double d = dpw * 1e3;
    return d <= 100.0 ? C0 / 22.0 : C0 / 22.0 * sqrt(100.0 / d);
}

double acbb_iso_s0(double pmax)
{
    double r = 4200e6 / pmax;
    return r * r * r;
}

double acbb_edge_margin(double alpha, double a, double r, double h)
{
    double edge = acos(fmax(-1.0, fmin(1.0, 1.0 - h / r)));
    return edge - (fabs(alpha) + a / r);
}
