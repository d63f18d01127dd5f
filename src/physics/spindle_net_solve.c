/* acbb — the spindle's joined network: steady and backward-Euler solves
 * with the coolant coupled exactly through its Schur complement, the
 * energy flows, the thermal growth and the view (docs/spindle.md "Heat"). */
#include <math.h>
#include <string.h>
#include "spindle_net_priv.h"

static int n_cool(const acbb_spindle_net *sn) { return sn->sp->def.n_cool; }
static int is_cool(const acbb_spindle_net *sn, int i)
{
    return i >= sn->sp->cool0 && i < sn->sp->cool0 + n_cool(sn);
}

void acbb_spindle_net_init(const acbb_spindle_net *sn, double *T)
{
    for (int i = 0; i < sn->n; i++) T[i] = is_cool(sn, i) ? sn->sp->def.T_in : sn->T_ambient;
}

/* Heat into the fixed nodes for temperatures T, W: the coolant cells'
 * (Q_cool) and all the others' (Q_air). */
static void to_fixed(const acbb_spindle_net *sn, const double *T, double *Q_cool, double *Q_air)
{
    int ne = acbb_tnet_edge_count(sn->net);
    *Q_cool = *Q_air = 0.0;
    for (int e = 0; e < ne; e++) {
        int ends[2];
        acbb_tnet_edge_nodes(sn->net, e, &ends[0], &ends[1]);
        double f = (T[ends[1]] - T[ends[0]]) / acbb_tnet_resistance(sn->net, e);
        for (int j = 0; j < 2; j++, f = -f)
            if (acbb_tnet_is_fixed(sn->net, ends[j])) *(is_cool(sn, ends[j]) ? Q_cool : Q_air) += f;
    }
}

/* Wall heat into each coolant cell for temperatures T, W. */
static void wall_heat(acbb_spindle_net *sn, const double *T, double *Q)
{
    int ne = acbb_tnet_edge_count(sn->net), c0 = sn->sp->cool0;
    memset(Q, 0, (size_t)n_cool(sn) * sizeof *Q);
    for (int e = 0; e < ne; e++) {
        int a, b;
        acbb_tnet_edge_nodes(sn->net, e, &a, &b);
        double f = (T[b] - T[a]) / acbb_tnet_resistance(sn->net, e);
        if (is_cool(sn, a)) Q[a - c0] += f;
        if (is_cool(sn, b)) Q[b - c0] -= f;
    }
}

/* Everything but the coolant, with the coolant cells held at Tc (NULL:
 * the inlet): steady (dt = 0) or one step from T_old, into T. */
static acbb_status solid(acbb_spindle_net *sn, double dt, const double *Tc, double *T)
{
    for (int m = 0; m < n_cool(sn); m++)
        acbb_tnet_set_fixed(sn->net, sn->sp->cool0 + m, Tc ? Tc[m] : sn->sp->def.T_in);
    if (!(dt > 0.0)) return acbb_tnet_steady(sn->net, sn->q, T);
    memcpy(T, sn->T_old, (size_t)sn->n * sizeof *T);
    return acbb_tnet_step(sn->net, sn->q, dt, T);
}

/* The coolant balances m_dot c_p (Tc_m - Tc_{m-1}) = Q_m(Tc), Tc_{-1} =
 * T_in (no hold-up): Q is affine in Tc (the solid's solve is linear), so
 * its matrix comes from one solve per cell raised by 1 K and the balances
 * are solved once, exactly (the scheme of shaft_thermal_solve.c). */
