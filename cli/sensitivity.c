/* acbb CLI — `acbb sensitivity PRESET --metric M`: which uncertain input
 * moves a result, and which could flip its sign (include/acbb/tools/sensitivity.h
 * does the work; this file parses, prints and writes). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/tools/measure.h"
#include "acbb/outputs.h"
#include "acbb/tools/plot.h"
#include "acbb/tools/sensitivity.h"
#include "commands.h"
#include "common.h"
#include "output.h"
#include "exit.h"
#include "progress.h"
#include "say.h"

/* The count with an ETA (progress.h). */
static void on_progress(void *ctx, size_t done, size_t total)
{
    acbb_cli_counter_step(ctx, done, total);
}

/* Options into the engine's; 0 or the exit status (message printed). */
/* An old column name (T_outer_ring_C, README "Renamed outputs") is an
 * alias: the outputs name the metric by its path. */
static void canonical_metric(char *metric, size_t cap)
{
    acbb_output e;
    long ball;
    char idx[24];
    if (acbb_output_find(metric, &e, &ball, NULL) != ACBB_OK) return;
    snprintf(idx, sizeof idx, "%ld", ball);
    acbb_output_path(&e, idx, metric, cap); /* fits: the path is no longer than
                                               an alias plus "balls[k]." */
}

static int parse_opts(const acbb_cli_args *a, acbb_sens_opts *o)
{
    const char *m = a->val[CLI_OPT_METRIC], *d = a->val[CLI_OPT_DELTA];
    if (!m) {
        acbb_cli_say("sensitivity: needs --metric M (e.g. losses_W.total, "
                        "balls[0].Qi_N)\n");
        return ACBB_EXIT_INPUT;
    }
    if (strlen(m) >= sizeof o->metric) {
        acbb_cli_say("sensitivity: --metric is too long\n");
        return ACBB_EXIT_INPUT;
    }
    snprintf(o->metric, sizeof o->metric, "%s", m);
    if (d && strcmp(d, "thermal_expansion") != 0) {
        acbb_cli_say("sensitivity: --delta takes thermal_expansion (TE - WTE), "
                        "got '%s'\n", d);
        return ACBB_EXIT_INPUT;
    }
    o->delta_te = d != NULL;
    o->oat = 1;
    long r = 0, jobs = 0;
    int rc = acbb_cli_count(a, CLI_OPT_MORRIS, 0, 0, ACBB_SENS_MORRIS_MAX, &r);
    if (!rc) rc = acbb_cli_count(a, CLI_OPT_JOBS, 0, 1, ACBB_CLI_MAX_JOBS, &jobs);
    o->morris_r = (int)r;
    o->morris_p = 4;
    o->seed = 1;
    o->jobs = (int)jobs;
    o->transient = a->val[CLI_OPT_TRANSIENT] != NULL;
    acbb_error err = {{0}};
    if (!rc && acbb_metric_check(o->metric, &err) != ACBB_OK) {
        acbb_cli_say("sensitivity: %s; `acbb metrics` lists them\n", err.msg);
        rc = ACBB_EXIT_INPUT;
    }
    if (!rc) canonical_metric(o->metric, sizeof o->metric);
    return rc;
}

static const char *metric_title(const acbb_sens_result *r, char *buf, size_t n)
{
    snprintf(buf, n, "%s%s", r->metric, r->delta_te ? " (TE - WTE)" : "");
    return buf;
}

/* The metric as an axis label: its words and unit ("outer ring (seed node
 * 5) temperature (°C)"), not its JSON path (issue 29 item 9). */
static void metric_words(const acbb_sens_result *r, char *buf, size_t n)
{
    static const struct { const char *plain, *printed; } units[] = {
        { "C", "\u00b0C" }, { "um", "\u03bcm" } };
    static const struct { const char *section, *word; } what[] = {
        { "temperature_C", "temperature" }, { "expansion_um", "expansion" },
        { "losses_W", "power loss" } };
    acbb_output o;
    long ball;
    acbb_error err = { { 0 } };
    if (acbb_output_find(r->metric, &o, &ball, &err) != ACBB_OK) {
        metric_title(r, buf, n);
        return;
    }
    const char *unit = o.unit, *word = "";
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (strcmp(unit, units[i].plain) == 0) unit = units[i].printed;
    for (size_t i = 0; i < sizeof what / sizeof what[0]; i++)
        if (o.row->section && strcmp(o.row->section, what[i].section) == 0 &&
            !strstr(o.label, what[i].word))
            word = what[i].word;
    snprintf(buf, n, "%s%s%s%s (%s)", r->delta_te ? "TE - WTE of " : "", o.label,
             word[0] ? " " : "", word, unit);
}

