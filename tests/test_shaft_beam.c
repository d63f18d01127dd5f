/* Tests for the spindle shaft beam (docs/spindle.md "Mechanics"): a hollow
 * Timoshenko cantilever against P L^3/(3EI) + P L/(kappa G A), a stepped
 * two-bearing shaft's nose deflection, reactions and stiffness against a
 * hand calculation, Timoshenko -> Euler-Bernoulli for slender beams, the
 * axial bar, Cowper's limits, a nonlinear support in equilibrium, and the
 * statuses of a free shaft and a bad segment. */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "shaft_beam.h"
#include "tap.h"

static const double E = 2.1e11, NU = 0.3;

static acbb_shaft_seg seg(double L, double D, double d)
{
    acbb_shaft_seg s = {.L = L, .d_out = D, .d_bore = d, .E = E, .nu = NU};
    return s;
}

static double kGA(const acbb_shaft_seg *s)
{
    return acbb_seg_shear_coeff(s) * E / (2.0 * (1.0 + NU)) * acbb_seg_area(s);
}

/* Cantilever of length L clamped at x = L by springs kc (radial, tilt,
 * axial), load P at the nose; returns the nose radial deflection. The
 * clamp's compliance is in series and exact: P/kc + (P L) L/kc. */
static double cantilever(double L, double D, double d, int n_div, double P, double kc,
                         acbb_shaft_result *r)
{
    acbb_shaft_seg s = seg(L, D, d);
    acbb_shaft_support sup = {.x = L, .k_axial = kc, .k_radial = kc, .k_tilt = kc};
    acbb_shaft_load ld = {.x = 0.0, .F_axial = P, .F_radial = P};
    acbb_shaft_beam *b = NULL;
    acbb_error err = {{0}};
    if (acbb_shaft_beam_build(&s, 1, &sup, 1, n_div, NULL, 0, &b, &err) != ACBB_OK ||
        acbb_shaft_beam_solve(b, &ld, 1, r, &err) != ACBB_OK) {
        printf("# %s\n", err.msg);
        acbb_shaft_beam_free(b);
        return NAN;
    }
    acbb_shaft_beam_free(b);
    return r->nose[1];
}

static void test_cantilever(void)
{
    const double L = 0.3, D = 0.04, d = 0.02, P = 1000.0, kc = 1e12;
    acbb_shaft_seg s = seg(L, D, d);
    double EI = E * acbb_seg_inertia(&s);
    double want = P * L * L * L / (3.0 * EI) + P * L / kGA(&s) + P / kc + P * L * L / kc;
    acbb_shaft_result r;
    is_close(cantilever(L, D, d, 1, P, kc, &r), want, 1e-10, 0.0,
             "hollow cantilever, 1 element: PL^3/3EI + PL/(kappa G A) + clamp");
    is_close(cantilever(L, D, d, 7, P, kc, &r), want, 1e-10, 0.0,
             "hollow cantilever, 7 elements: the same (nodally exact element)");
    is_close(r.nose[0], P * L / (E * acbb_seg_area(&s)) + P / kc, 1e-10, 0.0,
             "axial bar: nose u = F L/(E A) + F/k");
    is_close(r.k_axial, 1.0 / (L / (E * acbb_seg_area(&s)) + 1.0 / kc), 1e-10, 0.0,
             "axial nose stiffness");
    is_close(r.k_radial, P / want, 1e-10, 0.0, "radial nose stiffness = P / deflection");
    is_close(r.reaction[0][1], -P, 1e-12, 0.0, "clamp radial reaction = -P");
    is_close(r.reaction[0][2], P * L, 1e-10, 0.0, "clamp moment = P L (sum F x + M = 0)");
}

/* Nose overhang a (section 1), bearings at x = a (k1) and a + l (k2),
 * span section 2, a free tail behind the rear bearing; no tilt stiffness.
 * Unit-load method (bending and shear; the tail carries nothing):
 *   delta = P a^3/(3 EI1) + P a/(kGA1) + P a^2 l/(3 EI2) + P a^2/(l kGA2)
 *         + P/k1 (1 + a/l)^2 + P/k2 (a/l)^2
 * reactions F1 = -P (1 + a/l), F2 = +P a/l. */
