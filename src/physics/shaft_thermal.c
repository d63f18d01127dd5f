/* acbb — the spindle's thermal network: validation and build
 * (docs/spindle.md "Heat"; the solves are in shaft_thermal_solve.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "shaft_thermal_priv.h"

static acbb_status in_range(acbb_error *err, const char *name, double v, double lo, double hi,
                            int lo_open, const char *unit)
{
    if (isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi) return ACBB_OK;
    return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: %s = %g %s (must be in %c%g, %g])",
                          name, v, unit, lo_open ? '(' : '[', lo, hi);
}

static acbb_status span_inside(acbb_error *err, const char *name, acbb_span s, double lo,
                               double hi, const char *part)
{
    if (isfinite(s.x0) && isfinite(s.x1) && s.x0 <= s.x1 && s.x0 >= lo && s.x1 <= hi)
        return ACBB_OK;
    return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: %s from %g to %g m must lie "
                          "within the %s [%g, %g] m", name, s.x0, s.x1, part, lo, hi);
}

static acbb_status check_stations(const acbb_spindle_thermal_def *d, double Ls, double h0,
                                  double h1, acbb_error *err)
{
    if (d->n_station < 1 || d->n_station > ACBB_SPINDLE_MAX_STATIONS || !d->station)
        return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: %d bearing stations "
                              "(must be in [1, %d])", d->n_station, ACBB_SPINDLE_MAX_STATIONS);
    if (d->fixed_station < 0 || d->fixed_station >= d->n_station)
        return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: fixed station %d (must be "
                              "in [1, %d])", d->fixed_station + 1, d->n_station);
    acbb_status st = ACBB_OK;
    for (int k = 0; k < d->n_station && st == ACBB_OK; k++) {
        const acbb_spindle_station *s = &d->station[k];
        acbb_span at = {s->x, s->x};
        st = span_inside(err, "a bearing station", at, 0.0, Ls, "shaft");
        if (st == ACBB_OK) st = span_inside(err, "a bearing station", at, h0, h1, "housing");
        if (st == ACBB_OK) st = in_range(err, "station G_shaft", s->G_shaft, 0, 1e6, 1, "W/K");
        if (st == ACBB_OK) st = in_range(err, "station G_housing", s->G_housing, 0, 1e6, 1, "W/K");
        if (st == ACBB_OK) st = in_range(err, "station capacity", s->C, 0, 1e7, 0, "J/K");
    }
    return st;
}

static acbb_status check_motor(const acbb_spindle_thermal_def *d, double Ls, double h0,
                               double h1, acbb_error *err)
{
    acbb_status st = span_inside(err, "the rotor", d->rotor, 0.0, Ls, "shaft");
    if (st == ACBB_OK) st = span_inside(err, "the stator", d->stator, h0, h1, "housing");
    if (st == ACBB_OK) st = in_range(err, "G_gap", d->G_gap, 0, 1e6, 0, "W/K");
    if (st == ACBB_OK && d->G_gap > 0.0 &&
        acbb_overlap(d->rotor.x0, d->rotor.x1, d->stator.x0, d->stator.x1) <= 0.0)
        st = acbb_error_set(err, ACBB_EINVAL, "spindle thermal: G_gap = %g W/K needs a rotor "
                            "and a stator that overlap along the axis", d->G_gap);
    return st;
}

static acbb_status check_coolant(const acbb_spindle_thermal_def *d, double h0, double h1,
                                 acbb_error *err)
{
    if (d->n_cool < 0 || d->n_cool > ACBB_SPINDLE_MAX_COOL)
        return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: %d coolant cells (must be "
                              "in [0, %d])", d->n_cool, ACBB_SPINDLE_MAX_COOL);
    if (d->n_cool == 0) return ACBB_OK;
    acbb_status st = span_inside(err, "the coolant jacket", d->jacket, h0, h1, "housing");
    if (st == ACBB_OK && !(d->jacket.x1 > d->jacket.x0))
        st = acbb_error_set(err, ACBB_EINVAL, "spindle thermal: the coolant jacket has no length");
    if (st == ACBB_OK) st = in_range(err, "coolant m_dot", d->m_dot, 0, 100, 1, "kg/s");
    if (st == ACBB_OK) st = in_range(err, "coolant c_p", d->c_p, 0, 1e5, 1, "J/(kg K)");
    if (st == ACBB_OK) st = in_range(err, "coolant T_in", d->T_in, -50, 300, 0, "C");
    if (st == ACBB_OK) st = in_range(err, "jacket hA", d->hA, 0, 1e7, 1, "W/K");
    if (st == ACBB_OK) st = in_range(err, "coolant capacity", d->C_cool, 0, 1e8, 0, "J/K");
    return st;
}

static acbb_status check_def(const acbb_spindle_thermal_def *d, acbb_error *err)
{
    acbb_status st = acbb_shaft_segs_check("shaft", d->shaft, d->n_shaft, ACBB_SEG_THERM, err);
    if (st == ACBB_OK)
        st = acbb_shaft_segs_check("housing", d->housing, d->n_housing, ACBB_SEG_THERM, err);
    if (st == ACBB_OK) st = in_range(err, "housing start", d->housing_x0, -100, 100, 0, "m");
    if (st != ACBB_OK) return st;
    double Ls = acbb_shaft_segs_length(d->shaft, d->n_shaft);
    double h0 = d->housing_x0, h1 = h0 + acbb_shaft_segs_length(d->housing, d->n_housing);
    st = check_stations(d, Ls, h0, h1, err);
    if (st == ACBB_OK) st = check_motor(d, Ls, h0, h1, err);
    if (st == ACBB_OK) st = check_coolant(d, h0, h1, err);
    if (st == ACBB_OK) st = in_range(err, "T_air", d->T_air, -50, 300, 0, "C");
    if (st == ACBB_OK) st = in_range(err, "T_ref", d->T_ref, -50, 300, 0, "C");
    if (st == ACBB_OK) st = in_range(err, "h_housing", d->h_housing, 0, 1e5, 0, "W/(m2 K)");
    if (st == ACBB_OK) st = in_range(err, "h_shaft_end", d->h_shaft_end, 0, 1e5, 0, "W/(m2 K)");
    return st;
}

/* Copy the definition's arrays so the caller's may go. */
static acbb_status copy_def(acbb_spindle_thermal *sp, const acbb_spindle_thermal_def *d)
{
    sp->def = *d;
    sp->shaft = malloc((size_t)d->n_shaft * sizeof *sp->shaft);
    sp->housing = malloc((size_t)d->n_housing * sizeof *sp->housing);
    sp->station = malloc((size_t)d->n_station * sizeof *sp->station);
    if (!sp->shaft || !sp->housing || !sp->station) return ACBB_ENOMEM;
    memcpy(sp->shaft, d->shaft, (size_t)d->n_shaft * sizeof *sp->shaft);
    memcpy(sp->housing, d->housing, (size_t)d->n_housing * sizeof *sp->housing);
    memcpy(sp->station, d->station, (size_t)d->n_station * sizeof *sp->station);
    sp->def.shaft = sp->shaft;
    sp->def.housing = sp->housing;
    sp->def.station = sp->station;
    return ACBB_OK;
}

