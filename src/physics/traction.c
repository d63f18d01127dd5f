/* acbb — contact traction resultants (MODEL.md sections 4-5, Level 2). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "traction.h"

#define S_REG 1e-6 /* m/s, slip regularisation of MODEL.md section 4 */

static void cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* tc (cleared) laid out in P, room for cap points (NULL P: none). */
static void lay_out(acbb_traction_contact *tc, double *P, int cap)
{
    memset(tc, 0, sizeof *tc);
    if (!P) return;
    tc->P = P;
    tc->w = tc->P + 3 * cap;
    tc->p = tc->w + cap;
    tc->eta = tc->p + cap;
    tc->tb = tc->eta + cap;
    tc->tlim = tc->tb + cap;
    tc->cap = cap;
}

acbb_status acbb_traction_contact_init(acbb_traction_contact *tc, int grid)
{
    int cap = grid * grid;
    double *P = malloc(sizeof(double) * 8 * (size_t)cap);
    lay_out(tc, P, cap);
    return P ? ACBB_OK : ACBB_ENOMEM;
}

acbb_status acbb_traction_contact_renew(acbb_traction_contact *tc, int grid)
{
    if (tc->P && tc->cap == grid * grid) {
        lay_out(tc, tc->P, tc->cap);
        return ACBB_OK;
    }
    acbb_traction_contact_free(tc);
    return acbb_traction_contact_init(tc, grid);
}

void acbb_traction_contact_free(acbb_traction_contact *tc)
{
    free(tc->P);
    memset(tc, 0, sizeof *tc);
}

acbb_status acbb_traction_prepare(const acbb_scene *s, const acbb_quad *q,
                                  const acbb_contact_in *c, const acbb_film *f,
                                  const acbb_oil_state *o, acbb_traction_contact *tc)
{
    tc->np = 0;
    if (c->Q <= 1e-6 || c->a <= 0.0 || c->b <= 0.0) return ACBB_OK;
    if (q->n * q->n > tc->cap) return ACBB_EINVAL;
    double sa = sin(c->alpha), ca = cos(c->alpha);
    /* Normals from the ball centre: outer (sin a, 0, cos a), inner the
     * opposite; the major axis lies in the meridional plane. */
    double sg = c->inner ? -1.0 : 1.0;
    tc->n[0] = sg * sa; tc->n[1] = 0.0; tc->n[2] = sg * ca;
    tc->t[0] = ca; tc->t[1] = 0.0; tc->t[2] = -sa;
    tc->rm = 0.5 * c->dm;
    tc->H = fmax(f->hc, 1e-9);
    tc->phi_a = f->phi_a;
    tc->phi_f = f->phi_f;
    tc->s_reg = S_REG;
    double Rd = 2.0 * c->f * c->D / (2.0 * c->f + 1.0), a2 = c->a * c->a;
    double h0 = -sqrt(acbb_nonneg(Rd * Rd - a2)) + sqrt(acbb_nonneg(0.25 * c->D * c->D - a2));
    acbb_visc_law visc;
    acbb_visc_law_init(s, o, &visc);
    /* sqrt(1 - t^2) once per column (the same bits as per node). */
    double st[ACBB_QUAD_MAX];
    for (int j = 0; j < q->n; j++) st[j] = sqrt(1.0 - q->x[j] * q->x[j]);
    int k = 0;
    for (int i = 0; i < q->n; i++) {
        double xi = q->x[i], sq = sqrt(1.0 - xi * xi), x = c->a * xi;
        double h = sqrt(acbb_nonneg(Rd * Rd - x * x)) + h0; /* deformed surface, section 4 */
        for (int j = 0; j < q->n; j++, k++) {
            double t = q->x[j], y = c->b * sq * t;
            double *P = tc->P + 3 * k;
            for (int d = 0; d < 3; d++) P[d] = h * tc->n[d] + x * tc->t[d];
            P[1] += y;
            tc->w[k] = q->w[i] * q->w[j] * c->a * c->b * sq;
            tc->p[k] = c->pmax * sq * st[j];
            tc->eta[k] = f->phi_f > 0.0 ? acbb_visc_law_eval_mirror(&visc, tc->p, tc->eta, q->n, i, j)
                                        : 0.0;
            tc->tb[k] = tc->phi_a * s->mu_bd * tc->p[k];
            tc->tlim[k] = s->lambda_lim * acbb_nonneg(tc->p[k]);
        }
    }
    tc->np = k;
    return ACBB_OK;
}

