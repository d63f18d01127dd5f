/* The spindle's outputs (issue 31) from a view filled by hand
 * (include/acbb/spindle.h), before any engine fills one:
 * - the run JSON's `spindle` object: the names scripts rely on
 *   (spindle.nose_drift_um, spindle.nose_stiffness_N_per_um,
 *   spindle.sets[].preload_N) with the unit conversions done by hand, the
 *   arrays as long as the view says, a NaN written as null and counted;
 * - every `acbb metrics` row of the spindle equals the JSON at its path,
 *   and has no value (refused, null) for a scene that is not a spindle;
 * - the document validates against docs/schema/acbb.schema.json with
 *   python3-jsonschema (tests/schema_check.py), and the schema refuses it
 *   without spindle.nose_drift_um or with a key it does not describe;
 * - the text block of `acbb run`: the numbers, at most 80 columns a line,
 *   nothing of it for another scene; `acbb run --csv`'s spindle columns.
 * Run from the repository root (meson's workdir). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include "acbb/tools/json.h"
#include "acbb/outputs.h"
#include "acbb/scene.h"
#include "acbb/tools/sensitivity.h"
#include "json_path.h"
#include "output.h"
#include "tap.h"

#define SCHEMA "docs/schema/acbb.schema.json"

/* A spindle's view with numbers whose conversions are easy to check:
 * front DB pair at 45 mm, rear single bearing at 330 mm. */
static void fill(acbb_snapshot *s)
{
    memset(s, 0, sizeof *s);
    s->n_balls = 1;
    s->n_bearings = 2;
    acbb_spindle_view *v = &s->spindle;
    v->n_sets = 2;
    v->nose_drift_axial = 12.5e-6;     /* m -> 12.5 um */
    v->nose_drift_radial = 1.25e-6;
    v->nose_u = 0.75e-6;
    v->nose_w = 2.5e-6;
    v->nose_theta = 1.5e-5;            /* rad -> 15 urad */
    v->nose_k_axial = 150e6;           /* N/m -> 150 N/um */
    v->nose_k_radial = 45e6;           /* N/m -> 45 N/um */
    v->nose_k_tilt = 2500.0;           /* N m/rad -> 2.5 N m/mrad */
    v->Q_motor_W = 400.0;
    v->Q_bearings_W = 120.0;
    v->Q_coolant_W = 430.0;
    v->Q_air_W = 90.0;
    v->T_coolant_in_C = 20.0;
    v->T_coolant_out_C = 23.5;
    v->rear_shift = 4.5e-6;
    const double x[2] = { 0.045, 0.330 }, pre[2] = { 300.0, 150.0 };
    const int nb[2] = { 2, 1 };
    for (int k = 0; k < 2; k++) {
        acbb_spindle_set_view *t = &v->sets[k];
        t->x = x[k];
        t->n_bearings = nb[k];
        t->preload_N = pre[k];
        t->axial_N = 250.0 - 100.0 * k;
        t->radial_N = 600.0 - 400.0 * k;
        t->moment_Nm = 12.25;
        t->loss_W = 80.0 - 40.0 * k;
        t->T_inner_C = 41.0;
        t->T_outer_C = 35.5;
        t->T_ball_C = 42.0;
        for (int b = 0; b < nb[k]; b++) {
            t->contact_angle_inner_deg[b] = 15.5 + b;
            t->contact_angle_outer_deg[b] = 14.5 + b;
            t->Q_max_N[b] = 90.0 + 10.0 * b;
        }
        t->contact_lost = k == 1;
    }
    v->n_shaft = 5;
    v->n_housing = 3;
    for (int i = 0; i < 5; i++) {
        v->shaft_x[i] = 0.01 + 0.08 * i;
        v->shaft_T_C[i] = 30.0 + i;
    }
    for (int i = 0; i < 3; i++) {
        v->housing_x[i] = 0.05 + 0.1 * i;
        v->housing_T_C[i] = 25.0 + i;
    }
}

/* The run document of s (json) or `acbb run`'s summary of it as text
 * (malloc'd), with a default scene; *nonfinite: the writer's count. */
static char *capture(const acbb_snapshot *s, int json, long *nonfinite)
{
    acbb_scene sc;
    acbb_scene_default(&sc);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    acbb_json j;
    acbb_json_init(&j, f);
    acbb_cli_out o;
    acbb_cli_out_init(&o, f);
    if (json) acbb_json_write_run(&j, &sc, s);
    else acbb_cli_print_summary(&o, "spindle.ini", &sc, s);
    fclose(f);
    *nonfinite = json ? j.nonfinite : o.nonfinite;
    return buf;
}

