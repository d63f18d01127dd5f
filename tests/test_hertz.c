/* Tests for src/physics/hertz.c against MODEL.md section 2 reference values,
 * hand calculations and an independent AGM evaluation of K and E. */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include <gsl/gsl_errno.h>

#include "hertz.h"
#include "tap.h"

/* Independent complete elliptic integrals by the arithmetic-geometric mean
 * (Abramowitz & Stegun 17.6), parameter m = e^2. */
static void agm_KE(double m, double *K, double *E)
{
    double a = 1.0, b = sqrt(1.0 - m), s = 0.5 * m, p = 0.5;
    for (int it = 0; it < 40 && fabs(a - b) > 4e-16 * a; it++) {
        double c = 0.5 * (a - b);
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
        p *= 2.0;
        s += p * c * c;
    }
    *K = M_PI / (2.0 * a);
    *E = *K * (1.0 - s);
}

/* F(kappa) straight from MODEL.md section 2 with the AGM integrals. */
static double ellipticity_F_agm(double kappa)
{
    double K, E, k2 = kappa * kappa;
    agm_KE(1.0 - 1.0 / k2, &K, &E);
    return ((k2 + 1.0) * E - 2.0 * K) / ((k2 - 1.0) * E);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const double D = 6.35e-3, DM = 54e-3, F_GROOVE = 3.43 / 6.35;

static void test_modulus_and_radii(void)
{
    double Ep = acbb_effective_modulus(207e9, 0.3, 207e9, 0.3);
    is_close(Ep, 207e9 / 0.91, 1e-13, 0, "E' of equal steels = E/(1-nu^2)");
    is_close(Ep, 227.5e9, 2e-4, 0, "E' = 227.5 GPa (MODEL 2)");
    is_close(acbb_effective_modulus(207e9, 0.3, 143e9, 0.27),
             2.0 / (0.91 / 207e9 + (1 - 0.27 * 0.27) / 143e9), 1e-13, 0,
             "E' of steel on cast iron");

    double Rx, Ry, alpha = 15.0 * M_PI / 180.0;
    acbb_contact_radii(D, DM, alpha, F_GROOVE, 1, &Rx, &Ry);
    is_close(Rx, 2.8144e-3, 1e-4, 0, "inner Rx = 2.8144 mm");
    is_close(Ry, 42.707e-3, 1e-4, 0, "inner Ry = 42.707 mm");
    acbb_contact_radii(D, DM, alpha, F_GROOVE, 0, &Rx, &Ry);
    is_close(Rx, 3.5356e-3, 1e-4, 0, "outer Rx = 3.5356 mm");
    is_close(Ry, 3.43e-3 * 6.35e-3 / (2 * 3.43e-3 - 6.35e-3), 1e-13, 0,
             "outer Ry = lambda D / (2 lambda - D)");
}

static void test_reference_7008c(void)
{
    double Ep = 207e9 / 0.91, alpha = 15.0 * M_PI / 180.0, Rx, Ry;
    acbb_hertz_const c;

    acbb_contact_radii(D, DM, alpha, F_GROOVE, 1, &Rx, &Ry);
    ok(acbb_hertz_const_compute(Rx, Ry, Ep, ACBB_HERTZ_EXACT, &c) == ACBB_OK,
       "inner EXACT returns OK");
    is_close(c.kappa, 5.8415, 1e-4, 0, "inner kappa = 5.8415");
    is_close(c.K, 3.1673, 1e-4, 0, "inner K = 3.1673");
    is_close(c.E, 1.03919, 1e-4, 0, "inner E = 1.03919");
    is_close(c.Kc, 1.8287e10, 1e-4, 0, "inner Kc = 1.8287e10 N/m^1.5");
    is_close(c.R, 1.0 / (1.0 / Rx + 1.0 / Ry), 1e-14, 0, "R = 1/sum rho");
    is_close(c.F_rho, (1.0 / Rx - 1.0 / Ry) * c.R, 1e-14, 0, "F(rho)");
    is_close(ellipticity_F_agm(c.kappa), c.F_rho, 1e-11, 0,
             "inner kappa solves the ellipticity equation (AGM)");
    double K, E;
    agm_KE(1.0 - 1.0 / (c.kappa * c.kappa), &K, &E);
    is_close(c.K, K, 1e-13, 0, "inner K equals AGM K(kappa)");
    is_close(c.E, E, 1e-13, 0, "inner E equals AGM E(kappa)");

    acbb_contact_radii(D, DM, alpha, F_GROOVE, 0, &Rx, &Ry);
    ok(acbb_hertz_const_compute(Rx, Ry, Ep, ACBB_HERTZ_EXACT, &c) == ACBB_OK,
       "outer EXACT returns OK");
    is_close(c.kappa, 5.0666, 1e-4, 0, "outer kappa = 5.0666");
    is_close(c.Kc, 1.8954e10, 1e-4, 0, "outer Kc = 1.8954e10 N/m^1.5");
}

/* Reference (Ry/Rx, kappa, K, E) from an independent bisection on the AGM
 * form in double precision (Python), 1e-15 bracket. */
static void test_reference_table(void)
{
    static const double tab[][4] = {
        { 1.5, 1.3101029621127505, 1.7897650950422856, 1.3911375419208458 },
        { 10.0, 4.499447303155419, 2.9142026886672565, 1.0598843439393566 },
        { 100.0, 18.187103004388916, 4.289495451406558, 1.00573002019379 },
    };
    for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++) {
        acbb_hertz_const c;
        char name[96];
        acbb_hertz_const_compute(1e-3, tab[i][0] * 1e-3, 2e11, ACBB_HERTZ_EXACT, &c);
        snprintf(name, sizeof name, "Ry/Rx = %g: kappa", tab[i][0]);
        is_close(c.kappa, tab[i][1], 1e-10, 0, name);
        snprintf(name, sizeof name, "Ry/Rx = %g: K", tab[i][0]);
        is_close(c.K, tab[i][2], 1e-10, 0, name);
        snprintf(name, sizeof name, "Ry/Rx = %g: E", tab[i][0]);
        is_close(c.E, tab[i][3], 1e-10, 0, name);
    }
    /* Either side of the series switch at m = 1e-2 (kappa ~ 1.005). */
    for (double r = 1.010; r < 1.018; r += 0.001) {
        acbb_hertz_const c;
        char name[96];
        acbb_hertz_const_compute(1e-3, r * 1e-3, 2e11, ACBB_HERTZ_EXACT, &c);
        snprintf(name, sizeof name, "Ry/Rx = %.3f: kappa solves the equation", r);
        is_close(ellipticity_F_agm(c.kappa), c.F_rho, 1e-8, 0, name);
    }
}

