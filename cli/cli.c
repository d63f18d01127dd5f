/* acbb — headless command-line front end: a thin client of the engine API
 * (include/acbb/sim.h, include/acbb/scene.h). It loads a preset, applies
 * `--set` edits, drives acbb_sim_step to the end of the run (DESIGN.md
 * "Data flow") and writes the snapshot as a table, JSON or CSV.
 *
 * Exit status: 0 converged; 2 bad input or ill-posed scene (the engine's
 * message says what to change); 3 the solver did not reach steady state;
 * 4 internal error (non-finite output, I/O failure on stdout).
 *
 * Arguments are parsed by hand: each subcommand takes a preset and a few
 * options, getopt_long would add little, and no user text ever reaches a
 * shell. The locale is never set, so LC_NUMERIC stays "C" and presets,
 * CSV and JSON always use a decimal point. */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>
#include <gsl/gsl_errno.h>
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/history.h"
#include "output.h"
#include "plot.h"
#include "accuracy.h"
#include "../src/cli_report.h"
#include "tui.h"

enum { EXIT_CONVERGED = 0, EXIT_BADINPUT = 2, EXIT_SOLVER = 3, EXIT_INTERNAL = 4 };

#define CLI_PI 3.14159265358979323846
#define CLI_DEFAULT_PRESET "presets/7008C.ini"

static const char usage_text[] =
    "usage: acbb [COMMAND [ARGS]]\n"
    "\n"
    "commands:\n"
    "  (none) | tui [PRESET]\n"
    "        the terminal workbench, on presets/7008C.ini by default\n"
    "  run PRESET [--set section.key=value]... [--json] [--csv FILE] [--quiet]\n"
    "        [--plot FILE.png|FILE.svg]\n"
    "        run the coupled thermo-mechanical model to thermal steady state\n"
    "  check PRESET [--set section.key=value]...\n"
    "        validate the preset and the edits without running\n"
    "  sweep PRESET --param section.key --values v1,v2,... [--set ...]\n"
    "        [--json] [--csv FILE] [--jobs N]\n"
    "        one run per value of the parameter\n"
    "  study PRESET [--set ...] [--csv FILE] [--jobs N]\n"
    "        the seed's comparison with (TE) and without (WTE) thermal\n"
    "        expansion: loads 50..1000 N, speeds 2000..16000 rpm\n"
    "  plot PRESET [--set ...] [--kind temperature|losses|loads|angles|\n"
    "        history-loads|all] [--out FILE.png|FILE.svg | --dumb] [--size WxH]\n"
    "        run the scene and plot it through gnuplot\n"
    "  bench speed [PRESET] [--repeat N]\n"
    "        wall time of one run and of the 8-load sweep (median of N)\n"
    "  bench accuracy PRESET [--set ...] [--repeat N] [--knobs k1,..]\n"
    "        [--models m1,..] [--csv FILE] [--plot FILE]\n"
    "        error against the finest setting vs wall time, one knob at a time\n"
    "  report PRESET [--set ...] [--json] [--md FILE]\n"
    "        the seed's conclusions (MODEL.md section 12): held / not held\n"
    "  presets [DIR]   list presets/*.ini with their first comment line\n"
    "  keys            list every scene key with unit, range and help\n"
    "  help            this text (also --help, -h)\n"
    "\n"
    "--set edits use preset units, e.g. --set operating.axial_load_N=200\n"
    "(see `acbb keys`). --jobs defaults to the number of CPUs.\n"
    "\n"
    "exit status: 0 converged, 2 bad input or ill-posed scene,\n"
    "3 solver did not reach steady state, 4 internal error or gnuplot failure\n";

/* ---- arguments ---- */

enum {
    OPT_SET = 1 << 0, OPT_JSON = 1 << 1, OPT_CSV = 1 << 2, OPT_QUIET = 1 << 3,
    OPT_PARAM = 1 << 4, OPT_VALUES = 1 << 5, OPT_REPEAT = 1 << 6, OPT_JOBS = 1 << 7,
    OPT_PLOT = 1 << 8,
};