static void print_value(FILE *f, int ok, double v)
{
    if (ok) fprintf(f, " %11.5g", v);
    else fprintf(f, " %11s", "failed");
}

static void print_table(FILE *f, const char *preset, const acbb_sens_result *r)
{
    char t[128];
    fprintf(f, "sensitivity of %s, %s:\n%zu uncertain inputs, one at a time\n",
            metric_title(r, t, sizeof t), preset, r->n);
    if (r->ok0) fprintf(f, "at the scene's values: %.6g\n\n", r->y0);
    else fprintf(f, "at the scene's values: failed (%s)\n\n", r->fail0);
    /* Within 80 columns (issue 21 item 8): the input and its numbers on one
     * line, the plausible range it was moved over under it. */
    fprintf(f, "%-33s %11s %11s %9s\n", "input / plausible range", "at low", "at high", "effect");
    for (size_t i = 0; i < r->n; i++) {
        const acbb_sens_row *w = &r->rows[i];
        fprintf(f, "%-33s", w->in.key);
        print_value(f, w->ok_lo, w->y_lo);
        print_value(f, w->ok_hi, w->y_hi);
        if (w->ok_effect) fprintf(f, " %9.3g%s\n", w->effect, w->flips ? " FLIPS SIGN" : "");
        else fprintf(f, " %9s\n", "-");
        fprintf(f, "  %s..%s\n", w->in.lo, w->in.hi);
    }
    if (!r->morris_r) return;
    fprintf(f, "\nMorris elementary effects: r = %d trajectories on a p = %d grid, "
               "Delta = %.4g, %zu points, seed 1\n", r->morris_r, r->morris_p, r->morris_delta,
            (size_t)r->morris_r * (r->n + 1));
    fprintf(f, "(per whole plausible range; sigma large vs mu*: nonlinear or interacting)\n");
    fprintf(f, "%-33s %11s %11s %11s %5s\n", "input", "mu*", "mu", "sigma", "n");
    size_t order[ACBB_SENS_MAX];
    for (size_t i = 0; i < r->n; i++) order[i] = i;
    for (size_t i = 1; i < r->n; i++)   /* by mu*, largest first (insertion sort) */
        for (size_t j = i; j > 0 && r->rows[order[j]].mu_star > r->rows[order[j - 1]].mu_star; j--) {
            size_t t2 = order[j];
            order[j] = order[j - 1], order[j - 1] = t2;
        }
    for (size_t i = 0; i < r->n; i++) {
        const acbb_sens_row *w = &r->rows[order[i]];
        fprintf(f, "%-33s %11.4g %11.4g %11.4g %5d\n", w->in.key, w->mu_star, w->mu, w->sigma,
                w->n_ee);
    }
}

static void json_number(cJSON *o, const char *k, int ok, double v)
{
    cJSON_AddItemToObject(o, k, acbb_cli_json_number(ok ? v : NAN));
}

