/* acbb TUI — the Sweep screen: one key of the open (edited) scene over a
 * range, run in the background (whatif.h: acbb_sweep_run on every core),
 * each point on a chart of the chosen metric as it finishes, with the
 * points' table beside it. Also the metric menu both what-if screens
 * share (picker.h). */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "export.h"
#include "results.h"
#include "screens.h"
#include "acbb/tools/scene_schema.h"

#define TABLE_W 27   /* the points' table at the right: "%10s %13s" + a margin */
#define DEFAULT_N 9  /* points of the default range */

extern const acbb_screen acbb_screen_sweep;

/* ---- the metric menu (both what-if screens) ---- */

/* This screen's own state (screens.h init): the job and what it shows. */
typedef struct {
    acbb_sweepjob *job;
    acbb_sweep_view v;             /* copy of its published state, once per frame */
    char key[ACBB_SWEEP_KEY];      /* the swept key ("" until chosen) */
    char range[96];                /* "lo:hi:n" or "v1,v2,..." */
    int chosen;                    /* the key was typed (s), not a default */
    int metric, top;               /* metric menu index; first table row shown */
    unsigned long seen_run;        /* run whose end was already announced */
    unsigned long hidden_run;      /* a run of a preset no longer open (results.c) */
    char metric_custom[ACBB_SENS_METRIC]; /* a typed metric: the last entry of both screens' menus */
    acbb_axis_memo memo;           /* the chart's widen-only ranges */
    acbb_scene ran_on;             /* the scene its last job started on (results.c) */
} sweep_ui;

extern const acbb_screen acbb_screen_sweep;

static sweep_ui *sw(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_sweep);
}

int acbb_whatif_metric_count(const acbb_app *a)
{
    return acbb_metric_menu_n + (sw(a)->metric_custom[0] != '\0');
}

const char *acbb_whatif_metric(const acbb_app *a, int i, const char **label)
{
    int n = acbb_whatif_metric_count(a);
    i = ((i % n) + n) % n;
    if (i < acbb_metric_menu_n) {
        if (label) *label = acbb_metric_menu[i].label;
        return acbb_metric_menu[i].path;
    }
    if (label) *label = sw(a)->metric_custom;
    return sw(a)->metric_custom;
}

int acbb_whatif_metric_set(acbb_app *a, const char *text, int *slot)
{
    acbb_error err = { { 0 } };
    if (acbb_metric_check(text, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", err.msg);
        return 0;
    }
    for (int i = 0; i < acbb_metric_menu_n; i++)
        if (strcmp(acbb_metric_menu[i].path, text) == 0) {
            *slot = i;
            return 1;
        }
    snprintf(sw(a)->metric_custom, sizeof sw(a)->metric_custom, "%s", text);
    *slot = acbb_metric_menu_n;
    return 1;
}

/* ---- choosing the key and the range ---- */

static long find_field(const char *key)
{
    char name[128];
    for (size_t i = 0; acbb_scene_key_name(i, name, sizeof name); i++)
        if (strcmp(name, key) == 0) return (long)i;
    return -1;
}

/* The default range: the key's value x0.5 .. x1.5 in 9 points, kept
 * inside the key's allowed range (an open end is not reached). */
static void default_range(const acbb_app *a, size_t i, char *buf, size_t n)
{
    const acbb_field_info *f = acbb_scene_field(i);
    char val[64];
    acbb_scene_field_format(&a->ed.scene, i, val, sizeof val);
    double v = strtod(val, NULL);
    double lo = v == 0.0 ? f->min : 0.5 * v, hi = v == 0.0 ? v + 1.0 : 1.5 * v;
    if (lo > hi) { double t = lo; lo = hi; hi = t; }
    if (lo < f->min || (f->min_open && lo <= f->min)) lo = 0.5 * (f->min + v);
    if (hi > f->max || (f->max_open && hi >= f->max)) hi = 0.5 * (f->max + v);
    long pts = DEFAULT_N;
    if (f->type == ACBB_FIELD_INT) {
        lo = ceil(lo);
        hi = floor(hi);
        if (hi - lo + 1 < pts) pts = (long)(hi - lo + 1);
        if (pts < 1) pts = 1;
    }
    snprintf(buf, n, "%.6g:%.6g:%ld", lo, hi, pts);
}

/* Make `key` the swept key (a number key of the schema); 0 if refused. */
static int use_key(acbb_app *a, const char *key)
{
    long i = find_field(key);
    if (i < 0) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "no key %s (Tab completes; `acbb keys` lists them)", key);
        return 0;
    }
    const acbb_field_info *f = acbb_scene_field((size_t)i);
    if (f->type != ACBB_FIELD_REAL && f->type != ACBB_FIELD_INT) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s is a choice, not a number: the Sweep screen plots numbers"
                     " (acbb sweep --grid takes choices)", key);
        return 0;
    }
    snprintf(sw(a)->key, sizeof sw(a)->key, "%s", key);
    default_range(a, (size_t)i, sw(a)->range, sizeof sw(a)->range);
    return 1;
}

