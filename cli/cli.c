/* acbb CLI — the scene commands: run, check, study, bench speed and
 * keys (commands.h). Each loads a preset, applies `--set` edits, drives the
 * engine's one run loop (acbb_sim_drive, DESIGN.md "Data flow") and writes
 * the snapshot as a table, JSON or CSV (output.h). Exit statuses: exit.h. */
#include <math.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <unistd.h>
#include "acbb/batch.h"
#include "acbb/tools/history.h"
#include "acbb/tools/set.h"
#include "acbb/tools/life_eval.h"
#include "acbb/tools/measure.h"
#include "acbb/scene.h"
#include "acbb/tools/fidelity.h"
#include "acbb/sim.h"
#include "acbb/tools/study.h"
#include "acbb/units.h"
#include "acbb/tools/scene_schema.h"
#include "commands.h"
#include "common.h"
#include "exit.h"
#include "output.h"
#include "baseline.h"
#include "plot.h"
#include "presets.h"
#include "figures.h"
#include "progress.h"
#include "branches.h"
#include "say.h"

/* ---- driving a run ---- */

typedef void (*row_fn)(void *ctx, const acbb_snapshot *snap);

/* What a run reports on the way: rows (CSV, plot history) and the
 * progress line, both fed the snapshot after every step; `cancel` is the
 * Ctrl-C flag (progress.h). Every field but snap may be NULL. */
typedef struct {
    acbb_snapshot *snap;
    row_fn row;
    void *ctx;
    acbb_cli_progress *progress;
    const atomic_int *cancel;
} drive_ctx;

static int drive_hook(void *ctx, const acbb_sim *sim)
{
    drive_ctx *d = ctx;
    acbb_sim_snapshot(sim, d->snap);
    if (d->row) d->row(d->ctx, d->snap);
    if (d->progress) acbb_cli_progress_step(d->progress, d->snap);
    return 0;
}

/* The engine's run loop to the end of the run (or a cancel). `d->snap`
 * holds the final state. */
static acbb_status drive(acbb_sim *sim, drive_ctx *d)
{
    bool watch = d->row || (d->progress && d->progress->on);
    acbb_run_ctl ctl = { .hook = watch ? drive_hook : NULL, .ctx = d, .cancel = d->cancel };
    acbb_status st = acbb_sim_drive(sim, &ctl);
    acbb_sim_snapshot(sim, d->snap);
    return st;
}

/* Independent runs on the engine's batch runner (batch.h): results do not
 * depend on the number of workers. Each point runs as its scene says
 * (transient by default): `bench speed` times the scene as given. */
static acbb_status point_scene(void *ctx, size_t i, acbb_scene *out, acbb_batch_mode *mode,
                               acbb_error *err)
{
    (void)err;
    *out = ((const acbb_cli_point *)ctx)[i].scene;
    *mode = ACBB_BATCH_AS_SCENE;
    return ACBB_OK;
}

static void point_done(void *ctx, const acbb_batch_result *r)
{
    acbb_cli_point *p = &((acbb_cli_point *)ctx)[r->index];
    p->status = r->status;
    p->have_snap = r->snap != NULL;
    p->wall_ms = r->wall_ms;
    if (r->snap) p->snap = *r->snap;
    else snprintf(p->message, sizeof p->message, "%s", r->message);
}

/* Returns the number of workers that ran. */
static int run_points(acbb_cli_point *pts, size_t n, long jobs, const atomic_int *cancel)
{
    acbb_batch_opts o = { .jobs = (int)jobs, .cancel = cancel, .scene = point_scene,
                          .done = point_done, .ctx = pts };
    acbb_batch_stats st = { 0 };
    acbb_batch_run(n, &o, &st);
    return st.workers;
}

static bool points_ok(const acbb_cli_point *pts, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!acbb_cli_point_ok(&pts[i])) return false;
    return true;
}

/* ---- acbb run ---- */

static void csv_row_cb(void *ctx, const acbb_snapshot *snap)
{
    acbb_cli_csv_row(ctx, snap);
}

/* `run --csv` rows and the `--plot` history (plot.h) from one callback. */
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

