/* The output table (include/acbb/outputs.h).
 *
 * Round trip against the real CLI: for 7008C and combined-load (balls
 * differ under the radial load), `acbb run PRESET --json` is read with
 * cJSON and every table entry's path is walked through that JSON as text
 * ("ring.delta_x_um", "balls[3].losses_W.spin"); the number there equals
 * acbb_metric_value of the same path on a direct run of the same preset
 * (both printed as the JSON prints, %.17g). Every plain number of the
 * table's sections in the JSON is an entry (nothing left out).
 * Hand calculations on a made-up snapshot check the conversions; the
 * table's own rules (units and labels non-empty, paths and CSV names
 * unique, each path finds its own entry) close it.
 * $1 = the acbb binary. */
#include <cjson/cJSON.h>
#include <glob.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/outputs.h"
#include "acbb/scene.h"
#include "acbb/tools/sensitivity.h"
#include "acbb/units.h"
#include "json_path.h"
#include "tap.h"

static char *slurp_cmd(const char *cmd)
{
    FILE *p = popen(cmd, "r");
    if (!p) return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n - 1, p)) > 0) {
        n += got;
        if (n + 1 == cap) buf = realloc(buf, cap *= 2);
    }
    pclose(p);
    if (buf) buf[n] = '\0';
    return buf;
}

/* v as the JSON prints it, read back. */
static double as_printed(double v)
{
    char b[64];
    snprintf(b, sizeof b, "%.17g", v);
    return strtod(b, NULL);
}

static int run_direct(const char *preset, acbb_snapshot *snap)
{
    acbb_scene sc;
    acbb_sim *sim = NULL;
    if (acbb_scene_load(preset, &sc, NULL) != ACBB_OK || acbb_sim_create(&sc, NULL, &sim, NULL) != ACBB_OK)
        return 0;
    acbb_sim_drive(sim, &(acbb_run_ctl){ 0 });
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    return 1;
}

static int is_spindle(const acbb_output *e)
{
    return e->row->section && strncmp(e->row->section, "spindle", 7) == 0;
}

/* Every entry (ball entries for balls 0 and `ball`) read by name equals the
 * CLI's JSON number at that path. */
static void round_trip(const cJSON *root, const acbb_snapshot *s, const char *name, int ball)
{
    acbb_output e;
    size_t checked = 0, bad = 0;
    for (size_t i = 0; acbb_output_get(i, &e); i++) {
        int per_ball = e.row->scope == ACBB_OUT_BALL;
        /* A single bearing's JSON has no "set" object (MODEL.md 14), nor
         * another scene's a "spindle" one (its metrics have no value). */
        if (e.row->section && !strcmp(e.row->section, "set") && s->n_bearings < 2) continue;
        if (is_spindle(&e) && s->spindle.n_sets == 0) continue;
        for (int b = 0; b <= (per_ball ? 1 : 0); b++) {
            char k[16], path[96];
            snprintf(k, sizeof k, "%d", b ? ball : 0);
            acbb_output_path(&e, k, path, sizeof path);
            double v = NAN;
            const cJSON *j = json_path(root, path);
            int got = acbb_metric_value(s, path, &v, NULL) == ACBB_OK;
            int same = got && cJSON_IsNumber(j) && isfinite(v) && as_printed(v) == j->valuedouble;
            checked++;
            if (!same) {
                bad++;
                printf("# %s %s: metric %.10g, json %s\n", name, path, v,
                       cJSON_IsNumber(j) ? "a different number" : "missing");
            }
        }
    }
    ok(bad == 0 && checked > 60, "%s: %zu paths (balls 0 and %d) equal `acbb run --json`", name,
       checked, ball);
}

/* Numbers of the table's sections in the JSON (bearing ones, ball 0's), each
 * a metric: the table leaves no scalar of those sections out. */
static size_t leaves(const cJSON *obj, const char *prefix, size_t *unknown)
{
    size_t n = 0;
    const cJSON *c;
    cJSON_ArrayForEach(c, obj) {
        char path[128];
        snprintf(path, sizeof path, "%s.%s", prefix, c->string);
        if (cJSON_IsObject(c)) n += leaves(c, path, unknown);
        if (!cJSON_IsNumber(c)) continue;
        n++;
        if (acbb_metric_check(path, NULL) != ACBB_OK) {
            (*unknown)++;
            printf("# %s is in the JSON but not in the table\n", path);
        }
    }
    return n;
}

