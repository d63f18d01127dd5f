/* acbb TUI — the accuracy screen: `acbb bench accuracy` for the edited
 * scene, run by the bench thread (bench.h), shown as the CLI's table, the
 * frontier, and an error-vs-time chart (log-log, draw_acc_chart.c). */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acc_chart.h"
#include "results.h"
#include "screens.h"
#include "export.h"

extern const acbb_screen acbb_screen_accuracy;

/* This screen's own state (screens.h init): the benchmark and what it shows. */
typedef struct {
    acbb_bench *job;               /* the benchmark thread's hand-off */
    acbb_bench_state st;           /* copy of its published state, once per frame */
    char scene[256];               /* name of the scene the benchmark ran on */
    unsigned long seen_run;        /* run whose end was already announced */
    unsigned long hidden_run;      /* a run of a preset no longer open (results.c) */
    int top;                       /* first table row shown */
    acbb_scene ran_on;             /* the scene its last job started on (results.c) */
} acc_ui;

static acc_ui *acc(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_accuracy);
}

/* ---- starting, following, cancelling ---- */

void acbb_screen_accuracy_start(acbb_app *a, int with_dynamic)
{
    /* One run per setting: repeats only steady the timings, and the
     * dynamic level alone takes about a minute per run. */
    acbb_accuracy_options o = {
        .knobs = a->acc_knobs,
        .model_levels = with_dynamic ? ACBB_ACCURACY_ALL_LEVELS
                                     : ACBB_ACCURACY_ALL_LEVELS &
                                           ~ACBB_ACCURACY_LEVEL_BIT(ACBB_MODEL_DYNAMIC),
        .repeats = 1,
    };
    acbb_error err = { { 0 } };
    acbb_screen_show(a, acbb_screen_index(&acbb_screen_accuracy));
    if (acbb_bench_start(acc(a)->job, &a->ed.scene, &o, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", err.msg);
        return;
    }
    snprintf(acc(a)->scene, sizeof acc(a)->scene, "%s%s", acbb_editor_name(&a->ed),
             a->ed.modified ? "*" : "");
    acc(a)->top = 0;
    acc(a)->ran_on = a->ed.scene;
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "accuracy benchmark started: %zu settings%s (x cancels)",
                 acbb_accuracy_plan_size(&o), with_dynamic ? " with the dynamic level" : "");
}

/* Announce the end of a benchmark (once per run). */
static void follow(acbb_app *a)
{
    const acbb_bench_state *s = &acc(a)->st;
    if (s->phase == ACBB_BENCH_IDLE || s->phase == ACBB_BENCH_RUNNING ||
        s->run_id == acc(a)->seen_run)
        return;
    acc(a)->seen_run = s->run_id;
    char took[16];
    acbb_fmt_duration(s->ended_s - s->started_s, took, sizeof took);
    if (s->phase == ACBB_BENCH_DONE)
        acbb_app_msg(a, ACBB_ROLE_OK, "accuracy benchmark done: %zu settings in %s (g exports the plot)",
                     s->n, took);
    else if (s->phase == ACBB_BENCH_CANCELLED)
        acbb_app_msg(a, ACBB_ROLE_WARN, "accuracy benchmark cancelled after %zu of %zu settings",
                     s->n, s->total);
    else
        acbb_app_msg(a, ACBB_ROLE_ERROR, "accuracy benchmark failed: %s", s->message);
}

/* ---- the job's lifecycle (screens.h) ---- */

static acbb_status make(void *p, acbb_error *err) { return acbb_bench_new(&((acc_ui *)p)->job, err); }

static acbb_status init(acbb_app *a, void **state, acbb_error *err)
{
    (void)a;
    return acbb_screen_state_new(state, sizeof(acc_ui), make, err);
}

static void acc_free(void *state)
{
    acc_ui *p = state;
    if (!p) return;
    acbb_bench_free(p->job);
    free(p);
}

static int wake_fd(const acbb_app *a) { return acbb_bench_wake_fd(acc(a)->job); }

static void wake(acbb_app *a) { acbb_bench_drain_wake(acc(a)->job); }

