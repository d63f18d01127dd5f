/* acbb — the spindle thermal network's steady and backward-Euler solves,
 * with the coolant chain coupled exactly through a Schur complement, and
 * its results: boundary heat flows and the thermal growth
 * (docs/spindle.md "Heat"). */
#include <math.h>
#include <string.h>
#include "shaft_thermal_priv.h"

void acbb_spindle_thermal_set_uniform(acbb_spindle_thermal *sp, double T)
{
    for (int i = 0; i < sp->n; i++) sp->T[i] = T;
    sp->T[sp->air] = sp->def.T_air;
    sp->storage_rate = 0.0;
}

static acbb_status spread(double *q, const acbb_axial_chain *c, acbb_span s, double Q)
{
    double L = s.x1 - s.x0;
    if (Q == 0.0) return ACBB_OK;
    if (!(L > 0.0)) return ACBB_EINVAL;
    for (int i = 0; i < c->n; i++) q[c->first + i] += Q * acbb_overlap(c->x0[i], c->x1[i], s.x0, s.x1) / L;
    return ACBB_OK;
}

static acbb_status heat_vector(acbb_spindle_thermal *sp, const acbb_spindle_heat *h,
                               acbb_error *err)
{
    int ok = h && isfinite(h->rotor) && isfinite(h->stator) && h->rotor >= 0.0 &&
             h->stator >= 0.0 && h->rotor <= 1e6 && h->stator <= 1e6;
    for (int k = 0; ok && k < sp->def.n_station; k++)
        ok = isfinite(h->bearing[k]) && h->bearing[k] >= 0.0 && h->bearing[k] <= 1e6;
    if (!ok)
        return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: every heat input must be "
                              "in [0, 1e6] W");
    memset(sp->q, 0, (size_t)sp->n * sizeof *sp->q);
    if (spread(sp->q, &sp->sc, sp->def.rotor, h->rotor) != ACBB_OK ||
        spread(sp->q, &sp->hc, sp->def.stator, h->stator) != ACBB_OK)
        return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: motor heat on a rotor or "
                              "stator of no length");
    for (int k = 0; k < sp->def.n_station; k++) sp->q[sp->st0 + k] = h->bearing[k];
    sp->heat = *h;
    return ACBB_OK;
}

/* Heat into each coolant cell from its wall for temperatures T, W. */
static void coolant_wall(const acbb_spindle_thermal *sp, const double *T, double *Q)
{
    int ne = acbb_tnet_edge_count(sp->net), lo = sp->cool0, hi = sp->air;
    memset(Q, 0, (size_t)sp->def.n_cool * sizeof *Q);
    for (int e = 0; e < ne; e++) {
        int a, b;
        acbb_tnet_edge_nodes(sp->net, e, &a, &b);
        double f = (T[b] - T[a]) / acbb_tnet_resistance(sp->net, e);
        if (a >= lo && a < hi) Q[a - lo] += f;
        if (b >= lo && b < hi) Q[b - lo] -= f;
    }
}

/* The solid (everything but the coolant) with the coolant cells held at Tc:
 * a steady solve (dt = 0) or one step from T_old. Q gets the wall heats. */
static acbb_status solid_solve(acbb_spindle_thermal *sp, double dt, const double *Tc, double *Q)
{
    for (int m = 0; m < sp->def.n_cool; m++) acbb_tnet_set_fixed(sp->net, sp->cool0 + m, Tc[m]);
    acbb_status st;
    if (dt > 0.0) {
        memcpy(sp->T, sp->T_old, (size_t)sp->n * sizeof *sp->T);
        st = acbb_tnet_step(sp->net, sp->q, dt, sp->T);
    } else {
        st = acbb_tnet_steady(sp->net, sp->q, sp->T);
    }
    if (st == ACBB_OK && Q) coolant_wall(sp, sp->T, Q);
    return st;
}

/* Coolant balances (C_m/dt + m_dot c_p) Tc_m - m_dot c_p Tc_{m-1} = Q_m(Tc)
 * + C_m/dt Tc_m^old with Tc_{-1} = T_in; Q is affine in Tc, so its columns
 * come from unit perturbations and the system is solved once, exactly. */
