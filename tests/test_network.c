/* Tests for the bearing thermal networks (MODEL.md sections 8.1, 8.3):
 * structure, capacities and resistances against hand formulas, energy
 * balance and maximum principle at steady state, transient convergence,
 * heat mapping, part and inlet averages, guards. */
#include <math.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "network.h"
#include "tap.h"
#include "acbb/tools/surroundings.h"

#define RPM (2.0 * M_PI / 60.0)

static acbb_material mat(double E, double nu, double rho, double cp, double k, double chi)
{
    acbb_material m = {E, nu, rho, cp, k, chi};
    return m;
}

/* 7008C values of MODEL.md section 10, by hand (scene.c is written in
 * parallel; only the fields the network reads matter here). */
static void scene_7008c(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    s->pitch_diameter = 54e-3;
    s->ball_diameter = 6.35e-3;
    s->n_balls = 21;
    s->inner_groove_radius = s->outer_groove_radius = 3.43e-3;
    s->contact_angle0 = 15.0 * M_PI / 180.0;
    s->bore = 40e-3;
    s->outer_diameter = 68e-3;
    s->width = 15e-3;
    s->cage_width = 10.1e-3;
    s->cage_diameter = 57.7e-3;
    s->inner_land_diameter = 49.9e-3;
    s->outer_land_diameter = 58.1e-3;
    s->ball = s->ring = mat(207e9, 0.3, 7810, 450, 40.1, 12.5e-6);
    s->shaft = mat(212e9, 0.298, 7860, 485, 42.4, 11.5e-6);
    s->housing = mat(143e9, 0.27, 7300, 510, 45.0, 10.5e-6);
    s->cage = mat(206e9, 0.254, 7830, 460, 44.0, 11.7e-6);
    s->oil_density = 876;
    s->oil_nu40 = 30e-6;
    s->oil_nu100 = 5.3e-6;
    s->oil_k = 0.13;
    s->oil_cp = 1950;
    s->air_eta = 2e-5;
    s->air_density = 1.128;
    s->air_k = 0.027;
    s->air_cp = 1007;
    s->air_pr = 0.71;
    s->mix_k = 0.04;
    s->q_air = 1e-3;
    s->q_oil = 0.4e-6 / 3600.0;
    s->visc = ACBB_VISC_ROELANDS;
    s->shaft_bore = 25e-3;
    s->h_fit_outer = 5e3;
    s->h_fit_inner = 2e4;
    s->h_face = 3e3;
    s->h_natural = 10;
    s->inner_speed = 15000 * RPM;
    s->ambient_C = 26.0;
    s->network = ACBB_NET_46;
    s->contact_multiplier = 1.0;
    s->heat_partition = 0.5;
    s->housing_bc = ACBB_BC_CONVECTIVE;   /* [surroundings]: sizes 0 = derived */
}

/* Complete elliptic integral K(k) by the arithmetic-geometric mean,
 * independent of the GSL routine the engine uses. */
static double K_agm(double k)
{
    double a = 1.0, b = sqrt(1.0 - k * k);
    for (int i = 0; i < 40; i++) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return M_PI / (2.0 * a);
}

static int find_edge(const acbb_network *nw, int p, int q)
{
    for (int e = 0; e < acbb_tnet_edge_count(nw->net); e++) {
        int a, b;
        acbb_tnet_edge_nodes(nw->net, e, &a, &b);
        if ((a == p && b == q) || (a == q && b == p)) return e;
    }
    return -1;
}

/* 7008C running state: a ~ 1.0 mm, b ~ 0.17 mm, 15000 rpm; cage speed from
 * rolling kinematics omega_m = omega_i/2 (1 - D cos(alpha)/d_m). */
static acbb_net_inputs inputs_15k(const acbb_scene *s)
{
    acbb_net_inputs in = { 0 };
    in.a_i = in.a_o = 1.0e-3;
    in.b_i = in.b_o = 0.17e-3;
    in.omega_i = s->inner_speed;
    in.omega_m = 0.5 * s->inner_speed *
                 (1.0 - s->ball_diameter * cos(s->contact_angle0) / s->pitch_diameter);
    in.T_cavity_C = 40.0;
    return in;
}

static const acbb_heat_sources SRC = {20.0, 15.0, 5.0, 3.0, 0.0};   /* 43 W */

static double cap_sum(const acbb_network *nw, const int *nodes, int n)
{
    double c = 0.0;
    for (int i = 0; i < n; i++) c += acbb_tnet_capacity(nw->net, nodes[i]);
    return c;
}