typedef struct {
    const char *cmd;
    const char *pos[2];          /* positional arguments */
    int n_pos;
    const char **sets;           /* --set texts, in order (point into argv) */
    size_t n_sets;
    bool json, quiet;
    const char *csv, *param, *values, *plot;
    long repeat, jobs;
} cli_args;

static const struct {
    const char *name;
    int flag;
    bool takes_value;
} cli_options[] = {
    { "set", OPT_SET, true },       { "json", OPT_JSON, false },
    { "csv", OPT_CSV, true },       { "quiet", OPT_QUIET, false },
    { "param", OPT_PARAM, true },   { "values", OPT_VALUES, true },
    { "repeat", OPT_REPEAT, true }, { "jobs", OPT_JOBS, true },
    { "plot", OPT_PLOT, true },
};

static int usage_error(const char *cmd, const char *fmt, const char *what)
{
    fprintf(stderr, "acbb: %s: ", cmd);
    fprintf(stderr, fmt, what);
    fputs("\ntry `acbb --help`\n", stderr);
    return EXIT_BADINPUT;
}

static int parse_count(const char *cmd, const char *opt, const char *text, long *out)
{
    char *end = NULL;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (errno || end == text || *end || v < 1 || v > 100000) {
        fprintf(stderr, "acbb: %s: --%s %s: expected a whole number 1..100000\n",
                cmd, opt, text);
        return EXIT_BADINPUT;
    }
    *out = v;
    return 0;
}

static int apply_option(cli_args *a, int flag, const char *name, const char *val)
{
    switch (flag) {
    case OPT_SET: a->sets[a->n_sets++] = val; return 0;
    case OPT_JSON: a->json = true; return 0;
    case OPT_QUIET: a->quiet = true; return 0;
    case OPT_CSV: a->csv = val; return 0;
    case OPT_PARAM: a->param = val; return 0;
    case OPT_VALUES: a->values = val; return 0;
    case OPT_PLOT: a->plot = val; return 0;
    case OPT_REPEAT: return parse_count(a->cmd, name, val, &a->repeat);
    case OPT_JOBS: return parse_count(a->cmd, name, val, &a->jobs);
    }
    return EXIT_INTERNAL;
}

/* One `--name`, `--name value` or `--name=value` at argv[*i]. */
static int parse_option(cli_args *a, int allowed, int argc, char **argv, int *i)
{
    const char *arg = argv[*i] + 2;
    const char *eq = strchr(arg, '=');
    size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
    for (size_t k = 0; k < sizeof cli_options / sizeof cli_options[0]; k++) {
        const char *name = cli_options[k].name;
        if (strlen(name) != len || strncmp(arg, name, len) != 0) continue;
        if (!(allowed & cli_options[k].flag)) break;
        const char *val = NULL;
        if (cli_options[k].takes_value) {
            if (eq) val = eq + 1;
            else if (*i + 1 < argc) val = argv[++*i];
            else return usage_error(a->cmd, "option --%s needs a value", name);
        } else if (eq) {
            return usage_error(a->cmd, "option --%s takes no value", name);
        }
        return apply_option(a, cli_options[k].flag, name, val);
    }
    return usage_error(a->cmd, "unknown option %s", argv[*i]);
}

static int parse_args(cli_args *a, int allowed, int max_pos, int argc, char **argv)
{
    bool options_done = false;
    for (int i = 2; i < argc; i++) {
        const char *arg = argv[i];
        if (!options_done && strcmp(arg, "--") == 0) {
            options_done = true;
        } else if (!options_done && strncmp(arg, "--", 2) == 0) {
            int rc = parse_option(a, allowed, argc, argv, &i);
            if (rc) return rc;
        } else if (!options_done && arg[0] == '-' && arg[1] != '\0') {
            return usage_error(a->cmd, "unknown option %s", arg);
        } else if (a->n_pos < max_pos) {
            a->pos[a->n_pos++] = arg;
        } else {
            return usage_error(a->cmd, "unexpected argument %s", arg);
        }
    }
    return 0;
}

/* ---- scene ---- */

static int exit_for_status(acbb_status st)
{
    switch (st) {
    case ACBB_OK: return EXIT_CONVERGED;
    case ACBB_EINVAL: case ACBB_EIO: case ACBB_ILL_POSED: return EXIT_BADINPUT;
    case ACBB_ENOMEM: return EXIT_INTERNAL;
    default: return EXIT_SOLVER;
    }
}

