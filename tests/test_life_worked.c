/* A worked example of the rating life (issue 19, MODEL.md 15), calculated
 * by hand from the standards' formulas and asserted to 4 significant
 * digits (rtol 1e-4) against src/physics/life.c and, on the engine's path,
 * acbb_life_compute (scene keys -> ratings -> L_10r -> hours).
 *
 * Why a hand calculation: no published worked example (a textbook's or a
 * report's printed numbers from stated inputs) of ISO 281 C_r or ISO/TS
 * 16281 L_10r was within reach; docs/ratings.md lists what was searched.
 * Every number below was worked from the formulas quoted with it (30-digit
 * arithmetic, no acbb code), never read back from acbb.
 *
 * The case: a single-row angular-contact ball bearing, i = 1, Z = 18 balls
 * of D_w = 7.938 mm (5/16 in) on D_pw = 54 mm, alpha = 15 deg, grooves
 * r_i = 0.52 D_w = 4.12776 mm, r_e = 0.53 D_w = 4.20714 mm (Table 2's own
 * conformities, so f_c needs no reduction), inner ring rotating at
 * 6000 min^-1 under a fixed outer ring.
 *
 * 1. gamma = D_w cos(alpha) / D_pw = 7.938 * 0.9659258 / 54 = 0.1419911.
 * 2. f_c, ISO 281:2007 Table 2 (single-row radial and angular-contact
 *    ball bearings), between the rows 0.14 -> 58.8 and 0.16 -> 59.6:
 *    58.8 + (0.0019911 / 0.02) * 0.8 = 58.87964.
 * 3. C_r = b_m f_c (i cos alpha)^0.7 Z^(2/3) D_w^1.8 (ISO 281 6.1.1,
 *    b_m = 1.3): cos^0.7 = 0.9760243, 18^(2/3) = 6.868285,
 *    7.938^1.8 = 41.63705 -> C_r = 21 364.73 N.
 * 4. C_0r = f_0 i Z D_w^2 cos(alpha) (ISO 76:2006 6.1.1), f_0 from ISO 76
 *    Table 1 between 0.14 -> 15.4 and 0.15 -> 15.2: 15.4 - 0.19911 * 0.2
 *    = 15.36018 -> C_0r = 15.36018 * 18 * 7.938^2 * 0.9659258 = 16 828.09 N.
 * 5. Raceway ratings (ISO/TS 16281:2008 eqs. 19-20): the split term
 *    q = 1.044 ((1 - gamma)/(1 + gamma))^1.72 [r_i (2 r_e - D_w) /
 *    (r_e (2 r_i - D_w))]^0.41 = 1.044 * 0.6115416 * 1.171671 = 0.7480527,
 *    q^(10/3) = 0.3799916;
 *    Q_ci = C_r / (0.407 Z cos alpha) (1 + q^(10/3))^0.3
 *         = 21 364.73 / 7.076524 * 1.101445 = 3325.445 N,
 *    Q_ce = C_r / (0.389 Z cos alpha) (1 + q^(-10/3))^0.3
 *         = 21 364.73 / 6.763570 * 1.472417 = 4651.171 N.
 * 6. Loads: a combined load that just loads the whole circle, epsilon = 1
 *    (Sjovall): Q(psi) = Q_max [1 - (1 - cos psi) / (2 epsilon)]^1.5
 *    = Q_max |cos(psi/2)|^3, Q_max = 1500 N, balls at psi_j = 20 deg j:
 *    fractions 1, 0.9551122 (+-20), 0.8297695 (+-40), 0.6495191 (+-60),
 *    0.4495333 (+-80), 0.2655844 (+-100), 0.125 (+-120), 0.04000876
 *    (+-140), 0.005236133 (+-160), 0 (180). (It carries F_r = cos(alpha)
 *    sum Q_j cos psi_j = 6641.08 N and F_a = sin(alpha) sum Q_j = 2965.88 N.)
 *    sum f^3 = 4.656419, sum f^(10/3) = 18 * 252 / 1024 = 4.4296875;
 *    Q_ei = 1500 (4.656419 / 18)^(1/3) = 955.7650 N (rotating inner ring,
 *    exponent 3, eq. 25), Q_ee = 1500 (4.4296875 / 18)^0.3 = 984.9664 N
 *    (stationary outer ring, exponent 10/3, eq. 27).
 * 7. L_10r = [(Q_ci/Q_ei)^(-10/3) + (Q_ce/Q_ee)^(-10/3)]^(-9/10) (eq. 29)
 *    = [0.01566768 + 0.005660616]^-0.9 = 31.91093 x 10^6 rev; at
 *    6000 min^-1: 31.91093e6 / (60 * 6000) = 88.64148 h; the reference
 *    load C_r / L_10r^(1/3) = 6735.724 N.
 * 8. ISO 281's definition of C_r (the radial load a bearing carries for
 *    10^6 revolutions, clause 3 "basic dynamic radial load rating") read through
 *    ISO/TS 16281: under F_r = C_r with the half-circle load zone the
 *    rating assumes (epsilon = 0.5: Q_j = Q_max cos^1.5 psi_j, |psi_j| < 90
 *    deg), Q_max = C_r / (cos alpha sum cos^2.5 psi_j) = 5371.319 N
 *    (Stribeck's 4.37 F_r / (Z cos alpha) gives 5369.9), Q_ei = 3021.378 N,
 *    Q_ee = 3155.277 N and L_10r = 0.9993436 x 10^6 rev: the constants
 *    0.407 and 0.389 are J_r/J_1 and J_r/J_2 of that distribution
 *    (0.40681 and 0.38954 from its integrals), so L_10r must be 1 within
 *    their rounding and the 18-ball discretisation (0.5 %). */
