/* acbb — Hertz point contact (MODEL.md section 2). Pure functions. */
#include "hertz.h"

#include <math.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

/* Ellipticity search interval of MODEL.md section 2. kappa = 200 is reached
 * only for Ry/Rx of a few thousand, far outside any bearing groove. */
#define KAPPA_MAX 200.0
/* Brent stops when the bracket is this small relative to kappa. */
#define KAPPA_RTOL 1e-12
#define BRENT_MAX_ITER 100
/* Below this m = e^2 the exact ratio F(kappa) is evaluated by its series:
 * the closed form loses ~1e-15/m^2 of relative accuracy to cancellation. */
#define SERIES_M_MAX 1e-2

double acbb_effective_modulus(double E1, double nu1, double E2, double nu2)
{
    return 2.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

/* MODEL.md section 2, table of principal radii; gamma uses the operating
 * angle. The ball radius D/2 appears in both planes. */
void acbb_contact_radii(double D, double dm, double alpha, double f, int inner,
                        double *Rx, double *Ry)
{
    double gamma = D * cos(alpha) / dm;
    *Rx = inner ? 0.5 * D * (1.0 - gamma) : 0.5 * D * (1.0 + gamma);
    *Ry = f * D / (2.0 * f - 1.0);
}

/* Complete elliptic integrals for m = e^2 = 1 - 1/kappa^2. GSL takes the
 * modulus e, not the parameter m. The _e variants never call the GSL error
 * handler, so the result does not depend on the caller's handler. */
static int ellint_KE(double m, double *K, double *E)
{
    gsl_sf_result rk, re;
    double e = sqrt(m);
    if (gsl_sf_ellint_Kcomp_e(e, GSL_PREC_DOUBLE, &rk) != GSL_SUCCESS ||
        gsl_sf_ellint_Ecomp_e(e, GSL_PREC_DOUBLE, &re) != GSL_SUCCESS)
        return -1;
    *K = rk.val;
    *E = re.val;
    return 0;
}

/* Right-hand side of the ellipticity equation (MODEL.md section 2),
 * F(kappa) = [(kappa^2+1)E - 2K] / [(kappa^2-1)E], rewritten in m:
 * F = [(2-m)E - 2(1-m)K] / (m E). It rises monotonically from 0 at
 * kappa = 1 to 1 as kappa -> inf. Near kappa = 1 the numerator cancels, so
 * the Maclaurin series in m (derived from the K, E series) is used there:
 * F = 3m/8 + 3m^2/16 + 111m^3/1024 + 141m^4/2048 + O(m^5). */
static double ellipticity_F(double kappa)
{
    double m = 1.0 - 1.0 / (kappa * kappa);
    double K, E;
    if (m <= 0.0)
        return 0.0;
    if (m < SERIES_M_MAX)
        return m * (3.0 / 8.0 + m * (3.0 / 16.0 + m * (111.0 / 1024.0 +
                    m * (141.0 / 2048.0))));
    if (ellint_KE(m, &K, &E) != 0)
        return NAN;
    return ((2.0 - m) * E - 2.0 * (1.0 - m) * K) / (m * E);
}

typedef struct {
    double F_rho;
} ellipticity_params;

static double ellipticity_residual(double kappa, void *p)
{
    const ellipticity_params *ep = p;
    return ellipticity_F(kappa) - ep->F_rho;
}

/* Solve F(kappa) = F_rho (F_rho in (0,1)) with GSL's Brent solver. The
 * bracket starts around the Brewe-Hamrock estimate (within 7 % of exact on
 * 1 <= Ry/Rx <= 100) so Brent needs only a handful of iterations, and falls
 * back to [1, KAPPA_MAX]. The end points are checked here because
 * gsl_root_fsolver_set would call the (possibly aborting) GSL error handler
 * on a bad bracket. The solver is allocated per call: measured cost of the
 * whole EXACT call is a few microseconds (see tests/test_hertz.c), well
 * below the 20 us budget for the ~10^4 calls of a run, so a hand-written
 * stack solver is not worth its code. */
static acbb_status solve_kappa(double F_rho, double ratio, double *kappa)
{
    ellipticity_params ep = { F_rho };
    gsl_function fn = { ellipticity_residual, &ep };
    double k0 = 1.0339 * pow(ratio, 0.6360);
    double lo = fmax(1.0, 0.85 * k0), hi = fmin(KAPPA_MAX, 1.15 * k0);
    acbb_status st = ACBB_DIVERGED;

    if (hi <= lo || ellipticity_residual(lo, &ep) > 0.0)
        lo = 1.0;
    if (hi <= lo || ellipticity_residual(hi, &ep) < 0.0)
        hi = KAPPA_MAX;
    if (!(ellipticity_residual(hi, &ep) >= 0.0))
        return ACBB_EINVAL; /* ellipticity beyond KAPPA_MAX (or NaN) */

    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return ACBB_ENOMEM;
    if (gsl_root_fsolver_set(s, &fn, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < BRENT_MAX_ITER; it++) {
            if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS)
                break;
            lo = gsl_root_fsolver_x_lower(s);
            hi = gsl_root_fsolver_x_upper(s);
            if (gsl_root_test_interval(lo, hi, 0.0, KAPPA_RTOL) == GSL_SUCCESS) {
                *kappa = gsl_root_fsolver_root(s);
                st = ACBB_OK;
                break;
            }
        }
    }
    gsl_root_fsolver_free(s);
    return st;
}