static const char *err_text(const acbb_error *err, acbb_status st)
{
    return err->msg[0] ? err->msg : acbb_status_name(st);
}

static int load_scene(const char *preset, const cli_args *a, acbb_scene *sc)
{
    acbb_error err = { { 0 } };
    acbb_status st = acbb_scene_load(preset, sc, &err);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: %s\n", err_text(&err, st));
        return exit_for_status(st);
    }
    st = acbb_scene_apply_edits(sc, a->sets, a->n_sets, &err);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: %s\n", err_text(&err, st));
        return exit_for_status(st);
    }
    return 0;
}

/* ---- driving a run ---- */

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e3 * (double)ts.tv_sec + 1e-6 * (double)ts.tv_nsec;
}

typedef void (*row_fn)(void *ctx, const acbb_snapshot *snap);

typedef struct {
    acbb_snapshot *snap;
    row_fn row;
    void *ctx;
} drive_ctx;

static int drive_hook(void *ctx, const acbb_sim *sim)
{
    drive_ctx *d = ctx;
    acbb_sim_snapshot(sim, d->snap);
    d->row(d->ctx, d->snap);
    return 0;
}

/* The engine's run loop to the end of the run, calling `row` for the
 * initial state and after every step. `snap` holds the final state. */
static acbb_status drive(acbb_sim *sim, acbb_snapshot *snap, row_fn row, void *ctx)
{
    drive_ctx d = { snap, row, ctx };
    acbb_run_ctl ctl = { .hook = row ? drive_hook : NULL, .ctx = &d };
    acbb_status st = acbb_sim_drive(sim, &ctl);
    acbb_sim_snapshot(sim, snap);
    return st;
}

static void run_point(acbb_cli_point *p)
{
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    double t0 = now_ms();
    p->status = acbb_sim_new(&p->scene, &sim, &err);
    if (p->status != ACBB_OK) {
        p->have_snap = false;
        snprintf(p->message, sizeof p->message, "%s", err_text(&err, p->status));
        p->wall_ms = now_ms() - t0;
        return;
    }
    p->status = drive(sim, &p->snap, NULL, NULL);
    p->have_snap = true;
    acbb_sim_free(sim);
    p->wall_ms = now_ms() - t0;
}

/* Independent runs in parallel: each Sim is private to one thread and the
 * engine keeps no global mutable state (common rules), so the results do
 * not depend on the number of threads. */
typedef struct {
    acbb_cli_point *pts;
    size_t n;
    atomic_size_t next;
} point_pool;

static void *pool_worker(void *arg)
{
    point_pool *pool = arg;
    for (;;) {
        size_t i = atomic_fetch_add(&pool->next, 1);
        if (i >= pool->n) return NULL;
        run_point(&pool->pts[i]);
    }
}

static long cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? n : 1;
}

static void run_points(acbb_cli_point *pts, size_t n, long jobs)
{
    point_pool pool = { .pts = pts, .n = n };
    atomic_init(&pool.next, 0);
    size_t extra = jobs > 1 ? (size_t)jobs - 1 : 0;
    if (extra > n) extra = n;
    pthread_t tid[64];
    if (extra > 64) extra = 64;
    size_t started = 0;
    for (; started < extra; started++)
        if (pthread_create(&tid[started], NULL, pool_worker, &pool) != 0) break;
    pool_worker(&pool); /* the main thread works too; if no thread started, alone */
    for (size_t i = 0; i < started; i++) pthread_join(tid[i], NULL);
}

static bool points_ok(const acbb_cli_point *pts, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!acbb_cli_point_ok(&pts[i])) return false;
    return true;
}

/* ---- output files ---- */

/* CSV goes to FILE.tmp and is renamed over FILE when complete, so a reader
 * never sees a half-written file. */
typedef struct {
    const char *path;
    char *tmp;
    acbb_cli_out out;
} csv_file;

static int csv_open(csv_file *c, const char *path)
{
    c->path = path;
    FILE *f = acbb_cli_tmp_open(path, &c->tmp);
    if (!f) return EXIT_BADINPUT;
    acbb_cli_out_init(&c->out, f);
    return 0;
}

