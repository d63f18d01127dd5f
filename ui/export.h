/* acbb TUI — gnuplot export of the current run (no curses here). */
#ifndef ACBB_UI_EXPORT_H
#define ACBB_UI_EXPORT_H

#include <stddef.h>
#include "acbb/accuracy.h"
#include "acbb/history.h"
#include "acbb/plot.h"

/* Write temperature, losses, loads and angles as PNG and SVG into `dir`
 * (created if missing): dir/temperature.png, dir/temperature.svg, ...
 * Stops at the first failure (e.g. gnuplot missing) with err set.
 * *written counts the files written. */
acbb_status acbb_export_plots(const char *dir, const acbb_history *h, const acbb_snapshot *s,
                              const char *title, int *written, acbb_error *err);

/* Write the accuracy-versus-time plot of a finished benchmark
 * (acbb_plot_accuracy_file) as dir/accuracy.png and dir/accuracy.svg, the
 * CLI's 1000 x 650 pixels. Errors and *written as acbb_export_plots. */
acbb_status acbb_export_accuracy(const char *dir, const acbb_accuracy_row *rows, size_t n,
                                 const char *title, int *written, acbb_error *err);

#endif