static acbb_status with_coolant(acbb_spindle_net *sn, double dt, double *T)
{
    const acbb_spindle_thermal_def *d = &sn->sp->def;
    int nc = d->n_cool;
    double Tc[ACBB_SPINDLE_MAX_COOL], W = d->m_dot * d->c_p;
    acbb_status st = solid(sn, dt, NULL, T);
    if (nc == 0 || st != ACBB_OK) return st;
    wall_heat(sn, T, sn->Q0);
    for (int m = 0; m < nc; m++) Tc[m] = d->T_in;
    for (int j = 0; j < nc && st == ACBB_OK; j++) {
        Tc[j] = d->T_in + 1.0;
        st = solid(sn, dt, Tc, T);
        Tc[j] = d->T_in;
        wall_heat(sn, T, sn->Q1);
        for (int m = 0; m < nc; m++)
            gsl_matrix_set(sn->A, (size_t)m, (size_t)j, sn->Q0[m] - sn->Q1[m] + (m == j) * W -
                           (m == j + 1) * W);
    }
    if (st != ACBB_OK) return st;
    for (int m = 0; m < nc; m++) gsl_vector_set(sn->b, (size_t)m, sn->Q0[m]);
    int sgn;
    if (gsl_linalg_LU_decomp(sn->A, sn->perm, &sgn) != GSL_SUCCESS ||
        gsl_linalg_LU_solve(sn->A, sn->perm, sn->b, sn->y) != GSL_SUCCESS)
        return ACBB_SINGULAR;
    for (int m = 0; m < nc; m++) Tc[m] = d->T_in + gsl_vector_get(sn->y, (size_t)m);
    return solid(sn, dt, Tc, T);
}

/* The caller's heat on the nodes that carry it, plus the motor's. */
static acbb_status heat_vector(acbb_spindle_net *sn, const double *q)
{
    memcpy(sn->q, sn->q_motor, (size_t)sn->n * sizeof *sn->q);
    sn->Q_parts = 0.0;
    for (int i = 0; i < sn->n; i++) {
        if (q[i] == 0.0) continue;
        if (!isfinite(q[i]) || acbb_tnet_is_fixed(sn->net, sn->target[i])) return ACBB_EINVAL;
        sn->q[sn->target[i]] += q[i];
        sn->Q_parts += q[i];
    }
    return ACBB_OK;
}

/* Nodes that became spindle nodes read their temperature. */
static void read_targets(const acbb_spindle_net *sn, double *T)
{
    for (int i = 0; i < sn->n; i++)
        if (sn->target[i] != i) T[i] = T[sn->target[i]];
}

acbb_status acbb_spindle_net_solve(acbb_spindle_net *sn, const double *q, double dt, double *T,
                                   acbb_error *err)
{
    if (!q || !T || !isfinite(dt) || dt < 0.0)
        return acbb_error_set(err, ACBB_EINVAL, "spindle heat: time step %g s (must be >= 0) "
                              "or no heat or temperature vector", dt);
    if (heat_vector(sn, q) != ACBB_OK)
        return acbb_error_set(err, ACBB_EINVAL, "spindle heat: a heat input is not finite or "
                              "sits on a node held at a fixed temperature");
    memcpy(sn->T_old, T, (size_t)sn->n * sizeof *T);
    sn->dt = dt;
    acbb_status st = with_coolant(sn, dt, T);
    for (int i = 0; i < sn->n && st == ACBB_OK; i++)
        if (!isfinite(T[i])) st = ACBB_NONFINITE;
    if (st != ACBB_OK) {
        memcpy(T, sn->T_old, (size_t)sn->n * sizeof *T);
        return acbb_error_set(err, st, "spindle heat: the network solve failed (%s%s)",
                              acbb_status_name(st), st == ACBB_SINGULAR ?
                              ": a part has no path to the air or the coolant" : "");
    }
    read_targets(sn, T);
    return ACBB_OK;
}

void acbb_spindle_net_flows(const acbb_spindle_net *sn, const double *T, acbb_spindle_flows *f)
{
    const acbb_spindle_thermal_def *d = &sn->sp->def;
    memset(f, 0, sizeof *f);
    f->Q_parts = sn->Q_parts;
    f->Q_motor = sn->Q_motor;
    to_fixed(sn, T, &f->Q_coolant_wall, &f->Q_air);
    for (int i = 0; i < sn->n && sn->dt > 0.0; i++)
        if (!acbb_tnet_is_fixed(sn->net, i))
            f->storage_rate += acbb_tnet_capacity(sn->net, i) * (T[i] - sn->T_old[i]) / sn->dt;
    f->T_coolant_in = d->T_in;
    f->T_coolant_out = d->n_cool ? T[sn->sp->cool0 + d->n_cool - 1] : d->T_in;
    f->Q_advected = d->n_cool ? d->m_dot * d->c_p * (f->T_coolant_out - d->T_in) : 0.0;
}

