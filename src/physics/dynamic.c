/* acbb — dynamic ball model, see dynamic.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include "dynamic.h"
#include "acbb/limits.h"
#include "dynamic_priv.h"
#include "cancel.h"

#define NY 8          /* X1, X2 (um), V1, V2 (mm/s), wm, wx, wy, wz (/omega_i) */
#define FD_STEP 1e-7
#define TOL ACBB_DYN_RTOL /* rtol = atol of the BDF stepper on the scaled states (dynamic.h) */
#define SETTLED 1e-6  /* a skipped ball's last window moved omega_m less than this */

struct acbb_dyn {
    int grid, threads, alloc;   /* workers in use; tables allocated for `alloc` */
    acbb_traction_contact ci[ACBB_DYN_MAX_THREADS], co[ACBB_DYN_MAX_THREADS];
    long windows[ACBB_DYN_MAX_THREADS]; /* integrated by each worker (acbb_dyn_windows) */
    const atomic_int *cancel;   /* caller's flag, checked in every rhs call */
    acbb_dyn_stop_fn stop;      /* caller's bound (acbb_dyn_set_stop), or NULL */
    const void *stop_ctx;
    double skip_tol;            /* 0: every call integrates (see acbb_dyn_set_skip) */
    /* Inputs of each ball's last window and the relative move of omega_m
     * it made; in_ok[j] = 0: none yet. */
    double in[ACBB_MAX_BALLS][ACBB_BALL_INPUTS], last[ACBB_MAX_BALLS];
    int in_ok[ACBB_MAX_BALLS];
};

typedef struct {
    acbb_traction_contact *ci, *co; /* the worker's tables */
    const atomic_int *cancel;
    acbb_dyn_stop_fn stop;
    const void *stop_ctx;
    const acbb_geometry *g;
    const acbb_scene *s;
    const acbb_quad *quad;
    const acbb_oil_state *oil_i, *oil_o;
    const acbb_mixture *mix;
    acbb_ball_state b;        /* scratch: contact state at the current y */
    acbb_ball_frame fr;
    double omega_i;
    acbb_traction tri, tro;   /* at the last evaluation */
} dyn_ctx;

/* Contact load and its damping along one normal; returns the normal force
 * magnitude (>= 0) and fills the Hertz contact. */
static double contact(const acbb_hertz_const *hc, double delta, double rate, double mass,
                      acbb_hertz_contact *ct)
{
    acbb_hertz_from_deflection(hc, delta, ct);
    if (delta <= 0.0) return 0.0;
    double k = 1.5 * hc->Kc * sqrt(delta);
    double c = 2.0 * ACBB_DYN_DAMPING * sqrt(k * mass);
    return fmax(ct->Q + c * rate, 0.0);
}

/* Ball position, contact deflections and normal forces at state y. */
static void contacts_at(dyn_ctx *c, const double y[], double *Fi, double *Fo)
{
    const acbb_geometry *g = c->g;
    acbb_ball_state *b = &c->b;
    double X1 = y[0] * 1e-6, X2 = y[1] * 1e-6, V1 = y[2] * 1e-3, V2 = y[3] * 1e-3;
    double Lo = hypot(X1, X2), xi = c->fr.A1 - X1, zi = c->fr.A2 - X2, Li = hypot(xi, zi);
    b->alpha_o = atan2(X1, X2);
    b->alpha_i = atan2(xi, zi);
    b->delta_o = Lo - c->fr.L0_o;
    b->delta_i = Li - c->fr.L0_i;
    double rate_o = (X1 * V1 + X2 * V2) / Lo, rate_i = -(xi * V1 + zi * V2) / Li;
    *Fo = contact(&b->hc_o, b->delta_o, rate_o, g->mass, &b->ct_o);
    *Fi = contact(&b->hc_i, b->delta_i, rate_i, g->mass, &b->ct_i);
    b->Qi = b->ct_i.Q;
    b->Qo = b->ct_o.Q;
}

/* Traction point tables (film, grid, pressure-viscosity; MODEL.md
 * sections 4-5) of both contacts, prepared once at the window's start
 * state y and held over the window. Why: re-preparing them in every rhs
 * was half the cost, and it made the rhs carry the film's and the
 * viscosity's small variations, so the BDF error test held steps to ~1 us
 * at any tolerance; held tables make the rhs smooth in y (steps then
 * follow the tolerance). The normal forces stay exact in every rhs; what
 * is held within a window is the traction's dependence on the instantaneous
 * load and entrainment speed, which move by < 1e-4 relative over a warm
 * window. Refreshing them per accepted step instead (tried) makes the rhs
 * jump between steps: ~40x the CPU. At the fixed point (a window that
 * starts at its own average) the tables are exact, so the answer is the
 * same fixed point: BENCHMARKS.md gives the measured difference. */
