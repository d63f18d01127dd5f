/* acbb TUI — the Preload screen (issue 19 item 4): the preload window of
 * the edited scene, `acbb preload-map`'s engine call (preload_map.h) in
 * the background, drawn as a text chart that reads without colour: one
 * row per speed, one column per preload, `#` where the preload is inside
 * the window (no skid from below, the user's limits and no runaway from
 * above), a letter naming why elsewhere, the window in N at the right.
 * s and e edit the ranges, l the limits, r runs, x cancels, g exports the
 * chart through gnuplot as `acbb preload-map --plot` draws it. */
#include <curses.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "acbb/tools/plot.h"
#include "acbb/tools/preload_map.h"
#include "acbb/units.h"
#include "results.h"
#include "export.h"
#include "screens.h"

#define PM_SPEEDS 12    /* chart rows: the heading, the rows and the axis fit a 24-row terminal */
#define PM_PRELOADS 24  /* 2 columns each: speed + 48 + window column stay within 80 */

typedef struct {
    acbb_pmap_opts o;   /* the grid and limits this result was run with */
    int rows_done;      /* speed rows finished (the map runs one speed at a time) */
    acbb_pmap_cell cells[PM_SPEEDS * PM_PRELOADS];  /* speed-major, stride o.n_preloads */
    acbb_pmap_row rows[PM_SPEEDS];
} pm_result;

struct acbb_pmap_ui {
    acbb_job *job;
    acbb_scene scene;   /* the job's copy of the edited scene */
    pm_result work;     /* private to the job's thread while it runs */
    pm_result pub;      /* published under the job's lock */
    acbb_job_info info; /* the UI's copies, once per frame */
    pm_result view;
    unsigned long seen_run;
    unsigned long hidden_run; /* a run of a preset no longer open (results.c) */
    acbb_pmap_opts next; /* what r runs: the ranges and limits as typed */
    int chosen;          /* the ranges were typed (else they follow the scene) */
};

/* ---- the job ---- */

/* One acbb_preload_map call per speed (the engine call has no progress
 * callback; a speed's cells still run on every core), publishing each
 * finished row so the chart fills as it runs. Rows are per speed in the
 * engine too (rows_of), so the split changes no number. */
