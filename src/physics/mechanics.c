/* acbb — quasi-static Jones-Harris equilibrium, MODEL.md section 3.
 *
 * Two levels as in [HK-AC]: per ball a 2x2 system in the ball-centre
 * position (X1, X2) (GSL hybrids, unknowns in micrometres so the finite-
 * difference Jacobian steps are sensible), inside a ring equilibrium over
 * the force-controlled inner-ring DOFs (GSL Brent for the common pure-thrust
 * case where every ball is identical, GSL hybrids otherwise). The ball
 * problem is a hand-written damped Newton (see ball_newton for why). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_vector.h>
#include "mechanics.h"
#include "mechanics_priv.h"
#include "losses.h"
#include "broyden.h"

#define UM 1e-6          /* ring unknowns are in um and mrad for GSL's scaling */
#define MRAD 1e-3


typedef struct {
    const acbb_mech *m;
    acbb_ball_state *b;
    double A1, A2;
    acbb_thermal_offsets off;
    double L0;              /* unloaded groove-to-ball-centre length, outer */
    double *J;              /* NULL or this ball's last Jacobian (z, a), row-major */
    int *J_ok;
    int chord;              /* transient mode: try chord steps with J first */
} ball_ctx;

/* Smoothed Hertz law s(d)^1.5, s(d) = (d + sqrt(d^2 + eps^2)) / 2 with
 * eps = 1 nm (MODEL.md section 3 "Unloaded contacts"): keeps the Jacobian
 * regular when a contact opens; changes a loaded contact by < 1e-8. */
#define SMOOTH_EPS 1e-9
/* A contact carrying less than this is open (MODEL.md section 11): the
 * smoothed law leaves ~1e-9 N on an open contact. */
#define LOADED_N 1e-6
static double pos15(double d)
{
    double s = 0.5 * (d + sqrt(d * d + SMOOTH_EPS * SMOOTH_EPS));
    return s * sqrt(s);
}

static void zeta_split(acbb_control c, acbb_race_control mode, double *zi, double *zo)
{
    if (mode == ACBB_RACE_EQUAL) { *zi = 1.0; *zo = 1.0; return; }
    if (c == ACBB_CONTROL_INNER) { *zi = 2.0; *zo = 0.0; return; }
    *zi = 0.0; *zo = 2.0;
}

/* Friction force F that a contact must supply for the gyroscopic moment,
 * limited by what friction can give (mu Q): beyond it the ball pivots
 * ("gyroscopic slip", MODEL.md section 11). The smooth minimum
 * F / (1 + (F/cap)^8)^(1/8) differs from F by < 1e-9 below cap/10 and
 * keeps the Jacobian continuous. */
static double gyro_friction(double F, double cap)
{
    if (F == 0.0) return 0.0;
    if (cap <= 0.0) return 0.0;
    double r = F / cap, r2 = r * r, r4 = r2 * r2;
    return F / pow(1.0 + r4 * r4, 0.125);
}

/* Meridional friction forces on the ball (x', z'): f[0..1] at the inner
 * contact, f[2..3] at the outer one. Race control: the gyroscopic moment
 * split by zeta along the major-axis tangents t_i = (cos ai, -sin ai),
 * outer opposite; quasi-dynamic: the traction resultants. `a`: the contact
 * angles' sines and cosines (the caller's, issue 30 lever 4). */
static void ball_friction(const acbb_mech *m, const acbb_ball_state *b,
                          const acbb_kin_angles *a, double f[4])
{
    if (b->traction_valid) {
        /* Traction scales with the contact load while the equilibrium moves
         * (exact for boundary friction); it vanishes if a contact opens. */
        double ki = b->tr_Qi > 0.0 ? b->Qi / b->tr_Qi : 0.0;
        double ko = b->tr_Qo > 0.0 ? b->Qo / b->tr_Qo : 0.0;
        f[0] = ki * b->tr_i[0]; f[1] = ki * b->tr_i[2];
        f[2] = ko * b->tr_o[0]; f[3] = ko * b->tr_o[2];
        return;
    }
    double zi, zo, mg = b->Mg / m->g.D;
    zeta_split(b->control, m->race, &zi, &zo);
    double fi = gyro_friction(zi * mg, m->mu * b->Qi), fo = gyro_friction(zo * mg, m->mu * b->Qo);
    f[0] = fi * a->ci;
    f[1] = -fi * a->si;
    f[2] = -fo * a->co;
    f[3] = fo * a->so;
}

/* Evaluate the ball at (X1, X2): loads, angles, kinematics, body forces.
 * Writes b and returns the two ball-equilibrium residuals (N). */
static void ball_eval(const ball_ctx *c, double X1, double X2, double *r1, double *r2)
{
    const acbb_mech *m = c->m;
    const acbb_geometry *g = &m->g;
    acbb_ball_state *b = c->b;
    double Lo = hypot(X1, X2);
    double xi = c->A1 - X1, zi = c->A2 - X2;
    double Li = hypot(xi, zi);
    b->X1 = X1;
    b->X2 = X2;
    b->delta_o = Lo - (g->lambda_o - 0.5 * g->D - c->off.dL_o);
    b->delta_i = Li - (g->lambda_i - 0.5 * g->D - c->off.dL_i);
    b->alpha_o = atan2(X1, X2);
    b->alpha_i = atan2(xi, zi);
    b->Qo = b->hc_o.Kc * pos15(b->delta_o);
    b->Qi = b->hc_i.Kc * pos15(b->delta_i);
    /* The angles' sines and cosines are the geometry's ratios (one set for
     * the kinematics and the balance, issue 30 lever 4). */
    acbb_kin_angles an = { b->alpha_o, xi / Li, zi / Li, X1 / Lo, X2 / Lo };
    if (!(Li > 0.0 && Lo > 0.0))
        an = (acbb_kin_angles){ b->alpha_o, sin(b->alpha_i), cos(b->alpha_i), sin(b->alpha_o),
                                cos(b->alpha_o) };
    int qd = b->traction_valid;
    if (qd)
        acbb_kinematics_from_omega_sc(&an, g->D, g->dm, m->omega, b->qd_w[0], b->qd_w[1],
                                      b->qd_w[2], b->qd_w[3], &b->kin);
    else
        acbb_kinematics_race_control_sc(&an, g->D, g->dm, m->omega, b->control, &b->kin);
    double wm = b->kin.omega_m;
    b->Fc = m->centrifugal ? g->mass * (g->Re_o + X2) * wm * wm : 0.0;
    b->Mg = m->gyroscopic ? g->J * wm * b->kin.wz : 0.0;
    double f[4];
    ball_friction(m, b, &an, f);
    *r1 = b->Qi * an.si - b->Qo * an.so + f[0] + f[2];
    *r2 = b->Qi * an.ci - b->Qo * an.co + b->Fc + f[1] + f[3];
}

