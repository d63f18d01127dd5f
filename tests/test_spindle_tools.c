/* The study tools that split a scene into its bearing (the report's three
 * mountings, cli/mountings.c; its contact heat case,
 * src/batch/contact_study.c) on a spindle scene: they take the front
 * bearing on a rigid shaft. Before, they kept the spindle with a single
 * front bearing, which a floating rear refuses (every run of those report
 * sections ended bad_input on presets/spindle-belt-DB.ini). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "acbb/sim.h"
#include "acbb/tools/contact_study.h"
#include "acbb/tools/sensitivity.h"
#include "../cli/mountings.h"

#define BELT "presets/spindle-belt-DB.ini"
#define MOTOR "presets/spindle-motor-DBT.ini"

/* 1 when the scene compiles into a Sim (the scene's rules hold). */
static int builds(const acbb_scene *s, const char *what)
{
    acbb_sim *sim = NULL;
    acbb_error err = { "" };
    acbb_status st = acbb_sim_create(s, &(acbb_sim_opts){ 0 }, &sim, &err);
    acbb_sim_free(sim);
    return ok(st == ACBB_OK, "%s builds (%s)", what, st == ACBB_OK ? "ok" : err.msg);
}

/* Whether `key` is among the scene's uncertain inputs; *at its index. */
static int has_input(const acbb_sens_input *in, size_t n, const char *key, size_t *at)
{
    for (size_t i = 0; i < n; i++)
        if (strcmp(in[i].key, key) == 0) {
            if (at) *at = i;
            return 1;
        }
    return 0;
}

/* The keys each scene must offer as uncertain inputs (1) or not (0). */
typedef struct { const char *key; int want; } expect;

static void check_inputs(const char *preset, const expect *e, size_t n_e)
{
    static acbb_scene s, t;
    acbb_error err = { "" };
    if (!ok(acbb_scene_load(preset, &s, &err) == ACBB_OK, "%s loads (%s)", preset, err.msg))
        return;
    acbb_sens_input in[ACBB_SENS_MAX];
    size_t n = acbb_sens_inputs(&s, in, ACBB_SENS_MAX), bad = 0, invalid = 0;
    for (size_t i = 0; i < n_e; i++)
        if (has_input(in, n, e[i].key, NULL) != e[i].want) {
            printf("#   %s: %s %s\n", preset, e[i].key, e[i].want ? "missing" : "varied");
            bad++;
        }
    ok(bad == 0, "%s: the spindle keys it has are uncertain inputs, the others not (%zu "
       "inputs)", preset, n);
    /* every end is a scene the rules accept (a run that fails means something) */
    for (size_t i = 0; i < n; i++)
        for (int hi = 0; hi < 2; hi++) {
            t = s;
            if (acbb_sens_apply(&t, &in[i], hi, &err) != ACBB_OK
                || acbb_scene_validate(&t, &err) != ACBB_OK) {
                printf("#   %s = %s: %s\n", in[i].key, hi ? in[i].hi : in[i].lo, err.msg);
                invalid++;
            }
        }
    ok(invalid == 0, "%s: both ends of every input are valid scenes", preset);
}

/* The spindle keys with a plausible range (src/scene/scene_schema_spindle.h)
 * are varied by `acbb sensitivity` and `report --sensitivity` on a spindle
 * that has the part they describe (was: none of them, they had no range);
 * not on a scene without a spindle (the 7008C's inputs stay as they were),
 * nor the motor's on a belt spindle or the coolant's without a flow (the
 * rules would refuse those runs), nor on a spindle the bearing's housing
 * film and shaft bore coolant, which the spindle's own replace. Then the motor spindle's nose drift
 * through the sensitivity's own evaluation (acbb_sens_eval, the steady
 * solve) at both ends of two of them, a narrowed list that keeps the test
 * fast: each moves it. */