static void test_build46_structure(const acbb_scene *s, acbb_network *nw)
{
    acbb_error err = {{0}};
    ok(acbb_network_build(s, nw, &err) == ACBB_OK, "46-node build OK (%s)", err.msg);
    ok(nw->n == 46 && acbb_tnet_node_count(nw->net) == 46, "46 nodes");
    int nfix = 0, fixed_ok = 1;
    static const int D[] = {0, 28, 30, 38, 40, 42};
    for (int i = 0; i < 46; i++) nfix += acbb_tnet_is_fixed(nw->net, i);
    for (int i = 0; i < 6; i++) fixed_ok &= acbb_tnet_is_fixed(nw->net, D[i]);
    ok(nfix == 6 && fixed_ok, "exactly nodes 0, 28, 30, 38, 40, 42 are Dirichlet");
    /* MODEL.md 8.1 edge table, group by group:
     * 4+12+2+3+9+2+1+6+2+4+2+3+9+3+2+3+1 = 68 edges */
    ok(acbb_tnet_edge_count(nw->net) == 68, "68 edges as in the MODEL 8.1 table (%d)",
       acbb_tnet_edge_count(nw->net));
    int all_present = 1;
    static const int sample[][2] = {{2, 5}, {4, 8}, {31, 11}, {12, 37}, {7, 45},
                                    {45, 13}, {19, 44}, {44, 17}, {10, 18}, {21, 27},
                                    {24, 29}, {41, 42}, {43, 0}, {16, 43}, {36, 35}};
    for (size_t i = 0; i < sizeof sample / sizeof sample[0]; i++)
        all_present &= find_edge(nw, sample[i][0], sample[i][1]) >= 0;
    ok(all_present, "sampled edges of the MODEL table are present");
    ok(strcmp(nw->names[5], "5 OR outer front (sensor)") == 0 &&
       strcmp(nw->names[0], "0 ambient") == 0, "node names for display");
    ok(nw->heat_inner == 44 && nw->heat_outer == 45 && nw->heat_spin == 15 &&
       nw->heat_drag == 43, "heat destinations 44/45/15/43");
    ok(nw->node_outer_ring == 5 && nw->inlet_inner[0] == 19 && nw->inlet_inner[1] == 17 &&
       nw->inlet_outer[0] == 7 && nw->inlet_outer[1] == 13, "sensor node 5 and inlet pairs");
}

static void test_capacities46(const acbb_scene *s, const acbb_network *nw)
{
    double ch = s->housing.rho * s->housing.cp, cr = s->ring.rho * s->ring.cp;
    /* hand: housing sleeve r 34..60 mm x 45 mm plus shoulder r 30..34 x 10 */
    double Vh = M_PI * (0.060 * 0.060 - 0.034 * 0.034) * 0.045
                + M_PI * (0.034 * 0.034 - 0.030 * 0.030) * 0.010;
    double Ch = cap_sum(nw, (const int[]){1, 2, 3, 4, 36}, 5);
    is_close(Ch, ch * Vh, 1e-12, 0, "housing capacity = rho cp V (hand)");
    ok(Ch > 1300 / 2.0 && Ch < 1300 * 2.0, "housing ~1.3 kJ/K (%.0f J/K)", Ch);
    double r_race_o = 0.027 + 0.003175, r_race_i = 0.027 - 0.003175;
    double Cor = cap_sum(nw, (const int[]){6, 9}, 2);
    is_close(Cor, cr * M_PI * (0.034 * 0.034 - r_race_o * r_race_o) * 0.015, 1e-12, 0,
             "OR capacity = rho cp pi (r_o^2 - r_race^2) B (hand)");
    ok(Cor > 20 && Cor < 80, "OR ~40 J/K (%.1f J/K)", Cor);
    double Cir = cap_sum(nw, (const int[]){20, 23}, 2);
    is_close(Cir, cr * M_PI * (r_race_i * r_race_i - 0.020 * 0.020) * 0.015, 1e-12, 0,
             "IR capacity (hand)");
    ok(Cir > 14 && Cir < 56, "IR ~28 J/K (%.1f J/K)", Cir);
    double Cb = acbb_tnet_capacity(nw->net, 15);
    is_close(Cb, s->ball.rho * s->ball.cp * 21 * M_PI * pow(6.35e-3, 3) / 6, 1e-12, 0,
             "balls capacity = Z rho cp pi D^3/6");
    ok(Cb > 5 && Cb < 20, "balls ~10 J/K (%.2f J/K)", Cb);
    int algebraic_ok = 1;
    static const int alg[] = {5, 7, 10, 13, 17, 19, 22, 44, 45};
    for (size_t i = 0; i < sizeof alg / sizeof alg[0]; i++)
        algebraic_ok &= acbb_tnet_capacity(nw->net, alg[i]) == 0.0;
    ok(algebraic_ok, "surface and contact nodes are algebraic (C = 0)");
    ok(acbb_tnet_capacity(nw->net, 43) > 0 && acbb_tnet_capacity(nw->net, 43) < 0.1,
       "oil-air node has a small positive capacity");
}

static void test_adv_and_static_R(const acbb_scene *s, const acbb_network *nw)
{
    int e = find_edge(nw, 43, 0);
    /* at build the oil density is taken at ambient, rho20 (1 - 6.5e-4 (T - 20)) */
    double rho_oil = s->oil_density * (1.0 - 6.5e-4 * (s->ambient_C - 20.0));
    double G = s->q_oil * rho_oil * s->oil_cp + s->q_air * s->air_density * s->air_cp;
    is_close(acbb_tnet_resistance(nw->net, e), 1.0 / G, 1e-12, 0,
             "ADV 43-0 = 1/(q_oil rho cp + q_air rho cp) (hand, mass weighted)");
    is_close(acbb_tnet_resistance(nw->net, e), 0.88, 0.05, 0, "ADV ~0.88 K/W (MODEL 8.1)");
    /* TC fit half: 1/(h pi D_o B/2) */
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 2, 5)),
             1.0 / (5e3 * M_PI * 0.068 * 0.0075), 1e-12, 0, "TC 2-5 = 1/(h_fit pi D_o B/2)");
    /* BI per ball / Z */
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 13, 15)),
             1.0 / (M_PI * 40.1 * 6.35e-3) / 21, 1e-12, 0, "BI 13-15 = 1/(pi k D)/Z");
    /* GF: ln(r_land/r_c)/(2 pi k_f W_c) */
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 10, 18)),
             log(29.05 / 28.85) / (2 * M_PI * 0.04 * 10.1e-3), 1e-12, 0, "GF 10-18 (hand)");
    /* RC shaft: ln(20/12.5)/(2 pi k L/2), L = 45 mm */
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 27, 28)),
             log(20.0 / 12.5) / (2 * M_PI * 42.4 * 0.0225), 1e-12, 0, "RC 27-28 (hand)");
    /* at build (no update yet) contacts are open: 1e6 K/W */
    ok(acbb_tnet_resistance(nw->net, nw->edge_sp_race_i) == 1e6, "SP open before update");
}

