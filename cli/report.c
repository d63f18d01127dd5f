/* acbb CLI — `acbb report`: formats the engine study's results (see
 * cli/report.h for the command line and exit statuses). Everything judged
 * comes from include/acbb/tools/study.h; this file only parses arguments and
 * prints text (80 columns), JSON or Markdown. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/loss_kinds.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/outfile.h"
#include "acbb/tools/physics_profile.h"
#include "acbb/scene.h"
#include "acbb/tools/study.h"
#include "acbb/tools/scene_schema.h"
#include "common.h"
#include "exit.h"
#include "progress.h"
#include "report.h"
#include "report_contact.h"
#include "mountings.h"
#include "say.h"

/* What the formatters need besides the study. */
typedef struct {
    const char *preset;
    const char *const *sets;     /* the --set edits as typed */
    size_t n_sets;
    acbb_model_level model;      /* the preset's level */
    const acbb_study *st;
    const acbb_study_runs *runs;
    const acbb_study_rob *rob;   /* --sensitivity, else NULL */
    const acbb_study *by[N_MOUNTINGS]; /* the study under each mounting (acbb_cli_mountings) */
    const char *loss_set;        /* acbb_loss_set of the preset: "seed" | "extended" */
    const acbb_contact_study *contact; /* the runaway case under each contact model */
    const char *profile;         /* its physics.profile: "seed" | "reference" */
} report_view;

/* ---- robustness (--sensitivity) ---- */

/* "holds" / "does not hold", then the single plausible changes that turn
 * it, e.g. "surroundings.shaft_bore = convective (+6.719)". */
static void robust_text(char *buf, size_t cap, const acbb_study_robust *r)
{
    size_t u = 0;
    if (!r->ok) {
        snprintf(buf, cap, "the scene's run gave no value");
        return;
    }
    u += (size_t)snprintf(buf, cap, "%+.4g at the scene's values: %s; ", r->y,
                          r->holds ? "holds" : "does not hold");
    if (r->n_turns == 0)
        u += (size_t)snprintf(buf + u, u < cap ? cap - u : 0, "%s over all %zu plausible ranges "
                              "one at a time", r->holds ? "survives" : "no single change makes "
                              "it hold", r->n_inputs);
    else
        u += (size_t)snprintf(buf + u, u < cap ? cap - u : 0, "%s", r->holds
                              ? "fails with" : "holds with");
    for (size_t k = 0; k < r->n_turns && u < cap; k++)
        u += (size_t)snprintf(buf + u, cap - u, "%s %s = %s (%+.4g)", k ? "," : "",
                              r->turns[k].key, r->turns[k].value, r->turns[k].y);
    if (r->failed && u < cap)
        snprintf(buf + u, cap - u, " [%zu end(s) without a value]", r->failed);
}


static const char *const k_vmark[] = { "ok", "NO", "n/e" };

/* ---- text output (80 columns) ---- */

static void wrap(FILE *f, const char *head, int indent, const char *text)
{
    int col = fprintf(f, "%s", head);
    const char *w = text;
    bool first = true;
    while (*w) {
        while (*w == ' ') w++;
        if (!*w) break;
        int len = (int)strcspn(w, " ");
        if (!first && col + 1 + len > 80) {
            fprintf(f, "\n%*s", indent, "");
            col = indent;
            first = true;
        }
        col += fprintf(f, "%s%.*s", first ? "" : " ", len, w);
        first = false;
        w += len;
    }
    fputc('\n', f);
}

static const char *level_name(const report_view *c, int l2)
{
    return l2 ? "quasi-dynamic" : acbb_model_level_name(c->model);
}

/* " [checks 5a 9b]" of conclusion i. */
static void concl_checks(char *buf, size_t cap, const acbb_study_conclusion *cc, const char *pre,
                         const char *post)
{
    size_t n = (size_t)snprintf(buf, cap, "%s", pre);
    for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && cc->checks[k] && n < cap; k++)
        n += (size_t)snprintf(buf + n, cap - n, " %s", cc->checks[k]);
    if (n < cap) snprintf(buf + n, cap - n, "%s", post);
}

static void print_items_text(FILE *f, const report_view *c)
{
    fprintf(f, "%-4s %-14s %s\n", "item", "verdict", "statement / checks");
    for (size_t i = 0; i < acbb_study_n_items(c->st); i++) {
        const acbb_study_item *it = acbb_study_item_at(c->st, i);
        char head[64], st[600];
        snprintf(head, sizeof head, "%3d  %-14s ", it->num, acbb_verdict_name(it->verdict));
        snprintf(st, sizeof st, "%s%s", it->l2 ? "(L2) " : "", it->statement);
        wrap(f, head, 20, st);
        for (int k = 0; k < it->n_checks; k++) {
            const acbb_study_check *ch = &it->checks[k];
            snprintf(head, sizeof head, "%5s%-4s %-5s", "", ch->id,
                     ch->info ? "info" : k_vmark[ch->verdict]);
            wrap(f, head, 15, ch->text);
        }
    }
}

