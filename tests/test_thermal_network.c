/* Tests for the general thermal network (MODEL.md section 8.2): backward
 * Euler against hand recursions and the analytic RC response, steady state
 * against series-resistance hand solutions, energy balance, factorisation
 * caching, singular networks and input validation. */
#include <math.h>
#include <gsl/gsl_errno.h>
#include "thermal_network.h"
#include "tap.h"

/* Node 0 fixed at T0, node 1 with capacity C, edge R, heat q into node 1. */
static acbb_tnet *two_node(double C, double R, double T0)
{
    acbb_tnet *n = acbb_tnet_new(2);
    acbb_tnet_set_fixed(n, 0, T0);
    acbb_tnet_set_capacity(n, 1, C);
    acbb_tnet_add_edge(n, 0, 1, R);
    return n;
}

static void test_be_recursion(void)
{
    const double C = 40.0, R = 0.5, T0 = 26.0, q = 30.0, dt = 2.0;
    acbb_tnet *n = two_node(C, R, T0);
    double T[2] = {T0, T0}, Q[2] = {0.0, q};
    double Th = T0, maxerr = 0.0;
    int ok_all = 1;
    for (int k = 0; k < 50; k++) {
        ok_all &= acbb_tnet_step(n, Q, dt, T) == ACBB_OK;
        Th = (C / dt * Th + q + T0 / R) / (C / dt + 1.0 / R);
        maxerr = fmax(maxerr, fabs(T[1] - Th));
    }
    ok(ok_all, "50 BE steps return ACBB_OK");
    ok(maxerr < 1e-12, "BE matches hand recursion step by step (max err %.3g)", maxerr);
    ok(T[0] == T0, "fixed node keeps its value after a step");
    ok(acbb_tnet_factorisations(n) == 1, "50 steps with constant R, dt: one factorisation");
    acbb_tnet_free(n);
}

/* Error at t_end = 20 s of BE vs T0 + qR(1 - exp(-t/RC)). */
static double be_error(double dt)
{
    const double C = 40.0, R = 0.5, T0 = 26.0, q = 30.0, t_end = 20.0;
    acbb_tnet *n = two_node(C, R, T0);
    double T[2] = {T0, T0}, Q[2] = {0.0, q};
    int steps = (int)lround(t_end / dt);
    for (int k = 0; k < steps; k++) acbb_tnet_step(n, Q, dt, T);
    acbb_tnet_free(n);
    double exact = T0 + q * R * (1.0 - exp(-t_end / (R * C)));
    return fabs(T[1] - exact);
}

static void test_be_convergence(void)
{
    double e1 = be_error(1.0), e2 = be_error(0.5), e3 = be_error(0.25);
    ok(e3 < e2 && e2 < e1, "BE error shrinks with dt (%.4g %.4g %.4g)", e1, e2, e3);
    /* first order: halving dt roughly halves the error */
    ok(fabs(e1 / e2 - 2.0) < 0.2 && fabs(e2 / e3 - 2.0) < 0.1,
       "BE error ratios ~2 per halving (%.3f, %.3f)", e1 / e2, e2 / e3);
    ok(be_error(0.001) < 2e-3, "BE with dt=1 ms within 2 mK of the exponential");
}

static void test_two_node_steady_and_large_dt(void)
{
    const double C = 40.0, R = 0.5, T0 = 26.0, q = 30.0;
    acbb_tnet *n = two_node(C, R, T0);
    double T[2] = {0, 0}, Q[2] = {0.0, q};
    ok(acbb_tnet_steady(n, Q, T) == ACBB_OK, "2-node steady OK");
    is_close(T[1], T0 + q * R, 1e-14, 0, "steady = T0 + qR");
    is_close(acbb_tnet_heat_to_fixed(n, T), q, 1e-13, 0, "2-node heat to fixed = q");
    double Tb[2] = {T0, T0};
    ok(acbb_tnet_step(n, Q, 1e12, Tb) == ACBB_OK, "BE step with dt = 1e12 s OK");
    is_close(Tb[1], T[1], 1e-10, 0, "BE with huge dt equals the steady solution");
    acbb_tnet_free(n);
}