/* The ball unknowns are polar about the OR groove centre: the angle a and
 * z with outer deflection delta_o = sign(z) |z|^(2/3) um, so that the outer
 * load Kc delta^1.5 is linear in z. Newton on delta itself crawls when a
 * ball is held only by the centrifugal force (delta ~ 1 nm, where delta^1.5
 * is strongly curved). */
static double z_to_delta(double z) { return copysign(pow(fabs(z), 2.0 / 3.0), z) * UM; }
static double delta_to_z(double d) { return copysign(pow(fabs(d) / UM, 1.5), d); }

static int ball_polar(const ball_ctx *c, double z, double a, double r[2])
{
    double L = c->L0 + z_to_delta(z);
    ball_eval(c, L * sin(a), L * cos(a), &r[0], &r[1]);
    return isfinite(r[0]) && isfinite(r[1]);
}

static double norm2(const double r[2]) { return r[0] * r[0] + r[1] * r[1]; }

/* Damped Newton on the 2x2 ball problem, written by hand: GSL's hybrids
 * stalls (GSL_ENOPROG) on lightly loaded balls because its relative finite-
 * difference steps and trust region do not fit the ~1e6:1 contrast between
 * the radial and the angular stiffness. Capped, backtracked steps as in
 * MODEL.md section 3 ("damped Newton"). */
/* Transient mode: chord steps with the ball's last Jacobian (one
 * evaluation each instead of three; between thermal steps the ball moves
 * little). Returns 1 with b at the converged (z, a); 0 if a step does not
 * lower |r| or three do not converge, with (z, a), r at the last accepted
 * point and b possibly at a rejected trial. */
static int ball_chord(const ball_ctx *c, double *z, double *a, double r[2], double tol)
{
    const double *J = c->J;
    double det = J[0] * J[3] - J[1] * J[2];
    if (det == 0.0 || !isfinite(det)) return 0;
    for (int it = 0; it < 3; it++) {
        double dz = -(J[3] * r[0] - J[1] * r[1]) / det;
        double da = -(J[0] * r[1] - J[2] * r[0]) / det, rt[2];
        if (!ball_polar(c, *z + dz, *a + da, rt) || !(norm2(rt) < norm2(r))) return 0;
        *z += dz;
        *a += da;
        r[0] = rt[0];
        r[1] = rt[1];
        if (fabs(r[0]) <= tol && fabs(r[1]) <= tol) return 1;
    }
    return 0;
}

static acbb_status ball_newton(const ball_ctx *c, double *z, double *a, double tol)
{
    const double ha = 1e-9, capa = 0.05;
    double r[2], rz[2], ra[2];
    if (!ball_polar(c, *z, *a, r)) return ACBB_NONFINITE;
    if (c->chord && *c->J_ok && (fabs(r[0]) > tol || fabs(r[1]) > tol)) {
        if (ball_chord(c, z, a, r, tol)) return ACBB_OK;
        if (!ball_polar(c, *z, *a, r)) return ACBB_NONFINITE; /* b back at (z, a) */
    }
    for (int it = 0; it < 100; it++) {
        if (fabs(r[0]) <= tol && fabs(r[1]) <= tol) return ACBB_OK;
        double hz = 1e-7 * fmax(fabs(*z), 1e-3);
        if (!ball_polar(c, *z + hz, *a, rz) || !ball_polar(c, *z, *a + ha, ra))
            return ACBB_NONFINITE;
        double J00 = (rz[0] - r[0]) / hz, J10 = (rz[1] - r[1]) / hz;
        double J01 = (ra[0] - r[0]) / ha, J11 = (ra[1] - r[1]) / ha;
        c->J[0] = J00; c->J[1] = J01; c->J[2] = J10; c->J[3] = J11;
        *c->J_ok = 1;
        double det = J00 * J11 - J01 * J10;
        if (det == 0.0 || !isfinite(det)) return ACBB_DIVERGED;
        double dz = -(J11 * r[0] - J01 * r[1]) / det;
        double da = -(J00 * r[1] - J10 * r[0]) / det;
        /* Two candidate directions: each component capped on its own (lets
         * the radial load settle while the angle walks), then the plain
         * Newton direction scaled as a whole. Backtrack along each. */
        double capz = 2.0 * fmax(fabs(*z), 1.0);
        double d1z = fmax(fmin(dz, capz), -capz), d1a = fmax(fmin(da, capa), -capa);
        double k = fmax(fabs(dz) / capz, fabs(da) / capa);
        double d2z = k > 1.0 ? dz / k : dz, d2a = k > 1.0 ? da / k : da;
        double n0 = norm2(r), lam = 1.0, rt[2];
        int found = 0;
        for (int pass = 0; pass < 2 && !found; pass++) {
            dz = pass ? d2z : d1z;
            da = pass ? d2a : d1a;
            for (lam = 1.0; lam >= 1.0 / 1024; lam *= 0.5)
                if (ball_polar(c, *z + lam * dz, *a + lam * da, rt)
                    && norm2(rt) < n0 * (1.0 - 1e-4 * lam)) {
                    found = 1;
                    break;
                }
        }
        if (!found) {
            ball_polar(c, *z, *a, r);
            return fabs(r[0]) <= 1e3 * tol && fabs(r[1]) <= 1e3 * tol ? ACBB_OK : ACBB_DIVERGED;
        }
        *z += lam * dz;
        *a += lam * da;
        r[0] = rt[0];
        r[1] = rt[1];
    }
    return fabs(r[0]) <= 1e3 * tol && fabs(r[1]) <= 1e3 * tol ? ACBB_OK : ACBB_DIVERGED;
}