/* The item's verdict and whether a single plausible change turns it. */
static void item_rob_head(char *buf, size_t cap, const acbb_study_rob *r,
                          const acbb_study_item_rob *ir)
{
    static const char *const none[] = { "survives every plausible single change",
                                        "no single plausible change makes it hold",
                                        "no single plausible change makes it evaluable" };
    static const char *const some[] = { "fails with", "holds with", "changes with" };
    const char *v = acbb_verdict_name(ir->verdict);
    if (!ir->varied)
        snprintf(buf, cap, "%s; model-independent sanity item, not varied", v);
    else if (ir->n_turns == 0)
        snprintf(buf, cap, "%s; %s (%zu ends of %zu inputs)", v, none[ir->verdict], r->n_ends,
                 r->n_inputs);
    else
        snprintf(buf, cap, "%s; %s %zu of %zu single changes:", v, some[ir->verdict],
                 ir->n_turns, r->n_ends);
}

/* "key = end -> VERDICT (id: the check's numbers there; ...)" */
static void flip_text(char *buf, size_t cap, const acbb_study_flip *f)
{
    size_t u = (size_t)snprintf(buf, cap, "%s = %s -> %s", f->key, f->value,
                                acbb_verdict_name(f->verdict));
    for (int k = 0; k < f->n_checks && u < cap; k++)
        u += (size_t)snprintf(buf + u, cap - u, "%s%s %s: %s", k ? "; " : " (", f->checks[k].id,
                              k_vmark[f->checks[k].verdict], f->checks[k].text);
    if (f->n_checks && u < cap) snprintf(buf + u, cap - u, ")");
}

/* "key = end (1b ok, 1c NO), ..." over the flips that leave the item's verdict. */
static void partial_text(char *buf, size_t cap, const acbb_study_item_rob *ir)
{
    size_t u = (size_t)snprintf(buf, cap, "checks changed without turning the item:");
    for (size_t j = ir->n_turns; j < ir->n_flips && u < cap; j++) {
        const acbb_study_flip *f = &ir->flips[j];
        u += (size_t)snprintf(buf + u, cap - u, "%s %s = %s (", j > ir->n_turns ? "," : "",
                              f->key, f->value);
        for (int k = 0; k < f->n_checks && u < cap; k++)
            u += (size_t)snprintf(buf + u, cap - u, "%s%s %s", k ? ", " : "", f->checks[k].id,
                                  k_vmark[f->checks[k].verdict]);
        if (u < cap) u += (size_t)snprintf(buf + u, cap - u, ")");
    }
}

#define FLIP_TEXT (ACBB_STUDY_MAX_CHECKS * (ACBB_STUDY_TEXT + 16) + 256)

static void print_robust_text(FILE *f, const report_view *c)
{
    const acbb_study_rob *r = c->rob;
    char line[4600], head[16];
    snprintf(line, sizeof line, "Robustness (--sensitivity, %.1f s): the study re-run with "
             "every uncertain input set to each end of its plausible range (`acbb keys`), one "
             "at a time: %zu inputs, %zu ends (%zu at the scene's value), %zu runs, %zu points "
             "shared, %zu failed. Per item: its verdict, then the single changes that turn "
             "it, with the numbers of the checks that change there, and the changes that "
             "turn some checks only. Physics is unchanged; this says "
             "how close each verdict is to the uncertain inputs.", 1e-3 * r->wall_ms,
             r->n_inputs, r->n_ends, r->n_same, r->n_runs, r->n_shared, r->n_failed);
    wrap(f, "", 0, line);
    char *t = malloc(FLIP_TEXT);
    if (!t) return;
    for (size_t k = 0; k < r->n_items; k++) {
        const acbb_study_item_rob *ir = &r->items[k];
        item_rob_head(line, sizeof line, r, ir);
        snprintf(head, sizeof head, "%3d  ", ir->num);
        wrap(f, head, 5, line);
        for (size_t j = 0; j < ir->n_turns; j++) {
            flip_text(t, FLIP_TEXT, &ir->flips[j]);
            wrap(f, "     - ", 7, t);
        }
        if (ir->n_flips > ir->n_turns) {
            partial_text(t, FLIP_TEXT, ir);
            wrap(f, "     ", 5, t);
        }
    }
    fputc('\n', f);
    wrap(f, "", 0, "The TE - WTE differences behind the sign statements (items 1, 5, 8, 10-13, "
                   "15, 16) and the thresholds on the relative TE effect (items 3, 9, 14), at "
                   "their point of the sweeps, from the same runs:");
    for (size_t k = 0; k < r->n_signs; k++) {
        const acbb_study_robust *s = &r->signs[k];
        robust_text(t, FLIP_TEXT, s);
        snprintf(head, sizeof head, "%2d  ", s->sign->item);
        snprintf(line, sizeof line, "%s: %s", s->sign->what, t);
        wrap(f, head, 4, line);
    }
    free(t);
}