/* A set's bearings, read before the Sim is freed (NULL for one bearing). */
static acbb_snapshot *bearing_snaps(const acbb_sim *sim, const acbb_snapshot *snap)
{
    if (snap->n_bearings < 2) return NULL;
    acbb_snapshot *b = malloc(sizeof *b * (size_t)snap->n_bearings);
    for (int k = 0; b && k < snap->n_bearings; k++) acbb_sim_bearing_snapshot(sim, k, &b[k]);
    return b;
}

static int run_report(const acbb_cli_args *a, const char *preset, const acbb_scene *sc,
                      const acbb_snapshot *snap, const acbb_snapshot *bear,
                      const acbb_branches *br)
{
    acbb_cli_out o;
    acbb_cli_out_init(&o, stdout);
    const char *base = a->val[CLI_OPT_BASELINE];
    bool json = a->val[CLI_OPT_JSON] != NULL;
    int rc = 0;
    acbb_scene shown; /* with a schedule: at its last row */
    acbb_cli_schedule_shown(sc, &shown);
    if (json && !base) acbb_cli_json_run_parts(&o, sc, snap, bear, br);
    else if (!json && !a->val[CLI_OPT_QUIET]) acbb_cli_print_summary(&o, preset, &shown, snap);
    if (!json && !a->val[CLI_OPT_QUIET]) acbb_cli_print_schedule(&o, sc, snap);
    if (!json && !a->val[CLI_OPT_QUIET] && br) acbb_cli_print_branches(&o, br);
    if (base) rc = acbb_cli_baseline(base, sc, snap, json, a->val[CLI_OPT_QUIET] != NULL);
    rc = acbb_cli_worst(rc, acbb_cli_stdout_check(o.nonfinite));
    if (snap->life.edge_loaded && !a->val[CLI_OPT_QUIET]) { /* MODEL.md 15: a named warning */
        char c[32];
        acbb_life_contact_name(snap->life.edge_ball, snap->life.edge_race, c, sizeof c);
        acbb_cli_say("warning: edge loading: the contact ellipse of %s passes its "
                "shoulder by %.2f deg (life.inner_shoulder_mm, life.outer_shoulder_mm)\n", c,
                -snap->life.edge_margin_deg);
    }
    if (snap->life.kappa_clamped && !a->val[CLI_OPT_QUIET]) /* ISO 281 9.3.2: 0.1 <= kappa */
        acbb_cli_say("warning: kappa %.3g is below 0.1, where ISO 281 does not define "
                "a_ISO: a_ISO and L_nmr are taken at kappa 0.1 (life.kappa_clamped)\n",
                snap->life.kappa);
    if (snap->state != ACBB_RUN_CONVERGED) {
        acbb_cli_say("%s: %s\n", acbb_run_status_name(snap), snap->message);
        rc = acbb_cli_worst(rc, ACBB_EXIT_SOLVER);
    }
    return rc;
}

/* Compile the scene (cancellable: a dynamic-level set-up is long); on
 * failure the message, the JSON failure record and the exit status. */
static int start_sim(const acbb_scene *sc, bool json, const atomic_int *cancel,
                     acbb_cli_progress *prog, acbb_sim **sim)
{
    acbb_error err = { { 0 } };
    acbb_cli_progress_note(prog, "setting up the %s model", acbb_model_level_name(sc->model));
    acbb_status st = acbb_sim_create(sc, &(acbb_sim_opts){ .cancel = cancel }, sim, &err);
    acbb_cli_progress_end(prog);
    if (st == ACBB_OK) return 0;
    /* A bound met in the set-up is the run's named ending as one met in a
     * step: "wall_limit: wall-clock bound ... reached ...", as drive's end
     * prints it (test wall_message); other set-up failures are the input's
     * and print their message alone. */
    acbb_cli_say("%s%s%s\n", st == ACBB_WALL_LIMIT ? acbb_status_name(st) : "",
                 st == ACBB_WALL_LIMIT ? ": " : "", acbb_cli_err_text(&err, st));
    if (json) {
        acbb_cli_out o;
        acbb_cli_out_init(&o, stdout);
        acbb_cli_json_failed(&o, sc, acbb_status_name(st), acbb_cli_err_text(&err, st));
    }
    return acbb_cli_exit_for(st);
}