static void key_answer(acbb_app *a, const char *text)
{
    if (text[0] && use_key(a, text) && (sw(a)->chosen = 1))
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "sweep %s over %s (e edits the range, r runs)", sw(a)->key,
                     sw(a)->range);
}

/* The range is checked as r will check it (whatif.c): a range r refuses
 * is refused here, with the same reason (issue 21 item 5). */
static void range_answer(acbb_app *a, const char *text)
{
    if (!text[0]) return;
    char spec[192];
    snprintf(spec, sizeof spec, "%s=%s", sw(a)->key[0] ? sw(a)->key : "operating.axial_load_N", text);
    acbb_sweep *g = NULL;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_sweep_new(&g);
    if (st == ACBB_OK) st = acbb_sweep_add(g, spec, &err);
    size_t n = st == ACBB_OK ? acbb_sweep_n_points(g) : 0;
    acbb_sweep_free(g);
    if (st != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "range refused: %s", err.msg[0] ? err.msg : "out of memory");
        return;
    }
    if (n > ACBB_WHATIF_MAX_POINTS) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "range refused: %zu points, the TUI sweeps 1..%d "
                     "(acbb sweep does more)", n, ACBB_WHATIF_MAX_POINTS);
        return;
    }
    snprintf(sw(a)->range, sizeof sw(a)->range, "%s", text);
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "range %s (r runs the sweep)", sw(a)->range);
}

static void metric_answer(acbb_app *a, const char *text)
{
    if (text[0] && acbb_whatif_metric_set(a, text, &sw(a)->metric))
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "metric %s", text);
}

/* On the way in, unless a key was typed: the editor's key under the
 * cursor when the cursor was moved onto a number, else the axial load
 * (the first key, the pitch diameter, failed most of its default range).
 * Followed at every visit, not fixed at the first (issue 21 item 5). */
static void enter(acbb_app *a)
{
    char name[128];
    if (sw(a)->chosen || (sw(a)->v.job.started_s > 0 && sw(a)->v.job.ended_s == 0)) return; /* running */
    const acbb_field_info *f = acbb_scene_field(a->ed.cursor);
    if (a->ed.cursor > 0 && f && (f->type == ACBB_FIELD_REAL || f->type == ACBB_FIELD_INT) &&
        acbb_scene_key_name(a->ed.cursor, name, sizeof name))
        use_key(a, name);
    else
        use_key(a, "operating.axial_load_N");
}

/* ---- starting, following, cancelling ---- */

