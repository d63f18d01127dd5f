/* Tests of the scene module: schema and defaults (MODEL.md section 10), the
 * shipped presets, load/save round trip, every validation rule, every load
 * error, acbb_scene_set and atomic saving. Error strings are checked exactly:
 * they are the user interface of the preset files. */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "acbb/scene.h"
#include "acbb/tools/scene_edit.h"
#include "scene_internal.h"
#include "acbb/tools/scene_schema.h"
#include "tap.h"

static void write_bytes(const char *path, const char *bytes, size_t n);
static void test_file_syntax_attack(void);
static void test_non_regular(void);
static void test_value_attack(void);
static void test_intervals(void);
static void test_save_edits(void);

#define PI 3.14159265358979323846

static char g_dir[256];   /* mkdtemp directory for this run */

/* ---- helpers ---- */

static const char *tmp_path(const char *name, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%s", g_dir, name);
    return buf;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) { perror(path); exit(2); }
    fputs(text, f);
    fclose(f);
}

/* Whole file into a malloc'ed string (NULL if unreadable). */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    size_t got = fread(b, 1, (size_t)n, f);
    b[got] = '\0';
    fclose(f);
    return b;
}

static long field_index(const char *dotted)
{
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        char name[128];
        const acbb_field_info *in = acbb_scene_field(i);
        snprintf(name, sizeof name, "%s.%s", in->section, in->key);
        if (strcmp(name, dotted) == 0) return (long)i;
    }
    return -1;
}

/* Number of schema fields whose values differ; the formatted text is exact
 * (it converts back to the identical double), so equal text = equal value. */
static int count_differences(const acbb_scene *a, const acbb_scene *b, const char *label)
{
    int diff = 0;
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        char va[64], vb[64];
        acbb_scene_field_format(a, i, va, sizeof va);
        acbb_scene_field_format(b, i, vb, sizeof vb);
        if (strcmp(va, vb) != 0) {
            printf("#   %s: %s.%s: %s != %s\n", label, acbb_scene_field(i)->section,
                   acbb_scene_field(i)->key, va, vb);
            diff++;
        }
    }
    return diff;
}

/* Number of entries in `dir` that look like leftover temp files: acbb_out's
 * ".NAME.acbb-XXXXXX" or the ".tmp." names of older code. */
static int count_temp_files(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d) return 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (strstr(e->d_name, ".tmp.") || strstr(e->d_name, ".acbb-")) n++;
    closedir(d);
    return n;
}

/* Set on a default scene; expect failure `code` with exactly `msg`, and the
 * scene unchanged. */
static void expect_set_fails(const char *key, const char *value, acbb_status code,
                             const char *msg)
{
    acbb_scene s, before;
    acbb_error e = {{0}};
    acbb_scene_default(&s);
    before = s;
    acbb_status rc = acbb_scene_set(&s, key, value, &e);
    ok(rc == code, "set %s = %s returns %s (got %s)", key, value, acbb_status_name(code),
       acbb_status_name(rc));
    ok(strcmp(e.msg, msg) == 0, "set %s = %s: message", key, value);
    if (strcmp(e.msg, msg) != 0) printf("#   got  \"%s\"\n#   want \"%s\"\n", e.msg, msg);
    ok(memcmp(&s, &before, sizeof s) == 0, "set %s = %s leaves the scene unchanged", key, value);
}

static void expect_set_ok(acbb_scene *s, const char *key, const char *value)
{
    acbb_error e = {{0}};
    acbb_status rc = acbb_scene_set(s, key, value, &e);
    ok(rc == ACBB_OK, "set %s = %s accepted%s%s", key, value, rc ? ": " : "", rc ? e.msg : "");
}

/* Write `text` to a temp preset, load it, expect `code` and exactly
 * "<path><suffix>" as the message. */
static void expect_load_fails(const char *name, const char *text, acbb_status code,
                              const char *suffix)
{
    char path[512], want[1024];
    acbb_scene s, before;
    acbb_error e = {{0}};
    tmp_path(name, path, sizeof path);
    write_text(path, text);
    memset(&s, 0x5a, sizeof s);
    before = s;
    acbb_status rc = acbb_scene_load(path, &s, &e);
    snprintf(want, sizeof want, "%s%s", path, suffix);
    ok(rc == code, "load %s returns %s (got %s)", name, acbb_status_name(code),
       acbb_status_name(rc));
    ok(strcmp(e.msg, want) == 0, "load %s: message", name);
    if (strcmp(e.msg, want) != 0) printf("#   got  \"%s\"\n#   want \"%s\"\n", e.msg, want);
    ok(memcmp(&s, &before, sizeof s) == 0, "load %s leaves the output untouched", name);
}

/* ---- schema and defaults ---- */

/* The contract: every key, in order, with its default in preset units
 * (MODEL.md section 10). */