/* Q = 500 N on the inner contact, recomputed from the formulas of MODEL.md
 * section 2 with the tabulated kappa, K, E. */
static void test_contact_from_load(void)
{
    double Ep = 207e9 / 0.91, alpha = 15.0 * M_PI / 180.0, Rx, Ry;
    acbb_hertz_const c;
    acbb_hertz_contact h, h2;

    acbb_contact_radii(D, DM, alpha, F_GROOVE, 1, &Rx, &Ry);
    acbb_hertz_const_compute(Rx, Ry, Ep, ACBB_HERTZ_EXACT, &c);

    double Q = 500.0, R = 1.0 / (1.0 / Rx + 1.0 / Ry);
    double k = 5.8415, K = 3.1673, E = 1.03919;
    double a = pow(6.0 * k * k * E * Q * R / (M_PI * Ep), 1.0 / 3.0);
    double b = pow(6.0 * E * Q * R / (M_PI * k * Ep), 1.0 / 3.0);
    double delta = K * pow(4.5 / (E * R) * pow(Q / (M_PI * k * Ep), 2.0), 1.0 / 3.0);
    double pmax = 1.5 * Q / (M_PI * a * b);

    acbb_hertz_from_load(&c, Q, &h);
    is_close(h.Q, Q, 0, 0, "from_load keeps Q");
    is_close(h.a, a, 1e-4, 0, "a(500 N) by hand");
    is_close(h.b, b, 1e-4, 0, "b(500 N) by hand");
    is_close(h.delta, delta, 1e-4, 0, "delta(500 N) by hand");
    is_close(h.pmax, pmax, 1e-4, 0, "pmax(500 N) by hand");
    is_close(h.pmax, 3.0 * Q / (2.0 * M_PI * h.a * h.b), 1e-14, 0,
             "pmax = 3Q/(2 pi a b)");
    is_close(h.a / h.b, c.kappa, 1e-13, 0, "a/b = kappa");
    is_close(Q, c.Kc * pow(h.delta, 1.5), 1e-12, 0, "Q = Kc delta^1.5");

    acbb_hertz_from_deflection(&c, h.delta, &h2);
    is_close(h2.Q, Q, 1e-12, 0, "Q -> delta -> Q round trip");
    is_close(h2.a, h.a, 1e-12, 0, "round trip keeps a");
    is_close(h2.delta, h.delta, 0, 0, "from_deflection keeps delta exactly");

    acbb_hertz_from_load(&c, 4000.0, &h2);
    is_close(h2.a / h.a, cbrt(8.0), 1e-12, 0, "a scales as Q^(1/3)");
    is_close(h2.delta / h.delta, 4.0, 1e-12, 0, "delta scales as Q^(2/3)");

    acbb_hertz_from_load(&c, 0.0, &h2);
    ok(h2.Q == 0 && h2.a == 0 && h2.b == 0 && h2.delta == 0 && h2.pmax == 0,
       "Q = 0 gives an empty contact");
    acbb_hertz_from_load(&c, -3.0, &h2);
    ok(h2.Q == 0 && h2.a == 0 && h2.pmax == 0, "Q < 0 gives an empty contact");
    acbb_hertz_from_deflection(&c, -1e-6, &h2);
    ok(h2.Q == 0 && h2.a == 0 && h2.delta == 0, "delta < 0 gives an empty contact");
    acbb_hertz_from_deflection(&c, 0.0, &h2);
    ok(h2.Q == 0 && h2.b == 0 && h2.pmax == 0, "delta = 0 gives an empty contact");
}