static void start(acbb_app *a)
{
    if (!sw(a)->key[0]) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "no key to sweep yet: s chooses one");
        return;
    }
    const char *metrics[ACBB_WHATIF_METRICS];
    int n = acbb_whatif_metric_count(a);
    for (int i = 0; i < n && i < ACBB_WHATIF_METRICS; i++) metrics[i] = acbb_whatif_metric(a, i, NULL);
    char spec[192];
    snprintf(spec, sizeof spec, "%s=%s", sw(a)->key, sw(a)->range);
    acbb_error err = { { 0 } };
    if (acbb_sweepjob_start(sw(a)->job, &a->ed.scene, spec, metrics, (size_t)n, 0, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", err.msg);
        return;
    }
    sw(a)->top = 0;
    sw(a)->ran_on = a->ed.scene;
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "sweep started on %s%s: %s (x cancels)", acbb_editor_name(&a->ed),
                 a->ed.modified ? "*" : "", spec);
}

/* Announce the end of a run (once per run). */
static void follow(acbb_app *a)
{
    const acbb_sweep_view *v = &sw(a)->v;
    if (v->job.phase <= ACBB_JOB_RUNNING || v->job.run_id == sw(a)->seen_run) return;
    sw(a)->seen_run = v->job.run_id;
    char took[16];
    acbb_fmt_duration(v->job.ended_s - v->job.started_s, took, sizeof took);
    if (v->job.phase == ACBB_JOB_DONE)
        acbb_app_msg(a, v->failed ? ACBB_ROLE_WARN : ACBB_ROLE_OK, "sweep done: %zu points, %zu failed, in %s",
                     v->done, v->failed, took);
    else if (v->job.phase == ACBB_JOB_CANCELLED)
        acbb_app_msg(a, ACBB_ROLE_WARN, "sweep cancelled after %zu of %zu points", v->done, v->total);
    else
        acbb_app_msg(a, ACBB_ROLE_ERROR, "sweep failed: %s", v->job.message);
}

/* ---- the job's lifecycle (screens.h) ---- */

static acbb_status make(void *p, acbb_error *err) { return acbb_sweepjob_new(&((sweep_ui *)p)->job, err); }

static acbb_status init(acbb_app *a, void **state, acbb_error *err)
{
    (void)a;
    return acbb_screen_state_new(state, sizeof(sweep_ui), make, err);
}

static void sweep_free(void *state)
{
    sweep_ui *p = state;
    if (!p) return;
    acbb_sweepjob_free(p->job);
    free(p);
}

static int wake_fd(const acbb_app *a) { return acbb_job_wake_fd(acbb_sweepjob_job(sw(a)->job)); }

static void wake(acbb_app *a) { acbb_job_drain_wake(acbb_sweepjob_job(sw(a)->job)); }

static void poll(acbb_app *a)
{
    sweep_ui *p = sw(a);
    acbb_sweepjob_read(p->job, &p->v);
    if (p->v.job.run_id == p->hidden_run ||
        acbb_results_stale(a, &acbb_screen_sweep, &p->ran_on, p->v.job.phase > ACBB_JOB_RUNNING))
        memset(&p->v, 0, sizeof p->v);
    follow(a);
}

static void drop(acbb_app *a)
{
    sweep_ui *p = sw(a);
    acbb_job_cancel(acbb_sweepjob_job(p->job));
    acbb_sweepjob_read(p->job, &p->v); /* a run started since the last frame is hidden too */
    p->hidden_run = p->v.job.run_id;
}

static int running(const acbb_app *a) { return sw(a)->v.job.phase == ACBB_JOB_RUNNING; }

/* ---- drawing ---- */

/* Where the current metric sits among those the last sweep recorded (-1: not there). */
static int recorded(const acbb_app *a, const char **path, const char **label)
{
    *path = acbb_whatif_metric(a, sw(a)->metric, label);
    for (size_t m = 0; m < sw(a)->v.n_metrics; m++)
        if (strcmp(sw(a)->v.metrics[m], *path) == 0) return (int)m;
    return -1;
}