/* Tangential slip sl of ball against race at point k (normal part
 * removed) for ball angular velocity wb and race speed `race`; returns |sl|. */
static inline double point_slip(const acbb_traction_contact *tc, int k, const double wb[3],
                                double race, double sl[3])
{
    const double ex[3] = { 1.0, 0.0, 0.0 };
    const double *P = tc->P + 3 * k;
    double vb[3], pos[3] = { P[0], P[1], P[2] + tc->rm }, vr[3];
    cross(wb, P, vb);
    cross(ex, pos, vr);
    double sn = 0.0;
    for (int d = 0; d < 3; d++) {
        sl[d] = vb[d] - race * vr[d];
        sn += sl[d] * tc->n[d];
    }
    for (int d = 0; d < 3; d++) sl[d] -= sn * tc->n[d];
    return sqrt(sl[0] * sl[0] + sl[1] * sl[1] + sl[2] * sl[2]);
}

static inline int eyring_law(const acbb_scene *s)
{
    return s->traction != ACBB_TRACTION_BAIR_WINER && s->tau_eyring > 0.0;
}

/* Local traction magnitude at point k for slip speed mag (MODEL.md 5). */
static inline double point_tau(const acbb_scene *s, const acbb_traction_contact *tc, int k,
                               double mag)
{
    double tau = tc->tb[k];
    if (!(tc->phi_f > 0.0)) return tau;
    double eta = tc->eta[k];
    return tau + tc->phi_f * (eyring_law(s)
                                  ? acbb_eyring_capped(s->tau_eyring, eta, mag, tc->H, tc->tlim[k])
                                  : acbb_tau_lubricant(s, eta, mag, tc->H, tc->p[k]));
}

/* point_slip without its multiplications by the zero components of e_x
 * and of the normal (n[1] = 0 in the meridional plane, prepare): for
 * finite values the same bits (x * 0 only adds a signed zero), a quarter
 * of the arithmetic of the innermost loop of Level 2 (issue 30). */
static inline double point_slip_meridional(const acbb_traction_contact *tc, int k,
                                           const double wb[3], double race, double sl[3])
{
    const double *P = tc->P + 3 * k, *n = tc->n;
    sl[0] = wb[1] * P[2] - wb[2] * P[1];
    sl[1] = (wb[2] * P[0] - wb[0] * P[2]) + race * (P[2] + tc->rm);
    sl[2] = (wb[0] * P[1] - wb[1] * P[0]) - race * P[1];
    double sn = sl[0] * n[0] + sl[2] * n[2];
    sl[0] -= sn * n[0];
    sl[2] -= sn * n[2];
    return sqrt(sl[0] * sl[0] + sl[1] * sl[1] + sl[2] * sl[2]);
}

/* point_tau for a film under the Eyring law (the callers' common case,
 * decided once per contact): the same operations, so the same bits. */
static inline double point_tau_eyring(const acbb_scene *s, const acbb_traction_contact *tc,
                                      int k, double mag)
{
    return tc->tb[k] + tc->phi_f * acbb_eyring_capped(s->tau_eyring, tc->eta[k], mag, tc->H,
                                                      tc->tlim[k]);
}

void acbb_traction_eval(const acbb_scene *s, const acbb_traction_contact *tc,
                        const double wb[3], double race, acbb_traction *out)
{
    /* Sums in locals (out may alias nothing, but the compiler cannot know),
     * added in the same order: the same bits. */
    double F[3] = { 0.0, 0.0, 0.0 }, M[3] = { 0.0, 0.0, 0.0 };
    int merid = tc->n[1] == 0.0, eyring = tc->phi_f > 0.0 && eyring_law(s);
    for (int k = 0; k < tc->np; k++) {
        double sl[3], mag = merid ? point_slip_meridional(tc, k, wb, race, sl)
                                  : point_slip(tc, k, wb, race, sl);
        double tau = eyring ? point_tau_eyring(s, tc, k, mag) : point_tau(s, tc, k, mag);
        double g = -tau * tc->w[k] / sqrt(mag * mag + tc->s_reg * tc->s_reg);
        double f[3] = { g * sl[0], g * sl[1], g * sl[2] }, m[3];
        cross(tc->P + 3 * k, f, m);
        for (int d = 0; d < 3; d++) {
            F[d] += f[d];
            M[d] += m[d];
        }
    }
    memcpy(out->F, F, sizeof F);
    memcpy(out->M, M, sizeof M);
}

