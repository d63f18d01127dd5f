/* Tests for the spindle thermal network (docs/spindle.md "Heat"): a rod
 * between two fixed temperatures (exact), a convecting fin against the
 * cosh closed form (second order), the coolant chain's energy balance, the
 * whole network's steady and per-step energy balance, the transient
 * reaching the steady state, the thermal growth of a uniformly heated
 * stepped shaft (sum alpha dT L, exact) and the input checks. */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "axial_chain.h"
#include "shaft_thermal.h"
#include "tap.h"

static acbb_shaft_seg steel(double L, double D, double d, double k, double alpha)
{
    acbb_shaft_seg s = {.L = L, .d_out = D, .d_bore = d, .E = 2.1e11, .nu = 0.3,
                        .rho = 7850.0, .k = k, .c = 460.0, .alpha = alpha};
    return s;
}

/* Stepped rod, node 0 fixed at T1 -> front face, rear face -> last node at
 * T2. The flux is (T1 - T2)/sum L/(kA); each cell centre sits at T1 minus
 * the flux times the resistance from the front face: exact for any mesh. */
static void test_rod(void)
{
    acbb_shaft_seg s[2] = {steel(0.1, 0.04, 0.01, 45.0, 0), steel(0.15, 0.03, 0.01, 20.0, 0)};
    acbb_axial_chain c;
    acbb_error err = {{0}};
    acbb_axial_chain_make(s, 2, 0.0, 5, 1, &c, &err);
    acbb_tnet *net = acbb_tnet_new(c.n + 2);
    acbb_axial_chain_add(net, &c);
    int last = c.n + 1;
    acbb_tnet_set_fixed(net, 0, 80.0);
    acbb_tnet_set_fixed(net, last, 20.0);
    acbb_tnet_add_edge(net, 0, 1, acbb_axial_chain_end_resistance(&c, 0));
    acbb_tnet_add_edge(net, c.n, last, acbb_axial_chain_end_resistance(&c, 1));
    double T[32] = {0}, q[32] = {0};
    ok(acbb_tnet_steady(net, q, T) == ACBB_OK, "rod steady solve");
    double R1 = 0.1 / (45.0 * acbb_seg_area(&s[0])), R2 = 0.15 / (20.0 * acbb_seg_area(&s[1]));
    double flux = 60.0 / (R1 + R2), err_max = 0.0;
    for (int i = 0; i < c.n; i++) {
        double xc = 0.5 * (c.x0[i] + c.x1[i]);
        double R = xc <= 0.1 ? xc / 0.1 * R1 : R1 + (xc - 0.1) / 0.15 * R2;
        err_max = fmax(err_max, fabs(T[1 + i] - (80.0 - flux * R)));
    }
    ok(err_max < 1e-11, "stepped rod: cell temperatures on the exact piecewise-linear profile "
       "(max error %.2g K)", err_max);
    is_close(acbb_tnet_heat_to_fixed(net, T), 0.0, 0.0, 1e-10, "rod: what enters leaves");
    acbb_tnet_free(net);
    acbb_axial_chain_free(&c);
}

/* Fin of length L, base (x = 0) at Tb through the half cell, adiabatic tip,
 * surface film h to air at Ta; returns the max |T - closed form| over the
 * cell centres, theta/theta_b = cosh(m (L - x))/cosh(m L), m^2 = 4h/(kD). */
static double fin_error(int n, double *q_base)
{
    const double L = 0.2, D = 0.02, k = 50.0, h = 25.0, Tb = 100.0, Ta = 20.0;
    acbb_shaft_seg s = steel(L, D, 0.0, k, 0);
    acbb_axial_chain c;
    acbb_error err = {{0}};
    acbb_axial_chain_make(&s, 1, 0.0, n, 2, &c, &err);
    acbb_tnet *net = acbb_tnet_new(c.n + 2);
    acbb_axial_chain_add(net, &c);
    acbb_tnet_set_fixed(net, 0, Tb);
    acbb_tnet_set_fixed(net, 1, Ta);
    acbb_tnet_add_edge(net, 0, 2, acbb_axial_chain_end_resistance(&c, 0));
    acbb_axial_chain_convect(net, &c, h, 1);
    double T[256] = {0}, q[256] = {0}, m = sqrt(4.0 * h / (k * D)), e = 0.0;
    acbb_tnet_steady(net, q, T);
    for (int i = 0; i < c.n; i++) {
        double x = 0.5 * (c.x0[i] + c.x1[i]);
        e = fmax(e, fabs(T[2 + i] - Ta - (Tb - Ta) * cosh(m * (L - x)) / cosh(m * L)));
    }
    *q_base = (Tb - T[2]) / acbb_axial_chain_end_resistance(&c, 0);
    acbb_tnet_free(net);
    acbb_axial_chain_free(&c);
    return e;
}

