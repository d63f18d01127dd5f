/* acbb TUI — the Sensitivity screen: which uncertain input moves a result
 * (acbb_sensitivity_run in the background on the open, edited scene; the
 * metric from the what-if menu, optionally its TE - WTE difference, and
 * Morris elementary effects on request). Shows the progress, then the
 * one-at-a-time table sorted by effect with a text tornado: each input's
 * change of the metric at the low end ('-') and the high end ('=') of its
 * plausible range, left of the bar when it lowers the metric, right when
 * it raises it, all on one scale (the largest effect fills a half). */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "export.h"
#include "results.h"
#include "screens.h"

#define NUM_W 9        /* "at low", "at high" */
#define EFFECT_W 8
#define FLIPS_W 10     /* "FLIPS SIGN" */
#define INPUT_W_MIN 20    /* at 80 columns: 20 + the numbers + a 9|9 tornado */
#define INPUT_W_MAX 36
#define HALF_MAX 30

static const int morris_steps[] = { 0, 4, 10 };
#define MORRIS_N (int)(sizeof morris_steps / sizeof morris_steps[0])

/* This screen's own state (screens.h init): the job and what it shows. */
typedef struct {
    acbb_sensjob *job;
    acbb_sens_view v;              /* copy of its published state, once per frame */
    int metric, delta_te, morris_r, top;
    unsigned long seen_run;        /* run whose end was already announced */
    unsigned long hidden_run;      /* a run of a preset no longer open (results.c) */
    acbb_scene ran_on;             /* the scene its last job started on (results.c) */
} sens_ui;

extern const acbb_screen acbb_screen_sensitivity;

static sens_ui *sn(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_sensitivity);
}

/* ---- starting, following, cancelling ---- */

static void start(acbb_app *a)
{
    acbb_sens_opts o = { .oat = 1, .delta_te = sn(a)->delta_te, .morris_r = sn(a)->morris_r };
    snprintf(o.metric, sizeof o.metric, "%s", acbb_whatif_metric(a, sn(a)->metric, NULL));
    acbb_error err = { { 0 } };
    if (acbb_sensjob_start(sn(a)->job, &a->ed.scene, &o, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", err.msg);
        return;
    }
    sn(a)->top = 0;
    sn(a)->ran_on = a->ed.scene;
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "sensitivity of %s%s started on %s%s (x cancels)",
                 o.delta_te ? "TE-WTE " : "", o.metric, acbb_editor_name(&a->ed),
                 a->ed.modified ? "*" : "");
}

/* Announce the end of a run (once per run). */
static void follow(acbb_app *a)
{
    const acbb_sens_view *v = &sn(a)->v;
    if (v->job.phase <= ACBB_JOB_RUNNING || v->job.run_id == sn(a)->seen_run) return;
    sn(a)->seen_run = v->job.run_id;
    if (v->job.phase == ACBB_JOB_DONE)
        acbb_app_msg(a, v->res.failed ? ACBB_ROLE_WARN : ACBB_ROLE_OK,
                     "sensitivity done: %zu inputs, %zu runs, %zu failed", v->res.n, v->res.runs,
                     v->res.failed);
    else if (v->job.phase == ACBB_JOB_CANCELLED)
        acbb_app_msg(a, ACBB_ROLE_WARN, "sensitivity cancelled after %zu of %zu runs", v->done, v->total);
    else
        acbb_app_msg(a, ACBB_ROLE_ERROR, "sensitivity failed: %s", v->job.message);
}

/* ---- the job's lifecycle (screens.h) ---- */

static acbb_status make(void *p, acbb_error *err) { return acbb_sensjob_new(&((sens_ui *)p)->job, err); }

static acbb_status init(acbb_app *a, void **state, acbb_error *err)
{
    (void)a;
    return acbb_screen_state_new(state, sizeof(sens_ui), make, err);
}

static void sens_free(void *state)
{
    sens_ui *p = state;
    if (!p) return;
    acbb_sensjob_free(p->job);
    free(p);
}

static int wake_fd(const acbb_app *a) { return acbb_job_wake_fd(acbb_sensjob_job(sn(a)->job)); }

static void wake(acbb_app *a) { acbb_job_drain_wake(acbb_sensjob_job(sn(a)->job)); }

static void poll(acbb_app *a)
{
    sens_ui *p = sn(a);
    acbb_sensjob_read(p->job, &p->v);
    if (p->v.job.run_id == p->hidden_run ||
        acbb_results_stale(a, &acbb_screen_sensitivity, &p->ran_on, p->v.job.phase > ACBB_JOB_RUNNING))
        memset(&p->v, 0, sizeof p->v);
    follow(a);
}