/* Check `id` ("5a") of study s; when the item was not evaluated as a whole
 * (one check named by the item number), that check: it says why. */
static void print_mountings_text(FILE *f, const report_view *c)
{
    size_t nc;
    const acbb_study_conclusion *cc = acbb_study_conclusions(&nc);
    wrap(f, "", 0, acbb_cli_mount_intro);
    fprintf(f, "%-6s", "");
    for (int m = 0; m < N_MOUNTINGS; m++) fprintf(f, "%-15s", acbb_cli_mountings[m].name);
    fprintf(f, "%s\n", "holds under");
    for (size_t i = 0; i < nc; i++) {
        char where[48];
        fprintf(f, "(%zu)   ", i + 1);
        for (int m = 0; m < N_MOUNTINGS; m++)
            fprintf(f, "%-15s", acbb_verdict_name(acbb_study_conclusion_verdict(c->by[m], i)));
        fprintf(f, "%s\n", acbb_cli_holds_under(c->by, i, where, sizeof where));
        for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && cc[i].checks[k]; k++)
            for (int m = 0; m < N_MOUNTINGS; m++) {
                const acbb_study_check *ch = acbb_cli_find_check(c->by[m], cc[i].checks[k]);
                char head[48];
                snprintf(head, sizeof head, "%6s%-4s %-4s %s: ", "", cc[i].checks[k],
                         ch ? k_vmark[ch->verdict] : "n/e", acbb_cli_mountings[m].label);
                wrap(f, head, 12, ch ? ch->text : "not evaluated");
            }
    }
}

static void print_text(FILE *f, const report_view *c)
{
    char line[4600];
    snprintf(line, sizeof line, "acbb report: %s - the seed's acceptance statements "
             "(docs/physics.md section 12)", c->preset);
    wrap(f, "", 0, line);
    snprintf(line, sizeof line, "Runs: %zu (%s; items marked (L2) at quasi-dynamic), %zu failed, "
             "%.1f s wall. Load sweep 50-1000 N at 15000 rpm; speed sweeps 2000-16000 rpm at "
             "100 N and 1000 N; TE and WTE; zero-speed runs. Checks: ok = held, NO = not "
             "held, n/e = not evaluated, info = not part of the verdict. Loss set: %s; physics profile: %s.",
             c->runs->n, acbb_model_level_name(c->model), acbb_study_n_failed(c->st),
             1e-3 * c->runs->wall_ms, c->loss_set, c->profile);
    wrap(f, "", 0, line);
    fputc('\n', f);
    print_items_text(f, c);
    fputc('\n', f);
    wrap(f, "", 0, "Seed conclusions (seed section 5 lists seven), each judged from the checks "
                   "it maps onto:");
    size_t nc;
    const acbb_study_conclusion *cc = acbb_study_conclusions(&nc);
    for (size_t i = 0; i < nc; i++) {
        char head[64], txt[700], ids[64];
        snprintf(head, sizeof head, "(%zu)  %-14s ", i + 1,
                 acbb_verdict_name(acbb_study_conclusion_verdict(c->st, i)));
        concl_checks(ids, sizeof ids, &cc[i], " [checks", "]");
        snprintf(txt, sizeof txt, "%s%s", cc[i].text, ids);
        wrap(f, head, 20, txt);
    }
    int nv[3];
    acbb_study_counts(c->st, nv);
    fprintf(f, "\n%d held, %d not held, %d not evaluated\n", nv[0], nv[1], nv[2]);
    fputc('\n', f);
    print_mountings_text(f, c);
    fputc('\n', f);
    acbb_report_contact_text(f, c->contact);
    if (c->rob) {
        fputc('\n', f);
        print_robust_text(f, c);
    }
}

/* ---- JSON (the engine's writer, acbb/tools/json.h: one escaping, one number
 * format for every document) ---- */

