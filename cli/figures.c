/* acbb CLI — `acbb study PRESET --out DIR` (PRESET `seed` = 7008C): the
 * seed's Figs. 7-19 as PNG, SVG and CSV in DIR, and DIR/REPORT.md linking
 * them with the seed's captions, what the model shows and the verdicts of
 * the MODEL.md section 12 statements that cite each figure. Everything is
 * computed by the engine (study.h, figures.h); this file makes the
 * directory, times the three stages and writes the Markdown. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "acbb/tools/figures.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/outfile.h"
#include "acbb/tools/plot.h"
#include "acbb/tools/study.h"
#include "acbb/tools/scene_schema.h"
#include "common.h"
#include "exit.h"
#include "figures.h"
#include "mountings.h"
#include "plot.h"
#include "progress.h"
#include "say.h"

#define FIG_W 1004 /* "column": 8.5 x 6.4 cm at 300 dpi (plot.h) */
#define FIG_H 753

typedef struct {
    const char *preset, *dir;
    const acbb_study *st;
    const acbb_study_runs *runs;
    const acbb_fig_input *in;
    const acbb_figure_result *res;
    double ms[3];                /* study runs, trajectories, figures */
    int w, h;                    /* figure size, pixels (--size) */
    const acbb_study *by[N_MOUNTINGS]; /* the study under each mounting (mountings.h) */
} fig_view;

static void md_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '|' || *s == '*' || *s == '_' || *s == '[' || *s == ']') fputc('\\', f);
        fputc(*s, f);
    }
}

static const acbb_study_item *item_num(const acbb_study *st, int num)
{
    for (size_t i = 0; i < acbb_study_n_items(st); i++)
        if (acbb_study_item_at(st, i)->num == num) return acbb_study_item_at(st, i);
    return NULL;
}

static void md_panel(FILE *f, const acbb_figure_row *row, const acbb_figure_result *r)
{
    fprintf(f, "| %s | ", row->id);
    md_text(f, row->title);
    if (r->status != ACBB_OK) {
        fputs(" | not computed | ", f);
        md_text(f, r->message);
        fputs(" |\n", f);
        return;
    }
    fprintf(f, " | [PNG](%s.png) [SVG](%s.svg) [data](%s.csv) | %d series, %zu points; ",
            row->id, row->id, row->id, r->n_series, r->n_points);
    md_text(f, row->ylabel);
    fprintf(f, " from %.4g to %.4g", r->y_min, r->y_max);
    if (r->message[0]) {
        fputs("; left out: ", f);
        md_text(f, r->message);
    }
    fputs(" |\n", f);
}

static void md_figure(FILE *f, const fig_view *v, const acbb_seed_figure *sf)
{
    size_t n;
    const acbb_figure_row *rows = acbb_figure_table(&n);
    fprintf(f, "\n## Fig. %d\n\nSeed caption: ", sf->num);
    md_text(f, sf->caption);
    fputs(".\n\n| panel | what | files | what the model shows |\n|---|---|---|---|\n", f);
    for (size_t i = 0; i < n; i++)
        if (rows[i].seed_fig == sf->num) md_panel(f, &rows[i], &v->res[i]);
    if (sf->not_computed) {
        fputs("\nNot computed: ", f);
        md_text(f, sf->not_computed);
        fputs(".\n", f);
    }
    if (!sf->items[0]) {
        fputs("\nNo docs/physics.md section 12 statement cites this figure.\n", f);
        return;
    }
    fputs("\nStatements citing this figure (docs/physics.md section 12):\n\n", f);
    for (int k = 0; k < ACBB_FIG_MAX_ITEMS && sf->items[k]; k++) {
        const acbb_study_item *it = item_num(v->st, sf->items[k]);
        if (!it) continue;
        fprintf(f, "- Item %d: %s - ", it->num, acbb_verdict_name(it->verdict));
        md_text(f, it->statement);
        fputc('\n', f);
    }
}

/* The panels whose seed figure a statement cites: "fig17a, fig17c"; "" if none. */
static void item_panels(int item, char *buf, size_t cap)
{
    size_t ns, nr, u = 0;
    const acbb_seed_figure *sf = acbb_seed_figure_table(&ns);
    const acbb_figure_row *rows = acbb_figure_table(&nr);
    buf[0] = '\0';
    for (size_t i = 0; i < ns; i++)
        for (int k = 0; k < ACBB_FIG_MAX_ITEMS && sf[i].items[k]; k++) {
            if (sf[i].items[k] != item) continue;
            for (size_t r = 0; r < nr && u < cap; r++)
                if (rows[r].seed_fig == sf[i].num)
                    u += (size_t)snprintf(buf + u, cap - u, "%s%s", u ? ", " : "", rows[r].id);
        }
}

