/* Tests of the contact traction resultants (traction.h; MODEL.md section 4
 * "Level 2" for the slip field and the resultants F = iint tau dA,
 * M = iint P x tau dA, section 5 for the traction magnitude
 * tau_mag = phi_a mu_bd p + phi_f tau_lub with tau_lub <= Lambda_L p).
 * Every expected value is a hand calculation on a Hertz contact:
 * iint p dA = Q, and the spin moment of a Hertz circle (3 pi / 16) mu Q a. */
#include <math.h>
#include <string.h>
#include "tap.h"
#include "traction.h"
#include "acbb/units.h"

#define GRID 32

static void scene_min(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    s->mu_bd = 0.1;
    s->lambda_lim = 0.07;
    s->tau_eyring = 5e6;
    s->visc = ACBB_VISC_CONST;  /* eta(p) = eta0: the shear limit is reached everywhere */
    s->traction = ACBB_TRACTION_EYRING_CAP;
}

/* A Hertz ellipse of load Q and semi-axes a, b at angle alpha. dm sets the
 * orbit radius: a huge one makes the race-motion slip uniform over the
 * contact (relative spread ~ a / rm). */
static acbb_contact_in ellipse(int inner, double Q, double a, double b, double alpha, double dm)
{
    acbb_contact_in c = { 0 };
    c.inner = inner;
    c.Q = Q;
    c.a = a;
    c.b = b;
    c.pmax = 3.0 * Q / (2.0 * ACBB_PI * a * b);
    c.alpha = alpha;
    c.f = 0.54;
    c.D = 6.35e-3;
    c.dm = dm;
    return c;
}

/* Film with the given shares and thickness (the film model itself is tested
 * in test_lubrication). */
static acbb_film film_shares(double phi_a, double hc)
{
    acbb_film f = { 0 };
    f.hc = hc;
    f.phi_a = phi_a;
    f.phi_f = 1.0 - phi_a;
    return f;
}

/* An inner contact of 150 N in a mixed film (phi_a 0.4) under Roelands. */
static void mixed_inner(acbb_scene *s, acbb_contact_in *c, acbb_film *f)
{
    scene_min(s);
    s->visc = ACBB_VISC_ROELANDS;
    s->oil_alpha_pv = 2e-8;
    *c = ellipse(1, 150.0, 1.0e-3, 0.15e-3, 0.35, 54e-3);
    *f = film_shares(0.4, 2e-7);
}

static int prepared(const acbb_scene *s, const acbb_contact_in *c, const acbb_film *f,
                    acbb_traction_contact *tc)
{
    acbb_quad q;
    acbb_quad_init(&q, GRID);
    acbb_oil_state oil = { .T_C = 40, .rho = 860, .eta0 = 100.0 };
    acbb_traction_contact_free(tc); /* a re-prepared contact (tc starts zeroed) */
    return acbb_traction_contact_init(tc, GRID) == ACBB_OK
           && acbb_traction_prepare(s, &q, c, f, &oil, tc) == ACBB_OK && tc->np == GRID * GRID;
}

static double norm3(const double v[3])
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* Uniform slip along the rolling direction: the race turns (race > 0) under
 * a ball that does not rotate, on an orbit radius of 50 m, so the slip is
 * race * rm * e_y' to 1e-5 everywhere. Every point then carries the full
 * traction against it and the resultant is -tau_total * e_y'. */