#include <math.h>
#include <stdio.h>

#include "acbb/acbb.h"
#include "acbb/tools/life_eval.h"
#include "life.h"
#include "tap.h"

#define DEG (M_PI / 180.0)
#define SIG4 1e-4 /* 4 significant digits */
#define Z 18

static const double Dw = 7.938e-3, Dpw = 54e-3, ALPHA = 15 * DEG, FI = 0.52, FE = 0.53;

/* Step 6's loads (epsilon = 1) or step 8's (epsilon = 0.5, F_r = C_r). */
static void loads(double eps, double Qmax, double *Q)
{
    for (int j = 0; j < Z; j++) {
        double psi = 20.0 * j * DEG, x = 1.0 - (1.0 - cos(psi)) / (2.0 * eps);
        Q[j] = x > 0.0 ? Qmax * pow(x, 1.5) : 0.0;
    }
}

static double L10r_of(const double *Q)
{
    double Qci, Qce, C = acbb_iso_C(Dw, Z, ALPHA, Dpw, FI, FE);
    acbb_iso_raceway_ratings(C, Z, ALPHA, Dw * cos(ALPHA) / Dpw, FI, FE, &Qci, &Qce);
    return acbb_iso_L10r(Qci, acbb_iso_equiv_load(Q, Z, 3.0), Qce,
                         acbb_iso_equiv_load(Q, Z, 10.0 / 3.0));
}

