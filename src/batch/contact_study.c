/* acbb — the runaway case under each contact heat model (contact_study.h). */
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/contact_study.h"
#include "acbb/tools/measure.h"
#include "acbb/units.h"

const double acbb_contact_multipliers[ACBB_CONTACT_N_MULT] = { 0.25, 0.5, 1.0, 2.0 };

const char *acbb_contact_model_name(acbb_contact_model m)
{
    return m == ACBB_CONTACT_MOVING ? "moving" : "stationary";
}

void acbb_contact_case_scene(const acbb_scene *s, acbb_scene *out)
{
    *out = *s;
    out->inner_speed = acbb_rpm_to_rads(ACBB_CONTACT_RPM);
    out->axial_load = ACBB_CONTACT_PRELOAD_N;
    out->preload = ACBB_PRELOAD_DISPLACEMENT;
    out->preload_force = ACBB_CONTACT_PRELOAD_N;
    out->set_arrangement = ACBB_SET_SINGLE;
    out->set_n_bearings = 0;
    /* The case is the bearing's own: a spindle scene's front bearing on a
     * rigid shaft (a single front bearing on a spindle with a floating
     * rear is refused, and the shaft would not be the case's anyway). */
    out->shaft_segments = 0;
    out->schedule_n = 0;
    out->thermal_mode = ACBB_THERMAL_TRANSIENT;
}

acbb_status acbb_contact_study_run(const acbb_scene *s, const atomic_int *cancel,
                                   acbb_contact_study *out, acbb_error *err)
{
    double t0 = acbb_now_ms();
    acbb_snapshot *snap = malloc(sizeof *snap);
    if (!snap) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    memset(out, 0, sizeof *out);
    acbb_scene base;
    acbb_contact_case_scene(s, &base);
    acbb_status rc = ACBB_OK;
    for (int i = 0; i < ACBB_CONTACT_N_CASES && rc == ACBB_OK; i++) {
        acbb_contact_case *c = &out->cases[i];
        c->model = i < ACBB_CONTACT_N_MULT ? ACBB_CONTACT_STATIONARY : ACBB_CONTACT_MOVING;
        c->multiplier = acbb_contact_multipliers[i % ACBB_CONTACT_N_MULT];
        acbb_scene sc = base;
        sc.contact_model = c->model;
        sc.contact_multiplier = c->multiplier;
        rc = acbb_branch_run(&sc, cancel, snap);
        if (rc == ACBB_OK) acbb_branch_summarize(snap, &c->end);
    }
    free(snap);
    out->wall_ms = acbb_now_ms() - t0;
    if (rc == ACBB_CANCELLED) return acbb_error_set(err, rc, "cancelled");
    return rc == ACBB_OK ? ACBB_OK : acbb_error_set(err, rc, "out of memory");
}
