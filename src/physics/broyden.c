/* acbb — Broyden's method for small systems, see broyden.h. */
#include <math.h>
#include <string.h>
#include "broyden.h"

static double sum_abs(int n, const double *f)
{
    double s = 0.0;
    for (int i = 0; i < n; i++) s += fabs(f[i]);
    return s;
}

int acbb_newton_step(int n, const double *J, const double *f, double *d)
{
    double a[ACBB_BROYDEN_MAX][ACBB_BROYDEN_MAX + 1];
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < n; k++) a[i][k] = J[n * i + k];
        a[i][n] = -f[i];
    }
    for (int k = 0; k < n; k++) {
        int p = k;
        for (int i = k + 1; i < n; i++)
            if (fabs(a[i][k]) > fabs(a[p][k])) p = i;
        if (a[p][k] == 0.0 || !isfinite(a[p][k])) return 0;
        for (int m = 0; m <= n; m++) {
            double t = a[k][m];
            a[k][m] = a[p][m];
            a[p][m] = t;
        }
        for (int i = k + 1; i < n; i++) {
            double r = a[i][k] / a[k][k];
            for (int m = k; m <= n; m++) a[i][m] -= r * a[k][m];
        }
    }
    for (int k = n - 1; k >= 0; k--) {
        double t = a[k][n];
        for (int m = k + 1; m < n; m++) t -= a[k][m] * d[m];
        d[k] = t / a[k][k];
        if (!isfinite(d[k])) return 0;
    }
    return 1;
}

/* x + d into xn with fn_ = f(xn), d halved up to `halvings` times until
 * sum |f| drops below r (below 0.9 r when halving is allowed: a Jacobian
 * whose steps gain less than 10 % only crawls, and the callers' fallback
 * rebuilds it); 0 if it never does. */
static int damped_step(acbb_broyden_fn fn, void *ctx, int n, const double *x, double *d,
                       double r, int halvings, double *xn, double *fn_)
{
    double goal = halvings > 0 ? 0.9 * r : r;
    for (int h = 0; h <= halvings; h++) {
        if (h > 0)
            for (int k = 0; k < n; k++) d[k] *= 0.5;
        for (int k = 0; k < n; k++) xn[k] = x[k] + d[k];
        if (fn(xn, ctx, fn_) && sum_abs(n, fn_) < goal) return 1;
    }
    return 0;
}

int acbb_broyden(acbb_broyden_fn fn, void *ctx, int n, double *J, double *x, double *f,
                 double tol, int maxit, int halvings)
{
    acbb_broyden_opts o = { .halvings = halvings };
    return acbb_broyden_ex(fn, ctx, n, J, x, f, tol, maxit, &o);
}

int acbb_broyden_ex(acbb_broyden_fn fn, void *ctx, int n, double *J, double *x, double *f,
                    double tol, int maxit, const acbb_broyden_opts *o)
{
    double d[ACBB_BROYDEN_MAX], xn[ACBB_BROYDEN_MAX], fn_[ACBB_BROYDEN_MAX];
    if (n < 1 || n > ACBB_BROYDEN_MAX || (!o->have_f && !fn(x, ctx, f))) return 0;
    for (int it = 0; it < maxit; it++) {
        double r = sum_abs(n, f);
        if (r < tol) return 1;
        if (!acbb_newton_step(n, J, f, d)) return 0;
        if (!damped_step(fn, ctx, n, x, d, r, o->halvings, xn, fn_)) return 0;
        /* Good Broyden: J += (df - J d) d^T / (d . d), unless the step
         * started inside the residual's noise (its df is mostly noise). */
        if (r < o->noise) {
            memcpy(x, xn, sizeof x[0] * (size_t)n);
            memcpy(f, fn_, sizeof f[0] * (size_t)n);
            continue;
        }
        double dd = 0.0;
        for (int k = 0; k < n; k++) dd += d[k] * d[k];
        for (int i = 0; i < n; i++) {
            double u = fn_[i] - f[i];
            for (int k = 0; k < n; k++) u -= J[n * i + k] * d[k];
            for (int k = 0; k < n; k++) J[n * i + k] += u * d[k] / dd;
        }
        memcpy(x, xn, sizeof x[0] * (size_t)n);
        memcpy(f, fn_, sizeof f[0] * (size_t)n);
    }
    return sum_abs(n, f) < tol;
}

int acbb_fd_jacobian(acbb_broyden_fn fn, void *ctx, int n, const double *x, const double *f,
                     double rel, double *J)
{
    double xx[ACBB_BROYDEN_MAX], f1[ACBB_BROYDEN_MAX];
    if (n < 1 || n > ACBB_BROYDEN_MAX) return 0;
    for (int j = 0; j < n; j++) {
        memcpy(xx, x, sizeof xx[0] * (size_t)n);
        /* The step never falls below rel times a floor of 1 in x's
         * units (um, mrad): a coordinate near 0 (the radial offset under a
         * 1e-6 N radial load) would otherwise get a step lost in the
         * residual's noise and a garbage column (issue 30). */
        double h = rel * fmax(fabs(x[j]), 1.0);
        xx[j] += h;
        if (!fn(xx, ctx, f1)) return 0;
        for (int i = 0; i < n; i++) J[n * i + j] = (f1[i] - f[i]) / h;
    }
    return 1;
}