static int csv_close(csv_file *c)
{
    int rc = 0;
    if (acbb_cli_tmp_commit(c->out.f, c->tmp, c->path) != 0) {
        rc = EXIT_BADINPUT;
    } else if (c->out.nonfinite) {
        fprintf(stderr, "acbb: internal error: %ld non-finite values in %s\n",
                c->out.nonfinite, c->path);
        rc = EXIT_INTERNAL;
    }
    c->tmp = NULL;
    return rc;
}

static int stdout_check(const acbb_cli_out *o)
{
    if (o->nonfinite) {
        fprintf(stderr, "acbb: internal error: %ld non-finite values in the output\n",
                o->nonfinite);
        return EXIT_INTERNAL;
    }
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "acbb: cannot write to stdout\n");
        return EXIT_INTERNAL;
    }
    return 0;
}

static int worst(int a, int b) { return a > b ? a : b; }

/* ---- acbb run ---- */

static void csv_row_cb(void *ctx, const acbb_snapshot *snap)
{
    acbb_cli_csv_row(ctx, snap);
}

/* `run --csv` rows and the `--plot` history (cli_plot.h) from one callback. */
typedef struct {
    acbb_cli_out *csv;
    acbb_history *hist;
} run_rows;

static void run_row_cb(void *ctx, const acbb_snapshot *snap)
{
    run_rows *r = ctx;
    if (r->csv) csv_row_cb(r->csv, snap);
    if (r->hist) acbb_history_push(r->hist, snap);
}

static int run_report(const cli_args *a, const char *preset, const acbb_scene *sc,
                      const acbb_snapshot *snap)
{
    acbb_cli_out o;
    acbb_cli_out_init(&o, stdout);
    if (a->json) acbb_cli_json_run(&o, sc, snap);
    else if (!a->quiet) acbb_cli_print_summary(&o, preset, sc, snap);
    int rc = stdout_check(&o);
    if (snap->state != ACBB_RUN_CONVERGED) {
        fprintf(stderr, "acbb: %s: %s\n", acbb_run_status_name(snap), snap->message);
        rc = worst(rc, EXIT_SOLVER);
    }
    return rc;
}

static int cmd_run(cli_args *a, int argc, char **argv)
{
    int rc = parse_args(a, OPT_SET | OPT_JSON | OPT_CSV | OPT_QUIET | OPT_PLOT, 1, argc, argv);
    if (rc) return rc;
    if (a->n_pos != 1) return usage_error("run", "%s", "missing PRESET");
    const char *preset = a->pos[0];
    if (a->plot && (rc = acbb_cli_plot_check_path(a->plot))) return rc;
    acbb_scene sc;
    if ((rc = load_scene(preset, a, &sc))) return rc;

    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_sim_new(&sc, &sim, &err);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: %s\n", err_text(&err, st));
        if (a->json) {
            acbb_cli_out o;
            acbb_cli_out_init(&o, stdout);
            acbb_cli_json_failed(&o, &sc, acbb_status_name(st), err_text(&err, st));
        }
        return exit_for_status(st);
    }
    csv_file csv = { 0 };
    if (a->csv && (rc = csv_open(&csv, a->csv))) {
        acbb_sim_free(sim);
        return rc;
    }
    if (a->csv) acbb_cli_csv_header(&csv.out);
    acbb_snapshot *snap = malloc(sizeof *snap);
    if (!snap) {
        acbb_sim_free(sim);
        if (a->csv) csv_close(&csv);
        return EXIT_INTERNAL;
    }
    run_rows rows = { a->csv ? &csv.out : NULL, a->plot ? malloc(sizeof *rows.hist) : NULL };
    if (rows.hist) acbb_history_init(rows.hist);
    drive(sim, snap, (a->csv || rows.hist) ? run_row_cb : NULL, &rows);
    acbb_sim_free(sim);
    rc = a->csv ? csv_close(&csv) : 0;
    rc = worst(run_report(a, preset, &sc, snap), rc);
    if (a->plot && !rows.hist) rc = worst(rc, EXIT_INTERNAL);
    if (rows.hist) rc = worst(rc, acbb_cli_write_plot(a->plot, rows.hist, snap, preset));
    free(rows.hist);
    free(snap);
    return rc;
}