static void drop(acbb_app *a)
{
    sens_ui *p = sn(a);
    acbb_job_cancel(acbb_sensjob_job(p->job));
    acbb_sensjob_read(p->job, &p->v); /* a run started since the last frame is hidden too */
    p->hidden_run = p->v.job.run_id;
}

static int running(const acbb_app *a) { return sn(a)->v.job.phase == ACBB_JOB_RUNNING; }

static int cancel(acbb_app *a)
{
    if (!acbb_job_cancel(acbb_sensjob_job(sn(a)->job))) return 0;
    acbb_app_msg(a, ACBB_ROLE_WARN, "cancelling the sensitivity run ...");
    return 1;
}

static void metric_answer(acbb_app *a, const char *text)
{
    if (text[0] && acbb_whatif_metric_set(a, text, &sn(a)->metric))
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "metric %s", text);
}

/* ---- drawing ---- */

static void draw_heading(acbb_app *a, acbb_rect b)
{
    const acbb_sens_view *v = &sn(a)->v;
    const char *label, *path = acbb_whatif_metric(a, sn(a)->metric, &label);
    char unit[16], took[16];
    acbb_metric_unit(path, unit, sizeof unit);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "Sensitivity of %s%s [%s]  d TE-WTE: %s  y Morris: %s%.0d",
             sn(a)->delta_te ? "TE-WTE " : "", label, unit, sn(a)->delta_te ? "on" : "off",
             sn(a)->morris_r ? "r=" : "off", sn(a)->morris_r);
    int y = b.y + 1;
    acbb_fmt_duration(v->job.ended_s - v->job.started_s, took, sizeof took);
    switch (v->job.phase) {
    case ACBB_JOB_IDLE:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_NORMAL,
                 "< > metric  d TE-WTE  y Morris  r/Enter runs it on the edited scene");
        if (acbb_results_note(a, &acbb_screen_sensitivity))
            acbb_put_wrap(a, y + 1, b.x, b.w, 2, ACBB_ROLE_DIM, acbb_results_note(a, &acbb_screen_sensitivity));
        break;
    case ACBB_JOB_RUNNING:
        acbb_draw_job_line(a, y, b.x, b.w, v->job.cancel_requested, v->job.started_s, v->done,
                           v->total, "runs");
        break;
    case ACBB_JOB_DONE:
        if (!v->res.ok0)
            acbb_put(a, y, b.x, b.w, ACBB_ROLE_ERROR, "the run at the scene's values failed: %s",
                     v->res.fail0);
        else
            acbb_put(a, y, b.x, b.w, v->res.failed ? ACBB_ROLE_WARN : ACBB_ROLE_OK,
                     "done in %s: %zu runs, %zu failed; at the scene's values %.6g %s", took,
                     v->res.runs, v->res.failed, v->res.y0, unit);
        break;
    case ACBB_JOB_CANCELLED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_WARN, "cancelled after %zu of %zu runs; r reruns", v->done,
                 v->total);
        break;
    case ACBB_JOB_FAILED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_ERROR, "failed: %s", v->job.message);
        break;
    }
}

typedef struct {
    int name_w, half;          /* columns of the input; cells of a tornado half */
    double scale;              /* the largest effect: a full half */
    int morris;                /* mu*, sigma instead of the tornado */
    int full;                  /* every section.key fits: show them whole */
} cols;

static cols columns(const acbb_sens_result *res, int w)
{
    cols c = { .morris = res->morris_r > 0 };
    int fixed = 1 + NUM_W + 1 + NUM_W + 1 + EFFECT_W + 1 + FLIPS_W + 1;
    int rest = w - fixed - INPUT_W_MIN; /* the tornado's, then the name's */
    c.half = (rest - 1) / 2;
    if (c.half > HALF_MAX) c.half = HALF_MAX;
    if (c.half < 0) c.half = 0;
    c.name_w = w - fixed - (2 * c.half + 1);
    if (c.name_w > INPUT_W_MAX) c.name_w = INPUT_W_MAX;
    c.full = 1;
    for (size_t i = 0; i < res->n; i++) {
        if (isfinite(res->rows[i].effect) && res->rows[i].effect > c.scale) c.scale = res->rows[i].effect;
        if ((int)strlen(res->rows[i].in.key) > c.name_w) c.full = 0;
    }
    return c;
}

/* The input's name: section.key when every one fits, else the key alone,
 * cut with a '~' when even that is too long. */