/* thermal.contact_model = moving (docs/contact_heat.md): each body at its
 * own surface speed, by hand: R0 = K(e)/(2 pi k a), R_inf = 0.309955
 * sqrt(kappa/(v b))/(k a), R = (R0^-2 + R_inf^-2)^-1/2 per contact, / Z;
 * c_mv on the race side only. The stationary model ignores the speeds. */
static void test_moving46(const acbb_scene *s, acbb_network *nw, const acbb_net_inputs *in0)
{
    acbb_net_inputs in = *in0;
    in.v_race_i = 21.0;
    in.v_ball_i = 19.0;
    double kappa = 40.1 / (7810.0 * 450.0), k = 40.1, a = 1.0e-3, b = 0.17e-3;
    double R0 = K_agm(sqrt(1.0 - pow(b / a, 2))) / (2 * M_PI * k * a);
    double hand[2];
    const double v[2] = {21.0, 19.0};
    for (int i = 0; i < 2; i++) {
        double Rf = 0.309955 * sqrt(kappa / (v[i] * b)) / (k * a);
        hand[i] = 1.0 / sqrt(1.0 / (R0 * R0) + 1.0 / (Rf * Rf)) / 21;
    }
    acbb_scene sm = *s;
    sm.contact_model = ACBB_CONTACT_MOVING;
    sm.contact_multiplier = 0.5;
    ok(acbb_network_update(nw, &sm, &in) == ACBB_OK, "moving: update OK");
    is_close(acbb_tnet_resistance(nw->net, nw->edge_sp_race_i), 0.5 * hand[0], 1e-5, 0,
             "moving: race 19-44 at 21 m/s, c_mv 0.5 (hand)");
    is_close(acbb_tnet_resistance(nw->net, nw->edge_sp_ball_i), hand[1], 1e-5, 0,
             "moving: ball 44-17 at 19 m/s (hand)");
    ok(acbb_network_update(nw, s, &in) == ACBB_OK &&
       fabs(acbb_tnet_resistance(nw->net, nw->edge_sp_race_i) - R0 / 21) <= 1e-10 * R0 / 21,
       "stationary: the speeds change nothing");
}

static void test_update46(const acbb_scene *s, acbb_network *nw)
{
    acbb_net_inputs in = inputs_15k(s);
    ok(acbb_network_update(nw, s, &in) == ACBB_OK, "update at 15000 rpm OK");
    double e = sqrt(1.0 - pow(0.17 / 1.0, 2));
    double R_race = K_agm(e) / (2 * M_PI * 40.1 * 1.0e-3) / 21;
    is_close(acbb_tnet_resistance(nw->net, nw->edge_sp_race_i), R_race, 1e-10, 0,
             "SP race 19-44 = K(e)/(2 pi k a)/Z (AGM hand value)");
    is_close(acbb_tnet_resistance(nw->net, nw->edge_sp_ball_o), R_race, 1e-10, 0,
             "SP ball 45-13 (same k for 52100 balls)");
    /* rotating IR land cylinder at 15000 rpm: Kreith Nu = 0.133 Re^2/3 Pr^1/3,
     * nu ~ air (oil volume fraction 1e-7) */
    double nu = s->air_eta / s->air_density, d = 49.9e-3;
    double Re = s->inner_speed * d * d / nu;
    double h = 0.133 * pow(Re, 2.0 / 3.0) * cbrt(0.71) * 0.04 / d;
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 22, 43)),
             1.0 / (h * M_PI * d * 15e-3), 1e-3, 0, "CV 22-43 rotating cylinder (hand)");
    /* Whitaker ball at v = omega_m d_m/2, split in two halves */
    double v = in.omega_m * 0.027, Reb = v * 6.35e-3 / nu;
    double hb = (2 + (0.4 * sqrt(Reb) + 0.06 * pow(Reb, 2.0 / 3.0)) * pow(0.71, 0.4))
                * 0.04 / 6.35e-3;
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 15, 16)),
             1.0 / (2 * hb * 21 * M_PI * 6.35e-3 * 6.35e-3), 1e-3, 0,
             "CV 15-16 Whitaker sphere half (hand)");
    /* circle limit: K(0) = pi/2 -> 1/(4 k a) per contact, times c_mv */
    acbb_scene s2 = *s;
    s2.contact_multiplier = 2.0;
    acbb_net_inputs c = in;
    c.a_i = c.b_i = 0.5e-3;
    acbb_network_update(nw, &s2, &c);
    is_close(acbb_tnet_resistance(nw->net, nw->edge_sp_race_i),
             2.0 / (4 * 40.1 * 0.5e-3) / 21, 1e-12, 0,
             "circular spot: race side c_mv/(4 k a Z)");
    is_close(acbb_tnet_resistance(nw->net, nw->edge_sp_ball_i), 1.0 / (4 * 40.1 * 0.5e-3) / 21,
             1e-12, 0, "circular spot: ball side not multiplied");
    test_moving46(s, nw, &in);
    acbb_network_update(nw, s, &in);
}

