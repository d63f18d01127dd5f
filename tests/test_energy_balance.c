/* Energy balance of converged runs (MODEL.md 12 item 18): heat in equals
 * heat into the fixed nodes within ACBB_BALANCE_TOL on the 7- and 46-node
 * networks over a random sample of valid scenes; a state that does not
 * balance is not `converged` (issue 18's reproduction); heating off
 * reports no heat flow. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "acbb/sim.h"
#include "acbb/tools/lubricant.h"

static acbb_status run(const acbb_scene *s, acbb_snapshot *snap, acbb_error *err)
{
    acbb_sim *sim = NULL;
    acbb_status rc = acbb_sim_create(s, NULL, &sim, err);
    if (rc != ACBB_OK) return rc;
    rc = acbb_sim_run(sim);
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    return rc;
}

/* Issue 18's case: the undamped steady polish overshot (loop gain about
 * -1.5) into a cycle between 43.15 W and 0.99 W and ended `unbalanced`;
 * damped, it reaches the steady state the transient settled at. Both
 * thermal modes must converge, balance, and agree (branches.c's bounds). */
static void test_issue_case(void)
{
    acbb_snapshot snap[2];
    for (int steady = 0; steady < 2; steady++) {
        acbb_scene s;
        acbb_error err = { "" };
        ok(acbb_scene_load("presets/runaway-rigid-preload.ini", &s, &err) == ACBB_OK,
           "preset: %s", err.msg);
        const char *e[] = { "bearing.inner_groove_radius_mm=52.9824", "fidelity.network=7",
                            "lubricant.air_density_kg_m3=0.00479549", "effects.loss_spin=off",
                            "fidelity.model=quasi-static", "fidelity.thermal_mode=steady" };
        ok(acbb_scene_apply_edits(&s, e, 5 + steady, &err) == ACBB_OK, "issue 18 edits: %s",
           err.msg);
        acbb_snapshot *p = &snap[steady];
        acbb_status rc = run(&s, p, &err);
        const char *mode = steady ? "steady solve" : "transient";
        ok(rc == ACBB_OK && p->state == ACBB_RUN_CONVERGED, "issue 18 case, %s: %s (%s)", mode,
           acbb_status_name(rc), p->message);
        ok(fabs(p->heat_in - p->heat_out) <= ACBB_BALANCE_TOL * p->heat_in,
           "issue 18 case, %s: %.9g W in = %.9g W out", mode, p->heat_in, p->heat_out);
    }
    double dT = 0.0;
    for (int i = 0; i < snap[0].n_nodes; i++) dT = fmax(dT, fabs(snap[0].T[i] - snap[1].T[i]));
    double dP = fabs(snap[0].losses.total - snap[1].losses.total) / snap[1].losses.total;
    ok(snap[0].n_nodes == 7 && snap[1].n_nodes == 7 && dT <= 0.01 && dP <= 1e-4,
       "issue 18 case: transient and steady solve agree (%.2g K, loss %.2g relative)", dT, dP);
}

static void test_heating_off(void)
{
    for (int net = 0; net < 2; net++) {
        acbb_scene s;
        acbb_scene_default(&s);
        s.heating = false;
        s.network = net ? ACBB_NET_7 : ACBB_NET_46;
        s.bore_bc.kind = ACBB_BC_CONVECTIVE;
        s.bore_bc.dT = 10.0;
        if (net) { /* the end cap exists on the 7-node network only */
            s.cap_bc.kind = ACBB_BC_CONVECTIVE;
            s.cap_bc.dT = -8.0;
        }
        s.radial_load = 150.0;
        acbb_snapshot snap;
        acbb_error err = { "" };
        ok(run(&s, &snap, &err) == ACBB_OK, "%s-node, heating off with coolant offsets: %s",
           net ? "7" : "46", err.msg[0] ? err.msg : "converges");
        ok(snap.heat_in == 0.0 && snap.heat_out == 0.0,
           "%s-node, heating off: no heat flow (%g in, %g out)", net ? "7" : "46", snap.heat_in,
           snap.heat_out);
    }
}

/* The same for a bearing set, whose joined network has its own
 * boundaries (the set published their flow: -31.6 W for this pair). */
