/* Tests for src/physics/lubrication.c against MODEL.md section 5 values and hand
 * calculations of the Walther, Roelands, Hamrock-Dowson, Gupta,
 * Zhou-Hoeprich and Eyring formulas. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "lubrication.h"
#include "tap.h"

/* The 7008C lubricant of MODEL.md section 10, built by hand. */
static void make_scene(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    s->oil_density = 876.0;
    s->oil_nu40 = 30e-6;
    s->oil_nu100 = 5.3e-6;
    s->oil_eta_const = 0.2;
    s->oil_alpha_pv = 2.0e-8;
    s->oil_k = 0.13;
    s->oil_cp = 1950.0;
    s->air_eta = 2e-5;
    s->air_density = 1.128;
    s->air_cp = 1007.0;
    s->q_air = 1e-3;
    s->q_oil = 0.4e-6 / 3600.0;
    s->lambda_lim = 0.07;
    s->tau_eyring = 5e6;
    s->roughness_race = 0.34e-6;
    s->roughness_ball = 0.10e-6;
    s->ehl_film = true;
    s->visc = ACBB_VISC_ROELANDS;
    s->traction = ACBB_TRACTION_EYRING_CAP;
}

/* Walther with MODEL.md's rounded constants A_W = 9.3936, B_W = 3.6948. */
static double nu_model(double T_C)
{
    double y = 9.3936 - 3.6948 * log10(T_C + 273.15);
    return (pow(10.0, pow(10.0, y)) - 0.7) * 1e-6;
}

static void test_walther(const acbb_scene *s)
{
    acbb_oil_state o;
    acbb_oil_at(s, 40.0, &o);
    is_close(o.nu, 30e-6, 1e-12, 0, "Walther reproduces nu40");
    is_close(o.rho, 876.0 * (1.0 - 6.5e-4 * 20.0), 1e-14, 0,
             "rho(40 C) = 876 [1 - 6.5e-4 (40 - 20)]");
    is_close(o.eta0, o.rho * o.nu, 1e-14, 0, "eta0 = rho nu");
    is_close(o.eta0, 0.0259, 2e-3, 0, "eta0(40 C) = 0.0259 Pa s (MODEL 5)");
    ok(o.T_C == 40.0, "state keeps its temperature");
    acbb_oil_at(s, 100.0, &o);
    is_close(o.nu, 5.3e-6, 1e-12, 0, "Walther reproduces nu100");

    acbb_oil_at(s, 26.0, &o);
    is_close(o.eta0, 0.0497, 2e-3, 0, "eta0(26 C) = 0.0497 Pa s (MODEL 5)");
    is_close(o.nu, nu_model(26.0), 2e-3, 0, "nu(26 C) matches A_W = 9.3936, B_W = 3.6948");
    acbb_oil_at(s, 60.0, &o);
    is_close(o.eta0, 0.0124, 2e-3, 0, "eta0(60 C) = 0.0124 Pa s (MODEL 5)");
    is_close(o.nu, nu_model(60.0), 2e-3, 0, "nu(60 C) matches MODEL's Walther constants");

    /* beta_T against the analytic derivative of ln(rho nu):
     * dnu/dT = -(nu + 0.7) ln10 10^y B / T (mm^2/s), y = A - B log10 T;
     * dln(rho)/dT = -6.5e-4 / [1 - 6.5e-4 (T - 20)]. A, B from the two
     * reference points. */
    double y1 = log10(log10(30.7)), y2 = log10(log10(6.0));
    double B = (y1 - y2) / (log10(373.15) - log10(313.15));
    double A = y1 + B * log10(313.15);
    is_close(A, 9.3936, 1e-4, 0, "A_W = 9.3936 (MODEL 5)");
    is_close(B, 3.6948, 1e-4, 0, "B_W = 3.6948 (MODEL 5)");
    double T_C = 55.0, T = T_C + 273.15, y = A - B * log10(T);
    double nu_mm = pow(10.0, pow(10.0, y)) - 0.7;
    double dnu = -(nu_mm + 0.7) * log(10.0) * pow(10.0, y) * B / T;
    double beta = -(dnu / nu_mm - 6.5e-4 / (1.0 - 6.5e-4 * (T_C - 20.0)));
    acbb_oil_at(s, T_C, &o);
    is_close(o.beta_T, beta, 1e-4, 0, "beta_T = -dln(eta)/dT (analytic)");
    ok(o.beta_T > 0.02 && o.beta_T < 0.06, "beta_T of a mineral oil is 0.02..0.06 1/K");

    acbb_scene c = *s;
    c.visc = ACBB_VISC_CONST;
    acbb_oil_at(&c, 80.0, &o);
    ok(o.eta0 == 0.2 && o.beta_T == 0.0, "const model: eta0 = 0.2 Pa s, beta_T = 0");
    is_close(o.nu, 0.2 / (876.0 * (1.0 - 6.5e-4 * 60.0)), 1e-14, 0,
             "const model: nu = eta0 / rho(T)");
    is_close(acbb_viscosity_at_pressure(&c, &o, 1.5e9), 0.2, 0, 0,
             "const model: no pressure dependence");
}