/* 0 (fixed T0) -R1- 1 (C1) -R2- 2 (C2) -R3- 3 (fixed T3), q1 at 1, q2 at 2. */
static void test_three_node_chain(void)
{
    const double T0 = 20.0, T3 = 50.0, R1 = 2.0, R2 = 3.0, R3 = 5.0;
    const double q1 = 4.0, q2 = 7.0;
    acbb_tnet *n = acbb_tnet_new(4);
    acbb_tnet_set_fixed(n, 0, T0);
    acbb_tnet_set_fixed(n, 3, T3);
    acbb_tnet_set_capacity(n, 1, 10.0);
    acbb_tnet_set_capacity(n, 2, 20.0);
    acbb_tnet_add_edge(n, 0, 1, R1);
    acbb_tnet_add_edge(n, 1, 2, R2);
    acbb_tnet_add_edge(n, 2, 3, R3);
    double T[4], Q[4] = {0, q1, q2, 0};
    ok(acbb_tnet_steady(n, Q, T) == ACBB_OK, "3-node chain steady OK");
    /* Hand solution by superposition over series resistances Rt = R1+R2+R3:
     * the boundary-driven part is a linear divider T0 + (T3-T0) r/Rt; a
     * source q at a node with resistances Ra, Rb to the two fixed ends raises
     * that node by q Ra Rb / (Ra + Rb), and its neighbours by the divider. */
    double Rt = R1 + R2 + R3;
    /* source q1 at node 1: ends see Ra = R1, Rb = R2 + R3 */
    double dT1_q1 = q1 * R1 * (R2 + R3) / Rt;            /* rise at node 1 */
    double dT2_q1 = dT1_q1 * R3 / (R2 + R3);              /* divider to node 2 */
    /* source q2 at node 2: Ra = R1 + R2, Rb = R3 */
    double dT2_q2 = q2 * (R1 + R2) * R3 / Rt;
    double dT1_q2 = dT2_q2 * R1 / (R1 + R2);
    double T1 = T0 + (T3 - T0) * R1 / Rt + dT1_q1 + dT1_q2;
    double T2 = T0 + (T3 - T0) * (R1 + R2) / Rt + dT2_q1 + dT2_q2;
    is_close(T[1], T1, 1e-13, 0, "chain node 1 = hand series solution");
    is_close(T[2], T2, 1e-13, 0, "chain node 2 = hand series solution");
    /* energy: heat into fixed nodes = sum q (heat from T3 at 50 C counts
     * negative where it enters the network) */
    is_close(acbb_tnet_heat_to_fixed(n, T), q1 + q2, 1e-12, 0,
             "chain: heat to fixed nodes = sum q at steady state");
    is_close(acbb_tnet_heat_to_fixed(n, T), (T[1] - T0) / R1 + (T[2] - T3) / R3, 1e-13, 0,
             "heat_to_fixed = sum (T_free - T_fixed)/R over boundary edges");
    acbb_tnet_free(n);
}

/* Node 1 has C = 0 (algebraic), between fixed 0 and capacity node 2. */
static void test_zero_capacity_node(void)
{
    const double T0 = 0.0, R1 = 1.0, R2 = 2.0, C2 = 10.0, q1 = 3.0, q2 = 1.0, dt = 0.7;
    acbb_tnet *n = acbb_tnet_new(3);
    acbb_tnet_set_fixed(n, 0, T0);
    acbb_tnet_set_capacity(n, 2, C2);
    acbb_tnet_add_edge(n, 0, 1, R1);
    acbb_tnet_add_edge(n, 1, 2, R2);
    double T[3] = {T0, 5.0, 5.0}, Q[3] = {0, q1, q2};
    ok(acbb_tnet_step(n, Q, dt, T) == ACBB_OK, "step with a C=0 node OK");
    /* hand: eliminate node 1: T1 = (q1 + T0/R1 + T2/R2)/(1/R1+1/R2);
     * node 2: C2/dt (T2 - 5) = q2 + (T1 - T2)/R2 -> linear in T2. */
    double g1 = 1.0 / R1, g2 = 1.0 / R2;
    double a = g2 / (g1 + g2);               /* dT1/dT2 */
    double b = (q1 + T0 * g1) / (g1 + g2);   /* T1 at T2 = 0 */
    double T2 = (C2 / dt * 5.0 + q2 + g2 * b) / (C2 / dt + g2 - g2 * a);
    double T1 = b + a * T2;
    is_close(T[2], T2, 1e-13, 1e-13, "C=0 network: capacity node matches hand elimination");
    is_close(T[1], T1, 1e-13, 1e-13, "C=0 node is algebraic (instant balance)");
    acbb_tnet_free(n);
}