static double num_at(const cJSON *root, const char *path)
{
    const cJSON *n = json_path(root, path);
    return cJSON_IsNumber(n) ? n->valuedouble : NAN;
}

static void names_and_units(const cJSON *root)
{
    is_close(num_at(root, "spindle.nose_drift_um"), 12.5, 1e-12, 0, "spindle.nose_drift_um: 12.5e-6 m is 12.5 um");
    is_close(num_at(root, "spindle.nose_stiffness_N_per_um"), 45.0, 1e-12, 0,
             "spindle.nose_stiffness_N_per_um: the radial 45e6 N/m is 45 N/um");
    is_close(num_at(root, "spindle.nose_axial_stiffness_N_per_um"), 150.0, 1e-12, 0,
             "spindle.nose_axial_stiffness_N_per_um: 150 N/um");
    is_close(num_at(root, "spindle.nose_tilt_stiffness_Nm_per_mrad"), 2.5, 1e-12, 0,
             "spindle.nose_tilt_stiffness_Nm_per_mrad: 2500 N m/rad is 2.5 N m/mrad");
    is_close(num_at(root, "spindle.nose_tilt_urad"), 15.0, 1e-12, 0, "nose_tilt_urad: 1.5e-5 rad is 15 urad");
    is_close(num_at(root, "spindle.nose_displacement_um.radial"), 2.5, 1e-12, 0,
             "nose_displacement_um.radial 2.5 um");
    is_close(num_at(root, "spindle.rear_shift_um"), 4.5, 1e-12, 0, "rear_shift_um 4.5 um");
    is_close(num_at(root, "spindle.heat_W.coolant"), 430.0, 0, 0, "heat_W.coolant 430 W");
    is_close(num_at(root, "spindle.coolant_C.outlet"), 23.5, 0, 0, "coolant_C.outlet 23.5 C");
    is_close(num_at(root, "spindle.sets[0].preload_N"), 300.0, 0, 0, "spindle.sets[0].preload_N 300 N");
    is_close(num_at(root, "spindle.sets[1].preload_N"), 150.0, 0, 0, "spindle.sets[1].preload_N 150 N");
    is_close(num_at(root, "spindle.sets[1].x_mm"), 330.0, 1e-12, 0, "the rear set at 330 mm");
    const cJSON *s0 = json_path(root, "spindle.sets[0]"), *s1 = json_path(root, "spindle.sets[1]");
    const cJSON *p0 = cJSON_GetObjectItem(s0, "position"), *p1 = cJSON_GetObjectItem(s1, "position");
    ok(cJSON_IsString(p0) && !strcmp(p0->valuestring, "front") && cJSON_IsString(p1) &&
       !strcmp(p1->valuestring, "rear"), "sets[0] is the front set, sets[1] the rear");
    ok(cJSON_GetArraySize(cJSON_GetObjectItem(s0, "Q_max_N")) == 2 &&
       cJSON_GetArraySize(cJSON_GetObjectItem(s1, "contact_angle_inner_deg")) == 1,
       "a set's arrays have one number per bearing (2 front, 1 rear)");
    is_close(num_at(root, "spindle.sets[0].contact_angle_inner_deg[1]"), 16.5, 0, 0,
             "front bearing 1's inner contact angle 16.5 deg");
    ok(cJSON_IsFalse(cJSON_GetObjectItem(s0, "contact_lost")) &&
       cJSON_IsTrue(cJSON_GetObjectItem(s1, "contact_lost")), "contact_lost is a boolean per set");
    ok(cJSON_GetArraySize(json_path(root, "spindle.shaft.T_C")) == 5 &&
       cJSON_GetArraySize(json_path(root, "spindle.housing.x_mm")) == 3,
       "shaft and housing profiles have n_shaft (5) and n_housing (3) cells");
    is_close(num_at(root, "spindle.shaft.x_mm[4]"), 330.0, 1e-12, 0, "shaft cell 4 at 330 mm");
}