static void test_pressure(acbb_scene *s)
{
    acbb_oil_state o;
    acbb_oil_at(s, 40.0, &o);
    double eta0 = o.eta0;
    is_close(acbb_viscosity_at_pressure(s, &o, 0.0), eta0, 1e-15, 0,
             "Roelands at p = 0 is eta0");

    double lnv = log(eta0) + 9.67, Z = 2e-8 / (5.1e-9 * lnv), p = 1e9;
    double want = eta0 * exp(lnv * (pow(1.0 + p / 1.96e8, Z) - 1.0));
    is_close(acbb_viscosity_at_pressure(s, &o, p), want, 1e-12, 0,
             "Roelands at 1 GPa by hand");
    /* Local pressure-viscosity coefficient at p = 0: lnv Z / p_R. */
    double dp = 1e4;
    double slope = log(acbb_viscosity_at_pressure(s, &o, dp) / eta0) / dp;
    is_close(slope, 2e-8 / (5.1e-9 * 1.96e8), 1e-4, 0,
             "Roelands: d ln(eta)/dp at 0 = alpha / (5.1e-9 p_R)");

    int mono = 1;
    double prev = eta0;
    for (double q = 1e8; q <= 3e9; q += 1e8) {
        double v = acbb_viscosity_at_pressure(s, &o, q);
        mono = mono && v > prev;
        prev = v;
    }
    ok(mono, "Roelands increases with pressure up to 3 GPa");
    ok(acbb_viscosity_at_pressure(s, &o, 1e9) < eta0 * exp(2e-8 * 1e9),
       "Roelands below Barus at 1 GPa");

    s->visc = ACBB_VISC_BARUS;
    is_close(acbb_viscosity_at_pressure(s, &o, 1e9), eta0 * exp(2e-8 * 1e9), 1e-14, 0,
             "Barus = eta0 exp(alpha p)");
    is_close(acbb_viscosity_at_pressure(s, &o, -5e6), eta0, 1e-15, 0,
             "negative pressure treated as 0");
    s->visc = ACBB_VISC_ROELANDS;
}

/* Hamrock-Dowson 1977 by hand (MODEL.md 5). */
static double hd_hc(double eta0, double alpha, double u, double Q, double Rx,
                    double k, double Ep)
{
    double U = eta0 * u / (Ep * Rx), G = alpha * Ep, W = Q / (Ep * Rx * Rx);
    return Rx * 2.69 * pow(U, 0.67) * pow(G, 0.53) * pow(W, -0.067) *
           (1.0 - 0.61 * exp(-0.73 * k));
}

static double hd_hmin(double eta0, double alpha, double u, double Q, double Rx,
                      double k, double Ep)
{
    double U = eta0 * u / (Ep * Rx), G = alpha * Ep, W = Q / (Ep * Rx * Rx);
    return Rx * 3.63 * pow(U, 0.68) * pow(G, 0.49) * pow(W, -0.073) *
           (1.0 - exp(-0.68 * k));
}