static void test_two_bearings(void)
{
    const double a = 0.1, l = 0.25, tail = 0.08, P = 2000.0, k1 = 4e8, k2 = 2e8;
    acbb_shaft_seg s[3] = {seg(a, 0.06, 0.03), seg(l, 0.05, 0.025), seg(tail, 0.04, 0.025)};
    acbb_shaft_support sup[2] = {{.x = a, .k_axial = 1e8, .k_radial = k1},
                                 {.x = a + l, .k_radial = k2}};
    acbb_shaft_load ld = {.x = 0.0, .F_radial = P};
    double EI1 = E * acbb_seg_inertia(&s[0]), EI2 = E * acbb_seg_inertia(&s[1]);
    double want = P * a * a * a / (3 * EI1) + P * a / kGA(&s[0]) + P * a * a * l / (3 * EI2) +
                  P * a * a / (l * kGA(&s[1])) + P / k1 * (1 + a / l) * (1 + a / l) +
                  P / k2 * (a / l) * (a / l);
    acbb_shaft_beam *b = NULL;
    acbb_shaft_result r;
    acbb_error err = {{0}};
    int st = acbb_shaft_beam_build(s, 3, sup, 2, 4, NULL, 0, &b, &err);
    if (st == ACBB_OK) st = acbb_shaft_beam_solve(b, &ld, 1, &r, &err);
    ok(st == ACBB_OK, "two-bearing stepped shaft solves (%s)", err.msg);
    is_close(r.nose[1], want, 1e-10, 0.0, "nose deflection = hand calculation");
    is_close(r.k_radial, P / want, 1e-10, 0.0, "nose radial stiffness = P / delta");
    is_close(r.reaction[0][1], -P * (1 + a / l), 1e-10, 0.0, "front reaction -P(1+a/l)");
    is_close(r.reaction[1][1], P * a / l, 1e-10, 0.0, "rear reaction P a/l");
    is_close(r.k_axial, 1e8 * (1.0 / (1.0 + 1e8 * a / (E * acbb_seg_area(&s[0])))), 1e-10,
             0.0, "axial nose stiffness: front bearing in series with the overhang");
    ok(r.iterations <= 2, "linear supports: %d Newton iterations", r.iterations);
    acbb_shaft_beam_free(b);
}

/* delta_T - delta_EB = P L/(kappa G A): relative 3 EI/(kappa G A L^2),
 * which falls as (D/L)^2: each doubling of L quarters it. */
static void test_slender_limit(void)
{
    const double D = 0.04, d = 0.02, P = 100.0, kc = 1e12;
    acbb_shaft_seg s = seg(1.0, D, d);
    double EI = E * acbb_seg_inertia(&s), prev = NAN;
    int quarters = 1;
    for (int j = 0; j < 4; j++) {
        double L = 0.2 * pow(2.0, j);
        acbb_shaft_result r;
        double eb = P * L * L * L / (3.0 * EI);
        double rel = (cantilever(L, D, d, 5, P, kc, &r) - P / kc - P * L * L / kc - eb) / eb;
        if (j > 0) quarters &= fabs(prev / rel - 4.0) < 1e-5;
        prev = rel;
    }
    ok(quarters, "Timoshenko - Euler-Bernoulli shrinks as (D/L)^2");
    ok(prev > 0.0 && prev < 2e-3, "L/D = 40: Timoshenko within 0.2%% of Euler-Bernoulli (%g)",
       prev);
    double k[16];
    acbb_timoshenko_element(1.0, 0.0, 2.0, k);
    is_close(k[5], 4.0 * 1.0 / 2.0, 1e-15, 0.0, "phi = 0: element is Euler-Bernoulli (4EI/L)");
}

static void test_cowper(void)
{
    acbb_shaft_seg solid = seg(1, 0.05, 0.0), thin = seg(1, 0.05, 0.05 * (1 - 1e-7));
    is_close(acbb_seg_shear_coeff(&solid), 6 * 1.3 / (7 + 6 * 0.3), 1e-14, 0.0,
             "Cowper, solid circle: 6(1+nu)/(7+6nu)");
    is_close(acbb_seg_shear_coeff(&thin), 2 * 1.3 / (4 + 3 * 0.3), 1e-6, 0.0,
             "Cowper, thin tube: 2(1+nu)/(4+3nu)");
}

