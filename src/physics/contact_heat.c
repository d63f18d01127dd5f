/* acbb — contact spot resistances, stationary and moving (contact_heat.h,
 * docs/contact_heat.md). */
#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include "contact_heat.h"

/* Isothermal elliptic spot on a half space (MODEL.md 8.1 SP, [Y]):
 * R = K(e) / (2 pi k a), e = sqrt(1 - (b/a)^2), a >= b. */
double acbb_spot_r_stationary(double a, double b, double k)
{
    if (!(a > 0.0) || !(b > 0.0)) return INFINITY;
    if (b > a) {
        double t = a;
        a = b;
        b = t;
    }
    double kp = b / a, K;
    gsl_sf_result res;
    /* near e = 1 the modulus rounds to 1.0; use K ~ ln(4/k') there */
    if (kp < 1e-6 || gsl_sf_ellint_Kcomp_e(sqrt(1.0 - kp * kp), GSL_PREC_DOUBLE, &res))
        K = log(4.0 / kp);
    else
        K = res.val;
    return K / (2.0 * M_PI * k * a);
}

/* At high Pe a surface point under the spot is heated only for its passage
 * time s / v (s = distance from the leading edge), and heat flows into the
 * body one-dimensionally: Jaeger (1942), Archard (1959) "The temperature of
 * rubbing surfaces", Wear 2, 438. A uniform flux q gives the rise
 * (2 q / k) sqrt(kappa s / (pi v)); its mean over the ellipse (semi-axes a
 * across, b along the motion) is (2 q / k) sqrt(kappa / (pi v)) <sqrt s>,
 * <sqrt s> = 4 sqrt(2) B(1/2, 7/4) sqrt(b) / (3 pi). With q = Q / (pi a b):
 * R = C sqrt(kappa / (v b)) / (k a), C = 8 sqrt(2) Gamma(7/4) /
 * (3 pi^2 Gamma(9/4)) = 0.30995 (Archard's 0.31 for a circle). */
double acbb_spot_c_fast(void)
{
    return 8.0 * M_SQRT2 * tgamma(1.75) / (3.0 * M_PI * M_PI * tgamma(2.25));
}

double acbb_spot_r_fast(double a, double b, double k, double kappa, double v)
{
    if (!(a > 0.0) || !(b > 0.0) || !(v > 0.0)) return INFINITY;
    return acbb_spot_c_fast() * sqrt(kappa / (v * b)) / (k * a);
}

/* Tian & Kennedy (1994, J. Tribol. 116, 167) write the mean flash
 * temperature at every Peclet number as C / sqrt(A + Pe), which is the two
 * limits' conductances added in quadrature; the same combination here with
 * the elliptic stationary spot as the Pe -> 0 limit. */
double acbb_spot_r_moving(double a, double b, double k, double kappa, double v)
{
    double r0 = acbb_spot_r_stationary(a, b, k);
    double rf = acbb_spot_r_fast(a, b, k, kappa, v);
    if (!isfinite(r0) || !isfinite(rf)) return r0;
    return 1.0 / sqrt(1.0 / (r0 * r0) + 1.0 / (rf * rf));
}

double acbb_spot_peclet(double b, double kappa, double v)
{
    return kappa > 0.0 ? v * b / (2.0 * kappa) : 0.0;
}