/* ---- acbb check ---- */

static int cmd_check(cli_args *a, int argc, char **argv)
{
    int rc = parse_args(a, OPT_SET, 1, argc, argv);
    if (rc) return rc;
    if (a->n_pos != 1) return usage_error("check", "%s", "missing PRESET");
    acbb_scene sc;
    if ((rc = load_scene(a->pos[0], a, &sc))) return rc;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_scene_validate(&sc, &err);
    /* Ill-posedness (MODEL.md 11) is judged when the scene is compiled, so
     * check compiles it too; no thermal step is taken. */
    acbb_sim *sim = NULL;
    if (st == ACBB_OK) st = acbb_sim_new(&sc, &sim, &err);
    acbb_sim_free(sim);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: %s\n", err_text(&err, st));
        return exit_for_status(st);
    }
    printf("%s: ok\n", a->pos[0]);
    return stdout_check(&(acbb_cli_out){ .f = stdout });
}

/* ---- acbb sweep ---- */

/* Split "v1,v2,..." into points, each a copy of `base` with param = value. */
static int sweep_points(const cli_args *a, const acbb_scene *base,
                        acbb_cli_point **out, size_t *n_out)
{
    size_t n = 1;
    for (const char *p = a->values; *p; p++) n += *p == ',';
    acbb_cli_point *pts = calloc(n, sizeof *pts);
    if (!pts) return EXIT_INTERNAL;
    const char *p = a->values;
    for (size_t i = 0; i < n; i++) {
        size_t len = strcspn(p, ",");
        if (len == 0 || len >= sizeof pts[i].value) {
            fprintf(stderr, "acbb: sweep: --values %s: empty or too long value\n",
                    a->values);
            free(pts);
            return EXIT_BADINPUT;
        }
        memcpy(pts[i].value, p, len);
        pts[i].value[len] = '\0';
        p += len + (p[len] == ',');
        pts[i].scene = *base;
        acbb_error err = { { 0 } };
        acbb_status st = acbb_scene_set(&pts[i].scene, a->param, pts[i].value, &err);
        if (st != ACBB_OK) {
            fprintf(stderr, "acbb: --param %s=%s: %s\n", a->param, pts[i].value,
                    err_text(&err, st));
            free(pts);
            return EXIT_BADINPUT;
        }
    }
    *out = pts;
    *n_out = n;
    return 0;
}

static int cmd_sweep(cli_args *a, int argc, char **argv)
{
    int rc = parse_args(a, OPT_SET | OPT_JSON | OPT_CSV | OPT_PARAM | OPT_VALUES |
                        OPT_JOBS, 1, argc, argv);
    if (rc) return rc;
    if (a->n_pos != 1) return usage_error("sweep", "%s", "missing PRESET");
    if (!a->param || !a->values)
        return usage_error("sweep", "%s", "needs --param section.key and --values v1,v2,...");
    acbb_scene base;
    if ((rc = load_scene(a->pos[0], a, &base))) return rc;
    acbb_cli_point *pts = NULL;
    size_t n = 0;
    if ((rc = sweep_points(a, &base, &pts, &n))) return rc;
    run_points(pts, n, a->jobs);

    if (a->csv) {
        csv_file csv = { 0 };
        rc = csv_open(&csv, a->csv);
        if (!rc) {
            acbb_cli_sweep_csv(&csv.out, a->param, pts, n);
            rc = csv_close(&csv);
        }
    }
    acbb_cli_out o;
    acbb_cli_out_init(&o, stdout);
    if (a->json) acbb_cli_sweep_json(&o, a->param, pts, n);
    else acbb_cli_sweep_table(&o, a->param, pts, n);
    rc = worst(rc, stdout_check(&o));
    if (!points_ok(pts, n)) rc = worst(rc, EXIT_SOLVER);
    free(pts);
    return rc;
}

/* ---- acbb study ---- */

static const double study_loads[] = { 50, 100, 150, 200, 400, 600, 800, 1000 };
static const double study_speeds[] = { 2000, 4000, 6000, 8000, 10000, 12000, 14000, 16000 };
#define STUDY_N 8

