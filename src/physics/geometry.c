/* acbb — derived geometry (MODEL.md section 1) and thermal offsets of the
 * compatibility equations (MODEL.md section 3, seed eqs 12-13). */
#include <math.h>
#include "geometry.h"
#include "hertz.h"

static double groove_centre_distance(const acbb_scene *s)
{
    return s->inner_groove_radius + s->outer_groove_radius - s->ball_diameter;
}

double acbb_diametral_clearance(const acbb_scene *s)
{
    if (s->clearance > 0.0) return s->clearance;
    /* cos(alpha0) = 1 - Pd / (2 A0)  [HK-EC] */
    return 2.0 * groove_centre_distance(s) * (1.0 - cos(s->contact_angle0));
}

double acbb_free_contact_angle(const acbb_scene *s)
{
    if (!(s->clearance > 0.0)) return s->contact_angle0;
    double A0 = groove_centre_distance(s);
    if (!(A0 > 0.0)) return s->contact_angle0; /* refused by the groove rules */
    return acos(fmax(-1.0, 1.0 - s->clearance / (2.0 * A0)));
}

void acbb_geometry_init(const acbb_scene *s, acbb_geometry *g)
{
    g->D = s->ball_diameter;
    g->dm = s->pitch_diameter;
    g->Z = s->n_balls;
    g->lambda_i = s->inner_groove_radius;
    g->lambda_o = s->outer_groove_radius;
    g->f_i = g->lambda_i / g->D;
    g->f_o = g->lambda_o / g->D;
    g->A0 = g->lambda_i + g->lambda_o - g->D;
    g->alpha0 = acbb_free_contact_angle(s);
    g->Pd = acbb_diametral_clearance(s);
    g->d_i = g->dm - g->D - 0.5 * g->Pd;
    g->d_o = g->dm + g->D + 0.5 * g->Pd;
    g->Re_i = 0.5 * g->d_i + g->lambda_i;
    g->Re_o = 0.5 * g->d_o - g->lambda_o;
    g->E_eff = acbb_effective_modulus(s->ball.E, s->ball.nu, s->ring.E, s->ring.nu);
    g->mass = s->ball.rho * M_PI * g->D * g->D * g->D / 6.0;
    g->J = g->mass * g->D * g->D / 10.0;
}

void acbb_geometry_offsets(const acbb_geometry *g, acbb_geom_mode mode,
                           const acbb_expansion *e, double alpha_i, double alpha_o,
                           acbb_thermal_offsets *out)
{
    out->A0 = g->A0;
    out->dA1 = 0.0;
    out->dA2 = 0.0;
    out->dL_i = out->dL_o = 0.0;
    if (!e)
        return;
    if (mode == ACBB_GEOM_CLEAN) {
        /* Each displacement counted once: IR growth and centrifugal growth
         * push the inner groove centre out, OR growth relieves, ball growth
         * shortens both groove-to-ball-centre lengths. */
        out->dA2 = e->inner + e->inner_cen - e->outer;
        out->dL_i = out->dL_o = e->ball;
        return;
    }
    /* SEED: literal eqs (12)-(13) with the projections of eqs (5)-(11). */
    acbb_seed_projection p;
    acbb_expansion_seed_project(e, alpha_i, alpha_o, &p);
    double fi = g->lambda_i / (g->D + e->ball), fo = g->lambda_o / (g->D + e->ball);
    out->A0 = (fi + fo - 1.0) * g->D;
    out->dA1 = p.bax + p.ix;
    out->dA2 = e->inner + e->inner_cen - p.baz - p.iz;
    /* L = (f' - 1/2) D + delta - theta_ba: relative to lambda - D/2 this is
     * an extra shortening of (f - f') D plus theta_ba. */
    out->dL_i = e->ball + (g->f_i - fi) * g->D;
    out->dL_o = e->ball + (g->f_o - fo) * g->D;
}
