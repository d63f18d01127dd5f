/* fidelity.max_wall_s inside a step (issue 26 item 7), state-based: a
 * deadline already past when a step starts must end that step at once,
 * ACBB_WALL_LIMIT, no step counted, the last good state kept; no clock is
 * read by the test. Before, a bearing set's step checked the bound only
 * in its steady polish (a transient step at the quasi-static level ran
 * whole, iteration 1), its members never saw it (a dynamic member's ball
 * integrations ran whole), and a single bearing's step checked it only
 * in the ball-speed passes (none at the quasi-static level).
 * The deadline is set through the internal API (sim_struct.h, sim_set.h),
 * as the run loop arms it (sim.c arm_bound). */
#include <string.h>
#include "tap.h"
#include "acbb/tools/measure.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "sim_struct.h"
#include "sim_set_priv.h"

static int load(const char *path, const char *model, acbb_scene *s)
{
    acbb_error err = { { 0 } };
    int good = acbb_scene_load(path, s, &err) == ACBB_OK
               && acbb_scene_set(s, "fidelity.model", model, &err) == ACBB_OK
               && acbb_scene_set(s, "fidelity.max_wall_s", "1000", &err) == ACBB_OK;
    if (!good) printf("# %s: %s\n", path, err.msg);
    return good;
}

/* One bearing at the quasi-static level: its bound spent (max_wall_s
 * below what the set-up took), the next step stops before any work. */
static void test_single(void)
{
    acbb_scene s;
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (!load("presets/7008C.ini", "quasi-static", &s) || acbb_sim_create(&s, NULL, &sim, &err)) {
        ok(0, "7008C quasi-static set up (%s)", err.msg);
        return;
    }
    double T0 = sim->T[0];
    sim->s.max_wall_s = 1e-12; /* the set-up alone took longer */
    acbb_status rc = acbb_sim_step(sim);
    ok(rc == ACBB_WALL_LIMIT && sim->run.iter == 0 && sim->run.state == ACBB_RUN_FAILED
       && sim->T[0] == T0 && strstr(sim->run.msg, "fidelity.max_wall_s") != NULL,
       "single bearing, bound spent: the step ends %s at once (iterations %ld, T kept): %s",
       acbb_status_name(rc), sim->run.iter, sim->run.msg);
    acbb_sim_free(sim);
}

static acbb_set_sim *new_set(const char *model)
{
    acbb_scene s;
    acbb_set_sim *ss = NULL;
    acbb_error err = { { 0 } };
    if (!load("presets/pair-DB-heated.ini", model, &s)) return NULL;
    if (!strcmp(model, "dynamic")) acbb_scene_set(&s, "fidelity.contact_grid", "3", &err);
    if (acbb_set_sim_new(&s, &(acbb_sim_opts){ .cancel = NULL, .threads = 1 }, &ss, &err) != ACBB_OK)
        printf("# pair-DB-heated, %s: %s\n", model, err.msg);
    return ss;
}

/* A set's transient step at the quasi-static level. */
static void test_set_step(void)
{
    acbb_set_sim *ss = new_set("quasi-static");
    if (!ok(ss != NULL, "pair-DB-heated, quasi-static: set up")) return;
    double T0 = ss->T[0];
    acbb_set_sim_deadline(ss, acbb_now_ms() - 1.0);
    acbb_status rc = acbb_set_sim_step(ss);
    ok(rc == ACBB_WALL_LIMIT && ss->run.iter == 0 && ss->run.state == ACBB_RUN_FAILED
       && ss->T[0] == T0
       && strstr(ss->run.msg, "fidelity.max_wall_s = 1000 s reached; last good state kept"),
       "set, deadline past: its step ends %s at once (iterations %ld, T kept): %s",
       acbb_status_name(rc), ss->run.iter, ss->run.msg);
    acbb_set_sim_free(ss);
}

/* The set hands its deadline to its members: a dynamic member's ball
 * pass (acbb_simx_traction, what the set's mechanics calls) stops in its
 * first right-hand side. */
static void test_member(void)
{
    acbb_set_sim *ss = new_set("dynamic");
    if (!ok(ss != NULL, "pair-DB-heated, dynamic (3x3 grid): set up")) return;
    acbb_error err = { { 0 } };
    double change;
    acbb_set_sim_deadline(ss, acbb_now_ms() - 1.0);
    acbb_status rc = acbb_simx_traction(ss->b[0], &change, &err);
    ok(rc == ACBB_WALL_LIMIT, "set member, the set's deadline past: its ball pass ends %s (%s)",
       acbb_status_name(rc), err.msg);
    acbb_set_sim_deadline(ss, 0.0);
    rc = acbb_simx_traction(ss->b[0], &change, &err);
    ok(rc == ACBB_OK, "... and without a deadline it runs (%s)", acbb_status_name(rc));
    acbb_set_sim_free(ss);
}

int main(void)
{
    test_single();
    test_set_step();
    test_member();
    return done_testing();
}