static void test_uniform_slip(void)
{
    acbb_scene s;
    scene_min(&s);
    const double Q = 100.0, a = 0.5e-3, race = 1.0, wb0[3] = { 0, 0, 0 };
    const char *side[] = { "outer", "inner" };
    for (int inner = 0; inner < 2; inner++) {
        acbb_contact_in c = ellipse(inner, Q, a, 0.4 * a, 0.3, 100.0);
        /* Coulomb limit (boundary friction only): |F| = mu Q. */
        acbb_film f = film_shares(1.0, 0.0);
        acbb_traction_contact tc = { 0 };
        acbb_traction tr;
        ok(prepared(&s, &c, &f, &tc), "%s: %dx%d points prepared", side[inner], GRID, GRID);
        acbb_traction_eval(&s, &tc, wb0, race, &tr);
        is_close(tr.F[1], -s.mu_bd * Q, 1e-3, 0,
                 inner ? "inner, boundary friction: F_y' = -mu Q (MODEL 5)"
                       : "outer, boundary friction: F_y' = -mu Q (MODEL 5)");
        is_close(hypot(tr.F[0], tr.F[2]), 0.0, 0, 1e-4 * s.mu_bd * Q,
                 "uniform slip along y': no meridional traction");
        /* M = sum P x f with f = -|f| e_y' and P = h n + x t + y e_y':
         * the x t terms cancel by symmetry, so M = -(sum h |f|) n x e_y',
         * along the major-axis tangent, with h ~ D/2 (the deformed surface
         * lies within a^2/D of the ball radius). */
        double Mn = tr.M[0] * tc.n[0] + tr.M[1] * tc.n[1] + tr.M[2] * tc.n[2];
        is_close(hypot(Mn, tr.M[1]), 0.0, 0, 1e-6 * s.mu_bd * Q * c.D,
                 "moment lies along the major-axis tangent (no n, no y' part)");
        is_close(norm3(tr.M), s.mu_bd * Q * 0.5 * c.D, 0.02, 0, "|M| = mu Q D/2 within a^2/D");
        /* Reversed slip: F and M change sign, magnitude unchanged. */
        acbb_traction rev;
        acbb_traction_eval(&s, &tc, wb0, -race, &rev);
        is_close(rev.F[1], -tr.F[1], 1e-12, 0, "reversed race motion: F_y' changes sign");

        /* Limiting-shear limit (full film, Eyring far above the cap at a
         * 50 m/s slip over 0.1 um): tau = Lambda_L p, so |F| = Lambda_L Q. */
        f = film_shares(0.0, 1e-7);
        ok(prepared(&s, &c, &f, &tc), "full film prepared");
        acbb_traction_eval(&s, &tc, wb0, race, &tr);
        is_close(tr.F[1], -s.lambda_lim * Q, 1e-3, 0, "full film: F_y' = -Lambda_L Q (MODEL 5)");
        s.traction = ACBB_TRACTION_BAIR_WINER;
        acbb_traction_eval(&s, &tc, wb0, race, &tr);
        is_close(tr.F[1], -s.lambda_lim * Q, 1e-3, 0, "Bair-Winer, full film: F_y' = -Lambda_L Q");
        s.traction = ACBB_TRACTION_EYRING_CAP;
        /* Mixed shares add linearly: (phi_a mu + phi_f Lambda_L) Q. */
        f = film_shares(0.3, 1e-7);
        ok(prepared(&s, &c, &f, &tc), "mixed film prepared");
        acbb_traction_eval(&s, &tc, wb0, race, &tr);
        is_close(tr.F[1], -(0.3 * s.mu_bd + 0.7 * s.lambda_lim) * Q, 1e-3, 0,
                 "phi_a 0.3: F_y' = -(phi_a mu + phi_f Lambda_L) Q");
        acbb_traction_contact_free(&tc);
    }
}

/* Pure spin about the contact normal of a Hertz circle, no race motion:
 * slip = w n x P (the h n part of P drops out), the net force vanishes by
 * symmetry and the moment about n opposes the spin with
 * mu iint p r dA = (3 pi / 16) mu Q a. */