static acbb_status run(void *ctx, const atomic_int *cancel, acbb_error *err)
{
    struct acbb_pmap_ui *p = ctx;
    pm_result *w = &p->work;
    int np = w->o.n_preloads;
    for (int s = 0; s < w->o.n_speeds; s++) {
        acbb_pmap_opts o = w->o;
        o.speed_lo = o.speed_hi = acbb_pmap_axis(w->o.speed_lo, w->o.speed_hi, w->o.n_speeds, s);
        o.n_speeds = 1;
        o.cancel = cancel;
        acbb_status rc = acbb_preload_map(&p->scene, &o, &w->cells[s * np], &w->rows[s], err);
        if (rc == ACBB_EINVAL) return rc;
        w->rows_done = s + 1;
        acbb_job_lock(p->job);
        p->pub = *w;
        acbb_job_unlock(p->job);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

static void begin(void *ctx)
{
    struct acbb_pmap_ui *p = ctx;
    p->pub = p->work;
}

static void end(void *ctx, acbb_status rc)
{
    (void)rc;
    struct acbb_pmap_ui *p = ctx;
    p->pub = p->work;
}

static const acbb_job_fns k_fns = { run, begin, end };

/* The default grid: speeds 0.25..1.5 x the scene's, preloads 0.25..2.5 x
 * its assembly preload (100..1000 N when it has none), no limits beyond
 * skid and runaway (as `acbb preload-map` without --max-rise ...). */
static void defaults(const acbb_scene *s, acbb_pmap_opts *o)
{
    double n = s->inner_speed / ACBB_RPM, f = s->preload_force;
    if (!(n > 0.0)) n = 10000.0;
    o->speed_lo = round(0.25 * n);
    o->speed_hi = round(1.5 * n);
    o->n_speeds = 6;
    o->preload_lo = f > 0.0 ? round(0.25 * f) : 100.0;
    o->preload_hi = f > 0.0 ? round(2.5 * f) : 1000.0;
    o->n_preloads = 10;
}

extern const acbb_screen acbb_screen_preload;

/* This screen's state (its init made it). */
static struct acbb_pmap_ui *pm(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_preload);
}

static acbb_status make(void *p, acbb_error *err)
{
    return acbb_job_new(&((struct acbb_pmap_ui *)p)->job, "preload map", err);
}

static acbb_status init(acbb_app *a, void **state, acbb_error *err)
{
    acbb_status rc = acbb_screen_state_new(state, sizeof(struct acbb_pmap_ui), make, err);
    if (rc == ACBB_OK) defaults(&a->ed.scene, &((struct acbb_pmap_ui *)*state)->next);
    return rc;
}

static void pm_free(void *state)
{
    struct acbb_pmap_ui *p = state;
    if (!p) return;
    acbb_job_free(p->job);
    free(p);
}

static int wake_fd(const acbb_app *a) { return acbb_job_wake_fd(pm(a)->job); }

static void wake(acbb_app *a) { acbb_job_drain_wake(pm(a)->job); }

/* Cells of row s inside the window (flags 0, between the row's lo and hi). */
static int in_window(const acbb_pmap_cell *c, const acbb_pmap_row *r)
{
    return c->flags == 0 && r->lo_N >= 0 && c->preload_N >= r->lo_N && c->preload_N <= r->hi_N;
}

/* A row the cancel cut short: its window stands on part of the row. */
static int row_cut(const pm_result *v, int s)
{
    for (int k = 0; k < v->o.n_preloads; k++)
        if (v->cells[s * v->o.n_preloads + k].status == ACBB_CANCELLED) return 1;
    return 0;
}

/* Speed rows finished whole. */
static int rows_whole(const pm_result *v)
{
    int n = 0;
    for (int s = 0; s < v->rows_done; s++) n += !row_cut(v, s);
    return n;
}

static void poll(acbb_app *a)
{
    struct acbb_pmap_ui *p = pm(a);
    acbb_job_read(p->job, &p->info, &p->view, &p->pub, sizeof p->view);
    int edited = acbb_results_stale(a, &acbb_screen_preload, &p->scene, p->info.phase > ACBB_JOB_RUNNING);
    if (p->info.run_id == p->hidden_run || edited) { /* reads as never started */
        memset(&p->info, 0, sizeof p->info);
        memset(&p->view, 0, sizeof p->view);
    }
    if (p->info.phase <= ACBB_JOB_RUNNING || p->info.run_id == p->seen_run) return;
    p->seen_run = p->info.run_id;
    int with = 0;
    for (int s = 0; s < p->view.rows_done; s++) with += p->view.rows[s].lo_N >= 0 && !row_cut(&p->view, s);
    char took[16];
    acbb_fmt_duration(p->info.ended_s - p->info.started_s, took, sizeof took);
    if (p->info.phase == ACBB_JOB_DONE)
        acbb_app_msg(a, with ? ACBB_ROLE_OK : ACBB_ROLE_WARN,
                     "preload map done: a window at %d of %d speeds, in %s (g exports the chart)", with,
                     p->view.o.n_speeds, took);
    else if (p->info.phase == ACBB_JOB_CANCELLED)
        acbb_app_msg(a, ACBB_ROLE_WARN, "preload map cancelled after %d of %d speeds", rows_whole(&p->view),
                     p->view.o.n_speeds);
    else
        acbb_app_msg(a, ACBB_ROLE_ERROR, "preload map failed: %s", p->info.message);
}

static void drop(acbb_app *a)
{
    struct acbb_pmap_ui *p = pm(a);
    acbb_job_cancel(p->job);
    acbb_job_read(p->job, &p->info, &p->view, &p->pub, sizeof p->view);
    p->hidden_run = p->info.run_id;
}

static int running(const acbb_app *a)
{
    return pm(a)->info.phase == ACBB_JOB_RUNNING;
}

/* ---- ranges and limits ---- */

/* "LO:HI:N" with 0 < LO <= HI and N whole in 1..max: 1, else 0 and a message. */
static int parse_axis(acbb_app *a, const char *t, const char *what, int max, double *lo, double *hi,
                      int *n)
{
    char *e1, *e2, *e3;
    double l = strtod(t, &e1), h = *e1 == ':' ? strtod(e1 + 1, &e2) : NAN;
    long k = isfinite(h) && *e2 == ':' ? strtol(e2 + 1, &e3, 10) : 0;
    if (!isfinite(h) || *e2 != ':' || *e3 || !(l > 0.0) || !(h >= l) || !isfinite(l)) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s %s refused: LO:HI:N with 0 < LO <= HI, e.g. %s", what, t,
                     max == PM_SPEEDS ? "4000:16000:7" : "50:500:10");
        return 0;
    }
    if (k < 1 || k > max) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s %s refused: N 1..%d here (acbb preload-map: 1..%d)", what, t,
                     max, ACBB_PMAP_MAX_AXIS);
        return 0;
    }
    *lo = l;
    *hi = h;
    *n = (int)k;
    return 1;
}