static void draw_heading(acbb_app *a, acbb_rect b)
{
    const acbb_sweep_view *v = &sw(a)->v;
    const char *path, *label;
    recorded(a, &path, &label);
    char unit[16];
    acbb_metric_unit(path, unit, sizeof unit);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "Sweep %s = %s   metric: %s [%s]",
             sw(a)->key[0] ? sw(a)->key : "(s: choose a key)", sw(a)->range, label, unit);
    int y = b.y + 1;
    char took[16];
    acbb_fmt_duration(v->job.ended_s - v->job.started_s, took, sizeof took);
    switch (v->job.phase) {
    case ACBB_JOB_IDLE:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_NORMAL,
                 "s key  e range  < > metric  r/Enter sweeps the edited scene in the background");
        break;
    case ACBB_JOB_RUNNING:
        acbb_draw_job_line(a, y, b.x, b.w, v->job.cancel_requested, v->job.started_s, v->done,
                           v->total, "points");
        break;
    case ACBB_JOB_DONE:
        acbb_put(a, y, b.x, b.w, v->failed ? ACBB_ROLE_WARN : ACBB_ROLE_OK,
                 "done: %zu/%zu points, %zu failed, in %s", v->done, v->total, v->failed, took);
        break;
    case ACBB_JOB_CANCELLED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_WARN, "cancelled after %zu of %zu points (%zu failed); r reruns",
                 v->done, v->total, v->failed);
        break;
    case ACBB_JOB_FAILED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_ERROR, "failed: %s", v->job.message);
        break;
    }
}

/* The finished, converged points in index order (x, y of metric m). */
static size_t curve(const acbb_sweep_view *v, int m, double *x, double *y, double span[2])
{
    size_t n = 0;
    span[0] = INFINITY;
    span[1] = -INFINITY;
    for (size_t i = 0; i < v->total && i < ACBB_WHATIF_MAX_POINTS; i++) {
        const acbb_whatif_point *p = &v->pts[i];
        if (!p->have) continue;
        span[0] = fmin(span[0], p->x);
        span[1] = fmax(span[1], p->x);
        if (!p->ok || m < 0 || !isfinite(p->y[m])) continue;
        x[n] = p->x;
        y[n++] = p->y[m];
    }
    return n;
}

static void draw_chart(acbb_app *a, acbb_rect r, int m, const char *label, const char *yunit)
{
    double x[ACBB_WHATIF_MAX_POINTS], y[ACBB_WHATIF_MAX_POINTS];
    double span[2];
    size_t n = curve(&sw(a)->v, m, x, y, span);
    long fi = find_field(sw(a)->v.key);
    const double *ys[1] = { y };
    const char *names[1] = { label };
    acbb_chart_spec sp = { .title = label, .yunit = yunit,
                           .xunit = fi >= 0 ? acbb_scene_field((size_t)fi)->unit : "", .x = x,
                           .ys = ys, .names = names, .nser = 1, .n = n, .floor_y = NAN,
                           .memo = &sw(a)->memo, .memo_key = sw(a)->v.job.run_id * 64 + (unsigned)m,
                           .x_fixed = isfinite(span[0]), .x0 = span[0], .x1 = span[1] };
    if (sw(a)->v.job.phase == ACBB_JOB_IDLE) {
        const char *note = acbb_results_note(a, &acbb_screen_sweep);
        acbb_put_wrap(a, r.y + 1, r.x + 2, r.w - 2, 3, ACBB_ROLE_DIM, note ? note : "(no sweep yet: r runs one)");
        return;
    }
    if (m < 0) {
        acbb_put(a, r.y + 1, r.x + 2, r.w - 2, ACBB_ROLE_WARN, "(%s not recorded by this sweep: r reruns)",
                 label);
        return;
    }
    acbb_chart_draw(a, r, &sp);
}

