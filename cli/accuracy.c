/* acbb CLI — `acbb bench accuracy` (see accuracy.h).
 *
 * A thin client of include/acbb/tools/accuracy.h: load the preset, apply --set
 * edits, run the plan, print the table and the frontier, write CSV and the
 * plot. Arguments come parsed from the command table (args.h); no user
 * text reaches a shell (the plot module spawns gnuplot directly).
 * The locale is never set, so numbers always use a decimal point. */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/accuracy.h"
#include "acbb/units.h"
#include "acbb/tools/plot.h"
#include "acbb/scene.h"
#include "acbb/tools/scene_schema.h"
#include "accuracy.h"
#include "accuracy_row.h"
#include "commands.h"
#include "common.h"
#include "exit.h"
#include "progress.h"
#include "say.h"

#define ACC_PLOT_W 2067 /* "full": 17.5 cm at 300 dpi (plot.h) */
#define ACC_PLOT_H 1300

/* What the options say, checked. */
typedef struct {
    const char *preset;
    long repeat;
    unsigned knobs;      /* 0 = all */
    unsigned models;     /* 0 = all */
    const char *csv;
    const char *plot;
} acc_args;

static int bad_usage(const char *what, const char *arg)
{
    acbb_cli_say("bench accuracy: %s%s\ntry `acbb help bench accuracy`\n", what,
            arg ? arg : "");
    return ACBB_EXIT_INPUT;
}

/* ---- arguments ---- */

/* acbb_model_level from its scene name ("quasi-static"), or -1. */
static int model_from_name(const char *name)
{
    for (int m = ACBB_MODEL_STATIC; m <= ACBB_MODEL_DYNAMIC; m++)
        if (strcmp(acbb_model_level_name((acbb_model_level)m), name) == 0) return m;
    return -1;
}

/* "contact_grid,hertz" -> bit mask (1 << lookup(name)); every name must
 * be known to `lookup`. */
static int parse_list(const char *opt, const char *text, int (*lookup)(const char *),
                      unsigned *mask)
{
    char buf[256];
    if (strlen(text) >= sizeof buf) return bad_usage("list too long: ", text);
    strcpy(buf, text);
    *mask = 0;
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok;
         tok = strtok_r(NULL, ",", &save)) {
        int k = lookup(tok);
        if (k < 0) {
            acbb_cli_say("bench accuracy: %s: unknown name '%s'\n"
                    "try `acbb help bench accuracy`\n", opt, tok);
            return ACBB_EXIT_INPUT;
        }
        *mask |= 1u << (unsigned)k;
    }
    if (*mask == 0) return bad_usage("empty list: ", text);
    return 0;
}

static int check_args(acc_args *o, const acbb_cli_args *a)
{
    o->preset = a->preset;
    o->csv = a->val[CLI_OPT_CSV];
    o->plot = a->val[CLI_OPT_PLOT];
    int rc = acbb_cli_count(a, CLI_OPT_REPEAT, ACBB_ACCURACY_DEFAULT_REPEATS, 1,
                            ACBB_ACCURACY_MAX_REPEATS, &o->repeat);
    if (!rc && a->val[CLI_OPT_KNOBS])
        rc = parse_list("--knobs", a->val[CLI_OPT_KNOBS], acbb_accuracy_knob_from_name, &o->knobs);
    if (!rc && a->val[CLI_OPT_MODELS])
        rc = parse_list("--models", a->val[CLI_OPT_MODELS], model_from_name, &o->models);
    if (!rc && o->plot && acbb_plot_format_from_name(o->plot) != ACBB_PLOT_PNG &&
        acbb_plot_format_from_name(o->plot) != ACBB_PLOT_SVG)
        rc = bad_usage("--plot needs a .png or .svg file name, got ", o->plot);
    return rc;
}

/* ---- formatting ---- */

static void print_row(const acbb_accuracy_row *r)
{
    char line[160];
    acbb_cli_acc_row(r, line, sizeof line);
    puts(line);
}

static void print_table(const acc_args *a, const acbb_accuracy_row *rows, size_t n)
{
    printf("acbb bench accuracy %s (median wall time of %ld run%s per setting)\n",
           a->preset, a->repeat, a->repeat == 1 ? "" : "s");
    printf("One [fidelity] knob at a time around the preset. R: the knob's reference\n"
           "(finest value; model: highest level available), D: the preset's value.\n"
           "Errors in %% are |x - x_ref| / |x_ref| against the knob's reference: total\n"
           "loss, outer-ring temperature RISE above ambient (T; over max(rise, %g K): a\n"
           "smaller rise is within thermocouple tolerance), and for ball 0 at its\n"
           "inner contact the load Qi, angle alpha and sliding speed slide. work: cost in\n"
           "work units (M instructions, from the Sim's counters: repeatable).\n\n",
           ACBB_ACCURACY_T_FLOOR_K);
    char header[160];
    acbb_cli_acc_header(header, sizeof header);
    puts(header);
    acbb_accuracy_knob last = ACBB_KNOB_COUNT;
    for (size_t i = 0; i < n; i++) {
        if (rows[i].skipped) continue;
        if (last != ACBB_KNOB_COUNT && rows[i].knob != last) putchar('\n');
        last = rows[i].knob;
        print_row(&rows[i]);
    }
}