/* Force scale for the ball residual test: one ball's share of the load,
 * at least 1 N (MODEL.md section 3 tolerance 1e-8 max(Q, 1 N)). */
static double ball_force_scale(const acbb_mech *m)
{
    double F = fabs(m->Fx) + fabs(m->Fz);
    return fmax(F / m->g.Z, 1.0);
}

/* Park a ball whose contacts are both open (zero speed, no interference):
 * on the line between the groove centres, the gap g <= 0 split so that the
 * smoothed law gives Qi = Qo (the ball's equilibrium without body forces).
 * Zeroing the loads instead made the thrust jump by Z Kc (eps/2)^1.5 sin(a)
 * (~1 mN for 7008C) where the gap closes, so a thrust below that had no
 * equilibrium and ended as "contact lost" (MODEL.md 11, unloaded balls). */
static void ball_freeze(ball_ctx *c)
{
    const acbb_geometry *g = &c->m->g;
    const acbb_ball_state *b = c->b;
    double L = hypot(c->A1, c->A2);
    double Lo = g->lambda_o - 0.5 * g->D - c->off.dL_o;
    double gap = L - Lo - (g->lambda_i - 0.5 * g->D - c->off.dL_i);
    /* Qo(d_o) - Qi(gap - d_o) rises with d_o: bisect on the outer deflection. */
    double lo = gap - 1e-6, hi = 1e-6;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * (1.0 + fabs(lo)); it++) {
        double mid = 0.5 * (lo + hi);
        double f = b->hc_o.Kc * pos15(mid) - b->hc_i.Kc * pos15(gap - mid);
        if (f > 0.0) hi = mid; else lo = mid;
    }
    double r1, r2, Lb = Lo + 0.5 * (lo + hi);
    ball_eval(c, c->A1 / L * Lb, c->A2 / L * Lb, &r1, &r2);
    c->b->loaded = c->b->Qi > LOADED_N || c->b->Qo > LOADED_N;
}

/* ---- bracketed fallback (MODEL.md section 11: "fallback: 1-D bisection")
 * When Newton fails (a ball that only the centrifugal force presses on
 * the outer race has almost no angular stiffness), split the residual into
 * its components along and across the outer contact normal: along it the
 * residual falls monotonically with the outer deflection, so for each angle
 * a bracketed Brent solve finds z; across it, Brent on the angle. */

typedef struct {
    const ball_ctx *c;
    double a;
    gsl_root_fsolver *sz;
    int fail;
} fb_ctx;

static double fb_normal(double z, void *p)
{
    fb_ctx *f = p;
    double r[2];
    ball_polar(f->c, z, f->a, r);
    return r[0] * sin(f->a) + r[1] * cos(f->a);
}

static int brent_solve(gsl_root_fsolver *s, gsl_function *F, double lo, double hi,
                       double xtol, double *root)
{
    if (gsl_root_fsolver_set(s, F, lo, hi) != GSL_SUCCESS) return 0;
    for (int it = 0; it < 200; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) return 0;
        *root = gsl_root_fsolver_root(s);
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                   xtol, 1e-14) == GSL_SUCCESS)
            return 1;
    }
    return 1;
}

static double fb_tangential(double a, void *p)
{
    fb_ctx *f = p;
    f->a = a;
    gsl_function F = { fb_normal, f };
    /* z = -5: the outer contact is open by 2.9 um; z = 1e3: 100 um in. */
    double lo = -5.0, hi = 1e3, z = 0.0, r[2];
    if (fb_normal(lo, f) <= 0.0) {
        f->fail |= 1;
        return NAN;
    }
    if (!brent_solve(f->sz, &F, lo, hi, 1e-13, &z)) {
        f->fail |= 1;
        return NAN;
    }
    ball_polar(f->c, z, a, r);
    f->a = z; /* remember the deflection of the last angle tried */
    return r[0] * cos(a) - r[1] * sin(a);
}

static acbb_status ball_fallback(acbb_mech *m, const ball_ctx *c, double *z, double *a)
{
    fb_ctx f = { c, *a, m->brent_z, 0 };
    gsl_function F = { fb_tangential, &f };
    double lo = *a, hi = *a, step = 0.02;
    double flo = fb_tangential(lo, &f), fhi = flo;
    if (!isfinite(flo)) return ACBB_DIVERGED;
    for (int i = 0; i < 40 && flo * fhi > 0.0; i++) {
        lo = fmax(lo - step, -1.2);
        hi = fmin(hi + step, 1.5);
        flo = fb_tangential(lo, &f);
        fhi = fb_tangential(hi, &f);
        if (!isfinite(flo) || !isfinite(fhi)) return ACBB_DIVERGED;
        step *= 1.5;
    }
    if (flo * fhi > 0.0) return ACBB_DIVERGED;
    double root;
    if (!brent_solve(m->brent_a, &F, lo, hi, 1e-14, &root)) return ACBB_DIVERGED;
    fb_tangential(root, &f);
    *a = root;
    *z = f.a;
    return f.fail ? ACBB_DIVERGED : ACBB_OK;
}

