/* acbb — the rating life of a computed state (life_eval.h, MODEL.md 15):
 * ISO/TS 16281 reference life from the balls' loads at their operating
 * angles, the ISO 281 modified life from the oil's viscosity at the rings'
 * temperature, ISO 76 static safety per contact and the ellipse against the
 * shoulders. The formulas are physics/life.c's. */
#include <math.h>
#include <stdio.h>
#include "acbb/tools/life_eval.h"
#include "acbb/units.h"
#include "life_static.h"
#include "hertz.h"
#include "life.h"
#include "lubrication.h"

/* Load-weighted mean contact angle of one raceway (the nominal angle when
 * nothing is loaded): the angle the raceway's rating is taken at. */
static double mean_angle(const acbb_snapshot *sn, acbb_life_race r, double nominal)
{
    double w = 0.0, sum = 0.0;
    for (int j = 0; j < sn->n_balls; j++) {
        const acbb_ball_view *b = &sn->balls[j];
        double Q = r == ACBB_RACE_IN ? b->Qi : b->Qo;
        sum += Q * (r == ACBB_RACE_IN ? b->alpha_i : b->alpha_o);
        w += Q;
    }
    return w > 0.0 ? sum / w : nominal;
}

/* L_10r in 10^6 rev: raceway ratings at each raceway's operating angle,
 * the rotating inner ring's loads with exponent 3, the outer's with 10/3. */
static double reference_life(const acbb_scene *s, const acbb_snapshot *sn)
{
    double Dw = s->ball_diameter, dm = s->pitch_diameter;
    double fi = s->inner_groove_radius / Dw, fo = s->outer_groove_radius / Dw;
    double Qin[ACBB_MAX_BALLS], Qout[ACBB_MAX_BALLS], Qci, Qce, unused;
    int Z = sn->n_balls < ACBB_MAX_BALLS ? sn->n_balls : ACBB_MAX_BALLS;
    for (int j = 0; j < Z; j++) {
        Qin[j] = sn->balls[j].Qi;
        Qout[j] = sn->balls[j].Qo;
    }
    double ai = mean_angle(sn, ACBB_RACE_IN, s->contact_angle0);
    double ao = mean_angle(sn, ACBB_RACE_OUT, s->contact_angle0);
    double gi = Dw * cos(ai) / dm, go = Dw * cos(ao) / dm;
    acbb_iso_raceway_ratings(acbb_iso_C(Dw, Z, ai, dm, fi, fo), Z, ai, gi, fi, fo, &Qci, &unused);
    acbb_iso_raceway_ratings(acbb_iso_C(Dw, Z, ao, dm, fi, fo), Z, ao, go, fi, fo, &unused, &Qce);
    return acbb_iso_L10r(Qci, acbb_iso_equiv_load(Qin, Z, 3.0), Qce,
                         acbb_iso_equiv_load(Qout, Z, 10.0 / 3.0));
}

static double cap_h(double h) { return isfinite(h) ? fmin(h, ACBB_LIFE_CAP_H) : ACBB_LIFE_CAP_H; }

/* a_1, kappa and a_ISO: nu at the mean ring temperature (ISO 281 9.3.3
 * "operating temperature"), e_c C_u / P with P the reference load. */
static void modified(const acbb_scene *s, const acbb_snapshot *sn, double n_rpm, double L10h,
                     acbb_life *L)
{
    acbb_oil_state oil;
    L->T_oil_C = 0.5 * (sn->T_inner_ring + sn->T_outer_ring);
    acbb_oil_at(s, L->T_oil_C, &oil);
    double nu1 = acbb_iso_nu1(n_rpm, s->pitch_diameter);
    L->nu_mm2s = oil.nu * 1e6;
    L->nu1_mm2s = isfinite(nu1) ? nu1 * 1e6 : 0.0;
    L->kappa = isfinite(nu1) ? oil.nu / nu1 : 0.0;
    L->kappa_clamped = isfinite(nu1) && acbb_iso_kappa_clamped(L->kappa);
    L->ec = s->life_ec;
    L->Cu = s->life_Cu > 0.0 ? s->life_Cu : acbb_iso_Cu(L->C0, s->pitch_diameter);
    L->a1 = acbb_iso_a1(s->life_reliability);
    double ecp = L->P_ref > 0.0 ? L->ec * L->Cu / L->P_ref : INFINITY;
    L->a_iso = acbb_iso_a_iso(L->kappa, ecp);
    L->Lnmr_h = cap_h(L->a1 * L->a_iso * L10h);
}

/* Shoulder height over the groove bottom: the [life] input, else from the
 * land diameters (groove bottoms at d_m -/+ D_w). */
static double shoulder(const acbb_scene *s, acbb_life_race r)
{
    if (r == ACBB_RACE_IN)
        return s->life_shoulder_inner > 0.0 ? s->life_shoulder_inner
            : 0.5 * (s->inner_land_diameter - (s->pitch_diameter - s->ball_diameter));
    return s->life_shoulder_outer > 0.0 ? s->life_shoulder_outer
        : 0.5 * (s->pitch_diameter + s->ball_diameter - s->outer_land_diameter);
}