static void draw_table(acbb_app *a, acbb_rect r, int m, const char *yunit)
{
    const acbb_sweep_view *v = &sw(a)->v;
    long fi = find_field(v->key[0] ? v->key : sw(a)->key);
    char xh[32], yh[32];
    snprintf(xh, sizeof xh, "[%s]", fi >= 0 ? acbb_scene_field((size_t)fi)->unit : "");
    snprintf(yh, sizeof yh, "[%s]", yunit);
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, " %10.10s %13.13s", xh, yh);
    int rows = r.h - 1, n = (int)v->total;
    if (sw(a)->top > n - rows) sw(a)->top = n - rows;
    if (sw(a)->top < 0) sw(a)->top = 0;
    for (int k = 0; k < rows && sw(a)->top + k < n; k++) {
        const acbb_whatif_point *p = &v->pts[sw(a)->top + k];
        int yy = r.y + 1 + k;
        if (!p->have)
            acbb_put(a, yy, r.x, r.w, ACBB_ROLE_DIM, " %10s %13s", "...", v->job.phase == ACBB_JOB_RUNNING ? "running" : "-");
        else if (!p->ok)
            acbb_put(a, yy, r.x, r.w, ACBB_ROLE_ERROR, " %10.6g %13s", p->x, "failed");
        else if (m < 0 || !isfinite(p->y[m]))
            acbb_put(a, yy, r.x, r.w, ACBB_ROLE_DIM, " %10.6g %13s", p->x, "-");
        else
            acbb_put(a, yy, r.x, r.w, ACBB_ROLE_NORMAL, " %10.6g %13.6g", p->x, p->y[m]);
    }
}

/* The first failed point's reason, under the chart's title when room. */
static const char *first_failure(const acbb_sweep_view *v)
{
    for (size_t i = 0; i < v->total && i < ACBB_WHATIF_MAX_POINTS; i++)
        if (v->pts[i].have && !v->pts[i].ok) return v->pts[i].why;
    return NULL;
}

/* The last sweep's points belong to its key and range: once s or e chose
 * others they are not shown under the new heading (issue 29 item 2). */
static int superseded(const acbb_app *a)
{
    char spec[192];
    snprintf(spec, sizeof spec, "%s=%s", sw(a)->key, sw(a)->range);
    return sw(a)->v.job.phase > ACBB_JOB_RUNNING && strcmp(sw(a)->v.spec, spec) != 0;
}

static void draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    if (superseded(a)) {
        memset(&sw(a)->v, 0, sizeof sw(a)->v); /* this frame draws as before any sweep */
        draw_heading(a, b);
        acbb_put(a, b.y + 3, b.x + 2, b.w - 2, ACBB_ROLE_DIM, "(no sweep of this key and range yet: r runs it)");
        return;
    }
    draw_heading(a, b);
    const char *path, *label;
    int m = recorded(a, &path, &label);
    char unit[16];
    acbb_metric_unit(path, unit, sizeof unit);
    const char *why = first_failure(&sw(a)->v);
    int top = b.y + 2 + (why != NULL ? 2 : 0);
    if (why) { /* two rows: a reason is longer than 80 columns */
        char line[600];
        snprintf(line, sizeof line, "failed point: %s", why);
        acbb_put_wrap(a, b.y + 2, b.x, b.w, 2, ACBB_ROLE_ERROR, line);
    }
    acbb_rect chart = { top, b.x, b.y + b.h - top, b.w - TABLE_W - 1 };
    acbb_rect table = { top, b.x + b.w - TABLE_W, chart.h, TABLE_W };
    draw_chart(a, chart, m, label, unit);
    draw_table(a, table, m, unit);
}

/* ---- export ---- */

/* g: the chart of the finished sweep, the points joined (issue 29 item 8:
 * g exported the Run screen's plots instead). */