static acbb_status ellipse_exact(double F_rho, double ratio, acbb_hertz_const *c)
{
    double kappa = 1.0;
    /* A circle (Rx == Ry): kappa = 1, K = E = pi/2, no root to find. */
    if (F_rho > 0.0) {
        acbb_status st = solve_kappa(F_rho, ratio, &kappa);
        if (st != ACBB_OK)
            return st;
    }
    c->kappa = kappa;
    if (ellint_KE(1.0 - 1.0 / (kappa * kappa), &c->K, &c->E) != 0)
        return ACBB_DIVERGED;
    return ACBB_OK;
}

/* Brewe & Hamrock 1977 curve fits (MODEL.md section 2), ratio = Ry/Rx. */
static void ellipse_bh77(double ratio, acbb_hertz_const *c)
{
    c->kappa = 1.0339 * pow(ratio, 0.6360);
    c->E = 1.0003 + 0.5968 / ratio;
    c->K = 1.5277 + 0.6023 * log(ratio);
}

/* Hamrock & Brewe 1983 simplified fits (MODEL.md section 2). */
static void ellipse_hb83(double ratio, acbb_hertz_const *c)
{
    c->kappa = pow(ratio, 2.0 / M_PI);
    c->E = 1.0 + (M_PI_2 - 1.0) / ratio;
    c->K = M_PI_2 + (M_PI_2 - 1.0) * log(ratio);
}

/* Radii are symmetric in the Hertz solution apart from which axis is the
 * major one, so the fits and the solver use ratio = max/min >= 1 and
 * |F_rho|; kappa >= 1 is always semi-major / semi-minor. */
acbb_status acbb_hertz_const_compute(double Rx, double Ry, double E_eff,
                                     acbb_hertz_mode mode, acbb_hertz_const *out)
{
    acbb_hertz_const c;
    acbb_status st = ACBB_OK;

    memset(out, 0, sizeof *out);
    if (!(Rx > 0.0 && Ry > 0.0 && E_eff > 0.0 && isfinite(Rx) && isfinite(Ry) &&
          isfinite(E_eff)))
        return ACBB_EINVAL;

    memset(&c, 0, sizeof c);
    c.Rx = Rx;
    c.Ry = Ry;
    c.E_eff = E_eff;
    c.R = 1.0 / (1.0 / Rx + 1.0 / Ry);
    c.F_rho = (1.0 / Rx - 1.0 / Ry) * c.R;
    double ratio = Rx > Ry ? Rx / Ry : Ry / Rx;

    switch (mode) {
    case ACBB_HERTZ_BH77:
        ellipse_bh77(ratio, &c);
        break;
    case ACBB_HERTZ_HB83:
        ellipse_hb83(ratio, &c);
        break;
    case ACBB_HERTZ_EXACT:
    default:
        st = ellipse_exact(fabs(c.F_rho), ratio, &c);
        break;
    }
    if (st != ACBB_OK)
        return st;

    /* Q = Kc delta^1.5 (MODEL.md section 2). */
    c.Kc = M_PI * c.kappa * E_eff * sqrt(2.0 * c.E * c.R / (9.0 * c.K * c.K * c.K));
    *out = c;
    return ACBB_OK;
}

/* Semi-axes, deflection and peak pressure [HD] (MODEL.md section 2). */
void acbb_hertz_from_load(const acbb_hertz_const *c, double Q, acbb_hertz_contact *out)
{
    memset(out, 0, sizeof *out);
    if (!(Q > 0.0))
        return;
    double k = c->kappa, E = c->E, R = c->R, Ep = c->E_eff;
    double q = Q / (M_PI * k * Ep);
    out->Q = Q;
    out->a = cbrt(6.0 * k * k * E * Q * R / (M_PI * Ep));
    out->b = cbrt(6.0 * E * Q * R / (M_PI * k * Ep));
    out->delta = c->K * cbrt(9.0 / (2.0 * E * R) * q * q);
    out->pmax = 3.0 * Q / (2.0 * M_PI * out->a * out->b);
}

/* Q = Kc delta^1.5; the given delta is kept exactly (no round trip). */
void acbb_hertz_from_deflection(const acbb_hertz_const *c, double delta,
                                acbb_hertz_contact *out)
{
    memset(out, 0, sizeof *out);
    if (!(delta > 0.0))
        return;
    acbb_hertz_from_load(c, c->Kc * delta * sqrt(delta), out);
    if (out->Q > 0.0)
        out->delta = delta;
}