static void test_factorisation_counter(void)
{
    acbb_tnet *n = two_node(40.0, 0.5, 26.0);
    double T[2] = {26, 26}, Q[2] = {0, 10};
    acbb_tnet_step(n, Q, 1.0, T);
    long f0 = acbb_tnet_factorisations(n);
    for (int k = 0; k < 10; k++) acbb_tnet_step(n, Q, 1.0, T);
    ok(acbb_tnet_factorisations(n) == f0, "unchanged R and dt: no refactorisation");
    ok(acbb_tnet_set_resistance(n, 0, 0.5) == ACBB_OK, "set the same R returns OK");
    acbb_tnet_step(n, Q, 1.0, T);
    ok(acbb_tnet_factorisations(n) == f0, "setting the same R does not refactorise");
    acbb_tnet_set_resistance(n, 0, 0.6);
    acbb_tnet_step(n, Q, 1.0, T);
    ok(acbb_tnet_factorisations(n) == f0 + 1, "a changed R refactorises once");
    is_close(acbb_tnet_resistance(n, 0), 0.6, 0, 0, "resistance getter returns the new R");
    acbb_tnet_step(n, Q, 2.0, T);
    ok(acbb_tnet_factorisations(n) == f0 + 2, "a changed dt refactorises");
    acbb_tnet_set_capacity(n, 1, 40.0 * 2);
    acbb_tnet_step(n, Q, 2.0, T);
    ok(acbb_tnet_factorisations(n) == f0 + 3, "a changed capacity refactorises");
    /* steady keeps its own factors: alternating calls cost nothing extra */
    acbb_tnet_steady(n, Q, T);
    long f1 = acbb_tnet_factorisations(n);
    ok(f1 == f0 + 4, "first steady solve factorises G once");
    for (int k = 0; k < 5; k++) {
        acbb_tnet_step(n, Q, 2.0, T);
        acbb_tnet_steady(n, Q, T);
    }
    ok(acbb_tnet_factorisations(n) == f1, "alternating step/steady does not refactorise");
    acbb_tnet_set_capacity(n, 1, 1.0);
    acbb_tnet_steady(n, Q, T);
    ok(acbb_tnet_factorisations(n) == f1, "capacity change does not touch the steady factors");
    acbb_tnet_set_fixed(n, 0, 30.0);
    acbb_tnet_steady(n, Q, T);
    ok(acbb_tnet_factorisations(n) == f1, "new fixed value (same node) only changes the RHS");
    is_close(T[1], 30.0 + 10 * 0.6, 1e-14, 0, "new fixed value used in steady solve");
    acbb_tnet_free(n);
}

static void test_singular(void)
{
    /* nodes 1-2 joined to each other only; node 0 fixed with node 3 */
    acbb_tnet *n = acbb_tnet_new(4);
    acbb_tnet_set_fixed(n, 0, 20.0);
    acbb_tnet_add_edge(n, 0, 3, 1.0);
    acbb_tnet_add_edge(n, 1, 2, 1.0);
    double T[4] = {20, 20, 20, 20}, Q[4] = {0, 1, 0, 0};
    ok(acbb_tnet_steady(n, Q, T) == ACBB_SINGULAR, "floating component: steady SINGULAR");
    ok(acbb_tnet_step(n, Q, 1.0, T) == ACBB_SINGULAR,
       "floating component without capacity: step SINGULAR");
    /* with capacity the transient problem is well posed: the floating pair
     * simply accumulates q dt / C_total */
    acbb_tnet_set_capacity(n, 1, 2.0);
    acbb_tnet_set_capacity(n, 2, 2.0);
    T[1] = T[2] = 20.0;
    ok(acbb_tnet_step(n, Q, 1.0, T) == ACBB_OK, "floating component with capacity: step OK");
    is_close(0.5 * (T[1] + T[2]), 20.0 + 1.0 * 1.0 / 4.0, 1e-13, 0,
             "floating pair mean rises by q dt / C_total");
    ok(acbb_tnet_steady(n, Q, T) == ACBB_SINGULAR, "still SINGULAR for steady");
    /* The connectivity check is kept between factorisations (issue 30)
     * until a capacity, a fixed node or an edge changes. */
    acbb_tnet_set_capacity(n, 1, 0.0);
    acbb_tnet_set_capacity(n, 2, 0.0);
    ok(acbb_tnet_step(n, Q, 2.0, T) == ACBB_SINGULAR,
       "capacities back to zero: step SINGULAR again");
    acbb_tnet_add_edge(n, 2, 3, 1.0);
    ok(acbb_tnet_steady(n, Q, T) == ACBB_OK && acbb_tnet_step(n, Q, 2.0, T) == ACBB_OK,
       "an edge to the fixed node's side: steady and step OK");
    acbb_tnet_free(n);

    acbb_tnet *m = acbb_tnet_new(2);   /* no fixed node at all */
    acbb_tnet_add_edge(m, 0, 1, 1.0);
    double T2[2] = {0, 0}, Q2[2] = {1, 0};
    ok(acbb_tnet_steady(m, Q2, T2) == ACBB_SINGULAR, "no fixed node: SINGULAR");
    acbb_tnet_free(m);
}