/* Two spheres of radii r1, r2 (Johnson, Contact Mechanics, eq. 4.22-4.25):
 * 1/Rs = 1/r1 + 1/r2, 1/Es = sum (1-nu^2)/E = 2/E', a = (3 Q Rs / (4 Es))^(1/3),
 * delta = a^2 / Rs, p0 = 3Q/(2 pi a^2). Here Rx = Ry = Rs. */
static void test_circle(void)
{
    double r1 = 3.175e-3, r2 = 10e-3, Rs = 1.0 / (1.0 / r1 + 1.0 / r2);
    double Ep = 227.5e9, Es = 0.5 * Ep, Q = 200.0;
    acbb_hertz_const c;
    acbb_hertz_contact h;

    ok(acbb_hertz_const_compute(Rs, Rs, Ep, ACBB_HERTZ_EXACT, &c) == ACBB_OK,
       "circle EXACT returns OK");
    ok(c.kappa == 1.0, "circle: kappa = 1 exactly (got %.17g)", c.kappa);
    is_close(c.K, M_PI_2, 1e-15, 0, "circle: K = pi/2");
    is_close(c.E, M_PI_2, 1e-15, 0, "circle: E = pi/2");
    ok(c.F_rho == 0.0, "circle: F(rho) = 0");

    double a = cbrt(3.0 * Q * Rs / (4.0 * Es));
    acbb_hertz_from_load(&c, Q, &h);
    is_close(h.a, a, 1e-13, 0, "circle: a = (3QRs/(4Es))^(1/3)");
    is_close(h.b, a, 1e-13, 0, "circle: b = a");
    is_close(h.delta, a * a / Rs, 1e-13, 0, "circle: delta = a^2/Rs");
    is_close(h.pmax, 3.0 * Q / (2.0 * M_PI * a * a), 1e-13, 0,
             "circle: p0 = 3Q/(2 pi a^2)");
    is_close(c.Kc, 4.0 / 3.0 * Es * sqrt(Rs), 1e-13, 0, "circle: Kc = 4/3 Es sqrt(Rs)");

    /* Nearly circular: continuous with the circle, kappa just above 1. */
    acbb_hertz_const cn;
    ok(acbb_hertz_const_compute(Rs, Rs * (1.0 + 1e-7), Ep, ACBB_HERTZ_EXACT, &cn) ==
       ACBB_OK, "near-circle EXACT returns OK");
    /* F = 3m/8 to first order and kappa = 1 + m/2: kappa - 1 = 4F/3. */
    is_close(cn.kappa - 1.0, 4.0 / 3.0 * cn.F_rho, 1e-5, 0,
             "near-circle: kappa - 1 = 4F(rho)/3");
    is_close(cn.Kc, c.Kc, 1e-7, 0, "near-circle: Kc continuous with the circle");
}