static const char *const k_expected[][2] = {
    {"bearing.pitch_diameter_mm", "54"}, {"bearing.ball_diameter_mm", "6.35"},
    {"bearing.n_balls", "21"}, {"bearing.inner_groove_radius_mm", "3.43"},
    {"bearing.outer_groove_radius_mm", "3.43"}, {"bearing.contact_angle_deg", "15"},
    {"bearing.clearance_um", "0"},
    {"bearing.bore_mm", "40"}, {"bearing.outer_diameter_mm", "68"}, {"bearing.width_mm", "15"},
    {"bearing.cage_width_mm", "10.1"}, {"bearing.cage_diameter_mm", "57.7"},
    {"bearing.inner_land_diameter_mm", "49.9"}, {"bearing.outer_land_diameter_mm", "58.1"},
    {"bearing.roughness_race_um", "0.34"}, {"bearing.roughness_ball_um", "0.1"},
    {"materials.ball_E_GPa", "207"}, {"materials.ball_poisson", "0.3"},
    {"materials.ball_density_kg_m3", "7810"}, {"materials.ball_cp_J_kgK", "450"},
    {"materials.ball_k_W_mK", "40.1"}, {"materials.ball_expansion_ppm_K", "12.5"},
    {"materials.ring_E_GPa", "207"}, {"materials.ring_poisson", "0.3"},
    {"materials.ring_density_kg_m3", "7810"}, {"materials.ring_cp_J_kgK", "450"},
    {"materials.ring_k_W_mK", "40.1"}, {"materials.ring_expansion_ppm_K", "12.5"},
    {"materials.shaft_E_GPa", "212"}, {"materials.shaft_poisson", "0.298"},
    {"materials.shaft_density_kg_m3", "7860"}, {"materials.shaft_cp_J_kgK", "485"},
    {"materials.shaft_k_W_mK", "42.4"}, {"materials.shaft_expansion_ppm_K", "11.5"},
    {"materials.housing_E_GPa", "143"}, {"materials.housing_poisson", "0.27"},
    {"materials.housing_density_kg_m3", "7300"}, {"materials.housing_cp_J_kgK", "510"},
    {"materials.housing_k_W_mK", "45"}, {"materials.housing_expansion_ppm_K", "10.5"},
    {"materials.cage_E_GPa", "206"}, {"materials.cage_poisson", "0.254"},
    {"materials.cage_density_kg_m3", "7830"}, {"materials.cage_cp_J_kgK", "460"},
    {"materials.cage_k_W_mK", "44"}, {"materials.cage_expansion_ppm_K", "11.7"},
    {"lubricant.oil_density_kg_m3", "876"}, {"lubricant.oil_nu40_mm2_s", "30"},
    {"lubricant.oil_nu100_mm2_s", "5.3"}, {"lubricant.oil_eta_const_Pa_s", "0.2"},
    {"lubricant.oil_alpha_pv_per_GPa", "20"}, {"lubricant.oil_k_W_mK", "0.13"},
    {"lubricant.oil_cp_J_kgK", "1950"}, {"lubricant.air_eta_Pa_s", "2e-05"},
    {"lubricant.air_density_kg_m3", "1.128"}, {"lubricant.air_k_W_mK", "0.027"},
    {"lubricant.air_cp_J_kgK", "1007"}, {"lubricant.air_prandtl", "0.71"},
    {"lubricant.mixture_k_W_mK", "0.04"}, {"lubricant.air_flow_L_min", "60"},
    {"lubricant.oil_flow_ml_h", "0.4"}, {"lubricant.boundary_friction", "0.1"},
    {"lubricant.limiting_shear_ratio", "0.07"}, {"lubricant.eyring_stress_MPa", "5"},
    {"lubricant.hysteresis_loss", "0.007"}, {"lubricant.drag_coefficient", "0.45"},
    {"lubricant.viscosity_model", "roelands"}, {"lubricant.traction_model", "eyring-cap"},
    {"lubricant.method", "oil-air"}, {"lubricant.grade", "custom"},
    {"lubricant.viscosity_index", "100"}, {"lubricant.jet_speed_m_s", "10"},
    {"lubricant.bath_level_mm", "0"}, {"lubricant.grease_base_oil_nu40_mm2_s", "0"},
    {"mounting.shaft_bore_mm", "0"}, {"mounting.h_fit_outer_W_m2K", "5000"},
    {"mounting.h_fit_inner_W_m2K", "20000"}, {"mounting.h_face_W_m2K", "3000"},
    {"mounting.h_natural_W_m2K", "10"}, {"mounting.preload", "force"},
    {"mounting.preload_N", "300"},
    {"mounting.tilt", "auto"},
    {"set.arrangement", "single"}, {"set.n_bearings", "0"}, {"set.spacing_mm", "0"},
    {"set.load_offset_mm", "0"}, {"set.spacer_expansion_ppm_K", "0"},
    {"set.inner_spacer_mm", "0"}, {"set.outer_spacer_mm", "0"},
    {"surroundings.housing_outer_diameter_mm", "0"}, {"surroundings.housing_length_mm", "0"},
    {"surroundings.housing_exterior", "convective"}, {"surroundings.shaft_length_mm", "0"},
    {"surroundings.shaft_bore", "derived"}, {"surroundings.shaft_bore_h_W_m2K", "500"},
    {"surroundings.shaft_bore_coolant_dT_K", "0"}, {"surroundings.cap_outer_diameter_mm", "0"},
    {"surroundings.cap_thickness_mm", "0"}, {"surroundings.cap", "derived"},
    {"surroundings.cap_h_W_m2K", "10"}, {"surroundings.cap_coolant_dT_K", "0"},
    {"operating.inner_speed_rpm", "15000"}, {"operating.axial_load_N", "1000"},
    {"operating.radial_load_N", "0"}, {"operating.moment_load_Nm", "0"},
    {"operating.ambient_C", "26"},
    {"effects.heating", "on"}, {"effects.thermal_expansion", "on"}, {"effects.centrifugal", "on"},
    {"effects.gyroscopic", "on"}, {"effects.ring_centrifugal", "on"},
    {"effects.ehl_film", "on"}, {"effects.loss_shear", "on"}, {"effects.loss_slip", "on"},
    {"effects.loss_spin", "on"}, {"effects.loss_rolling", "on"}, {"effects.loss_drag", "on"},
    {"effects.loss_cage", "off"},
    {"effects.loss_ehl_rolling", "off"}, {"effects.loss_churning", "off"},
    {"fidelity.model", "quasi-dynamic"}, {"fidelity.contact_grid", "6"},
    {"fidelity.hertz", "bh77"}, {"fidelity.geometry", "clean"},
    {"fidelity.race_control", "outer"}, {"fidelity.loss_form", "clean"},
    {"fidelity.hysteresis_axis", "major"}, {"fidelity.rolling_hysteresis", "seed"},
    {"fidelity.mech_tol", "1e-08"},
    {"fidelity.steady_tol_K_s", "0.0001"},
    {"fidelity.network", "46"}, {"fidelity.thermal_mode", "transient"}, {"fidelity.time_step_s", "5"},
    {"fidelity.preset", "custom"}, {"fidelity.target_error_pct", "0"},
    {"fidelity.max_wall_s", "0"}, /* issue 20: the wall-clock bound, off */
    {"thermal.max_time_s", "36000"}, {"thermal.max_steps", "20000"},
    {"thermal.temp_limit_C", "150"}, {"thermal.contact_multiplier", "1"},
    {"thermal.contact_model", "stationary"}, /* issue 25: the seed's spots */
    {"thermal.heat_partition", "0.5"},
    {"life.reliability_pct", "90"},
    {"life.contamination_ec", "0.5"},
    {"life.fatigue_limit_N", "0"},
    {"life.inner_shoulder_mm", "0"},
    {"life.outer_shoulder_mm", "0"},
    {"life.internals_estimated", "off"},
    {"physics.profile", "seed"},
    /* issue 31: the spindle (shaft.segments = 0: none) */
    {"shaft.segments", "0"}, {"shaft.seg1_length_mm", "0"}, {"shaft.seg1_od_mm", "0"},
    {"shaft.seg1_bore_mm", "0"}, {"shaft.seg2_length_mm", "0"}, {"shaft.seg2_od_mm", "0"},
    {"shaft.seg2_bore_mm", "0"}, {"shaft.seg3_length_mm", "0"}, {"shaft.seg3_od_mm", "0"},
    {"shaft.seg3_bore_mm", "0"}, {"shaft.seg4_length_mm", "0"}, {"shaft.seg4_od_mm", "0"},
    {"shaft.seg4_bore_mm", "0"}, {"shaft.seg5_length_mm", "0"}, {"shaft.seg5_od_mm", "0"},
    {"shaft.seg5_bore_mm", "0"}, {"shaft.seg6_length_mm", "0"}, {"shaft.seg6_od_mm", "0"},
    {"shaft.seg6_bore_mm", "0"}, {"shaft.seg7_length_mm", "0"}, {"shaft.seg7_od_mm", "0"},
    {"shaft.seg7_bore_mm", "0"}, {"shaft.seg8_length_mm", "0"}, {"shaft.seg8_od_mm", "0"},
    {"shaft.seg8_bore_mm", "0"}, {"shaft.n_div", "4"}, {"shaft.end_film_W_m2K", "10"},
    {"housing.segments", "0"}, {"housing.seg1_length_mm", "0"}, {"housing.seg1_od_mm", "0"},
    {"housing.seg1_bore_mm", "0"}, {"housing.seg2_length_mm", "0"}, {"housing.seg2_od_mm", "0"},
    {"housing.seg2_bore_mm", "0"}, {"housing.seg3_length_mm", "0"}, {"housing.seg3_od_mm", "0"},
    {"housing.seg3_bore_mm", "0"}, {"housing.seg4_length_mm", "0"}, {"housing.seg4_od_mm", "0"},
    {"housing.seg4_bore_mm", "0"}, {"housing.seg5_length_mm", "0"}, {"housing.seg5_od_mm", "0"},
    {"housing.seg5_bore_mm", "0"}, {"housing.seg6_length_mm", "0"}, {"housing.seg6_od_mm", "0"},
    {"housing.seg6_bore_mm", "0"}, {"housing.seg7_length_mm", "0"}, {"housing.seg7_od_mm", "0"},
    {"housing.seg7_bore_mm", "0"}, {"housing.seg8_length_mm", "0"}, {"housing.seg8_od_mm", "0"},
    {"housing.seg8_bore_mm", "0"}, {"housing.x0_mm", "0"}, {"housing.outer_film_W_m2K", "10"},
    {"motor.rotor_loss_W", "0"}, {"motor.stator_loss_W", "0"}, {"motor.x0_mm", "0"},
    {"motor.x1_mm", "0"}, {"motor.gap_conductance_W_K", "0"}, {"spindle.front_x_mm", "0"},
    {"spindle.rear_x_mm", "0"}, {"spindle.rear_support", "spring"},
    {"spindle.rear_arrangement", "single"}, {"spindle.rear_spacing_mm", "0"},
    {"spindle.rear_preload_N", "0"}, {"spindle.rear_spring_N", "300"},
    {"spindle.rear_friction_N", "0"}, {"spindle.coolant_flow_l_min", "0"},
    {"spindle.coolant_inlet_dT_K", "0"}, {"spindle.coolant_density_kg_m3", "1000"},
    {"spindle.coolant_cp_J_kgK", "4180"}, {"spindle.jacket_x0_mm", "0"},
    {"spindle.jacket_x1_mm", "0"}, {"spindle.jacket_hA_W_K", "0"}, {"spindle.coolant_cells", "8"},
};

static void test_key_list_and_defaults(void)
{
    size_t n = sizeof k_expected / sizeof k_expected[0];
    acbb_scene s;
    acbb_scene_default(&s);
    ok(acbb_scene_field_count() == n, "schema has %zu keys (got %zu)", n,
       acbb_scene_field_count());
    int bad = 0;
    for (size_t i = 0; i < n && i < acbb_scene_field_count(); i++) {
        const acbb_field_info *in = acbb_scene_field(i);
        char name[128], val[64];
        snprintf(name, sizeof name, "%s.%s", in->section, in->key);
        acbb_scene_field_format(&s, i, val, sizeof val);
        if (strcmp(name, k_expected[i][0]) != 0 || strcmp(val, k_expected[i][1]) != 0) {
            printf("#   field %zu: %s = %s, want %s = %s\n", i, name, val, k_expected[i][0],
                   k_expected[i][1]);
            bad++;
        }
    }
    ok(bad == 0, "every key name and default value as in MODEL.md section 10");
    ok(acbb_scene_field(n) == NULL, "acbb_scene_field past the end is NULL");
}

static void test_defaults_in_si(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    /* Hand conversions from the preset units of MODEL.md section 10. */
    is_close(s.pitch_diameter, 0.054, 1e-15, 0, "d_m = 54 mm = 0.054 m");
    is_close(s.ball_diameter, 6.35e-3, 1e-15, 0, "D = 6.35 mm");
    ok(s.n_balls == 21, "Z = 21");
    is_close(s.contact_angle0, 15.0 * PI / 180.0, 1e-15, 0, "alpha0 = 15 deg = 0.2618 rad");
    is_close(s.inner_speed, 1570.7963267948965, 1e-15, 0, "15000 rpm = 1570.796 rad/s");
    is_close(s.q_air, 1e-3, 1e-15, 0, "air flow 60 L/min = 1e-3 m^3/s");
    is_close(s.q_oil, 0.4e-6 / 3600.0, 1e-15, 0, "oil flow 0.4 ml/h = 1.111e-10 m^3/s");
    is_close(s.oil_alpha_pv, 2e-8, 1e-15, 0, "alpha_pv 20 1/GPa = 2e-8 1/Pa");
    is_close(s.oil_nu40, 30e-6, 1e-15, 0, "nu40 30 mm^2/s = 3e-5 m^2/s");
    is_close(s.tau_eyring, 5e6, 1e-15, 0, "tau_E 5 MPa");
    is_close(s.ball.E, 207e9, 1e-15, 0, "ball E 207 GPa");
    is_close(s.housing.E, 143e9, 1e-15, 0, "housing E 143 GPa");
    is_close(s.cage.chi, 11.7e-6, 1e-15, 0, "cage expansion 11.7 ppm/K");
    is_close(s.roughness_race, 0.34e-6, 1e-15, 0, "race roughness 0.34 um");
    is_close(s.shaft.nu, 0.298, 0, 0, "shaft poisson 0.298");
    is_close(s.ambient_C, 26.0, 0, 0, "ambient stays in C");
    is_close(s.h_fit_inner, 20000.0, 0, 0, "IR fit conductance");
    ok(s.thermal_expansion && s.loss_drag && s.gyroscopic, "effects on by default");
    ok(s.model == ACBB_MODEL_QUASI_DYNAMIC && s.hertz == ACBB_HERTZ_BH77 && s.network == ACBB_NET_46 &&
       s.visc == ACBB_VISC_ROELANDS && s.preload == ACBB_PRELOAD_FORCE &&
       s.race_control == ACBB_RACE_OUTER && s.thermal_mode == ACBB_THERMAL_TRANSIENT,
       "enum defaults");
    ok(s.contact_grid == 6 && s.max_steps == 20000, "int defaults");
    acbb_error e = {{0}};
    ok(acbb_scene_validate(&s, &e) == ACBB_OK, "defaults validate%s", e.msg);
}