static void test_validation(void)
{
    ok(acbb_tnet_new(0) == NULL, "new(0) returns NULL");
    acbb_tnet *n = two_node(1.0, 1.0, 0.0);
    ok(acbb_tnet_node_count(n) == 2 && acbb_tnet_edge_count(n) == 1, "node/edge counts");
    ok(acbb_tnet_add_edge(n, 0, 2, 1.0) == ACBB_EINVAL, "edge to bad node index: EINVAL");
    ok(acbb_tnet_add_edge(n, -1, 1, 1.0) == ACBB_EINVAL, "negative node index: EINVAL");
    ok(acbb_tnet_add_edge(n, 1, 1, 1.0) == ACBB_EINVAL, "self loop: EINVAL");
    ok(acbb_tnet_add_edge(n, 0, 1, 0.0) == ACBB_EINVAL, "R = 0: EINVAL");
    ok(acbb_tnet_add_edge(n, 0, 1, -2.0) == ACBB_EINVAL, "R < 0: EINVAL");
    ok(acbb_tnet_add_edge(n, 0, 1, NAN) == ACBB_EINVAL, "R = NaN: EINVAL");
    ok(acbb_tnet_set_resistance(n, 0, -1.0) == ACBB_EINVAL, "set R < 0: EINVAL");
    ok(acbb_tnet_set_resistance(n, 5, 1.0) == ACBB_EINVAL, "set R bad edge: EINVAL");
    ok(acbb_tnet_set_capacity(n, 1, -1.0) == ACBB_EINVAL, "C < 0: EINVAL");
    ok(acbb_tnet_set_capacity(n, 2, 1.0) == ACBB_EINVAL, "capacity bad node: EINVAL");
    ok(acbb_tnet_set_fixed(n, 1, INFINITY) == ACBB_EINVAL, "fixed T = inf: EINVAL");
    ok(acbb_tnet_edge_count(n) == 1, "rejected edges were not added");
    double T[2] = {0, 0}, Q[2] = {0, 1};
    ok(acbb_tnet_step(n, Q, 0.0, T) == ACBB_EINVAL, "dt = 0: EINVAL");
    ok(acbb_tnet_step(n, Q, NAN, T) == ACBB_EINVAL, "dt = NaN: EINVAL");
    Q[1] = NAN;
    ok(acbb_tnet_step(n, Q, 1.0, T) == ACBB_EINVAL, "q NaN at free node: EINVAL");
    ok(acbb_tnet_steady(n, Q, T) == ACBB_EINVAL, "steady q NaN: EINVAL");
    Q[1] = 1.0;
    Q[0] = NAN;   /* entries at fixed nodes are ignored */
    ok(acbb_tnet_steady(n, Q, T) == ACBB_OK, "q NaN at a fixed node is ignored");
    Q[0] = 0.0;
    T[1] = INFINITY;
    ok(acbb_tnet_step(n, Q, 1.0, T) == ACBB_EINVAL, "T^k infinite at free node: EINVAL");
    acbb_tnet_free(n);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_be_recursion();
    test_be_convergence();
    test_two_node_steady_and_large_dt();
    test_three_node_chain();
    test_zero_capacity_node();
    test_factorisation_counter();
    test_singular();
    test_validation();
    return done_testing();
}
