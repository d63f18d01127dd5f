/* The spindle's scene (issue 31; docs/spindle.md "Scene"): every
 * cross-field rule of [shaft] [housing] [motor] [spindle] with its exact
 * message, the 0.01 mm seat tolerance on both sides of its edge, the keys
 * that do nothing (acbb_scene_inactive_effects, acbb_scene_key_inactive),
 * that a scene without a spindle needs none of it, and that the spindle
 * presets save and read back. Messages are the
 * user interface of the preset files: checked whole. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acbb/scene.h"
#include "acbb/tools/scene_edit.h"
#include "acbb/tools/scene_inactive.h"
#include "acbb/tools/scene_schema.h"
#include "tap.h"

/* A DB pair of 7008C (bore 40, OD 68, width 15 mm) at 30 mm, a single rear
 * bearing at 230 mm; shaft 60 + 150 + 40 mm (od 40 under the bearings),
 * housing from 10 to 245 mm with a 68 mm bore. */
static const char k_base[] =
    "[set]\narrangement = DB\n"
    "[mounting]\npreload = displacement\npreload_N = 300\n"
    "[shaft]\nsegments = 3\n"
    "seg1_length_mm = 60\nseg1_od_mm = 40\nseg1_bore_mm = 20\n"
    "seg2_length_mm = 150\nseg2_od_mm = 50\nseg2_bore_mm = 20\n"
    "seg3_length_mm = 40\nseg3_od_mm = 40\nseg3_bore_mm = 20\n"
    "[housing]\nsegments = 1\nx0_mm = 10\n"
    "seg1_length_mm = 235\nseg1_od_mm = 120\nseg1_bore_mm = 68\n"
    "[spindle]\nfront_x_mm = 30\nrear_x_mm = 230\n";

/* The base with `edits` ("key=value;key=value") applied, then the rules:
 * the message, "" when the scene passes. */
static const char *check(const char *edits, char *msg, size_t n)
{
    acbb_scene s;
    acbb_error err = { 0 };
    snprintf(msg, n, "base: ");
    if (acbb_scene_load_text(k_base, &s, &err) != ACBB_OK) {
        snprintf(msg, n, "base: %s", err.msg);
        return msg;
    }
    char buf[512];
    snprintf(buf, sizeof buf, "%s", edits);
    for (char *save = NULL, *e = strtok_r(buf, ";", &save); e; e = strtok_r(NULL, ";", &save)) {
        char *eq = strchr(e, '=');
        if (!eq) continue;
        *eq = '\0';
        if (acbb_scene_set_value(&s, e, eq + 1, &err) != ACBB_OK) {
            snprintf(msg, n, "edit %s: %s", e, err.msg);
            return msg;
        }
    }
    msg[0] = '\0';
    if (acbb_scene_validate(&s, &err) != ACBB_OK) snprintf(msg, n, "%s", err.msg);
    return msg;
}

static void expect(const char *edits, const char *want)
{
    char msg[1024];
    check(edits, msg, sizeof msg);
    if (!ok(strcmp(msg, want) == 0, "%s: %s", edits[0] ? edits : "(base)",
            want[0] ? "refused with its message" : "passes"))
        printf("#   got  \"%s\"\n#   want \"%s\"\n", msg, want);
}

static void test_base_and_file(void)
{
    expect("", "");
    /* Through a file-like source the message names it, as every rule's. */
    char text[2048];
    snprintf(text, sizeof text, "%s%s", k_base, "rear_support = floating\n[operating]\n");
    acbb_scene s;
    acbb_error err = { 0 };
    ok(acbb_scene_load_text(text, &s, &err) == ACBB_OK, "floating rear with a DB front: loads");
    snprintf(text, sizeof text, "%s%s", k_base, "coolant_flow_l_min = 4\n");
    ok(acbb_scene_load_text(text, &s, &err) == ACBB_EINVAL
           && strcmp(err.msg, "<text>: spindle.coolant_flow_l_min = 4 with jacket_x0_mm = 0, "
                              "jacket_x1_mm = 0: coolant needs a jacket (jacket_x1_mm > "
                              "jacket_x0_mm)") == 0,
       "a preset text's rule message starts with its source: %s", err.msg);
}

