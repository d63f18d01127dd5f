/* acbb CLI — `acbb sweep`: a grid of points run by the engine's sweep pool
 * (include/acbb/tools/sweep.h), streamed as each point finishes (sweep.h), or,
 * for the 1-D `--param K --values V` form alone, the table / JSON / CSV of
 * output.h once every point is in. */
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/tools/measure.h"
#include "commands.h"
#include "common.h"
#include "exit.h"
#include "output.h"
#include "progress.h"
#include "sweep.h"
#include "say.h"

typedef struct {
    const acbb_sweep *grid;
    acbb_cli_sweep_id id;      /* the header and the records' fingerprint */
    acbb_cli_sink sink[2];
    size_t n_sinks;
    size_t total, done, failed;
    long nonfinite;
    int oom;                   /* a record could not be built */
    int progress;              /* stderr is a terminal */
    double t0, last_shown;
    acbb_cli_point *pts;       /* the 1-D form: results kept for the table */
    const acbb_scene *base;
    char first_failed[700];    /* "key=value, ...: status: message" of the first failure */
    size_t first_index;        /* its index (the lowest failed: not the thread order) */
} sweep_run;

/* The failed point of lowest index, named by its grid values, for the line
 * that says why the sweep exits 3 (acbb_cli_runs_failed). */
static void note_failure(sweep_run *s, const acbb_sweep_result *r)
{
    if (s->first_failed[0] && r->index >= s->first_index) return;
    s->first_index = r->index;
    size_t u = 0, cap = sizeof s->first_failed;
    for (size_t d = 0; d < acbb_sweep_n_dims(s->grid) && u < cap; d++)
        u += (size_t)snprintf(s->first_failed + u, cap - u, "%s%s=%s", d ? ", " : "",
                              acbb_sweep_key(s->grid, d),
                              acbb_sweep_value(s->grid, r->index, d));
    if (u < cap)
        snprintf(s->first_failed + u, cap - u, ": %s: %s",
                 r->have_snap ? acbb_run_status_name(&r->snap) : acbb_status_name(r->status),
                 r->have_snap ? r->snap.message : r->message);
}

static void show_progress(sweep_run *s, int final)
{
    double now = acbb_now_ms(), el = (now - s->t0) / 1e3;
    if (!s->progress || (!final && now - s->last_shown < 200)) return;
    s->last_shown = now;
    double rate = el > 0 ? (double)s->done / el : 0;
    double eta = rate > 0 ? (double)(s->total - s->done) / rate : 0;
    acbb_cli_progress_draw("\rsweep: %zu/%zu done, %zu failed, %.1f points/s, ETA %.0f s   %s",
            s->done, s->total, s->failed, rate, eta, final ? "\n" : "");
}

/* Called by the engine under its lock, one point at a time. */
static void on_point(void *ctx, const acbb_sweep_result *r)
{
    sweep_run *s = ctx;
    s->done++;
    if (!(r->have_snap && r->snap.state == ACBB_RUN_CONVERGED)) {
        s->failed++;
        note_failure(s, r);
    }
    /* Each record whole, in one write (issue 26 item 4: a failed write
     * leaves the file at its last whole record, sweep_sink.c). */
    for (size_t k = 0; k < s->n_sinks; k++) {
        acbb_cli_sink *o = &s->sink[k];
        size_t len = 0;
        char *text = acbb_cli_sweep_record_text(o->fmt, &s->id, r, &len, &s->nonfinite);
        if (!text) s->oom = 1, acbb_cli_interrupt_stop();
        else if (acbb_cli_sink_put(o, text, len) == 0) o->written++;
        free(text);
    }
    if (s->pts) {
        acbb_cli_point *p = &s->pts[r->index];
        snprintf(p->value, sizeof p->value, "%s", acbb_sweep_value(s->grid, r->index, 0));
        acbb_error err = { { 0 } };
        acbb_sweep_scene(s->grid, s->base, r->index, &p->scene, &err);
        p->status = r->status;
        p->have_snap = r->have_snap;
        snprintf(p->message, sizeof p->message, "%s", r->message);
        p->wall_ms = r->wall_ms;
        p->snap = r->snap;
    }
    show_progress(s, 0);
}