static void input_name(const char *key, const cols *c, char *buf, size_t n)
{
    const char *dot = strchr(key, '.');
    const char *name = c->full || !dot ? key : dot + 1;
    if ((int)strlen(name) <= c->name_w) snprintf(buf, n, "%s", name);
    else snprintf(buf, n, "%.*s~", c->name_w - 1, name);
}

/* One end's cells on the tornado: `fill` from the centre towards its side. */
static void tornado_end(char *bar, int half, double d, double scale, char fill)
{
    if (!isfinite(d) || !(scale > 0)) return;
    int cells = (int)lround(fabs(d) / scale * half);
    for (int k = 1; k <= cells && k <= half; k++) bar[d < 0 ? half - k : half + k] = fill;
}

static void tornado(const acbb_sens_row *r, double y0, const cols *c, char *bar)
{
    memset(bar, ' ', (size_t)(2 * c->half + 1));
    bar[2 * c->half + 1] = '\0';
    bar[c->half] = '|';
    double dl = r->ok_lo ? r->y_lo - y0 : NAN, dh = r->ok_hi ? r->y_hi - y0 : NAN;
    /* The longer end first, so the shorter shows on top of it. */
    int hi_first = !(fabs(dl) >= fabs(dh)) && isfinite(dh);
    tornado_end(bar, c->half, hi_first ? dh : dl, c->scale, hi_first ? '=' : '-');
    tornado_end(bar, c->half, hi_first ? dl : dh, c->scale, hi_first ? '-' : '=');
}

static void fmt_end(int ok, double v, char *buf, size_t n)
{
    if (ok) snprintf(buf, n, "%.5g", v);
    else snprintf(buf, n, "failed");
}

static void draw_row(acbb_app *a, int y, acbb_rect r, const cols *c, const acbb_sens_row *row)
{
    char name[64], lo[24], hi[24], eff[24], tail[2 * HALF_MAX + 8];
    input_name(row->in.key, c, name, sizeof name);
    fmt_end(row->ok_lo, row->y_lo, lo, sizeof lo);
    fmt_end(row->ok_hi, row->y_hi, hi, sizeof hi);
    /* no effect measured (its runs failed) is not "no effect" */
    if (row->ok_effect) snprintf(eff, sizeof eff, "%.3g", row->effect);
    else snprintf(eff, sizeof eff, "-");
    if (c->morris && row->n_ee > 0) snprintf(tail, sizeof tail, "%9.3g %9.3g", row->mu_star, row->sigma);
    else if (c->morris) snprintf(tail, sizeof tail, "%9s %9s", "-", "-");
    else tornado(row, sn(a)->v.res.y0, c, tail);
    acbb_put(a, y, r.x, r.w, row->flips ? ACBB_ROLE_WARN : ACBB_ROLE_NORMAL, "%-*s %*s %*s %*s %-*s %s",
             c->name_w, name, NUM_W, lo, NUM_W, hi, EFFECT_W, eff, FLIPS_W, row->flips ? "FLIPS SIGN" : "",
             tail);
}

static void draw_table(acbb_app *a, acbb_rect r)
{
    const acbb_sens_view *v = &sn(a)->v;
    if (!v->have_result || r.h < 2) {
        if (v->job.phase == ACBB_JOB_RUNNING)
            acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_DIM, "(the table comes when every run has finished)");
        return;
    }
    cols c = columns(&v->res, r.w);
    char tail[2 * HALF_MAX + 8];
    if (c.morris) snprintf(tail, sizeof tail, "%9s %9s", "mu*", "sigma");
    else snprintf(tail, sizeof tail, "%*s|%-*s", c.half, "low -", c.half, "= high");
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%-*s %*s %*s %*s %-*s %s", c.name_w, "input", NUM_W,
             "at low", NUM_W, "at high", EFFECT_W, "effect", FLIPS_W, "", tail);
    int rows = r.h - 1, n = (int)v->res.n;
    if (sn(a)->top > n - rows) sn(a)->top = n - rows;
    if (sn(a)->top < 0) sn(a)->top = 0;
    for (int k = 0; k < rows && sn(a)->top + k < n; k++)
        draw_row(a, r.y + 1 + k, r, &c, &v->res.rows[sn(a)->top + k]);
}

static void draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    draw_heading(a, b);
    acbb_rect t = { b.y + 2, b.x, b.h - 2, b.w };
    draw_table(a, t);
}

/* ---- export ---- */