/* Ctrl-C / SIGTERM end the run as `cancelled` with the last good state
 * (progress.h); the output below is written as for any other failure. */
int acbb_cli_cmd_run(const acbb_cli_args *a)
{
    int rc = 0;
    const char *preset = a->preset;
    const char *plot = a->val[CLI_OPT_PLOT], *csv_path = a->val[CLI_OPT_CSV];
    bool json = a->val[CLI_OPT_JSON] != NULL;
    if (plot && (rc = acbb_cli_plot_check_path(plot))) return rc;
    const char *base = a->val[CLI_OPT_BASELINE];
    if (base && (rc = acbb_cli_baseline_check(base))) return rc;
    acbb_scene sc;
    if ((rc = acbb_cli_load_scene(a, &sc))) return rc;
    /* The scene resolved as the Sim will (acbb_scene_resolve): the report,
     * JSON and other branch show the knobs and oil used, and the note
     * says which fidelity entry was chosen, before the run. */
    acbb_fidelity_choice fc;
    if (acbb_scene_resolve(&sc, &sc, &fc) && !a->val[CLI_OPT_QUIET])
        acbb_cli_say("%s\n", fc.note);

    acbb_cli_progress prog;
    acbb_cli_progress_init(&prog, stderr, sc.steady_tol);
    prog.schedule = sc.schedule_n > 0 && sc.heating && sc.thermal_mode == ACBB_THERMAL_TRANSIENT
                    ? &sc : NULL;
    const atomic_int *cancel = acbb_cli_interrupt_begin();
    /* --max-wall bounds the whole command: the other branch gets what the
     * run left (issue 26 item 7). */
    double deadline = sc.max_wall_s > 0.0 ? acbb_now_ms() + 1e3 * sc.max_wall_s : 0.0;
    acbb_sim *sim = NULL;
    rc = start_sim(&sc, json, cancel, &prog, &sim);
    acbb_cli_file csv = { 0 };
    if (!rc && csv_path && (rc = acbb_cli_file_open(&csv, csv_path))) acbb_sim_free(sim);
    acbb_snapshot *snap = rc ? NULL : malloc(sizeof *snap);
    if (!rc && !snap) {
        acbb_sim_free(sim);
        if (csv_path) acbb_out_abort(csv.handle);
        rc = acbb_cli_no_memory("run");
    }
    if (rc) {
        acbb_cli_interrupt_end();
        return rc;
    }
    csv.out.set_n = acbb_set_layout(&sc, NULL, NULL);
    csv.out.spindle = sc.shaft_segments > 0;
    if (csv_path) acbb_cli_csv_header(&csv.out);
    run_rows rows = { csv_path ? &csv.out : NULL, plot ? malloc(sizeof *rows.hist) : NULL };
    if (rows.hist) acbb_history_init(rows.hist);
    drive(sim, &(drive_ctx){ snap, (csv_path || rows.hist) ? run_row_cb : NULL, &rows, &prog,
                             cancel });
    acbb_branches br_store, *br = NULL; /* the other branch (acbb/tools/branches.h) */
    acbb_error berr;
    if (!acbb_cli_interrupted() && acbb_cli_branches_wanted(a, &sc)) {
        acbb_cli_progress_note(&prog, "solving the other branch (steady solve vs transient)");
        if (acbb_branches_compare(&sc, snap, cancel, deadline, &br_store, &berr) == ACBB_OK)
            br = &br_store;
    }
    acbb_cli_progress_end(&prog);
    acbb_cli_interrupt_end();
    acbb_snapshot *bear = bearing_snaps(sim, snap);
    acbb_sim_free(sim);
    rc = csv_path ? acbb_cli_file_close(&csv) : 0;
    rc = acbb_cli_worst(run_report(a, preset, &sc, snap, bear, br), rc);
    free(bear);
    if (plot && !rows.hist) rc = acbb_cli_worst(rc, acbb_cli_no_memory("run --plot"));
    if (rows.hist) rc = acbb_cli_worst(rc, acbb_cli_write_plot(plot, rows.hist, snap, preset));
    free(rows.hist);
    free(snap);
    return rc;
}

/* ---- acbb check ---- */