/* Hardening radial support f = -(k w + c w^3); other DOFs linear. */
static acbb_status cubic(void *ctx, const double d[3], double f[3], double K[9])
{
    const double *kc = ctx;
    memset(K, 0, 9 * sizeof *K);
    f[0] = -kc[0] * d[0];
    f[1] = -(kc[0] * d[1] + kc[1] * d[1] * d[1] * d[1]);
    f[2] = -kc[2] * d[2];
    K[0] = kc[0];
    K[4] = kc[0] + 3.0 * kc[1] * d[1] * d[1];
    K[8] = kc[2];
    return ACBB_OK;
}

static void test_nonlinear_support(void)
{
    double c1[3] = {1e8, 1e17, 1e5}, c2[3] = {1e8, 5e16, 0.0};
    acbb_shaft_seg s = seg(0.4, 0.05, 0.02);
    acbb_shaft_support sup[2] = {{.x = 0.1, .fn = cubic, .ctx = c1},
                                 {.x = 0.35, .fn = cubic, .ctx = c2}};
    acbb_shaft_load ld[2] = {{.x = 0.0, .F_axial = -300.0, .F_radial = 5000.0, .M = 40.0},
                             {.x = 0.2, .F_radial = -1000.0}};
    double lx = 0.2;
    acbb_shaft_beam *b = NULL;
    acbb_shaft_result r;
    acbb_error err = {{0}};
    int st = acbb_shaft_beam_build(&s, 1, sup, 2, 6, &lx, 1, &b, &err);
    if (st == ACBB_OK) st = acbb_shaft_beam_solve(b, ld, 2, &r, &err);
    ok(st == ACBB_OK && r.iterations > 2, "cubic supports: Newton converges in %d iterations",
       r.iterations);
    double Fr = 5000.0 - 1000.0 + r.reaction[0][1] + r.reaction[1][1];
    double Mo = 40.0 - 1000.0 * 0.2 + r.reaction[0][1] * 0.1 + r.reaction[0][2] +
                r.reaction[1][1] * 0.35 + r.reaction[1][2];
    double Fa = -300.0 + r.reaction[0][0] + r.reaction[1][0];
    ok(fabs(Fr) < 1e-8 * 5000.0, "radial force balance (%g N)", Fr);
    ok(fabs(Mo) < 1e-8 * 5000.0, "moment balance sum(F x + M) = 0 (%g N m)", Mo);
    ok(fabs(Fa) < 1e-8 * 300.0, "axial force balance (%g N)", Fa);
    double x, d[3];
    ok(acbb_shaft_beam_node(b, acbb_shaft_beam_nodes(b) - 1, &x, d) == ACBB_OK &&
       fabs(x - 0.4) < 1e-15, "last node at the shaft's end");
    acbb_shaft_beam_free(b);
}

/* Softening radial support f = -F0 atan(w/w0) (linear axially). */
static acbb_status soft(void *ctx, const double d[3], double f[3], double K[9])
{
    const double F0 = 1000.0, w0 = 1e-5;
    (void)ctx;
    memset(K, 0, 9 * sizeof *K);
    f[0] = -1e8 * d[0];
    f[1] = -F0 * atan(d[1] / w0);
    f[2] = 0.0;
    K[0] = 1e8;
    K[4] = F0 / w0 / (1.0 + d[1] / w0 * d[1] / w0);
    return ACBB_OK;
}

/* Warm start from a deep point of a softening support, then the load is
 * taken away: a plain Newton step from there overshoots ever further (the
 * atan(x) = 0 case); the damped step brings the shaft back to rest. */
static void test_damped_newton(void)
{
    acbb_shaft_seg s = seg(0.4, 0.05, 0.02);
    acbb_shaft_support sup[2] = {{.x = 0.1, .fn = soft}, {.x = 0.3, .k_radial = 1e4}};
    acbb_shaft_load ld = {.x = 0.1, .F_radial = 0.95 * 1000.0 * M_PI / 2.0};
    double lx = 0.1;
    acbb_shaft_beam *b = NULL;
    acbb_shaft_result r;
    acbb_error err = {{0}};
    int st = acbb_shaft_beam_build(&s, 1, sup, 2, 4, &lx, 1, &b, &err);
    if (st == ACBB_OK) st = acbb_shaft_beam_solve(b, &ld, 1, &r, &err);
    ok(st == ACBB_OK && r.reaction[0][1] < -0.9 * ld.F_radial,
       "softening support carries the load (%g N)", r.reaction[0][1]);
    ld.F_radial = 0.0;
    st = acbb_shaft_beam_solve(b, &ld, 1, &r, &err);
    ok(st == ACBB_OK, "load removed: the warm-started Newton converges (%s)", err.msg);
    ok(st == ACBB_OK && fabs(r.nose[1]) < 1e-15, "... back to rest (nose %g m)", r.nose[1]);
    acbb_shaft_beam_free(b);
}