static void test_heating_off_set(void)
{
    acbb_scene s;
    acbb_error err = { "" };
    ok(acbb_scene_load("presets/pair-DB-heated.ini", &s, &err) == ACBB_OK, "pair preset: %s",
       err.msg);
    const char *e[] = { "effects.heating=off", "surroundings.shaft_bore=convective",
                        "surroundings.shaft_bore_coolant_dT_K=10", "surroundings.cap=convective",
                        "surroundings.cap_coolant_dT_K=-8" };
    ok(acbb_scene_apply_edits(&s, e, 5, &err) == ACBB_OK, "edits: %s", err.msg);
    acbb_snapshot snap;
    ok(run(&s, &snap, &err) == ACBB_OK, "DB pair, heating off with coolant offsets: converges");
    ok(snap.heat_in == 0.0 && snap.heat_out == 0.0, "DB pair, heating off: no heat flow (%g in, "
       "%g out)", snap.heat_in, snap.heat_out);
}

/* Random valid scenes: speed, axial load, a radial load (the tilt free,
 * issue 18) within the ill-posedness guard (Fa >= 1.25 Fr tan 15 deg),
 * network, bore boundary, lubrication method with churning, an ISO grade,
 * the EHL rolling loss; stationary and moving contact heat; steady and
 * transient. rand_r: reproducible. */
static void test_random_sample(void)
{
    unsigned seed = 18;
    int n_conv[2] = { 0, 0 }, n_bal[2] = { 0, 0 }, n[2] = { 0, 0 }, n_rad = 0, n_jet = 0;
    double worst[2] = { 0, 0 };
    for (int k = 0; k < 16; k++) {
        acbb_scene s;
        acbb_scene_default(&s);
        int net = k % 2;
        s.network = net ? ACBB_NET_7 : ACBB_NET_46;
        /* every fourth point transient (the issue's case is), the rest the
         * direct steady solve */
        s.thermal_mode = k % 4 == 3 ? ACBB_THERMAL_TRANSIENT : ACBB_THERMAL_STEADY;
        s.model = ACBB_MODEL_QUASI_STATIC;
        /* both contact heat models on both networks (docs/contact_heat.md);
         * drawn without rand_r so the other draws stay as they were */
        s.contact_model = (k / 2) % 2 ? ACBB_CONTACT_MOVING : ACBB_CONTACT_STATIONARY;
        s.inner_speed = (2000 + rand_r(&seed) % 14000) * 2 * M_PI / 60;
        s.axial_load = 100 + rand_r(&seed) % 900;
        if (rand_r(&seed) % 2) {
            s.bore_bc.kind = ACBB_BC_CONVECTIVE;
            s.bore_bc.dT = (double)(rand_r(&seed) % 20) - 5.0;
        }
        s.loss_ehl_rolling = rand_r(&seed) % 2;
        if (rand_r(&seed) % 2) s.radial_load = (double)(rand_r(&seed) % (int)(s.axial_load));
        if (rand_r(&seed) % 2) {
            s.lub_method = ACBB_LUB_OIL_JET;
            s.loss_churning = true;
        }
        if (rand_r(&seed) % 2) {
            s.oil_grade = ACBB_GRADE_VG22 + (acbb_oil_grade)(rand_r(&seed) % 3);
            acbb_lubricant_apply(&s);
        }
        n_rad += s.radial_load > 0.0;
        n_jet += s.lub_method == ACBB_LUB_OIL_JET;
        acbb_snapshot snap;
        acbb_error err = { "" };
        acbb_status rc = run(&s, &snap, &err);
        n[net]++;
        if (snap.state != ACBB_RUN_CONVERGED) {
            printf("# %s %d rpm %.0f N, %.0f N radial: %s\n", net ? "7" : "46",
                   (int)(s.inner_speed * 60 / (2 * M_PI)), s.axial_load, s.radial_load,
                   acbb_status_name(rc));
            continue;
        }
        n_conv[net]++;
        double rel = fabs(snap.heat_in - snap.heat_out) / snap.heat_in;
        worst[net] = fmax(worst[net], rel);
        n_bal[net] += rel <= ACBB_BALANCE_TOL;
    }
    printf("# %d of 16 with a radial load, %d oil-jet with churning\n", n_rad, n_jet);
    for (int net = 0; net < 2; net++) {
        ok(n_conv[net] == n[net], "%s-node: %d of %d random scenes converge", net ? "7" : "46",
           n_conv[net], n[net]);
        ok(n_bal[net] == n_conv[net], "%s-node: all balance, worst |in - out|/in = %.2e",
           net ? "7" : "46", worst[net]);
    }
}

int main(void)
{
    test_issue_case();
    test_heating_off();
    test_heating_off_set();
    test_random_sample();
    return done_testing();
}
