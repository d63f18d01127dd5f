/* acbb — ISO rating-life and static-safety formulas on plain numbers
 * (MODEL.md 15): ISO 281:2007 (C, a1, a_ISO, nu1, C_u), ISO 76:2006 (C0,
 * 4200 MPa), ISO/TS 16281:2008 (raceway ratings, equivalent raceway loads,
 * reference life). SI in and out (m, N, Pa, rad); the standards' mm/N
 * constants are applied inside. Single-row radial ball bearings (i = 1),
 * balls up to 25.4 mm. Pure functions, no state. */
#ifndef ACBB_PHYS_LIFE_H
#define ACBB_PHYS_LIFE_H

#include <stdbool.h>
#include "acbb/life.h"

/* ISO 281 Table 2 f_c (single-row deep-groove and angular-contact ball
 * bearings) at gamma = D_w cos(alpha) / D_pw, linearly interpolated. */
double acbb_iso_fc(double gamma);
/* ISO 76 Table 1 f_0 for radial ball bearings at gamma. */
double acbb_iso_f0(double gamma);
/* Factor <= 1 on f_c for grooves wider than Table 2's basis (r_i = 0.52,
 * r_e = 0.53 D_w; ISO 281 6.1.1: "a correspondingly reduced value of f_c"),
 * from the Lundberg-Palmgren conformity terms the f_c values come from
 * (ISO/TS 16281 eqs. 19-20; Harris & Kotzalas, Essential Concepts 3.3). */
double acbb_iso_fc_conformity(double gamma, double fi, double fo);
/* Basic dynamic radial rating C_r, N (ISO 281 6.1.1, b_m = 1.3) with the
 * conformity reduction; fi, fo = groove radius / D_w. */
double acbb_iso_C(double Dw, int Z, double alpha, double dpw, double fi, double fo);
/* Basic static radial rating, N, by ISO 76's definition (clause 3): the radial
 * load whose most loaded contact, Q_max = 5 F_r / (Z cos alpha), reaches
 * 4200 MPa at the centre on whichever raceway gets there first (Hertz
 * with the real groove radii fi, fo = r / D_w and the effective modulus
 * E_eff, Pa). Table 1's f_0 Z D_w^2 cos(alpha) where the grooves and the
 * steel are the table's (acbb_iso_table_basis), the stress elsewhere. */
double acbb_iso_C0(double Dw, int Z, double alpha, double dpw, double fi, double fo,
                   double E_eff);
/* The two bases: Table 1 (ISO 76 6.1) and the 4200 MPa stress (0 if the
 * Hertz solve fails). */
double acbb_iso_C0_table(double Dw, int Z, double alpha, double dpw);
double acbb_iso_C0_stress(double Dw, int Z, double alpha, double dpw, double fi, double fo,
                          double E_eff);
/* Grooves 0.52 / 0.53 D_w (to the 1 um presets are written in) and steel
 * on steel (207 GPa, 0.3): Table 1's basis. */
bool acbb_iso_table_basis(double Dw, double fi, double fo, double E_eff);
/* Ball load, N, at which a contact at the nominal angle alpha first reaches
 * the centre stress p, Pa, on either raceway (which one into *race if not
 * NULL); 0 if the Hertz solve fails. */
double acbb_iso_Q_at_stress(double p, double Dw, double dpw, double alpha, double fi, double fo,
                            double E_eff, acbb_life_race *race);
/* Raceway ratings Q_ci, Q_ce, N, from C_r (ISO/TS 16281 eqs. 19-20). */
void acbb_iso_raceway_ratings(double C, int Z, double alpha, double gamma, double fi, double fo,
                              double *Qci, double *Qce);
/* (1/Z sum Q_j^p)^(1/p): p = 3 for the rotating ring, 10/3 for the
 * stationary one (ISO/TS 16281 eqs. 25-28). */
double acbb_iso_equiv_load(const double *Q, int Z, double p);
/* L_10r, 10^6 revolutions (ISO/TS 16281 eq. 29); +inf when unloaded. */
double acbb_iso_L10r(double Qci, double Qei, double Qce, double Qee);
/* a_1 for reliability R in % (90..99.95), ISO 281 9.2 (Table 12's formula). */
double acbb_iso_a1(double reliability_pct);
/* Rated viscosity nu_1, m^2/s, at n rpm and pitch diameter dpw (ISO 281
 * 9.3.3, eqs. for n < 1000 and n >= 1000 min^-1); +inf at n <= 0. */
double acbb_iso_nu1(double n_rpm, double dpw);
/* a_ISO for radial ball bearings (ISO 281 9.3.2, eqs. 31-33), kappa held to
 * 0.1..4, at most 50. ISO 281 counts kappa > 4 as 4 but does not define
 * a_ISO below 0.1: there the value is a_ISO(0.1), which the caller must
 * report (acbb_iso_kappa_clamped). */
double acbb_iso_a_iso(double kappa, double ec_Cu_P);
/* kappa below ISO 281's range (0.1): a_ISO was taken at 0.1. */
bool acbb_iso_kappa_clamped(double kappa);
/* Fatigue load limit C_u of a ball bearing, N (ISO 281 Annex B.3.2.2):
 * C0 / 22, times (100 / D_pw mm)^0.5 above 100 mm; on C0's basis. */
double acbb_iso_Cu(double C0, double dpw);
/* Static safety of one contact (ISO 76 / ISO/TS 16281: 4200 MPa). */
double acbb_iso_s0(double pmax);
/* Angle left between the contact ellipse's end and the shoulder edge, rad
 * (< 0: the ellipse is truncated): contact at alpha on a groove of radius
 * r, major semi-axis a along the groove, shoulder h above the groove
 * bottom (Harris & Kotzalas, Essential Concepts 6.8 "truncation"). */
double acbb_edge_margin(double alpha, double a, double r, double h);

#endif