/* A linear support whose reaction fails from its third call on. */
static acbb_status failing(void *ctx, const double d[3], double f[3], double K[9])
{
    int *calls = ctx;
    memset(K, 0, 9 * sizeof *K);
    for (int i = 0; i < 3; i++) {
        K[4 * i] = 1e8;
        f[i] = -1e8 * d[i] * (1.0 + d[i] * 1e3);
    }
    return ++*calls >= 3 ? ACBB_NONFINITE : ACBB_OK;
}

static void test_failed_solve_resets(void)
{
    int calls = 0;
    acbb_shaft_seg s = seg(0.4, 0.05, 0.02);
    acbb_shaft_support sup[2] = {{.x = 0.1, .fn = failing, .ctx = &calls},
                                 {.x = 0.3, .k_radial = 1e8}};
    acbb_shaft_load ld = {.x = 0.0, .F_radial = 1000.0};
    acbb_shaft_beam *b = NULL;
    acbb_shaft_result r;
    acbb_error err = {{0}};
    acbb_shaft_beam_build(&s, 1, sup, 2, 4, NULL, 0, &b, &err);
    ok(acbb_shaft_beam_solve(b, &ld, 1, &r, &err) == ACBB_NONFINITE,
       "a support's failure is the solve's status");
    has_substr(err.msg, "a support's reaction failed (nonfinite)", "message names it");
    double d[3] = {1, 1, 1};
    acbb_shaft_beam_node(b, 0, NULL, d);
    ok(d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0, "a failed solve leaves no trial behind");
    acbb_shaft_beam_free(b);
}

static void test_statuses(void)
{
    acbb_shaft_seg s = seg(0.4, 0.05, 0.02);
    acbb_shaft_support one = {.x = 0.1, .k_axial = 1e8, .k_radial = 1e8};
    acbb_shaft_support two[2] = {{.x = 0.1, .k_radial = 1e8}, {.x = 0.3, .k_radial = 1e8}};
    acbb_shaft_load ld = {.x = 0.0, .F_radial = 1.0};
    acbb_shaft_beam *b = NULL;
    acbb_shaft_result r;
    acbb_error err = {{0}};
    acbb_shaft_beam_build(&s, 1, &one, 1, 4, NULL, 0, &b, &err);
    ok(acbb_shaft_beam_solve(b, &ld, 1, &r, &err) == ACBB_SINGULAR,
       "one radial spring without tilt stiffness: singular");
    has_substr(err.msg, "free (tilt", "message names the free tilt");
    acbb_shaft_beam_free(b);
    acbb_shaft_beam_build(&s, 1, two, 2, 4, NULL, 0, &b, &err);
    ok(acbb_shaft_beam_solve(b, &ld, 1, &r, &err) == ACBB_SINGULAR, "no axial spring: singular");
    has_substr(err.msg, "free (axial", "message names the free axial motion");
    acbb_shaft_load off = {.x = 0.123, .F_radial = 1.0};
    ok(acbb_shaft_beam_solve(b, &off, 1, &r, &err) == ACBB_EINVAL,
       "a load off the mesh is refused");
    acbb_shaft_beam_free(b);
    s.d_bore = 0.05;
    ok(acbb_shaft_beam_build(&s, 1, &one, 1, 4, NULL, 0, &b, &err) == ACBB_EINVAL && !b,
       "bore = outer diameter refused");
    has_substr(err.msg, "shaft segment 1: bore diameter = 0.05 m", "message names field and unit");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_cantilever();
    test_two_bearings();
    test_slender_limit();
    test_cowper();
    test_nonlinear_support();
    test_damped_newton();
    test_failed_solve_resets();
    test_statuses();
    return done_testing();
}