static void poll(acbb_app *a)
{
    acc_ui *p = acc(a);
    acbb_bench_read(p->job, &p->st);
    if (p->st.run_id == p->hidden_run ||
        acbb_results_stale(a, &acbb_screen_accuracy, &p->ran_on, p->st.phase > ACBB_BENCH_RUNNING))
        memset(&p->st, 0, sizeof p->st);
    follow(a);
}

static void drop(acbb_app *a)
{
    acc_ui *p = acc(a);
    acbb_bench_cancel(p->job);
    acbb_bench_read(p->job, &p->st); /* a run started since the last frame is hidden too */
    p->hidden_run = p->st.run_id;
}

static int running(const acbb_app *a) { return acc(a)->st.phase == ACBB_BENCH_RUNNING; }

static int cancel(acbb_app *a)
{
    if (!acbb_bench_cancel(acc(a)->job)) return 0;
    acbb_app_msg(a, ACBB_ROLE_WARN, "cancelling the accuracy benchmark ...");
    return 1;
}

/* ---- export ---- */

static void export_plot(acbb_app *a)
{
    if (acc(a)->st.phase != ACBB_BENCH_DONE) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s",
                     acc(a)->st.phase == ACBB_BENCH_RUNNING ? "the benchmark is still running"
                                                        : "no finished benchmark to plot (b runs one)");
        return;
    }
    /* Say so before gnuplot runs: the export takes a moment. */
    acbb_app_msg(a, ACBB_ROLE_WARN, "exporting the accuracy plot to %s ...", a->plot_dir);
    move(a->lay.message.y, 0);
    clrtoeol();
    acbb_put(a, a->lay.message.y, 0, a->lay.message.w, ACBB_ROLE_WARN, "%s", a->msg);
    wnoutrefresh(stdscr);
    doupdate();
    char title[320];
    snprintf(title, sizeof title, "acbb bench accuracy %s (1 run per setting)", acc(a)->scene);
    acbb_error err = { { 0 } };
    int written = 0;
    char sfx[16];
    if (acbb_export_accuracy(a->plot_dir, acc(a)->st.rows, acc(a)->st.n, title, sfx, sizeof sfx, &written, &err) !=
        ACBB_OK)
        acbb_app_msg(a, ACBB_ROLE_ERROR, "plot export failed: %s", err.msg);
    else
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %d accuracy plots (PNG+SVG) to %s/%s%s%s", written,
                     a->plot_dir, sfx[0] ? " as accuracy" : "", sfx, sfx[0] ? " (earlier kept)" : "");
}

/* ---- heading ---- */

static void draw_heading(acbb_app *a)
{
    const acbb_bench_state *s = &acc(a)->st;
    acbb_rect b = a->lay.body;
    char el[16];
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER,
             "Accuracy vs time: each [fidelity] knob against its finest setting%s%s",
             s->phase == ACBB_BENCH_IDLE ? "" : ", ", s->phase == ACBB_BENCH_IDLE ? "" : acc(a)->scene);
    int y = b.y + 1;
    switch (s->phase) {
    case ACBB_BENCH_IDLE:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_NORMAL,
                 "b runs it on the edited scene, one run per setting; B adds the dynamic level");
        if (acbb_results_note(a, &acbb_screen_accuracy))
            acbb_put_wrap(a, y + 1, b.x, b.w, 2, ACBB_ROLE_DIM, acbb_results_note(a, &acbb_screen_accuracy));
        break;
    case ACBB_BENCH_RUNNING:
        acbb_draw_job_line(a, y, b.x, b.w, s->cancel_requested, s->started_s, s->done, s->total,
                           "settings");
        break;
    case ACBB_BENCH_DONE:
        acbb_fmt_duration(s->ended_s - s->started_s, el, sizeof el);
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_OK,
                 "done: %zu settings in %s. R reference, D the scene's value, * frontier", s->n, el);
        break;
    case ACBB_BENCH_CANCELLED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_WARN,
                 "cancelled after %zu of %zu settings: no errors without the references; b reruns",
                 s->n, s->total);
        break;
    case ACBB_BENCH_FAILED:
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_ERROR, "failed: %s", s->message);
        break;
    }
}

/* ---- table ---- */

static int is_pick(const acbb_bench_state *s, size_t i)
{
    return s->phase == ACBB_BENCH_DONE && s->picks[s->rows[i].knob] == (long)i;
}