static void test_segments(void)
{
    expect("shaft.seg2_length_mm=0", "shaft.seg2_length_mm = 0 with shaft.segments = 3: segments "
           "1 to 3 must each be given (length > 0 mm)");
    expect("shaft.segments=4", "shaft.seg4_length_mm = 0 with shaft.segments = 4: segments 1 to "
           "4 must each be given (length > 0 mm)");
    expect("shaft.seg2_od_mm=0", "shaft.seg2_od_mm = 0 with shaft.segments = 3: segments 1 to 3 "
           "must each be given (od > 0 mm)");
    expect("shaft.seg1_bore_mm=40", "shaft.seg1_bore_mm = 40 with seg1_od_mm = 40: a segment's "
           "bore must be smaller than its outer diameter");
    expect("housing.seg1_bore_mm=130", "housing.seg1_bore_mm = 130 with seg1_od_mm = 120: a "
           "segment's bore must be smaller than its outer diameter");
    expect("housing.segments=0", "shaft.segments = 3 with housing.segments = 0: a spindle needs "
           "a housing (housing.segments >= 1)");
    expect("shaft.segments=5;shaft.seg4_length_mm=5;shaft.seg4_od_mm=30;shaft.seg5_length_mm=5;"
           "shaft.seg5_od_mm=30;shaft.n_div=20",
           "shaft.n_div = 20 with shaft.segments = 5: 100 cells along the shaft, at most 96 "
           "(segments x n_div)");
    expect("shaft.segments=0;housing.segments=0", "");
}

static void test_rear(void)
{
    expect("spindle.rear_spring_N=0", "spindle.rear_support = spring with rear_spring_N = 0: the "
           "springs must push (rear_spring_N > 0 N), or use rear_support = floating");
    expect("spindle.rear_spring_N=0;spindle.rear_support=floating", "");
    expect("spindle.rear_arrangement=DB;spindle.rear_spacing_mm=10", "spindle.rear_spacing_mm = "
           "10 is shorter than bearing.width_mm = 15: neighbouring rear bearings would overlap; "
           "the centre distance is at least one width (0 = adjacent)");
    expect("spindle.rear_arrangement=DB", "spindle.rear_arrangement = DB with rear_preload_N = 0: "
           "an opposed rear set needs a preload > 0 N (its spacers)");
    expect("spindle.rear_arrangement=DB;spindle.rear_preload_N=200", "");
    expect("set.arrangement=DT", "set.arrangement = DT with spindle.rear_support = spring: the "
           "front set is then the shaft's only axial location and must carry thrust both ways "
           "(DB, DF, DBT or QBC), or use spindle.rear_support = fixed");
    expect("set.arrangement=single;spindle.rear_support=floating", "set.arrangement = single with "
           "spindle.rear_support = floating: the front set is then the shaft's only axial "
           "location and must carry thrust both ways (DB, DF, DBT or QBC), or use "
           "spindle.rear_support = fixed");
    expect("set.arrangement=DT;spindle.rear_support=fixed", "");
    /* One front bearing under a radial load without thrust: the rear set
     * carries the shaft too (a lone bearing would be refused). */
    expect("set.arrangement=single;mounting.preload=force;spindle.rear_support=fixed;"
           "operating.radial_load_N=500;operating.axial_load_N=0", "");
    /* A DBT front set (3 x 15 mm, 12.5 to 57.5 mm) on the 60 mm seat. */
    expect("set.arrangement=DBT;spindle.front_x_mm=35", "");
}

