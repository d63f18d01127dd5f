/* acbb TUI — the accuracy screen's numbers and its error-vs-time chart
 * model (no curses here, so test_worker checks them by hand).
 *
 * The chart is log-log like `acbb bench accuracy --plot` (plot.h): x is the
 * median wall time in ms, y is max(e_loss, e_T) in %. Both axes span whole
 * decades. An error of exactly 0 (every reference) has no logarithm, so the
 * lowest decade of the y range is kept free and such points sit on it: the
 * bottom row reads "0". The y range always holds the frontier tolerance
 * (ACBB_ACCURACY_FRONTIER_TOL, 1 %) so its line can be drawn. */
#ifndef ACBB_UI_ACC_CHART_H
#define ACBB_UI_ACC_CHART_H

#include <stddef.h>
#include "acbb/tools/accuracy.h"
#include "bench.h"

typedef struct {
    double x, y;         /* log10(ms), log10(error %); y = ymin for an error of 0 */
    acbb_accuracy_knob knob;
    size_t row;          /* index into the rows */
    int zero;            /* the error is exactly 0 */
} acbb_acc_point;

typedef struct {
    double xmin, xmax;   /* log10 ms, whole decades, xmax > xmin */
    double ymin, ymax;   /* log10 %, whole decades, ymin <= log10(tol %) - 1 < ymax */
    size_t n;
    acbb_acc_point p[ACBB_BENCH_MAX_ROWS];
} acbb_acc_chart;

/* max(e_loss, e_T) in %, the quantity the frontier bounds; NaN when either
 * is undefined (failed, skipped, or errors not yet known). */
double acbb_acc_error_pct(const acbb_accuracy_row *r);

/* Points and decade ranges for rows[0..n) (at most ACBB_BENCH_MAX_ROWS):
 * converged rows with a defined error and a positive time. Returns c->n. */
size_t acbb_acc_chart_build(const acbb_accuracy_row *rows, size_t n, acbb_acc_chart *c);

/* The chart's letter for a knob: M model, G contact_grid, H hertz,
 * E mech_tol, S steady_tol, T thermal, N network. */
char acbb_acc_knob_letter(acbb_accuracy_knob k);

/* A relative error as a percentage in at most 6 characters, exactly as the
 * CLI's table prints it: "-" undefined, "0", "2e-03" below 0.01, "2.21". */
void acbb_acc_fmt_pct(double e, char *buf, size_t n);

/* A decade label: 10^d % as "0.01%" .. "1000%", else "1e-05%" (<= 7 chars). */
void acbb_acc_fmt_pct_decade(int d, char *buf, size_t n);
/* A decade label: 10^d ms as "1ms" .. "100ms", "1s" .. "1000s", else "1e+06ms". */
void acbb_acc_fmt_ms_decade(int d, char *buf, size_t n);

/* "contact_grid=4": the key without its "fidelity." section. */
void acbb_acc_setting_label(const acbb_accuracy_row *r, char *buf, size_t n);

#endif