/* Inner groove centre and unloaded lengths of one ball, thermal terms
 * included (MODEL.md section 3 table). */
static void ball_frame(const acbb_mech *m, const acbb_ball_state *b, double A1, double A2,
                       ball_ctx *c)
{
    /* SEED projections use the angles of the last accepted solve, so the
     * residual stays a fixed function of the unknowns within one solve. */
    acbb_geometry_offsets(&m->g, m->geom, m->e, b->alpha_i_lag, b->alpha_o_lag, &c->off);
    /* A1, A2 were built with the nominal A0; SEED mode swaps in its A0'. */
    c->A1 = A1 + (c->off.A0 - m->g.A0) * sin(m->g.alpha0) + c->off.dA1;
    c->A2 = A2 + (c->off.A0 - m->g.A0) * cos(m->g.alpha0) + c->off.dA2;
}

static acbb_status ball_solve(acbb_mech *m, acbb_ball_state *b, int j, double A1, double A2)
{
    ball_ctx c = { .m = m, .b = b, .J = m->ball_J[j], .J_ok = &m->ball_J_ok[j],
                   .chord = m->hertz_tol > 0.0 };
    ball_frame(m, b, A1, A2, &c);

    /* Quick exit: no speed and no inner contact possible -> frozen ball. */
    double Lmax = (m->g.lambda_o - 0.5 * m->g.D - c.off.dL_o)
                + (m->g.lambda_i - 0.5 * m->g.D - c.off.dL_i);
    if (m->omega == 0.0 && hypot(c.A1, c.A2) <= Lmax) {
        ball_freeze(&c);
        return ACBB_OK;
    }
    c.L0 = m->g.lambda_o - 0.5 * m->g.D - c.off.dL_o;
    /* Start no deeper than outer contact: a ball parked open at zero speed
     * (ball_freeze) sits a gap away, where the bracketed fallback's radial
     * bracket may not reach. */
    double z = delta_to_z(fmax(hypot(b->X1, b->X2) - c.L0, 0.0)), a = atan2(b->X1, b->X2);
    double tol = fmax(m->tol, 1e-14) * ball_force_scale(m);
    double z0 = z, a0 = a;
    acbb_status rc = ball_newton(&c, &z, &a, tol);
    if (rc != ACBB_OK) {
        z = z0;
        a = a0;
        rc = ball_fallback(m, &c, &z, &a);
        if (rc == ACBB_OK) /* polish with Newton from the bracketed root */
            rc = ball_newton(&c, &z, &a, tol);
    }
    if (rc != ACBB_OK)
        return rc;
    /* ball_newton's last evaluation was at the accepted (z, a), so b holds
     * that state already (no re-evaluation: same bits, one fewer call). */
    b->loaded = b->Qi > LOADED_N || b->Qo > LOADED_N;
    return ACBB_OK;
}

/* Groove-centre offsets of ball j for ring displacements (MODEL.md 3). */
/* The ring's offsets at a ball of azimuth psi, from cp = cos psi and
 * sp = sin psi. */
static void ring_offsets_cs(const acbb_mech *m, const acbb_mech_state *st, double cp,
                            double sp, double *A1, double *A2)
{
    const acbb_geometry *g = &m->g;
    *A1 = g->A0 * sin(g->alpha0) + st->dx + g->Re_i * (st->thy * cp + st->thz * sp);
    *A2 = g->A0 * cos(g->alpha0) + st->dz * cp - st->dy * sp;
}

static void ring_offsets(const acbb_mech *m, const acbb_mech_state *st, double psi,
                         double *A1, double *A2)
{
    ring_offsets_cs(m, st, cos(psi), sin(psi), A1, A2);
}

/* cos and sin of solved ball j's azimuth, kept while it stays (issue 30
 * lever 4); the same values as computing them. */
static void psi_trig(acbb_mech *m, int j, double psi, double *cp, double *sp)
{
    if (m->psi_key[j] != psi) {
        m->psi_key[j] = psi;
        m->psi_cos[j] = cos(psi);
        m->psi_sin[j] = sin(psi);
    }
    *cp = m->psi_cos[j];
    *sp = m->psi_sin[j];
}

/* Solve every distinct ball and sum the ring reactions, each ball weighted
 * by how many it stands for (acbb_mech_weight). */
static acbb_status solve_balls(acbb_mech *m, acbb_mech_state *st)
{
    const acbb_geometry *g = &m->g;
    int nb = acbb_mech_distinct(st);
    st->Fx = st->Fy = st->Fz = st->My = st->Mz = 0.0;
    for (int j = 0; j < nb; j++) {
        acbb_ball_state *b = &st->ball[j];
        double A1, A2, cp, sp;
        psi_trig(m, j, b->psi, &cp, &sp);
        ring_offsets_cs(m, st, cp, sp, &A1, &A2);
        acbb_status rc = ball_solve(m, b, j, A1, A2);
        if (rc != ACBB_OK)
            return rc;
        double f[4];
        acbb_kin_angles an = { b->alpha_o, sin(b->alpha_i), cos(b->alpha_i), 0.0, 0.0 };
        if (!b->traction_valid) { /* race control's friction needs the outer angle too */
            an.so = sin(b->alpha_o);
            an.co = cos(b->alpha_o);
        }
        ball_friction(m, b, &an, f);
        double si = an.si, ci = an.ci;
        double ax = b->Qi * si + f[0];
        double rad = b->Qi * ci + f[1];
        double w = acbb_mech_weight(st, j);
        st->Fx += w * ax;
        st->Fz += w * rad * cp;
        st->Fy -= w * rad * sp;
        /* Friction along the major-axis tangent acts at the groove radius. */
        double mom = g->Re_i * ax - (f[0] * ci - f[1] * si) * g->f_i * g->D;
        st->My += w * mom * cp;
        st->Mz += w * mom * sp;
    }
    /* The odd sums cancel between mirror images (and all but Fx under
     * pure thrust): set exactly, not left at round-off. */
    if (st->symmetric || st->mirror) st->Fy = st->Mz = 0.0;
    if (st->symmetric) st->Fz = st->My = 0.0;
    acbb_mech_spread(st);
    return ACBB_OK;
}

