/* acbb — power losses per contact, MODEL.md section 6 (seed eqs 14-18,
 * cleaned). The integrals run over the contact ellipse mapped to the unit
 * square: x'' = a xi, y'' = b sqrt(1-xi^2) t, dA = ab sqrt(1-xi^2) dxi dt,
 * p = pmax sqrt(1-xi^2) sqrt(1-t^2). */
#include <math.h>
#include <gsl/gsl_integration.h>
#include "acbb/losses.h"

acbb_status acbb_quad_init(acbb_quad *q, int n)
{
    if (n < 1 || n > ACBB_QUAD_MAX)
        return ACBB_EINVAL;
    gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc((size_t)n);
    if (!t)
        return ACBB_ENOMEM;
    q->n = n;
    for (int i = 0; i < n; i++)
        gsl_integration_glfixed_point(-1.0, 1.0, (size_t)i, &q->x[i], &q->w[i], t);
    gsl_integration_glfixed_table_free(t);
    return ACBB_OK;
}

/* Height of the deformed contact surface above the ball centre at x''
 * (MODEL.md section 4): the pressure surface has radius R_d = 2fD/(2f+1). */
static double surface_height(const acbb_contact_in *c, double x)
{
    double Rd = 2.0 * c->f * c->D / (2.0 * c->f + 1.0);
    double a2 = c->a * c->a;
    return sqrt(fmax(Rd * Rd - x * x, 0.0)) - sqrt(fmax(Rd * Rd - a2, 0.0))
         + sqrt(fmax(0.25 * c->D * c->D - a2, 0.0));
}

double acbb_slip_velocity(const acbb_contact_in *c, double x)
{
    /* V = s h w_roll + w_race (r_m + s h cos(alpha)), s = +1 outer, -1 inner:
     * ball surface speed minus race surface speed in the rolling direction. */
    double sg = c->inner ? -1.0 : 1.0;
    double h = surface_height(c, x);
    return sg * h * c->roll + c->race * (0.5 * c->dm + sg * h * cos(c->alpha));
}

double acbb_slip_speed(const acbb_contact_in *c, double x)
{
    double V = acbb_slip_velocity(c, x);
    if (c->pivot == 0.0) return fabs(V);
    return hypot(V, c->pivot * surface_height(c, x));
}

acbb_status acbb_contact_losses(const acbb_scene *s, const acbb_quad *q,
                                const acbb_contact_in *c, const acbb_oil_state *oil,
                                acbb_contact_loss *out)
{
    *out = (acbb_contact_loss){ 0 };
    if (c->Q <= 1e-6 || c->a <= 0.0 || c->b <= 0.0) {
        out->film.phi_a = 1.0;
        out->film.phi_T = 1.0;
        return ACBB_OK;
    }
    double u = fabs(c->u);
    double V0 = acbb_slip_speed(c, 0.0);
    double srr = u > 1e-6 ? fmin(fabs(V0) / u, 2.0) : 0.0;
    acbb_film_compute(s, oil, u, c->Q, c->Rx, c->kappa, c->E_eff, c->pmax, srr, &out->film);
    const acbb_film *fl = &out->film;
    int seed = s->loss_form == ACBB_LOSS_SEED;
    int fluid = fl->phi_f > 0.0;
    int do_L = s->loss_shear && fluid, do_t = s->loss_slip, do_s = s->loss_spin;
    double H = fl->hc, mu = s->mu_bd, ab = c->a * c->b;
    double sumL = 0, sumT = 0, sumS = 0, sumPV = 0, sumP = 0;

    for (int i = 0; i < q->n; i++) {
        double xi = q->x[i], sq = sqrt(1.0 - xi * xi);
        double x = c->a * xi;
        double V = acbb_slip_speed(c, x);
        for (int k = 0; k < q->n; k++) {
            double t = q->x[k];
            double w = q->w[i] * q->w[k] * ab * sq;   /* dA */
            double p = c->pmax * sq * sqrt(1.0 - t * t);
            double eta = fluid ? acbb_viscosity_at_pressure(s, oil, p) : 0.0;
            double tauV = fluid ? acbb_tau_lubricant(s, eta, V, H, p) : 0.0;
            sumP += p * w;
            sumPV += p * V * w;
            if (do_L)
                sumL += (seed ? tauV : fl->phi_f * tauV * V) * w;
            if (do_t)
                sumT += (seed ? (fl->phi_a * mu * p + fl->phi_f * tauV) * V
                              : fl->phi_a * mu * p * V) * w;
            if (do_s) {
                double y = c->b * sq * t, r = hypot(x, y);
                double us = fabs(c->spin) * r;
                double tauS = fluid ? acbb_tau_lubricant(s, eta, us, H, p) : 0.0;
                sumS += (fl->phi_a * mu * p + fl->phi_f * tauS) * r * w;
            }
        }
    }
    out->slide = sumP > 0.0 ? sumPV / sumP : 0.0;
    /* Seed eq (14) multiplies a force by omega_m D; kept only as an option. */
    out->P_L = do_L ? (seed ? sumL * fabs(c->omega_m) * c->D : sumL) : 0.0;
    out->P_t = do_t ? sumT : 0.0;
    out->P_s = do_s ? fabs(c->spin) * sumS : 0.0;
    if (s->loss_rolling) {
        /* Johnson's hysteresis force 4 eps Q a_c / (3 pi D) [J section 9]. */
        double ac = s->hyst_axis == ACBB_HYST_MINOR ? c->b : c->a;
        if (seed) {
            double arm = c->dm + (c->inner ? -2.0 : 2.0) * c->delta;
            out->P_r = 2.0 * s->hysteresis * c->Q * ac * arm / (3.0 * M_PI * c->D)
                     * fabs(c->omega_m);
        } else {
            out->P_r = 4.0 * s->hysteresis * c->Q * ac / (3.0 * M_PI * c->D) * u;
        }
    }
    if (!isfinite(out->P_L) || !isfinite(out->P_t) || !isfinite(out->P_s)
        || !isfinite(out->P_r))
        return ACBB_NONFINITE;
    return ACBB_OK;
}

double acbb_drag_force(const acbb_scene *s, const acbb_mixture *mix, double omega_m)
{
    double v = omega_m * s->pitch_diameter;
    return M_PI / 32.0 * s->drag_cd * mix->rho * s->ball_diameter * s->ball_diameter * v * v;
}

double acbb_drag_loss(const acbb_scene *s, const acbb_mixture *mix, double omega_m)
{
    return s->n_balls * fabs(omega_m) * acbb_drag_force(s, mix, omega_m)
         * 0.5 * s->pitch_diameter;
}