/* g: the tornado chart of the finished run, as `acbb sensitivity --plot`
 * draws it (issue 29 item 8: g exported the Run screen's plots instead). */
static void export_plot(acbb_app *a)
{
    const acbb_sens_view *v = &sn(a)->v;
    if (!v->have_result || v->res.n == 0) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s", v->job.phase == ACBB_JOB_RUNNING
                     ? "the sensitivity run is still running" : "no sensitivity result to plot (r runs one)");
        return;
    }
    acbb_tornado_bar bars[ACBB_SENS_MAX];
    for (size_t i = 0; i < v->res.n; i++)
        bars[i] = (acbb_tornado_bar){ v->res.rows[i].in.key, v->res.rows[i].ok_lo ? v->res.rows[i].y_lo : NAN,
                                      v->res.rows[i].ok_hi ? v->res.rows[i].y_hi : NAN };
    char metric[ACBB_SENS_METRIC + 16], title[PATH_MAX + 160], png[PATH_MAX + 32], svg[PATH_MAX + 32];
    snprintf(metric, sizeof metric, "%s%s", v->res.metric, v->res.delta_te ? " (TE - WTE)" : "");
    snprintf(title, sizeof title, "%s: %s over each plausible range", acbb_editor_name(&a->ed), metric);
    acbb_error err = { { 0 } };
    if (acbb_export_tornado(a->plot_dir, "sensitivity", bars, v->res.n, v->res.ok0 ? v->res.y0 : NAN, title,
                            metric, png, svg, sizeof png, &err) != ACBB_OK)
        acbb_app_msg(a, ACBB_ROLE_ERROR, "plot export failed: %s", err.msg);
    else
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %s and %s", png, svg);
}

/* ---- keys ---- */

static int on_key(acbb_app *a, int ch)
{
    int page = a->lay.body.h - 3 > 1 ? a->lay.body.h - 3 : 1;
    if (acbb_scroll_key(ch, page, (int)sn(a)->v.res.n, &sn(a)->top)) return 1;
    switch (ch) {
    case 'r': case '\n': case '\r': case KEY_ENTER: start(a); return 1;
    case 'g': export_plot(a); return 1;
    case 'x':
        if (!cancel(a)) acbb_app_msg(a, ACBB_ROLE_WARN, "no sensitivity run (r starts one)");
        return 1;
    case 27: return cancel(a);
    case '<': case '>': case 'h': case 'l': case KEY_LEFT: case KEY_RIGHT: {
        int dir = ch == '>' || ch == 'l' || ch == KEY_RIGHT ? 1 : -1, n = acbb_whatif_metric_count(a);
        sn(a)->metric = ((sn(a)->metric + dir) % n + n) % n;
        return 1;
    }
    case 'c':
        acbb_app_ask(a, "metric (JSON path, Tab completes): ", acbb_whatif_metric(a, sn(a)->metric, NULL),
                     metric_answer, acbb_metric_choice);
        return 1;
    case 'd':
        sn(a)->delta_te = !sn(a)->delta_te;
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "%s", sn(a)->delta_te ? "TE - WTE: two runs per point"
                                                               : "the metric itself (TE as set)");
        return 1;
    case 'y': {
        int i = 0;
        while (i < MORRIS_N && morris_steps[i] != sn(a)->morris_r) i++;
        sn(a)->morris_r = morris_steps[(i + 1) % MORRIS_N];
        acbb_app_msg(a, ACBB_ROLE_NORMAL, sn(a)->morris_r ? "Morris: %d trajectories after the table"
                                                         : "Morris off%.0d", sn(a)->morris_r);
        return 1;
    }
    default: return 0;
    }
}

static const acbb_help_line help[] = {
    { "r  Enter", "run it on the edited scene" },
    { "x  Esc", "cancel the run" },
    { "< > h l", "cycle the metric" },
    { "c", "type a metric (JSON path)" },
    { "d", "metric TE - WTE on/off" },
    { "y", "Morris off/r=4/r=10 (mu* sigma)" },
    { "g", "export the tornado chart (PNG+SVG)" },
    { "j k PgUp/Dn", "scroll the table" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_sensitivity = {
    .name = "Sensitivity", .key = '0', .draw = draw, .on_key = on_key, .help = help,
    .hint = "r run  x/Esc cancel  </> metric  c type metric  d TE-WTE  y Morris  ? help",
    .init = init, .free = sens_free, .wake_fd = wake_fd, .wake = wake, .poll = poll, .drop = drop,
    .running = running, .job_subject = "The sensitivity analysis", .job_noun = "sensitivity analysis",
};