static void print_notes(const acbb_accuracy_row *rows, size_t n)
{
    bool any = false;
    for (size_t i = 0; i < n; i++) {
        if (rows[i].status == ACBB_OK) continue;
        char label[96];
        acbb_cli_acc_label(&rows[i], label, sizeof label);
        if (!any) putchar('\n');
        any = true;
        if (rows[i].skipped)
            printf("note: %s skipped, not available: %s\n", label, rows[i].message);
        else
            printf("note: %s %s: %s\n", label, acbb_cli_acc_status(&rows[i]), rows[i].message);
    }
}

static void print_frontier(const acbb_accuracy_row *rows, size_t n)
{
    long picks[ACBB_KNOB_COUNT];
    acbb_accuracy_frontier(rows, n, ACBB_ACCURACY_FRONTIER_TOL, picks);
    printf("\nfrontier: the cheapest setting (work units) within %g %% of its reference on\n"
           "loss and T\n", 100.0 * ACBB_ACCURACY_FRONTIER_TOL);
    printf("%-12s %-19s %7s %6s %6s  %s\n", "knob", "choice", "work", "loss%", "T%",
           "vs reference");
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        long ref = acbb_accuracy_reference(rows, n, (acbb_accuracy_knob)k);
        bool present = false;
        for (size_t i = 0; i < n; i++) present = present || rows[i].knob == (acbb_accuracy_knob)k;
        if (!present) continue;
        const char *name = acbb_accuracy_knob_name((acbb_accuracy_knob)k);
        if (picks[k] < 0) {
            printf("%-12s %s\n", name, "- (the reference did not converge)");
            continue;
        }
        const acbb_accuracy_row *r = &rows[picks[k]];
        char label[96], el[16], eT[16], vs[64];
        acbb_cli_acc_label(r, label, sizeof label);
        acbb_accuracy_format_pct(r->e_loss, el, sizeof el);
        acbb_accuracy_format_pct(r->e_T, eT, sizeof eT);
        if (picks[k] == ref)
            snprintf(vs, sizeof vs, "the reference itself");
        else
            snprintf(vs, sizeof vs, "%.2fx less work", rows[ref].work / r->work);
        printf("%-12s %-19s %7.1f %6s %6s  %s\n", name, label, r->work, el, eT, vs);
    }
}

/* ---- CSV ---- */

static void csv_num(FILE *f, double x)
{
    if (isfinite(x)) fprintf(f, ",%.17g", x);
    else fputc(',', f);
}

static void csv_rows(FILE *f, const acbb_accuracy_row *rows, size_t n)
{
    /* The results by their `acbb metrics` names and units (issue 28 item 7:
     * they were loss_W, Qi_N, alpha_i_rad, slide_i_m_s); the angle in
     * degrees as the output table computes it (SI / ACBB_DEG). */
    fputs("knob,key,value,is_reference,is_default,status,iterations,wall_ms,losses_W.total,"
          "dT_outer_K,balls[0].Qi_N,balls[0].alpha_i_deg,balls[0].slide_i_mps,e_loss,e_T,e_Qi,"
          "e_alpha,e_slide,work\n", f);
    for (size_t i = 0; i < n; i++) {
        const acbb_accuracy_row *r = &rows[i];
        fprintf(f, "%s,%s,%s,%d,%d,%s,%ld", acbb_accuracy_knob_name(r->knob), r->key, r->value,
                r->is_reference, r->is_default, acbb_cli_acc_status(r), r->iterations);
        const double v[] = { r->wall_ms, r->loss, r->dT_outer, r->Qi, r->alpha_i / ACBB_DEG, r->slide_i,
                             r->e_loss, r->e_T, r->e_Qi, r->e_alpha, r->e_slide, r->work };
        for (size_t k = 0; k < sizeof v / sizeof v[0]; k++) csv_num(f, v[k]);
        fputc('\n', f);
    }
}

/* Through the atomic writer: a reader never sees a half-written file. */
static int write_csv(const char *path, const acbb_accuracy_row *rows, size_t n)
{
    acbb_cli_file file;
    int rc = acbb_cli_file_open(&file, path);
    if (rc) return rc;
    csv_rows(file.out.f, rows, n);
    return acbb_cli_file_close(&file);
}