static void coverage(const cJSON *root, const char *name)
{
    static const char *const sections[] = { "losses_W", "temperature_C", "expansion_um", "ring",
                                            "squeeze_um", "energy_W", "set",
                                            "life" };
    size_t n = 0, unknown = 0, bearing = 0, per_ball = 0;
    for (size_t i = 0; i < sizeof sections / sizeof sections[0]; i++)
        n += leaves(cJSON_GetObjectItemCaseSensitive(root, sections[i]), sections[i], &unknown);
    n += leaves(json_path(root, "balls[0]"), "balls[0]", &unknown);
    acbb_output e;
    for (size_t i = 0; acbb_output_get(i, &e); i++) {
        if (e.row->scope == ACBB_OUT_BALL) per_ball++;
        else if (is_spindle(&e)) continue; /* test_spindle_out */
        else if (strcmp(e.row->section, "set") || cJSON_GetObjectItemCaseSensitive(root, "set"))
            bearing++; /* a single bearing's JSON has no "set" object */
    }
    ok(unknown == 0 && n == bearing + per_ball,
       "%s: the JSON's %zu scalars of the table's sections are its %zu + %zu entries", name, n,
       bearing, per_ball);
}

static void against_cli(const char *acbb, const char *preset, const char *name, int ball,
                        int balls_differ)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "'%s' run %s --json 2>/dev/null", acbb, preset);
    char *text = slurp_cmd(cmd);
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    static acbb_snapshot s;
    int ran = run_direct(preset, &s);
    const cJSON *st = cJSON_GetObjectItemCaseSensitive(root, "status");
    ok(root && ran && cJSON_IsString(st) && strcmp(st->valuestring, "converged") == 0 &&
       s.state == ACBB_RUN_CONVERGED && s.n_balls > ball,
       "%s: `acbb run --json` and a direct run converged (%d balls)", name, s.n_balls);
    if (root && ran) {
        char p0[32], pk[32];
        snprintf(p0, sizeof p0, "balls[0].Qi_N");
        snprintf(pk, sizeof pk, "balls[%d].Qi_N", ball);
        const cJSON *q0 = json_path(root, p0), *qk = json_path(root, pk);
        if (balls_differ)
            ok(cJSON_IsNumber(q0) && cJSON_IsNumber(qk) && q0->valuedouble != qk->valuedouble,
               "%s: ball %d carries another load than ball 0 (the index matters)", name, ball);
        round_trip(root, &s, name, ball);
        coverage(root, name);
    }
    cJSON_Delete(root);
    free(text);
}

/* Conversions by hand on a made-up snapshot. */
static void by_hand(void)
{
    static acbb_snapshot s;
    memset(&s, 0, sizeof s);
    s.n_balls = 2;
    s.exp_inner = 1.25e-6;
    s.exp_inner_cen = 0.5e-6;
    s.stiffness_tilt = 2500.0;          /* N m/rad = 2.5 N m/mrad */
    s.tilt_y = 2e-4;                    /* rad = 0.2 mrad */
    s.heat_out = 7.5;
    s.balls[1].psi = 90.0 * ACBB_DEG;
    s.balls[1].pmax_o = 1.5e9;
    s.balls[1].a_i = 1e-4;
    s.balls[1].slide_i = 0.125;
    s.balls[1].loss_kind[ACBB_LOSS_SPIN] = 0.75;
    const struct { const char *path; double want; } cases[] = {
        { "expansion_um.inner_ring", 1.75 },  { "expansion_um.inner_thermal", 1.25 },
        { "ring.stiffness_tilt_Nm_per_mrad", 2.5 }, { "ring.tilt_y_mrad", 0.2 },
        { "energy_W.out", 7.5 },              { "balls[1].psi_deg", 90.0 },
        { "balls[1].pmax_o_GPa", 1.5 },       { "balls[1].a_i_mm", 0.1 },
        { "balls[1].slide_i_mps", 0.125 },    { "balls[1].losses_W.spin", 0.75 },
        { "balls[0].losses_W.spin", 0.0 },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double v = NAN;
        acbb_metric_value(&s, cases[i].path, &v, NULL);
        is_close(v, cases[i].want, 1e-12, 1e-15, cases[i].path);
    }
    acbb_output e;
    long k;
    ok(acbb_output_find("balls[0].losses_W.drag", &e, &k, NULL) == ACBB_EINVAL,
       "a bearing-level loss (drag) has no per-ball entry");
    ok(acbb_output_find("balls[1].Qi_N", &e, &k, NULL) == ACBB_OK && k == 1 &&
       isnan(acbb_output_value(&e, &s, 2)), "a ball past n_balls reads as NaN, not a number");
    acbb_error err = {{0}};
    ok(acbb_output_find("balls[64].Qi_N", &e, &k, &err) == ACBB_EINVAL && strstr(err.msg, "0..63"),
       "ball index past ACBB_MAX_BALLS refused: %s", err.msg);
    ok(acbb_output_find("ring.Qi_N", &e, &k, &err) == ACBB_EINVAL && strstr(err.msg, "is unknown")
           && !strstr(err.msg, "acbb metrics"),
       "a ball key in a bearing section is unknown; the engine's message names no CLI command: %s",
       err.msg);
}

