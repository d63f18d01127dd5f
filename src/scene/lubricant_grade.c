/* acbb — a lubricant given by its ISO viscosity grade (MODEL.md 16).
 *
 * - ISO 3448: grade VG n has the midpoint viscosity n mm^2/s at 40 C.
 * - ASTM D2270 (= ISO 2909) defines the viscosity index VI from nu40 (U)
 *   and nu100 (Y) through L and H, the nu40 of the VI 0 and VI 100
 *   reference oils with the same nu100: VI = 100 (L - U)/(L - H) for
 *   U >= H, else VI = (10^N - 1)/0.00715 + 100 with
 *   N = (log H - log U)/log Y. For Y > 70 mm^2/s the standard gives
 *   L = 0.8353 Y^2 + 14.67 Y - 216, H = 0.1684 Y^2 + 11.85 Y - 97; from
 *   2 to 70 it tabulates L and H (viscosity_index_table.c, interpolated
 *   linearly between rows as the standard says). Below Y = 2, where
 *   D2270 is not defined, see below_range().
 * - Pressure-viscosity: Wooster's correlation for mineral oils,
 *   alpha = (0.6 + 0.965 log10 eta0[cP]) 1e-8 1/Pa (as quoted in
 *   Stachowiak & Batchelor, Engineering Tribology, ch. 2), eta0 at 40 C;
 *   it gives 1.97e-8 for the seed's oil (MODEL.md 10 assumes 2.0e-8).
 * Explicit values override: a graded scene keeps any of oil_nu40,
 * oil_nu100, oil_alpha_pv set to other than its default. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include "gsl_quiet.h"
#include "lubricant_grade.h"
#include "viscosity_index_table.h"
#include "acbb/tools/lubricant.h"

static const double k_midpoint[ACBB_GRADES] = {
    0, 2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500,
};

double acbb_grade_midpoint(acbb_oil_grade g)
{
    return g > ACBB_GRADE_CUSTOM && g < ACBB_GRADES ? k_midpoint[g] : 0.0;
}

#define Y0 2.0 /* D2270's first row */

static double L_formula(double Y) { return 0.8353 * Y * Y + 14.67 * Y - 216.0; }
static double H_formula(double Y) { return 0.1684 * Y * Y + 11.85 * Y - 97.0; }

/* L and H for Y >= 2 (the table, then the formulas above 70) */
static void ref_oils(double Y, double *L, double *H)
{
    if (acbb_d2270_table(Y, L, H)) return;
    *L = L_formula(Y);
    *H = H_formula(Y);
}

double acbb_viscosity_index(double nu40, double nu100)
{
    if (!(nu100 >= Y0)) return NAN; /* outside D2270 */
    double L, H;
    ref_oils(nu100, &L, &H);
    if (nu40 >= H) return 100.0 * (L - nu40) / (L - H);
    double N = (log10(H) - log10(nu40)) / log10(nu100);
    return (pow(10.0, N) - 1.0) / 0.00715 + 100.0;
}

typedef struct { double nu40, vi; } vi_goal;

static double vi_miss(double Y, void *p)
{
    const vi_goal *g = p;
    return acbb_viscosity_index(g->nu40, Y) - g->vi;
}

/* nu40 of the oil with nu100 = Y and viscosity index vi (D2270 solved for U) */
static double nu40_of(double Y, double vi)
{
    double L, H;
    ref_oils(Y, &L, &H);
    if (vi <= 100.0) return L - vi / 100.0 * (L - H);
    return H / pow(Y, log10(1.0 + 0.00715 * (vi - 100.0)));
}

static double loglog(double nu) { return log10(log10(nu + 0.7)); }

/* Below D2270's range (nu100 < 2 mm^2/s: VG2-VG5 at common VIs): the
 * Walther slope (ASTM D341) of the oil with nu100 = 2 and the same VI,
 * carried to nu40 (an extrapolation, UNSURE). */
static double below_range(double nu40, double vi)
{
    double x = log10(100.0 + 273.15) - log10(40.0 + 273.15);
    double B = (loglog(nu40_of(Y0, vi)) - loglog(Y0)) / x;
    return pow(10.0, pow(10.0, loglog(nu40) - B * x)) - 0.7;
}

double acbb_nu100_from_vi(double nu40, double vi)
{
    /* VI grows with nu100 at fixed nu40: bracket in D2270's range */
    vi_goal g = { nu40, vi };
    double lo = Y0, hi = 0.999 * nu40;
    if (!(hi > lo) || vi_miss(lo, &g) > 0.0) return below_range(nu40, vi);
    if (vi_miss(hi, &g) < 0.0) return hi;
    gsl_function F = { vi_miss, &g };
    acbb_gsl_enter(); /* a scene call, outside any Sim's bracket */
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) {
        acbb_gsl_leave();
        return NAN;
    }
    /* A NaN at an end (a NaN vi from a library caller) fails here. */
    double Y = gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS ? 0.5 * (lo + hi) : NAN;
    for (int it = 0; it < 200 && isfinite(Y); it++) {
        gsl_root_fsolver_iterate(s);
        Y = gsl_root_fsolver_root(s);
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                   0.0, 1e-13) == GSL_SUCCESS)
            break;
    }
    gsl_root_fsolver_free(s);
    acbb_gsl_leave();
    return Y;
}

double acbb_wooster_alpha(double eta)
{
    return (0.6 + 0.965 * log10(eta * 1e3)) * 1e-8;
}

/* oil density at 40 C by the law of lubrication.c (MODEL.md 5) */
static double rho40(const acbb_scene *s)
{
    return s->oil_density * (1.0 - 6.5e-4 * (40.0 - 20.0));
}

void acbb_lubricant_apply(acbb_scene *s)
{
    acbb_scene d;
    acbb_scene_default(&d);
    double nu40 = acbb_grade_midpoint(s->oil_grade) * 1e-6;
    if (s->lub_method == ACBB_LUB_GREASE && s->grease_nu40 > 0.0) nu40 = s->grease_nu40;
    if (nu40 <= 0.0) return; /* custom oil, no grease base oil: as given */
    if (s->oil_nu40 == d.oil_nu40) s->oil_nu40 = nu40;
    if (s->oil_nu100 == d.oil_nu100)
        s->oil_nu100 = acbb_nu100_from_vi(s->oil_nu40 * 1e6, s->oil_vi) * 1e-6;
    if (s->oil_alpha_pv == d.oil_alpha_pv)
        s->oil_alpha_pv = acbb_wooster_alpha(rho40(s) * s->oil_nu40);
}

acbb_status acbb_lubricant_explain(const acbb_scene *s, acbb_status rc, acbb_error *err)
{
    if (rc == ACBB_OK || !err || acbb_grade_midpoint(s->oil_grade) <= 0.0 ||
        strncmp(err->msg, "lubricant.oil_", 14) != 0)
        return rc;
    char was[sizeof err->msg];
    snprintf(was, sizeof was, "%s", err->msg);
    return acbb_error_set(err, rc, "lubricant.grade = VG%g with lubricant.viscosity_index = %g "
                          "derives %s: choose a higher grade or viscosity index, "
                          "or set that key", acbb_grade_midpoint(s->oil_grade), s->oil_vi, was);
}