static void test_film(acbb_scene *s)
{
    const double Rx = 2.8144e-3, k = 5.8415, Ep = 207e9 / 0.91, Q = 100.0;
    const double pmax = 1.2e9, u = 10.0;
    acbb_oil_state o;
    acbb_film f, f2;

    acbb_oil_at(s, 40.0, &o);
    /* Isothermal case: beta_T = 0 switches the thermal factor off. */
    acbb_oil_state iso = o;
    iso.beta_T = 0.0;
    acbb_film_compute(s, &iso, u, Q, Rx, k, Ep, pmax, 0.0, &f);
    double hc = hd_hc(o.eta0, 2e-8, u, Q, Rx, k, Ep);
    is_close(f.hc, hc, 1e-12, 0, "hc by hand (Hamrock-Dowson 1977)");
    is_close(f.hmin, hd_hmin(o.eta0, 2e-8, u, Q, Rx, k, Ep), 1e-12, 0,
             "hmin by hand (Hamrock-Dowson 1977)");
    ok(f.phi_T == 1.0, "phi_T = 1 without temperature-viscosity coupling");
    ok(hc > 0.1e-6 && hc < 1e-6, "hc(10 m/s, 40 C) = %.3g m is sub-micron", hc);
    double sigma = sqrt(0.34e-6 * 0.34e-6 + 0.10e-6 * 0.10e-6);
    is_close(sigma, 0.354e-6, 2e-3, 0, "sigma = 0.354 um (MODEL 5)");
    is_close(f.lambda, f.hc / sigma, 1e-14, 0, "lambda = hc / sqrt(sr^2 + sb^2)");
    double L = f.lambda;
    double share = fmin(1.0, 1.21 * pow(L, 0.64) / (1.0 + 0.37 * pow(L, 1.26)));
    is_close(f.phi_f, share, 1e-14, 0, "Zhou-Hoeprich share by hand");
    is_close(f.phi_a, 1.0 - f.phi_f, 0, 1e-16, "phi_a = 1 - phi_f");

    acbb_film_compute(s, &iso, 2.0 * u, Q, Rx, k, Ep, pmax, 0.0, &f2);
    is_close(f2.hc / f.hc, pow(2.0, 0.67), 1e-12, 0, "hc scales as u^0.67");
    is_close(f2.hmin / f.hmin, pow(2.0, 0.68), 1e-12, 0, "hmin scales as u^0.68");
    acbb_film_compute(s, &iso, u, 4.0 * Q, Rx, k, Ep, pmax, 0.0, &f2);
    is_close(f2.hc / f.hc, pow(4.0, -0.067), 1e-12, 0, "hc scales as Q^-0.067");

    /* Gupta thermal factor by hand, SRR = 0.5. */
    double srr = 0.5, Lt = o.beta_T * o.eta0 * u * u / 0.13;
    double phiT = (1.0 - 13.2 * (pmax / Ep) * pow(Lt, 0.42)) /
                  (1.0 + 0.213 * (1.0 + 2.23 * pow(srr, 0.83)) * pow(Lt, 0.64));
    acbb_film_compute(s, &o, u, Q, Rx, k, Ep, pmax, srr, &f2);
    ok(phiT > 0.1 && phiT < 1.0, "hand phi_T = %.4f is inside the clamp", phiT);
    is_close(f2.phi_T, phiT, 1e-12, 0, "Gupta phi_T by hand");
    is_close(f2.hc, phiT * hc, 1e-12, 0, "hc carries phi_T");
    is_close(f2.hmin, phiT * f.hmin, 1e-12, 0, "hmin carries phi_T");
    acbb_film_compute(s, &o, u, Q, Rx, k, Ep, pmax, -srr, &f);
    is_close(f.phi_T, f2.phi_T, 0, 0, "phi_T uses |SRR|");

    acbb_film_compute(s, &o, u, Q, Rx, k, Ep, pmax, 2.0, &f);
    acbb_film_compute(s, &o, u, Q, Rx, k, Ep, pmax, 7.0, &f2);
    is_close(f2.phi_T, f.phi_T, 0, 0, "SRR clamped at 2 in phi_T");

    int in_range = 1;
    for (double v = 1e-3; v < 2e3; v *= 3.0) {
        acbb_film_compute(s, &o, v, Q, Rx, k, Ep, pmax, 1.0, &f);
        in_range = in_range && f.phi_T >= 0.1 && f.phi_T <= 1.0;
    }
    ok(in_range, "phi_T within [0.1, 1] for u in 1e-3..2e3 m/s");
    acbb_film_compute(s, &o, 2e3, Q, Rx, k, Ep, 3e9, 2.0, &f);
    ok(f.phi_T == 0.1, "phi_T clamped at 0.1 under extreme shear heating");
    acbb_film_compute(s, &o, 1e-3, Q, Rx, k, Ep, pmax, 1.0, &f);
    ok(f.phi_T > 0.999, "phi_T -> 1 at very low speed (%.6f)", f.phi_T);
}