static void test_sensitivity(void)
{
    static const expect motor[] = {
        { "spindle.jacket_hA_W_K", 1 }, { "spindle.coolant_flow_l_min", 1 },
        { "spindle.coolant_inlet_dT_K", 1 }, { "motor.rotor_loss_W", 1 },
        { "motor.stator_loss_W", 1 }, { "motor.gap_conductance_W_K", 1 },
        { "spindle.rear_spring_N", 1 }, { "housing.outer_film_W_m2K", 1 },
        { "shaft.end_film_W_m2K", 1 }, { "spindle.rear_friction_N", 0 },
        { "mounting.h_fit_inner_W_m2K", 1 }, { "mounting.h_natural_W_m2K", 0 },
        { "surroundings.shaft_bore", 0 }, { "surroundings.shaft_bore_h_W_m2K", 0 } };
    static const expect belt[] = {
        { "spindle.rear_friction_N", 1 }, { "housing.outer_film_W_m2K", 1 },
        { "shaft.end_film_W_m2K", 1 }, { "spindle.jacket_hA_W_K", 0 },
        { "spindle.coolant_flow_l_min", 0 }, { "motor.rotor_loss_W", 0 },
        { "motor.gap_conductance_W_K", 0 }, { "spindle.rear_spring_N", 0 } };
    static const expect bearing[] = {
        { "spindle.jacket_hA_W_K", 0 }, { "spindle.rear_friction_N", 0 },
        { "spindle.rear_spring_N", 0 }, { "housing.outer_film_W_m2K", 0 },
        { "shaft.end_film_W_m2K", 0 }, { "motor.rotor_loss_W", 0 },
        { "mounting.h_fit_inner_W_m2K", 1 }, { "mounting.h_natural_W_m2K", 1 },
        { "surroundings.shaft_bore", 1 } };
    check_inputs(MOTOR, motor, sizeof motor / sizeof motor[0]);
    check_inputs(BELT, belt, sizeof belt / sizeof belt[0]);
    check_inputs("presets/7008C.ini", bearing, sizeof bearing / sizeof bearing[0]);

    static acbb_scene base, sc[4];
    acbb_error err = { "" };
    if (acbb_scene_load(MOTOR, &base, &err) != ACBB_OK) return;
    acbb_sens_input in[ACBB_SENS_MAX];
    size_t n = acbb_sens_inputs(&base, in, ACBB_SENS_MAX), at[2];
    if (!ok(has_input(in, n, "spindle.jacket_hA_W_K", &at[0])
            && has_input(in, n, "motor.rotor_loss_W", &at[1]), "motor spindle: both inputs"))
        return;
    for (int k = 0; k < 4; k++) {
        sc[k] = base;
        acbb_sens_apply(&sc[k], &in[at[k / 2]], k % 2, &err);
    }
    acbb_sens_opts o = { .metric = "spindle.nose_drift_um", .oat = 1, .jobs = 1 };
    double y[4];
    size_t runs = 0;
    char fail[256] = "";
    acbb_status st = acbb_sens_eval(sc, 4, &o, y, fail, sizeof fail, &runs);
    ok(st == ACBB_OK && runs == 4, "motor spindle: the four runs (%zu) %s", runs, fail);
    for (int k = 0; k < 2; k++)
        ok(isfinite(y[2 * k]) && isfinite(y[2 * k + 1]) && fabs(y[2 * k + 1] - y[2 * k]) > 0.01,
           "%s %s..%s: the nose drift moves, %.4f to %.4f um", in[at[k]].key, in[at[k]].lo,
           in[at[k]].hi, y[2 * k], y[2 * k + 1]);
}

int main(void)
{
    test_sensitivity();
    acbb_scene base, s;
    acbb_error err = { "" };
    if (!ok(acbb_scene_load(BELT, &base, &err) == ACBB_OK, "%s loads (%s)", BELT, err.msg))
        return done_testing();
    ok(base.shaft_segments > 0, "the preset is a spindle");

    acbb_contact_case_scene(&base, &s);
    ok(s.shaft_segments == 0 && s.set_arrangement == ACBB_SET_SINGLE,
       "the contact heat case is the front bearing alone, no shaft");
    builds(&s, "the contact heat case of the belt spindle");

    ok(acbb_cli_own_mounting(&base) == -1,
       "a spindle is none of the three mountings (its own study is not reused as the DB pair)");
    for (int m = 0; m < N_MOUNTINGS; m++) {
        char what[96];
        acbb_cli_mounting_scene(&base, m, &s);
        snprintf(what, sizeof what, "the %s mounting of the belt spindle",
                 acbb_cli_mountings[m].name);
        ok(s.shaft_segments == 0, "%s has no shaft", what);
        builds(&s, what);
    }

    /* Another scene keeps its own mounting: the DB pair of the belt
     * spindle's front, without the shaft, is the DB mounting. */
    s = base;
    s.shaft_segments = 0;
    ok(acbb_cli_own_mounting(&s) == M_DB, "the front DB pair alone is the DB mounting");
    return done_testing();
}