static void check_steady(const acbb_scene *s, acbb_network *nw, const char *tag,
                         const int *hot, int n_hot, double *Tss)
{
    double q[ACBB_MAX_NODES];
    acbb_network_heat(nw, s, &SRC, q);
    double qsum = 0.0;
    for (int i = 0; i < nw->n; i++) qsum += q[i];
    is_close(qsum, 43.0, 1e-14, 0, "heat map conserves the 43 W");
    ok(acbb_tnet_steady(nw->net, q, Tss) == ACBB_OK, "%s: steady solve OK", tag);
    is_close(acbb_tnet_heat_to_fixed(nw->net, Tss), qsum, 1e-9, 0,
             "steady: heat in == heat to fixed nodes (1e-9)");
    int maxp = 1, imax = 0;
    for (int i = 0; i < nw->n; i++) {
        maxp &= Tss[i] >= s->ambient_C - 1e-9;
        if (Tss[i] > Tss[imax]) imax = i;
    }
    ok(maxp, "%s: every node >= ambient (maximum principle)", tag);
    int hot_ok = 0;
    for (int i = 0; i < n_hot; i++) hot_ok |= imax == hot[i];
    ok(hot_ok, "%s: hottest node is a contact/ball node (%s, %.2f C)", tag,
       nw->names[imax], Tss[imax]);
    printf("# %s steady: outer ring node %d = %.3f C, hottest %s = %.3f C\n", tag,
           nw->node_outer_ring, Tss[nw->node_outer_ring], nw->names[imax], Tss[imax]);
}

/* March BE to steady; also checks the per-step BE energy identity
 * sum_i C_i (T_i^{k+1} - T_i^k)/dt = sum q - heat_to_fixed(T^{k+1}). */
static void check_transient(const acbb_scene *s, acbb_network *nw, const char *tag,
                            const double *Tss)
{
    double q[ACBB_MAX_NODES], T[ACBB_MAX_NODES], Told[ACBB_MAX_NODES];
    acbb_network_heat(nw, s, &SRC, q);
    for (int i = 0; i < nw->n; i++) T[i] = s->ambient_C;
    double worst_balance = 0.0, dt = 5.0;
    int ok_all = 1;
    long f0 = acbb_tnet_factorisations(nw->net);
    for (int k = 0; k < 40000; k++) {
        memcpy(Told, T, sizeof T);
        ok_all &= acbb_tnet_step(nw->net, q, dt, T) == ACBB_OK;
        if (k < 100) {
            double stored = 0.0;
            for (int i = 0; i < nw->n; i++)
                stored += acbb_tnet_capacity(nw->net, i) * (T[i] - Told[i]) / dt *
                          !acbb_tnet_is_fixed(nw->net, i);
            double bal = stored - (43.0 - acbb_tnet_heat_to_fixed(nw->net, T));
            worst_balance = fmax(worst_balance, fabs(bal));
        }
    }
    ok(ok_all, "%s: 40000 BE steps of 5 s OK", tag);
    ok(acbb_tnet_factorisations(nw->net) == f0 + 1, "%s: one factorisation for the run", tag);
    ok(worst_balance < 1e-8, "%s: BE energy identity per step (worst %.2g W)", tag,
       worst_balance);
    double dev = 0.0;
    for (int i = 0; i < nw->n; i++) dev = fmax(dev, fabs(T[i] - Tss[i]));
    ok(dev < 1e-3, "%s: transient (dt = 5 s, 2e5 s) reaches steady (max dev %.2g K)", tag,
       dev);
}

static void test_open_and_still(const acbb_scene *s, acbb_network *nw)
{
    acbb_net_inputs in = { .T_cavity_C = 26.0 };
    ok(acbb_network_update(nw, s, &in) == ACBB_OK, "update with a = 0, omega = 0 OK");
    int finite = 1;
    for (int e = 0; e < acbb_tnet_edge_count(nw->net); e++) {
        double R = acbb_tnet_resistance(nw->net, e);
        finite &= isfinite(R) && R > 0;
    }
    ok(finite, "all resistances finite and positive with no contact and no speed");
    ok(acbb_tnet_resistance(nw->net, nw->edge_sp_race_o) == 1e6, "a = 0 -> spot 1e6 K/W");
    /* standstill: films fall back to h_natural */
    is_close(acbb_tnet_resistance(nw->net, find_edge(nw, 22, 43)),
             1.0 / (10.0 * M_PI * 49.9e-3 * 15e-3), 1e-12, 0,
             "omega = 0: IR land film uses h_natural");
    double q[ACBB_MAX_NODES], T[ACBB_MAX_NODES];
    acbb_network_heat(nw, s, &SRC, q);
    ok(acbb_tnet_steady(nw->net, q, T) == ACBB_OK, "open contacts: steady still solvable");
    acbb_net_inputs bad = inputs_15k(s);
    bad.a_i = NAN;
    ok(acbb_network_update(nw, s, &bad) == ACBB_EINVAL, "NaN semi-axis: EINVAL");
    bad = inputs_15k(s);
    bad.b_o = -1e-4;
    ok(acbb_network_update(nw, s, &bad) == ACBB_EINVAL, "negative semi-axis: EINVAL");
}