static void test_introspection(void)
{
    const acbb_field_info *in = acbb_scene_field((size_t)field_index("operating.inner_speed_rpm"));
    ok(in && in->type == ACBB_FIELD_REAL && strcmp(in->unit, "rpm") == 0 && in->min == 0 &&
       in->max == 100000, "inner_speed_rpm: REAL, rpm, 0..100000");
    in = acbb_scene_field((size_t)field_index("fidelity.model"));
    ok(in && in->type == ACBB_FIELD_ENUM && strcmp(in->choices[1], "quasi-static") == 0 &&
       in->choices[4] == NULL, "fidelity.model: ENUM with 4 choices");
    in = acbb_scene_field((size_t)field_index("fidelity.contact_grid"));
    ok(in && in->type == ACBB_FIELD_INT && in->min == 2 && in->max == 64,
       "contact_grid: INT 2..64");
    in = acbb_scene_field((size_t)field_index("effects.thermal_expansion"));
    ok(in && in->type == ACBB_FIELD_BOOL, "thermal_expansion: BOOL");

    char buf[160];
    acbb_scene_field_range((size_t)field_index("bearing.ball_diameter_mm"), buf, sizeof buf);
    ok(strcmp(buf, "0 < x <= 100 mm") == 0, "range text of ball diameter: %s", buf);
    acbb_scene_field_range((size_t)field_index("materials.cage_poisson"), buf, sizeof buf);
    ok(strcmp(buf, "0 < x < 0.5") == 0, "range text of poisson: %s", buf);
    acbb_scene_field_range((size_t)field_index("fidelity.model"), buf, sizeof buf);
    ok(strcmp(buf, "static | quasi-static | quasi-dynamic | dynamic") == 0,
       "range text of an enum: %s", buf);
    acbb_scene_field_range((size_t)field_index("effects.loss_spin"), buf, sizeof buf);
    ok(strcmp(buf, "on | off") == 0, "range text of a bool: %s", buf);

    ok(strcmp(acbb_model_level_name(ACBB_MODEL_STATIC), "static") == 0 &&
       strcmp(acbb_model_level_name(ACBB_MODEL_QUASI_STATIC), "quasi-static") == 0 &&
       strcmp(acbb_model_level_name(ACBB_MODEL_QUASI_DYNAMIC), "quasi-dynamic") == 0 &&
       strcmp(acbb_model_level_name(ACBB_MODEL_DYNAMIC), "dynamic") == 0,
       "acbb_model_level_name");
}

/* ---- presets ---- */

static void test_presets(void)
{
    acbb_scene def, s;
    acbb_error e = {{0}};
    acbb_scene_default(&def);

    acbb_status rc = acbb_scene_load("presets/7008C.ini", &s, &e);
    ok(rc == ACBB_OK, "presets/7008C.ini loads%s%s", rc ? ": " : "", rc ? e.msg : "");
    ok(count_differences(&s, &def, "7008C") == 0, "presets/7008C.ini equals the defaults");

    rc = acbb_scene_load("presets/teaching-7node.ini", &s, &e);
    ok(rc == ACBB_OK, "teaching-7node.ini loads%s%s", rc ? ": " : "", rc ? e.msg : "");
    ok(s.network == ACBB_NET_7, "teaching: 7-node network");
    is_close(s.inner_speed, 8000.0 * 2.0 * PI / 60.0, 1e-15, 0, "teaching: 8000 rpm");
    is_close(s.axial_load, 300.0, 0, 0, "teaching: 300 N");
    is_close(s.ball_diameter, def.ball_diameter, 0, 0, "teaching: same bearing");

    rc = acbb_scene_load("presets/combined-load.ini", &s, &e);
    ok(rc == ACBB_OK, "combined-load.ini loads%s%s", rc ? ": " : "", rc ? e.msg : "");
    is_close(s.radial_load, 600.0, 0, 0, "combined: Fr 600 N");
    /* Well-posed (MODEL.md section 11) yet Fr tan(alpha0)/Fa > 0.6, the
     * rigid-ring threshold past which part of the ball set unloads. */
    double ratio = s.radial_load * tan(15.0 * PI / 180.0) / s.axial_load;
    ok(s.axial_load >= 1.25 * s.radial_load * tan(s.contact_angle0) && ratio > 0.6,
       "combined: Fa = %g N well-posed, Fr tan(a0)/Fa = %.3f > 0.6", s.axial_load, ratio);

    rc = acbb_scene_load("presets/light-load-skid.ini", &s, &e);
    ok(rc == ACBB_OK, "light-load-skid.ini loads%s%s", rc ? ": " : "", rc ? e.msg : "");
    is_close(s.axial_load, 50.0, 0, 0, "skid: 50 N");
    is_close(s.inner_speed, 16000.0 * 2.0 * PI / 60.0, 1e-15, 0, "skid: 16000 rpm");
}

/* ---- save / load round trip ---- */

static void test_round_trip(void)
{
    acbb_scene s, back;
    acbb_error e = {{0}};
    char p1[512], p2[512], p3[512];
    acbb_scene_default(&s);
    /* Awkward conversions and every value kind. */
    expect_set_ok(&s, "operating.inner_speed_rpm", "12345.678");
    expect_set_ok(&s, "bearing.contact_angle_deg", "17.3");
    expect_set_ok(&s, "lubricant.air_flow_L_min", "33.3");
    expect_set_ok(&s, "lubricant.oil_flow_ml_h", "0.77");
    expect_set_ok(&s, "lubricant.oil_alpha_pv_per_GPa", "19.1");
    expect_set_ok(&s, "fidelity.model", "static");
    expect_set_ok(&s, "fidelity.network", "7");
    expect_set_ok(&s, "effects.gyroscopic", "no");
    expect_set_ok(&s, "operating.moment_load_Nm", "-2.5");
    /* SI values that no short preset number produces. */
    s.inner_speed = 1234.5678901234567;
    s.contact_angle0 = 0.3;
    s.q_air = 7.7e-4;
    s.q_oil = 1.3e-10;
    s.ball.E = 2.0999e11 + 0.123;
    s.oil_alpha_pv = 1.9e-8 / 3.0;
    s.mech_tol = 1e-11 / 3.0;
    ok(acbb_scene_validate(&s, &e) == ACBB_OK, "round-trip scene is valid");

    tmp_path("rt1.ini", p1, sizeof p1);
    tmp_path("rt2.ini", p2, sizeof p2);
    tmp_path("rt3.ini", p3, sizeof p3);
    ok(acbb_scene_save(p1, &s, &e) == ACBB_OK, "save");
    acbb_status rc = acbb_scene_load(p1, &back, &e);
    ok(rc == ACBB_OK, "load of saved file%s%s", rc ? ": " : "", rc ? e.msg : "");
    ok(count_differences(&s, &back, "round trip") == 0, "load(save(s)) == s, every field");
    ok(back.inner_speed == s.inner_speed && back.contact_angle0 == s.contact_angle0 &&
       back.q_air == s.q_air && back.q_oil == s.q_oil && back.ball.E == s.ball.E &&
       back.oil_alpha_pv == s.oil_alpha_pv && back.mech_tol == s.mech_tol,
       "awkward SI values come back bit-identical");
    ok(back.model == ACBB_MODEL_STATIC && back.network == ACBB_NET_7 && !back.gyroscopic,
       "enums and bools come back");

    ok(acbb_scene_save(p2, &s, &e) == ACBB_OK && acbb_scene_save(p3, &back, &e) == ACBB_OK,
       "save twice");
    char *t1 = read_text(p1), *t2 = read_text(p2), *t3 = read_text(p3);
    ok(t1 && t2 && t3 && strcmp(t1, t2) == 0 && strcmp(t1, t3) == 0,
       "saving the same scene twice (and its reload) gives identical bytes");

    /* Every line fits inih's 200-byte buffer, every key has a comment above. */
    int long_lines = 0, keys = 0, commented = 0;
    const char *prev = "";
    for (char *line = strtok(t1, "\n"); line; line = strtok(NULL, "\n")) {
        if (strlen(line) > 197) long_lines++;
        if (line[0] != ';' && line[0] != '[' && strchr(line, '=')) {
            keys++;
            commented += prev[0] == ';';
        }
        prev = line;
    }
    ok(long_lines == 0, "no saved line longer than 197 characters");
    ok(keys == (int)acbb_scene_field_count() && commented == keys,
       "all %d keys saved, each under a help comment (%d keys, %d commented)",
       (int)acbb_scene_field_count(), keys, commented);
    ok(t2 && strstr(t2, "\n; inner ring speed [0 <= x <= 100000 rpm]\ninner_speed_rpm = ") != NULL,
       "help line carries the range and unit");
    free(t1);
    free(t2);
    free(t3);
}

/* ---- range rules (acbb_scene_set, no PATH:LINE prefix) ---- */