static cJSON *result_json(const acbb_sens_result *r)
{
    cJSON *root = cJSON_CreateObject(), *rows = cJSON_CreateArray();
    cJSON_AddNumberToObject(root, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddStringToObject(root, "metric", r->metric);
    if (r->delta_te) cJSON_AddStringToObject(root, "delta", "thermal_expansion");
    else cJSON_AddNullToObject(root, "delta");
    json_number(root, "value", r->ok0, r->y0);
    if (!r->ok0) cJSON_AddStringToObject(root, "failed", r->fail0);
    for (size_t i = 0; i < r->n; i++) {
        const acbb_sens_row *w = &r->rows[i];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "key", w->in.key);
        cJSON_AddStringToObject(o, "base", w->in.base);
        cJSON_AddStringToObject(o, "low", w->in.lo);
        cJSON_AddStringToObject(o, "high", w->in.hi);
        cJSON_AddStringToObject(o, "source", w->in.src);
        json_number(o, "at_low", w->ok_lo, w->y_lo);
        json_number(o, "at_high", w->ok_hi, w->y_hi);
        json_number(o, "effect", w->ok_effect, w->effect);
        cJSON_AddBoolToObject(o, "flips", w->flips);
        if (r->morris_r) {
            json_number(o, "mu_star", w->n_ee > 0, w->mu_star);
            json_number(o, "mu", w->n_ee > 0, w->mu);
            json_number(o, "sigma", w->n_ee > 0, w->sigma);
            cJSON_AddNumberToObject(o, "n_effects", w->n_ee);
        }
        cJSON_AddItemToArray(rows, o);
    }
    cJSON_AddItemToObject(root, "inputs", rows);
    if (r->morris_r) {
        cJSON *m = cJSON_AddObjectToObject(root, "morris");
        cJSON_AddNumberToObject(m, "trajectories", r->morris_r);
        cJSON_AddNumberToObject(m, "levels", r->morris_p);
        cJSON_AddItemToObject(m, "delta", acbb_cli_json_number(r->morris_delta));
        cJSON_AddNumberToObject(m, "points", (double)r->morris_r * (double)(r->n + 1));
        cJSON_AddNumberToObject(m, "seed", 1);
    }
    cJSON_AddNumberToObject(root, "runs", (double)r->runs);
    cJSON_AddNumberToObject(root, "failed_runs", (double)r->failed);
    cJSON_AddItemToObject(root, "wall_ms", acbb_cli_json_number(r->wall_ms));
    return root;
}

static void csv_number(FILE *f, int ok, double v)
{
    if (ok && isfinite(v)) fprintf(f, ",%.17g", v);
    else fputc(',', f);
}

/* Sources hold commas: quoted, a quote doubled (RFC 4180). */
static void csv_text(FILE *f, const char *s)
{
    fputs(",\"", f);
    for (; *s; s++) fprintf(f, *s == '"' ? "\"\"" : "%c", *s);
    fputc('"', f);
}

static void write_csv(FILE *f, const acbb_sens_result *r)
{
    fprintf(f, "metric,delta,key,base,low,high,source,value,at_low,at_high,effect,flips,"
               "mu_star,mu,sigma,n_effects\n");
    for (size_t i = 0; i < r->n; i++) {
        const acbb_sens_row *w = &r->rows[i];
        fprintf(f, "%s,%s,%s,%s,%s,%s", r->metric, r->delta_te ? "thermal_expansion" : "",
                w->in.key, w->in.base, w->in.lo, w->in.hi);
        csv_text(f, w->in.src);
        csv_number(f, r->ok0, r->y0);
        csv_number(f, w->ok_lo, w->y_lo);
        csv_number(f, w->ok_hi, w->y_hi);
        csv_number(f, w->ok_effect, w->effect);
        fprintf(f, ",%d", w->flips);
        csv_number(f, w->n_ee > 0, w->mu_star);
        csv_number(f, w->n_ee > 0, w->mu);
        csv_number(f, w->n_ee > 0, w->sigma);
        fprintf(f, ",%d\n", w->n_ee);
    }
}

static int write_plot(const char *path, const char *preset, const acbb_sens_result *r)
{
    int fmt = acbb_plot_format_from_name(path);
    acbb_tornado_bar bars[ACBB_SENS_MAX];
    for (size_t i = 0; i < r->n; i++)
        bars[i] = (acbb_tornado_bar){r->rows[i].in.key, r->rows[i].ok_lo ? r->rows[i].y_lo : NAN,
                                     r->rows[i].ok_hi ? r->rows[i].y_hi : NAN};
    char t[128], title[320], xlabel[160];
    /* the preset's name, not its path; the metric in words on the axis */
    const char *base = strrchr(preset, '/');
    base = base ? base + 1 : preset;
    int len = (int)strcspn(base, ".");
    metric_title(r, t, sizeof t);
    snprintf(title, sizeof title, "%.*s: each uncertain input over its plausible range", len, base);
    metric_words(r, xlabel, sizeof xlabel);
    /* full width (17.5 cm at 300 dpi: the inputs' names need it); a bar
     * per input, each a text row and a half high at the print text size */
    int w = 2067, h = (int)((7.0 + 1.6 * (double)r->n) * acbb_plot_font_px(w));
    acbb_error err = {{0}};
    acbb_status st = fmt == ACBB_PLOT_PNG || fmt == ACBB_PLOT_SVG
        ? acbb_plot_tornado_file(bars, r->n, r->ok0 ? r->y0 : NAN, (acbb_plot_format)fmt, path,
                                 w, h, title, xlabel, &err)
        : acbb_error_set(&err, ACBB_EINVAL, "--plot %s: use a .png or .svg name", path);
    if (st == ACBB_OK) return 0;
    acbb_cli_say("sensitivity: %s\n", err.msg);
    return st == ACBB_EINVAL ? ACBB_EXIT_INPUT : ACBB_EXIT_INTERNAL;
}