static void json_check(acbb_json *j, const acbb_study_check *ch)
{
    acbb_json_open(j, NULL, '{', true);
    acbb_json_str(j, "id", ch->id);
    acbb_json_str(j, "verdict", acbb_verdict_name(ch->verdict));
    acbb_json_bool(j, "info", ch->info);
    acbb_json_str(j, "text", ch->text);
    acbb_json_close(j, '}');
}

static void json_checks(acbb_json *j, const char *key, const acbb_study_check *ch, int n,
                        bool one_line)
{
    acbb_json_open(j, key, '[', one_line);
    for (int k = 0; k < n; k++) json_check(j, &ch[k]);
    acbb_json_close(j, ']');
}

/* --sensitivity: the sign conditions of item `item` and what turns them. */
static void json_conditions(acbb_json *j, const acbb_study_rob *rob, int item)
{
    acbb_json_open(j, "conditions", '[', true);
    for (size_t k = 0; k < rob->n_signs; k++) {
        const acbb_study_robust *r = &rob->signs[k];
        if (r->sign->item != item) continue;
        acbb_json_open(j, NULL, '{', true);
        acbb_json_str(j, "condition", r->sign->what);
        acbb_json_str(j, "metric", r->sign->metric);
        acbb_json_num(j, "load_N", r->sign->load_N);
        acbb_json_num(j, "speed_rpm", r->sign->speed_rpm);
        if (r->ok) acbb_json_num(j, "value", r->y);
        else acbb_json_null(j, "value");
        acbb_json_bool(j, "holds", r->holds);
        acbb_json_long(j, "failed", (long)r->failed);
        acbb_json_open(j, "turned_by", '[', true);
        for (size_t t = 0; t < r->n_turns; t++) {
            acbb_json_open(j, NULL, '{', true);
            acbb_json_str(j, "key", r->turns[t].key);
            acbb_json_str(j, "value", r->turns[t].value);
            acbb_json_num(j, "at", r->turns[t].y);
            acbb_json_close(j, '}');
        }
        acbb_json_close(j, ']');
        acbb_json_close(j, '}');
    }
    acbb_json_close(j, ']');
}

/* --sensitivity: the item's verdict under every single change that turns it. */
static void json_robust(acbb_json *j, const report_view *c, size_t i)
{
    if (!c->rob || i >= c->rob->n_items) return;
    const acbb_study_item_rob *ir = &c->rob->items[i];
    acbb_json_open(j, "robustness", '{', false);
    acbb_json_bool(j, "varied", ir->varied);
    acbb_json_long(j, "inputs", (long)c->rob->n_inputs);
    acbb_json_long(j, "ends", (long)c->rob->n_ends);
    acbb_json_bool(j, "turned", ir->n_turns > 0);
    acbb_json_open(j, "changes", '[', false);
    for (size_t k = 0; k < ir->n_flips; k++) {
        const acbb_study_flip *fl = &ir->flips[k];
        acbb_json_open(j, NULL, '{', true);
        acbb_json_str(j, "key", fl->key);
        acbb_json_str(j, "value", fl->value);
        acbb_json_bool(j, "turns_item", fl->turns_item);
        acbb_json_str(j, "verdict", acbb_verdict_name(fl->verdict));
        json_checks(j, "checks", fl->checks, fl->n_checks, true);
        acbb_json_close(j, '}');
    }
    acbb_json_close(j, ']');
    json_conditions(j, c->rob, ir->num);
    acbb_json_close(j, '}');
}

/* The item's verdict and checks under each mounting. */
static void json_mountings(acbb_json *j, const report_view *c, size_t i)
{
    acbb_json_open(j, "mountings", '{', false);
    for (int m = 0; m < N_MOUNTINGS; m++) {
        const acbb_study_item *it = acbb_study_item_at(c->by[m], i);
        acbb_json_open(j, acbb_cli_mountings[m].json, '{', false);
        acbb_json_str(j, "verdict", acbb_verdict_name(it->verdict));
        json_checks(j, "checks", it->checks, it->n_checks, false);
        acbb_json_close(j, '}');
    }
    acbb_json_close(j, '}');
}