/* The grid from --param/--values (first) and every --grid. */
static int build_grid(const acbb_cli_args *a, acbb_sweep *g)
{
    acbb_error err = { { 0 } };
    if (a->val[CLI_OPT_PARAM] || a->val[CLI_OPT_VALUES]) {
        if (!a->val[CLI_OPT_PARAM] || !a->val[CLI_OPT_VALUES]) {
            acbb_cli_say("sweep: --param and --values go together\n");
            return ACBB_EXIT_INPUT;
        }
        size_t len = strlen(a->val[CLI_OPT_PARAM]) + strlen(a->val[CLI_OPT_VALUES]) + 2;
        char *spec = malloc(len);
        if (!spec) return acbb_cli_no_memory("sweep");
        snprintf(spec, len, "%s=%s", a->val[CLI_OPT_PARAM], a->val[CLI_OPT_VALUES]);
        acbb_status st = acbb_sweep_add(g, spec, &err);
        free(spec);
        if (st != ACBB_OK) goto bad;
    }
    for (size_t i = 0; i < a->n_grids; i++)
        if (acbb_sweep_add(g, a->grids[i], &err) != ACBB_OK) goto bad;
    if (acbb_sweep_n_dims(g) > 0) return 0;
    acbb_cli_say("sweep: needs --grid section.key=v1,v2,... (repeatable) or "
                    "--param section.key and --values v1,v2,...\n");
    return ACBB_EXIT_INPUT;
bad:
    acbb_cli_say("sweep: --grid %s\n", err.msg);
    return ACBB_EXIT_INPUT;
}

/* Every --metric in its canonical form (sweep_metric.c); refused before
 * anything runs (exit 2). */
static int parse_metrics(const acbb_cli_args *a, acbb_cli_metrics *m)
{
    m->n = 0;
    m->no_stiffness = a->val[CLI_OPT_NO_STIFFNESS] != NULL; /* first: a stiffness metric is refused */
    for (size_t i = 0; i < a->n_metrics; i++) {
        char msg[300];
        if (acbb_cli_sweep_metric_add(m, a->metrics[i], msg, sizeof msg) != 0) {
            acbb_cli_say("sweep: --metric %s: %s\n", a->metrics[i], msg);
            return ACBB_EXIT_INPUT;
        }
    }
    return 0;
}

/* "K/N", 1 <= K <= N. */
static int parse_shard(const acbb_cli_args *a, acbb_sweep_opts *o)
{
    const char *t = a->val[CLI_OPT_SHARD];
    if (!t) return 0;
    char *end = NULL;
    unsigned long k = strtoul(t, &end, 10), n = 0;
    if (end != t && *end == '/') {
        const char *t2 = end + 1;
        n = strtoul(t2, &end, 10);
        if (end == t2) n = 0;
    }
    if (t[0] == '-' || *end || k < 1 || n < 1 || k > n || n > 1000000) {
        acbb_cli_say("sweep: --shard %s: expected K/N with 1 <= K <= N <= 1000000\n", t);
        return ACBB_EXIT_INPUT;
    }
    o->shard_k = k;
    o->shard_n = n;
    return 0;
}

/* A grid value its key refuses (a typo, a value out of range) is refused
 * before anything runs (exit 2), naming it: every point with it would fail. */
static int check_grid(const acbb_sweep *g, const acbb_scene *base, int first_is_param)
{
    size_t d = 0, v = 0;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_sweep_check_values(g, base, &d, &v, &err);
    if (st == ACBB_OK) return 0;
    acbb_cli_say("sweep: %s %s, value %zu of %zu: %s; nothing was run\n",
            d == 0 && first_is_param ? "--param" : "--grid", acbb_sweep_key(g, d), v + 1,
            acbb_sweep_n_values(g, d), acbb_cli_err_text(&err, st));
    return acbb_cli_exit_for(st) == ACBB_EXIT_INTERNAL ? ACBB_EXIT_INTERNAL : ACBB_EXIT_INPUT;
}

/* The 1-D form refuses a bad value before running anything (exit 2). */
static int check_values(const acbb_sweep *g, const acbb_scene *base, const char *param)
{
    for (size_t i = 0; i < acbb_sweep_n_points(g); i++) {
        acbb_scene sc;
        acbb_error err = { { 0 } };
        acbb_status st = acbb_sweep_scene(g, base, i, &sc, &err);
        if (st != ACBB_OK) {
            acbb_cli_say("--param %s=%s: %s\n", param, acbb_sweep_value(g, i, 0),
                    acbb_cli_err_text(&err, st));
            return ACBB_EXIT_INPUT;
        }
    }
    return 0;
}

