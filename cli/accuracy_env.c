/* acbb CLI — `acbb bench accuracy --envelope` (accuracy.h): every knob
 * setting over the seed's 48 study points, the frontier over the envelope,
 * and the ladder's measured numbers as rows for src/scene/fidelity_presets.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/accuracy.h"
#include "acbb/batch.h"
#include "acbb/tools/fidelity.h"
#include "accuracy.h"
#include "common.h"
#include "exit.h"
#include "progress.h"
#include "say.h"

static void label_of(const acbb_envelope_row *r, char *buf, size_t n)
{
    const char *dot = strchr(r->key, '.');
    if (r->knob == ACBB_KNOB_COUNT) snprintf(buf, n, "ladder %s", r->value);
    else snprintf(buf, n, "%s=%s", dot ? dot + 1 : r->key, r->value);
}

/* The worst path difference in K ("-" without a path): %.3f, so that a
 * few mK read as such next to the relative number; below 1 mK "%.0e" (as
 * the percentages: a solver-tolerance difference is not printed as 0). */
static void format_K(double k, char *buf, size_t n)
{
    if (!isfinite(k)) snprintf(buf, n, "-");
    else if (k == 0.0) snprintf(buf, n, "0");
    else if (k < 1e-3) snprintf(buf, n, "%.0e", k);
    else snprintf(buf, n, "%.3f", k);
}

/* Work and ms, "-" when no point converged (no NaN reaches the table). */
static void format_num(double v, char *buf, size_t n)
{
    if (isfinite(v)) snprintf(buf, n, "%.1f", v);
    else snprintf(buf, n, "-");
}

static void print_row(const acbb_envelope_row *r)
{
    char label[96], e[6][16], ok[16], pk[16], work[24], ms[24];
    label_of(r, label, sizeof label);
    const double v[6] = { r->worst_steady, r->median_steady, r->worst_loss, r->worst_T,
                          r->worst_path, r->median_path };
    for (int k = 0; k < 6; k++) acbb_accuracy_format_pct(v[k], e[k], sizeof e[k]);
    format_K(r->worst_path_K, pk, sizeof pk);
    snprintf(ok, sizeof ok, "%d/%d", r->n_ok, r->n_points);
    format_num(r->work, work, sizeof work);
    format_num(r->wall_ms, ms, sizeof ms);
    printf("%-22s %-2s %5s %6s %6s %6s %6s %6s %7s %6s %8s %7s\n", label,
           r->is_reference ? "R" : (r->is_default ? "D" : ""), ok, e[0], e[1], e[2], e[3], e[4],
           pk, e[5], work, ms);
}

static void print_table(const acbb_envelope_row *rows, size_t n)
{
    printf("%-22s %-2s %5s %6s %6s %6s %6s %6s %7s %6s %8s %7s\n", "setting", "", "ok", "worst%",
           "med%", "wLoss%", "wT%", "wPath%", "wPathK", "mPath%", "work", "ms");
    for (size_t i = 0; i < n; i++) {
        if (i > 0 && rows[i].knob != rows[i - 1].knob) putchar('\n');
        print_row(&rows[i]);
    }
}

static void print_frontier(const acbb_envelope_row *rows, size_t n)
{
    long picks[ACBB_KNOB_COUNT];
    acbb_envelope_frontier(rows, n, ACBB_ACCURACY_FRONTIER_TOL, picks);
    printf("\nfrontier over the envelope: per knob the least work whose worst steady and\n"
           "path errors are within %g %% at every point (ties: the coarser setting)\n",
           100.0 * ACBB_ACCURACY_FRONTIER_TOL);
    for (int k = 0; k < ACBB_KNOB_COUNT; k++) {
        if (picks[k] < 0) continue;
        char label[96], w[16], p[16], pk[16];
        label_of(&rows[picks[k]], label, sizeof label);
        acbb_accuracy_format_pct(rows[picks[k]].worst_steady, w, sizeof w);
        acbb_accuracy_format_pct(rows[picks[k]].worst_path, p, sizeof p);
        format_K(rows[picks[k]].worst_path_K, pk, sizeof pk);
        printf("  %-12s %-22s worst %s %%, path %s %% (%s K), %.1f work units\n",
               acbb_accuracy_knob_name((acbb_accuracy_knob)k), label, w, p, pk,
               rows[picks[k]].work);
    }
}