int acbb_cli_cmd_check(const acbb_cli_args *a)
{
    int rc;
    acbb_scene sc;
    if ((rc = acbb_cli_load_scene(a, &sc))) return rc;
    acbb_error err = { { 0 } };
    /* Ill-posedness (MODEL.md 11) is judged when the scene is compiled, so
     * check compiles it too; no thermal step is taken. */
    acbb_status st = acbb_sim_check(&sc, &err);
    if (st != ACBB_OK) {
        acbb_cli_say("%s\n", acbb_cli_err_text(&err, st));
        return acbb_cli_exit_for(st);
    }
    printf("%s: ok\n", a->preset);
    return acbb_cli_stdout_check(0);
}

/* ---- acbb study ---- */

static int study_table(const acbb_cli_args *a, long jobs);

/* PRESET `seed` is the seed's case, 7008C, through the preset search path;
 * with --out DIR the seed's figures are written (cli/figures.c). */
int acbb_cli_cmd_study(const acbb_cli_args *args)
{
    long jobs;
    int rc = acbb_cli_count(args, CLI_OPT_JOBS, acbb_batch_cpus(), 1, ACBB_CLI_MAX_JOBS, &jobs);
    if (rc) return rc;
    acbb_cli_args *a = malloc(sizeof *a);
    if (!a) return acbb_cli_no_memory("study");
    *a = *args;
    const char *name = acbb_cli_study_preset_name(a->pos[0]);
    if (acbb_cli_resolve_preset(name, a->preset_buf, sizeof a->preset_buf, true) != 0)
        rc = ACBB_EXIT_INPUT;
    a->preset = a->preset_buf;
    if (!rc) rc = a->val[CLI_OPT_OUT] ? acbb_cli_study_figures(a, jobs) : study_table(a, jobs);
    free(a);
    return rc;
}

/* A run the cancel stopped mid-way is shown as not run: its numbers are
 * those of an unfinished transient (issue 16). */
typedef struct {
    acbb_cli_point *pts;
    acbb_cli_counter count;  /* "study: 12/48 runs, ..., ETA" (issue 28 item 13) */
} study_ctx;

static void study_done(void *ctx, const acbb_batch_result *r)
{
    study_ctx *sc = ctx;
    acbb_cli_counter_step(&sc->count, r->done, r->total);
    point_done(sc->pts, r);
    acbb_cli_point *p = &sc->pts[r->index];
    if (r->status != ACBB_CANCELLED || !p->have_snap) return;
    p->have_snap = false;
    p->status = ACBB_CANCELLED;
    snprintf(p->message, sizeof p->message, "cancelled before it finished");
}

/* The failed runs said on stderr (the table marks each); those the cancel
 * stopped are the cancel's to say. */
static int study_failed(const acbb_cli_point *pts, const acbb_cli_study_block *blocks)
{
    size_t failed = 0, first = 0;
    for (size_t i = 0; i < ACBB_STUDY_COMPARE_N; i++) {
        if (acbb_cli_point_ok(&pts[i]) || pts[i].status == ACBB_CANCELLED) continue;
        if (!failed++) first = i;
    }
    const acbb_cli_study_block *b = blocks;
    while (b < blocks + ACBB_STUDY_NSWEEPS - 1 && first / 2 >= b->first + b->count) b++;
    const acbb_cli_point *p = &pts[first];
    char what[700];
    snprintf(what, sizeof what, "%s at %s %s: %s: %s", first % 2 ? "WTE" : "TE", b->x_label,
             p->value, acbb_cli_point_status(p), p->have_snap ? p->snap.message : p->message);
    return acbb_cli_runs_failed("study", failed, ACBB_STUDY_COMPARE_N, what,
                                "the table marks them with *");
}

/* The engine plans and runs the table (acbb_study_compare_*, study.h);
 * here it is only formatted. */