/* One contact's s0 and edge margin into the running minima. */
static void contact(const acbb_scene *s, const acbb_ball_view *b, int j, acbb_life_race r,
                    acbb_life *L, double *margin)
{
    int in = r == ACBB_RACE_IN;
    double Q = in ? b->Qi : b->Qo, p = in ? b->pmax_i : b->pmax_o;
    if (!(Q > 0.0) || !(p > 0.0)) return;
    double s0 = acbb_iso_s0(p);
    if (L->s0_ball < 0 || s0 < L->s0_min) {
        L->s0_min = s0;
        L->s0_ball = j;
        L->s0_race = r;
    }
    double rg = in ? s->inner_groove_radius : s->outer_groove_radius;
    double m = acbb_edge_margin(in ? b->alpha_i : b->alpha_o, in ? b->a_i : b->a_o, rg,
                                shoulder(s, r));
    if (L->edge_ball < 0 || m < *margin) {
        *margin = m;
        L->edge_ball = j;
        L->edge_race = r;
    }
}

static void statics(const acbb_scene *s, const acbb_snapshot *sn, acbb_life *L)
{
    double margin = 0.0;
    L->s0_ball = L->edge_ball = -1;
    L->s0_min = 0.0;
    for (int j = 0; j < sn->n_balls; j++) {
        contact(s, &sn->balls[j], j, ACBB_RACE_IN, L, &margin);
        contact(s, &sn->balls[j], j, ACBB_RACE_OUT, L, &margin);
    }
    L->edge_margin_deg = acbb_rad_to_deg(margin);
    L->edge_loaded = L->edge_ball >= 0 && margin < 0.0;
    if (L->s0_ball < 0) L->s0_min = 0.0;
}

/* C0 on ISO 76's 4200 MPa basis with the real grooves and materials (the
 * table where they are its own): the scene's geometry alone decides it. */
void acbb_life_static_basis(const acbb_scene *s, acbb_life_static *b)
{
    double Dw = s->ball_diameter, fi = s->inner_groove_radius / Dw;
    double fo = s->outer_groove_radius / Dw;
    double E = acbb_effective_modulus(s->ball.E, s->ball.nu, s->ring.E, s->ring.nu);
    b->C0 = acbb_iso_C0(Dw, s->n_balls, s->contact_angle0, s->pitch_diameter, fi, fo, E);
    b->C0_table = acbb_iso_table_basis(Dw, fi, fo, E);
    b->C0_stress = acbb_iso_C0_stress(Dw, s->n_balls, s->contact_angle0, s->pitch_diameter, fi,
                                      fo, E);
}

/* The static equivalent load P0 of the worst contact on the same basis:
 * the radial load C0_stress / s0. */
static void static_rating(const acbb_life_static *b, acbb_life *L)
{
    L->C0 = b->C0;
    L->C0_table = b->C0_table;
    L->P0 = L->s0_ball >= 0 && L->s0_min > 0.0 ? b->C0_stress / L->s0_min : 0.0;
}

void acbb_life_compute(const acbb_scene *s, const acbb_snapshot *sn, acbb_life *L)
{
    acbb_life_static b;
    acbb_life_static_basis(s, &b);
    acbb_life_compute_with(s, sn, &b, L);
}

void acbb_life_compute_with(const acbb_scene *s, const acbb_snapshot *sn,
                            const acbb_life_static *basis, acbb_life *L)
{
    *L = (acbb_life){ 0 };
    int Z = sn->n_balls < ACBB_MAX_BALLS ? sn->n_balls : ACBB_MAX_BALLS;
    L->estimated = s->life_estimated;
    L->C = acbb_iso_C(s->ball_diameter, s->n_balls, s->contact_angle0, s->pitch_diameter,
                      s->inner_groove_radius / s->ball_diameter,
                      s->outer_groove_radius / s->ball_diameter);
    statics(s, sn, L);
    static_rating(basis, L);
    double n_rpm = acbb_rads_to_rpm(fabs(s->inner_speed));
    double L10 = Z > 0 ? reference_life(s, sn) : INFINITY;
    L->L10r_Mrev = isfinite(L10) ? fmin(L10, ACBB_LIFE_CAP_H) : ACBB_LIFE_CAP_H;
    L->P_ref = isfinite(L10) && L10 > 0.0 ? L->C / cbrt(L10) : 0.0;
    double L10h = n_rpm > 0.0 ? L10 * 1e6 / (60.0 * n_rpm) : INFINITY;
    L->L10r_h = cap_h(L10h);
    modified(s, sn, n_rpm, L10h, L);
}

void acbb_life_contact_name(int ball, acbb_life_race race, char *buf, unsigned long n)
{
    if (ball < 0) snprintf(buf, n, "none");
    else snprintf(buf, n, "%s ball %d", race == ACBB_RACE_IN ? "inner" : "outer", ball);
}