/* Axial growth of chain c from xa to xb, signed (negative when xb < xa), m. */
static double growth_between(const acbb_axial_chain *c, const double *T, double T_ref, double xa,
                             double xb)
{
    double g = acbb_axial_chain_growth(c, T, T_ref, fmin(xa, xb), fmax(xa, xb));
    return xb >= xa ? g : -g;
}

/* Free radial growth of a chain's cell at x: alpha (T - T_ref) r, with r
 * the outer radius (shaft) or the bore's (housing), m. */
static double radial_at(const acbb_axial_chain *c, const double *T, double T_ref, double x,
                        int bore)
{
    int i = acbb_axial_chain_cell_at(c, x);
    const acbb_shaft_seg *s = c->seg[i];
    return s->alpha * (T[c->first + i] - T_ref) * 0.5 * (bore ? s->d_bore : s->d_out);
}

void acbb_spindle_net_growth(const acbb_spindle_net *sn, const double *T, acbb_spindle_growth *g)
{
    const acbb_axial_chain *sc = &sn->sp->sc, *hc = &sn->sp->hc;
    double Tr = sn->T_ambient, xf = sn->x_set[0], xr = sn->x_set[1];
    g->shift_axial = growth_between(sc, T, Tr, xf, xr) - growth_between(hc, T, Tr, xf, xr);
    for (int p = 0; p < 2; p++) {
        g->radial_shaft[p] = radial_at(sc, T, Tr, sn->x_set[p], 0);
        g->radial_housing[p] = radial_at(hc, T, Tr, sn->x_set[p], 1);
    }
    g->nose_axial = growth_between(sc, T, Tr, 0.0, xf);
    g->nose_radial = radial_at(sc, T, Tr, 0.0, 0);
}

/* A chain's cells into at most ACBB_SPINDLE_MAX_CELLS entries: groups of
 * neighbours, each at its length-weighted centre and mean temperature. */
static int chain_view(const acbb_axial_chain *c, const double *T, double *x, double *Tv)
{
    int g = (c->n + ACBB_SPINDLE_MAX_CELLS - 1) / ACBB_SPINDLE_MAX_CELLS, n = 0;
    for (int i0 = 0; i0 < c->n; i0 += g, n++) {
        double L = 0.0, xs = 0.0, Ts = 0.0;
        for (int i = i0; i < i0 + g && i < c->n; i++) {
            double l = c->x1[i] - c->x0[i];
            L += l;
            xs += l * 0.5 * (c->x0[i] + c->x1[i]);
            Ts += l * T[c->first + i];
        }
        x[n] = xs / L;
        Tv[n] = Ts / L;
    }
    return n;
}

void acbb_spindle_net_view(const acbb_spindle_net *sn, const double *T, acbb_spindle_view *v)
{
    acbb_spindle_flows f;
    acbb_spindle_growth g;
    acbb_spindle_net_flows(sn, T, &f);
    acbb_spindle_net_growth(sn, T, &g);
    v->n_shaft = chain_view(&sn->sp->sc, T, v->shaft_x, v->shaft_T_C);
    v->n_housing = chain_view(&sn->sp->hc, T, v->housing_x, v->housing_T_C);
    v->Q_motor_W = f.Q_motor;
    v->Q_bearings_W = f.Q_parts;
    v->Q_coolant_W = f.Q_advected;
    v->Q_air_W = f.Q_air;
    v->T_coolant_in_C = f.T_coolant_in;
    v->T_coolant_out_C = f.T_coolant_out;
    v->nose_drift_axial = g.nose_axial;
    v->nose_drift_radial = g.nose_radial;
    v->rear_shift = g.shift_axial;
    for (int p = 0; p < 2; p++) v->sets[p].x = sn->x_set[p];
}