/* ---- ring equilibrium ---- */

static void ring_set(acbb_mech *m, acbb_mech_state *st, const double *x)
{
    int k = 0;
    if (!m->fix_axial) st->dx = x[k++] * UM;
    if (m->dof_dz) st->dz = x[k++] * UM;
    if (m->dof_thy) st->thy = x[k++] * MRAD;
}

static int ring_dof(const acbb_mech *m)
{
    return !m->fix_axial + m->dof_dz + m->dof_thy;
}

static double ring_force_scale(const acbb_mech *m)
{
    return fmax(fabs(m->Fx) + fabs(m->Fz), 1.0);
}

static int ring_f(const gsl_vector *x, void *p, gsl_vector *f)
{
    acbb_mech *m = p;
    acbb_mech_state *st = m->trial;
    ring_set(m, st, x->data);
    acbb_status rc = solve_balls(m, st);
    if (rc != ACBB_OK) {
        m->inner_status = rc;
        return GSL_EBADFUNC;
    }
    int k = 0;
    if (!m->fix_axial) gsl_vector_set(f, k++, m->Fx - st->Fx);
    if (m->dof_dz) gsl_vector_set(f, k++, m->Fz - st->Fz);
    if (m->dof_thy) gsl_vector_set(f, k++, (m->My - st->My) / m->g.Re_i);
    return GSL_SUCCESS;
}

static double thrust_residual(double dx_um, void *p)
{
    acbb_mech *m = p;
    m->trial->dx = dx_um * UM;
    acbb_status rc = solve_balls(m, m->trial);
    if (rc != ACBB_OK) {
        m->inner_status = rc;
        return NAN;
    }
    return m->trial->Fx - m->Fx;
}

/* Pure thrust on identical balls: 1-D, monotone in dx, so a bracketed
 * Brent solve is both robust and cheap. */
/* Secant steps from the warm start: after the first thermal step the root
 * moves little, so this usually converges in 3-4 evaluations. Returns 1 on
 * convergence; on any sign of trouble the caller brackets instead. */
static int thrust_secant(acbb_mech *m, double *x, double *fx)
{
    double tol = m->tol * ring_force_scale(m);
    double x0 = *x, f0 = *fx, x1 = x0 + 1e-3, f1 = thrust_residual(x1, m);
    for (int it = 0; it < 8 && isfinite(f1); it++) {
        if (fabs(f1) <= tol) { *x = x1; *fx = f1; return 1; }
        if (f1 == f0 || fabs(f1) > fabs(f0)) break;
        double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1; f0 = f1;
        x1 = x2; f1 = thrust_residual(x1, m);
    }
    *fx = thrust_residual(*x, m); /* leave the trial state at the start */
    return 0;
}

/* Fallback when GSL rejects the bracket: gsl_root_fsolver_set evaluates
 * the ends again, and a residual within solver noise of zero may then show
 * the same sign at both. Plain bisection on the signs already known. */
static acbb_status thrust_bisect(acbb_mech *m, double lo, double flo, double hi, double fhi)
{
    double tol = m->tol * ring_force_scale(m);
    for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi), f = thrust_residual(mid, m);
        if (!isfinite(f)) return m->inner_status != ACBB_OK ? m->inner_status : ACBB_DIVERGED;
        if (fabs(f) <= tol || hi - lo < 1e-12 * (1.0 + fabs(mid))) return ACBB_OK;
        if ((f < 0.0) == (flo < 0.0)) { lo = mid; flo = f; } else { hi = mid; fhi = f; }
    }
    (void)fhi;
    return ACBB_DIVERGED;
}

static acbb_status solve_thrust(acbb_mech *m, acbb_mech_state *st)
{
    double x = st->dx / UM;
    double fx = thrust_residual(x, m);
    if (!isfinite(fx)) return m->inner_status;
    if (fabs(fx) <= m->tol * ring_force_scale(m))
        return ACBB_OK;
    if (thrust_secant(m, &x, &fx))
        return ACBB_OK;
    if (!isfinite(fx)) return m->inner_status;
    double step = 0.05 + 1e-3 * fabs(x), lo = x, hi = x, flo = fx, fhi = fx;
    for (int i = 0; i < 60 && flo * fhi > 0.0; i++) {
        if (fx > 0.0) { hi = lo; fhi = flo; lo -= step; flo = thrust_residual(lo, m); }
        else { lo = hi; flo = fhi; hi += step; fhi = thrust_residual(hi, m); }
        if (!isfinite(flo) || !isfinite(fhi)) return m->inner_status;
        step *= 2.0;
    }
    if (flo * fhi > 0.0)
        return ACBB_DIVERGED;
    gsl_function F = { thrust_residual, m };
    if (gsl_root_fsolver_set(m->brent, &F, lo, hi) != GSL_SUCCESS)
        return thrust_bisect(m, lo, flo, hi, fhi);
    for (int it = 0; it < 200; it++) {
        if (gsl_root_fsolver_iterate(m->brent) != GSL_SUCCESS)
            return m->inner_status != ACBB_OK ? m->inner_status : ACBB_DIVERGED;
        double r = gsl_root_fsolver_root(m->brent);
        double a = gsl_root_fsolver_x_lower(m->brent), b = gsl_root_fsolver_x_upper(m->brent);
        double fr = thrust_residual(r, m);
        if (fabs(fr) <= m->tol * ring_force_scale(m) || b - a < 1e-12 * (1.0 + fabs(r)))
            return ACBB_OK;
    }
    return ACBB_DIVERGED;
}