static void speeds_answer(acbb_app *a, const char *text)
{
    acbb_pmap_opts *o = &pm(a)->next;
    if (text[0] && parse_axis(a, text, "speeds", PM_SPEEDS, &o->speed_lo, &o->speed_hi, &o->n_speeds)) {
        pm(a)->chosen = 1;
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "speeds %s rpm (r runs the map)", text);
    }
}

static void preloads_answer(acbb_app *a, const char *text)
{
    acbb_pmap_opts *o = &pm(a)->next;
    if (text[0] &&
        parse_axis(a, text, "preloads", PM_PRELOADS, &o->preload_lo, &o->preload_hi, &o->n_preloads)) {
        pm(a)->chosen = 1;
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "preloads %s N (r runs the map)", text);
    }
}

/* "RISE:LIFE:S0" (K, h, -), each >= 0, 0 = not checked. */
static void limits_answer(acbb_app *a, const char *text)
{
    if (!text[0]) return;
    double v[3];
    const char *t = text;
    char *e = NULL;
    for (int i = 0; i < 3; i++) {
        v[i] = strtod(t, &e);
        if (e == t || !(v[i] >= 0.0) || !isfinite(v[i]) || *e != (i < 2 ? ':' : '\0')) {
            acbb_app_msg(a, ACBB_ROLE_ERROR, "limits %s refused: RISE_K:LIFE_h:S0, each >= 0 "
                         "(0 = not checked), e.g. 40:20000:2", text);
            return;
        }
        t = e + 1;
    }
    acbb_pmap_opts *o = &pm(a)->next;
    o->max_rise_K = v[0];
    o->min_life_h = v[1];
    o->min_s0 = v[2];
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "limits %s (r runs the map)", text);
}

static void fmt_axis(double lo, double hi, int n, char *buf, size_t len)
{
    snprintf(buf, len, "%g:%g:%d", lo, hi, n);
}

static void fmt_limits(const acbb_pmap_opts *o, char *buf, size_t len)
{
    snprintf(buf, len, "%g:%g:%g", o->max_rise_K, o->min_life_h, o->min_s0);
}

/* The ranges follow the scene until typed (a newly opened preset). */
static void enter(acbb_app *a)
{
    struct acbb_pmap_ui *p = pm(a);
    if (!p->chosen) defaults(&a->ed.scene, &p->next);
}

/* ---- starting, cancelling, exporting ---- */

static void start(acbb_app *a)
{
    struct acbb_pmap_ui *p = pm(a);
    acbb_error err = { { 0 } };
    if (!acbb_job_claim(p->job, &err)) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s", err.msg);
        return;
    }
    p->scene = a->ed.scene;
    memset(&p->work, 0, sizeof p->work);
    p->work.o = p->next;
    if (acbb_job_start(p->job, &k_fns, p, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", err.msg);
        return;
    }
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "preload map started on %s%s (x cancels)", acbb_editor_name(&a->ed),
                 a->ed.modified ? "*" : "");
}

static int cancel(acbb_app *a)
{
    if (!acbb_job_cancel(pm(a)->job)) return 0;
    acbb_app_msg(a, ACBB_ROLE_WARN, "cancelling the preload map ...");
    return 1;
}

/* dir/preload_window.png and .svg: `acbb preload-map --plot`'s chart. */
static void export_chart(acbb_app *a)
{
    const pm_result *v = &pm(a)->view;
    if (pm(a)->info.phase == ACBB_JOB_RUNNING || v->rows_done == 0) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s", v->rows_done ? "the map is still running"
                                                            : "no preload map to plot (r runs one)");
        return;
    }
    /* The CLI's chart (acbb_plot_pmap_chart): a window's end at the grid's
     * first or last preload is "no limit inside the grid", not a limit; a
     * row the cancel cut short has no window. */
    acbb_pmap_row rows[PM_SPEEDS];
    for (int s = 0; s < v->rows_done; s++) {
        rows[s] = v->rows[s];
        if (row_cut(v, s)) rows[s].lo_N = rows[s].hi_N = -1.0;
    }
    acbb_plot_pmap c;
    acbb_plot_xy px;
    acbb_plot_pmap_chart(&v->o, rows, (size_t)v->rows_done, &c, &px);
    char png[PATH_MAX + 32], svg[PATH_MAX + 32];
    acbb_error err = { { 0 } };
    if (acbb_export_xy(a->plot_dir, "preload_window", &px, 1000, 600, png, svg, sizeof png, &err) != ACBB_OK)
        acbb_app_msg(a, ACBB_ROLE_ERROR, "plot export failed: %s", err.msg);
    else
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %s and %s", png, svg);
}