static void test_stations(void)
{
    expect("spindle.front_x_mm=230", "spindle.front_x_mm = 230 with rear_x_mm = 230: the front "
           "set must be nearer the nose (front_x_mm < rear_x_mm)");
    expect("spindle.front_x_mm=215", "spindle.front_x_mm = 215 with rear_x_mm = 230: the front "
           "set reaches 230 mm, past the rear set's start at 222.5 mm: the sets overlap");
    expect("spindle.front_x_mm=10", "spindle.front_x_mm = 10: the front set (DB, 2 x "
           "bearing.width_mm) spans -5 to 25 mm; the shaft (0 to 250 mm) must hold it");
    expect("spindle.front_x_mm=15", "spindle.front_x_mm = 15: the front set (DB, 2 x "
           "bearing.width_mm) spans 0 to 30 mm; the housing (10 to 245 mm) must hold it");
    expect("spindle.rear_x_mm=245", "spindle.rear_x_mm = 245: the rear set (single, 1 x "
           "bearing.width_mm) spans 237.5 to 252.5 mm; the shaft (0 to 250 mm) must hold it");
    expect("spindle.rear_x_mm=200", "shaft.seg2_od_mm = 50 at the rear set's bearing 1 (centre "
           "200 mm) with bearing.bore_mm = 40: the inner rings sit on the shaft, so its outer "
           "diameter there must equal the bearing's bore (within 0.01 mm)");
    /* The ring's edge touching a shoulder is no overlap: 202.5 + 7.5 = 210. */
    expect("spindle.rear_x_mm=217.5", "");
    expect("spindle.rear_x_mm=217", "shaft.seg2_od_mm = 50 at the rear set's bearing 1 (centre "
           "217 mm) with bearing.bore_mm = 40: the inner rings sit on the shaft, so its outer "
           "diameter there must equal the bearing's bore (within 0.01 mm)");
    expect("housing.seg1_bore_mm=70", "housing.seg1_bore_mm = 70 at the front set's bearing 1 "
           "(centre 22.5 mm) with bearing.outer_diameter_mm = 68: the outer rings sit in the "
           "housing, so its bore there must equal the bearing's outer diameter (within 0.01 mm)");
    expect("housing.seg1_bore_mm=68.01", "");
    expect("housing.seg1_bore_mm=68.011", "housing.seg1_bore_mm = 68.011 at the front set's "
           "bearing 1 (centre 22.5 mm) with bearing.outer_diameter_mm = 68: the outer rings sit "
           "in the housing, so its bore there must equal the bearing's outer diameter (within "
           "0.01 mm)");
    expect("shaft.seg1_od_mm=39.99", "");
}