static void test_spin_moment(void)
{
    acbb_scene s;
    scene_min(&s);
    const double Q = 100.0, a = 0.5e-3, w = 200.0;
    acbb_contact_in c = ellipse(0, Q, a, a, 0.3, 54e-3);
    acbb_film f = film_shares(1.0, 0.0);
    acbb_traction_contact tc = { 0 };
    ok(prepared(&s, &c, &f, &tc), "circle prepared");
    double wb[3] = { w * tc.n[0], w * tc.n[1], w * tc.n[2] };
    acbb_traction tr;
    acbb_traction_eval(&s, &tc, wb, 0.0, &tr);
    double Mn = tr.M[0] * tc.n[0] + tr.M[1] * tc.n[1] + tr.M[2] * tc.n[2];
    is_close(Mn, -3.0 * ACBB_PI / 16.0 * s.mu_bd * Q * a, 2e-3, 0,
             "spin moment about n = -(3 pi/16) mu Q a (32x32)");
    is_close(norm3(tr.F), 0.0, 0, 1e-6 * s.mu_bd * Q, "pure spin: no net force");
    acbb_traction_contact_free(&tc);
}

/* No slip, no traction; general slip reverses exactly with the motion. */
static void test_zero_and_reversal(void)
{
    acbb_scene s;
    acbb_contact_in c;
    acbb_film f;
    mixed_inner(&s, &c, &f);
    acbb_traction_contact tc = { 0 };
    ok(prepared(&s, &c, &f, &tc), "inner contact, mixed film prepared");
    const double zero[3] = { 0, 0, 0 };
    acbb_traction tr, rev;
    acbb_traction_eval(&s, &tc, zero, 0.0, &tr);
    ok(norm3(tr.F) == 0.0 && norm3(tr.M) == 0.0, "zero slip: F = M = 0 exactly");
    /* A generic motion (rolling, spin and pivoting at once): reversing
     * every velocity reverses the slip at every point, hence F and M. */
    const double wb[3] = { -1700.0, 35.0, 480.0 }, race = 820.0;
    const double nwb[3] = { 1700.0, -35.0, -480.0 };
    acbb_traction_eval(&s, &tc, wb, race, &tr);
    acbb_traction_eval(&s, &tc, nwb, -race, &rev);
    double scale = norm3(tr.F), mscale = norm3(tr.M);
    ok(scale > 1e-3 * s.mu_bd * c.Q, "generic slip gives traction (|F| = %.3g N)", scale);
    int anti = 1;
    for (int d = 0; d < 3; d++)
        anti &= fabs(rev.F[d] + tr.F[d]) <= 1e-12 * scale
                && fabs(rev.M[d] + tr.M[d]) <= 1e-12 * mscale;
    ok(anti, "slip reversal: F and M change sign exactly (antisymmetry)");
    ok(scale <= (0.4 * s.mu_bd + 0.6 * s.lambda_lim) * c.Q * (1 + 1e-3),
       "|F| (%.4g N) <= (phi_a mu + phi_f Lambda_L) Q: traction never exceeds its cap", scale);
    acbb_traction_contact_free(&tc);
}

/* An unloaded contact has no points and no traction. */
static void test_unloaded(void)
{
    acbb_scene s;
    scene_min(&s);
    acbb_contact_in c = ellipse(0, 0.0, 0.0, 0.0, 0.3, 54e-3);
    acbb_film f = film_shares(1.0, 0.0);
    acbb_traction_contact tc = { 0 };
    acbb_quad q;
    acbb_quad_init(&q, GRID);
    acbb_oil_state oil = { .eta0 = 0.05 };
    ok(acbb_traction_contact_init(&tc, GRID) == ACBB_OK
           && acbb_traction_prepare(&s, &q, &c, &f, &oil, &tc) == ACBB_OK && tc.np == 0,
       "Q = 0: no contact points (MODEL 11: skip contact integrals when Q < 1e-6 N)");
    const double wb[3] = { -1000, 0, 300 };
    acbb_traction tr;
    acbb_traction_eval(&s, &tc, wb, 500.0, &tr);
    ok(norm3(tr.F) == 0.0 && norm3(tr.M) == 0.0, "Q = 0: F = M = 0");
    acbb_quad_init(&q, GRID);
    acbb_traction_contact small;
    acbb_traction_contact_init(&small, 8);
    c = ellipse(0, 100.0, 0.5e-3, 0.5e-3, 0.3, 54e-3);
    ok(acbb_traction_prepare(&s, &q, &c, &f, &oil, &small) == ACBB_EINVAL,
       "a %dx%d rule in an 8x8 table is refused (EINVAL), not overrun", GRID, GRID);
    acbb_traction_contact_free(&small);
    acbb_traction_contact_free(&tc);
}