/* The measured numbers for k_table (relative errors and K, %.3g; work %.4g). */
static void print_c_rows(const acbb_envelope_row *rows, size_t n)
{
    printf("\nstored frontier rows (paste the numbers into src/scene/fidelity_presets.c):\n");
    for (size_t i = 0; i < n; i++) {
        const acbb_envelope_row *r = &rows[i];
        if (r->knob != ACBB_KNOB_COUNT) continue;
        if (r->n_ok < r->n_points) { /* numbers over some points only, or NaN: no row */
            printf("  /* %-9s */ not measured: converged at %d of %d points\n", r->value,
                   r->n_ok, r->n_points);
            continue;
        }
        printf("  /* %-9s */ %.3g, %.3g, %.3g, %.3g, %.3g, %.4g\n", r->value, r->worst_steady,
               r->median_steady, r->worst_path, r->median_path, r->worst_path_K, r->work);
    }
}

static void tick(void *ctx, size_t done, size_t total)
{
    (void)ctx;
    acbb_cli_progress_draw("\racbb: bench accuracy --envelope: %zu/%zu points%s", done, total,
                           done == total ? "\r\033[K" : "");
}

/* Settings without a converged pair (it and its reference) at every
 * point: exit 3 and one line on stderr saying so. */
static int say_failed(const acbb_envelope_row *rows, size_t n)
{
    size_t failed = 0, first = 0;
    for (size_t i = 0; i < n; i++)
        if (rows[i].n_ok < rows[i].n_points && !failed++) first = i;
    if (!failed) return 0;
    char label[96];
    label_of(&rows[first], label, sizeof label);
    acbb_cli_say("bench accuracy --envelope: %zu of %zu settings did not converge with their "
                 "reference at every point (first: %s, %d of %d); the ok column counts them\n",
                 failed, n, label, rows[first].n_ok, rows[first].n_points);
    return ACBB_EXIT_SOLVER;
}

int acbb_cli_accuracy_envelope(const acbb_cli_args *a, const acbb_scene *base, unsigned knobs,
                               unsigned models)
{
    long points = 0, jobs = 0;
    int rc = acbb_cli_count(a, CLI_OPT_POINTS, ACBB_ENVELOPE_POINTS, 1, ACBB_ENVELOPE_POINTS,
                            &points);
    if (!rc) rc = acbb_cli_count(a, CLI_OPT_JOBS, 0, 1, ACBB_CLI_MAX_JOBS, &jobs);
    if (rc) return rc;
    acbb_envelope_options o = { .knobs = knobs, .model_levels = models, .points = (int)points,
                                .jobs = (int)jobs, .ladder = 1 };
    /* A cancelled envelope prints nothing: its rows would be over fewer
     * points than they say (progress.h). */
    o.cancel = acbb_cli_interrupt_begin();
    size_t cap = acbb_envelope_size(&o), n = 0;
    acbb_envelope_row *rows = calloc(cap, sizeof *rows);
    if (!rows) return ACBB_EXIT_INTERNAL;
    acbb_error err = { { 0 } };
    double ms = 0.0;
    acbb_status st = acbb_accuracy_envelope(base, &o, rows, cap, &n, &ms,
                                            acbb_cli_progress_wanted(stderr) ? tick : NULL, NULL,
                                            &err);
    acbb_cli_interrupt_end();
    if (st == ACBB_CANCELLED) {
        free(rows);
        return acbb_cli_cancelled("bench accuracy", "no table written (it would be partial)");
    }
    if (st != ACBB_OK) {
        acbb_cli_say("bench accuracy: %s\n", err.msg[0] ? err.msg : acbb_status_name(st));
        free(rows);
        return acbb_cli_exit_for(st);
    }
    int workers = acbb_batch_workers((size_t)points, (int)jobs);
    printf("acbb bench accuracy %s --envelope: %ld of the seed's 48 study points, %d thread%s,"
           " %.1f s\n", a->preset, points, workers, workers == 1 ? "" : "s", 1e-3 * ms);
    printf("Per setting over the points: worst / median of max(loss, T) error %% against its\n"
           "knob's reference (ladder: against 'reference'), worst loss and T errors, the\n"
           "transient path error (max |T(t) - T_ref(t)|, outer ring) in %% and, wPathK, in K,\n"
           "median work units and wall ms per point. Temperature errors (T, path) are over\n"
           "max(reference rise, %g K): a smaller rise is within thermocouple tolerance.\n"
           "'-' = no path. ok: points where it and its reference converged.\n\n",
           ACBB_ACCURACY_T_FLOOR_K);
    print_table(rows, n);
    print_frontier(rows, n);
    print_c_rows(rows, n);
    rc = say_failed(rows, n);
    free(rows);
    return acbb_cli_worst(rc, acbb_cli_stdout_check(0));
}