static void test_motor_and_coolant(void)
{
    expect("motor.x0_mm=100;motor.x1_mm=50", "motor.x1_mm = 50 with x0_mm = 100: the motor's "
           "rear end must not lie in front of its front end (x1_mm >= x0_mm; equal: no motor)");
    expect("motor.rotor_loss_W=500", "motor.rotor_loss_W = 500 with x0_mm = 0, x1_mm = 0: the "
           "losses need the motor's span (x1_mm > x0_mm)");
    expect("motor.stator_loss_W=800;motor.x0_mm=90;motor.x1_mm=90", "motor.stator_loss_W = 800 "
           "with x0_mm = 90, x1_mm = 90: the losses need the motor's span (x1_mm > x0_mm)");
    expect("motor.x0_mm=100;motor.x1_mm=260", "motor.x0_mm = 100, x1_mm = 260: the motor (100 to "
           "260 mm) must lie on the shaft (0 to 250 mm)");
    expect("motor.x0_mm=5;motor.x1_mm=100", "motor.x0_mm = 5, x1_mm = 100: the motor (5 to 100 "
           "mm) must lie on the housing (10 to 245 mm)");
    expect("motor.x0_mm=80;motor.x1_mm=180;motor.rotor_loss_W=500;motor.stator_loss_W=800", "");
    expect("spindle.jacket_x0_mm=100;spindle.jacket_x1_mm=90", "spindle.jacket_x1_mm = 90 with "
           "jacket_x0_mm = 100: the jacket's rear end must not lie in front of its front end "
           "(jacket_x1_mm >= jacket_x0_mm; equal: no jacket)");
    expect("spindle.jacket_x0_mm=5;spindle.jacket_x1_mm=100", "spindle.jacket_x0_mm = 5, "
           "jacket_x1_mm = 100: the jacket (5 to 100 mm) must lie on the housing (10 to 245 mm)");
    expect("spindle.coolant_flow_l_min=4;spindle.jacket_x0_mm=60;spindle.jacket_x1_mm=200",
           "spindle.coolant_flow_l_min = 4 with jacket_hA_W_K = 0: the jacket wall must pass heat "
           "(jacket_hA_W_K > 0 W/K: film coefficient times wetted area)");
    expect("spindle.coolant_flow_l_min=4;spindle.jacket_x0_mm=60;spindle.jacket_x1_mm=200;"
           "spindle.jacket_hA_W_K=50;spindle.coolant_inlet_dT_K=124",
           "spindle.coolant_inlet_dT_K = 124 with operating.ambient_C = 26: the coolant (150 C) "
           "must be below thermal.temp_limit_C = 150 C");
    expect("spindle.coolant_flow_l_min=4;spindle.jacket_x0_mm=60;spindle.jacket_x1_mm=200;"
           "spindle.jacket_hA_W_K=50;spindle.coolant_inlet_dT_K=-5", "");
}

/* The scene after `edits` (as check() builds it, rules not applied). */
static void scene_with(const char *text, const char *edits, acbb_scene *s)
{
    acbb_error err;
    if (text) acbb_scene_load_text(text, s, &err);
    else acbb_scene_default(s);
    char buf[256];
    snprintf(buf, sizeof buf, "%s", edits);
    for (char *save = NULL, *e = strtok_r(buf, ";", &save); e; e = strtok_r(NULL, ";", &save)) {
        char *eq = strchr(e, '=');
        if (eq) *eq = '\0';
        if (eq) acbb_scene_set_value(s, e, eq + 1, &err);
    }
}

/* Does the scene name `key` as unused, and under which first name? */
static void inactive(const char *text, const char *edits, const char *key, bool want,
                     const char *names)
{
    acbb_scene s;
    scene_with(text, edits, &s);
    acbb_inactive_effect e = { 0 };
    bool got = acbb_scene_key_inactive(&s, key, &e);
    bool pass = got == want && (!want || strcmp(e.key, names) == 0);
    if (!ok(pass, "%s: %s %s", edits, key, want ? "has no effect" : "acts"))
        printf("#   got %d \"%s\" (%s)\n", got, e.key ? e.key : "", e.why ? e.why : "");
}

