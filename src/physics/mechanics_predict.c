/* acbb — the start of a transient step's mechanics solve (issue 30): the
 * last root moved on along the secant of the last two, by the projection
 * of the thermal expansions' move on the last one. A transient's
 * temperatures drift one way, so the ring and the balls start closer to
 * the new root than the last one (fewer ring residuals, each a solve of
 * every distinct ball); the root is the same to the solve's tolerance
 * (MODEL.md section 3: the equilibrium is unique). */
#include <math.h>
#include <string.h>
#include "mechanics_priv.h"

/* Expansions in metres, compared absolutely. */
static void inputs(const acbb_expansion *e, double u[MECH_PRED_U])
{
    u[0] = e->ball;
    u[1] = e->inner;
    u[2] = e->inner_cen;
    u[3] = e->outer;
}

/* Only transient steps of a free ring (acbb_mech_set_transient), under
 * the loads and speed the history was made with. */
static int applies(const acbb_mech *m, const acbb_mech_state *st)
{
    return m->hertz_tol > 0.0 && m->e && !m->prescribed && m->ph_omega == m->omega
           && m->ph_nb == acbb_mech_distinct(st) && m->ph_F[0] == m->Fx
           && m->ph_F[1] == m->Fz && m->ph_F[2] == m->My && m->ph_fix == m->fix_axial;
}

void acbb_mechx_predict(acbb_mech *m, acbb_mech_state *st)
{
    if (m->ph_n < 2 || !applies(m, st)) return;
    const double *x0 = m->ph_x[0], *x1 = m->ph_x[1];
    /* From the last root only (not from a checkpoint put back). */
    if (st->dx != x0[0] || st->dz != x0[1] || st->thy != x0[2]) return;
    double u[MECH_PRED_U], num = 0.0, den = 0.0;
    inputs(m->e, u);
    for (int k = 0; k < MECH_PRED_U; k++) {
        double a = u[k] - m->ph_u[0][k], b = m->ph_u[0][k] - m->ph_u[1][k];
        num += a * b;
        den += b * b;
    }
    double t = den > 0.0 ? num / den : 0.0; /* 0: the inputs did not move */
    if (!(t > 0.0 && t < 4.0)) return;
    if (!m->fix_axial) st->dx += t * (x0[0] - x1[0]);
    if (m->dof_dz && !m->hold_radial) st->dz += t * (x0[1] - x1[1]);
    if (m->dof_thy && !m->hold_tilt) st->thy += t * (x0[2] - x1[2]);
    for (int j = 0; j < m->ph_nb; j++) {
        st->ball[j].X1 += t * (m->ph_b[0][j][0] - m->ph_b[1][j][0]);
        st->ball[j].X2 += t * (m->ph_b[0][j][1] - m->ph_b[1][j][1]);
        st->ball[j].alpha_i += t * (m->ph_b[0][j][2] - m->ph_b[1][j][2]);
        st->ball[j].alpha_o += t * (m->ph_b[0][j][3] - m->ph_b[1][j][3]);
    }
}

void acbb_mechx_remember(acbb_mech *m, const acbb_mech_state *st)
{
    int nb = acbb_mech_distinct(st);
    if (m->ph_n > 0 && !applies(m, st)) m->ph_n = 0;
    if (!(m->hertz_tol > 0.0 && m->e && !m->prescribed)) return;
    memcpy(m->ph_x[1], m->ph_x[0], sizeof m->ph_x[0]);
    memcpy(m->ph_u[1], m->ph_u[0], sizeof m->ph_u[0]);
    memcpy(m->ph_b[1], m->ph_b[0], sizeof m->ph_b[0][0] * (size_t)nb);
    m->ph_x[0][0] = st->dx;
    m->ph_x[0][1] = st->dz;
    m->ph_x[0][2] = st->thy;
    for (int j = 0; j < nb; j++) {
        m->ph_b[0][j][0] = st->ball[j].X1;
        m->ph_b[0][j][1] = st->ball[j].X2;
        m->ph_b[0][j][2] = st->ball[j].alpha_i;
        m->ph_b[0][j][3] = st->ball[j].alpha_o;
    }
    inputs(m->e, m->ph_u[0]);
    m->ph_nb = nb;
    m->ph_omega = m->omega;
    m->ph_F[0] = m->Fx;
    m->ph_F[1] = m->Fz;
    m->ph_F[2] = m->My;
    m->ph_fix = m->fix_axial;
    m->ph_n = m->ph_n < 2 ? m->ph_n + 1 : 2;
}