static acbb_status coupled(acbb_spindle_thermal *sp, double dt)
{
    const acbb_spindle_thermal_def *d = &sp->def;
    int nc = d->n_cool;
    double Tc[ACBB_SPINDLE_MAX_COOL] = {0}, Q[ACBB_SPINDLE_MAX_COOL];
    double W = d->m_dot * d->c_p, cdt = dt > 0.0 ? d->C_cool / nc / dt : 0.0;
    if (nc == 0) return solid_solve(sp, dt, NULL, NULL);
    for (int m = 0; m < nc; m++) Tc[m] = d->T_in;
    acbb_status st = solid_solve(sp, dt, Tc, sp->Q0);
    for (int j = 0; j < nc && st == ACBB_OK; j++) {
        Tc[j] = d->T_in + 1.0;
        st = solid_solve(sp, dt, Tc, Q);
        Tc[j] = d->T_in;
        for (int m = 0; m < nc; m++) gsl_matrix_set(sp->A, (size_t)m, (size_t)j, sp->Q0[m] - Q[m]);
    }
    if (st != ACBB_OK) return st;
    for (int m = 0; m < nc; m++) {
        *gsl_matrix_ptr(sp->A, (size_t)m, (size_t)m) += cdt + W;
        if (m > 0) *gsl_matrix_ptr(sp->A, (size_t)m, (size_t)(m - 1)) -= W;
        gsl_vector_set(sp->b, (size_t)m, sp->Q0[m] + cdt * (sp->T_old[sp->cool0 + m] - d->T_in));
    }
    int sgn;
    if (gsl_linalg_LU_decomp(sp->A, sp->perm, &sgn) != GSL_SUCCESS ||
        gsl_linalg_LU_solve(sp->A, sp->perm, sp->b, sp->y) != GSL_SUCCESS)
        return ACBB_SINGULAR;
    for (int m = 0; m < nc; m++) Tc[m] = d->T_in + gsl_vector_get(sp->y, (size_t)m);
    return solid_solve(sp, dt, Tc, NULL);
}

static acbb_status finish(acbb_spindle_thermal *sp, acbb_status st, acbb_error *err)
{
    for (int i = 0; i < sp->n && st == ACBB_OK; i++)
        if (!isfinite(sp->T[i])) st = ACBB_NONFINITE;
    if (st != ACBB_OK) {
        memcpy(sp->T, sp->T_old, (size_t)sp->n * sizeof *sp->T);
        return acbb_error_set(err, st, "spindle thermal: the network solve failed (%s%s)",
                              acbb_status_name(st), st == ACBB_SINGULAR ?
                              ": a part has no path to the air or the coolant" : "");
    }
    return ACBB_OK;
}

acbb_status acbb_spindle_thermal_steady(acbb_spindle_thermal *sp, const acbb_spindle_heat *h,
                                        acbb_error *err)
{
    acbb_status st = heat_vector(sp, h, err);
    if (st != ACBB_OK) return st;
    memcpy(sp->T_old, sp->T, (size_t)sp->n * sizeof *sp->T);
    sp->storage_rate = 0.0;
    return finish(sp, coupled(sp, 0.0), err);
}

/* Heat stored per second over the step just taken (solid and coolant), W. */
static double storage(const acbb_spindle_thermal *sp, double dt)
{
    double s = 0.0, Cc = sp->def.n_cool ? sp->def.C_cool / sp->def.n_cool : 0.0;
    for (int i = 0; i < sp->n; i++) {
        double C = (i >= sp->cool0 && i < sp->air) ? Cc : acbb_tnet_capacity(sp->net, i);
        s += C * (sp->T[i] - sp->T_old[i]) / dt;
    }
    return s;
}

acbb_status acbb_spindle_thermal_step(acbb_spindle_thermal *sp, const acbb_spindle_heat *h,
                                      double dt, acbb_error *err)
{
    if (!isfinite(dt) || dt <= 0.0)
        return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: time step %g s (must be > 0)",
                              dt);
    acbb_status st = heat_vector(sp, h, err);
    if (st != ACBB_OK) return st;
    memcpy(sp->T_old, sp->T, (size_t)sp->n * sizeof *sp->T);
    st = finish(sp, coupled(sp, dt), err);
    sp->storage_rate = st == ACBB_OK ? storage(sp, dt) : 0.0;
    return st;
}

/* Heat into `node` over its edges to nodes in [lo, hi), W. */
static double flow_into(const acbb_spindle_thermal *sp, int node, int lo, int hi)
{
    int ne = acbb_tnet_edge_count(sp->net);
    double f = 0.0;
    for (int e = 0; e < ne; e++) {
        int a, b;
        acbb_tnet_edge_nodes(sp->net, e, &a, &b);
        int other = a == node ? b : (b == node ? a : -1);
        if (other >= lo && other < hi)
            f += (sp->T[other] - sp->T[node]) / acbb_tnet_resistance(sp->net, e);
    }
    return f;
}