/* point_tau and its slip derivative d tau / d mag at once, for the
 * Eyring law (the Jacobian's only law): one asinh per point instead of
 * one for each (issue 30 lever 4), the same operations as
 * acbb_eyring_capped, so the same bits. The derivative is the Eyring
 * branch's below its cap (the asperity part phi_a mu p does not depend on
 * the slip). */
static inline double point_tau_dtau(const acbb_scene *s, const acbb_traction_contact *tc,
                                    int k, double mag, double *dtau)
{
    double tau = tc->tb[k];
    *dtau = 0.0;
    if (!(tc->phi_f > 0.0)) return tau;
    double te = s->tau_eyring, eta = tc->eta[k], tn = eta * (mag / tc->H), fl = 0.0;
    if (tc->tlim[k] > 0.0 && tn > 0.0) {
        double x = tn / te;
        fl = te * acbb_asinh_pos(x);
        if (fl < tc->tlim[k]) *dtau = tc->phi_f * (eta / tc->H) / sqrt(1.0 + x * x);
        else fl = tc->tlim[k];
    }
    return tau + tc->phi_f * fl;
}

int acbb_traction_eval_jac(const acbb_scene *s, const acbb_traction_contact *tc,
                           const double wb[3], double race, acbb_traction *out,
                           double dF[3][4], double dM[3][4])
{
    memset(out, 0, sizeof *out);
    memset(dF, 0, sizeof(double) * 12);
    memset(dM, 0, sizeof(double) * 12);
    if (tc->phi_f > 0.0 && !eyring_law(s)) return 0;
    /* Sums in locals (the compiler cannot know the outputs alias none of
     * the tables, so it stored and reloaded them every point), added in
     * the same order: the same bits (issue 30). */
    double F[3] = { 0.0, 0.0, 0.0 }, Mo[3] = { 0.0, 0.0, 0.0 };
    double JF[3][4] = { { 0.0 } }, JM[3][4] = { { 0.0 } };
    int merid = tc->n[1] == 0.0;
    for (int k = 0; k < tc->np; k++) {
        const double *P = tc->P + 3 * k, *n = tc->n;
        double sl[3], mag = merid ? point_slip_meridional(tc, k, wb, race, sl)
                                  : point_slip(tc, k, wb, race, sl);
        double dtau, tau = point_tau_dtau(s, tc, k, mag, &dtau);
        double R2 = mag * mag + tc->s_reg * tc->s_reg, R = sqrt(R2), g = -tau * tc->w[k] / R;
        /* dg/dmag of g = -tau(mag) w / sqrt(mag^2 + s_reg^2). */
        double dg = -tc->w[k] * (dtau / R - tau * mag / (R2 * R));
        double f[3] = { g * sl[0], g * sl[1], g * sl[2] }, m[3];
        cross(P, f, m);
        /* Slip derivatives: d/dwb_j = e_j x P, d/drace = -(e_x x pos),
         * each with its normal part removed like the slip itself. */
        double D[4][3] = { { 0.0, -P[2], P[1] }, { P[2], 0.0, -P[0] }, { -P[1], P[0], 0.0 },
                           { 0.0, P[2] + tc->rm, -P[1] } };
        for (int j = 0; j < 4; j++) {
            double dn = D[j][0] * n[0] + D[j][1] * n[1] + D[j][2] * n[2], dmag = 0.0;
            for (int d = 0; d < 3; d++) D[j][d] -= dn * n[d];
            if (mag > 0.0) dmag = (sl[0] * D[j][0] + sl[1] * D[j][1] + sl[2] * D[j][2]) / mag;
            double df[3], dm[3];
            for (int d = 0; d < 3; d++) df[d] = g * D[j][d] + dg * dmag * sl[d];
            cross(P, df, dm);
            for (int d = 0; d < 3; d++) {
                JF[d][j] += df[d];
                JM[d][j] += dm[d];
            }
        }
        for (int d = 0; d < 3; d++) {
            F[d] += f[d];
            Mo[d] += m[d];
        }
    }
    memcpy(out->F, F, sizeof F);
    memcpy(out->M, Mo, sizeof Mo);
    memcpy(dF, JF, sizeof JF);
    memcpy(dM, JM, sizeof JM);
    return 1;
}