static int legacy_output(const acbb_cli_args *a, const sweep_run *s)
{
    const acbb_cli_point *pts = s->pts;
    size_t n = s->total;
    const char *param = a->val[CLI_OPT_PARAM];
    int rc = 0;
    if (a->val[CLI_OPT_CSV]) {
        acbb_cli_file csv = { 0 };
        rc = acbb_cli_file_open(&csv, a->val[CLI_OPT_CSV]);
        if (!rc) {
            acbb_cli_sweep_csv(&csv.out, param, pts, n);
            rc = acbb_cli_file_close(&csv);
        }
    }
    acbb_cli_out o;
    acbb_cli_out_init(&o, stdout);
    if (a->val[CLI_OPT_JSON]) acbb_cli_sweep_json(&o, param, pts, n);
    else acbb_cli_sweep_table(&o, param, pts, n);
    rc = acbb_cli_worst(rc, acbb_cli_stdout_check(o.nonfinite));
    rc = acbb_cli_worst(rc, acbb_cli_runs_failed("sweep", s->failed, s->done, s->first_failed,
                                                 a->val[CLI_OPT_JSON] ? "their records say why"
                                                 : "the table lists them"));
    for (size_t i = 0; i < n; i++) /* cancelled: the cancel says so (below) */
        if (!acbb_cli_point_ok(&pts[i])) rc = acbb_cli_worst(rc, ACBB_EXIT_SOLVER);
    return rc;
}

/* The engine's sweep stopped short (out of memory: sweep.h). */
static int sweep_error(acbb_status st, const char *kept)
{
    acbb_cli_say("sweep: %s; %s\n", acbb_status_name(st), kept);
    return acbb_cli_exit_for(st);
}

/* The 1-D form: every point's row at the end. A point the cancel stopped
 * (or never started) keeps the row `cancelled` set here, so the table
 * shows the finished points and, plainly, the others. */
static int sweep_table(const acbb_cli_args *a, sweep_run *s, const acbb_scene *base,
                       acbb_sweep_opts *o)
{
    s->pts = calloc(s->total, sizeof *s->pts);
    if (!s->pts) return acbb_cli_no_memory("sweep");
    for (size_t i = 0; i < s->total; i++) {
        acbb_cli_point *p = &s->pts[i];
        snprintf(p->value, sizeof p->value, "%s", acbb_sweep_value(s->grid, i, 0));
        p->status = ACBB_CANCELLED;
        snprintf(p->message, sizeof p->message, "cancelled before it finished");
    }
    s->t0 = acbb_now_ms();
    acbb_status st = acbb_sweep_run(s->grid, base, o, NULL);
    show_progress(s, 1);
    int rc = st == ACBB_OK || st == ACBB_CANCELLED ? legacy_output(a, s)
                                                   : sweep_error(st, "no table printed");
    char kept[96];
    snprintf(kept, sizeof kept, "the table shows the %zu finished point%s", s->done,
             s->done == 1 ? "" : "s");
    rc = acbb_cli_worst(rc, acbb_cli_cancelled("sweep", kept));
    free(s->pts);
    s->pts = NULL;
    return rc;
}

/* Open --jsonl / --csv for streaming; an existing file is resumed. */
static int open_sink(sweep_run *s, const char *path, acbb_cli_rec_format fmt,
                     unsigned char *count)
{
    acbb_cli_sink *o = &s->sink[s->n_sinks];
    size_t found = 0;
    int rc = acbb_cli_sink_open(o, path, fmt, &s->id, count, &found);
    if (o->fd >= 0) s->n_sinks++; /* closed (and its lock dropped) at the end */
    if (!rc && found && s->progress)
        acbb_cli_say("sweep: %s: note: resuming, %zu point%s already there\n", path, found,
                     found == 1 ? "" : "s");
    return rc;
}

static int close_sinks(sweep_run *s)
{
    int rc = s->oom ? ACBB_EXIT_INTERNAL : 0;
    if (s->oom) acbb_cli_say("sweep: out of memory building a record\n");
    for (size_t k = 0; k < s->n_sinks; k++) rc = acbb_cli_worst(rc, acbb_cli_sink_close(&s->sink[k]));
    return rc;
}

/* A closed pipe or a file over `ulimit -f` is a write error (exit 4, the
 * message names the output), not a silent death by SIGPIPE or SIGXFSZ
 * (issue 26 item 11). */
static void quiet_signals(int on, struct sigaction *old)
{
    struct sigaction ign = { .sa_handler = SIG_IGN };
    sigemptyset(&ign.sa_mask);
    if (on) {
        sigaction(SIGPIPE, &ign, &old[0]);
        sigaction(SIGXFSZ, &ign, &old[1]);
    } else {
        sigaction(SIGPIPE, &old[0], NULL);
        sigaction(SIGXFSZ, &old[1], NULL);
    }
}