/* Every spindle metric equals the JSON at its path (the same double). */
static void metrics_equal_json(const cJSON *root, const acbb_snapshot *s)
{
    acbb_output e;
    size_t n = 0, bad = 0;
    for (size_t i = 0; acbb_output_get(i, &e); i++) {
        if (!e.row->section || strncmp(e.row->section, "spindle", 7) != 0) continue;
        char path[96];
        acbb_output_path(&e, "0", path, sizeof path);
        double v = NAN;
        int got = acbb_metric_value(s, path, &v, NULL) == ACBB_OK;
        n++;
        if (!got || v != num_at(root, path)) {
            bad++;
            printf("# %s: metric %.17g, json %.17g\n", path, v, num_at(root, path));
        }
    }
    ok(bad == 0 && n == 31, "the %zu spindle metrics (31 planned) equal the JSON at their paths", n);
    acbb_error err = { { 0 } };
    ok(acbb_output_find("spindle.sets[1].preload_N", &e, &(long){ 0 }, &err) == ACBB_OK &&
       !strcmp(e.unit, "N"), "spindle.sets[1].preload_N is a metric in N");
}

/* Validate the file against the schema; 0 when it conforms, 77: no jsonschema. */
static int schema_check(const char *file)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "python3 tests/schema_check.py " SCHEMA " '%s' 2>/dev/null", file);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fputs(text, f);
    return fclose(f) == 0;
}

/* The document, one with its drift removed and one with a key too many. */
static void schema(const char *text, const cJSON *root)
{
    char dir[] = "/tmp/acbb-spindle-out.XXXXXX", file[96];
    if (!mkdtemp(dir)) {
        ok(0, "a temporary directory");
        return;
    }
    snprintf(file, sizeof file, "%s/run.json", dir);
    int rc = write_file(file, text) ? schema_check(file) : -1;
    if (rc == 77) {
        skip("no python3 jsonschema", "the spindle document validates against the schema");
    } else {
        ok(rc == 0, "the spindle run document validates against " SCHEMA " (rc %d)", rc);
        cJSON *c = cJSON_Duplicate(root, 1);
        cJSON_DeleteItemFromObject(cJSON_GetObjectItem(c, "spindle"), "nose_drift_um");
        char *t = cJSON_PrintUnformatted(c);
        ok(write_file(file, t) && schema_check(file) == 1,
           "the schema refuses a spindle without nose_drift_um (it is required)");
        free(t);
        cJSON_Delete(c);
        c = cJSON_Duplicate(root, 1);
        cJSON *sets = cJSON_GetObjectItem(cJSON_GetObjectItem(c, "spindle"), "sets");
        cJSON_AddNumberToObject(cJSON_GetArrayItem(sets, 0), "preload_kN", 0.3);
        t = cJSON_PrintUnformatted(c);
        ok(write_file(file, t) && schema_check(file) == 1,
           "the schema refuses a key it does not describe (sets[0].preload_kN)");
        free(t);
        cJSON_Delete(c);
    }
    remove(file);
    rmdir(dir);
}

static void document(void)
{
    static acbb_snapshot s;
    fill(&s);
    long nonfinite = -1;
    char *text = capture(&s, 1, &nonfinite);
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    ok(root && nonfinite == 0, "the run JSON of a filled spindle view parses, no non-finite number");
    if (root) {
        names_and_units(root);
        metrics_equal_json(root, &s);
        schema(text, root);
    }
    cJSON_Delete(root);
    free(text);
    /* The writer's guard: a NaN is null, counted. */
    s.spindle.nose_k_radial = NAN;
    s.spindle.sets[0].Q_max_N[1] = INFINITY;
    text = capture(&s, 1, &nonfinite);
    root = text ? cJSON_Parse(text) : NULL;
    ok(root && cJSON_IsNull(json_path(root, "spindle.nose_stiffness_N_per_um")) &&
       cJSON_IsNull(json_path(root, "spindle.sets[0].Q_max_N[1]")) && nonfinite == 2,
       "a NaN and an Inf in the view are null in the JSON and counted (%ld)", nonfinite);
    cJSON_Delete(root);
    free(text);
}

/* A scene that is not a spindle: no `spindle` object, its metrics refused. */
static void not_a_spindle(void)
{
    static acbb_snapshot s;
    memset(&s, 0, sizeof s);
    long nonfinite;
    char *text = capture(&s, 1, &nonfinite);
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    ok(root && !cJSON_GetObjectItem(root, "spindle"), "n_sets = 0: the run JSON has no spindle object");
    cJSON_Delete(root);
    free(text);
    acbb_error err = { { 0 } };
    double v = 0.0;
    ok(acbb_metric_value(&s, "spindle.nose_drift_um", &v, &err) == ACBB_EINVAL &&
           strstr(err.msg, "not a spindle"),
       "the metric spindle.nose_drift_um of another scene has no value: %s", err.msg);
    acbb_output e;
    long k;
    ok(acbb_output_find("spindle.sets[0].preload_N", &e, &k, NULL) == ACBB_OK &&
       acbb_output_missing(&e, &s) != NULL, "... and is missing (null in sweep records), not 0");
}

