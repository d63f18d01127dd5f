/* The study tools that split a scene into its bearing (the report's three
 * mountings, cli/mountings.c; its contact heat case,
 * src/batch/contact_study.c) on a spindle scene: they take the front
 * bearing on a rigid shaft. Before, they kept the spindle with a single
 * front bearing, which a floating rear refuses (every run of those report
 * sections ended bad_input on presets/spindle-belt-DB.ini). */
#include <stdio.h>
#include "tap.h"
#include "acbb/sim.h"
#include "acbb/tools/contact_study.h"
#include "../cli/mountings.h"

#define BELT "presets/spindle-belt-DB.ini"

/* 1 when the scene compiles into a Sim (the scene's rules hold). */
static int builds(const acbb_scene *s, const char *what)
{
    acbb_sim *sim = NULL;
    acbb_error err = { "" };
    acbb_status st = acbb_sim_create(s, &(acbb_sim_opts){ 0 }, &sim, &err);
    acbb_sim_free(sim);
    return ok(st == ACBB_OK, "%s builds (%s)", what, st == ACBB_OK ? "ok" : err.msg);
}

int main(void)
{
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