static acbb_status add_G(acbb_tnet *net, int a, int b, double G)
{
    if (!(G > 0.0)) return ACBB_OK;
    int e = acbb_tnet_add_edge(net, a, b, 1.0 / G);
    return e < 0 ? (acbb_status)e : ACBB_OK;
}

void acbb_spindle_cool_cell(const acbb_spindle_thermal *sp, int m, double *x0, double *x1)
{
    double L = sp->def.jacket.x1 - sp->def.jacket.x0;
    *x0 = sp->def.jacket.x0 + L * m / sp->def.n_cool;
    *x1 = sp->def.jacket.x0 + L * (m + 1) / sp->def.n_cool;
}

/* Shaft end faces: the half cell in series with the face's film. */
static acbb_status add_shaft_ends(acbb_spindle_thermal *sp)
{
    double h = sp->def.h_shaft_end;
    if (!(h > 0.0)) return ACBB_OK;
    for (int end = 0; end < 2; end++) {
        const acbb_shaft_seg *s = end ? &sp->shaft[sp->def.n_shaft - 1] : &sp->shaft[0];
        double R = acbb_axial_chain_end_resistance(&sp->sc, end) + 1.0 / (h * acbb_seg_area(s));
        int cell = sp->sc.first + (end ? sp->sc.n - 1 : 0);
        int e = acbb_tnet_add_edge(sp->net, cell, sp->air, R);
        if (e < 0) return (acbb_status)e;
    }
    return ACBB_OK;
}

