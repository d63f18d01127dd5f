/* Physics profiles (issue 25, physics_profile.h): physics.profile sets the
 * DEFAULTS of the profile table's keys; a key given in the preset or by
 * acbb_scene_set keeps its value whatever the profile, wherever the
 * profile key stands in the file; a preset without the key is seed;
 * saving into a user's file does not spell out what the profile gives;
 * the reference profile's losses run and move the total the right way. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "tap.h"
#include "acbb/tools/physics_profile.h"
#include "acbb/sim.h"
#include "acbb/tools/scene_edit.h"
#include "acbb/tools/scene_inactive.h"
#include "scene_internal.h"

static acbb_scene load(const char *text)
{
    acbb_scene s;
    acbb_error e = { "" };
    if (acbb_scene_load_text(text, &s, &e) != ACBB_OK) {
        ok(0, "load: %s", e.msg);
        acbb_scene_default(&s);
    }
    return s;
}

static int is_reference(const acbb_scene *s)
{
    return s->roll_hyst == ACBB_ROLL_HYST_JOHNSON && s->loss_ehl_rolling && s->loss_churning
        && s->loss_cage;
}

static int is_seed(const acbb_scene *s)
{
    return s->roll_hyst == ACBB_ROLL_HYST_SEED && !s->loss_ehl_rolling && !s->loss_churning
        && !s->loss_cage;
}

static void test_table(void)
{
    acbb_scene d;
    acbb_scene_default(&d);
    ok(d.profile == ACBB_PROFILE_SEED && is_seed(&d), "the default scene is seed");
    ok(strcmp(acbb_profile_name(ACBB_PROFILE_SEED), "seed") == 0
       && strcmp(acbb_profile_name(ACBB_PROFILE_REFERENCE), "reference") == 0
       && strcmp(acbb_profile_name((acbb_physics_profile)7), "?") == 0, "profile names");
    size_t n = acbb_profile_row_count();
    ok(n >= 4, "the table has %zu rows", n);
    for (size_t k = 0; k < n; k++) {
        for (int p = 0; p < 2; p++) {
            acbb_scene s = d;
            acbb_error e = { "" };
            const char *v = acbb_profile_row_value(k, (acbb_physics_profile)p);
            ok(acbb_scene_set(&s, acbb_profile_row_key(k), v, &e) == ACBB_OK,
               "row %zu: %s = %s is a valid value (%s)", k, acbb_profile_row_key(k), v, e.msg);
        }
    }
    ok(acbb_profile_row_key(n) == NULL && acbb_profile_row_value(n, ACBB_PROFILE_SEED) == NULL,
       "past the table: NULL");
    /* The row of a field, found by name (issue 30), is the row naming it. */
    int rows_ok = 1;
    for (size_t k = 0; k < n; k++)
        rows_ok = rows_ok && acbb_sf_profile_field(k) != NULL
                  && acbb_sf_profile_row(acbb_sf_profile_field(k)) == (int)k;
    ok(rows_ok && acbb_sf_profile_row(acbb_sf_find("operating", "axial_load_N")) == -1
       && acbb_sf_profile_row(acbb_sf_find("effects", "thermal_expansion")) == -1
       && acbb_sf_profile_row(NULL) == -1,
       "each row's field has that row; other keys of the same sections none");
}

static void test_load(void)
{
    acbb_scene s = load("[operating]\ninner_speed_rpm = 1000\n");
    ok(s.profile == ACBB_PROFILE_SEED && is_seed(&s), "a preset without the key is seed");
    s = load("[physics]\nprofile = reference\n");
    ok(s.profile == ACBB_PROFILE_REFERENCE && is_reference(&s), "profile = reference sets its keys");
    ok(s.profile_given == 0, "  none of them given");
    /* An explicit key wins, before or after the profile key in the file. */
    s = load("[effects]\nloss_cage = off\n[physics]\nprofile = reference\n");
    ok(!s.loss_cage && s.loss_ehl_rolling && s.roll_hyst == ACBB_ROLL_HYST_JOHNSON,
       "a key given before the profile key keeps its value");
    s = load("[physics]\nprofile = reference\n[fidelity]\nrolling_hysteresis = seed\n");
    ok(s.roll_hyst == ACBB_ROLL_HYST_SEED && s.loss_cage && s.loss_churning,
       "a key given after it keeps its value");
    s = load("[physics]\nprofile = seed\n[effects]\nloss_ehl_rolling = on\n");
    ok(s.loss_ehl_rolling && !s.loss_cage, "seed with one extended loss given");
}

static void test_set(void)
{
    acbb_scene s = load("[effects]\nloss_cage = off\n[physics]\nprofile = reference\n");
    acbb_error e = { "" };
    ok(acbb_scene_set(&s, "physics.profile", "seed", &e) == ACBB_OK && is_seed(&s),
       "set physics.profile = seed: its keys go back (the given one had the seed value)");
    ok(acbb_scene_set(&s, "effects.loss_ehl_rolling", "on", &e) == ACBB_OK
       && acbb_scene_set(&s, "physics.profile", "reference", &e) == ACBB_OK
       && acbb_scene_set(&s, "physics.profile", "seed", &e) == ACBB_OK && s.loss_ehl_rolling
       && !s.loss_cage, "a key set by hand stays through profile changes (given: %x)",
       s.profile_given);
    acbb_scene d;
    acbb_scene_default(&d);
    const char *edits[] = { "effects.loss_churning=off", "physics.profile=reference" };
    ok(acbb_scene_apply_edits(&d, edits, 2, &e) == ACBB_OK && !d.loss_churning && d.loss_cage,
       "--set edits: the key wins whatever the order of the edits");
}