static void export_plot(acbb_app *a)
{
    const char *path, *label;
    int m = recorded(a, &path, &label);
    double x[ACBB_WHATIF_MAX_POINTS], y[ACBB_WHATIF_MAX_POINTS], span[2];
    size_t n = sw(a)->v.job.phase > ACBB_JOB_RUNNING && m >= 0 ? curve(&sw(a)->v, m, x, y, span) : 0;
    if (n == 0) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s", sw(a)->v.job.phase == ACBB_JOB_RUNNING
                     ? "the sweep is still running" : "no swept point of this metric to plot (r runs a sweep)");
        return;
    }
    char unit[16], xl[ACBB_SWEEP_KEY + 32], yl[160], title[PATH_MAX + 64], png[PATH_MAX + 32], svg[PATH_MAX + 32];
    long fi = find_field(sw(a)->v.key);
    snprintf(xl, sizeof xl, "%s, %s", sw(a)->v.key, fi >= 0 ? acbb_scene_field((size_t)fi)->unit : "");
    acbb_metric_unit(path, unit, sizeof unit);
    snprintf(yl, sizeof yl, "%s, %s", label, unit);
    snprintf(title, sizeof title, "%s: sweep of %s", acbb_editor_name(&a->ed), sw(a)->v.key);
    acbb_plot_series sr = { label, x, y, n, 1, 1, 1 };
    acbb_plot_xy px = { title, xl, yl, &sr, 1 };
    acbb_error err = { { 0 } };
    if (acbb_export_xy(a->plot_dir, "sweep", &px, 1000, 600, png, svg, sizeof png, &err) != ACBB_OK)
        acbb_app_msg(a, ACBB_ROLE_ERROR, "plot export failed: %s", err.msg);
    else
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %s and %s", png, svg);
}

/* ---- keys ---- */

static int cancel(acbb_app *a)
{
    if (!acbb_job_cancel(acbb_sweepjob_job(sw(a)->job))) return 0;
    acbb_app_msg(a, ACBB_ROLE_WARN, "cancelling the sweep ...");
    return 1;
}

static int on_key(acbb_app *a, int ch)
{
    int page = a->lay.body.h - 4 > 1 ? a->lay.body.h - 4 : 1;
    if (acbb_scroll_key(ch, page, (int)sw(a)->v.total, &sw(a)->top)) return 1;
    switch (ch) {
    case 'r': case '\n': case '\r': case KEY_ENTER: start(a); return 1;
    case 'g': export_plot(a); return 1;
    case 'x':
        if (!cancel(a)) acbb_app_msg(a, ACBB_ROLE_WARN, "no sweep running (r starts one)");
        return 1;
    case 27: return cancel(a); /* otherwise Esc clears the message as everywhere */
    case 's': {
        char name[128] = "";
        if (!sw(a)->key[0]) acbb_scene_key_name(a->ed.cursor, name, sizeof name);
        acbb_app_ask(a, "sweep key (Tab completes): ", sw(a)->key[0] ? sw(a)->key : name, key_answer,
                     acbb_scene_key_name);
        return 1;
    }
    case 'e':
        acbb_app_ask(a, "range lo:hi:n or v1,v2,...: ", sw(a)->range, range_answer, NULL);
        return 1;
    case '<': case '>': case 'h': case 'l': case KEY_LEFT: case KEY_RIGHT: {
        int dir = ch == '>' || ch == 'l' || ch == KEY_RIGHT ? 1 : -1, n = acbb_whatif_metric_count(a);
        sw(a)->metric = ((sw(a)->metric + dir) % n + n) % n;
        return 1;
    }
    case 'c':
        acbb_app_ask(a, "metric (JSON path, Tab completes): ", acbb_whatif_metric(a, sw(a)->metric, NULL),
                     metric_answer, acbb_metric_choice);
        return 1;
    default: return 0;
    }
}

static const acbb_help_line help[] = {
    { "s", "choose the key (Tab completes)" },
    { "e", "edit the range lo:hi:n" },
    { "< > h l", "cycle the metric" },
    { "c", "type a metric (JSON path)" },
    { "r  Enter", "sweep the edited scene" },
    { "g", "export the chart (PNG+SVG)" },
    { "x  Esc", "cancel the sweep" },
    { "j k PgUp/Dn", "scroll the points" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_sweep = {
    .name = "Sweep", .key = '9', .draw = draw, .on_key = on_key, .enter = enter, .help = help,
    .hint = "s key  e range  </> metric  c type metric  r sweep  x/Esc cancel  ? help",
    .init = init, .free = sweep_free, .wake_fd = wake_fd, .wake = wake, .poll = poll, .drop = drop,
    .running = running, .job_subject = "A sweep", .job_noun = "sweep",
};