static void test_fin(void)
{
    double q20, q40, q80;
    double e20 = fin_error(20, &q20), e40 = fin_error(40, &q40), e80 = fin_error(80, &q80);
    ok(e40 / e20 < 0.3 && e40 / e20 > 0.2 && e80 / e40 < 0.3 && e80 / e40 > 0.2,
       "fin: error falls as h^2 (%.3g, %.3g, %.3g K)", e20, e40, e80);
    ok(e80 < 1e-4 * 80.0, "fin, 80 cells: within 1e-4 of theta_b of the cosh form (%.2g K)", e80);
    const double m = 10.0, kAm = 50.0 * M_PI / 4.0 * 0.02 * 0.02 * m;
    is_close(q80, kAm * 80.0 * tanh(m * 0.2), 1e-3, 0.0, "fin base heat k A m theta_b tanh(mL)");
}

static const acbb_shaft_seg *shaft_segs(void)
{
    static acbb_shaft_seg s[3];
    s[0] = steel(0.12, 0.07, 0.03, 45.0, 11.5e-6);
    s[1] = steel(0.25, 0.06, 0.03, 40.0, 12.5e-6);
    s[2] = steel(0.10, 0.05, 0.03, 45.0, 11.0e-6);
    return s;
}

static acbb_spindle_thermal_def spindle_def(acbb_shaft_seg *housing,
                                            acbb_spindle_station *st)
{
    housing[0] = steel(0.20, 0.16, 0.11, 50.0, 11e-6);
    housing[1] = steel(0.22, 0.14, 0.10, 50.0, 11e-6);
    st[0] = (acbb_spindle_station){.x = 0.06, .G_shaft = 2.0, .G_housing = 3.0, .C = 100.0};
    st[1] = (acbb_spindle_station){.x = 0.40, .G_shaft = 1.5, .G_housing = 2.5, .C = 80.0};
    acbb_spindle_thermal_def d = {
        .shaft = shaft_segs(), .n_shaft = 3, .housing = housing, .n_housing = 2,
        .housing_x0 = 0.03, .n_div = 6, .station = st, .n_station = 2, .fixed_station = 0,
        .rotor = {0.18, 0.30}, .stator = {0.17, 0.31}, .G_gap = 5.0,
        .jacket = {0.05, 0.40}, .n_cool = 8, .m_dot = 0.01, .c_p = 4180.0, .T_in = 20.0,
        .hA = 150.0, .C_cool = 2000.0, .T_air = 22.0, .h_housing = 10.0, .h_shaft_end = 30.0,
        .T_ref = 20.0};
    return d;
}

static const acbb_spindle_heat HEAT = {.rotor = 300.0, .stator = 600.0, .bearing = {80.0, 40.0}};

static double out_total(const acbb_spindle_thermal_result *r)
{
    return r->Q_air_shaft + r->Q_air_housing + r->Q_coolant_wall;
}

static void test_steady_balance(void)
{
    acbb_shaft_seg hs[2];
    acbb_spindle_station st[2];
    acbb_spindle_thermal_def d = spindle_def(hs, st);
    acbb_spindle_thermal *sp = NULL;
    acbb_spindle_thermal_result r;
    acbb_error err = {{0}};
    int s = acbb_spindle_thermal_build(&d, &sp, &err);
    if (s == ACBB_OK) s = acbb_spindle_thermal_steady(sp, &HEAT, &err);
    ok(s == ACBB_OK, "spindle steady solve (%s)", err.msg);
    acbb_spindle_thermal_results(sp, &r);
    is_close(r.Q_in, 1020.0, 1e-15, 0.0, "sources: rotor + stator + bearings");
    is_close(out_total(&r), r.Q_in, 1e-9, 0.0, "steady: sources = heat to air + coolant");
    is_close(r.Q_advected, r.Q_coolant_wall, 1e-9, 0.0,
             "coolant: wall heat = m_dot c_p (T_out - T_in)");
    ok(r.Q_coolant_wall > 0.5 * r.Q_in && r.Q_air_housing > 0.0 && r.Q_air_shaft > 0.0,
       "every boundary takes heat (coolant %.1f W, housing air %.1f W, shaft ends %.2f W)",
       r.Q_coolant_wall, r.Q_air_housing, r.Q_air_shaft);
    int rising = 1;
    double prev = d.T_in, x, T;
    for (int m = 0; m < acbb_spindle_thermal_cells(sp, ACBB_SPINDLE_COOLANT); m++) {
        acbb_spindle_thermal_cell(sp, ACBB_SPINDLE_COOLANT, m, &x, &T);
        rising &= T > prev;
        prev = T;
    }
    ok(rising && prev == r.T_coolant_out, "coolant warms along the jacket to %.3f C", prev);
    is_close(r.Q_to_shaft[0] + r.Q_to_housing[0], 80.0, 1e-9, 0.0,
             "front bearing: its heat leaves to shaft + housing");
    is_close(r.Q_to_shaft[1] + r.Q_to_housing[1], 40.0, 1e-9, 0.0,
             "rear bearing: its heat leaves to shaft + housing");
    ok(r.T_station[0] > r.T_coolant_out && r.growth_axial > 0.0,
       "bearings above the coolant; the nose grows forward (%.3g um)", r.growth_axial * 1e6);
    acbb_spindle_thermal_free(sp);
}