static void test_fits(void)
{
    double worst_kappa = 0, worst_kc = 0, worst_K = 0, worst_E = 0;
    double mid_kappa = 0, mid_kc = 0;
    for (int i = 0; i <= 40; i++) {
        double r = pow(100.0, i / 40.0); /* 1 .. 100 */
        acbb_hertz_const ex, bh, hb;
        acbb_hertz_const_compute(2e-3, 2e-3 * r, 2e11, ACBB_HERTZ_EXACT, &ex);
        acbb_hertz_const_compute(2e-3, 2e-3 * r, 2e11, ACBB_HERTZ_BH77, &bh);
        acbb_hertz_const_compute(2e-3, 2e-3 * r, 2e11, ACBB_HERTZ_HB83, &hb);
        if (i == 20) {
            is_close(bh.kappa, 1.0339 * pow(r, 0.6360), 1e-14, 0, "BH77 kappa fit");
            is_close(bh.E, 1.0003 + 0.5968 / r, 1e-14, 0, "BH77 E fit");
            is_close(bh.K, 1.5277 + 0.6023 * log(r), 1e-14, 0, "BH77 K fit");
            is_close(hb.kappa, pow(r, 2.0 / M_PI), 1e-14, 0, "HB83 kappa fit");
            is_close(hb.E, 1.0 + (M_PI / 2 - 1.0) / r, 1e-14, 0, "HB83 E fit");
            is_close(hb.K, M_PI / 2 + (M_PI / 2 - 1.0) * log(r), 1e-14, 0,
                     "HB83 K fit");
            is_close(bh.Kc, M_PI * bh.kappa * 2e11 *
                     sqrt(2.0 * bh.E * bh.R / (9.0 * pow(bh.K, 3))), 1e-14, 0,
                     "BH77 Kc from the fitted kappa, K, E");
        }
        double ek = fabs(bh.kappa / ex.kappa - 1), ec = fabs(bh.Kc / ex.Kc - 1);
        worst_kappa = fmax(worst_kappa, ek);
        worst_kc = fmax(worst_kc, ec);
        worst_K = fmax(worst_K, fabs(bh.K / ex.K - 1));
        worst_E = fmax(worst_E, fabs(bh.E / ex.E - 1));
        if (r >= 2.5 && r <= 45.0) {
            mid_kappa = fmax(mid_kappa, ek);
            mid_kc = fmax(mid_kc, ec);
        }
    }
    ok(worst_K < 0.03, "BH77 K within 3%% on Ry/Rx in [1,100] (worst %.4f)", worst_K);
    ok(worst_E < 0.03, "BH77 E within 3%% on Ry/Rx in [1,100] (worst %.4f)", worst_E);
    ok(mid_kappa < 0.03, "BH77 kappa within 3%% on Ry/Rx in [2.5,45] (worst %.4f)",
       mid_kappa);
    ok(mid_kc < 0.03, "BH77 Kc within 3%% on Ry/Rx in [2.5,45] (worst %.4f)", mid_kc);
    /* The 3 % claim does not hold at the ends of [1,100]: kappa is 3.4 % off
     * at 1 and 6.3 % at 100, Kc 8.7 % at 1 (measured; see the report). */
    ok(worst_kappa > 0.03 && worst_kappa < 0.065,
       "BH77 kappa error on [1,100] is 3..6.5%% (worst %.4f)", worst_kappa);
    ok(worst_kc < 0.09, "BH77 Kc within 9%% on [1,100] (worst %.4f)", worst_kc);

    acbb_hertz_const a, b;
    acbb_hertz_const_compute(2e-3, 30e-3, 2e11, ACBB_HERTZ_EXACT, &a);
    acbb_hertz_const_compute(30e-3, 2e-3, 2e11, ACBB_HERTZ_EXACT, &b);
    is_close(b.kappa, a.kappa, 1e-14, 0, "swapped radii give the same kappa");
    is_close(b.Kc, a.Kc, 1e-14, 0, "swapped radii give the same Kc");
}

static void test_invalid(void)
{
    acbb_hertz_const c;
    ok(acbb_hertz_const_compute(0.0, 1e-3, 2e11, ACBB_HERTZ_EXACT, &c) == ACBB_EINVAL,
       "Rx = 0 is EINVAL");
    ok(c.Kc == 0.0, "EINVAL leaves a zeroed result");
    ok(acbb_hertz_const_compute(1e-3, 1e-3, -1.0, ACBB_HERTZ_BH77, &c) == ACBB_EINVAL,
       "E' < 0 is EINVAL");
    ok(acbb_hertz_const_compute(1e-3, NAN, 2e11, ACBB_HERTZ_EXACT, &c) == ACBB_EINVAL,
       "NaN radius is EINVAL");
    ok(acbb_hertz_const_compute(1e-3, 1e3, 2e11, ACBB_HERTZ_EXACT, &c) == ACBB_EINVAL,
       "Ry/Rx = 1e6 (kappa > 200) is EINVAL");
}

static void test_cost(void)
{
    enum { N = 20000 };
    double Ep = 227.5e9, sum = 0.0, t0 = now_s();
    for (int i = 0; i < N; i++) {
        acbb_hertz_const c;
        double Ry = 42.707e-3 * (1.0 + 1e-4 * (i % 100));
        acbb_hertz_const_compute(2.8144e-3, Ry, Ep, ACBB_HERTZ_EXACT, &c);
        sum += c.kappa;
    }
    double us = (now_s() - t0) / N * 1e6;
    /* The cost is reported, not judged (no wall-clock threshold in
     * `meson test`; BENCHMARKS.md "Latencies the tests report"). */
    printf("# one EXACT acbb_hertz_const_compute: %.2f us\n", us);
    ok(sum > N * 5.8, "EXACT calls: mean kappa above 5.8 (%.2f us a call)", us);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_modulus_and_radii();
    test_reference_7008c();
    test_reference_table();
    test_contact_from_load();
    test_circle();
    test_fits();
    test_invalid();
    test_cost();
    return done_testing();
}