static void test_no_refactor_on_same_update(const acbb_scene *s, acbb_network *nw)
{
    acbb_net_inputs in = inputs_15k(s);
    double q[ACBB_MAX_NODES], T[ACBB_MAX_NODES];
    acbb_network_heat(nw, s, &SRC, q);
    for (int i = 0; i < nw->n; i++) T[i] = 26.0;
    acbb_network_update(nw, s, &in);
    acbb_tnet_step(nw->net, q, 5.0, T);
    long f0 = acbb_tnet_factorisations(nw->net);
    acbb_network_update(nw, s, &in);
    acbb_tnet_step(nw->net, q, 5.0, T);
    ok(acbb_tnet_factorisations(nw->net) == f0, "identical update: no refactorisation");
    in.a_o *= 1.01;
    acbb_network_update(nw, s, &in);
    acbb_tnet_step(nw->net, q, 5.0, T);
    ok(acbb_tnet_factorisations(nw->net) == f0 + 1, "changed contact size: refactorised");
}

static void test_averages46(const acbb_network *nw)
{
    double T[46];
    for (int i = 0; i < 46; i++) T[i] = 3.0 + 1.5 * i;
    acbb_part_temps p;
    acbb_network_part_temps(nw, T, &p);
    is_close(p.ball, T[15], 0, 0, "ball = T15");
    is_close(p.inner_ring, (T[19] + T[20] + T[22] + T[23]) / 4, 1e-15, 0,
             "inner ring = mean 19, 20, 22, 23");
    is_close(p.shaft, (T[27] + T[29]) / 2, 1e-15, 0, "shaft = mean 27, 29");
    is_close(p.housing, (T[1] + T[2] + T[3] + T[4]) / 4, 1e-15, 0, "housing = mean 1..4");
    is_close(p.outer_ring, (T[5] + T[6] + T[8] + T[9]) / 4, 1e-15, 0,
             "outer ring = mean 5, 6, 8, 9");
    double ti, to;
    acbb_network_inlet_temps(nw, T, &ti, &to);
    is_close(ti, (T[19] + T[17]) / 2, 1e-15, 0, "inner inlet = (T19 + T17)/2");
    is_close(to, (T[7] + T[13]) / 2, 1e-15, 0, "outer inlet = (T7 + T13)/2");
}

static void test_net7(const acbb_scene *s0)
{
    acbb_scene s = *s0;
    s.network = ACBB_NET_7;
    acbb_network nw;
    acbb_error err = {{0}};
    ok(acbb_network_build(&s, &nw, &err) == ACBB_OK, "7-node build OK (%s)", err.msg);
    ok(nw.n == 7 && acbb_tnet_node_count(nw.net) == 7 && acbb_tnet_edge_count(nw.net) == 10,
       "7 nodes, 10 edges (MODEL 8.3)");
    int nfix = 0;
    for (int i = 0; i < 7; i++) nfix += acbb_tnet_is_fixed(nw.net, i);
    ok(nfix == 1 && acbb_tnet_is_fixed(nw.net, 0), "only node 0 is Dirichlet (shaft free)");
    /* heat mapping with phi_p = 0.3 */
    acbb_scene sp = s;
    sp.heat_partition = 0.3;
    double q[7];
    acbb_network_heat(&nw, &sp, &SRC, q);
    ok(q[2] == 0.3 * 15.0 && q[4] == 0.3 * 20.0 && q[6] == 3.0 && q[0] == 0 && q[1] == 0 &&
       q[5] == 0, "7-node: 2 <- phi outer, 4 <- phi inner, 6 <- drag");
    is_close(q[3], 0.7 * 35.0 + 5.0, 1e-15, 0, "7-node: 3 <- (1-phi)(inner+outer) + spin");
    acbb_net_inputs in = inputs_15k(&s);
    ok(acbb_network_update(&nw, &s, &in) == ACBB_OK, "7-node update OK");
    double e = sqrt(1.0 - pow(0.17, 2));
    double Rsp = K_agm(e) / (2 * M_PI * 40.1 * 1.0e-3) / 21;
    double Rbi = 1.0 / (M_PI * 40.1 * 6.35e-3) / 21;
    is_close(acbb_tnet_resistance(nw.net, find_edge(&nw, 2, 3)), 2 * Rsp + Rbi, 1e-10, 0,
             "7-node 2-3 = SP race + SP ball + BI (hand)");
    /* oil density at the cavity temperature of the update (40 C) */
    is_close(acbb_tnet_resistance(nw.net, find_edge(&nw, 6, 0)),
             1.0 / (s.q_oil * 876 * (1 - 6.5e-4 * 20.0) * 1950 + s.q_air * 1.128 * 1007),
             1e-12, 0, "7-node ADV 6-0 (hand, oil density at T_cavity)");
    double Cb = acbb_tnet_capacity(nw.net, 3), Ch = acbb_tnet_capacity(nw.net, 1);
    ok(Cb > 15 && Cb < 40, "7-node balls+cage capacity ~10+13 J/K (%.1f)", Cb);
    ok(Ch > 650 && Ch < 2600, "7-node housing ~1.3 kJ/K (%.0f)", Ch);
    double Tss[7];
    static const int hot7[] = {3};
    check_steady(&s, &nw, "7-node", hot7, 1, Tss);
    check_transient(&s, &nw, "7-node", Tss);
    double T[7] = {1, 2, 3, 4, 5, 6, 7};
    acbb_part_temps p;
    acbb_network_part_temps(&nw, T, &p);
    ok(p.ball == 4 && p.inner_ring == 5 && p.shaft == 6 && p.housing == 2 &&
       p.outer_ring == 3, "7-node part temps = T3, T4, T5, T1, T2");
    double ti, to;
    acbb_network_inlet_temps(&nw, T, &ti, &to);
    ok(ti == 4.5 && to == 3.5, "7-node inlets: (T4+T3)/2, (T2+T3)/2");
    acbb_network_free(&nw);
}