/* Pair k of the study: TE point 2k and WTE point 2k+1, otherwise equal.
 * The scene is a plain value in SI units, so the study edits it directly. */
static void study_pair(acbb_cli_point *pts, size_t k, const acbb_scene *base,
                       double speed_rpm, double load_N, double x)
{
    for (int m = 0; m < 2; m++) {
        acbb_cli_point *p = &pts[2 * k + (size_t)m];
        p->scene = *base;
        p->scene.inner_speed = speed_rpm * 2.0 * CLI_PI / 60.0;
        p->scene.axial_load = load_N;
        p->scene.thermal_expansion = (m == 0);
        snprintf(p->value, sizeof p->value, "%g", x);
    }
}

static int cmd_study(cli_args *a, int argc, char **argv)
{
    int rc = parse_args(a, OPT_SET | OPT_CSV | OPT_JOBS, 1, argc, argv);
    if (rc) return rc;
    if (a->n_pos != 1) return usage_error("study", "%s", "missing PRESET");
    acbb_scene base;
    if ((rc = load_scene(a->pos[0], a, &base))) return rc;

    double rpm = base.inner_speed * 60.0 / (2.0 * CLI_PI);
    char titles[3][96];
    snprintf(titles[0], sizeof titles[0], "load sweep at %.0f rpm", rpm);
    snprintf(titles[1], sizeof titles[1], "speed sweep at 100 N");
    snprintf(titles[2], sizeof titles[2], "speed sweep at 1000 N");
    const acbb_cli_study_block blocks[3] = {
        { "load", titles[0], "Fx N", 0, STUDY_N },
        { "speed_100N", titles[1], "n rpm", STUDY_N, STUDY_N },
        { "speed_1000N", titles[2], "n rpm", 2 * STUDY_N, STUDY_N },
    };
    size_t n_pairs = 3 * STUDY_N;
    acbb_cli_point *pts = calloc(2 * n_pairs, sizeof *pts);
    if (!pts) return EXIT_INTERNAL;
    for (size_t k = 0; k < STUDY_N; k++) {
        study_pair(pts, k, &base, rpm, study_loads[k], study_loads[k]);
        study_pair(pts, STUDY_N + k, &base, study_speeds[k], 100.0, study_speeds[k]);
        study_pair(pts, 2 * STUDY_N + k, &base, study_speeds[k], 1000.0, study_speeds[k]);
    }
    run_points(pts, 2 * n_pairs, a->jobs);

    if (a->csv) {
        csv_file csv = { 0 };
        rc = csv_open(&csv, a->csv);
        if (!rc) {
            acbb_cli_study_csv(&csv.out, pts, blocks, 3);
            rc = csv_close(&csv);
        }
    }
    acbb_cli_out o;
    acbb_cli_out_init(&o, stdout);
    acbb_cli_study_table(&o, pts, blocks, 3);
    rc = worst(rc, stdout_check(&o));
    if (!points_ok(pts, 2 * n_pairs)) rc = worst(rc, EXIT_SOLVER);
    free(pts);
    return rc;
}

/* ---- acbb bench speed ---- */

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

static double median(double *v, size_t n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Wall time of `n` points run with `jobs` threads, `repeat` times. */
static int bench_points(const acbb_scene *base, const double *loads, size_t n,
                        long jobs, long repeat, double *times, acbb_cli_point *pts)
{
    for (long r = 0; r < repeat; r++) {
        for (size_t i = 0; i < n; i++) {
            memset(&pts[i], 0, sizeof pts[i]);
            pts[i].scene = *base;
            if (loads) pts[i].scene.axial_load = loads[i];
        }
        double t0 = now_ms();
        run_points(pts, n, jobs);
        times[r] = now_ms() - t0;
        if (!points_ok(pts, n)) return EXIT_SOLVER;
    }
    return 0;
}

static int bench_fail(const acbb_cli_point *pts, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (acbb_cli_point_ok(&pts[i])) continue;
        fprintf(stderr, "acbb: bench: run %zu: %s: %s\n", i, acbb_cli_point_status(&pts[i]),
                pts[i].have_snap ? pts[i].snap.message : pts[i].message);
    }
    return EXIT_SOLVER;
}