static int notes_churning(const acbb_scene *s)
{
    acbb_inactive_effect in[16];
    size_t n = acbb_scene_inactive_effects(s, in, 16);
    for (size_t i = 0; i < n; i++)
        if (strcmp(in[i].effect, "loss_churning") == 0) return 1;
    return 0;
}

/* Churning finds no bulk oil under oil-air: a user who switched it on is
 * told; a profile that has it on (also written out in full, as acbb new
 * does) is not the user's input. */
static void test_inactive(void)
{
    acbb_scene s = load("[physics]\nprofile = reference\n");
    ok(s.loss_churning && !notes_churning(&s), "reference, oil-air: churning on, no note");
    s = load("[physics]\nprofile = reference\n[effects]\nloss_churning = on\n");
    ok(!notes_churning(&s), "  the same value given explicitly: no note");
    s = load("[effects]\nloss_churning = on\n");
    ok(notes_churning(&s), "seed with churning switched on under oil-air: the note");
    acbb_inactive_effect in[16];
    s = load("[physics]\nprofile = reference\n[fidelity]\nhysteresis_axis = minor\n");
    size_t n = acbb_scene_inactive_effects(&s, in, 16);
    int axis = 0;
    for (size_t i = 0; i < n; i++) axis |= strcmp(in[i].effect, "hysteresis_axis") == 0;
    ok(axis, "hysteresis_axis set under rolling_hysteresis = johnson is named inactive");
}

static int file_has(const char *path, const char *needle)
{
    FILE *f = fopen(path, "r");
    char line[512];
    int found = 0;
    while (f && fgets(line, sizeof line, f)) found |= strstr(line, needle) != NULL;
    if (f) fclose(f);
    return found;
}

static void test_save_edits(void)
{
    char path[] = "/tmp/acbb-profile-XXXXXX";
    int fd = mkstemp(path);
    ok(fd >= 0, "temp file");
    if (fd < 0) return;
    const char text[] = "[operating]\ninner_speed_rpm = 1000\n";
    ok(write(fd, text, sizeof text - 1) == (ssize_t)(sizeof text - 1), "write preset");
    close(fd);
    acbb_scene s;
    acbb_error e = { "" };
    ok(acbb_scene_load(path, &s, &e) == ACBB_OK
       && acbb_scene_set(&s, "physics.profile", "reference", &e) == ACBB_OK
       && acbb_scene_save_edits(path, &s, &e) == ACBB_OK, "edit and save (%s)", e.msg);
    ok(file_has(path, "profile = reference") && !file_has(path, "loss_cage")
       && !file_has(path, "loss_ehl_rolling") && !file_has(path, "rolling_hysteresis"),
       "saved: the profile key, not the keys it sets");
    acbb_scene r;
    ok(acbb_scene_load(path, &r, &e) == ACBB_OK && is_reference(&r), "reloads as reference");
    ok(acbb_scene_set(&r, "effects.loss_cage", "off", &e) == ACBB_OK
       && acbb_scene_save_edits(path, &r, &e) == ACBB_OK && file_has(path, "loss_cage = off"),
       "a key differing from its profile's value is written");
    unlink(path);
}

static double total(acbb_scene s)
{
    acbb_sim *sim = NULL;
    acbb_error e = { "" };
    acbb_snapshot snap;
    s.heating = false;
    int good = acbb_sim_create(&s, NULL, &sim, &e) == ACBB_OK && acbb_sim_run(sim) == ACBB_OK;
    if (sim) acbb_sim_snapshot(sim, &snap);
    acbb_sim_free(sim);
    return good ? snap.losses.total : NAN;
}

/* The seed point (7008C, 15 000 rpm, 1000 N, isothermal at 26 C): the
 * reference profile's rolling hysteresis is Johnson's in the rolling
 * direction, (3/16) b / R_x against the seed's 4 a / (3 pi D): with a/b
 * about 6 on this bearing it is several times smaller, and the total with
 * it (plus the EHL rolling force and cage shear) is below the seed's. */
static void test_run(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_error e = { "" };
    double seed = total(s);
    ok(acbb_scene_set(&s, "physics.profile", "reference", &e) == ACBB_OK, "reference");
    acbb_sim *sim = NULL;
    acbb_snapshot snap;
    s.heating = false;
    ok(acbb_sim_create(&s, NULL, &sim, &e) == ACBB_OK && acbb_sim_run(sim) == ACBB_OK,
       "the reference profile runs at the seed point");
    if (sim) acbb_sim_snapshot(sim, &snap);
    acbb_sim_free(sim);
    ok(snap.losses.P[ACBB_LOSS_EHL_ROLLING] > 0 && snap.losses.P[ACBB_LOSS_CAGE] > 0,
       "EHL rolling %.3g W and cage %.3g W are on", snap.losses.P[ACBB_LOSS_EHL_ROLLING],
       snap.losses.P[ACBB_LOSS_CAGE]);
    ok(snap.losses.P[ACBB_LOSS_ROLLING] > 0 && snap.losses.total < seed,
       "reference total %.3f W below the seed's %.3f W (Johnson hysteresis %.3f W)",
       snap.losses.total, seed, snap.losses.P[ACBB_LOSS_ROLLING]);
}

int main(void)
{
    test_table();
    test_load();
    test_set();
    test_inactive();
    test_save_edits();
    test_run();
    return done_testing();
}