static void test_share_and_guards(acbb_scene *s)
{
    const double Rx = 2.8144e-3, k = 5.8415, Ep = 207e9 / 0.91, Q = 100.0;
    acbb_oil_state o;
    acbb_film f;
    acbb_scene r = *s;

    acbb_oil_at(s, 40.0, &o);
    r.roughness_race = 1e-3;
    r.roughness_ball = 0.0;
    acbb_film_compute(&r, &o, 10.0, Q, Rx, k, Ep, 1e9, 0.0, &f);
    ok(f.lambda < 1e-3 && f.phi_f < 0.01, "lambda -> 0: phi_f -> 0 (%.3g)", f.phi_f);
    is_close(f.phi_a, 1.0 - f.phi_f, 0, 1e-16, "lambda -> 0: phi_a = 1 - phi_f");
    r.roughness_race = 1e-8;
    acbb_film_compute(&r, &o, 10.0, Q, Rx, k, Ep, 1e9, 0.0, &f);
    ok(f.lambda > 10.0 && f.phi_f == 1.0 && f.phi_a == 0.0,
       "large lambda (%.1f): full film, phi_f = 1", f.lambda);

    /* Share is monotone in lambda, reaching 1 and staying there. */
    int mono = 1;
    double prev = -1.0;
    for (double sg = 1e-4; sg > 1e-9; sg /= 1.3) {
        r.roughness_race = sg;
        acbb_film_compute(&r, &o, 10.0, Q, Rx, k, Ep, 1e9, 0.0, &f);
        mono = mono && f.phi_f >= prev && f.phi_f <= 1.0;
        prev = f.phi_f;
    }
    ok(mono && prev == 1.0, "phi_f non-decreasing in lambda and ends at 1");

    acbb_film_compute(s, &o, 0.0, Q, Rx, k, Ep, 1e9, 0.0, &f);
    ok(f.hc == 0 && f.hmin == 0 && f.lambda == 0 && f.phi_f == 0 && f.phi_a == 1 &&
       f.phi_T == 1, "u = 0: boundary lubrication, no film");
    acbb_film_compute(s, &o, 0.9e-6, Q, Rx, k, Ep, 1e9, 0.0, &f);
    ok(f.hc == 0 && f.phi_a == 1, "u < 1e-6 m/s: no film");
    r = *s;
    r.ehl_film = false;
    acbb_film_compute(&r, &o, 10.0, Q, Rx, k, Ep, 1e9, 0.0, &f);
    ok(f.hc == 0 && f.hmin == 0 && f.lambda == 0 && f.phi_f == 0 && f.phi_a == 1 &&
       f.phi_T == 1, "ehl_film off: boundary lubrication");
}