/* Jacket cells on housing cells one to one (the first housing segment,
 * 6 cells): each coolant cell's balance, upwind,
 * m_dot c_p (Tc_m - Tc_{m-1}) = (hA/6) (T_housing,m - Tc_m), Tc_{-1} = T_in. */
static void test_coolant_cells(void)
{
    acbb_shaft_seg hs[2];
    acbb_spindle_station st[2];
    acbb_spindle_thermal_def d = spindle_def(hs, st);
    d.jacket = (acbb_span){0.03, 0.23};
    d.n_cool = 6;
    acbb_spindle_thermal *sp = NULL;
    acbb_error err = {{0}};
    acbb_spindle_thermal_build(&d, &sp, &err);
    ok(acbb_spindle_thermal_steady(sp, &HEAT, &err) == ACBB_OK, "aligned jacket solves");
    double W = d.m_dot * d.c_p, G = d.hA / 6.0, prev = d.T_in, worst = 0.0, Tc, Th;
    for (int m = 0; m < 6; m++) {
        acbb_spindle_thermal_cell(sp, ACBB_SPINDLE_COOLANT, m, NULL, &Tc);
        acbb_spindle_thermal_cell(sp, ACBB_SPINDLE_HOUSING, m, NULL, &Th);
        worst = fmax(worst, fabs(W * (Tc - prev) - G * (Th - Tc)) / (G * fabs(Th - Tc)));
        prev = Tc;
    }
    ok(worst < 1e-9, "each coolant cell: m_dot c_p (Tc_m - Tc_m-1) = G (T_wall - Tc_m) "
       "(worst %.2g)", worst);
    acbb_spindle_thermal_free(sp);
}

/* Backward Euler conserves energy step by step: Q_in = outflows +
 * m_dot c_p (T_out - T_in) + sum C dT/dt; and it reaches the steady state. */
static void test_transient(void)
{
    acbb_shaft_seg hs[2];
    acbb_spindle_station st[2];
    acbb_spindle_thermal_def d = spindle_def(hs, st);
    acbb_spindle_thermal *sp = NULL, *ss = NULL;
    acbb_spindle_thermal_result r;
    acbb_error err = {{0}};
    acbb_spindle_thermal_build(&d, &ss, &err);
    acbb_spindle_thermal_steady(ss, &HEAT, &err);
    acbb_spindle_thermal_build(&d, &sp, &err);
    double worst = 0.0, dist[201] = {0};
    int n = acbb_spindle_thermal_cells(sp, ACBB_SPINDLE_SHAFT);
    for (int k = 1; k <= 200; k++) {
        if (acbb_spindle_thermal_step(sp, &HEAT, 300.0, &err) != ACBB_OK) break;
        acbb_spindle_thermal_results(sp, &r);
        double bal = r.Q_air_shaft + r.Q_air_housing + r.Q_advected + r.storage_rate - r.Q_in;
        worst = fmax(worst, fabs(bal) / r.Q_in);
        for (int i = 0; i < n; i++) {
            double Ta, Tb;
            acbb_spindle_thermal_cell(sp, ACBB_SPINDLE_SHAFT, i, NULL, &Ta);
            acbb_spindle_thermal_cell(ss, ACBB_SPINDLE_SHAFT, i, NULL, &Tb);
            dist[k] = fmax(dist[k], fabs(Ta - Tb));
        }
    }
    ok(worst < 1e-9, "every step: sources = outflows + advection + storage (worst %.2g)", worst);
    ok(dist[1] > 1.0 && dist[100] < dist[10] && dist[200] < dist[100] && dist[200] < 1e-6,
       "transient reaches the steady state (%.3g K after 1 step, %.2g K after 200)", dist[1],
       dist[200]);
    acbb_spindle_thermal_free(sp);
    acbb_spindle_thermal_free(ss);
}