/* Axial displacement at x of a chain located at xf: its growth between
 * the two, signed by the side of xf that x is on. */
static double axial_at(const acbb_axial_chain *c, const double *T, double T_ref, double xf,
                       double x)
{
    double g = acbb_axial_chain_growth(c, T, T_ref, fmin(x, xf), fmax(x, xf));
    return x >= xf ? g : -g;
}

static void growth(const acbb_spindle_thermal *sp, acbb_spindle_thermal_result *r)
{
    const acbb_spindle_thermal_def *d = &sp->def;
    double xf = d->station[d->fixed_station].x;
    r->growth_axial = acbb_axial_chain_growth(&sp->sc, sp->T, d->T_ref, 0.0, xf);
    for (int k = 0; k < d->n_station; k++) {
        double x = d->station[k].x;
        r->shift_axial[k] = axial_at(&sp->sc, sp->T, d->T_ref, xf, x) -
                            axial_at(&sp->hc, sp->T, d->T_ref, xf, x);
        int i = acbb_axial_chain_cell_at(&sp->sc, d->station[k].x);
        int j = acbb_axial_chain_cell_at(&sp->hc, d->station[k].x);
        const acbb_shaft_seg *s = sp->sc.seg[i], *hs = sp->hc.seg[j];
        r->growth_radial_shaft[k] = s->alpha * (sp->T[sp->sc.first + i] - d->T_ref) * 0.5 * s->d_out;
        r->growth_radial_housing[k] =
            hs->alpha * (sp->T[sp->hc.first + j] - d->T_ref) * 0.5 * hs->d_bore;
        r->T_station[k] = sp->T[sp->st0 + k];
        r->Q_to_shaft[k] = -flow_into(sp, sp->st0 + k, sp->sc.first, sp->sc.first + sp->sc.n);
        r->Q_to_housing[k] = -flow_into(sp, sp->st0 + k, sp->hc.first, sp->hc.first + sp->hc.n);
    }
}

void acbb_spindle_thermal_results(const acbb_spindle_thermal *sp,
                                  acbb_spindle_thermal_result *r)
{
    const acbb_spindle_thermal_def *d = &sp->def;
    memset(r, 0, sizeof *r);
    r->Q_in = sp->heat.rotor + sp->heat.stator;
    for (int k = 0; k < d->n_station; k++) r->Q_in += sp->heat.bearing[k];
    r->Q_air_shaft = flow_into(sp, sp->air, sp->sc.first, sp->sc.first + sp->sc.n);
    r->Q_air_housing = flow_into(sp, sp->air, sp->hc.first, sp->hc.first + sp->hc.n);
    for (int m = 0; m < d->n_cool; m++)
        r->Q_coolant_wall += flow_into(sp, sp->cool0 + m, 0, sp->cool0);
    r->T_coolant_out = d->n_cool ? sp->T[sp->air - 1] : d->T_in;
    r->Q_advected = d->n_cool ? d->m_dot * d->c_p * (r->T_coolant_out - d->T_in) : 0.0;
    r->storage_rate = sp->storage_rate;
    growth(sp, r);
}

static const acbb_axial_chain *chain_of(const acbb_spindle_thermal *sp, acbb_spindle_part p)
{
    return p == ACBB_SPINDLE_SHAFT ? &sp->sc : (p == ACBB_SPINDLE_HOUSING ? &sp->hc : NULL);
}

int acbb_spindle_thermal_cells(const acbb_spindle_thermal *sp, acbb_spindle_part part)
{
    const acbb_axial_chain *c = chain_of(sp, part);
    return c ? c->n : (part == ACBB_SPINDLE_COOLANT ? sp->def.n_cool : 0);
}

acbb_status acbb_spindle_thermal_cell(const acbb_spindle_thermal *sp, acbb_spindle_part part,
                                      int i, double *x, double *T)
{
    const acbb_axial_chain *c = chain_of(sp, part);
    if (i < 0 || i >= acbb_spindle_thermal_cells(sp, part)) return ACBB_EINVAL;
    double x0, x1;
    if (c) {
        x0 = c->x0[i];
        x1 = c->x1[i];
    } else {
        acbb_spindle_cool_cell(sp, i, &x0, &x1);
    }
    if (x) *x = 0.5 * (x0 + x1);
    if (T) *T = sp->T[(c ? c->first : sp->cool0) + i];
    return ACBB_OK;
}