/* Why conclusion i holds or not under mounting m, in words. */
static void md_why(FILE *f, const fig_view *v, const acbb_study_conclusion *c, size_t i, int m)
{
    const acbb_study *s = v->by[m];
    acbb_verdict cv = acbb_study_conclusion_verdict(s, i);
    fprintf(f, "- %s %s it is %s: ", m == M_DB ? "as a" : "under", acbb_cli_mountings[m].name,
            acbb_verdict_name(cv));
    if (cv == ACBB_VERDICT_HELD) {
        fputs("every check it rests on holds (", f);
        for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && c->checks[k]; k++)
            fprintf(f, "%scheck %s", k ? ", " : "", c->checks[k]);
        fputs(").\n", f);
        return;
    }
    const char *sep = "";
    for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && c->checks[k]; k++) {
        const acbb_study_check *ch = acbb_cli_find_check(s, c->checks[k]);
        if (ch && ch->verdict == ACBB_VERDICT_HELD) continue;
        fprintf(f, "%scheck %s %s", sep, c->checks[k],
                !ch || ch->verdict == ACBB_VERDICT_NOT_EVALUATED ? "could not be evaluated"
                                                                 : "does not hold");
        sep = " and ";
    }
    fputs(" (its numbers below).\n", f);
}

/* Conclusion (6)'s omega_so at 100 N (fig17c) reverses sign in the
 * model: say so, since the check reads the signed value (study_items_b.c
 * check 16c) and a reader of the figure sees the fall pass through zero. */
static void md_spin_sign(FILE *f, const fig_view *v)
{
    const acbb_study_point *pts = v->runs->sweep[ACBB_STUDY_L2][ACBB_STUDY_S100];
    for (int k = 1; k < ACBB_STUDY_NPTS; k++) {
        const acbb_study_point *a = &pts[2 * (k - 1) + ACBB_STUDY_TE];
        const acbb_study_point *b = &pts[2 * k + ACBB_STUDY_TE];
        double sa = a->last.balls[0].spin_o, sb = b->last.balls[0].spin_o;
        if (!a->ok || !b->ok || !(sa > 0.0 && sb < 0.0)) continue;
        fprintf(f, "\nNote (fig17c): under the constant force the outer contact's spin omega\\_so "
                "(with expansion) changes sign between %g rpm (%+.4g rad/s) and %g rpm (%+.4g "
                "rad/s): the spin at the outer contact reverses. Check 16c reads the signed value, "
                "which rises and then falls as the seed says; its magnitude grows again after "
                "the reversal, which the seed's figure does not show.\n",
                acbb_study_speeds[k - 1], sa, acbb_study_speeds[k], sb);
        return;
    }
}

/* One conclusion: its verdict under each mounting, why, and every check
 * it rests on with its statement, what it measures and its numbers. */
static void md_conclusion(FILE *f, const fig_view *v, const acbb_study_conclusion *c, size_t i)
{
    fprintf(f, "\n### (%zu) ", i + 1);
    acbb_cli_md_text(f, c->text);
    fputs("\n\nWhy:\n\n", f);
    for (int m = 0; m < N_MOUNTINGS; m++) md_why(f, v, c, i, m);
    for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && c->checks[k]; k++) {
        const acbb_study_item *it = item_num(v->st, atoi(c->checks[k]));
        char panels[200];
        item_panels(atoi(c->checks[k]), panels, sizeof panels);
        fprintf(f, "\nCheck %s is a test of statement %d (\"", c->checks[k], atoi(c->checks[k]));
        acbb_cli_md_text(f, it ? it->statement : "?");
        fprintf(f, "\")%s%s. What it measures and its numbers:\n\n", panels[0] ? "; figures: " : "",
                panels);
        for (int m = 0; m < N_MOUNTINGS; m++) {
            const acbb_study_check *ch = acbb_cli_find_check(v->by[m], c->checks[k]);
            fprintf(f, "- %s, %s: ", acbb_cli_mountings[m].name,
                    ch ? acbb_verdict_name(ch->verdict) : "NOT EVALUATED");
            acbb_cli_md_text(f, ch ? ch->text : "not evaluated");
            fputc('\n', f);
        }
    }
    if (i == 5) md_spin_sign(f, v);
}

/* The seed's seven conclusions (seed section 5) as `acbb report --md`
 * judges them, under the three mountings (issue 29 item 10: with the
 * numbers, the reasons and every check named defined). */
