/* Tests of acbb_scene_resolve (fidelity.h), the one place a scene is
 * resolved before a run (issue 27 item 3), and of acbb_sim_scene: the
 * Sim's constructor and restart keep exactly that resolution.
 *
 * Scenes are compared key by key through the schema's formatter (the run
 * JSON's scene echo), so a difference in any key fails. */
#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "acbb/tools/fidelity.h"
#include "acbb/sim.h"
#include "acbb/tools/scene_schema.h"

/* The first key whose formatted value differs, or NULL. */
static const char *first_diff(const acbb_scene *a, const acbb_scene *b)
{
    static char key[96];
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        char va[128], vb[128];
        acbb_scene_field_format(a, i, va, sizeof va);
        acbb_scene_field_format(b, i, vb, sizeof vb);
        if (strcmp(va, vb) != 0) {
            const acbb_field_info *fi = acbb_scene_field(i);
            snprintf(key, sizeof key, "%s.%s", fi->section, fi->key);
            return key;
        }
    }
    return NULL;
}

static int load(const char *preset, const char *const *edits, size_t n, acbb_scene *s)
{
    acbb_error err = { { 0 } };
    char path[128];
    snprintf(path, sizeof path, "presets/%s.ini", preset);
    acbb_status st = acbb_scene_load(path, s, &err);
    if (st == ACBB_OK) st = acbb_scene_apply_edits(s, edits, n, &err);
    return ok(st == ACBB_OK, "%s loads with its edits (%s)", preset, err.msg);
}

static void same(const acbb_scene *a, const acbb_scene *b, const char *what)
{
    const char *k = first_diff(a, b);
    ok(k == NULL, "%s (first differing key: %s)", what, k ? k : "none");
}

/* Resolving twice changes nothing; the Sim keeps the one resolution. */
static void check_case(const char *preset, const char *const *edits, size_t n, int chosen)
{
    acbb_scene in, r1, r2;
    if (!load(preset, edits, n, &in)) return;
    ok(acbb_scene_resolve(&in, &r1, NULL) == chosen, "%s: fidelity entry chosen = %d",
       preset, chosen);
    ok(r1.fidelity_preset == ACBB_FIDELITY_CUSTOM && r1.target_error == 0.0,
       "%s: the resolved scene names no preset or target", preset);
    ok(acbb_scene_resolve(&r1, &r2, NULL) == 0, "%s: a resolved scene chooses nothing", preset);
    same(&r1, &r2, "resolving a resolved scene changes nothing");
    acbb_scene r3 = in;
    acbb_scene_resolve(&r3, &r3, NULL);
    same(&r1, &r3, "resolving in place equals resolving into a copy");
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (!ok(acbb_sim_create(&in, &(acbb_sim_opts){ 0 }, &sim, &err) == ACBB_OK,
            "%s: the Sim builds (%s)", preset, err.msg))
        return;
    same(acbb_sim_scene(sim), &r1, "acbb_sim_scene equals acbb_scene_resolve of the input");
    acbb_sim_free(sim);
}

/* A restart with another scene resolves that scene, once. */
static void check_restart(void)
{
    acbb_scene a, b, rb;
    const char *eb[] = { "fidelity.preset=fast", "lubricant.grade=VG46" };
    if (!load("7008C", NULL, 0, &a) || !load("7008C", eb, 2, &b)) return;
    acbb_scene_resolve(&b, &rb, NULL);
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (!ok(acbb_sim_create(&a, &(acbb_sim_opts){ 0 }, &sim, &err) == ACBB_OK, "7008C builds"))
        return;
    ok(acbb_sim_restart(sim, &b, 1, &err) == ACBB_OK, "restart with a preset (%s)", err.msg);
    same(acbb_sim_scene(sim), &rb, "after a restart acbb_sim_scene is the new scene resolved");
    acbb_sim_free(sim);
}

/* Hand values: VG32's nu40 is its ISO 3448 midpoint, 32 mm^2/s; the fast
 * entry's knobs are the table's (acbb_fidelity_set). */
static void check_values(void)
{
    acbb_scene in, r, want;
    const char *e[] = { "fidelity.preset=fast", "lubricant.grade=VG32" };
    if (!load("7008C", e, 2, &in)) return;
    acbb_scene_resolve(&in, &r, NULL);
    is_close(r.oil_nu40, 32e-6, 1e-12, 0, "VG32 resolves nu40 = 32 mm^2/s");
    acbb_fidelity_choice fc;
    ok(acbb_fidelity_resolve(&in, &fc) == 1 && fc.point, "the preset names an entry");
    want = r;
    acbb_fidelity_set(&want, fc.point);
    same(&r, &want, "the resolved knobs are the fast entry's");
}

int main(void)
{
    const char *fast[] = { "fidelity.preset=fast", "lubricant.grade=VG32" };
    const char *target[] = { "fidelity.target_error_pct=5" };
    check_case("7008C", NULL, 0, 0);
    check_case("7008C", fast, 2, 1);
    check_case("7008C", target, 1, 1);
    check_case("pair-DB-heated", fast, 2, 1);
    check_case("run-in-ramp", fast, 1, 1);
    check_restart();
    check_values();
    return done_testing();
}
