/* acbb — pieces of the mechanics API that need no solver state: the
 * closed-form static thrust angle (an independent reference for the tests
 * and the initial guess), the loss/traction view of one contact and the
 * inputs that decide whether a ball's results can be kept (mechanics.h).
 * Kept apart from the equilibrium solver in mechanics.c. */
#include <math.h>
#include <stddef.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include "mechanics.h"

static double thrust_closed_form(double a, void *p)
{
    const double *q = p; /* Fx, Z, Kn, A0, alpha0 */
    double c = cos(q[4]) / cos(a) - 1.0;
    return q[1] * q[2] * pow(q[3], 1.5) * pow(fmax(c, 0.0), 1.5) * sin(a) - q[0];
}

double acbb_static_thrust_angle(double Fx, int Z, double Kn, double A0, double alpha0)
{
    double q[5] = { Fx, (double)Z, Kn, A0, alpha0 };
    if (Fx <= 0.0) return alpha0;
    gsl_function F = { thrust_closed_form, q };
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return NAN;
    double lo = alpha0, hi = 0.5 * M_PI - 1e-9, r = NAN;
    if (gsl_root_fsolver_set(s, &F, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < 200; it++) {
            if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
            r = gsl_root_fsolver_root(s);
            if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s),
                                       gsl_root_fsolver_x_upper(s), 1e-15, 1e-14) == GSL_SUCCESS)
                break;
        }
    }
    gsl_root_fsolver_free(s);
    return r;
}

void acbb_mech_contact_input(const acbb_geometry *g, const acbb_ball_state *b, int inner,
                             double omega_i, acbb_contact_in *c)
{
    const acbb_hertz_const *hc = inner ? &b->hc_i : &b->hc_o;
    const acbb_hertz_contact *ct = inner ? &b->ct_i : &b->ct_o;
    c->inner = inner;
    c->Q = ct->Q;
    c->a = ct->a;
    c->b = ct->b;
    c->pmax = ct->pmax;
    c->delta = inner ? b->delta_i : b->delta_o;
    c->alpha = inner ? b->alpha_i : b->alpha_o;
    c->f = inner ? g->f_i : g->f_o;
    c->D = g->D;
    c->dm = g->dm;
    c->Rx = hc->Rx;
    c->kappa = hc->kappa;
    c->E_eff = hc->E_eff;
    c->roll = inner ? b->kin.roll_i : b->kin.roll_o;
    c->race = inner ? omega_i - b->kin.omega_m : -b->kin.omega_m;
    c->spin = inner ? b->kin.spin_i : b->kin.spin_o;
    c->pivot = b->kin.wy;
    c->u = inner ? b->kin.u_i : b->kin.u_o;
    c->omega_m = b->kin.omega_m;
}

void acbb_ball_inputs(const acbb_ball_state *b, double eta0_i, double eta0_o, double omega_i,
                      double in[ACBB_BALL_INPUTS])
{
    double w = omega_i > 0.0 ? omega_i : 1.0;
    in[0] = b->Qi; in[1] = b->Qo; in[2] = b->alpha_i; in[3] = b->alpha_o;
    in[4] = eta0_i; in[5] = eta0_o;
    if (b->traction_valid) {
        for (int d = 0; d < 4; d++) in[6 + d] = b->qd_w[d] / w;
    } else {
        in[6] = b->kin.omega_m / w; in[7] = b->kin.wx / w;
        in[8] = b->kin.wy / w; in[9] = b->kin.wz / w;
    }
}

const double acbb_ball_loss_weights[ACBB_BALL_INPUTS] = { 1, 1, 3, 3, 1, 1, 100, 100, 100, 100 };

double acbb_ball_moved(const double from[ACBB_BALL_INPUTS], const double to[ACBB_BALL_INPUTS],
                       const double *weight)
{
    double d = 0.0;
    for (int k = 0; k < ACBB_BALL_INPUTS; k++) {
        /* Angles (2, 3) in radians and the scaled speeds (6..9) absolute. */
        int absolute = k == 2 || k == 3 || k >= 6;
        double scale = absolute ? 1.0 : fmax(fabs(from[k]), 1e-300);
        d = fmax(d, (weight ? weight[k] : 1.0) * fabs(to[k] - from[k]) / scale);
    }
    return d;
}

void acbb_mech_state_copy(acbb_mech_state *dst, const acbb_mech_state *src)
{
    /* Only the balls in use: the array is sized for the largest bearing. */
    memcpy(dst, src, offsetof(acbb_mech_state, ball));
    memcpy(dst->ball, src->ball, sizeof src->ball[0] * (size_t)src->n);
}
