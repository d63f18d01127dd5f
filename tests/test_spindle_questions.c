/* What the answers of docs/spindle.md "Questions a spindle answers" rely
 * on: trends that follow from the physics, on the two spindle presets run
 * to their steady state by the steady solve (fidelity.thermal_mode =
 * steady; a few runs, fast). Each case edits the preset the way
 * `acbb sweep --grid KEY=...` would (acbb_scene_apply_edits with the same
 * text) and compares two points of the sweep. The runaway speed's bracket
 * is checked through the sweep (tests/test_spindle_questions.sh). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "acbb/sim.h"

#define MOTOR "presets/spindle-motor-DBT.ini"
#define BELT "presets/spindle-belt-DB.ini"

/* One point: the preset, the steady solve, the edit `key=value`; the
 * snapshot at its end. Returns 1 when the run converged. */
static int point(const char *preset, const char *key, double value, acbb_snapshot *o)
{
    acbb_scene s;
    acbb_error err = { "" };
    char edit[128];
    snprintf(edit, sizeof edit, "%s=%.17g", key, value);
    const char *edits[] = { "fidelity.thermal_mode=steady", edit };
    acbb_sim *sim = NULL;
    memset(o, 0, sizeof *o);
    if (acbb_scene_load(preset, &s, &err) != ACBB_OK
        || acbb_scene_apply_edits(&s, edits, 2, &err) != ACBB_OK
        || acbb_sim_create(&s, &(acbb_sim_opts){ 0 }, &sim, &err) != ACBB_OK) {
        ok(0, "%s with %s: %s", preset, edit, err.msg);
        return 0;
    }
    acbb_sim_run(sim);
    acbb_sim_snapshot(sim, o);
    acbb_sim_free(sim);
    printf("# %s %s: %s (%s)\n", preset, edit,
           o->state == ACBB_RUN_CONVERGED ? "converged" : "failed", o->message);
    return o->state == ACBB_RUN_CONVERGED && o->spindle.n_sets == 2;
}

static void show(const char *what, const acbb_snapshot *o)
{
    const acbb_spindle_view *v = &o->spindle;
    printf("# " "%s: drift %.4f um, k_r %.3f N/um, T_out %.4f C, front preload %.3f N axial %.3f N "
         "loss %.3f W, rear axial %.3f N lost %d\n",
         what, v->nose_drift_axial * 1e6, v->nose_k_radial * 1e-6, v->T_coolant_out_C,
         v->sets[0].preload_N, v->sets[0].axial_N, v->sets[0].loss_W, v->sets[1].axial_N,
         v->sets[1].contact_lost);
}

static double front_axial(const acbb_snapshot *o)
{
    return fabs(o->spindle.sets[0].axial_N);
}

int main(void)
{
    acbb_snapshot a, b;

    /* More coolant flow: the same heat leaves with a smaller rise of the
     * coolant (m_dot c_p (T_out - T_in)), the housing and the shaft run
     * colder, so the nose grows less. */
    if (ok(point(MOTOR, "spindle.coolant_flow_l_min", 1.0, &a)
               && point(MOTOR, "spindle.coolant_flow_l_min", 8.0, &b),
           "motor spindle at 1 and 8 L/min converged")) {
        show("1 L/min", &a);
        show("8 L/min", &b);
        ok(b.spindle.T_coolant_out_C < a.spindle.T_coolant_out_C,
           "more coolant flow: lower coolant outlet (%.4f C at 8 L/min, %.4f C at 1)",
           b.spindle.T_coolant_out_C, a.spindle.T_coolant_out_C);
        ok(a.spindle.T_coolant_out_C > a.spindle.T_coolant_in_C,
           "the coolant leaves warmer than it came (%.4f > %.4f C)",
           a.spindle.T_coolant_out_C, a.spindle.T_coolant_in_C);
        ok(b.spindle.nose_drift_axial > 0.0
               && b.spindle.nose_drift_axial < a.spindle.nose_drift_axial,
           "more coolant flow: smaller nose drift (%.4f um at 8 L/min, %.4f um at 1)",
           b.spindle.nose_drift_axial * 1e6, a.spindle.nose_drift_axial * 1e6);
    }

    /* More front preload: stiffer contacts, a stiffer nose; the rigid
     * triple runs at a higher preload. */
    if (ok(point(MOTOR, "mounting.preload_N", 150.0, &a)
               && point(MOTOR, "mounting.preload_N", 600.0, &b),
           "motor spindle at 150 and 600 N front preload converged")) {
        show("150 N", &a);
        show("600 N", &b);
        ok(b.spindle.nose_k_radial > a.spindle.nose_k_radial,
           "more front preload: higher radial nose stiffness (%.3f N/um at 600 N, %.3f at 150)",
           b.spindle.nose_k_radial * 1e-6, a.spindle.nose_k_radial * 1e-6);
        ok(b.spindle.sets[0].preload_N > a.spindle.sets[0].preload_N,
           "more front preload: the front set runs at more (%.1f N, %.1f N)",
           b.spindle.sets[0].preload_N, a.spindle.sets[0].preload_N);
    }

    /* Higher speed: more loss in the bearings; the rigid front triple's
     * inner rings grow (heat, centrifugal) more than its outer rings, so
     * it runs at a higher preload; the warmer shaft grows the nose more. */
    if (ok(point(MOTOR, "operating.inner_speed_rpm", 8000.0, &a)
               && point(MOTOR, "operating.inner_speed_rpm", 14000.0, &b),
           "motor spindle at 8000 and 14000 rpm converged")) {
        show("8000 rpm", &a);
        show("14000 rpm", &b);
        ok(b.spindle.sets[0].loss_W > a.spindle.sets[0].loss_W,
           "higher speed: more front set loss (%.2f W, %.2f W)", b.spindle.sets[0].loss_W,
           a.spindle.sets[0].loss_W);
        ok(b.spindle.sets[0].preload_N > a.spindle.sets[0].preload_N
               && a.spindle.sets[0].preload_N > 300.0,
           "higher speed: the rigid front set runs at more preload, above its 300 N assembly "
           "(%.1f N, %.1f N)",
           b.spindle.sets[0].preload_N, a.spindle.sets[0].preload_N);
        ok(b.spindle.nose_drift_axial > a.spindle.nose_drift_axial,
           "higher speed: more nose drift (%.3f um, %.3f um)", b.spindle.nose_drift_axial * 1e6,
           a.spindle.nose_drift_axial * 1e6);
    }

    /* The floating rear set's sleeve: it carries at most its friction, and
     * more friction holds more of the shaft's growth as thrust on the
     * front pair. */
    if (ok(point(BELT, "spindle.rear_friction_N", 40.0, &a)
               && point(BELT, "spindle.rear_friction_N", 400.0, &b),
           "belt spindle at 40 and 400 N sleeve friction converged")) {
        show("40 N", &a);
        show("400 N", &b);
        ok(fabs(a.spindle.sets[1].axial_N) <= 40.0 * (1.0 + 1e-9)
               && fabs(b.spindle.sets[1].axial_N) <= 400.0 * (1.0 + 1e-9),
           "the rear set carries at most the friction (%.3f N of 40, %.3f N of 400)",
           a.spindle.sets[1].axial_N, b.spindle.sets[1].axial_N);
        ok(front_axial(&b) > front_axial(&a),
           "more friction: more thrust on the front pair (%.3f N, %.3f N)", front_axial(&b),
           front_axial(&a));
    }

    return done_testing();
}