static int ring_eval(const double *x, void *p, double *f)
{
    acbb_mech *m = p;
    gsl_vector_const_view X = gsl_vector_const_view_array(x, (size_t)ring_dof(m));
    gsl_vector_view F = gsl_vector_view_array(f, (size_t)ring_dof(m));
    m->ring_evals++;
    return ring_f(&X.vector, m, &F.vector) == GSL_SUCCESS;
}

/* Broyden from the last ring Jacobian of this DOF set (broyden.h); the
 * first solve builds one by forward steps of 1e-6 relative (the residual
 * carries the ball solves' noise, far above round-off), steps halved up to
 * 6 times (a stiffness probe starts far off); then GSL's hybrid. 1: at root.
 * Transient steps (hertz_tol > 0; issue 30): the ring residual is a sum of
 * ball solves each converged to its tolerance, so steps from below 100
 * times the ring's tolerance leave the Jacobian as it is (their change of
 * the residual is mostly noise, which would corrupt the Jacobian the next
 * solves start from), and a solve that took more than 4 residuals builds
 * the next solve's Jacobian afresh (it had gone stale). */
static int ring_broyden(acbb_mech *m, int n, const double *x0)
{
    double x[MAX_RING_DOF], f[MAX_RING_DOF], *J = m->ring_J[n];
    double tol = m->tol * ring_force_scale(m);
    int transient = m->hertz_tol > 0.0, have_f = 0;
    memcpy(x, x0, sizeof x[0] * (size_t)n);
    if (!m->ring_J_ok[n]) {
        if (!ring_eval(x, m, f)) return 0;
        double r = 0.0;
        for (int i = 0; i < n; i++) r += fabs(f[i]);
        if (r < tol) return 1;
        if (!acbb_fd_jacobian(ring_eval, m, n, x, f, 1e-6, J)) return 0;
        m->ring_J_ok[n] = 1;
        have_f = transient; /* f is x's: not evaluated again */
    }
    long before = m->ring_evals;
    acbb_broyden_opts o = { .halvings = 6, .noise = transient ? 100.0 * tol : 0.0,
                            .have_f = have_f };
    if (acbb_broyden_ex(ring_eval, m, n, J, x, f, tol, 12, &o)) {
        if (transient && m->ring_evals - before > 4) m->ring_J_ok[n] = 0;
        return 1;
    }
    m->ring_J_ok[n] = 0;
    return 0;
}

/* A held-displacement solve the hybrid could not finish: GSL's own
 * difference steps are relative to x, so a radial offset near 0 (a
 * radial load of 1e-6 N) gets a step lost in the residual's noise (issue
 * 30). Broyden's floored steps from the same start, before giving up. */
static acbb_status held_fallback(acbb_mech *m, acbb_mech_state *st, int n)
{
    double x0[MAX_RING_DOF];
    int k = 0;
    if (m->dof_dz) x0[k++] = st->dz / UM;
    if (m->dof_thy) x0[k++] = st->thy / MRAD;
    acbb_status inner = m->inner_status; 
    m->inner_status = ACBB_OK;
    if (m->fix_axial && k == n && ring_broyden(m, n, x0))
        return solve_balls(m, st);
    return inner != ACBB_OK ? inner : m->inner_status != ACBB_OK ? m->inner_status : ACBB_DIVERGED;
}

static acbb_status solve_ring(acbb_mech *m, acbb_mech_state *st)
{
    int n = ring_dof(m);
    m->trial = st;
    m->inner_status = ACBB_OK;
    if (n == 0)
        return solve_balls(m, st);
    if (n == 1 && !m->fix_axial)
        return solve_thrust(m, st);
    double x0[MAX_RING_DOF];
    int k = 0;
    if (!m->fix_axial) x0[k++] = st->dx / UM;
    if (m->dof_dz) x0[k++] = st->dz / UM;
    if (m->dof_thy) x0[k++] = st->thy / MRAD;
    /* Held-displacement solves (sim.c's axial stiffness, a 0.3 nm central
     * difference; displacement preload) keep the hybrid path's noise. */
    if ((!m->fix_axial || m->broyden_held) && ring_broyden(m, n, x0))
        return ACBB_OK;
    m->inner_status = ACBB_OK;
    gsl_vector_view xv = gsl_vector_view_array(x0, n);
    gsl_multiroot_function F = { ring_f, (size_t)n, m };
    gsl_multiroot_fsolver *s = m->ring_solver[n];
    if (gsl_multiroot_fsolver_set(s, &F, &xv.vector) != GSL_SUCCESS)
        return held_fallback(m, st, n);
    double tol = m->tol * ring_force_scale(m);
    int status = gsl_multiroot_test_residual(s->f, tol);
    for (int it = 0; status == GSL_CONTINUE && it < 300; it++) {
        if (gsl_multiroot_fsolver_iterate(s) != GSL_SUCCESS)
            break;
        status = gsl_multiroot_test_residual(s->f, tol);
    }
    if (status != GSL_SUCCESS && gsl_multiroot_test_residual(s->f, 1e3 * tol) != GSL_SUCCESS)
        return held_fallback(m, st, n);
    ring_set(m, st, s->x->data);
    return solve_balls(m, st); /* leave st exactly at the accepted root */
}

/* ---- Hertz constants at the operating angles ---- */