static int study_table(const acbb_cli_args *a, long jobs)
{
    int rc;
    acbb_scene base;
    if ((rc = acbb_cli_load_scene(a, &base))) return rc;
    acbb_study_compare *plan = malloc(sizeof *plan);
    acbb_cli_point *pts = calloc(ACBB_STUDY_COMPARE_N, sizeof *pts);
    if (!plan || !pts) {
        free(plan);
        free(pts);
        return acbb_cli_no_memory("study");
    }
    acbb_study_compare_plan(&base, plan);
    acbb_cli_study_block blocks[ACBB_STUDY_NSWEEPS];
    for (int b = 0; b < ACBB_STUDY_NSWEEPS; b++) {
        const acbb_study_compare_block *pb = &plan->blocks[b];
        blocks[b] = (acbb_cli_study_block){ pb->name, pb->title,
                                            pb->sweep == ACBB_STUDY_LOAD ? "Fx N" : "n rpm",
                                            pb->first, pb->count };
    }
    for (size_t i = 0; i < ACBB_STUDY_COMPARE_N; i++) {
        pts[i].scene = plan->pts[i].scene;
        snprintf(pts[i].value, sizeof pts[i].value, "%g", plan->pts[i].x);
    }
    study_ctx ctx = { .pts = pts };
    acbb_cli_counter_init(&ctx.count, "study");
    acbb_study_compare_run(plan, (int)jobs, acbb_cli_interrupt_begin(), study_done, &ctx, NULL);
    acbb_cli_interrupt_end();

    if (a->val[CLI_OPT_CSV]) {
        acbb_cli_file csv = { 0 };
        rc = acbb_cli_file_open(&csv, a->val[CLI_OPT_CSV]);
        if (!rc) {
            acbb_cli_study_csv(&csv.out, pts, blocks, ACBB_STUDY_NSWEEPS);
            rc = acbb_cli_file_close(&csv);
        }
    }
    acbb_cli_out o;
    acbb_cli_out_init(&o, stdout);
    acbb_cli_study_table(&o, pts, blocks, ACBB_STUDY_NSWEEPS);
    rc = acbb_cli_worst(rc, acbb_cli_stdout_check(o.nonfinite));
    if (!points_ok(pts, ACBB_STUDY_COMPARE_N)) rc = acbb_cli_worst(rc, ACBB_EXIT_SOLVER);
    rc = acbb_cli_worst(rc, study_failed(pts, blocks));
    rc = acbb_cli_worst(rc, acbb_cli_cancelled("study", "the table shows the runs that finished"));
    free(pts);
    free(plan);
    return rc;
}

/* ---- acbb bench speed ---- */

/* Wall time of `n` points run with `jobs` workers, `repeat` times;
 * *workers (may be NULL) gets how many ran. On a failure *ran = n: the
 * points the failure listing may name (the others were not run). */
static int bench_points(const acbb_scene *base, const double *loads, size_t n, long jobs,
                        long repeat, double *times, acbb_cli_point *pts, int *workers,
                        size_t *ran)
{
    *ran = n;
    for (long r = 0; r < repeat; r++) {
        for (size_t i = 0; i < n; i++) {
            memset(&pts[i], 0, sizeof pts[i]);
            pts[i].scene = *base;
            if (loads) pts[i].scene.axial_load = loads[i];
        }
        double t0 = acbb_now_ms();
        int w = run_points(pts, n, jobs, acbb_cli_interrupt_flag());
        times[r] = acbb_now_ms() - t0;
        if (workers) *workers = w;
        if (!points_ok(pts, n)) return ACBB_EXIT_SOLVER;
    }
    return 0;
}

/* Only the `n` points of the timing that failed: a point it did not run
 * (zeroed, status ok) is not a failure. */
static int bench_fail(const acbb_cli_point *pts, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (acbb_cli_point_ok(&pts[i])) continue;
        acbb_cli_say("bench speed: run %zu: %s: %s\n", i, acbb_cli_point_status(&pts[i]),
                pts[i].have_snap ? pts[i].snap.message : pts[i].message);
    }
    return ACBB_EXIT_SOLVER;
}