static int write_outputs(const acbb_cli_args *a, const acbb_sens_result *r)
{
    int rc = 0;
    if (a->val[CLI_OPT_JSON]) {
        cJSON *j = result_json(r);
        char *text = j ? cJSON_Print(j) : NULL;
        if (text) printf("%s\n", text);
        else rc = ACBB_EXIT_INTERNAL;
        free(text);
        cJSON_Delete(j);
    } else {
        print_table(stdout, a->preset, r);
    }
    if (a->val[CLI_OPT_CSV]) {
        acbb_cli_file c;
        int frc = acbb_cli_file_open(&c, a->val[CLI_OPT_CSV]);
        if (!frc) write_csv(c.out.f, r), frc = acbb_cli_file_close(&c);
        rc = acbb_cli_worst(rc, frc);
    }
    if (a->val[CLI_OPT_PLOT]) rc = acbb_cli_worst(rc, write_plot(a->val[CLI_OPT_PLOT], a->preset, r));
    return acbb_cli_worst(rc, acbb_cli_stdout_check(0));
}

/* A metric the scene can never have (a spindle's of another scene,
 * acbb_output_missing) is bad input, said before any run: every run would
 * end without a value. */
static int metric_fits(const char *metric, const acbb_scene *sc)
{
    static acbb_snapshot probe; /* no result yet: only the scene's kind */
    acbb_output e;
    long ball;
    memset(&probe, 0, sizeof probe);
    probe.spindle.n_sets = sc->shaft_segments > 0 ? ACBB_SPINDLE_SETS : 0;
    const char *why = acbb_output_find(metric, &e, &ball, NULL) == ACBB_OK
                          ? acbb_output_missing(&e, &probe) : NULL;
    if (!why) return 0;
    acbb_cli_say("sensitivity: metric %s has no value here: %s\n", metric, why);
    return ACBB_EXIT_INPUT;
}

int acbb_cli_cmd_sensitivity(const acbb_cli_args *a)
{
    acbb_scene sc;
    acbb_sens_opts o = {0};
    int rc = parse_opts(a, &o);
    if (!rc) rc = acbb_cli_load_scene(a, &sc);
    if (!rc) rc = metric_fits(o.metric, &sc);
    if (rc) return rc;
    acbb_sens_result *r = malloc(sizeof *r);
    if (!r) return ACBB_EXIT_INTERNAL;
    acbb_cli_counter ps;
    acbb_cli_counter_init(&ps, "sensitivity");
    o.progress = on_progress;
    o.ctx = &ps;
    /* SIGINT / SIGTERM stop the runs within a step (progress.h); a
     * table of some inputs only would read as the whole answer, so a
     * cancelled analysis prints none. */
    o.cancel = acbb_cli_interrupt_begin();
    acbb_error err = {{0}};
    acbb_status st = acbb_sensitivity_run(&sc, &o, r, &err);
    acbb_cli_interrupt_end();
    if (st == ACBB_CANCELLED) {
        if (ps.show) acbb_cli_progress_draw("\n");
        const char *kept = "no table and no file written (they would be partial)";
        if (a->val[CLI_OPT_JSON]) acbb_cli_cancelled_json(stdout, "sensitivity", kept);
        free(r);
        return acbb_cli_worst(acbb_cli_cancelled("sensitivity", kept), acbb_cli_stdout_check(0));
    }
    if (st != ACBB_OK) {
        acbb_cli_say("sensitivity: %s\n", acbb_cli_err_text(&err, st));
        free(r);
        return acbb_cli_exit_for(st);
    }
    rc = write_outputs(a, r);
    if (!r->ok0 || r->failed)
        acbb_cli_say("sensitivity: %zu point(s) without a value (a run did not reach "
                        "steady state)%s%s\n",
                r->failed, r->ok0 ? "" : "; the base run: ", r->ok0 ? "" : r->fail0);
    rc = acbb_cli_worst(rc, r->failed ? ACBB_EXIT_SOLVER : 0);
    free(r);
    return rc;
}