static void test_build_errors(const acbb_scene *s0)
{
    acbb_scene s = *s0;
    acbb_network nw;
    acbb_error err = {{0}};
    s.housing_od = 0.060;   /* the housing no longer sits at a fixed 120 mm */
    ok(acbb_network_build(&s, &nw, &err) == ACBB_EINVAL, "OD beyond the housing: EINVAL");
    has_substr(err.msg, "do not hold the bearing", "message names the surroundings");
    s = *s0;
    s.cage_diameter = 59e-3;
    ok(acbb_network_build(&s, &nw, &err) == ACBB_EINVAL, "cage OD above OR land: EINVAL");
    has_substr(err.msg, "radii must increase", "message explains the radius order");
    s = *s0;
    s.network = (acbb_network_kind)7;
    ok(acbb_network_build(&s, &nw, &err) == ACBB_EINVAL, "unknown kind: EINVAL");
    s = *s0;
    s.housing.k = 0;
    ok(acbb_network_build(&s, &nw, &err) == ACBB_EINVAL, "k = 0: EINVAL");
    ok(nw.net == NULL, "failed build leaves no network to free");
}

/* ---- surroundings (MODEL.md 8.1, 13 "Surroundings") ---- */

/* The derived surroundings of the default (7008C) scene are the seed rig of
 * MODEL.md 8.1 bit for bit; a set value is used as given; other bearings get
 * the rig scaled (diameters by OD/68, axial sizes by width/15). */
static void test_surroundings_derived(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_surroundings u;
    acbb_scene_surroundings(&s, &u);
    ok(u.housing_od == 0.120 && u.housing_length == 0.045 && u.cap_od == 0.120 &&
       u.cap_thickness == 0.010 && u.shoulder_thickness == 0.010 && u.shaft_length == 0.045 &&
       u.shaft_bore == 0.025, "7008C: housing 120 x 45, cap 120 x 10, shoulder 10, shaft "
       "45 long with a 25 mm bore, exactly the seed rig");
    ok(u.shoulder_inset == 0.004 && u.cap_inset == 0.006 && u.x_end_wall == 0.017 &&
       u.cage_clearance == 0.0015, "7008C: shoulder r 30, cap bore r 28, node 36 at 17 mm, "
       "cage bore r 25.5, exactly the seed rig");
    s.housing_od = 0.2;
    s.cap_thickness = 0.012;
    s.shaft_bore = 0.02;
    acbb_scene_surroundings(&s, &u);
    ok(u.housing_od == 0.2 && u.cap_od == 0.2 && u.cap_thickness == 0.012 &&
       u.shaft_bore == 0.02, "set sizes are used as given (the cap follows the housing)");
    acbb_scene_default(&s);
    s.outer_diameter = 0.136;
    s.width = 0.030;
    s.bore = 0.080;
    acbb_scene_surroundings(&s, &u);
    is_close(u.housing_od, 0.240, 1e-15, 0, "OD x 2: housing OD x 2 (240 mm)");
    is_close(u.housing_length, 0.090, 1e-15, 0, "width x 2: housing length x 2 (90 mm)");
    is_close(u.cap_thickness, 0.020, 1e-15, 0, "width x 2: cap thickness x 2 (20 mm)");
    is_close(u.shaft_bore, 0.050, 1e-15, 0, "bore x 2: shaft bore x 2 (50 mm)");
}

/* The hand-built 7008C scene scaled by bore / 40 mm (70xx proportions). */
static void scaled_scene(acbb_scene *s, double bore_mm)
{
    scene_7008c(s);
    double k = bore_mm / 40.0;
    double *dims[] = {&s->pitch_diameter, &s->ball_diameter, &s->inner_groove_radius,
                      &s->outer_groove_radius, &s->bore, &s->outer_diameter, &s->width,
                      &s->cage_width, &s->cage_diameter, &s->inner_land_diameter,
                      &s->outer_land_diameter, &s->shaft_bore};
    for (size_t i = 0; i < sizeof dims / sizeof dims[0]; i++) *dims[i] *= k;
}

/* Bores 10..200 mm: both networks build with the derived surroundings, and
 * their steady states conserve energy and obey the maximum principle. The
 * bearing of the issue (pitch 100 mm, bore 80 mm) was refused before. */