static int start_tables(dyn_ctx *c, const double y[])
{
    double Fi, Fo;
    contacts_at(c, y, &Fi, &Fo);
    const acbb_geometry *g = c->g;
    acbb_ball_state *b = &c->b;
    double wi = c->omega_i;
    acbb_kinematics_from_omega(b->alpha_i, b->alpha_o, g->D, g->dm, wi, y[4] * wi, y[5] * wi,
                               y[6] * wi, y[7] * wi, &b->kin);
    acbb_contact_in ci;
    for (int inner = 0; inner < 2; inner++) {
        acbb_mech_contact_input(g, b, inner, wi, &ci);
        acbb_film film;
        double u = fabs(ci.u), srr = u > 1e-6 ? fmin(acbb_slip_speed(&ci, 0.0) / u, 2.0) : 0.0;
        acbb_traction_contact *tc = inner ? c->ci : c->co;
        const acbb_oil_state *oil = inner ? c->oil_i : c->oil_o;
        acbb_film_compute(c->s, oil, u, ci.Q, ci.Rx, ci.kappa, ci.E_eff, ci.pmax, srr, &film);
        if (acbb_traction_prepare(c->s, c->quad, &ci, &film, oil, tc) != ACBB_OK)
            return GSL_EBADFUNC;
    }
    return GSL_SUCCESS;
}

static int rhs(double t, const double y[], double dydt[], void *p)
{
    (void)t;
    dyn_ctx *c = p;
    /* A window can take seconds: GSL's driver stops at once on a failed rhs. */
    if (acbb_cancelled(c->cancel) || (c->stop && c->stop(c->stop_ctx))) return GSL_EBADFUNC;
    const acbb_geometry *g = c->g;
    acbb_ball_state *b = &c->b;
    double wi = c->omega_i, mass = g->mass, X2 = y[1] * 1e-6, V1 = y[2] * 1e-3, V2 = y[3] * 1e-3;
    double wm = y[4] * wi, wb[3] = { y[5] * wi, y[6] * wi, y[7] * wi }, Fi, Fo;
    contacts_at(c, y, &Fi, &Fo);
    acbb_traction_eval(c->s, c->ci, wb, wi - wm, &c->tri);
    acbb_traction_eval(c->s, c->co, wb, -wm, &c->tro);
    double r = g->Re_o + X2;
    double Fv = c->s->loss_drag ? acbb_drag_force(c->s, c->mix, wm) : 0.0;
    /* Meridional forces: normals (inner pushes out along +n, outer in),
     * tractions, centrifugal force of the orbiting frame. */
    double Fx = Fi * sin(b->alpha_i) - Fo * sin(b->alpha_o) + c->tri.F[0] + c->tro.F[0];
    double Fz = Fi * cos(b->alpha_i) - Fo * cos(b->alpha_o) + c->tri.F[2] + c->tro.F[2]
              + (c->s->centrifugal ? mass * r * wm * wm : 0.0);
    double Fy = c->tri.F[1] + c->tro.F[1] + Fv;
    /* Orbit: d(m r^2 wm)/dt = -r Fy (motion is along -y'), Coriolis included. */
    double dwm = (-Fy - 2.0 * mass * V2 * wm) / (mass * r);
    /* Rotation in the orbiting frame: J dw/dt = M - J wm e_x x w - J dwm/dt e_x. */
    double J = g->J, gy = c->s->gyroscopic ? 1.0 : 0.0;
    double M[3] = { c->tri.M[0] + c->tro.M[0], c->tri.M[1] + c->tro.M[1],
                    c->tri.M[2] + c->tro.M[2] };
    double dw[3] = { (M[0] - J * dwm) / J, (M[1] + gy * J * wm * wb[2]) / J,
                     (M[2] - gy * J * wm * wb[1]) / J };
    dydt[0] = V1 * 1e6;
    dydt[1] = V2 * 1e6;
    dydt[2] = Fx / mass * 1e3;
    dydt[3] = Fz / mass * 1e3;
    dydt[4] = dwm / wi;
    for (int k = 0; k < 3; k++) dydt[5 + k] = dw[k] / wi;
    for (int k = 0; k < NY; k++)
        if (!isfinite(dydt[k])) return GSL_EBADFUNC;
    return GSL_SUCCESS;
}

/* Finite-difference Jacobian (the BDF stepper needs one; the traction
 * field has no convenient closed-form derivative). */