static void draw_row(acbb_app *a, int y, acbb_rect r, size_t i)
{
    const acbb_accuracy_row *row = &acc(a)->st.rows[i];
    char label[96], mark[4], ms[16], e[4][16];
    acbb_acc_setting_label(row, label, sizeof label);
    snprintf(mark, sizeof mark, "%s%s%s", row->is_reference ? "R" : "", row->is_default ? "D" : "",
             is_pick(&acc(a)->st, i) ? "*" : "");
    if (isfinite(row->wall_ms)) snprintf(ms, sizeof ms, "%8.1f", row->wall_ms);
    else snprintf(ms, sizeof ms, "%8s", "-");
    const double errs[4] = { row->e_loss, row->e_T, row->e_Qi, row->e_alpha };
    for (int k = 0; k < 4; k++) acbb_acc_fmt_pct(errs[k], e[k], sizeof e[k]);
    const char *status = row->skipped ? "skipped"
                         : row->status == ACBB_OK ? "converged" : acbb_status_name(row->status);
    acbb_role role = row->skipped ? ACBB_ROLE_DIM
                     : row->status != ACBB_OK ? ACBB_ROLE_ERROR
                     : is_pick(&acc(a)->st, i) ? ACBB_ROLE_OK : ACBB_ROLE_NORMAL;
    acbb_put(a, y, r.x, r.w, role, "%-19s %-3s %-13s %s %6s %6s %6s %6s", label, mark, status, ms,
             e[0], e[1], e[2], e[3]);
}

static void draw_table(acbb_app *a, acbb_rect r)
{
    const acbb_bench_state *s = &acc(a)->st;
    if (r.h < 2) return;
    int visible = r.h - 1;
    int lines = (int)s->n + (s->phase == ACBB_BENCH_RUNNING && s->done < s->total);
    int max_top = lines > visible ? lines - visible : 0;
    if (acc(a)->top > max_top) acc(a)->top = max_top;
    if (acc(a)->top < 0) acc(a)->top = 0;
    /* Which rows are shown, in the first column: the line is full at 80. */
    char first[48] = "setting";
    if (max_top > 0)
        snprintf(first, sizeof first, "setting %d-%d/%d", acc(a)->top + 1,
                 acc(a)->top + (visible < lines ? visible : lines), lines);
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%-19s %-3s %-13s %8s %6s %6s %6s %6s", first, "",
             "status", "ms", "loss%", "T%", "Qi%", "alpha%");
    for (int k = 0; k < visible; k++) {
        int i = acc(a)->top + k, y = r.y + 1 + k;
        if (i < (int)s->n) draw_row(a, y, r, (size_t)i);
        else if (i < lines)
            acbb_put(a, y, r.x, r.w, ACBB_ROLE_DIM, "... setting %zu of %zu running", s->done + 1,
                     s->total);
    }
    if (s->phase == ACBB_BENCH_IDLE)
        acbb_put(a, r.y + 1, r.x, r.w, ACBB_ROLE_DIM, "(no results yet)");
}

/* ---- frontier ---- */

/* Knob k's pick: "contact_grid=6 (70.95x faster)", or just the setting
 * when `brief`; "" if the knob is not in the rows. */
static void pick_text(const acbb_bench_state *s, int k, int brief, char *buf, size_t n)
{
    int present = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < s->n; i++) present |= s->rows[i].knob == (acbb_accuracy_knob)k;
    if (!present) return;
    long p = s->picks[k], ref = acbb_accuracy_reference(s->rows, s->n, (acbb_accuracy_knob)k);
    if (p < 0) {
        snprintf(buf, n, "%s: -%s", acbb_accuracy_knob_name((acbb_accuracy_knob)k),
                 brief ? "" : " (reference failed)");
        return;
    }
    char label[96];
    acbb_acc_setting_label(&s->rows[p], label, sizeof label);
    if (brief) snprintf(buf, n, "%s", label);
    else if (p == ref) snprintf(buf, n, "%s (the reference)", label);
    else snprintf(buf, n, "%s (%.2fx faster)", label, s->rows[ref].wall_ms / s->rows[p].wall_ms);
}