static void md_conclusions(FILE *f, const fig_view *v)
{
    size_t nc;
    const acbb_study_conclusion *cc = acbb_study_conclusions(&nc);
    fprintf(f, "\n## Seed conclusions (seed section 5)\n\nThe seed's %zu conclusions, each judged "
            "from tests (checks) of the statements of docs/physics.md section 12, as `acbb report` "
            "judges them. A check is named by its statement's number and a letter (check 16c is "
            "a test of statement 16); each is given below with its statement, what it measures "
            "and the numbers that decide it. A conclusion is HELD when every check it rests on "
            "holds, NOT HELD when one does not.\n\n", nc);
    acbb_cli_md_text(f, acbb_cli_mount_intro);
    fputs("\n\n| # | conclusion | constant force | rigid preload | DB pair | holds under |\n"
          "|---|---|---|---|---|---|\n", f);
    for (size_t i = 0; i < nc; i++) {
        fprintf(f, "| (%zu) | ", i + 1);
        acbb_cli_md_text(f, cc[i].text);
        fputs(" |", f);
        acbb_cli_mountings_md_row(f, v->by, i);
    }
    for (size_t i = 0; i < nc; i++) md_conclusion(f, v, &cc[i], i);
}

static void md_report(FILE *f, const fig_view *v)
{
    int nv[3];
    acbb_study_counts(v->st, nv);
    fprintf(f, "# The seed's Figs. 7-19 from acbb\n\nGenerated by `acbb study PRESET --out DIR` "
            "(PRESET %s; `seed` is 7008C). Each panel has the seed's quantity and axes; TE (with thermal "
            "expansion) is drawn solid, WTE (without) dashed; per-ball quantities are ball "
            "0's; \"room temperature\" is the WTE steady state (docs/physics.md section 12). "
            "Trajectory "
            "panels are the TE load-sweep runs (15000 rpm) re-driven step by step.\n\n",
            v->preset);
    fprintf(f, "Runs: %zu study runs at %s (items marked L2 at quasi-dynamic), %zu failed; "
            "wall time: study %.2f s, trajectories %.2f s, figures %.2f s.\n\n", v->runs->n,
            acbb_model_level_name(v->runs->model), acbb_study_n_failed(v->st),
            1e-3 * v->ms[0], 1e-3 * v->ms[1], 1e-3 * v->ms[2]);
    fprintf(f, "**Statements: %d held, %d not held, %d not evaluated** (of %zu; `acbb "
            "report` gives the evidence).\n", nv[0], nv[1], nv[2], acbb_study_n_items(v->st));
    md_conclusions(f, v);
    size_t n;
    const acbb_seed_figure *sf = acbb_seed_figure_table(&n);
    for (size_t i = 0; i < n; i++) md_figure(f, v, &sf[i]);
}

/* DIR exists as a directory afterwards, or 2 with the reason. */
static int make_dir(const char *dir)
{
    struct stat sb;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        acbb_cli_say("study: --out %s: %s\n", dir, strerror(errno));
        return ACBB_EXIT_INPUT;
    }
    if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
        acbb_cli_say("study: --out %s: not a directory\n", dir);
        return ACBB_EXIT_INPUT;
    }
    return 0;
}

static int write_report(const fig_view *v)
{
    char path[4200];
    acbb_error err = { { 0 } };
    acbb_out *o = NULL;
    FILE *f = NULL;
    snprintf(path, sizeof path, "%s/REPORT.md", v->dir);
    if (acbb_out_open(path, &o, &f, &err) != ACBB_OK) {
        acbb_cli_say("study: %s\n", err.msg);
        return ACBB_EXIT_INPUT;
    }
    md_report(f, v);
    if (acbb_out_commit(o, &err) != ACBB_OK) {
        acbb_cli_say("study: %s\n", err.msg);
        return ACBB_EXIT_INTERNAL;
    }
    return 0;
}

/* Stdout: one line per panel not written, then the totals and timings. */
static int summary(const fig_view *v, size_t n)
{
    size_t ok = 0;
    int rc = 0;
    for (size_t i = 0; i < n; i++) {
        if (v->res[i].status == ACBB_OK) {
            ok++;
            continue;
        }
        acbb_cli_say("study: %s not written: %s\n", acbb_figure_table(&n)[i].id,
                v->res[i].message);
        if (v->res[i].status != ACBB_EINVAL) rc = ACBB_EXIT_INTERNAL;
    }
    printf("wrote %zu of %zu seed figure panels (PNG, SVG, CSV) and REPORT.md in %s\n"
           "wall time: study %.2f s (%zu runs), trajectories %.2f s, figures %.2f s\n", ok, n,
           v->dir, 1e-3 * v->ms[0], v->runs->n, 1e-3 * v->ms[1], 1e-3 * v->ms[2]);
    return rc;
}

/* Cancelled (SIGINT / SIGTERM, progress.h): no REPORT.md is written, and
 * one from an earlier run goes once panels were redrawn (it would describe
 * other figures), so nothing in DIR claims a complete set. */
static int figures_cancelled(const fig_view *v, bool drawn)
{
    char path[4200], kept[160];
    snprintf(path, sizeof path, "%s/REPORT.md", v->dir);
    if (drawn) remove(path);
    snprintf(kept, sizeof kept, "%s, no REPORT.md written", drawn ? "the panels were drawn"
                                                                  : "no panel drawn");
    return acbb_cli_cancelled("study", kept);
}