static int jac(double t, const double y[], double *dfdy, double dfdt[], void *p)
{
    double f0[NY], f1[NY], yy[NY];
    int rc = rhs(t, y, f0, p);
    if (rc != GSL_SUCCESS) return rc;
    for (int j = 0; j < NY; j++) {
        memcpy(yy, y, sizeof yy);
        double h = FD_STEP * fmax(fabs(y[j]), 1.0);
        yy[j] += h;
        if ((rc = rhs(t, yy, f1, p)) != GSL_SUCCESS) return rc;
        for (int i = 0; i < NY; i++) dfdy[i * NY + j] = (f1[i] - f0[i]) / h;
    }
    for (int i = 0; i < NY; i++) dfdt[i] = 0.0;
    return GSL_SUCCESS;
}

acbb_status acbb_dyn_new(int grid, acbb_dyn **out)
{
    acbb_dyn *d = calloc(1, sizeof *d);
    if (!d) return ACBB_ENOMEM;
    d->grid = grid;
    if (acbb_dyn_set_threads(d, 1) != ACBB_OK) {
        acbb_dyn_free(d);
        return ACBB_ENOMEM;
    }
    *out = d;
    return ACBB_OK;
}

acbb_status acbb_dyn_set_threads(acbb_dyn *d, int n)
{
    if (n < 1 || n > ACBB_DYN_MAX_THREADS) return ACBB_EINVAL;
    /* A worker whose second table failed keeps its first (freed by
     * acbb_dyn_free, or used by a later call that gets the second). */
    for (; d->alloc < n; d->alloc++) {
        acbb_traction_contact *ci = &d->ci[d->alloc], *co = &d->co[d->alloc];
        if ((!ci->P && acbb_traction_contact_init(ci, d->grid) != ACBB_OK)
            || (!co->P && acbb_traction_contact_init(co, d->grid) != ACBB_OK))
            return ACBB_ENOMEM;
    }
    d->threads = n;
    return ACBB_OK;
}

int acbb_dyn_threads(const acbb_dyn *d)
{
    return d->threads;
}

void acbb_dyn_set_cancel(acbb_dyn *d, const atomic_int *cancel)
{
    d->cancel = cancel;
}

void acbb_dyn_set_stop(acbb_dyn *d, acbb_dyn_stop_fn stop, const void *ctx)
{
    d->stop = stop;
    d->stop_ctx = ctx;
}

void acbb_dyn_set_skip(acbb_dyn *d, double tol)
{
    d->skip_tol = tol > 0.0 ? tol : 0.0;
}

/* A window's inputs are the quasi-dynamic skip's (acbb_ball_inputs: both
 * loads, angles and inlet viscosities, MODEL.md section 4) without the ball
 * speeds, which are the window's own result. */
static const double k_window_weights[ACBB_BALL_INPUTS] = { 1, 1, 1, 1, 1, 1, 0, 0, 0, 0 };

/* A ball may keep its averaged speeds only if its last window had already
 * settled (moved omega_m by less than the tolerance) and its inputs have
 * not moved since: the fixed point it relaxes to is then the same. */
static int skip_ball(const acbb_dyn *d, int j, const acbb_ball_state *b,
                     const double in[ACBB_BALL_INPUTS])
{
    return d->skip_tol > 0.0 && j < ACBB_MAX_BALLS && d->in_ok[j] && b->traction_valid
        && d->last[j] < SETTLED && acbb_ball_moved(d->in[j], in, k_window_weights) < d->skip_tol;
}

long acbb_dyn_windows(const acbb_dyn *d)
{
    long n = 0;
    for (int w = 0; w < ACBB_DYN_MAX_THREADS; w++) n += d->windows[w];
    return n;
}

void acbb_dyn_free(acbb_dyn *d)
{
    if (!d) return;
    for (int w = 0; w < ACBB_DYN_MAX_THREADS; w++) {
        acbb_traction_contact_free(&d->ci[w]);
        acbb_traction_contact_free(&d->co[w]);
    }
    free(d);
}

acbb_status acbb_dyn_ball(acbb_dyn *d, acbb_mech *m, const acbb_scene *s,
                          const acbb_quad *quad, double omega_i,
                          const acbb_oil_state *oil_i, const acbb_oil_state *oil_o,
                          const acbb_mixture *mix, acbb_mech_state *st, int j,
                          double window, double *change, acbb_error *err)
{
    acbb_dyn_env env = { m, s, quad, omega_i, oil_i, oil_o, mix };
    return acbb_dyn_ball_on(d, 0, &env, st, j, window, change, err);
}

/* Ball j on worker w's tables (the skip record of ball j is only touched by
 * the worker that has ball j). */