static int cmd_bench(cli_args *a, int argc, char **argv)
{
    a->repeat = 5;
    int rc = parse_args(a, OPT_REPEAT | OPT_SET, 2, argc, argv);
    if (rc) return rc;
    if (a->n_pos < 1 || strcmp(a->pos[0], "speed") != 0)
        return usage_error("bench", "%s", "expected `acbb bench speed [PRESET]`");
    const char *preset = a->n_pos == 2 ? a->pos[1] : CLI_DEFAULT_PRESET;
    acbb_scene base;
    if ((rc = load_scene(preset, a, &base))) return rc;

    long ncpu = cpu_count();
    struct utsname u;
    const char *machine = uname(&u) == 0 ? u.machine : "unknown";
    double *times = calloc((size_t)a->repeat, sizeof *times);
    acbb_cli_point *pts = calloc(STUDY_N, sizeof *pts);
    if (!times || !pts) {
        free(times);
        free(pts);
        return EXIT_INTERNAL;
    }
    printf("acbb bench speed %s (median of %ld)\n", preset, a->repeat);
    printf("machine            %s, %ld CPUs online (sysconf)\n", machine, ncpu);

    if ((rc = bench_points(&base, NULL, 1, 1, a->repeat, times, pts))) goto fail;
    printf("one run            %10.2f ms  (%ld iterations, %s, model %s)\n",
           median(times, (size_t)a->repeat), pts[0].snap.iteration,
           acbb_cli_point_status(&pts[0]), acbb_model_level_name(base.model));
    if ((rc = bench_points(&base, study_loads, STUDY_N, 1, a->repeat, times, pts)))
        goto fail;
    printf("8-load sweep       %10.2f ms  (1 thread; loads 50..1000 N)\n",
           median(times, (size_t)a->repeat));
    if (ncpu > 1) {
        if ((rc = bench_points(&base, study_loads, STUDY_N, ncpu, a->repeat, times, pts)))
            goto fail;
        printf("8-load sweep       %10.2f ms  (%ld threads)\n",
               median(times, (size_t)a->repeat), ncpu);
    }
    rc = stdout_check(&(acbb_cli_out){ .f = stdout });
    free(times);
    free(pts);
    return rc;
fail:
    rc = bench_fail(pts, STUDY_N);
    free(times);
    free(pts);
    return rc;
}

/* ---- acbb presets / keys ---- */

static int cmp_str(const void *x, const void *y)
{
    return strcmp(*(char *const *)x, *(char *const *)y);
}

/* First line whose first non-blank character is ';' or '#', marker and
 * blanks stripped. */
static void first_comment(const char *path, char *buf, size_t n)
{
    snprintf(buf, n, "(no description)");
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[512];
    while (fgets(line, sizeof line, f)) {
        char *p = line + strspn(line, " \t");
        if (*p != ';' && *p != '#') continue;
        p += strspn(p, ";# \t");
        p[strcspn(p, "\r\n")] = '\0';
        snprintf(buf, n, "%s", p);
        break;
    }
    fclose(f);
}

static int cmd_presets(cli_args *a, int argc, char **argv)
{
    int rc = parse_args(a, 0, 1, argc, argv);
    if (rc) return rc;
    const char *dir = a->n_pos ? a->pos[0] : "presets";
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "acbb: presets: cannot open %s: %s\n", dir, strerror(errno));
        return EXIT_BADINPUT;
    }
    char **names = NULL;
    size_t n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".ini") != 0) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 16;
            char **grown = realloc(names, cap * sizeof *names);
            if (!grown) break;
            names = grown;
        }
        if (!(names[n] = strdup(e->d_name))) break;
        n++;
    }
    closedir(d);
    if (n) qsort(names, n, sizeof *names, cmp_str);
    int width = 0;
    for (size_t i = 0; i < n; i++)
        if ((int)strlen(names[i]) > width) width = (int)strlen(names[i]);
    width += (int)strlen(dir) + 1;
    for (size_t i = 0; i < n; i++) {
        char path[4096], desc[256];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        first_comment(path, desc, sizeof desc);
        printf("%-*s  %s\n", width, path, desc);
        free(names[i]);
    }
    free(names);
    return stdout_check(&(acbb_cli_out){ .f = stdout });
}