/* ---- plot ---- */

/* gnuplot missing or failing costs only the picture: the table is already
 * on stdout. */
static int write_plot(const char *path, const char *preset, const acbb_accuracy_row *rows,
                      size_t n)
{
    acbb_error err = { { 0 } };
    acbb_plot_format fmt = (acbb_plot_format)acbb_plot_format_from_name(path);
    acbb_status st = acbb_plot_accuracy_file(rows, n, fmt, path, ACC_PLOT_W, ACC_PLOT_H, preset,
                                             &err);
    if (st == ACBB_OK) return 0;
    acbb_cli_say("%s — plot not written\n", err.msg[0] ? err.msg : acbb_status_name(st));
    return ACBB_EXIT_INTERNAL;
}

/* ---- main ---- */

static void progress_tick(void *ctx, size_t done, size_t total)
{
    (void)ctx;
    acbb_cli_progress_draw("\racbb: bench accuracy: %zu/%zu settings%s", done, total,
                           done == total ? "\r\033[K" : "");
}

/* Settings that failed (not those skipped as not available): exit 3 and
 * one line on stderr saying so (the notes on stdout say which). */
static int say_failed(const acbb_accuracy_row *rows, size_t n)
{
    size_t failed = 0, ran = 0;
    char first[700] = "";
    for (size_t i = 0; i < n; i++) {
        if (rows[i].skipped) continue;
        ran++;
        if (rows[i].status == ACBB_OK || failed++) continue;
        char label[96];
        acbb_cli_acc_label(&rows[i], label, sizeof label);
        snprintf(first, sizeof first, "%s: %s: %s", label, acbb_cli_acc_status(&rows[i]),
                 rows[i].message);
    }
    return acbb_cli_runs_failed("bench accuracy", failed, ran, first,
                                "the table's notes list them");
}

/* Cancelled: the settings that finished, without errors (an unfinished
 * knob has no reference) or frontier; no --csv or --plot file (README
 * "Usage"). */
static int bench_cancelled(const acc_args *a, const acbb_accuracy_row *rows, size_t n)
{
    print_table(a, rows, n);
    char kept[128];
    snprintf(kept, sizeof kept, "%zu setting%s timed (errors need the knob's reference); no "
             "file written", n, n == 1 ? "" : "s");
    return acbb_cli_worst(acbb_cli_cancelled("bench accuracy", kept), acbb_cli_stdout_check(0));
}

static int run_bench(const acc_args *a, const acbb_scene *base)
{
    acbb_accuracy_options opt = { .knobs = a->knobs, .model_levels = a->models,
                                  .repeats = (int)a->repeat };
    size_t cap = acbb_accuracy_plan_size(&opt), n = 0;
    acbb_accuracy_row *rows = calloc(cap, sizeof *rows);
    if (!rows) return ACBB_EXIT_INTERNAL;
    acbb_error err = { { 0 } };
    acbb_accuracy_progress tick = acbb_cli_progress_wanted(stderr) ? progress_tick : NULL;
    opt.cancel = acbb_cli_interrupt_begin();
    acbb_status st = acbb_accuracy_run(base, &opt, rows, cap, &n, tick, NULL, &err);
    acbb_cli_interrupt_end();
    if (st == ACBB_CANCELLED) {
        if (tick) acbb_cli_progress_draw("\n");
        int rc = bench_cancelled(a, rows, n);
        free(rows);
        return rc;
    }
    if (st != ACBB_OK) {
        acbb_cli_say("bench accuracy: %s\n", err.msg[0] ? err.msg : acbb_status_name(st));
        free(rows);
        return acbb_cli_exit_for(st);
    }
    print_table(a, rows, n);
    print_notes(rows, n);
    print_frontier(rows, n);
    int rc = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        acbb_cli_say("cannot write to stdout\n");
        rc = ACBB_EXIT_INTERNAL;
    }
    if (a->csv) rc = acbb_cli_worst(rc, write_csv(a->csv, rows, n));
    if (a->plot) rc = acbb_cli_worst(rc, write_plot(a->plot, a->preset, rows, n));
    rc = acbb_cli_worst(rc, say_failed(rows, n));
    free(rows);
    return rc;
}

int acbb_cli_bench_accuracy(const acbb_cli_args *args)
{
    acc_args a = { 0 };
    acbb_scene base;
    int rc = check_args(&a, args);
    if (!rc) rc = acbb_cli_load_scene(args, &base);
    if (!rc && args->val[CLI_OPT_ENVELOPE])
        return acbb_cli_accuracy_envelope(args, &base, a.knobs, a.models);
    if (!rc) rc = run_bench(&a, &base);
    return rc;
}