static void json_item(acbb_json *j, const report_view *c, size_t i, size_t nc)
{
    const acbb_study_item *it = acbb_study_item_at(c->st, i);
    acbb_json_open(j, NULL, '{', false);
    acbb_json_long(j, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    acbb_json_long(j, "item", it->num);
    acbb_json_str(j, "statement", it->statement);
    acbb_json_str(j, "verdict", acbb_verdict_name(it->verdict));
    acbb_json_str(j, "level", level_name(c, it->l2));
    acbb_json_open(j, "seed_conclusions", '[', true);
    for (size_t k = 0; k < nc; k++)
        if (acbb_study_item_in_conclusion(c->st, i, k)) acbb_json_long(j, NULL, (long)(k + 1));
    acbb_json_close(j, ']');
    acbb_json_open(j, "evidence", '{', false);
    json_checks(j, "checks", it->checks, it->n_checks, false);
    acbb_json_open(j, "values", '{', false);
    for (int k = 0; k < it->n_values; k++) acbb_json_num(j, it->values[k].key, it->values[k].v);
    acbb_json_close(j, '}');
    acbb_json_close(j, '}');
    json_mountings(j, c, i);
    /* item 9's rigid-preload mounting is judged at the runaway case */
    if (it->num == 9) acbb_report_contact_json(j, c->contact);
    json_robust(j, c, i);
    acbb_json_close(j, '}');
}

/* Returns the writer's misuse count: nesting past ACBB_JSON_DEPTH would
 * leave invalid JSON (the deepest path here is 7 levels). A NaN evidence
 * value (a failed or cancelled run) is null by design, not an error. */
static long print_json(FILE *f, const report_view *c)
{
    size_t n = acbb_study_n_items(c->st), nc;
    acbb_study_conclusions(&nc);
    acbb_json j;
    acbb_json_init(&j, f);
    acbb_json_open(&j, NULL, '[', false);
    for (size_t i = 0; i < n; i++) json_item(&j, c, i, nc);
    acbb_json_close(&j, ']');
    return j.misuse;
}

/* ---- Markdown ---- */

#define md_text acbb_cli_md_text

static void print_md_head(FILE *f, const report_view *c)
{
    int nv[3];
    acbb_study_counts(c->st, nv);
    fputs("# Seed report: the acceptance statements of docs/physics.md section 12\n\n", f);
    fprintf(f, "Generated by `acbb report %s", c->preset);
    for (size_t i = 0; i < c->n_sets; i++) fprintf(f, " --set %s", c->sets[i]);
    if (c->rob) fputs(" --sensitivity", f);
    fputs("` (the engine study, src/study*.c, formatted by cli/report.c). Physics over "
          "wished-for results: every statement is judged from runs of the engine, HELD, NOT "
          "HELD or NOT EVALUATED, with the numbers that decide it.\n\n", f);
    fprintf(f, "Runs: %zu at %s (the preset's level), items marked (L2) at quasi-dynamic; %zu "
            "failed. Load sweep 50, 100, 150, 200, 400, 600, 800, 1000 N at 15000 rpm; speed "
            "sweeps 2000-16000 rpm (step 2000) at 100 N and 1000 N; each with (TE) and without "
            "(WTE) thermal expansion; one zero-speed run at the preset's load and four (WTE) at "
            "the light loads. \"Room temperature\" is the WTE state (expansions held at 0), "
            "\"final\" the TE run's converged state, \"step 0\" the TE run's start (which "
            "already carries the centrifugal ring growth); per-ball numbers are ball 0's.\n\n", c->runs->n,
            acbb_model_level_name(c->model), acbb_study_n_failed(c->st));
    fprintf(f, "**%d held, %d not held, %d not evaluated** (of %zu).\n\n", nv[0], nv[1], nv[2],
            acbb_study_n_items(c->st));
    fprintf(f, "Loss set: %s (docs/physics.md section %s); physics profile: %s.\n\n", c->loss_set,
            strcmp(c->loss_set, "seed") == 0 ? "6: the seed's five" : "16: the seed's five and more",
            c->profile);
}

static void print_robust_md(FILE *f, const report_view *c)
{
    const acbb_study_rob *r = c->rob;
    char *t = malloc(FLIP_TEXT);
    if (!t) return;
    fprintf(f, "\n## Robustness over the plausible ranges (`--sensitivity`)\n\n"
            "The whole study re-run with every uncertain input (the ASSUMED and UNSURE "
            "parameters of docs/physics.md and the surroundings; `acbb keys` gives each plausible "
            "range "
            "and its source) set to each end of its range, one at a time, and every check "
            "evaluated there: %zu inputs, %zu ends (%zu equal to the scene's value), %zu runs in "
            "one pool, %zu points shared with the base runs (the input provably has no effect "
            "there), %zu failed; %.1f s. For an item that does not hold: the single plausible "
            "changes that would make it hold; for one that holds: those that would break it; "
            "each with the numbers of the checks that change. Nothing in the physics is changed "
            "to make a statement hold.\n\n| # | verdict | single plausible changes that turn "
            "it |\n|---|---|---|\n", r->n_inputs, r->n_ends, r->n_same, r->n_runs, r->n_shared,
            r->n_failed, 1e-3 * r->wall_ms);
    for (size_t k = 0; k < r->n_items; k++) {
        const acbb_study_item_rob *ir = &r->items[k];
        fprintf(f, "| %d | %s | ", ir->num, acbb_verdict_name(ir->verdict));
        item_rob_head(t, FLIP_TEXT, r, ir);
        md_text(f, strchr(t, ';') + 2);
        for (size_t j = 0; j < ir->n_turns; j++) {
            fprintf(f, "%s", j ? ", " : " ");
            md_text(f, ir->flips[j].key);
            fprintf(f, " = %s -> %s", ir->flips[j].value, acbb_verdict_name(ir->flips[j].verdict));
        }
        fputs(" |\n", f);
    }
    fputs("\n### The numbers under each change\n\nEvery single change that turns an item "
          "(**bold**) or some of its checks only, with those checks as evaluated there.\n\n", f);
    for (size_t k = 0; k < r->n_items; k++)
        for (size_t j = 0; j < r->items[k].n_flips; j++) {
            const acbb_study_flip *fl = &r->items[k].flips[j];
            flip_text(t, FLIP_TEXT, fl);
            fprintf(f, fl->turns_item ? "- **item %d**: " : "- item %d: ", r->items[k].num);
            md_text(f, t);
            fputc('\n', f);
        }
    fputs("\n### TE - WTE at the points of the sign statements\n\n"
          "The differences behind the sign statements and the thresholds on the relative TE "
          "effect (items 3, 9, 14), read from the same runs.\n\n"
          "| # | condition | at the scene's values | single plausible changes that turn it |\n"
          "|---|---|---|---|\n", f);
    for (size_t k = 0; k < r->n_signs; k++) {
        const acbb_study_robust *s = &r->signs[k];
        robust_text(t, FLIP_TEXT, s);
        char *colon = strstr(t, "; ");   /* value and verdict | the changes */
        if (colon) *colon = '\0';
        fprintf(f, "| %d | ", s->sign->item);
        md_text(f, s->sign->what);
        fputs(" | ", f);
        md_text(f, t);
        fputs(" | ", f);
        md_text(f, colon ? colon + 2 : "");
        fputs(" |\n", f);
    }
    free(t);
}

static void print_md(FILE *f, const report_view *c)
{
    size_t n = acbb_study_n_items(c->st), nc;
    const acbb_study_conclusion *cc = acbb_study_conclusions(&nc);
    print_md_head(f, c);
    fputs("| # | verdict | level | statement |\n|---|---|---|---|\n", f);
    for (size_t i = 0; i < n; i++) {
        const acbb_study_item *it = acbb_study_item_at(c->st, i);
        fprintf(f, "| %d | %s | %s | ", it->num, acbb_verdict_name(it->verdict),
                level_name(c, it->l2));
        md_text(f, it->statement);
        fputs(" |\n", f);
    }
    fputs("\n## Seed conclusions (seed section 5)\n\n| # | verdict | conclusion | checks |\n"
          "|---|---|---|---|\n", f);
    for (size_t i = 0; i < nc; i++) {
        char ids[64];
        fprintf(f, "| (%zu) | %s | ", i + 1,
                acbb_verdict_name(acbb_study_conclusion_verdict(c->st, i)));
        md_text(f, cc[i].text);
        concl_checks(ids, sizeof ids, &cc[i], " |", " |\n");
        fputs(ids, f);
    }
    fputs("\n## Seed conclusions by mounting\n\n", f);
    acbb_cli_mountings_md(f, c->by);
    acbb_report_contact_md(f, c->contact);
    fputs("\n## Evidence\n", f);
    for (size_t i = 0; i < n; i++) {
        const acbb_study_item *it = acbb_study_item_at(c->st, i);
        fprintf(f, "\n### %d. %s (%s)\n\n", it->num, acbb_verdict_name(it->verdict),
                level_name(c, it->l2));
        md_text(f, it->statement);
        fputs("\n\n", f);
        for (int k = 0; k < it->n_checks; k++) {
            fprintf(f, "- **%s %s**: ", it->checks[k].id,
                    it->checks[k].info ? "info" : acbb_verdict_name(it->checks[k].verdict));
            md_text(f, it->checks[k].text);
            fputc('\n', f);
        }
    }
    if (c->rob) print_robust_md(f, c);
    fputs("\nThresholds docs/physics.md does not give are fixed in src/batch/study_priv.h "
          "(REPORT_*) and "
          "named in each check.\n", f);
}

/* ---- arguments and entry ---- */

/* --inputs K1,K2,...: split at the commas into buf; implies --sensitivity. */
typedef struct {
    const char *keys[ACBB_SENS_MAX];
    size_t n;
    char buf[ACBB_SENS_MAX * 64];
} input_keys;

static int split_keys(input_keys *k, const char *v)
{
    size_t n = strlen(v);
    k->n = 0;
    if (n >= sizeof k->buf) return -1;
    memcpy(k->buf, v, n + 1);
    for (char *save = NULL, *t = strtok_r(k->buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        if (k->n == ACBB_SENS_MAX) return -1;
        k->keys[k->n++] = t;
    }
    return 0;
}

/* "robustness: 812 of 1904 runs", at most about four times a second (the
 * progress line's own redraw clock). */
static void rob_progress_fn(void *ctx, size_t done, size_t total)
{
    acbb_cli_progress *p = ctx;
    if (acbb_now_ms() - p->last_ms < 250.0) return;
    p->last_ms = acbb_now_ms();
    acbb_cli_progress_note(p, "robustness: %zu of %zu runs  (Ctrl-C stops)", done, total);
}

/* The study and, with --sensitivity, its robustness, under the one
 * SIGINT/SIGTERM handler (progress.h). 0; -1 when a signal stopped
 * them; else the exit status of a failed robustness (2 for bad --inputs,
 * 4 out of memory; message printed, and no report: it would lack the
 * section asked for).
 *
 * Cancelled means the engine stopped a run (ACBB_CANCELLED), as for
 * `sensitivity` and `bench accuracy`, the other all-or-nothing commands: a
 * signal that arrives after the last run finished (before the handler is
 * taken down) stopped nothing, so the complete report is printed and the
 * exit status is the runs' own. */
static int run_all(const acbb_cli_args *a, const input_keys *k, acbb_study *st,
                   acbb_study *const *other, acbb_study_rob *rob, bool *have_rob,
                   const acbb_scene *base, acbb_contact_study *cs)
{
    long jobs = 0;
    if (acbb_cli_count(a, CLI_OPT_JOBS, 0, 1, ACBB_CLI_MAX_JOBS, &jobs) != 0)
        return ACBB_EXIT_INPUT;
    acbb_cli_progress rp;
    acbb_cli_progress_init(&rp, stderr, 0.0);
    const atomic_int *cancel = acbb_cli_interrupt_begin();
    acbb_cli_progress_note(&rp, "report: running the study  (Ctrl-C stops)");
    acbb_status ss = acbb_study_run(st, (int)jobs, cancel);
    for (int m = 0; m < N_MOUNTINGS && ss != ACBB_CANCELLED; m++) {
        if (!other[m]) continue;
        acbb_cli_progress_note(&rp, "report: the study under %s  (Ctrl-C stops)",
                               acbb_cli_mountings[m].name);
        acbb_status so = acbb_study_run(other[m], (int)jobs, cancel);
        if (so == ACBB_CANCELLED) ss = so;
    }
    int rc = 0;
    if (ss != ACBB_CANCELLED) {
        acbb_error err = { { 0 } };
        acbb_cli_progress_note(&rp, "report: contact heat models on the runaway case  "
                               "(Ctrl-C stops)");
        acbb_status cr = acbb_contact_study_run(base, cancel, cs, &err);
        if (cr == ACBB_CANCELLED) ss = cr;
        else if (cr != ACBB_OK) {
            acbb_cli_say("report: contact heat models: %s; no report printed\n",
                    err.msg);
            rc = acbb_cli_exit_for(cr);
        }
    }
    if (ss != ACBB_CANCELLED && (a->val[CLI_OPT_SENSITIVITY] || k->n)) {
        acbb_error err = { { 0 } };
        acbb_study_rob_opts o = { .keys = k->n ? k->keys : NULL, .n_keys = k->n,
                                  .jobs = (int)jobs, .cancel = cancel,
                                  .progress = rob_progress_fn, .ctx = &rp };
        acbb_status rs = acbb_study_robustness(st, &o, rob, &err);
        *have_rob = rs == ACBB_OK;
        if (rs == ACBB_CANCELLED) {
            ss = rs;
        } else if (rs != ACBB_OK) {
            acbb_cli_say("report: --sensitivity: %s; %s\n",
                    err.msg[0] ? err.msg : acbb_status_name(rs), a->val[CLI_OPT_MD]
                    ? "no report printed, --md file not written" : "no report printed");
            rc = acbb_cli_exit_for(rs);
        }
    }
    acbb_cli_progress_end(&rp);
    acbb_cli_interrupt_end();
    return ss == ACBB_CANCELLED ? -1 : rc;
}

/* A cancelled report prints no verdicts (unfinished runs would read as NOT
 * EVALUATED findings) and writes no --md file (README "Usage"). */
static int cancelled(const acbb_cli_args *a)
{
    const char *kept = a->val[CLI_OPT_MD] ? "no report printed, --md file not written"
                                          : "no report printed";
    if (a->val[CLI_OPT_JSON]) acbb_cli_cancelled_json(stdout, "report", kept);
    return acbb_cli_worst(acbb_cli_cancelled("report", kept), acbb_cli_stdout_check(0));
}

static void free_studies(acbb_study *st, acbb_study *const *other)
{
    acbb_study_free(st);
    for (int m = 0; m < N_MOUNTINGS; m++) acbb_study_free(other[m]);
}

/* Plan, run and print; the Markdown file is opened before the runs so a
 * bad path fails fast, and replaces FILE only when complete. */
static int report(const acbb_cli_args *a, const input_keys *k, const acbb_scene *base)
{
    acbb_error err = { { 0 } };
    acbb_out *md = NULL;
    FILE *mf = NULL;
    const char *md_path = a->val[CLI_OPT_MD];
    if (md_path && acbb_out_open(md_path, &md, &mf, &err) != ACBB_OK) {
        acbb_cli_say("report: --md %s\n", err.msg);
        return ACBB_EXIT_INPUT;
    }
    acbb_study *st = NULL, *other[N_MOUNTINGS] = { NULL };
    int own = acbb_cli_own_mounting(base);
    acbb_status ps = acbb_study_plan(base, &st, &err);
    for (int m = 0; m < N_MOUNTINGS && ps == ACBB_OK; m++) {
        acbb_scene ms;
        acbb_cli_mounting_scene(base, m, &ms);
        if (m != own) ps = acbb_study_plan(&ms, &other[m], &err);
    }
    if (ps != ACBB_OK) {
        acbb_cli_say("report: out of memory\n");
        if (md) acbb_out_abort(md);
        free_studies(st, other);
        return ACBB_EXIT_INTERNAL;
    }
    acbb_study_rob rob = { 0 };
    bool have_rob = false;
    acbb_contact_study *cs = calloc(1, sizeof *cs);
    if (!cs) acbb_cli_say("report: out of memory\n");
    int rc = cs ? run_all(a, k, st, other, &rob, &have_rob, base, cs) : ACBB_EXIT_INTERNAL;
    if (rc != 0) {
        if (md) acbb_out_abort(md);
        free_studies(st, other);
        acbb_study_rob_free(&rob);
        free(cs);
        return rc < 0 ? cancelled(a) : rc;
    }
    report_view v = { a->preset, a->sets, a->n_sets, base->model, st, acbb_study_results(st),
                      have_rob ? &rob : NULL, { NULL }, acbb_loss_set(base), cs,
                      acbb_profile_name(base->profile) };
    for (int m = 0; m < N_MOUNTINGS; m++) v.by[m] = m == own ? st : other[m];
    long misuse = a->val[CLI_OPT_JSON] ? print_json(stdout, &v) : 0;
    if (!a->val[CLI_OPT_JSON]) print_text(stdout, &v);
    rc = acbb_cli_study_failed("report", st, "the statements that need them read n/e");
    if (misuse) { /* invalid JSON printed: a bug */
        acbb_cli_say("report: internal error: the JSON printed is invalid (%ld misuses of "
                     "its writer)\n", misuse);
        rc = ACBB_EXIT_INTERNAL;
    }
    rc = acbb_cli_worst(rc, acbb_cli_stdout_check(0)); /* says so on stderr */
    if (md) {
        print_md(mf, &v);
        if (acbb_out_commit(md, &err) != ACBB_OK) {
            acbb_cli_say("report: --md %s\n", err.msg);
            rc = ACBB_EXIT_INTERNAL;
        }
    }
    free_studies(st, other);
    acbb_study_rob_free(&rob);
    free(cs);
    return rc;
}

int acbb_cli_cmd_report(const acbb_cli_args *a)
{
    input_keys k = { .n = 0 };
    if (a->val[CLI_OPT_INPUTS] && split_keys(&k, a->val[CLI_OPT_INPUTS]) != 0) {
        acbb_cli_say("report: --inputs: too many inputs (at most %d)\n", ACBB_SENS_MAX);
        return ACBB_EXIT_INPUT;
    }
    acbb_scene base;
    int rc = acbb_cli_load_scene(a, &base);
    acbb_error err = { { 0 } };
    if (!rc && k.n && acbb_study_rob_check_keys(&base, &(acbb_study_rob_opts){ .keys = k.keys,
                                                .n_keys = k.n }, &err) != ACBB_OK) {
        acbb_cli_say("report: --inputs: %s; nothing run\n", err.msg);
        return ACBB_EXIT_INPUT;
    }
    return rc ? rc : report(a, &k, &base);
}
