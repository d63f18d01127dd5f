/* acbb — stepped hollow cylinders: validation, section properties, the
 * Cowper shear coefficient and the shared axial mesh (docs/spindle.md). */
#include <math.h>
#include <stdlib.h>
#include "shaft_section.h"

static acbb_status bad(acbb_error *err, const char *what, int k, const char *field,
                       double v, const char *rule)
{
    return acbb_error_set(err, ACBB_EINVAL, "%s segment %d: %s = %g %s", what, k + 1,
                          field, v, rule);
}

static acbb_status check_geom(const char *what, const acbb_shaft_seg *g, int k,
                              acbb_error *err)
{
    if (!isfinite(g->L) || g->L <= 0.0 || g->L > 100.0)
        return bad(err, what, k, "length", g->L, "m (must be in (0, 100])");
    if (!isfinite(g->d_out) || g->d_out <= 0.0 || g->d_out > 10.0)
        return bad(err, what, k, "outer diameter", g->d_out, "m (must be in (0, 10])");
    if (!isfinite(g->d_bore) || g->d_bore < 0.0 || g->d_bore >= g->d_out)
        return bad(err, what, k, "bore diameter", g->d_bore,
                   "m (must be >= 0 and below the outer diameter)");
    return ACBB_OK;
}

static acbb_status check_mech(const char *what, const acbb_shaft_seg *g, int k,
                              acbb_error *err)
{
    if (!isfinite(g->E) || g->E < 1e8 || g->E > 1e13)
        return bad(err, what, k, "E", g->E, "Pa (must be in [1e8, 1e13])");
    if (!isfinite(g->nu) || g->nu < 0.0 || g->nu >= 0.5)
        return bad(err, what, k, "nu", g->nu, "(must be in [0, 0.5))");
    return ACBB_OK;
}

static acbb_status check_therm(const char *what, const acbb_shaft_seg *g, int k,
                               acbb_error *err)
{
    if (!isfinite(g->k) || g->k <= 0.0 || g->k > 5000.0)
        return bad(err, what, k, "k", g->k, "W/(m K) (must be in (0, 5000])");
    if (!isfinite(g->rho) || g->rho <= 0.0 || g->rho > 30000.0)
        return bad(err, what, k, "rho", g->rho, "kg/m3 (must be in (0, 30000])");
    if (!isfinite(g->c) || g->c <= 0.0 || g->c > 10000.0)
        return bad(err, what, k, "c", g->c, "J/(kg K) (must be in (0, 10000])");
    if (!isfinite(g->alpha) || g->alpha < 0.0 || g->alpha > 1e-3)
        return bad(err, what, k, "alpha", g->alpha, "1/K (must be in [0, 1e-3])");
    return ACBB_OK;
}

acbb_status acbb_shaft_segs_check(const char *what, const acbb_shaft_seg *s, int n,
                                  int use, acbb_error *err)
{
    if (!s || n < 1)
        return acbb_error_set(err, ACBB_EINVAL, "%s: at least one segment is needed", what);
    for (int k = 0; k < n; k++) {
        acbb_status st = check_geom(what, &s[k], k, err);
        if (st == ACBB_OK && (use & ACBB_SEG_MECH)) st = check_mech(what, &s[k], k, err);
        if (st == ACBB_OK && (use & ACBB_SEG_THERM)) st = check_therm(what, &s[k], k, err);
        if (st != ACBB_OK) return st;
    }
    return ACBB_OK;
}

double acbb_shaft_segs_length(const acbb_shaft_seg *s, int n)
{
    double L = 0.0;
    for (int k = 0; k < n; k++) L += s[k].L;
    return L;
}

int acbb_shaft_segs_locate(const acbb_shaft_seg *s, int n, double x)
{
    double x0 = 0.0;
    if (x < 0.0) return -1;
    for (int k = 0; k < n; k++) {
        if (x < x0 + s[k].L) return k;
        x0 += s[k].L;
    }
    return x <= x0 * (1.0 + 1e-12) ? n - 1 : -1;
}

double acbb_seg_area(const acbb_shaft_seg *s)
{
    return M_PI / 4.0 * (s->d_out * s->d_out - s->d_bore * s->d_bore);
}

double acbb_seg_inertia(const acbb_shaft_seg *s)
{
    double D2 = s->d_out * s->d_out, d2 = s->d_bore * s->d_bore;
    return M_PI / 64.0 * (D2 * D2 - d2 * d2);
}

/* Cowper, J. Appl. Mech. 33 (1966) 335-340, Table 1, hollow circle. */
double acbb_seg_shear_coeff(const acbb_shaft_seg *s)
{
    double m = s->d_bore / s->d_out, m2 = m * m, nu = s->nu;
    double a = (1.0 + m2) * (1.0 + m2);
    return 6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

acbb_status acbb_shaft_mesh(const acbb_shaft_seg *s, int n, int n_div,
                            const double *extra, int n_extra,
                            double **x_out, int *n_out, acbb_error *err)
{
    if (n_div < 1 || n_div > 1000 || n_extra < 0 || (n_extra > 0 && !extra))
        return acbb_error_set(err, ACBB_EINVAL,
                              "shaft mesh: divisions per segment = %d (must be in [1, 1000])",
                              n_div);
    double Ltot = acbb_shaft_segs_length(s, n), x0 = 0.0;
    double *x = malloc((size_t)(n * n_div + 1 + n_extra) * sizeof *x);
    if (!x) return acbb_error_set(err, ACBB_ENOMEM, "shaft mesh: out of memory");
    int m = 0;
    for (int k = 0; k < n; k++) {
        for (int j = 0; j < n_div; j++) x[m++] = x0 + s[k].L * j / n_div;
        x0 += s[k].L;
    }
    x[m++] = Ltot;
    for (int j = 0; j < n_extra; j++)
        if (extra[j] >= 0.0 && extra[j] <= Ltot) x[m++] = extra[j];
    qsort(x, (size_t)m, sizeof *x, cmp_double);
    int u = 1;
    for (int j = 1; j < m; j++)
        if (x[j] - x[u - 1] > 1e-9 * Ltot) x[u++] = x[j];
    x[u - 1] = Ltot;   /* a merged end keeps the exact length */
    *x_out = x;
    *n_out = u;
    return ACBB_OK;
}