static int figures(const acbb_cli_args *a, acbb_study *st, acbb_study *const *by, long jobs)
{
    size_t n;
    acbb_figure_table(&n);
    acbb_figure_result *res = calloc(n, sizeof *res);
    fig_view v = { a->preset, a->val[CLI_OPT_OUT], st, acbb_study_results(st), NULL, res,
                   { 0, 0, 0 }, FIG_W, FIG_H, { by[0], by[1], by[2] } };
    acbb_fig_input *in = NULL;
    acbb_error err = { { 0 } };
    if (!res) return acbb_cli_no_memory("study");
    acbb_error serr = { { 0 } };
    if (a->val[CLI_OPT_SIZE] && (acbb_cli_parse_size(a->val[CLI_OPT_SIZE], &v.w, &v.h) ||
                                 acbb_plot_check_size(ACBB_PLOT_PNG, v.w, v.h, &serr) != ACBB_OK)) {
        if (serr.msg[0]) acbb_cli_say("study: --size: %s\n", serr.msg);
        free(res);
        return ACBB_EXIT_INPUT;
    }
    acbb_cli_progress prog;
    acbb_cli_progress_init(&prog, stderr, 0.0);
    const atomic_int *cancel = acbb_cli_interrupt_begin();
    acbb_cli_progress_note(&prog, "study: running the study  (Ctrl-C stops)");
    double t0 = acbb_now_ms();
    acbb_status ss = acbb_study_run(st, (int)jobs, cancel);
    /* the conclusions under the other mountings (REPORT.md, as `acbb report`) */
    for (int m = 0; m < N_MOUNTINGS && ss != ACBB_CANCELLED; m++) {
        if (by[m] == st) continue;
        acbb_cli_progress_note(&prog, "study: the study under %s  (Ctrl-C stops)",
                               acbb_cli_mountings[m].name);
        if (acbb_study_run(by[m], (int)jobs, cancel) == ACBB_CANCELLED) ss = ACBB_CANCELLED;
    }
    double t1 = acbb_now_ms();
    int rc = 0;
    if (ss != ACBB_CANCELLED) {
        acbb_cli_progress_note(&prog, "study: recording the trajectories  (Ctrl-C stops)");
        ss = acbb_figures_record(v.runs, (int)jobs, cancel, &in, &err);
        if (ss != ACBB_OK && ss != ACBB_CANCELLED) {
            acbb_cli_say("study: %s\n", err.msg);
            rc = ACBB_EXIT_INTERNAL;
        }
    }
    double t2 = acbb_now_ms();
    bool drawn = !rc && ss != ACBB_CANCELLED;
    if (drawn) acbb_figures_write_all(in, v.dir, (int)jobs, v.w, v.h, res);
    acbb_cli_progress_end(&prog);
    acbb_cli_interrupt_end();
    if (acbb_cli_interrupted()) {
        acbb_figures_input_free(in);
        free(res);
        return figures_cancelled(&v, drawn);
    }
    v.ms[0] = t1 - t0;
    v.ms[1] = t2 - t1;
    v.ms[2] = acbb_now_ms() - t2;
    v.in = in;
    if (!rc) rc = write_report(&v);
    if (!rc) rc = summary(&v, n);
    if (!rc) rc = acbb_cli_study_failed("study", st, "REPORT.md counts them");
    acbb_figures_input_free(in);
    free(res);
    return acbb_cli_worst(rc, acbb_cli_stdout_check(0));
}

int acbb_cli_study_figures(const acbb_cli_args *a, long jobs)
{
    acbb_scene base;
    int rc = acbb_cli_load_scene(a, &base);
    if (!rc) rc = make_dir(a->val[CLI_OPT_OUT]);
    if (rc) return rc;
    acbb_study *st = NULL, *by[N_MOUNTINGS] = { NULL };
    acbb_error err = { { 0 } };
    int own = acbb_cli_own_mounting(&base);
    acbb_status ps = acbb_study_plan(&base, &st, &err);
    for (int m = 0; m < N_MOUNTINGS && ps == ACBB_OK; m++) {
        acbb_scene ms;
        acbb_cli_mounting_scene(&base, m, &ms);
        if (m != own) ps = acbb_study_plan(&ms, &by[m], &err);
        else by[m] = st;
    }
    if (ps == ACBB_OK) rc = figures(a, st, by, jobs);
    else acbb_cli_say("study: out of memory\n"), rc = ACBB_EXIT_INTERNAL;
    for (int m = 0; m < N_MOUNTINGS; m++)
        if (by[m] != st) acbb_study_free(by[m]);
    acbb_study_free(st);
    return rc;
}