static void test_tau(acbb_scene *s)
{
    int capped = 1;
    for (double p = 1e7; p < 4e9; p *= 3.0)
        for (double eta = 1e-3; eta < 1e9; eta *= 10.0)
            for (double du = 1e-4; du < 100.0; du *= 10.0) {
                double t = acbb_tau_lubricant(s, eta, du, 1e-7, p);
                capped = capped && t >= 0.0 && t <= 0.07 * p * (1 + 1e-15);
            }
    ok(capped, "Eyring: 0 <= tau <= Lambda_L p everywhere on the grid");

    double eta = 0.01, du = 1e-6, H = 1e-6;
    is_close(acbb_tau_lubricant(s, eta, du, H, 1e9), eta * du / H, 1e-9, 0,
             "Eyring: tau = eta du/H for a tiny shear rate");
    is_close(acbb_tau_lubricant(s, eta, -du, H, 1e9), eta * du / H, 1e-9, 0,
             "tau does not depend on the sign of du");
    double t = acbb_tau_lubricant(s, 100.0, 1.0, 1e-7, 1e9);
    is_close(t, 5e6 * asinh(100.0 * 1e7 / 5e6), 1e-14, 0,
             "Eyring below the cap: tau_E asinh(eta gdot / tau_E)");
    is_close(acbb_tau_lubricant(s, 1e6, 1.0, 1e-7, 1e9), 0.07e9, 1e-14, 0,
             "Eyring at the cap: Lambda_L p");
    is_close(acbb_tau_lubricant(s, 0.01, 1.0, 0.0, 1e9),
             acbb_tau_lubricant(s, 0.01, 1.0, 1e-9, 1e9), 0, 0,
             "film H floored at 1e-9 m");
    is_close(acbb_tau_lubricant(s, 0.01, 1.0, 0.0, 1e9), 5e6 * asinh(1e7 / 5e6),
             1e-14, 0, "H = 0 uses gdot = du / 1e-9 m");
    ok(acbb_tau_lubricant(s, 0.01, 1.0, 1e-7, 0.0) == 0.0, "tau = 0 at zero pressure");
    ok(acbb_tau_lubricant(s, 0.01, 0.0, 1e-7, 1e9) == 0.0, "tau = 0 without sliding");

    s->traction = ACBB_TRACTION_BAIR_WINER;
    double tl = 0.07 * 1e9, ng = 0.05 * 2.0 / 1e-7;
    is_close(acbb_tau_lubricant(s, 0.05, 2.0, 1e-7, 1e9), tl * (1.0 - exp(-ng / tl)),
             1e-14, 0, "Bair-Winer by hand");
    is_close(acbb_tau_lubricant(s, 0.01, 1e-6, 1e-6, 1e9), 0.01, 1e-9, 0,
             "Bair-Winer: Newtonian at low shear");
    ok(acbb_tau_lubricant(s, 1e9, 10.0, 1e-8, 1e9) <= tl,
       "Bair-Winer never exceeds Lambda_L p");
    s->traction = ACBB_TRACTION_EYRING_CAP;
}

static void test_mixture(const acbb_scene *s)
{
    acbb_oil_state o;
    acbb_mixture m;
    acbb_oil_at(s, 40.0, &o);
    acbb_mixture_at(s, &o, &m);
    double qo = 0.4e-6 / 3600.0, X = qo / (qo + 1e-3);
    double rho = X * o.rho + (1 - X) * 1.128;
    is_close(m.X, X, 1e-14, 0, "X = q_oil / (q_oil + q_air)");
    is_close(m.rho, rho, 1e-14, 0, "rho_eff = X rho_oil + (1-X) rho_air");
    is_close(m.eta, X * o.eta0 + (1 - X) * 2e-5, 1e-14, 0, "eta_eff volume-weighted");
    is_close(m.cp, (X * o.rho * 1950.0 + (1 - X) * 1.128 * 1007.0) / rho, 1e-14, 0,
             "cp_eff mass-weighted");
    is_close(m.rho, 1.128, 1e-4, 0, "default oil-air mist is essentially air");

    acbb_scene e = *s;
    e.q_oil = 1.0;
    e.q_air = 1.0;
    acbb_mixture_at(&e, &o, &m);
    is_close(m.cp, (o.rho * 1950.0 + 1.128 * 1007.0) / (o.rho + 1.128), 1e-14, 0,
             "50/50 by volume: cp weighted by mass");
    e.q_oil = 0.0;
    e.q_air = 0.0;
    acbb_mixture_at(&e, &o, &m);
    ok(m.X == 0.0 && m.rho == 1.128, "no flow at all: pure air");
}

/* acbb_nonneg stands for fmax(x, 0.0) in the contact tables (issue 30):
 * the same bits for signed zeros, NaN, infinities, subnormals and both
 * signs, so the tables it fills are those fmax filled. */
static void test_nonneg(void)
{
    volatile double z = 0.0;
    const double xs[] = { -0.0, 0.0, NAN, -NAN, INFINITY, -INFINITY, 4.9e-324, -4.9e-324,
                          1e-300, -1e-300, 1.5, -1.5, 1e300, -1e300 };
    int same = 1;
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        double x = xs[i] * (1.0 + z); /* through memory: no folding */
        double a = acbb_nonneg(x), b = fmax(x, 0.0);
        same &= memcmp(&a, &b, sizeof a) == 0;
    }
    ok(same, "acbb_nonneg(x) = fmax(x, 0) bit for bit (-0, NaN, inf, subnormal, +-)");
}

int main(void)
{
    acbb_scene s;
    gsl_set_error_handler_off();
    make_scene(&s);
    test_walther(&s);
    test_pressure(&s);
    test_film(&s);
    test_share_and_guards(&s);
    test_tau(&s);
    test_mixture(&s);
    test_nonneg();
    return done_testing();
}