static acbb_status add_stations(acbb_spindle_thermal *sp)
{
    acbb_status st = ACBB_OK;
    for (int k = 0; k < sp->def.n_station && st == ACBB_OK; k++) {
        const acbb_spindle_station *s = &sp->station[k];
        int node = sp->st0 + k;
        st = acbb_tnet_set_capacity(sp->net, node, s->C);
        if (st == ACBB_OK)
            st = add_G(sp->net, node, sp->sc.first + acbb_axial_chain_cell_at(&sp->sc, s->x),
                       s->G_shaft);
        if (st == ACBB_OK)
            st = add_G(sp->net, node, sp->hc.first + acbb_axial_chain_cell_at(&sp->hc, s->x),
                       s->G_housing);
    }
    return st;
}

/* Air gap: G_gap shared by the length common to a shaft cell, a housing
 * cell and the rotor-stator overlap. */
static acbb_status add_gap(acbb_spindle_thermal *sp)
{
    const acbb_spindle_thermal_def *d = &sp->def;
    if (!(d->G_gap > 0.0)) return ACBB_OK;
    double g0 = fmax(d->rotor.x0, d->stator.x0), g1 = fmin(d->rotor.x1, d->stator.x1);
    for (int i = 0; i < sp->sc.n; i++)
        for (int j = 0; j < sp->hc.n; j++) {
            double lo = fmax(fmax(sp->sc.x0[i], sp->hc.x0[j]), g0);
            double hi = fmin(fmin(sp->sc.x1[i], sp->hc.x1[j]), g1);
            if (hi - lo <= 1e-12 * (g1 - g0)) continue;   /* disjoint up to round-off */
            acbb_status st = add_G(sp->net, sp->sc.first + i, sp->hc.first + j,
                                   d->G_gap * (hi - lo) / (g1 - g0));
            if (st != ACBB_OK) return st;
        }
    return ACBB_OK;
}

/* Jacket wall: hA shared by each coolant cell's overlap with housing cells. */
static acbb_status add_coolant(acbb_spindle_thermal *sp)
{
    const acbb_spindle_thermal_def *d = &sp->def;
    double Lj = d->jacket.x1 - d->jacket.x0;
    for (int m = 0; m < d->n_cool; m++) {
        double c0, c1;
        acbb_spindle_cool_cell(sp, m, &c0, &c1);
        acbb_status st = acbb_tnet_set_fixed(sp->net, sp->cool0 + m, d->T_in);
        for (int j = 0; j < sp->hc.n && st == ACBB_OK; j++) {
            double ov = acbb_overlap(c0, c1, sp->hc.x0[j], sp->hc.x1[j]);
            if (ov > 1e-12 * Lj)   /* cells that only touch share no wall */
                st = add_G(sp->net, sp->cool0 + m, sp->hc.first + j, d->hA * ov / Lj);
        }
        if (st != ACBB_OK) return st;
    }
    return ACBB_OK;
}