/* Streaming: the points of the shard not yet in every output file. */
static int sweep_stream(const acbb_cli_args *a, sweep_run *s, const acbb_scene *base,
                        acbb_sweep_opts *o)
{
    unsigned char *count = calloc(s->total ? s->total : 1, 1);
    if (!count) return acbb_cli_no_memory("sweep");
    struct sigaction old[2];
    quiet_signals(1, old);
    int rc = 0;
    if (a->val[CLI_OPT_JSONL]) rc = open_sink(s, a->val[CLI_OPT_JSONL], ACBB_CLI_REC_JSONL, count);
    if (!rc && a->val[CLI_OPT_CSV]) rc = open_sink(s, a->val[CLI_OPT_CSV], ACBB_CLI_REC_CSV, count);
    if (!rc && s->n_sinks == 0) rc = open_sink(s, "-", ACBB_CLI_REC_JSONL, count);
    size_t n_files = 0;
    for (size_t k = 0; k < s->n_sinks; k++) n_files += (size_t)s->sink[k].own;
    /* A point is done when every output file has it. */
    for (size_t i = 0; i < s->total; i++) count[i] = n_files && count[i] >= n_files;
    o->skip = count;
    if (!rc) {
        s->total = acbb_sweep_n_todo(s->grid, o);
        s->t0 = acbb_now_ms();
        acbb_status st = acbb_sweep_run(s->grid, base, o, NULL);
        show_progress(s, 1);
        if (st != ACBB_OK && st != ACBB_CANCELLED) rc = sweep_error(st, "the finished points were recorded");
    }
    rc = acbb_cli_worst(rc, close_sinks(s));
    quiet_signals(0, old);
    if (s->nonfinite) rc = acbb_cli_worst(rc, acbb_cli_stdout_check(s->nonfinite));
    rc = acbb_cli_worst(rc, acbb_cli_runs_failed("sweep", s->failed, s->done, s->first_failed,
                                                 "their records say why"));
    char kept[160];
    snprintf(kept, sizeof kept, "%zu finished point%s recorded; run the same command again "
             "to resume", s->done, s->done == 1 ? "" : "s");
    rc = acbb_cli_worst(rc, acbb_cli_cancelled("sweep", kept));
    free(count);
    return rc;
}

int acbb_cli_cmd_sweep(const acbb_cli_args *a)
{
    long jobs = 0, max_points = 0; /* read only when every count parsed */
    int rc = acbb_cli_count(a, CLI_OPT_JOBS, 0, 1, ACBB_CLI_MAX_JOBS, &jobs);
    if (!rc) rc = acbb_cli_count(a, CLI_OPT_MAX_POINTS, 0, 1, ACBB_SWEEP_MAX_POINTS, &max_points);
    acbb_sweep_opts o = { .jobs = (int)jobs, .max_points = (size_t)max_points,
                          .done = on_point,
                          .transient = a->val[CLI_OPT_TRANSIENT] != NULL };
    if (!rc) rc = parse_shard(a, &o);
    acbb_cli_metrics metrics;
    if (!rc) rc = parse_metrics(a, &metrics);
    o.skip_stiffness = !rc && metrics.no_stiffness;
    acbb_sweep *g = NULL;
    if (!rc && acbb_sweep_new(&g) != ACBB_OK) rc = acbb_cli_no_memory("sweep");
    if (!rc) rc = build_grid(a, g);
    acbb_scene base;
    if (!rc) rc = acbb_cli_load_scene(a, &base);
    if (!rc) rc = check_grid(g, &base, a->val[CLI_OPT_PARAM] != NULL);
    if (rc) {
        acbb_sweep_free(g);
        return rc;
    }
    sweep_run s = { .grid = g, .total = acbb_sweep_n_points(g), .base = &base,
                    .progress = acbb_cli_progress_wanted(stderr) };
    o.ctx = &s;
    acbb_cli_sweep_id_init(&s.id, g, &base, o.transient, &metrics);
    s.id.csv_header = a->val[CLI_OPT_CSV_HEADER] != NULL;
    /* --metric and --csv-header are options of the records: they ask for them */
    bool legacy = a->n_grids == 0 && !a->val[CLI_OPT_JSONL] && !a->val[CLI_OPT_SHARD] &&
                  !a->val[CLI_OPT_MAX_POINTS] && metrics.n == 0 && !s.id.csv_header &&
                  !metrics.no_stiffness;
    /* SIGINT / SIGTERM stop the sweep within a step; what finished is
     * kept (progress.h). */
    o.cancel = acbb_cli_interrupt_begin();
    if (!legacy) {
        rc = sweep_stream(a, &s, &base, &o);
    } else if (!(rc = check_values(g, &base, a->val[CLI_OPT_PARAM]))) {
        rc = sweep_table(a, &s, &base, &o);
    }
    acbb_cli_interrupt_end();
    acbb_sweep_free(g);
    return rc;
}
