/* acbb — thermal and centrifugal expansion (MODEL.md section 7, seed eqs
 * 1-11). All results are radial displacements (radius changes), m. */
#include "expansion.h"
#include "geometry.h"

#include <math.h>
#include <string.h>

/* Eq (1): ball radius growth. */
double acbb_expansion_ball(double chi, double dT, double D)
{
    return chi * dT * 0.5 * D;
}

/* Eq (3), cleaned form: free growth of the raceway radius r_race plus the
 * shaft interaction through the bore radius r_bore. */
double acbb_expansion_inner(double chi_i, double dT_i, double chi_s, double dT_s,
                            double nu_s, double r_bore, double r_race)
{
    return chi_i * dT_i * r_race +
           (chi_s * dT_s * (1.0 + nu_s) - chi_i * dT_i) * r_bore * r_bore / r_race;
}

/* Eq (4): the OR raceway follows the housing bore of radius r_h. */
double acbb_expansion_outer(double chi_h, double dT_h, double nu_h, double r_h)
{
    return chi_h * dT_h * (1.0 + nu_h) * r_h;
}

/* Eq (9): outer-surface displacement of a free rotating annular disc in
 * plane stress [TG]; r_outer is the IR raceway radius. */
double acbb_expansion_centrifugal(double rho, double omega, double E, double nu,
                                  double r_bore, double r_outer)
{
    return rho * omega * omega * r_outer / (4.0 * E) *
           ((3.0 + nu) * r_bore * r_bore + (1.0 - nu) * r_outer * r_outer);
}

/* IR raceway radius r_il = d_i/2, d_i = dm - D - Pd/2 with the unmounted
 * clearance Pd (given, or 2 A0 (1 - cos alpha0), A0 = lambda_i + lambda_o
 * - D; MODEL.md section 1; 7008C: d_i = 47.633 mm). */
static double inner_raceway_radius(const acbb_scene *s)
{
    return 0.5 * (s->pitch_diameter - s->ball_diameter - 0.5 * acbb_diametral_clearance(s));
}

void acbb_expansion_compute(const acbb_scene *s, const acbb_part_temps *t,
                            acbb_expansion *out)
{
    double r_bore = 0.5 * s->bore;
    double r_il = inner_raceway_radius(s);

    memset(out, 0, sizeof *out);
    /* WTE forces every expansion to 0, the centrifugal one included: the
     * seed's WTE model has none of eqs (1)-(11) (MODEL.md sections 9, 12). */
    if (!s->thermal_expansion)
        return;
    {
        double dT_b = t->ball - s->ambient_C;
        double dT_i = t->inner_ring - s->ambient_C;
        double dT_s = t->shaft - s->ambient_C;
        double dT_h = t->housing - s->ambient_C;
        out->ball = acbb_expansion_ball(s->ball.chi, dT_b, s->ball_diameter);
        out->inner = acbb_expansion_inner(s->ring.chi, dT_i, s->shaft.chi, dT_s,
                                          s->shaft.nu, r_bore, r_il);
        /* SEED: the seed prints the bore radius in eq (3)'s first term. */
        if (s->geometry == ACBB_GEOM_SEED)
            out->inner -= s->ring.chi * dT_i * (r_il - r_bore);
        out->outer = acbb_expansion_outer(s->housing.chi, dT_h, s->housing.nu,
                                          0.5 * s->outer_diameter);
    }
    if (s->ring_centrifugal)
        out->inner_cen = acbb_expansion_centrifugal(s->ring.rho, s->inner_speed,
                                                    s->ring.E, s->ring.nu,
                                                    r_bore, r_il);
}

/* SEED projections, eqs (5)-(8), (10)-(11) with the operating angles. */
void acbb_expansion_seed_project(const acbb_expansion *e, double alpha_i,
                                 double alpha_o, acbb_seed_projection *p)
{
    p->onl = e->outer * cos(alpha_o);
    p->inl = p->onl * cos(alpha_i - alpha_o);
    p->ix = p->inl * sin(alpha_i);
    p->iz = p->inl * cos(alpha_i);
    p->bax = e->ball * sin(alpha_i);
    p->baz = e->ball * cos(alpha_i);
}