static void test_range_rules(void)
{
    expect_set_fails("bearing.ball_diameter_mm", "-3", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = -3: must be > 0 mm");
    expect_set_fails("bearing.ball_diameter_mm", "0", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = 0: must be > 0 mm");
    expect_set_fails("bearing.ball_diameter_mm", "101", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = 101: must be > 0 and <= 100 mm");
    expect_set_fails("operating.inner_speed_rpm", "1e9", ACBB_EINVAL,
                     "operating.inner_speed_rpm = 1e9: must be between 0 and 100000 rpm");
    expect_set_fails("operating.axial_load_N", "-5", ACBB_EINVAL,
                     "operating.axial_load_N = -5: must be >= 0 N");
    expect_set_fails("materials.ball_poisson", "0.5", ACBB_EINVAL,
                     "materials.ball_poisson = 0.5: must be > 0 and < 0.5");
    expect_set_fails("operating.ambient_C", "-51", ACBB_EINVAL,
                     "operating.ambient_C = -51: must be >= -50 C");
    expect_set_fails("fidelity.contact_grid", "65", ACBB_EINVAL,
                     "fidelity.contact_grid = 65: must be between 2 and 64");
    expect_set_fails("fidelity.contact_grid", "1", ACBB_EINVAL,
                     "fidelity.contact_grid = 1: must be >= 2");
    expect_set_fails("bearing.n_balls", "20.5", ACBB_EINVAL,
                     "bearing.n_balls = 20.5: must be a whole number");
    expect_set_fails("fidelity.mech_tol", "1e-15", ACBB_EINVAL,
                     "fidelity.mech_tol = 1e-15: must be >= 1e-14");
    expect_set_fails("bearing.ball_diameter_mm", "abc", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = abc: not a number");
    expect_set_fails("bearing.ball_diameter_mm", "12abc", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = 12abc: not a number (unexpected \"abc\" after 12)");
    expect_set_fails("bearing.ball_diameter_mm", "6,35", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = 6,35: not a number (unexpected \",35\" after 6)");
    expect_set_fails("bearing.ball_diameter_mm", "nan", ACBB_EINVAL,
                     "bearing.ball_diameter_mm = nan: must be a finite number");
    expect_set_fails("operating.axial_load_N", "inf", ACBB_EINVAL,
                     "operating.axial_load_N = inf: must be a finite number");
    expect_set_fails("operating.axial_load_N", "1e999", ACBB_EINVAL,
                     "operating.axial_load_N = 1e999: must be a finite number");
    expect_set_fails("operating.axial_load_N", "", ACBB_EINVAL,
                     "operating.axial_load_N = : missing value");
    expect_set_fails("fidelity.model", "fast", ACBB_EINVAL,
                     "fidelity.model = fast: must be one of: static, quasi-static, "
                     "quasi-dynamic, dynamic");
    expect_set_fails("fidelity.network", "12", ACBB_EINVAL,
                     "fidelity.network = 12: must be one of: 46, 7");
    expect_set_fails("effects.centrifugal", "maybe", ACBB_EINVAL,
                     "effects.centrifugal = maybe: must be on or off (or true/false, yes/no, 1/0)");

    /* Boundaries that are inside, and every bool spelling. */
    acbb_scene s;
    acbb_scene_default(&s);
    expect_set_ok(&s, "operating.inner_speed_rpm", "100000");
    expect_set_ok(&s, "operating.inner_speed_rpm", "0");
    expect_set_ok(&s, "operating.axial_load_N", " 0 ");
    expect_set_ok(&s, "fidelity.contact_grid", "64");
    expect_set_ok(&s, "fidelity.model", "Quasi-Dynamic");
    ok(s.model == ACBB_MODEL_QUASI_DYNAMIC, "enum matched without case");
    const char *const yes[] = {"on", "true", "yes", "1", "ON"};
    const char *const no[] = {"off", "false", "no", "0", "Off"};
    int bool_ok = 0;
    for (int i = 0; i < 5; i++) {
        acbb_error e;
        bool_ok += acbb_scene_set(&s, "effects.loss_spin", no[i], &e) == ACBB_OK && !s.loss_spin;
        bool_ok += acbb_scene_set(&s, "effects.loss_spin", yes[i], &e) == ACBB_OK && s.loss_spin;
    }
    ok(bool_ok == 10, "bool spellings on/off true/false yes/no 1/0 accepted");
    char buf[64];
    acbb_scene_set(&s, "effects.loss_spin", "no", NULL);
    acbb_scene_field_format(&s, (size_t)field_index("effects.loss_spin"), buf, sizeof buf);
    ok(strcmp(buf, "off") == 0, "bool formats as off");
}

/* ---- bad keys in acbb_scene_set ---- */

static void test_set_keys(void)
{
    expect_set_fails("operating.axial_lod_N", "5", ACBB_EINVAL,
                     "operating.axial_lod_N: unknown key (did you mean operating.axial_load_N?)");
    expect_set_fails("axial_load_N", "5", ACBB_EINVAL,
                     "axial_load_N: expected section.key (did you mean operating.axial_load_N?)");
    expect_set_fails("operatin.axial_load_N", "5", ACBB_EINVAL,
                     "operatin.axial_load_N: unknown section [operatin] (did you mean "
                     "operating.axial_load_N?)");
    expect_set_fails("bearing.qqqqqqqqqqqqqq", "5", ACBB_EINVAL,
                     "bearing.qqqqqqqqqqqqqq: unknown key");
}

/* ---- cross-field rules: one test each ---- */

static void test_cross_rules(void)
{
    /* Raceway diameters by hand (MODEL.md section 1): d_i = 47.633 mm,
     * d_o = 60.367 mm for the 7008C. */
    double A0 = 3.43 + 3.43 - 6.35, Pd = 2 * A0 * (1 - cos(15 * PI / 180));
    double di = 54 - 6.35 - Pd / 2, d_o = 54 + 6.35 + Pd / 2;
    is_close(di, 47.633, 0, 5e-4, "hand d_i = 47.633 mm");
    is_close(d_o, 60.367, 0, 5e-4, "hand d_o = 60.367 mm");

    expect_set_fails("bearing.inner_groove_radius_mm", "3.2", ACBB_EINVAL,
                     "bearing.inner_groove_radius_mm = 3.2 with ball_diameter_mm = 6.35: groove "
                     "curvature f = radius / ball_diameter = 0.5039 must be >= 0.505 "
                     "(docs/physics.md section 11)");
    expect_set_fails("bearing.outer_groove_radius_mm", "3", ACBB_EINVAL,
                     "bearing.outer_groove_radius_mm = 3 with ball_diameter_mm = 6.35: groove "
                     "curvature f = radius / ball_diameter = 0.4724 must be >= 0.505 "
                     "(docs/physics.md section 11)");
    /* 27 * 6.35 = 171.45 mm > 0.98 pi 54 = 166.25 mm; 26 balls (165.1 mm) fit. */
    ok(27 * 6.35 > 0.98 * PI * 54 && 26 * 6.35 <= 0.98 * PI * 54, "hand: 26 fit, 27 do not");
    expect_set_fails("bearing.n_balls", "27", ACBB_EINVAL,
                     "bearing.n_balls = 27 with ball_diameter_mm = 6.35, pitch_diameter_mm = 54: "
                     "the balls do not fit on the pitch circle (n_balls * ball_diameter = "
                     "171.4 mm > 0.98 pi pitch_diameter = 166.3 mm)");
    acbb_scene s;
    acbb_scene_default(&s);
    expect_set_ok(&s, "bearing.n_balls", "26");
    expect_set_fails("bearing.bore_mm", "47.7", ACBB_EINVAL,
                     "bearing.bore_mm = 47.7 with pitch_diameter_mm = 54, ball_diameter_mm = "
                     "6.35: the inner ring has no material (bore must be < the inner raceway "
                     "diameter d_i = 47.6326 mm, docs/physics.md section 1)");
    expect_set_ok(&s, "bearing.bore_mm", "47.6");
    expect_set_fails("bearing.outer_diameter_mm", "60.3", ACBB_EINVAL,
                     "bearing.outer_diameter_mm = 60.3 with pitch_diameter_mm = 54, "
                     "ball_diameter_mm = 6.35: the outer ring has no material (outer_diameter "
                     "must be > the outer raceway diameter d_o = 60.3674 mm, docs/physics.md "
                     "section 1)");
    expect_set_fails("bearing.inner_land_diameter_mm", "54.5", ACBB_EINVAL,
                     "bearing.inner_land_diameter_mm = 54.5 with pitch_diameter_mm = 54: the "
                     "inner land must lie between the inner raceway (d_i = 47.6326 mm) and the "
                     "pitch circle");
    expect_set_fails("bearing.outer_land_diameter_mm", "60.5", ACBB_EINVAL,
                     "bearing.outer_land_diameter_mm = 60.5 with pitch_diameter_mm = 54: the "
                     "outer land must lie between the pitch circle and the outer raceway "
                     "(d_o = 60.3674 mm)");
    expect_set_fails("bearing.cage_diameter_mm", "58.2", ACBB_EINVAL,
                     "bearing.cage_diameter_mm = 58.2 with inner_land_diameter_mm = 49.9, "
                     "outer_land_diameter_mm = 58.1: the cage must lie between the two lands");
    expect_set_fails("bearing.width_mm", "6", ACBB_EINVAL,
                     "bearing.width_mm = 6 with ball_diameter_mm = 6.35: the rings must be "
                     "wider than the balls");
    expect_set_fails("bearing.cage_width_mm", "15.5", ACBB_EINVAL,
                     "bearing.cage_width_mm = 15.5 with width_mm = 15: the cage must not be "
                     "wider than the rings");
    expect_set_fails("mounting.shaft_bore_mm", "40", ACBB_EINVAL,
                     "mounting.shaft_bore_mm = 40 with bearing.bore_mm = 40: the shaft bore "
                     "must be smaller than the bearing bore");
    expect_set_fails("lubricant.oil_nu100_mm2_s", "30", ACBB_EINVAL,
                     "lubricant.oil_nu100_mm2_s = 30 with oil_nu40_mm2_s = 30: the viscosity "
                     "at 100 C must be lower than at 40 C");
    expect_set_fails("thermal.max_time_s", "4", ACBB_EINVAL,
                     "fidelity.time_step_s = 5 with thermal.max_time_s = 4: the time step must not "
                     "exceed the time limit");
    expect_set_fails("thermal.temp_limit_C", "26", ACBB_EINVAL,
                     "thermal.temp_limit_C = 26 with operating.ambient_C = 26: the runaway "
                     "limit must be above the ambient temperature");
}

/* Pure-radial guard (MODEL.md section 11): 1.25 * 600 * tan 15 deg = 200.96 N. */
static void test_ill_posed(void)
{
    acbb_scene s;
    acbb_error e = {{0}};
    acbb_scene_default(&s);
    is_close(1.25 * 600 * tan(15 * PI / 180), 200.96, 0, 0.005, "hand: 1.25 Fr tan a0 = 200.96 N");
    expect_set_ok(&s, "operating.radial_load_N", "600");
    acbb_scene before = s;
    acbb_status rc = acbb_scene_set(&s, "operating.axial_load_N", "50", &e);
    ok(rc == ACBB_ILL_POSED, "axial 50 N with radial 600 N is ACBB_ILL_POSED (got %s)",
       acbb_status_name(rc));
    const char *want = "operating.radial_load_N = 600 with axial_load_N = 50: a single "
                       "angular-contact bearing needs axial_load_N >= 201 N (1.25 Fr tan(alpha0)) "
                       "or mounting.preload = displacement";
    if (!ok(strcmp(e.msg, want) == 0, "ill-posed message says what to change"))
        printf("#   got \"%s\"\n", e.msg);
    ok(memcmp(&s, &before, sizeof s) == 0, "scene restored after the ill-posed set");
    expect_set_ok(&s, "operating.axial_load_N", "201");
    expect_set_ok(&s, "mounting.preload", "displacement");
    expect_set_ok(&s, "operating.axial_load_N", "0");
    /* A moment: 1.25 (600 tan 15 deg + 2 * 50 / 0.054) = 201 + 2315 = 2516 N. */
    acbb_scene_default(&s);
    expect_set_ok(&s, "operating.radial_load_N", "600");
    expect_set_ok(&s, "operating.axial_load_N", "2500");
    rc = acbb_scene_set(&s, "operating.moment_load_Nm", "-50", &e);
    ok(rc == ACBB_ILL_POSED, "moment -50 N m with 2500 N of thrust is ACBB_ILL_POSED (got %s)",
       acbb_status_name(rc));
    want = "operating.moment_load_Nm = -50 with axial_load_N = 2500, radial_load_N = 600: a "
           "single angular-contact bearing needs axial_load_N >= 2516 N (1.25 (Fr tan(alpha0) "
           "+ 2 |M| / pitch diameter)) or mounting.preload = displacement";
    if (!ok(strcmp(e.msg, want) == 0, "moment ill-posed message names the thrust it needs"))
        printf("#   got \"%s\"\n", e.msg);
    expect_set_ok(&s, "operating.moment_load_Nm", "-40"); /* needs 2053 N */
    expect_set_ok(&s, "mounting.preload", "displacement");
    expect_set_ok(&s, "operating.axial_load_N", "0");
}

/* Rules on a Scene built in code, not parsed. */
static void test_validate_direct(void)
{
    acbb_scene s;
    acbb_error e = {{0}};
    acbb_scene_default(&s);
    s.inner_speed = 100000.0 * 2.0 * PI / 60.0;
    ok(acbb_scene_validate(&s, &e) == ACBB_OK, "inclusive upper bound in SI passes");
    s.ball.nu = 0.5;
    ok(acbb_scene_validate(&s, &e) == ACBB_EINVAL &&
       strcmp(e.msg, "materials.ball_poisson = 0.5: must be > 0 and < 0.5") == 0,
       "validate checks ranges: %s", e.msg);
    acbb_scene_default(&s);
    s.pitch_diameter = NAN;
    ok(acbb_scene_validate(&s, &e) == ACBB_EINVAL &&
       strcmp(e.msg, "bearing.pitch_diameter_mm = nan: must be a finite number") == 0,
       "validate rejects NaN: %s", e.msg);
    acbb_scene_default(&s);
    s.model = (acbb_model_level)9;
    ok(acbb_scene_validate(&s, &e) == ACBB_EINVAL &&
       strcmp(e.msg, "fidelity.model = 9: not a valid choice") == 0,
       "validate rejects a bad enum: %s", e.msg);
}

/* ---- load errors ---- */

static void test_load_errors(void)
{
    char path[512], want[600];
    acbb_scene s;
    acbb_error e = {{0}};

    tmp_path("missing.ini", path, sizeof path);
    ok(acbb_scene_load(path, &s, &e) == ACBB_EIO, "missing file is ACBB_EIO");
    snprintf(want, sizeof want, "%s: cannot open: No such file or directory", path);
    ok(strcmp(e.msg, want) == 0, "missing file message: %s", e.msg);

    ok(acbb_scene_load(g_dir, &s, &e) == ACBB_EIO, "a directory is ACBB_EIO");
    snprintf(want, sizeof want, "%s: cannot read: a directory, not a regular file (a preset "
             "must be a file)", g_dir);
    ok(strcmp(e.msg, want) == 0, "directory message: %s", e.msg);

    expect_load_fails("empty.ini", "", ACBB_EINVAL, ": empty preset (no keys)");
    expect_load_fails("comments.ini", "; nothing\n[bearing]\n\n# here\n", ACBB_EINVAL,
                      ": empty preset (no keys)");
    expect_load_fails("malformed.ini", "[bearing]\nball_diameter_mm 6.35\n", ACBB_EINVAL,
                      ":2: malformed line (expected key = value or [section])");
    expect_load_fails("bracket.ini", "; x\n[bearing\nball_diameter_mm = 6\n", ACBB_EINVAL,
                      ":2: malformed line (expected key = value or [section])");
    expect_load_fails("typo.ini", "[bearing]\nball_diamter_mm = 6\n", ACBB_EINVAL,
                      ":2: bearing.ball_diamter_mm: unknown key (did you mean "
                      "bearing.ball_diameter_mm?)");
    expect_load_fails("section.ini", "[operatin]\ninner_speed_rpm = 5\n", ACBB_EINVAL,
                      ":2: operatin.inner_speed_rpm: unknown section [operatin] (did you mean "
                      "operating.inner_speed_rpm?)");
    expect_load_fails("nosection.ini", "ball_diameter_mm = 6\n", ACBB_EINVAL,
                      ":1: ball_diameter_mm: key outside any [section] (did you mean "
                      "bearing.ball_diameter_mm?)");
    expect_load_fails("line12.ini",
                      ";1\n;2\n;3\n;4\n;5\n;6\n;7\n;8\n;9\n[bearing]\npitch_diameter_mm = 54\n"
                      "ball_diameter_mm = -3\n",
                      ACBB_EINVAL, ":12: bearing.ball_diameter_mm = -3: must be > 0 mm");
    expect_load_fails("speed.ini", "[operating]\ninner_speed_rpm = 1e9   ; too fast\n",
                      ACBB_EINVAL,
                      ":2: operating.inner_speed_rpm = 1e9: must be between 0 and 100000 rpm");
    expect_load_fails("junk.ini", "[operating]\naxial_load_N = 12abc\n", ACBB_EINVAL,
                      ":2: operating.axial_load_N = 12abc: not a number (unexpected \"abc\" "
                      "after 12)");
    expect_load_fails("twice.ini",
                      "[operating]\naxial_load_N = 500\n[bearing]\n[operating]\naxial_load_N = 600\n",
                      ACBB_EINVAL, ":5: operating.axial_load_N: set twice (first at line 2)");
    char longline[400];
    memset(longline, 'x', sizeof longline);
    memcpy(longline, "[bearing]\n; ", 12);
    memcpy(longline + 250, "\nn_balls = 20\n", 15);
    expect_load_fails("long.ini", longline, ACBB_EINVAL,
                      ":2: line too long (at most 197 characters)");
    /* The first error in the file is reported, whichever kind it is. */
    expect_load_fails("first1.ini", "[bearing]\nnonsense\nn_balls = 2\n", ACBB_EINVAL,
                      ":2: malformed line (expected key = value or [section])");
    expect_load_fails("first2.ini", "[bearing]\nn_balls = 2\nnonsense\n", ACBB_EINVAL,
                      ":2: bearing.n_balls = 2: must be >= 3");
    expect_load_fails("cross.ini", "[bearing]\nn_balls = 30\n", ACBB_EINVAL,
                      ": bearing.n_balls = 30 with ball_diameter_mm = 6.35, pitch_diameter_mm = "
                      "54: the balls do not fit on the pitch circle (n_balls * ball_diameter = "
                      "190.5 mm > 0.98 pi pitch_diameter = 166.3 mm)");
    expect_load_fails("radial.ini", "[operating]\nradial_load_N = 600\naxial_load_N = 50\n",
                      ACBB_ILL_POSED,
                      ": operating.radial_load_N = 600 with axial_load_N = 50: a single "
                      "angular-contact bearing needs axial_load_N >= 201 N (1.25 Fr tan(alpha0)) "
                      "or mounting.preload = displacement");
}

static void test_load_syntax(void)
{
    char path[512];
    acbb_scene s;
    acbb_error e = {{0}};
    /* Indented keys after a key are keys (not continuations), inline
     * comments are stripped, CRLF line ends and a missing final newline work. */
    tmp_path("syntax.ini", path, sizeof path);
    write_text(path, "\xEF\xBB\xBF; BOM first\r\n[operating]\r\naxial_load_N = 500 ; half\r\n"
                     "    radial_load_N = 10\r\n  [effects]\r\n\tloss_drag = off\r\n"
                     "[fidelity]\r\nmodel = static");
    acbb_status rc = acbb_scene_load(path, &s, &e);
    ok(rc == ACBB_OK, "syntax variants load%s%s", rc ? ": " : "", rc ? e.msg : "");
    ok(s.axial_load == 500.0 && s.radial_load == 10.0 && !s.loss_drag &&
       s.model == ACBB_MODEL_STATIC, "values read through the syntax variants");
    ok(s.ball_diameter == 6.35e-3 && s.loss_spin, "unlisted keys keep their defaults");
}

/* ---- saving ---- */

static void test_save_failures(void)
{
    char path[512], want[700], sub[300];
    acbb_scene s;
    acbb_error e = {{0}};
    acbb_scene_default(&s);

    tmp_path("no-such-dir/x.ini", path, sizeof path);
    ok(acbb_scene_save(path, &s, &e) == ACBB_EIO, "save into a missing directory is ACBB_EIO");
    snprintf(want, sizeof want, "cannot write %s: cannot create a temporary file beside it: "
             "No such file or directory", path);
    ok(strcmp(e.msg, want) == 0, "missing directory message: %s", e.msg);

    /* A target that cannot be replaced (a directory) is refused before any
     * temp file is made. Works as root too, unlike a read-only directory. */
    tmp_path("savefail", sub, sizeof sub);
    mkdir(sub, 0755);
    snprintf(path, sizeof path, "%s/target.ini", sub);
    mkdir(path, 0755);
    ok(acbb_scene_save(path, &s, &e) == ACBB_EIO, "save over a directory is ACBB_EIO");
    snprintf(want, sizeof want, "cannot write %s: it is a directory", path);
    ok(strcmp(e.msg, want) == 0, "directory target message: %s", e.msg);
    ok(count_temp_files(sub) == 0, "no temp file left after a failed save");
    struct stat st = { 0 };
    ok(stat(path, &st) == 0 && S_ISDIR(st.st_mode), "the target is left as it was");
    rmdir(path);

    /* Read-only directory, when not root (root ignores the permission). */
    snprintf(path, sizeof path, "%s/ro.ini", sub);
    chmod(sub, 0555);
    if (geteuid() != 0) {
        ok(acbb_scene_save(path, &s, &e) == ACBB_EIO, "save into a read-only directory fails");
        ok(count_temp_files(sub) == 0 && access(path, F_OK) != 0,
           "nothing written into the read-only directory");
    }
    chmod(sub, 0755);

    /* An invalid scene is not saved, and the old file stays. */
    snprintf(path, sizeof path, "%s/keep.ini", sub);
    write_text(path, "[operating]\naxial_load_N = 700\n");
    s.n_balls = 2;
    ok(acbb_scene_save(path, &s, &e) == ACBB_EINVAL, "an invalid scene is not saved");
    snprintf(want, sizeof want, "%s: not saved: bearing.n_balls = 2: must be >= 3",
             path);
    ok(strcmp(e.msg, want) == 0, "invalid scene message: %s", e.msg);
    char *t = read_text(path);
    ok(t && strcmp(t, "[operating]\naxial_load_N = 700\n") == 0, "old file untouched");
    free(t);
    unlink(path);
    rmdir(sub);
}

static void test_save_replaces(void)
{
    char path[512];
    acbb_scene s, back;
    acbb_error e = {{0}};
    tmp_path("replace.ini", path, sizeof path);
    write_text(path, "old contents that are not a preset\n");
    chmod(path, 0640);
    acbb_scene_default(&s);
    expect_set_ok(&s, "operating.axial_load_N", "432.1");
    ok(acbb_scene_save(path, &s, &e) == ACBB_OK, "save over an existing file");
    ok(acbb_scene_load(path, &back, &e) == ACBB_OK && back.axial_load == 432.1,
       "the file now holds the new scene");
    struct stat st = { 0 };
    ok(stat(path, &st) == 0 && (st.st_mode & 07777) == 0640, "file mode kept (0%o)",
       (unsigned)(st.st_mode & 07777));
    ok(count_temp_files(g_dir) == 0, "no temp file left after a good save");
    unlink(path);
}

/* Remove the files the tests wrote, then the directory. */
static void cleanup(void)
{
    DIR *d = opendir(g_dir);
    if (!d) return;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        char p[600];
        if (e->d_name[0] == '.') continue;
        snprintf(p, sizeof p, "%s/%s", g_dir, e->d_name);
        unlink(p);
    }
    closedir(d);
    if (rmdir(g_dir) != 0) printf("# left %s (%s)\n", g_dir, strerror(errno));
}

/* A batch of edits is judged as a whole: the order does not matter, an
 * edit's own error names it, and a failed batch leaves the scene alone. */
static void test_apply_edits(void)
{
    acbb_scene s, before;
    acbb_scene_default(&s);
    s.radial_load = 600;
    s.axial_load = 1000;
    before = s;
    acbb_error err = { "" };
    const char *batch[] = { "operating.axial_load_N=150", "operating.radial_load_N=0" };
    ok(acbb_scene_set(&s, "operating.axial_load_N", "150", &err) == ACBB_ILL_POSED,
       "one edit at a time: axial 150 N with 600 N radial is refused");
    ok(acbb_scene_apply_edits(&s, batch, 2, &err) == ACBB_OK && s.axial_load == 150
           && s.radial_load == 0,
       "the same edits as a batch pass, in either order (%s)", err.msg);
    s = before;
    const char *bad[] = { "operating.radial_load_N=0", "bearing.ball_diameter_mm=-3" };
    ok(acbb_scene_apply_edits(&s, bad, 2, &err) == ACBB_EINVAL, "a bad edit fails the batch");
    ok(strcmp(err.msg, "bearing.ball_diameter_mm=-3: bearing.ball_diameter_mm = -3: "
                       "must be > 0 mm") == 0, "message names the edit: %s", err.msg);
    ok(s.radial_load == 600, "scene unchanged after a failed batch");
    const char *cross[] = { "operating.axial_load_N=50" };
    ok(acbb_scene_apply_edits(&s, cross, 1, &err) == ACBB_ILL_POSED,
       "cross-field rules still run on the result");
    const char *noeq[] = { "operating.axial_load_N" };
    ok(acbb_scene_apply_edits(&s, noeq, 1, &err) == ACBB_EINVAL
           && strcmp(err.msg, "operating.axial_load_N: expected section.key=value") == 0,
       "an edit without '=' is refused: %s", err.msg);
}

/* Issue 30, sixth round: the rules' range test of a value in SI units
 * (acbb_sf_out_of_range_si) judges every field's ends as the reason text
 * of a row scaled to SI did (scene_rules.c before): at each end and one
 * step either side of it, open ends and closed. */
static int si_agrees(const acbb_sfield *f, double v)
{
    acbb_sfield scaled = *f;
    char why[160];
    scaled.info.min *= f->scale;
    scaled.info.max *= f->scale;
    acbb_sf_range_reason(&scaled, v, why, sizeof why);
    return acbb_sf_out_of_range_si(f, v) == (why[0] != '\0');
}

static void test_range_si(void)
{
    int agree = 1, n = 0, outside = 0;
    for (size_t i = 0; i < acbb_sf_n; i++) {
        const acbb_sfield *f = &acbb_sf_table[i];
        if (f->info.type != ACBB_FIELD_REAL && f->info.type != ACBB_FIELD_INT) continue;
        double ends[2] = { f->info.min * f->scale, f->info.max * f->scale };
        for (int e = 0; e < 2; e++)
            for (int d = -1; d <= 1; d++) {
                double v = d < 0 ? nextafter(ends[e], -INFINITY)
                         : d > 0 ? nextafter(ends[e], INFINITY) : ends[e];
                agree = agree && si_agrees(f, v);
                outside += acbb_sf_out_of_range_si(f, v);
                n++;
            }
    }
    ok(agree && outside > n / 4, "range test in SI: %d values at and beside every field's ends "
       "judged as the scaled row's reason (%d outside)", n, outside);
}

int main(void)
{
    snprintf(g_dir, sizeof g_dir, "%s/acbb-scene-XXXXXX",
             getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    if (!mkdtemp(g_dir)) {
        perror("mkdtemp");
        return 2;
    }
    test_key_list_and_defaults();
    test_defaults_in_si();
    test_introspection();
    test_presets();
    test_round_trip();
    test_range_rules();
    test_range_si();
    test_set_keys();
    test_cross_rules();
    test_ill_posed();
    test_validate_direct();
    test_load_errors();
    test_load_syntax();
    test_save_failures();
    test_save_replaces();
    test_apply_edits();
    test_file_syntax_attack();
    test_non_regular();
    test_value_attack();
    test_intervals();
    test_save_edits();
    cleanup();
    return done_testing();
}

/* ---- findings of the outside attack ("Nothing lost, nothing overwritten") ---- */

static void write_bytes(const char *path, const char *bytes, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) { perror(path); exit(2); }
    fwrite(bytes, 1, n, f);
    fclose(f);
}

/* No byte below 0x20, no DEL, no UTF-8 C1 control: safe to print. */
static int printable(const char *msg)
{
    for (const unsigned char *p = (const unsigned char *)msg; *p; p++)
        if (*p < 0x20 || *p == 0x7f || (p[0] == 0xc2 && p[1] >= 0x80 && p[1] <= 0x9f)) return 0;
    return 1;
}

static void expect_bytes_fail(const char *name, const char *bytes, size_t n, const char *suffix)
{
    char path[512], want[1024];
    acbb_scene s;
    acbb_error e = {{0}};
    tmp_path(name, path, sizeof path);
    write_bytes(path, bytes, n);
    acbb_status rc = acbb_scene_load(path, &s, &e);
    snprintf(want, sizeof want, "%s%s", path, suffix);
    ok(rc == ACBB_EINVAL && strcmp(e.msg, want) == 0, "load %s refused", name);
    if (strcmp(e.msg, want) != 0) printf("#   got  \"%s\"\n#   want \"%s\"\n", e.msg, want);
}

static void test_file_syntax_attack(void)
{
    /* Text after a header used to be dropped: the run used 1000 N. */
    expect_load_fails("hdr.ini", "[operating] axial_load_N = 5000\n[bearing]\nn_balls = 20\n",
                      ACBB_EINVAL, ":1: text after the section header [operating]: "
                      "\"axial_load_N = 5000\" (put each key on a line of its own)");
    expect_load_fails("hdrcr.ini", "[operating]\raxial_load_N = 5000\n[bearing]\nn_balls = 20\n",
                      ACBB_EINVAL, ":1: text after the section header [operating]: "
                      "\"axial_load_N = 5000\" (put each key on a line of its own)");
    char path[512];
    acbb_scene s;
    acbb_error e = {{0}};
    tmp_path("hdrok.ini", path, sizeof path);
    write_text(path, "[operating] ; the test point\r\n[effects]  # x\naxial_load_N = 7\n"
                     "[operating]\t\r\naxial_load_N = 500\n");
    acbb_status rc = acbb_scene_load(path, &s, &e);
    ok(rc == ACBB_EINVAL && strstr(e.msg, "effects.axial_load_N: unknown key"),
       "a comment after a header is fine; the key belongs to [effects]: %s", e.msg);
    write_text(path, "[operating] ; the test point\r\naxial_load_N = 500\n");
    ok(acbb_scene_load(path, &s, &e) == ACBB_OK && s.axial_load == 500.0,
       "header with a trailing comment and CRLF loads");

    /* \v and \f are blanks to inih: such a line was a continuation. */
    expect_load_fails("vt.ini", "[operating]\naxial_load_N = 500\n\vradial_load_N = 10\n",
                      ACBB_EINVAL, ":3: control character \\x0b in the line (a preset is plain "
                      "text; only spaces and tabs as blanks)");
    expect_load_fails("ff.ini", "[operating]\naxial_load_N = 500\n\fradial_load_N = 10\n",
                      ACBB_EINVAL, ":3: control character \\x0c in the line (a preset is plain "
                      "text; only spaces and tabs as blanks)");
    expect_load_fails("esc.ini", "; \x1b]0;owned\x07\n[operating]\naxial_load_N = 5\n",
                      ACBB_EINVAL, ":1: control character \\x1b in the line (a preset is plain "
                      "text; only spaces and tabs as blanks)");
    /* A NUL cut the value: "50\0" "00" was read as 50. */
    static const char nul[] = "[operating]\naxial_load_N = 50\0" "00\nradial_load_N = 0\n";
    expect_bytes_fail("nul.ini", nul, sizeof nul - 1, ":2: NUL byte in line 2 (a preset is plain "
                      "text)");
    static const char nul_end[] = "[operating]\naxial_load_N = 50\0";
    expect_bytes_fail("nulend.ini", nul_end, sizeof nul_end - 1,
                      ":2: NUL byte in line 2 (a preset is plain text)");
}

static void test_non_regular(void)
{
    char path[512], want[700];
    acbb_scene s;
    acbb_error e = {{0}};
    tmp_path("fifo.ini", path, sizeof path);
    if (mkfifo(path, 0600) != 0) {
        skip(strerror(errno), "a FIFO is refused at once");
    } else {
        /* Before the fix open() blocked for ever; the alarm turns that
         * into a failed test run instead of a hang (not a timing check). */
        alarm(60);
        acbb_status rc = acbb_scene_load(path, &s, &e);
        alarm(0);
        snprintf(want, sizeof want, "%s: cannot read: a FIFO, not a regular file (a preset must "
                 "be a file)", path);
        ok(rc == ACBB_EIO && strcmp(e.msg, want) == 0, "a FIFO is refused: %s", e.msg);
        unlink(path);
    }
    acbb_status rc = acbb_scene_load("/dev/null", &s, &e);
    ok(rc == ACBB_EIO && strcmp(e.msg, "/dev/null: cannot read: a device, not a regular file "
                                "(a preset must be a file)") == 0,
       "a device is refused: %s", e.msg);
}

static void test_value_attack(void)
{
    expect_set_fails("operating.axial_load_N", "0x10", ACBB_EINVAL,
                     "operating.axial_load_N = 0x10: decimal numbers only (hexadecimal like "
                     "0x10 is not accepted)");
    expect_set_fails("bearing.n_balls", "0X15", ACBB_EINVAL,
                     "bearing.n_balls = 0X15: decimal numbers only (hexadecimal like 0x10 is "
                     "not accepted)");
    expect_set_fails("operating.moment_load_Nm", "-0x1p3", ACBB_EINVAL,
                     "operating.moment_load_Nm = -0x1p3: decimal numbers only (hexadecimal like "
                     "0x10 is not accepted)");
    expect_load_fails("preload0.ini", "[mounting]\npreload = displacement\npreload_N = 0\n",
                      ACBB_EINVAL, ": mounting.preload = displacement with preload_N = 0: a "
                      "displacement preload is set by the force that makes it; preload_N must "
                      "be > 0 N (or use preload = force)");
    /* Quoted text is escaped: a value, a key, a section from a file. */
    expect_set_fails("operating.axial_load_N", "5\x1b[2J", ACBB_EINVAL,
                     "operating.axial_load_N = 5\\x1b[2J: not a number (unexpected "
                     "\"\\x1b[2J\" after 5)");
    acbb_scene s;
    acbb_error e = {{0}};
    acbb_scene_default(&s);
    ok(acbb_scene_set(&s, "bearing.x\x1b]0;t\x07", "1", &e) == ACBB_EINVAL && printable(e.msg)
           && strstr(e.msg, "bearing.x\\x1b]0;t\\x07: unknown key"),
       "a key with control characters is shown escaped: %s", e.msg);
    const char *edits[] = { "operating.axial_load_N=\x9b" "2J", "x\x1b=1" };
    ok(acbb_scene_apply_edits(&s, edits + 1, 1, &e) == ACBB_EINVAL && printable(e.msg),
       "--set text is shown escaped: %s", e.msg);
    ok(acbb_scene_apply_edits(&s, edits, 1, &e) == ACBB_EINVAL && strstr(e.msg, "\\x9b") == NULL
           && strstr(e.msg, "\x9b") != NULL,
       "a lone 0x9b byte (not a UTF-8 C1 control) is passed on: %s", e.msg);
    char path[512];
    tmp_path("c1.ini", path, sizeof path);
    write_text(path, "[bearing]\nball\xc2\x9b = 6\n");
    ok(acbb_scene_load(path, &s, &e) == ACBB_EINVAL && printable(e.msg)
           && strstr(e.msg, ":2: bearing.ball\\xc2\\x9b: unknown key"),
       "a C1 control in a file's key is shown escaped: %s", e.msg);
}

static void expect_interval(const char *key, const char *want)
{
    char buf[160];
    acbb_scene_field_interval((size_t)field_index(key), buf, sizeof buf);
    ok(strcmp(buf, want) == 0, "interval of %s is %s (got %s)", key, want, buf);
}

static void test_intervals(void)
{
    expect_interval("bearing.ball_diameter_mm", "(0, 100] mm");
    expect_interval("bearing.n_balls", "[3, 64]");
    expect_interval("materials.ball_poisson", "(0, 0.5)");
    expect_interval("bearing.roughness_race_um", "[0, 10] um");
    expect_interval("effects.loss_drag", "on | off");
    expect_interval("fidelity.hertz", "exact | bh77 | hb83");
    /* The brackets are the check: each end is accepted iff it is closed. */
    int wrong = 0, open_ends = 0;
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        const acbb_field_info *in = acbb_scene_field(i);
        if (in->type != ACBB_FIELD_REAL && in->type != ACBB_FIELD_INT) continue;
        char key[128], v[40];
        snprintf(key, sizeof key, "%s.%s", in->section, in->key);
        for (int end = 0; end < 2; end++) {
            acbb_scene s;
            acbb_error e;
            acbb_scene_default(&s);
            bool open = end ? in->max_open : in->min_open;
            snprintf(v, sizeof v, "%.17g", end ? in->max : in->min);
            bool accepted = acbb_scene_set_value(&s, key, v, &e) == ACBB_OK;
            open_ends += open;
            if (accepted == open) {
                printf("#   %s = %s: accepted %d, bracket says open %d\n", key, v, accepted, open);
                wrong++;
            }
        }
    }
    ok(wrong == 0 && open_ends > 10, "every range end: accepted exactly when the bracket is "
       "closed (%d open ends)", open_ends);
}

/* ---- saving into the user's file ---- */

/* A hand-written preset: 21 lines, comments, odd spellings, a ':'. */
static const char k_hand[] =
    "; My spindle bearing, hand-tuned\n"
    "; (c) test bench 3\n"
    "\n"
    "[bearing]\n"
    "# geometry from the drawing\n"
    "pitch_diameter_mm = 54\n"
    "ball_diameter_mm  =  6.35   ; measured\n"
    "n_balls: 21\n"
    "\n"
    "[operating]\n"
    "; the test point\n"
    "inner_speed_rpm = 1.5e4 ; 15k\n"
    "axial_load_N = 1000   ; N, hydraulic\n"
    "ambient_C = 26\n"
    "\n"
    "[effects]\n"
    "loss_drag = yes\n"
    "centrifugal = on\n"
    "\n"
    "[fidelity]\n"
    "model = quasi-dynamic\n";

/* Lines that differ between two texts (-1: different line counts); the
 * differing lines are printed. */
static int line_diffs(const char *a, const char *b)
{
    int diffs = 0, la = 0, lb = 0;
    while (*a || *b) {
        size_t na = strcspn(a, "\n"), nb = strcspn(b, "\n");
        la += *a != '\0';
        lb += *b != '\0';
        if (na != nb || memcmp(a, b, na) != 0) {
            printf("#   - %.*s\n#   + %.*s\n", (int)na, a, (int)nb, b);
            diffs++;
        }
        a += na + (a[na] == '\n');
        b += nb + (b[nb] == '\n');
    }
    return la == lb ? diffs : -1;
}

/* Write `old`, load it, apply `edit` (section.key=value), save_edits; the
 * file must then read `want` exactly. */
static void expect_edit(const char *name, const char *old, const char *edit, const char *want)
{
    char path[512];
    acbb_scene s;
    acbb_error e = {{0}};
    tmp_path(name, path, sizeof path);
    write_text(path, old);
    acbb_scene_default(&s);
    acbb_status rc = acbb_scene_load(path, &s, &e);
    if (rc == ACBB_OK) rc = acbb_scene_apply_edits(&s, &edit, 1, &e);
    if (rc == ACBB_OK) rc = acbb_scene_save_edits(path, &s, &e);
    char *got = read_text(path);
    ok(rc == ACBB_OK && got && strcmp(got, want) == 0, "save_edits %s: %s%s%s", name, edit,
       rc ? ": " : "", rc ? e.msg : "");
    if (got && strcmp(got, want) != 0) printf("#   got:\n%s#   want:\n%s", got, want);
    free(got);
}

static void test_save_edits_lines(void)
{
    char path[512];
    acbb_scene s, back;
    acbb_error e = {{0}};
    tmp_path("hand.ini", path, sizeof path);
    write_text(path, k_hand);
    ok(acbb_scene_load(path, &s, &e) == ACBB_OK, "the hand-written preset loads");
    ok(acbb_scene_save_edits(path, &s, &e) == ACBB_OK, "save_edits of the unchanged scene");
    char *t = read_text(path);
    ok(t && strcmp(t, k_hand) == 0, "unchanged scene: the file is byte for byte the same "
       "(1.5e4, yes, ':' kept)");
    free(t);
    expect_set_ok(&s, "operating.axial_load_N", "1500");
    ok(acbb_scene_save_edits(path, &s, &e) == ACBB_OK, "save_edits with one value changed");
    t = read_text(path);
    ok(t && line_diffs(k_hand, t) == 1, "exactly one line of 21 differs");
    ok(t && strstr(t, "\naxial_load_N = 1500   ; N, hydraulic\n") != NULL,
       "the changed line keeps its inline comment and spacing");
    ok(t && strstr(t, "; My spindle bearing, hand-tuned\n; (c) test bench 3\n\n[bearing]\n"
                      "# geometry from the drawing\n") == t, "comments intact");
    free(t);
    ok(acbb_scene_load(path, &back, &e) == ACBB_OK && count_differences(&s, &back, "edit") == 0,
       "the edited file loads back as the saved scene");
}

static void test_save_edits_new_keys(void)
{
    expect_edit("newkey.ini", "[operating]\n; load\naxial_load_N = 1000\n\n[effects]\nloss_drag = on\n",
                "operating.radial_load_N=50",
                "[operating]\n; load\naxial_load_N = 1000\nradial_load_N = 50\n\n[effects]\n"
                "loss_drag = on\n");
    expect_edit("newsec.ini", "[operating]\naxial_load_N = 1000\n", "mounting.preload_N=400",
                "[operating]\naxial_load_N = 1000\n\n[mounting]\npreload_N = 400\n");
    expect_edit("header.ini", "[effects]\n; nothing here yet\n[operating]\naxial_load_N = 900\n",
                "effects.loss_cage=on",
                "[effects]\nloss_cage = on\n; nothing here yet\n[operating]\naxial_load_N = 900\n");
    expect_edit("crlf.ini", "[operating]\r\naxial_load_N = 1000\r\n", "operating.radial_load_N=10",
                "[operating]\r\naxial_load_N = 1000\r\nradial_load_N = 10\r\n");
    expect_edit("crlf2.ini", "[operating]\r\naxial_load_N = 1000 ; x\r\n",
                "operating.axial_load_N=700", "[operating]\r\naxial_load_N = 700 ; x\r\n");
    expect_edit("noeol.ini", "[operating]\naxial_load_N = 1000", "operating.radial_load_N=10",
                "[operating]\naxial_load_N = 1000\nradial_load_N = 10\n");
    expect_edit("twice.ini", "[operating]\naxial_load_N = 1000\n[bearing]\nn_balls = 21\n"
                "[operating]\nambient_C = 26\n; end\n", "operating.radial_load_N=10",
                "[operating]\naxial_load_N = 1000\n[bearing]\nn_balls = 21\n[operating]\n"
                "ambient_C = 26\nradial_load_N = 10\n; end\n");
    /* Back to the default: the line stays, with the default value. */
    expect_edit("default.ini", "[effects]\nloss_cage = on\n", "effects.loss_cage=off",
                "[effects]\nloss_cage = off\n");
}

static void test_save_edits_files(void)
{
    char path[512], real[512], sub[300], want[1400];
    acbb_scene s, back;
    acbb_error e = {{0}};
    tmp_path("edits", sub, sizeof sub);
    mkdir(sub, 0755);
    acbb_scene_default(&s);
    expect_set_ok(&s, "operating.axial_load_N", "1500");

    /* A symlinked preset stays a link; its target is updated. */
    snprintf(real, sizeof real, "%s/real.ini", sub);
    snprintf(path, sizeof path, "%s/link.ini", sub);
    write_text(real, k_hand);
    ok(symlink("real.ini", path) == 0, "symlink made");
    ok(acbb_scene_save_edits(path, &s, &e) == ACBB_OK, "save_edits through a symlink");
    struct stat st = { 0 };
    char target[64] = "";
    ssize_t n = readlink(path, target, sizeof target - 1);
    if (n > 0) target[n] = '\0';
    ok(lstat(path, &st) == 0 && S_ISLNK(st.st_mode) && strcmp(target, "real.ini") == 0,
       "the link is still a link to real.ini");
    ok(acbb_scene_load(real, &back, &e) == ACBB_OK && back.axial_load == 1500.0,
       "the link's target holds the new value");
    ok(acbb_scene_save(path, &s, &e) == ACBB_OK && lstat(path, &st) == 0 && S_ISLNK(st.st_mode),
       "the full save keeps the link too");
    unlink(path);

    /* The mode of the file is kept (read-only for the group and others). */
    chmod(real, 0604);
    expect_set_ok(&s, "operating.axial_load_N", "1400");
    ok(acbb_scene_save_edits(real, &s, &e) == ACBB_OK && stat(real, &st) == 0
           && (st.st_mode & 07777) == 0604, "mode 0604 kept (0%o)", (unsigned)(st.st_mode & 07777));

    /* No file yet: the whole preset, as acbb_scene_save writes it. */
    snprintf(path, sizeof path, "%s/new.ini", sub);
    ok(acbb_scene_save_edits(path, &s, &e) == ACBB_OK, "save_edits creates a new file");
    ok(acbb_scene_save(real, &s, &e) == ACBB_OK, "full save for comparison");
    char *a = read_text(path), *b = read_text(real);
    ok(a && b && strcmp(a, b) == 0, "a new file holds the full preset");
    free(a);
    free(b);
    unlink(path);

    /* An old file that is not a preset is not touched. */
    write_text(real, "[operating]\naxial_lod_N = 5\n");
    ok(acbb_scene_save_edits(real, &s, &e) == ACBB_EINVAL, "an unreadable old file: not saved");
    snprintf(want, sizeof want, "%s: not saved: %s:2: operating.axial_lod_N: unknown key (did "
             "you mean operating.axial_load_N?) (the file is kept as it is; fix that line or "
             "save under another name)", real, real);
    ok(strcmp(e.msg, want) == 0, "message names the line: %s", e.msg);
    a = read_text(real);
    ok(a && strcmp(a, "[operating]\naxial_lod_N = 5\n") == 0, "old file untouched");
    free(a);
    /* The old file's cross-field rules do not matter: only the new scene's. */
    write_text(real, "[bearing]\nn_balls = 30\n");
    ok(acbb_scene_save_edits(real, &s, &e) == ACBB_OK, "an old file that breaks a rule is "
       "fixed by the save: %s", e.msg);
    a = read_text(real);
    ok(a && strcmp(a, "[bearing]\nn_balls = 21\n\n[operating]\naxial_load_N = 1400\n") == 0,
       "n_balls rewritten, the changed key appended in a new section");
    free(a);
    s.n_balls = 2;
    ok(acbb_scene_save_edits(real, &s, &e) == ACBB_EINVAL, "an invalid scene is not saved");
    ok(count_temp_files(sub) == 0, "no temp file left in the directory");
    unlink(real);
    rmdir(sub);
}

static void test_save_edits(void)
{
    test_save_edits_lines();
    test_save_edits_new_keys();
    test_save_edits_files();
}