static void test_inactive(void)
{
    acbb_scene s;
    acbb_inactive_effect in[16];
    acbb_scene_default(&s);
    ok(acbb_scene_inactive_effects(&s, in, 16) == 0, "the default scene: no unused key");
    const char *all = "shaft.seg*_mm, shaft.n_div, shaft.end_film_W_m2K, housing.*, motor.*, "
                      "spindle.*";
    inactive(NULL, "motor.rotor_loss_W=300", "motor.rotor_loss_W", true, all);
    inactive(NULL, "motor.rotor_loss_W=300", "shaft.seg3_bore_mm", true, all);
    inactive(NULL, "motor.rotor_loss_W=300", "spindle.coolant_cells", true, all);
    inactive(NULL, "motor.rotor_loss_W=300", "shaft.segments", false, "");
    inactive(NULL, "shaft.n_div=6", "shaft.n_div", true, all);
    inactive(k_base, "shaft.seg5_od_mm=30", "shaft.seg5_od_mm", true, "shaft.seg[4-8]_*");
    inactive(k_base, "shaft.seg5_od_mm=30", "shaft.seg4_length_mm", true, "shaft.seg[4-8]_*");
    inactive(k_base, "shaft.seg5_od_mm=30", "shaft.seg3_od_mm", false, "");
    inactive(k_base, "shaft.seg5_od_mm=30", "shaft.segments", false, "");
    inactive(k_base, "housing.seg2_length_mm=30", "housing.seg2_length_mm", true,
             "housing.seg[2-8]_*");
    inactive(k_base, "spindle.rear_friction_N=40", "spindle.rear_friction_N", true,
             "spindle.rear_friction_N");
    inactive(k_base, "spindle.rear_friction_N=40;spindle.rear_support=floating",
             "spindle.rear_friction_N", false, "");
    inactive(k_base, "spindle.rear_support=floating;spindle.rear_spring_N=100",
             "spindle.rear_spring_N", true, "spindle.rear_spring_N");
    inactive(k_base, "spindle.rear_preload_N=100", "spindle.rear_preload_N", true,
             "spindle.rear_preload_N");
    inactive(k_base, "spindle.rear_spacing_mm=20", "spindle.rear_spacing_mm", true,
             "spindle.rear_spacing_mm");
    inactive(k_base, "spindle.rear_spacing_mm=20;spindle.rear_arrangement=DT",
             "spindle.rear_spacing_mm", false, "");
    const char *cool = "spindle.coolant_inlet_dT_K, coolant_density_kg_m3, coolant_cp_J_kgK, "
                       "coolant_cells, jacket_*";
    inactive(k_base, "spindle.coolant_cells=4", "spindle.jacket_hA_W_K", true, cool);
    inactive(k_base, "spindle.coolant_cells=4", "spindle.coolant_flow_l_min", false, "");
    inactive(k_base, "motor.gap_conductance_W_K=2", "motor.gap_conductance_W_K", true,
             "motor.gap_conductance_W_K");
    inactive(k_base, "set.load_offset_mm=5", "set.load_offset_mm", true, "set.load_offset_mm");
    /* The rows before the spindle's still match (names are fnmatch patterns). */
    inactive(NULL, "surroundings.cap_h_W_m2K=20;fidelity.network=7", "surroundings.cap_h_W_m2K",
             true, "surroundings.cap_*");
}

/* A spindle preset saved whole (acbb_scene_write) reads back to the same
 * value of every key: the new sections save and load like the others. */
static void test_round_trip(const char *path)
{
    acbb_scene s, t;
    acbb_error err = { 0 };
    char *text = NULL;
    size_t len = 0;
    bool loaded = acbb_scene_load(path, &s, &err) == ACBB_OK;
    FILE *f = open_memstream(&text, &len);
    bool written = loaded && f && acbb_scene_write(f, &s, &err) == ACBB_OK;
    if (f) fclose(f);
    bool back = written && acbb_scene_load_text(text, &t, &err) == ACBB_OK;
    int differ = 0;
    for (size_t i = 0; back && i < acbb_scene_field_count(); i++) {
        char a[64], b[64];
        acbb_scene_field_format(&s, i, a, sizeof a);
        acbb_scene_field_format(&t, i, b, sizeof b);
        differ += strcmp(a, b) != 0;
    }
    ok(back && differ == 0 && s.shaft_segments > 0 && t.shaft_segments == s.shaft_segments,
       "%s: loads, is a spindle, saves whole and reads back key for key (%d differ)%s%s", path,
       differ, back ? "" : ": ", back ? "" : err.msg);
    free(text);
}

int main(void)
{
    test_base_and_file();
    test_segments();
    test_rear();
    test_stations();
    test_motor_and_coolant();
    test_inactive();
    test_round_trip("presets/spindle-belt-DB.ini");
    test_round_trip("presets/spindle-motor-DBT.ini");
    return done_testing();
}