static void test_scaled_networks(void)
{
    static const double bores[] = {10, 40, 80, 100, 200};
    static const int hot46[] = {13, 15, 17, 44, 45}, hot7[] = {2, 3, 4};
    for (int i = 0; i < 5; i++)
        for (int kind = 0; kind < 2; kind++) {
            acbb_scene s;
            scaled_scene(&s, bores[i]);
            s.network = kind ? ACBB_NET_7 : ACBB_NET_46;
            acbb_network nw;
            acbb_error err = {{0}};
            char tag[64];
            snprintf(tag, sizeof tag, "bore %g mm, %s", bores[i], kind ? "7-node" : "46-node");
            if (!ok(acbb_network_build(&s, &nw, &err) == ACBB_OK, "%s: builds (%s)", tag, err.msg))
                continue;
            acbb_net_inputs in = inputs_15k(&s);
            ok(acbb_network_update(&nw, &s, &in) == ACBB_OK, "%s: update OK", tag);
            double Tss[ACBB_MAX_NODES];
            check_steady(&s, &nw, tag, kind ? hot7 : hot46, 3 + 2 * !kind, Tss);
            acbb_network_free(&nw);
        }
}

/* Steady node temperatures of scene s under SRC at 15000 rpm. */
static int steady_of(const acbb_scene *s, double *T, int *n)
{
    acbb_network nw;
    acbb_error err = {{0}};
    if (acbb_network_build(s, &nw, &err) != ACBB_OK) return 0;
    acbb_net_inputs in = inputs_15k(s);
    double q[ACBB_MAX_NODES];
    acbb_network_update(&nw, s, &in);
    acbb_network_heat(&nw, s, &SRC, q);
    int good = acbb_tnet_steady(nw.net, q, T) == ACBB_OK &&
               fabs(acbb_tnet_heat_to_fixed(nw.net, T) - 43.0) < 43.0 * 1e-9;
    *n = nw.n;
    acbb_network_free(&nw);
    return good;
}

/* Convective faces: the film 1/(h A) in series (hand areas of MODEL.md 8.1
 * geometry), h -> 1e9 W/m^2K gives the fixed face, a warm coolant warms the
 * shaft, a fixed housing exterior pins nodes 1, 3, 32, 33. */
static void test_face_bcs(const acbb_scene *s0)
{
    acbb_scene s = *s0;
    acbb_network a, b;
    acbb_error err = {{0}};
    acbb_network_build(&s, &a, &err);
    s.bore_bc = (acbb_face_bc){ACBB_BC_CONVECTIVE, 500, 0};
    s.cap_bc = (acbb_face_bc){ACBB_BC_CONVECTIVE, 20, 0};
    ok(acbb_network_build(&s, &b, &err) == ACBB_OK, "convective bore and cap build");
    double dR_bore = acbb_tnet_resistance(b.net, find_edge(&b, 27, 28)) -
                     acbb_tnet_resistance(a.net, find_edge(&a, 27, 28));
    is_close(dR_bore, 1.0 / (500 * 2 * M_PI * 0.0125 * 0.0225), 1e-9, 0,
             "bore film in series: 1/(h 2 pi r_sb L_s/2), r_sb 12.5, L_s 45 mm");
    double r1 = 0.028 + 0.032 / 3.0;   /* cap bore r 28, outer r 60, inner third */
    double dR_cap = acbb_tnet_resistance(b.net, find_edge(&b, 41, 38)) -
                    acbb_tnet_resistance(a.net, find_edge(&a, 41, 38));
    is_close(dR_cap, 1.0 / (20 * M_PI * (r1 * r1 - 0.028 * 0.028)), 1e-9, 0,
             "cap film in series: 1/(h A), inner third of the r 28..60 mm face");
    acbb_network_free(&a);
    acbb_network_free(&b);

    double Tf[ACBB_MAX_NODES], Tc[ACBB_MAX_NODES];
    int nf, nc;
    s = *s0;
    ok(steady_of(&s, Tf, &nf), "fixed faces: steady, balanced");
    s.bore_bc = (acbb_face_bc){ACBB_BC_CONVECTIVE, 1e9, 0};
    s.cap_bc = (acbb_face_bc){ACBB_BC_CONVECTIVE, 1e9, 0};
    ok(steady_of(&s, Tc, &nc), "h = 1e9 faces: steady, balanced");
    double worst = 0.0;
    for (int i = 0; i < nf; i++) worst = fmax(worst, fabs(Tc[i] - Tf[i]));
    ok(worst < 1e-3, "h = 1e9 W/m^2K equals the fixed faces (max |dT| %.2g K)", worst);
    s.bore_bc = (acbb_face_bc){ACBB_BC_FIXED, 0, 10};
    steady_of(&s, Tc, &nc);
    ok(Tc[28] == s.ambient_C + 10 && Tc[27] > Tf[27] + 5, "coolant +10 K: bore at %.1f C, "
       "shaft %.2f > %.2f C", Tc[28], Tc[27], Tf[27]);

    s = *s0;
    s.housing_bc = ACBB_BC_FIXED;
    acbb_network_build(&s, &a, &err);
    int pinned = 1;
    static const int ext[] = {1, 3, 32, 33};
    for (int i = 0; i < 4; i++) pinned &= acbb_tnet_is_fixed(a.net, ext[i]);
    ok(pinned && find_edge(&a, 0, 1) < 0, "fixed housing exterior: 1, 3, 32, 33 pinned, no film");
    acbb_network_free(&a);
    int good = steady_of(&s, Tc, &nc);
    ok(good && Tc[5] < Tf[5], "fixed housing: cooler outer ring (%.2f < %.2f C)", Tc[5], Tf[5]);

    s = *s0;
    s.network = ACBB_NET_7;
    steady_of(&s, Tf, &nf);
    s.bore_bc = (acbb_face_bc){ACBB_BC_CONVECTIVE, 500, 10};
    good = steady_of(&s, Tc, &nc);
    ok(good && nc == 8 && Tc[7] == s.ambient_C + 10,
       "7-node, coolant +10 K: an eighth node fixed at %.1f C, balanced", Tc[7]);
    ok(Tc[5] > Tf[5] + 5, "7-node: warm coolant behind a film: warmer shaft (%.2f > %.2f C)",
       Tc[5], Tf[5]);
}