/* ---- drawing ---- */

/* One cell: # inside the window, . inside the limits but off the window's
 * run, a letter for the first reason out (the CLI's table), - not run. */
static char cell_char(const acbb_pmap_cell *c, const acbb_pmap_row *r)
{
    if (c->status == ACBB_CANCELLED) return '-';
    if (in_window(c, r)) return '#';
    const char *v = acbb_pmap_verdict(c);
    return !strcmp(v, "ok") ? '.' : !strcmp(v, "low_s0") ? '0' : !strcmp(v, "runaway") ? 'R'
           : !strcmp(v, "failed") ? 'x' : !strcmp(v, "short_life") ? 'l' : v[0];
}

static void draw_heading(acbb_app *a, acbb_rect b)
{
    struct acbb_pmap_ui *p = pm(a);
    char sp[48], pl[48], lim[64];
    fmt_axis(p->next.speed_lo, p->next.speed_hi, p->next.n_speeds, sp, sizeof sp);
    fmt_axis(p->next.preload_lo, p->next.preload_hi, p->next.n_preloads, pl, sizeof pl);
    fmt_limits(&p->next, lim, sizeof lim);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "Preload window  speeds %s rpm  preloads %s N  limits %s",
             sp, pl, lim);
    const pm_result *v = &p->view;
    char took[16];
    acbb_fmt_duration(p->info.ended_s - p->info.started_s, took, sizeof took);
    int y = b.y + 1;
    switch (p->info.phase) {
    case ACBB_JOB_IDLE:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_NORMAL,
                 "s speeds  e preloads  l limits (rise K:life h:s0, 0 off)  r maps the scene");
        break;
    case ACBB_JOB_RUNNING:
        acbb_draw_job_line(a, y, b.x, b.w, p->info.cancel_requested, p->info.started_s,
                           (size_t)v->rows_done, (size_t)v->o.n_speeds, "speeds");
        break;
    case ACBB_JOB_DONE:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_OK, "done: %d speeds x %d preloads in %s", v->o.n_speeds,
                 v->o.n_preloads, took);
        break;
    case ACBB_JOB_CANCELLED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_WARN, "cancelled after %d of %d speeds; r reruns", rows_whole(v),
                 v->o.n_speeds);
        break;
    case ACBB_JOB_FAILED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_ERROR, "failed: %s", p->info.message);
        break;
    }
}

/* The map's limits line: what bounds the window in the result shown. */
static void draw_limits(acbb_app *a, int y, acbb_rect b, const acbb_pmap_opts *o)
{
    char t[160];
    int n = snprintf(t, sizeof t, "%swindow: no skid (gyroscopic/traction <= 1)",
                     o->spring ? "spring preload  " : "");
    if (o->max_rise_K > 0) n += snprintf(t + n, sizeof t - (size_t)n, ", rise <= %g K", o->max_rise_K);
    if (o->min_life_h > 0) n += snprintf(t + n, sizeof t - (size_t)n, ", Lnm >= %g h", o->min_life_h);
    if (o->min_s0 > 0) n += snprintf(t + n, sizeof t - (size_t)n, ", s0 >= %g", o->min_s0);
    snprintf(t + n, sizeof t - (size_t)n, ", no runaway");
    acbb_put(a, y, b.x, b.w, ACBB_ROLE_NORMAL, "%s", t);
    acbb_put(a, y + 1, b.x, b.w, ACBB_ROLE_DIM,
             "# window  . ok  s skid  h hot  l life  0 s0  R runaway  x failed  - not run");
}

static void draw_row(acbb_app *a, int y, acbb_rect b, const pm_result *v, int s)
{
    const acbb_pmap_row *r = &v->rows[s];
    int np = v->o.n_preloads;
    char cells[2 * PM_PRELOADS + 1];
    double speed = acbb_pmap_axis(v->o.speed_lo, v->o.speed_hi, v->o.n_speeds, s);
    if (s >= v->rows_done) {
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_DIM, "%8.0f  %s", speed,
                 pm(a)->info.phase == ACBB_JOB_RUNNING ? "running ..." : "-");
        return;
    }
    for (int k = 0; k < np; k++) {
        cells[2 * k] = cell_char(&v->cells[s * np + k], r);
        cells[2 * k + 1] = ' ';
    }
    cells[2 * np] = '\0';
    char win[40];
    if (row_cut(v, s)) snprintf(win, sizeof win, "cut short");
    else if (r->lo_N >= 0) snprintf(win, sizeof win, "%g..%g", r->lo_N, r->hi_N);
    else snprintf(win, sizeof win, "none");
    acbb_put(a, y, b.x, b.w, r->lo_N >= 0 && !row_cut(v, s) ? ACBB_ROLE_NORMAL : ACBB_ROLE_WARN, "%8.0f  %s %s", speed,
             cells, win);
}