static void formulas(void)
{
    double g = Dw * cos(ALPHA) / Dpw, Q[Z], Qci, Qce;
    is_close(acbb_iso_fc(g), 58.87964, SIG4, 0, "step 2: f_c, ISO 281 Table 2 interpolated");
    is_close(acbb_iso_fc_conformity(g, FI, FE), 1.0, 0, 1e-12,
             "step 2: no reduction at r_i = 0.52, r_e = 0.53 D_w");
    double C = acbb_iso_C(Dw, Z, ALPHA, Dpw, FI, FE);
    is_close(C, 21364.73, SIG4, 0, "step 3: C_r = 21 364.73 N (ISO 281 6.1.1)");
    is_close(acbb_iso_f0(g), 15.36018, SIG4, 0, "step 4: f_0, ISO 76 Table 1 interpolated");
    is_close(acbb_iso_C0_table(Dw, Z, ALPHA, Dpw), 16828.09, SIG4, 0, "step 4: C_0r = 16 828.09 N");
    acbb_iso_raceway_ratings(C, Z, ALPHA, g, FI, FE, &Qci, &Qce);
    is_close(Qci, 3325.445, SIG4, 0, "step 5: Q_ci = 3325.445 N (ISO/TS 16281 eq. 19)");
    is_close(Qce, 4651.171, SIG4, 0, "step 5: Q_ce = 4651.171 N (eq. 20)");
    loads(1.0, 1500.0, Q);
    double Qei = acbb_iso_equiv_load(Q, Z, 3.0), Qee = acbb_iso_equiv_load(Q, Z, 10.0 / 3.0);
    is_close(Qei, 955.7650, SIG4, 0, "step 6: Q_ei = 955.7650 N (exponent 3)");
    is_close(Qee, 984.9664, SIG4, 0, "step 6: Q_ee = 984.9664 N (exponent 10/3)");
    is_close(acbb_iso_L10r(Qci, Qei, Qce, Qee), 31.91093, SIG4, 0,
             "step 7: L_10r = 31.91093 x 10^6 rev (eq. 29)");
    loads(0.5, 5371.319, Q);
    double L = L10r_of(Q);
    is_close(L, 0.9993436, SIG4, 0, "step 8: F_r = C_r, epsilon = 0.5: L_10r = 0.9993436");
    is_close(L, 1.0, 0.005, 0, "step 8: ISO 281's C_r is the load for 10^6 rev (within 0.5 %)");
}

/* The same case on the engine's path: the geometry as preset keys, the
 * step-6 loads as a computed state (both contacts at the nominal angle, as
 * a standing bearing has them), acbb_life_compute as every run calls it. */
static void engine(void)
{
    static acbb_snapshot sn;
    acbb_scene s;
    acbb_error e;
    acbb_life L;
    const char *edits[] = {
        "bearing.ball_diameter_mm=7.938",       "bearing.pitch_diameter_mm=54",
        "bearing.n_balls=18",                   "bearing.contact_angle_deg=15",
        "bearing.inner_groove_radius_mm=4.12776", "bearing.outer_groove_radius_mm=4.20714",
        "operating.inner_speed_rpm=6000",
    };
    double Q[Z];
    acbb_scene_default(&s);
    int applied = acbb_scene_apply_edits(&s, edits, sizeof edits / sizeof *edits, &e) == ACBB_OK;
    ok(applied, "the worked example's geometry is a valid scene%s%s", applied ? "" : ": ",
       applied ? "" : e.msg);
    loads(1.0, 1500.0, Q);
    sn.n_balls = Z;
    sn.n_bearings = 1;
    sn.T_inner_ring = sn.T_outer_ring = 40.0;
    for (int j = 0; j < Z; j++) {
        sn.balls[j].psi = 20.0 * j * DEG;
        sn.balls[j].Qi = sn.balls[j].Qo = Q[j];
        sn.balls[j].alpha_i = sn.balls[j].alpha_o = ALPHA;
    }
    acbb_life_compute(&s, &sn, &L);
    is_close(L.C, 21364.73, SIG4, 0, "engine: life.C_N = 21 364.73 N");
    is_close(L.C0, 16828.09, SIG4, 0, "engine: life.C0_N = 16 828.09 N");
    is_close(L.L10r_Mrev, 31.91093, SIG4, 0, "engine: L_10r = 31.91093 x 10^6 rev");
    is_close(L.L10r_h, 88.64148, SIG4, 0, "engine: life.L10r_h = 88.64148 h at 6000 min^-1");
    is_close(L.P_ref, 6735.724, SIG4, 0, "engine: reference load C_r / L_10r^(1/3) = 6735.724 N");
}

int main(void)
{
    formulas();
    engine();
    return done_testing();
}