/* *refreshed: how many balls got new constants. */
static acbb_status refresh_hertz(const acbb_mech *m, acbb_mech_state *st, int *refreshed)
{
    const acbb_geometry *g = &m->g;
    int nb = acbb_mech_distinct(st);
    /* Kc varies ~1e-3 per degree: an angle change below 1e-11 rad leaves
     * the constants unchanged to round-off; in transient steps
     * (acbb_mech_set_transient) hertz_tol keeps them a little longer. */
    double tol = fmax(m->hertz_tol, 1e-11);
    *refreshed = 0;
    for (int j = 0; j < nb; j++) {
        acbb_ball_state *b = &st->ball[j];
        if (b->hc_i.Kc > 0.0 && fabs(b->alpha_i - b->hc_alpha_i) < tol
            && fabs(b->alpha_o - b->hc_alpha_o) < tol)
            continue;
        ++*refreshed;
        b->hc_alpha_i = b->alpha_i;
        b->hc_alpha_o = b->alpha_o;
        double Rx, Ry;
        acbb_contact_radii(g->D, g->dm, b->alpha_i, g->f_i, 1, &Rx, &Ry);
        acbb_status rc = acbb_hertz_const_compute(Rx, Ry, g->E_eff, m->hertz, &b->hc_i);
        if (rc != ACBB_OK) return rc;
        acbb_contact_radii(g->D, g->dm, b->alpha_o, g->f_o, 0, &Rx, &Ry);
        rc = acbb_hertz_const_compute(Rx, Ry, g->E_eff, m->hertz, &b->hc_o);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

/* The solved balls' contacts; the others are copies of theirs (the last
 * solve_balls spread them: the same inputs, so the same bits), not
 * recomputed (issue 30 lever 4: 21 balls of a pure-thrust ring). */
static void finish_contacts(const acbb_mech *m, acbb_mech_state *st)
{
    int nb = acbb_mech_distinct(st);
    for (int j = 0; j < nb; j++) {
        acbb_ball_state *b = &st->ball[j];
        acbb_hertz_from_load(&b->hc_i, b->Qi, &b->ct_i);
        acbb_hertz_from_load(&b->hc_o, b->Qo, &b->ct_o);
        if (m->race == ACBB_RACE_AUTO && b->loaded)
            b->control = acbb_race_control_choose(b->Qi, b->ct_i.a, b->hc_i.E, b->Qo,
                                                  b->ct_o.a, b->hc_o.E, b->alpha_i,
                                                  b->alpha_o, b->control);
    }
    for (int j = nb; j < st->n; j++) {
        acbb_ball_state *b = &st->ball[j];
        const acbb_ball_state *src = &st->ball[acbb_mech_source(st, j)];
        b->ct_i = src->ct_i;
        b->ct_o = src->ct_o;
        b->control = src->control;
    }
}

static int state_finite(const acbb_mech_state *st)
{
    for (int j = 0; j < st->n; j++) {
        const acbb_ball_state *b = &st->ball[j];
        if (!isfinite(b->Qi) || !isfinite(b->Qo) || !isfinite(b->alpha_i)
            || !isfinite(b->alpha_o) || !isfinite(b->kin.omega_m))
            return 0;
    }
    return isfinite(st->dx) && isfinite(st->dz) && isfinite(st->Fx);
}

/* Held ring displacements: the ball symmetry follows them (identical
 * balls only when the ring moves axially alone). */
static void prescribed_state(const acbb_mech *m, acbb_mech_state *w)
{
    int sym = m->dz_fixed == 0.0 && m->thy_fixed == 0.0;
    if (w->symmetric && !sym) acbb_mech_spread(w);
    w->symmetric = sym;
    w->mirror = !sym;
    w->dz = m->dz_fixed;
    w->thy = m->thy_fixed;
    w->dy = w->thz = 0.0;
}

/* What a failed solve puts back: st's header and the balls it solves
 * (`keep`, saved before the solve); the other balls are their images
 * (acbb_mech_spread), as they were. */
static void put_back(acbb_mech_state *st, const acbb_mech_state *keep)
{
    memcpy(st, keep, offsetof(acbb_mech_state, ball));
    memcpy(st->ball, keep->ball, sizeof st->ball[0] * (size_t)acbb_mech_distinct(keep));
    acbb_mech_spread(st);
}

acbb_status acbb_mech_solve(acbb_mech *m, double omega_i, const acbb_expansion *e,
                            acbb_mech_state *st, acbb_error *err)
{
    static const char *what = "mechanics";
    /* Solved in place (issue 30 lever 4: no copy of every ball record in
     * and out); a failure puts back what it changed. */
    acbb_mech_state *keep = malloc(sizeof *keep), *w = st;
    if (!keep) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", what);
    memcpy(keep, st, offsetof(acbb_mech_state, ball));
    memcpy(keep->ball, st->ball, sizeof st->ball[0] * (size_t)acbb_mech_distinct(st));
    m->omega = omega_i;
    if (e) m->e_copy = *e;
    m->e = e ? &m->e_copy : NULL;
    if (m->fix_axial) w->dx = m->dx_fixed;
    if (m->prescribed) prescribed_state(m, w);
    if (m->hold_radial) w->dz = m->dz_hold;
    if (m->hold_tilt) w->thy = m->thy_hold;
    for (int j = 0; j < acbb_mech_distinct(w); j++) {
        w->ball[j].alpha_i_lag = w->ball[j].alpha_i;
        w->ball[j].alpha_o_lag = w->ball[j].alpha_o;
    }
    acbb_mechx_predict(m, w);
    acbb_status rc = ACBB_OK;
    /* The Hertz constants depend on the operating angles: iterate the
     * solve with refreshed constants until the angles stop moving. */
    for (int pass = 0; pass < 8; pass++) {
        double ai = w->ball[0].alpha_i, ao = w->ball[0].alpha_o;
        int refreshed;
        if ((rc = refresh_hertz(m, w, &refreshed)) != ACBB_OK) break;
        /* Transient mode: no constant changed, so a further pass would
         * solve the same equations again. */
        if (pass > 0 && refreshed == 0 && m->hertz_tol > 0.0) break;
        if ((rc = solve_ring(m, w)) != ACBB_OK) break;
        if (fabs(w->ball[0].alpha_i - ai) < 1e-11 && fabs(w->ball[0].alpha_o - ao) < 1e-11)
            break;
    }
    if (rc == ACBB_OK && !state_finite(w))
        rc = ACBB_NONFINITE;
    if (rc == ACBB_OK) {
        /* A converged equilibrium with no inner contact carrying load is a
         * lost contact, unless the applied load itself is below what open
         * contacts carry: 1e-5 N of thrust puts ~2e-6 N on each ball, less
         * than LOADED_N but a carried load (the threshold follows it). */
        double floor_N = fmin(LOADED_N, 0.5 * (fabs(m->Fx) + fabs(m->Fz)) / m->g.Z);
        int any = 0;
        for (int j = 0; j < w->n; j++) any |= w->ball[j].Qi > floor_N;
        if (!any && !m->prescribed && (fabs(m->Fx) > 0.0 || fabs(m->Fz) > 0.0 || (m->fix_axial && !m->centred)))
            rc = ACBB_CONTACT_LOST;
    }
    if (rc != ACBB_OK) {
        put_back(st, keep);
        free(keep);
        return acbb_error_set(err, rc, "%s: equilibrium %s at %.0f rpm", what,
                              rc == ACBB_CONTACT_LOST ? "lost every inner contact"
                                                      : "did not converge",
                              omega_i * 30.0 / M_PI);
    }
    finish_contacts(m, w);
    acbb_mechx_remember(m, w);
    free(keep);
    return ACBB_OK;
}

acbb_status acbb_mech_init_state(acbb_mech *m, acbb_mech_state *st, acbb_error *err)
{
    const acbb_geometry *g = &m->g;
    memset(st, 0, sizeof *st);
    st->n = g->Z;
    acbb_mech_adopt_state(m, st);
    acbb_race_control rc0 = m->race;
    for (int j = 0; j < st->n; j++) {
        acbb_ball_state *b = &st->ball[j];
        b->psi = 2.0 * M_PI * j / g->Z;
        b->alpha_i = b->alpha_o = g->alpha0;
        b->control = rc0 == ACBB_RACE_INNER ? ACBB_CONTROL_INNER : ACBB_CONTROL_OUTER;
    }
    int refreshed;
    acbb_status rc = refresh_hertz(m, st, &refreshed);
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "mechanics: Hertz constants failed");
    /* Static thrust guess [HK-EC]: K_n from both contacts, closed-form angle. */
    acbb_ball_state *b0 = &st->ball[0];
    double Kn = pow(pow(b0->hc_i.Kc, -2.0 / 3.0) + pow(b0->hc_o.Kc, -2.0 / 3.0), -1.5);
    double Fx = m->fix_axial ? 0.0 : fmax(m->Fx, 1.0);
    double a = m->centred ? 0.0 : acbb_static_thrust_angle(Fx, g->Z, Kn, g->A0, g->alpha0);
    if (!isfinite(a)) a = g->alpha0;
    double dn = m->centred ? 0.0 : g->A0 * (cos(g->alpha0) / cos(a) - 1.0);
    double q = pow(fmax(dn, 0.0), 1.5) * Kn;
    double Lo = g->lambda_o - 0.5 * g->D + pow(q / b0->hc_o.Kc, 2.0 / 3.0);
    st->dx = m->fix_axial ? m->dx_fixed : (g->A0 + dn) * sin(a) - g->A0 * sin(g->alpha0);
    /* Centred under radial load: start the ring where the most loaded ball
     * carries Stribeck's 5 Fr / Z [HK-EC, static load distribution], past
     * half the clearance, so the first Jacobian sees loaded balls. */
    if (m->centred && m->Fz > 0.0)
        st->dz = 0.5 * g->Pd + pow(5.0 * m->Fz / (g->Z * Kn), 2.0 / 3.0);
    for (int j = 0; j < st->n; j++) {
        acbb_ball_state *b = &st->ball[j];
        b->alpha_i = b->alpha_o = a;
        b->X1 = Lo * sin(a);
        b->X2 = Lo * cos(a);
    }
    return acbb_mech_solve(m, 0.0, NULL, st, err);
}

void acbb_mech_probing(acbb_mech *m, int on)
{
    if (on) {
        memcpy(m->kept_J, m->ball_J, sizeof m->kept_J);
        memcpy(m->kept_J_ok, m->ball_J_ok, sizeof m->kept_J_ok);
    } else {
        memcpy(m->ball_J, m->kept_J, sizeof m->kept_J);
        memcpy(m->ball_J_ok, m->kept_J_ok, sizeof m->kept_J_ok);
    }
}

void acbb_mech_ball_frame(const acbb_mech *m, const acbb_mech_state *st, int j,
                          acbb_ball_frame *f)
{
    const acbb_ball_state *b = &st->ball[j];
    ball_ctx c = { .m = m };
    double A1, A2;
    ring_offsets(m, st, b->psi, &A1, &A2);
    ball_frame(m, b, A1, A2, &c);
    f->A1 = c.A1;
    f->A2 = c.A2;
    f->L0_i = m->g.lambda_i - 0.5 * m->g.D - c.off.dL_i;
    f->L0_o = m->g.lambda_o - 0.5 * m->g.D - c.off.dL_o;
}