static void draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    draw_heading(a, b);
    const pm_result *v = &pm(a)->view;
    if (pm(a)->info.phase == ACBB_JOB_IDLE) {
        const char *note = acbb_results_note(a, &acbb_screen_preload);
        acbb_put_wrap(a, b.y + 3, b.x + 2, b.w - 2, 2, ACBB_ROLE_DIM, note ? note : "(no preload map yet: r runs one)");
        return;
    }
    draw_limits(a, b.y + 2, b, &v->o);
    int np = v->o.n_preloads, gw = 2 * np - 1;
    acbb_put(a, b.y + 4, b.x, b.w, ACBB_ROLE_HEADER, "%8s  %-*s window N", "n rpm", gw + 1,
             np > 4 ? "preload ->" : "preload");
    int y = b.y + 5;
    for (int s = 0; s < v->o.n_speeds && y < b.y + b.h - 1; s++) draw_row(a, y++, b, v, s);
    /* The preload axis under the cells: its ends under the first and last column. */
    char axis[2 * PM_PRELOADS + 48];
    int n = snprintf(axis, sizeof axis, "%g", v->o.preload_lo);
    if (np > 1) snprintf(axis + n, sizeof axis - (size_t)n, "%*g N", gw - n > 1 ? gw - n : 1,
                         v->o.preload_hi);
    acbb_put(a, y, b.x, b.w, ACBB_ROLE_DIM, "%8s  %s", "N", axis);
}

/* ---- keys ---- */

static int on_key(acbb_app *a, int ch)
{
    struct acbb_pmap_ui *p = pm(a);
    char init[64];
    switch (ch) {
    case 'r': case '\n': case '\r': case KEY_ENTER: start(a); return 1;
    case 'x':
        if (!cancel(a)) acbb_app_msg(a, ACBB_ROLE_WARN, "no preload map running (r starts one)");
        return 1;
    case 27: return cancel(a); /* otherwise Esc clears the message as everywhere */
    case 's':
        fmt_axis(p->next.speed_lo, p->next.speed_hi, p->next.n_speeds, init, sizeof init);
        acbb_app_ask(a, "speeds rpm LO:HI:N: ", init, speeds_answer, NULL);
        return 1;
    case 'e':
        fmt_axis(p->next.preload_lo, p->next.preload_hi, p->next.n_preloads, init, sizeof init);
        acbb_app_ask(a, "preloads N LO:HI:N: ", init, preloads_answer, NULL);
        return 1;
    case 'l':
        fmt_limits(&p->next, init, sizeof init);
        acbb_app_ask(a, "limits RISE_K:LIFE_h:S0 (0 = not checked): ", init, limits_answer, NULL);
        return 1;
    case 'g': export_chart(a); return 1;
    case 'k':
        p->next.spring = !p->next.spring;
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "%s (r runs the map)", p->next.spring
                     ? "spring preload: a constant axial force" : "rigid preload: set at rest, held");
        return 1;
    default: return 0;
    }
}

static const acbb_help_line help[] = {
    { "s", "edit the speeds LO:HI:N (rpm, N up to 12)" },
    { "e", "edit the preloads LO:HI:N (N, N up to 24)" },
    { "l", "edit the limits RISE_K:LIFE_h:S0 (0 = not checked)" },
    { "r  Enter", "map the edited scene (as acbb preload-map)" },
    { "x  Esc", "cancel the map" },
    { "g", "export the window chart (PNG+SVG) to the plot directory" },
    { "k", "spring (constant-force) or rigid preload (acbb preload-map --spring)" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_preload = {
    .name = "Preload", .key = 'P', .draw = draw, .on_key = on_key, .enter = enter, .help = help,
    .hint = "s speeds  e preloads  l limits  r map  x/Esc cancel  g export  ? help",
    .init = init, .free = pm_free, .wake_fd = wake_fd, .wake = wake, .poll = poll, .drop = drop,
    .running = running, .job_subject = "The preload map", .job_noun = "preload map",
};