/* Every entry has a unit and a label; paths and CSV names are unique; each
 * path finds its own entry; count agrees with the enumeration. */
static void table_rules(void)
{
    enum { CAP = 256 };
    static char paths[CAP][96], flats[CAP][64];
    acbb_output e, f;
    size_t n = 0, no_unit = 0, dup = 0, lost = 0;
    for (; n < CAP && acbb_output_get(n, &e); n++) {
        acbb_output_path(&e, "0", paths[n], sizeof paths[n]);
        acbb_output_flat(&e, flats[n], sizeof flats[n]);
        if (!e.unit || !e.unit[0] || !e.label || !e.label[0]) {
            no_unit++;
            printf("# %s: no unit or label\n", paths[n]);
        }
        for (size_t j = 0; j < n; j++)
            if (strcmp(paths[j], paths[n]) == 0 || strcmp(flats[j], flats[n]) == 0) {
                dup++;
                printf("# %s / %s repeats entry %zu\n", paths[n], flats[n], j);
            }
        long k;
        if (acbb_output_find(paths[n], &f, &k, NULL) != ACBB_OK || f.row != e.row || f.loss != e.loss)
            lost++;
    }
    ok(n > 0 && n == acbb_output_count(), "%zu entries, as acbb_output_count says", n);
    ok(no_unit == 0, "every entry has a unit and a label");
    ok(dup == 0, "paths and CSV/sweep names are unique");
    ok(lost == 0, "every path finds its own entry");
    char name[96];
    size_t m = 0;
    while (acbb_metric_name(m, name, sizeof name)) m++;
    ok(m == n, "acbb_metric_name lists the table (%zu names)", m);
}

/* A failed stiffness probe (issue 30) is a null with a reason in the run
 * JSON, never the 0 the snapshot holds; the others stay numbers. */
static void failed_probe(void)
{
    static acbb_snapshot s;
    memset(&s, 0, sizeof s);
    s.stiffness_radial = 256e6;
    s.stiffness_failed = ACBB_STIFF_AXIAL | ACBB_STIFF_TILT_HELD;
    acbb_scene sc;
    acbb_scene_default(&sc);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    acbb_json j;
    acbb_json_init(&j, f);
    acbb_json_write_run(&j, &sc, &s);
    fclose(f);
    cJSON *doc = cJSON_Parse(buf);
    cJSON *ring = cJSON_GetObjectItem(doc, "ring");
    ok(cJSON_IsNull(cJSON_GetObjectItem(ring, "stiffness_axial_N_per_um"))
           && cJSON_IsNull(cJSON_GetObjectItem(ring, "stiffness_tilt_held_Nm_per_mrad")),
       "failed axial and held-tilt probes are null in \"ring\"");
    cJSON *kr = cJSON_GetObjectItem(ring, "stiffness_radial_N_per_um");
    ok(cJSON_IsNumber(kr) && kr->valuedouble == 256.0, "the radial probe that converged stays a number");
    cJSON *why = cJSON_GetObjectItem(ring, "stiffness_missing");
    ok(cJSON_IsString(why) && strstr(why->valuestring, "did not converge"),
       "\"ring\" says why: %s", cJSON_IsString(why) ? why->valuestring : "(none)");
    ok(j.nonfinite == 0, "a missing probe is not a non-finite number");
    double v = 0.0;
    acbb_error err = { { 0 } };
    ok(acbb_metric_value(&s, "ring.stiffness_axial_N_per_um", &v, &err) == ACBB_EINVAL &&
           strstr(err.msg, "did not converge"),
       "nor a metric's 0: acbb_metric_value refuses it (%s)", err.msg);
    ok(acbb_metric_value(&s, "ring.stiffness_radial_N_per_um", &v, NULL) == ACBB_OK && v == 256.0,
       "the converged probe is a metric value (256 N/um)");
    cJSON_Delete(doc);
    free(buf);
}

int main(int argc, char **argv)
{
    table_rules();
    by_hand();
    failed_probe();
    if (argc < 2) {
        skip("no acbb binary given", "round trip against `acbb run --json`");
        return done_testing();
    }
    against_cli(argv[1], "presets/7008C.ini", "7008C", 3, 0);
    against_cli(argv[1], "presets/combined-load.ini", "combined-load", 3, 1);
    against_cli(argv[1], "presets/pair-rigid-16k.ini", "pair-rigid-16k", 3, 0);
    /* A spindle's metrics too (issue 31), once its presets exist. */
    glob_t g;
    if (glob("presets/spindle-*.ini", 0, NULL, &g) == 0) {
        for (size_t i = 0; i < g.gl_pathc; i++) against_cli(argv[1], g.gl_pathv[i], g.gl_pathv[i], 3, 0);
        globfree(&g);
    } else {
        skip("no presets/spindle-*.ini yet", "a spindle's metrics equal `acbb run --json`");
    }
    return done_testing();
}