static const char *type_name(acbb_field_type t)
{
    switch (t) {
    case ACBB_FIELD_REAL: return "real";
    case ACBB_FIELD_INT: return "integer";
    case ACBB_FIELD_BOOL: return "on|off";
    case ACBB_FIELD_ENUM: return "choice";
    }
    return "?";
}

static void print_key(const acbb_field_info *fi, const char *deflt)
{
    printf("%s.%s = %s\n    ", fi->section, fi->key, deflt);
    if (fi->type == ACBB_FIELD_ENUM && fi->choices) {
        for (size_t c = 0; fi->choices[c]; c++) printf("%s%s", c ? "|" : "", fi->choices[c]);
    } else if (fi->type == ACBB_FIELD_REAL || fi->type == ACBB_FIELD_INT) {
        printf("%s", type_name(fi->type));
        if (fi->unit && fi->unit[0]) printf(" [%s]", fi->unit);
        if (isfinite(fi->max) && fi->max < 1e300) printf(", %g .. %g", fi->min, fi->max);
        else printf(", >= %g", fi->min);
    } else {
        printf("%s", type_name(fi->type));
    }
    printf(": %s\n", fi->help ? fi->help : "");
}

static int cmd_keys(cli_args *a, int argc, char **argv)
{
    int rc = parse_args(a, 0, 0, argc, argv);
    if (rc) return rc;
    acbb_scene sc;
    acbb_scene_default(&sc);
    size_t n = acbb_scene_field_count();
    for (size_t i = 0; i < n; i++) {
        const acbb_field_info *fi = acbb_scene_field(i);
        if (!fi) continue;
        char buf[128];
        acbb_scene_field_format(&sc, i, buf, sizeof buf);
        print_key(fi, buf);
    }
    return stdout_check(&(acbb_cli_out){ .f = stdout });
}

/* ---- main ---- */

static int usage(FILE *f, int rc)
{
    fputs(usage_text, f);
    return rc;
}

static bool is_help(const char *s)
{
    return strcmp(s, "help") == 0 || strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0;
}

int main(int argc, char **argv)
{
    /* The default GSL handler aborts the process (common rules). */
    gsl_set_error_handler_off();
    if (argc < 2 || strcmp(argv[1], "tui") == 0)
        return acbb_tui_main(argc < 2 ? argc : argc - 1, argc < 2 ? argv : argv + 1);
    if (is_help(argv[1])) return usage(stdout, EXIT_CONVERGED);
    for (int i = 2; i < argc; i++)
        if (strcmp(argv[i], "--") == 0) break;
        else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return usage(stdout, EXIT_CONVERGED);

    const char **sets = calloc((size_t)argc, sizeof *sets);
    if (!sets) return EXIT_INTERNAL;
    cli_args a = { .cmd = argv[1], .sets = sets, .jobs = cpu_count(), .repeat = 5 };
    static const struct {
        const char *name;
        int (*fn)(cli_args *, int, char **);
    } cmds[] = {
        { "run", cmd_run },         { "check", cmd_check }, { "sweep", cmd_sweep },
        { "study", cmd_study },     { "bench", cmd_bench }, { "presets", cmd_presets },
        { "keys", cmd_keys },
    };
    if (strcmp(argv[1], "plot") == 0) {
        free(sets);
        return acbb_cli_plot(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "report") == 0) {
        free(sets);
        return acbb_cli_report(argc - 1, argv + 1);
    }
    if (strcmp(argv[1], "bench") == 0 && argc > 2 && strcmp(argv[2], "accuracy") == 0) {
        free(sets);
        return acbb_cli_bench_accuracy(argc - 2, argv + 2);
    }
    int rc = -1;
    for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++)
        if (strcmp(argv[1], cmds[i].name) == 0) rc = cmds[i].fn(&a, argc, argv);
    free(sets);
    if (rc < 0) {
        fprintf(stderr, "acbb: unknown command '%s'\n\n", argv[1]);
        return usage(stderr, EXIT_BADINPUT);
    }
    return rc;
}