/* surroundings.shaft_bore / cap = derived (the default): [S]'s fixed faces
 * on the seed rig only; any other bearing gets the convective faces,
 * exactly as if they were set convective (issue 18: no unlimited sink). */
static void test_derived_faces(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    ok(s.bore_bc.kind == ACBB_BC_DERIVED && s.cap_bc.kind == ACBB_BC_DERIVED, "default: derived");
    ok(acbb_face_bc_kind(&s, &s.bore_bc) == ACBB_BC_FIXED
       && acbb_face_bc_kind(&s, &s.cap_bc) == ACBB_BC_FIXED, "7008C on the seed rig: fixed faces");
    acbb_scene t = s;
    t.housing_od = 0.121;
    ok(acbb_face_bc_kind(&t, &t.bore_bc) == ACBB_BC_CONVECTIVE, "another housing: convective");
    t = s;
    t.bore = 70e-3; t.outer_diameter = 110e-3; t.width = 20e-3; t.pitch_diameter = 90e-3;
    t.ball_diameter = 12e-3; t.n_balls = 19; t.inner_groove_radius = t.outer_groove_radius = 6.5e-3;
    t.cage_diameter = 96e-3; t.inner_land_diameter = 80e-3; t.outer_land_diameter = 97e-3;
    acbb_scene c = t;
    c.bore_bc.kind = c.cap_bc.kind = ACBB_BC_CONVECTIVE;
    acbb_network a, b;
    acbb_error err = {{0}};
    ok(acbb_network_build(&t, &a, &err) == ACBB_OK && acbb_network_build(&c, &b, &err) == ACBB_OK,
       "70 x 110 x 20 bearing builds: %s", err.msg);
    ok(acbb_tnet_resistance(a.net, find_edge(&a, 27, 28))
           == acbb_tnet_resistance(b.net, find_edge(&b, 27, 28))
       && acbb_tnet_resistance(a.net, find_edge(&a, 41, 38))
              == acbb_tnet_resistance(b.net, find_edge(&b, 41, 38)),
       "derived faces of a 70 x 110 x 20 bearing = convective faces (bore and cap films)");
    acbb_network_free(&a);
    acbb_network_free(&b);
    t.bore_bc.kind = ACBB_BC_FIXED;
    ok(acbb_face_bc_kind(&t, &t.bore_bc) == ACBB_BC_FIXED, "set fixed stays fixed at any size");
}

/* Cross-field rule: the surroundings must hold the bearing. */
static void test_surroundings_rule(void)
{
    static const char *const cases[][3] = {
        {"surroundings.housing_outer_diameter_mm", "60", "the housing must be larger"},
        {"surroundings.housing_length_mm", "30", "length >= 35 mm"},
        {"surroundings.cap_outer_diameter_mm", "68", "the end cap must cover"},
        {"surroundings.shaft_length_mm", "10", "at least as long as the inner ring"},
        {"surroundings.shaft_bore_coolant_dT_K", "130", "must be below thermal.temp_limit_C"},
    };
    for (int i = 0; i < 5; i++) {
        acbb_scene s;
        acbb_scene_default(&s);
        acbb_error err = {{0}};
        ok(acbb_scene_set(&s, cases[i][0], cases[i][1], &err) == ACBB_EINVAL,
           "%s = %s refused", cases[i][0], cases[i][1]);
        has_substr(err.msg, cases[i][2], err.msg);
    }
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_error err = {{0}};
    ok(acbb_scene_set(&s, "bearing.outer_diameter_mm", "130", &err) == ACBB_OK,
       "a larger OD is fine with the derived housing (%s)", err.msg);
}

int main(void)
{
    gsl_set_error_handler_off();
    acbb_scene s;
    scene_7008c(&s);
    acbb_network nw;
    test_build46_structure(&s, &nw);
    test_capacities46(&s, &nw);
    test_adv_and_static_R(&s, &nw);
    test_update46(&s, &nw);
    double Tss[46];
    static const int hot46[] = {13, 15, 17, 44, 45};
    check_steady(&s, &nw, "46-node", hot46, 5, Tss);
    check_transient(&s, &nw, "46-node", Tss);
    test_no_refactor_on_same_update(&s, &nw);
    test_averages46(&nw);
    test_open_and_still(&s, &nw);
    acbb_network_free(&nw);
    test_net7(&s);
    test_build_errors(&s);
    test_surroundings_derived();
    test_scaled_networks();
    test_face_bcs(&s);
    test_surroundings_rule();
    test_derived_faces();
    return done_testing();
}