acbb_status acbb_dyn_ball_on(acbb_dyn *d, int w, const acbb_dyn_env *env, acbb_mech_state *st,
                             int j, double window, double *change, acbb_error *err)
{
    acbb_ball_state *b = &st->ball[j];
    double omega_i = env->omega_i;
    *change = 0.0;
    if (omega_i <= 0.0 || b->Qi < 1e-3 || b->Qo < 1e-3) {
        if (j < ACBB_MAX_BALLS) d->in_ok[j] = 0;
        return ACBB_OK;
    }
    double in[ACBB_BALL_INPUTS];
    acbb_ball_inputs(b, env->oil_i->eta0, env->oil_o->eta0, omega_i, in);
    if (skip_ball(d, j, b, in)) return ACBB_OK;
    d->windows[w]++;
    dyn_ctx c = { .ci = &d->ci[w], .co = &d->co[w], .cancel = d->cancel,
                  .stop = d->stop, .stop_ctx = d->stop_ctx,
                  .g = acbb_mech_geometry(env->m), .s = env->s, .quad = env->quad,
                  .oil_i = env->oil_i, .oil_o = env->oil_o, .mix = env->mix, .b = *b,
                  .omega_i = omega_i };
    acbb_mech_ball_frame(env->m, st, j, &c.fr);
    const double *w0 = b->traction_valid ? b->qd_w : NULL;
    double y[NY] = { b->X1 * 1e6, b->X2 * 1e6, 0.0, 0.0,
                     (w0 ? w0[0] : b->kin.omega_m) / omega_i, (w0 ? w0[1] : b->kin.wx) / omega_i,
                     (w0 ? w0[2] : b->kin.wy) / omega_i, (w0 ? w0[3] : b->kin.wz) / omega_i };
    gsl_odeiv2_system sys = { rhs, jac, NY, &c };
    gsl_odeiv2_driver *drv = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_msbdf,
                                                           1e-9, TOL, TOL);
    if (!drv) return acbb_error_set(err, ACBB_ENOMEM, "dynamic model: out of memory");
    gsl_odeiv2_driver_set_hmax(drv, window / 20.0);
    /* Average over the second half of the window on a fixed sample grid. */
    const int NS = 40;
    double t = 0.0, avg[NY] = { 0 }, tri[3] = { 0 }, tro[3] = { 0 }, Qi = 0, Qo = 0;
    int rc = start_tables(&c, y);
    if (rc == GSL_SUCCESS) rc = gsl_odeiv2_driver_apply(drv, &t, 0.5 * window, y);
    for (int k = 1; k <= NS && rc == GSL_SUCCESS; k++) {
        rc = gsl_odeiv2_driver_apply(drv, &t, 0.5 * window * (1.0 + (double)k / NS), y);
        double f[NY];
        if (rc == GSL_SUCCESS) rc = rhs(t, y, f, &c);
        for (int i = 0; i < NY; i++) avg[i] += y[i] / NS;
        for (int i = 0; i < 3; i++) {
            tri[i] += c.tri.F[i] / NS;
            tro[i] += c.tro.F[i] / NS;
        }
        Qi += c.b.Qi / NS;
        Qo += c.b.Qo / NS;
    }
    gsl_odeiv2_driver_free(drv);
    if (rc == GSL_EBADFUNC && acbb_cancelled(d->cancel))
        return acbb_error_set(err, ACBB_CANCELLED, "cancelled; last good state kept");
    acbb_status why = rc == GSL_EBADFUNC && d->stop ? d->stop(d->stop_ctx) : ACBB_OK;
    if (why != ACBB_OK)
        return acbb_error_set(err, why, "%s", "stopped by the run's bound; last good state kept");
    if (rc != GSL_SUCCESS)
        return acbb_error_set(err, ACBB_DIVERGED, "dynamic model: integration of ball %d failed "
                              "(GSL status %d)", j + 1, rc);
    double wm0 = b->kin.omega_m;
    for (int k = 0; k < 4; k++) b->qd_w[k] = avg[4 + k] * omega_i;
    memcpy(b->tr_i, tri, sizeof tri);
    memcpy(b->tr_o, tro, sizeof tro);
    b->tr_Qi = Qi;
    b->tr_Qo = Qo;
    b->traction_valid = 1;
    *change = fabs(b->qd_w[0] - wm0) / fmax(fabs(wm0), 1e-12);
    if (j < ACBB_MAX_BALLS) {
        memcpy(d->in[j], in, sizeof in);
        d->last[j] = *change;
        d->in_ok[j] = 1;
    }
    return ACBB_OK;
}