static acbb_status alloc_state(acbb_spindle_thermal *sp)
{
    size_t n = (size_t)sp->n, nc = (size_t)(sp->def.n_cool > 0 ? sp->def.n_cool : 1);
    sp->net = acbb_tnet_new(sp->n);
    sp->T = calloc(n, sizeof *sp->T);
    sp->T_old = calloc(n, sizeof *sp->T_old);
    sp->q = calloc(n, sizeof *sp->q);
    sp->Q0 = calloc(nc, sizeof *sp->Q0);
    sp->A = gsl_matrix_alloc(nc, nc);
    sp->b = gsl_vector_alloc(nc);
    sp->y = gsl_vector_alloc(nc);
    sp->perm = gsl_permutation_alloc(nc);
    return (sp->net && sp->T && sp->T_old && sp->q && sp->Q0 && sp->A && sp->b && sp->y &&
            sp->perm) ? ACBB_OK : ACBB_ENOMEM;
}

static acbb_status build_net(acbb_spindle_thermal *sp, acbb_error *err)
{
    const acbb_spindle_thermal_def *d = &sp->def;
    acbb_status st = acbb_axial_chain_make(sp->shaft, d->n_shaft, 0.0, d->n_div, 0, &sp->sc, err);
    if (st == ACBB_OK)
        st = acbb_axial_chain_make(sp->housing, d->n_housing, d->housing_x0, d->n_div, sp->sc.n,
                                   &sp->hc, err);
    if (st != ACBB_OK) return st;
    sp->st0 = sp->sc.n + sp->hc.n;
    sp->cool0 = sp->st0 + d->n_station;
    sp->air = sp->cool0 + d->n_cool;
    sp->n = sp->air + 1;
    if (alloc_state(sp) != ACBB_OK)
        return acbb_error_set(err, ACBB_ENOMEM, "spindle thermal: out of memory");
    st = acbb_tnet_set_fixed(sp->net, sp->air, d->T_air);
    if (st == ACBB_OK) st = acbb_axial_chain_add(sp->net, &sp->sc);
    if (st == ACBB_OK) st = acbb_axial_chain_add(sp->net, &sp->hc);
    if (st == ACBB_OK) st = acbb_axial_chain_convect(sp->net, &sp->hc, d->h_housing, sp->air);
    if (st == ACBB_OK) st = add_shaft_ends(sp);
    if (st == ACBB_OK) st = add_stations(sp);
    if (st == ACBB_OK) st = add_gap(sp);
    if (st == ACBB_OK) st = add_coolant(sp);
    if (st != ACBB_OK)
        return acbb_error_set(err, st, "spindle thermal: network build failed (%s)",
                              acbb_status_name(st));
    return ACBB_OK;
}

acbb_status acbb_spindle_thermal_build(const acbb_spindle_thermal_def *def,
                                       acbb_spindle_thermal **out, acbb_error *err)
{
    *out = NULL;
    if (!def) return acbb_error_set(err, ACBB_EINVAL, "spindle thermal: no definition");
    acbb_status st = check_def(def, err);
    if (st != ACBB_OK) return st;
    acbb_spindle_thermal *sp = calloc(1, sizeof *sp);
    if (!sp || copy_def(sp, def) != ACBB_OK) {
        acbb_spindle_thermal_free(sp);
        return acbb_error_set(err, ACBB_ENOMEM, "spindle thermal: out of memory");
    }
    st = build_net(sp, err);
    if (st != ACBB_OK) {
        acbb_spindle_thermal_free(sp);
        return st;
    }
    acbb_spindle_thermal_set_uniform(sp, def->T_air);
    *out = sp;
    return ACBB_OK;
}

void acbb_spindle_thermal_free(acbb_spindle_thermal *sp)
{
    if (!sp) return;
    acbb_axial_chain_free(&sp->sc);
    acbb_axial_chain_free(&sp->hc);
    acbb_tnet_free(sp->net);
    free(sp->shaft);
    free(sp->housing);
    free(sp->station);
    free(sp->T);
    free(sp->T_old);
    free(sp->q);
    free(sp->Q0);
    if (sp->A) gsl_matrix_free(sp->A);
    if (sp->b) gsl_vector_free(sp->b);
    if (sp->y) gsl_vector_free(sp->y);
    if (sp->perm) gsl_permutation_free(sp->perm);
    free(sp);
}