/* The picks wrapped after `x0` on the rows of r, breaking only between
 * picks (two spaces apart, one when `brief`: all seven settings must fit
 * two rows of 80); draws only if `draw`. Returns 1 if every pick fitted. */
static int wrap_picks(acbb_app *a, acbb_rect r, int x0, int brief, int draw)
{
    int y = r.y, x = x0, gap = brief ? 1 : 2;
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        char t[160];
        pick_text(&acc(a)->st, k, brief, t, sizeof t);
        if (!t[0]) continue;
        int len = (int)strlen(t);
        if (x + len > r.x + r.w && x > r.x) {
            if (y + 1 >= r.y + r.h) return 0;
            y++;
            x = r.x;
        }
        if (x + len > r.x + r.w) return 0;
        if (draw) acbb_put(a, y, x, len, ACBB_ROLE_OK, "%s", t);
        x += len + gap;
    }
    return 1;
}

static void draw_frontier(acbb_app *a, acbb_rect r)
{
    const acbb_bench_state *s = &acc(a)->st;
    if (r.h < 1) return;
    if (s->phase != ACBB_BENCH_DONE) {
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_DIM, "%s",
                 s->phase == ACBB_BENCH_RUNNING ? "frontier: when the plan has run"
                                                : "frontier: needs the whole plan (b runs it)");
        return;
    }
    char head[96];
    snprintf(head, sizeof head, "frontier (cheapest within %g%% on loss, T):",
             100.0 * ACBB_ACCURACY_FRONTIER_TOL);
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%s", head);
    if (r.h >= 1 + ACBB_KNOB_COUNT) { /* one line per knob */
        int y = r.y + 1;
        for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
            char t[160];
            pick_text(s, k, 0, t, sizeof t);
            if (t[0]) acbb_put(a, y++, r.x, r.w, ACBB_ROLE_OK, "  %s", t);
        }
        return;
    }
    /* Wrapped after the heading; with many knobs only the settings fit
     * (the table's ms column and * mark tell the rest). */
    int x0 = r.x + (int)strlen(head) + 1;
    int brief = !wrap_picks(a, r, x0, 0, 0);
    wrap_picks(a, r, x0, brief, 1);
}

/* ---- screen ---- */

static void draw(acbb_app *a)
{
    draw_heading(a);
    draw_table(a, a->lay.acc_table);
    draw_frontier(a, a->lay.acc_frontier);
    acbb_draw_accuracy_chart(a, a->lay.acc_chart, &acc(a)->st);
}

static int on_key(acbb_app *a, int ch)
{
    int page = a->lay.acc_table.h - 1 > 1 ? a->lay.acc_table.h - 1 : 1;
    switch (ch) {
    case 'x':
        if (!cancel(a)) acbb_app_msg(a, ACBB_ROLE_WARN, "no benchmark running (b starts one)");
        return 1;
    case 27: return cancel(a); /* otherwise Esc clears the message as everywhere */
    case 'j': case KEY_DOWN: acc(a)->top++; return 1;
    case 'k': case KEY_UP: acc(a)->top--; return 1;
    case KEY_NPAGE: acc(a)->top += page; return 1;
    case KEY_PPAGE: acc(a)->top -= page; return 1;
    case KEY_HOME: acc(a)->top = 0; return 1;
    case KEY_END: acc(a)->top = ACBB_BENCH_MAX_ROWS; return 1; /* clamped when drawn */
    case 'g': export_plot(a); return 1;
    default: return 0;
    }
}

static const acbb_help_line help[] = {
    { "b", "benchmark edited scene" },
    { "B", "same, + dynamic level" },
    { "x  Esc", "cancel the benchmark" },
    { "j k PgUp/Dn", "scroll the table" },
    { "g", "export its plot (gnuplot)" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_accuracy = {
    .name = "Accuracy", .key = '8', .draw = draw, .on_key = on_key, .help = help,
    .hint = "b benchmark  B +dynamic  x/Esc cancel  j/k scroll  g export plot  ? help",
    .init = init, .free = acc_free, .wake_fd = wake_fd, .wake = wake, .poll = poll, .drop = drop,
    .running = running, .job_subject = "The accuracy benchmark", .job_noun = "benchmark",
};