int acbb_cli_cmd_bench_speed(const acbb_cli_args *a)
{
    long repeat, jobs;
    int rc = acbb_cli_count(a, CLI_OPT_REPEAT, 5, 1, 100000, &repeat);
    if (!rc) rc = acbb_cli_count(a, CLI_OPT_JOBS, acbb_batch_cpus(), 1, ACBB_CLI_MAX_JOBS, &jobs);
    if (rc) return rc;
    /* Without PRESET: the seed's case, through the search path. */
    acbb_cli_args with_default = *a;
    if (!a->preset) {
        if (acbb_cli_resolve_preset("7008C", with_default.preset_buf,
                                    sizeof with_default.preset_buf, true) != 0)
            return ACBB_EXIT_INPUT;
        with_default.preset = with_default.preset_buf;
    }
    const char *preset = with_default.preset;
    acbb_scene base;
    if ((rc = acbb_cli_load_scene(&with_default, &base))) return rc;

    struct utsname u;
    const char *machine = uname(&u) == 0 ? u.machine : "unknown";
    double *times = calloc((size_t)repeat, sizeof *times);
    acbb_cli_point *pts = calloc(ACBB_STUDY_NPTS, sizeof *pts);
    if (!times || !pts) {
        free(times);
        free(pts);
        return acbb_cli_no_memory("bench speed");
    }
    acbb_cli_interrupt_begin();
    printf("acbb bench speed %s (median of %ld)\n", preset, repeat);
    printf("machine            %s, %d CPUs usable (affinity)\n", machine, acbb_batch_cpus());

    size_t ran = 0;
    if ((rc = bench_points(&base, NULL, 1, 1, repeat, times, pts, NULL, &ran))) goto fail;
    printf("one run            %10.2f ms (%ld iterations, %s, %s)\n",
           acbb_median(times, (size_t)repeat), pts[0].snap.iteration,
           acbb_cli_point_status(&pts[0]), acbb_model_level_name(base.model));
    if ((rc = bench_points(&base, acbb_study_loads, ACBB_STUDY_NPTS, 1, repeat, times, pts,
                           NULL, &ran)))
        goto fail;
    printf("8-load sweep       %10.2f ms  (1 thread; loads 50..1000 N)\n",
           acbb_median(times, (size_t)repeat));
    if (jobs > 1) {
        int w = 1;
        if ((rc = bench_points(&base, acbb_study_loads, ACBB_STUDY_NPTS, jobs, repeat, times,
                               pts, &w, &ran)))
            goto fail;
        printf("8-load sweep       %10.2f ms  (%d threads)\n", acbb_median(times, (size_t)repeat),
               w);
    }
    acbb_cli_interrupt_end();
    rc = acbb_cli_stdout_check(0);
    free(times);
    free(pts);
    return rc;
fail:
    acbb_cli_interrupt_end();
    rc = acbb_cli_interrupted() ? acbb_cli_cancelled("bench speed", "the timings above finished")
                                : bench_fail(pts, ran);
    free(times);
    free(pts);
    return rc;
}

/* ---- acbb keys ---- */

/* One key: its default, then the interval exactly as the check applies it
 * ("(0, 100] mm": an open end is refused, a closed one accepted), then the
 * plausible range of an uncertain input (what `acbb sensitivity` varies). */
static void print_key(size_t i, const acbb_field_info *fi, const char *deflt)
{
    char range[160], plaus[320];
    acbb_scene_field_interval(i, range, sizeof range);
    /* Wrapped at 80 columns, continuations under the text (issue 21 item 8). */
    char line[800];
    printf("%s.%s = %s\n    ", fi->section, fi->key, deflt);
    snprintf(line, sizeof line, "%s: %s", range, fi->help ? fi->help : "");
    acbb_cli_wrap(stdout, line, 4, 6);
    fputc('\n', stdout);
    acbb_scene_field_plausible(i, plaus, sizeof plaus);
    if (plaus[0]) {
        snprintf(line, sizeof line, "plausible: %s", plaus);
        fputs("    ", stdout);
        acbb_cli_wrap(stdout, line, 4, 6);
        fputc('\n', stdout);
    }
}

int acbb_cli_cmd_keys(const acbb_cli_args *a)
{
    (void)a;
    acbb_scene sc;
    acbb_scene_default(&sc);
    size_t n = acbb_scene_field_count();
    for (size_t i = 0; i < n; i++) {
        const acbb_field_info *fi = acbb_scene_field(i);
        if (!fi) continue;
        char buf[128];
        acbb_scene_field_format(&sc, i, buf, sizeof buf);
        print_key(i, fi, buf);
    }
    return acbb_cli_stdout_check(0);
}