/* Everything at 60 C (air, coolant, no heat), assembled at 20 C: the nose
 * grows by sum alpha (60 - 20) L from the fixed bearing at x = 0.2 forward,
 * alpha1 over 0.12 m and alpha2 over 0.08 m. */
static void test_uniform_growth(void)
{
    acbb_shaft_seg hs[2];
    acbb_spindle_station st[2];
    acbb_spindle_thermal_def d = spindle_def(hs, st);
    st[0].x = 0.2;
    d.T_air = d.T_in = 60.0;
    acbb_spindle_thermal *sp = NULL;
    acbb_spindle_thermal_result r;
    acbb_error err = {{0}};
    acbb_spindle_heat none = {0};
    acbb_spindle_thermal_build(&d, &sp, &err);
    ok(acbb_spindle_thermal_steady(sp, &none, &err) == ACBB_OK, "uniform steady solve");
    acbb_spindle_thermal_results(sp, &r);
    is_close(r.growth_axial, 40.0 * (11.5e-6 * 0.12 + 12.5e-6 * 0.08), 1e-10, 0.0,
             "axial growth at the nose = sum alpha dT L over the stepped shaft");
    is_close(r.growth_radial_shaft[0], 12.5e-6 * 40.0 * 0.03, 1e-10, 0.0,
             "radial growth of the shaft at the fixed bearing = alpha dT D/2");
    is_close(r.growth_radial_housing[1], 11e-6 * 40.0 * 0.05, 1e-10, 0.0,
             "radial growth of the housing bore at the rear bearing = alpha dT d/2");
    is_close(r.shift_axial[1], 40.0 * (12.5e-6 * 0.17 + 11.0e-6 * 0.03 - 11e-6 * 0.2), 1e-10,
             0.0, "rear bearing: shaft growth - housing growth from the fixed bearing");
    ok(r.shift_axial[0] == 0.0, "no shift at the fixed bearing");
    is_close(out_total(&r), 0.0, 0.0, 1e-9, "no heat, no flow");
    double rear = r.shift_axial[1];
    acbb_spindle_thermal_free(sp);
    d.fixed_station = 1;
    acbb_spindle_thermal_build(&d, &sp, &err);
    acbb_spindle_thermal_steady(sp, &none, &err);
    acbb_spindle_thermal_results(sp, &r);
    is_close(r.shift_axial[0], -rear, 1e-10, 0.0,
             "rear bearing located: the front station shifts the other way");
    acbb_spindle_thermal_free(sp);
}

static void test_checks(void)
{
    acbb_shaft_seg hs[2];
    acbb_spindle_station st[2];
    acbb_spindle_thermal_def d = spindle_def(hs, st);
    acbb_spindle_thermal *sp = NULL;
    acbb_error err = {{0}};
    d.m_dot = 0.0;
    ok(acbb_spindle_thermal_build(&d, &sp, &err) == ACBB_EINVAL && !sp, "m_dot = 0 refused");
    has_substr(err.msg, "coolant m_dot = 0 kg/s (must be in (0, 100])", "message with unit, range");
    d = spindle_def(hs, st);
    st[1].x = 0.5;
    acbb_spindle_thermal_build(&d, &sp, &err);
    has_substr(err.msg, "a bearing station from 0.5 to 0.5 m must lie within the shaft",
               "a station off the shaft refused");
    d = spindle_def(hs, st);
    d.n_cool = 0;
    d.h_housing = d.h_shaft_end = 0.0;
    acbb_spindle_thermal_build(&d, &sp, &err);
    ok(acbb_spindle_thermal_steady(sp, &HEAT, &err) == ACBB_SINGULAR,
       "no air and no coolant: singular");
    has_substr(err.msg, "no path to the air or the coolant", "message says why");
    acbb_spindle_heat neg = HEAT;
    neg.bearing[1] = -1.0;
    ok(acbb_spindle_thermal_step(sp, &neg, 1.0, &err) == ACBB_EINVAL, "negative heat refused");
    acbb_spindle_thermal_free(sp);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_rod();
    test_fin();
    test_steady_balance();
    test_coolant_cells();
    test_transient();
    test_uniform_growth();
    test_checks();
    return done_testing();
}