/* The analytic derivatives of acbb_traction_eval_jac against central
 * differences of acbb_traction_eval (steps 1e-4 of the speeds: truncation
 * ~1e-8 relative), for a generic motion of a mixed-film contact (Eyring
 * below its cap at most points) and for a pure-boundary one; the
 * resultants equal acbb_traction_eval's bit for bit; Bair-Winer has no
 * analytic derivative here (returns 0). */
static void check_jacobian(const acbb_scene *s, const acbb_traction_contact *tc,
                           const double wb[3], double race, const char *what)
{
    acbb_traction tr, ref;
    double dF[3][4], dM[3][4];
    ok(acbb_traction_eval_jac(s, tc, wb, race, &tr, dF, dM) == 1, "%s: analytic Jacobian", what);
    acbb_traction_eval(s, tc, wb, race, &ref);
    ok(memcmp(&tr, &ref, sizeof tr) == 0, "%s: F, M equal acbb_traction_eval's exactly", what);
    double worst = 0.0, scale = 0.0;
    for (int j = 0; j < 4; j++) {
        double u[4] = { wb[0], wb[1], wb[2], race }, h = 1e-4 * fmax(fabs(u[j]), 100.0);
        acbb_traction p, m;
        u[j] += h;
        acbb_traction_eval(s, tc, u, u[3], &p);
        u[j] -= 2.0 * h;
        acbb_traction_eval(s, tc, u, u[3], &m);
        for (int d = 0; d < 3; d++) {
            double fdF = (p.F[d] - m.F[d]) / (2.0 * h), fdM = (p.M[d] - m.M[d]) / (2.0 * h);
            /* Moments over the ball radius: force units, one scale. */
            worst = fmax(worst, fmax(fabs(fdF - dF[d][j]), fabs(fdM - dM[d][j]) / 3.175e-3));
            scale = fmax(scale, fmax(fabs(fdF), fabs(fdM) / 3.175e-3));
        }
    }
    ok(scale > 0.0 && worst <= 1e-6 * scale,
       "%s: analytic dF, dM/r vs central differences: worst %.2e of %.3g N s/rad (<= 1e-6)",
       what, worst, scale);
}

static void test_jacobian(void)
{
    acbb_scene s;
    scene_min(&s);
    s.visc = ACBB_VISC_ROELANDS;
    s.oil_alpha_pv = 2e-8;
    s.tau_eyring = 2e6;
    s.lambda_lim = 0.5; /* the cap far: the Eyring branch at most points */
    acbb_contact_in c = ellipse(1, 150.0, 1.0e-3, 0.15e-3, 0.35, 54e-3);
    acbb_film f = film_shares(0.4, 2e-7);
    acbb_traction_contact tc = { 0 };
    ok(prepared(&s, &c, &f, &tc), "inner contact, mixed film prepared");
    /* Near-rolling ball (slip of a few cm/s, as Level 2 solves), spin and
     * pivoting: both the Eyring and the regularised boundary terms vary. */
    const double wb[3] = { -1700.0, 3.5, 480.0 };
    double race = 1700.0 * 3.175e-3 / (0.027 + 3.175e-3 * cos(0.35)) * 1.001;
    check_jacobian(&s, &tc, wb, race, "mixed film");
    f = film_shares(1.0, 2e-7);
    ok(prepared(&s, &c, &f, &tc), "boundary-only contact prepared");
    check_jacobian(&s, &tc, wb, race, "boundary only");
    s.traction = ACBB_TRACTION_BAIR_WINER;
    f = film_shares(0.4, 2e-7);
    ok(prepared(&s, &c, &f, &tc), "Bair-Winer contact prepared");
    acbb_traction tr;
    double dF[3][4], dM[3][4];
    ok(acbb_traction_eval_jac(&s, &tc, wb, race, &tr, dF, dM) == 0,
       "Bair-Winer with a film: no analytic Jacobian (0, the caller differences)");
    acbb_traction_contact_free(&tc);
}

