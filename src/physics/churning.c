/* acbb — churning (oil bath) and jet momentum (oil jet), MODEL.md 16.
 *
 * Oil bath: the drag of MODEL.md 6 (ii) with the bath as the medium, for
 * the share of the balls that is immersed: P = f Z F_D v, F_D = 1/2 C_D
 * rho_oil (pi D^2/4) v^2, v = omega_m d_m/2 (the orbital speed, as [S-15]),
 * C_D(Re) the sphere curve of Clift & Gauvin (1970, Re < 3e5; in oil Re is
 * far below the air drag's 1e3-2e5). f is the immersed ball volume
 * averaged over the orbit, the lowest ball centre D/2 above the lowest
 * point of the outer raceway. The air drag P_v covers the rest (1 - f).
 * Oil jet: the balls and cage take the jet oil from its exit speed
 * v_jet (aimed along the rotation) to the orbital speed v; Euler's
 * turbomachine equation gives the shaft power rho q v (v - v_jet), >= 0.
 * Oil-air and grease: no bulk oil, 0. */
#include <math.h>
#include <gsl/gsl_integration.h>
#include "churning.h"

#define ORBIT_POINTS 64

/* immersed volume fraction of a sphere of radius R whose bottom is `depth`
 * below the level (spherical cap) */
static double cap_fraction(double depth, double R)
{
    double h = fmin(fmax(depth, 0.0), 2.0 * R);
    return h * h * (3.0 * R - h) / (4.0 * R * R * R);
}

double acbb_bath_immersion(const acbb_scene *s)
{
    if (s->lub_method != ACBB_LUB_OIL_BATH || !(s->bath_level > 0.0)) return 0.0;
    double R = 0.5 * s->ball_diameter, rm = 0.5 * s->pitch_diameter;
    gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc(ORBIT_POINTS);
    if (!t) return NAN;
    double sum = 0.0;
    for (size_t i = 0; i < ORBIT_POINTS; i++) {
        double psi, w;
        gsl_integration_glfixed_point(0.0, M_PI, i, &psi, &w, t);
        double bottom = rm * (1.0 - cos(psi));   /* ball bottom above the raceway bottom */
        sum += w * cap_fraction(s->bath_level - bottom, R);
    }
    gsl_integration_glfixed_table_free(t);
    return sum / M_PI;  /* the orbit is symmetric about the lowest point */
}

double acbb_sphere_cd(double Re)
{
    if (!(Re > 0.0)) return 0.0;
    return 24.0 / Re * (1.0 + 0.15 * pow(Re, 0.687)) + 0.42 / (1.0 + 4.25e4 * pow(Re, -1.16));
}

static double bath_loss(const acbb_scene *s, const acbb_oil_state *oil, double v)
{
    double f = acbb_bath_immersion(s);
    if (!(f > 0.0) || !(oil->eta0 > 0.0)) return 0.0;
    double D = s->ball_diameter;
    double Re = oil->rho * v * D / oil->eta0;
    double F = 0.5 * acbb_sphere_cd(Re) * oil->rho * 0.25 * M_PI * D * D * v * v;
    return f * s->n_balls * F * v;
}

double acbb_churning_loss(const acbb_scene *s, const acbb_oil_state *oil, double omega_m)
{
    double v = fabs(omega_m) * 0.5 * s->pitch_diameter;
    if (s->lub_method == ACBB_LUB_OIL_BATH) return bath_loss(s, oil, v);
    if (s->lub_method == ACBB_LUB_OIL_JET)
        return fmax(0.0, oil->rho * s->q_oil * v * (v - s->jet_speed));
    return 0.0;
}
