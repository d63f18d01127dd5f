/* acbb — the snapshot's per-ball and squeeze views (sim.h), split from the
 * stepper (sim.c) so that each file keeps one job. */
#include <math.h>
#include "acbb/sim.h"
#include "sim_priv.h"

double acbb_snap_fin(double v) { return isfinite(v) ? v : 0.0; }

void acbb_snap_ball_view(const acbb_ball_state *b, const acbb_contact_loss *in,
                         const acbb_contact_loss *out, acbb_ball_view *v)
{
    v->psi = b->psi;
    v->Qi = b->Qi; v->Qo = b->Qo;
    v->alpha_i = b->alpha_i; v->alpha_o = b->alpha_o;
    v->slide_i = in->slide; v->slide_o = out->slide;
    v->spin_i = b->kin.spin_i; v->spin_o = b->kin.spin_o;
    v->film_i = in->film.hc; v->film_o = out->film.hc;
    v->pmax_i = b->ct_i.pmax; v->pmax_o = b->ct_o.pmax;
    v->a_i = b->ct_i.a; v->b_i = b->ct_i.b; v->a_o = b->ct_o.a; v->b_o = b->ct_o.b;
    v->omega_m = b->kin.omega_m;
    v->omega_x = b->kin.wx; v->omega_y = b->kin.wy; v->omega_z = b->kin.wz;
    v->hmin_i = in->film.hmin; v->hmin_o = out->film.hmin;
    v->loss = 0.0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        v->loss_kind[l] = acbb_snap_fin(in->P[l] + out->P[l]);
        v->loss += in->P[l] + out->P[l];
    }
    /* Last guard only: evaluate() already ended the run on a non-finite value. */
    double *f[] = { &v->psi, &v->Qi, &v->Qo, &v->alpha_i, &v->alpha_o, &v->slide_i,
                    &v->slide_o, &v->spin_i, &v->spin_o, &v->film_i, &v->film_o, &v->pmax_i,
                    &v->pmax_o, &v->a_i, &v->b_i, &v->a_o, &v->b_o, &v->omega_m, &v->omega_x,
                    &v->omega_y, &v->omega_z, &v->loss, &v->hmin_i, &v->hmin_o };
    for (size_t k = 0; k < sizeof f / sizeof f[0]; k++) *f[k] = acbb_snap_fin(*f[k]);
}

/* MODEL.md 13: S = theta_i + theta_icen - theta_o + 2 theta_ba cos(alpha). */
void acbb_snap_squeeze(const acbb_expansion *e, const acbb_ball_state *b, acbb_squeeze *q)
{
    double alpha = 0.5 * (b->alpha_i + b->alpha_o);
    q->inner_thermal = acbb_snap_fin(e->inner);
    q->inner_centrifugal = acbb_snap_fin(e->inner_cen);
    q->outer = acbb_snap_fin(-e->outer);
    q->ball = acbb_snap_fin(2.0 * e->ball * cos(alpha));
    q->net = q->inner_thermal + q->inner_centrifugal + q->outer + q->ball;
}

const char *acbb_run_status_name(const acbb_snapshot *snap)
{
    if (snap->state == ACBB_RUN_CONVERGED) return "converged";
    if (snap->state == ACBB_RUN_RUNNING) return "running";
    return acbb_status_name(snap->status);
}

/* ---- checks used by the stepper (stepper.c, sim.c) ---- */

int acbb_snap_contact_finite(const acbb_contact_loss *c)
{
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        if (!isfinite(c->P[l])) return 0;
    return isfinite(c->slide) && isfinite(c->film.hc);
}

double acbb_snap_max_pmax(const acbb_mech_state *ms)
{
    double p = 0.0;
    for (int j = 0; j < ms->n; j++)
        p = fmax(p, fmax(ms->ball[j].ct_i.pmax, ms->ball[j].ct_o.pmax));
    return p;
}

int acbb_snap_all_finite(const double *T, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(T[i])) return 0;
    return 1;
}