static size_t widest_line(const char *t)
{
    size_t w = 0;
    while (t && *t) {
        size_t n = strcspn(t, "\n");
        if (n > w) w = n;
        t += n + (t[n] == '\n');
    }
    return w;
}

static void text_block(void)
{
    static acbb_snapshot s;
    fill(&s);
    long nonfinite;
    char *t = capture(&s, 0, &nonfinite);
    const char *b = t ? strstr(t, "\nspindle ") : NULL;
    ok(b != NULL, "the summary has a spindle block");
    has_substr(b, "front set at 45.0 mm (2 bearings), rear at 330.0 mm (1 bearing)",
               "it says where the sets sit");
    has_substr(b, "nose drift   axial 12.5 um, radial 1.25 um; rear shift 4.5 um",
               "the nose drift and the rear shift in um");
    has_substr(b, "nose stiff   radial 45 N/um, axial 150 N/um, tilt 2.5 N m/mrad",
               "the nose stiffness, radial first");
    has_substr(b, "heat W       motor 400, bearings 120; to coolant 430, to air 90",
               "the heat split");
    has_substr(b, "coolant C    inlet 20, outlet 23.5", "the coolant's inlet and outlet");
    has_substr(b, "along x      shaft 30.0..34.0 C (hottest at 330 mm), housing 25.0..27.0 C",
               "the span of the shaft's and the housing's temperatures, where the shaft is hottest");
    has_substr(b, "front     300.0    250.0     600.0      12.25   80.00", "the front set's row");
    has_substr(b, "a bearing of the rear set has lifted off", "a set that lifted off is named");
    size_t w = widest_line(b);
    ok(w <= 80 && nonfinite == 0, "the block's widest line is %zu columns (<= 80)", w);
    for (const char *l = b ? b + 1 : NULL; l && *l;) { /* the block, as TAP comments */
        size_t n = strcspn(l, "\n");
        printf("# %.*s\n", (int)n, l);
        l += n + (l[n] == '\n');
    }
    free(t);
    s.spindle.nose_k_axial = s.spindle.nose_k_radial = s.spindle.nose_k_tilt = 0.0;
    t = capture(&s, 0, &nonfinite);
    has_substr(t, "nose stiff   not computed", "no stiffness yet: `not computed`, not 0 N/um");
    free(t);
    memset(&s, 0, sizeof s);
    t = capture(&s, 0, &nonfinite);
    ok(t && !strstr(t, "nose drift") && !strstr(t, "\nspindle"),
       "another scene's summary has no spindle block");
    free(t);
}

/* `acbb run --csv`'s spindle columns: after the set's, the table's paths,
 * one number each in a row. */
static void csv(void)
{
    static acbb_snapshot s;
    fill(&s);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    static acbb_cli_out o;
    acbb_cli_out_init(&o, f);
    o.set_n = 2;
    o.spindle = true;
    acbb_cli_csv_header(&o);
    acbb_cli_csv_row(&o, &s);
    fclose(f);
    const char *want = ",set.preload_N,bearings[0].temperature_C.outer_ring,"
                       "bearings[1].temperature_C.outer_ring,spindle.nose_drift_um,"
                       "spindle.nose_radial_drift_um,spindle.rear_shift_um,"
                       "spindle.sets[0].preload_N,spindle.sets[1].preload_N,"
                       "spindle.sets[0].T_outer_C,spindle.sets[1].T_outer_C,"
                       "spindle.coolant_C.outlet\n";
    char *nl = buf ? strchr(buf, '\n') : NULL;
    size_t wl = strlen(want);
    ok(nl && (size_t)(nl + 1 - buf) >= wl && !strncmp(nl + 1 - wl, want, wl),
       "the run CSV's header ends with the set's and then the spindle's columns");
    size_t ch = 0, cr = 0;
    for (const char *p = buf; p && p < nl; p++) ch += *p == ',';
    for (const char *p = nl ? nl + 1 : NULL; p && *p; p++) cr += *p == ',';
    has_substr(nl, ",12.5,1.25,4.5,300,150,35.5,35.5,23.5\n",
               "its row ends with the drift (um), the preloads, outer rings and the coolant outlet");
    ok(ch == cr && ch > 40 && o.nonfinite == 0, "as many fields in the row as in the header (%zu)", ch + 1);
    free(buf);
}

int main(void)
{
    document();
    not_a_spindle();
    text_block();
    csv();
    return done_testing();
}