/* The point tables share a viscosity between mirror nodes (issue 30):
 * every node's viscosity must still be the law's at that node's own
 * pressure, bit for bit, for even and odd grids (an odd grid has a middle
 * row and column that are their own mirrors); the sharing pays because
 * the Gauss nodes off the middle are exact +-x pairs of equal weight. */
static void test_mirror_viscosity(void)
{
    acbb_scene s;
    acbb_contact_in c;
    acbb_film f;
    mixed_inner(&s, &c, &f);
    acbb_oil_state oil = { .T_C = 40, .rho = 860, .eta0 = 0.05 };
    acbb_visc_law law;
    acbb_visc_law_init(&s, &oil, &law);
    int bad_eta = 0, bad_pair = 0, shared = 0, transposed = 0;
    for (int n = 1; n <= ACBB_QUAD_MAX; n++) {
        acbb_quad q;
        acbb_traction_contact tc = { 0 };
        if (acbb_quad_init(&q, n) != ACBB_OK || acbb_traction_contact_init(&tc, n) != ACBB_OK
            || acbb_traction_prepare(&s, &q, &c, &f, &oil, &tc) != ACBB_OK || tc.np != n * n) {
            bad_eta++;
            acbb_traction_contact_free(&tc);
            continue;
        }
        for (int i = 0; i < n; i++) /* GSL's middle node of some odd rules is ~1e-17, not 0 */
            bad_pair += i != n - 1 - i && (q.x[n - 1 - i] != -q.x[i] || q.w[n - 1 - i] != q.w[i]);
        for (int k = 0; k < tc.np; k++) {
            bad_eta += tc.eta[k] != acbb_visc_law_eval(&law, tc.p[k]);
            shared += k > 0 && tc.p[k] == tc.p[k - 1];
            int i = k / n, j = k % n; /* the transposed node (j, i) before it */
            transposed += j < i && tc.p[j * n + i] == tc.p[k];
        }
        acbb_traction_contact_free(&tc);
    }
    ok(bad_pair == 0, "Gauss rules of 1..%d nodes: nodes off the middle in exact +-x pairs "
       "of equal weight (%d not)", ACBB_QUAD_MAX, bad_pair);
    ok(bad_eta == 0, "grids 1..%d: every node's viscosity is the law's at its pressure (%d not)",
       ACBB_QUAD_MAX, bad_eta);
    ok(shared > 0, "mirror nodes do share pressures (%d neighbours in a row)", shared);
    ok(transposed > 0, "transposed nodes share pressures too (%d)", transposed);
}

/* The inline asinh of the Eyring stresses (traction.h acbb_asinh_pos)
 * against the C library's over 1e-12 .. 1e12 and at its branch edges
 * (2^-28, 2, 2^28): to 1 ulp (the same identities: on glibc the same
 * bits, which the run JSON's bit-identity relies on there). */
static void test_asinh(void)
{
    double worst = 0.0;
    const double edges[] = { 0x1p-28, 2.0, 0x1p28 };
    for (double x = 1e-12; x < 1e12; x *= 1.0137) {
        double a = acbb_asinh_pos(x), b = asinh(x);
        worst = fmax(worst, fabs(a - b) / b);
    }
    for (int e = 0; e < 3; e++)
        for (int k = -3; k <= 3; k++) {
            double x = edges[e] * (1.0 + k * 0x1p-52), a = acbb_asinh_pos(x), b = asinh(x);
            worst = fmax(worst, fabs(a - b) / b);
        }
    ok(worst <= 0x1p-52, "inline asinh = the C library's to %.1e (<= 1 ulp)", worst);
}

int main(void)
{
    test_asinh();
    test_mirror_viscosity();
    test_uniform_slip();
    test_spin_moment();
    test_zero_and_reversal();
    test_unloaded();
    test_jacobian();
    return done_testing();
}
