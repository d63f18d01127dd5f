/* acbb TUI — gnuplot export of the screens' results (no curses here).
 *
 * An export never overwrites an earlier one (issue 29 item 8): the files
 * are dir/NAME.png and dir/NAME.svg the first time, then NAME-2, NAME-3,
 * ... (one counter for a group of files written together), so a TE run's
 * plots and a WTE run's stay side by side. The caller names the files. */
#ifndef ACBB_UI_EXPORT_H
#define ACBB_UI_EXPORT_H

#include <stddef.h>
#include "acbb/tools/accuracy.h"
#include "acbb/tools/history.h"
#include "acbb/tools/plot.h"

/* Create dir if missing; into suffix[0..len) the first of "", "-2", "-3",
 * ... for which no dir/<base><suffix>.png or .svg exists, for every base
 * of bases[0..n). ACBB_EIO if dir cannot be made or 999 are taken. */
acbb_status acbb_export_suffix(const char *dir, const char *const *bases, size_t n, char *suffix,
                               size_t len, acbb_error *err);

/* Write temperature, losses, loads, angles and history-loads as PNG and
 * SVG into `dir`: dir/temperature<suffix>.png, ... Stops at the first
 * failure (e.g. gnuplot missing) with err set. *written counts the files
 * written; suffix[0..slen) gets the counter used. */
acbb_status acbb_export_plots(const char *dir, const acbb_history *h, const acbb_snapshot *s,
                              const char *title, char *suffix, size_t slen, int *written,
                              acbb_error *err);

/* The accuracy-versus-time plot of a finished benchmark
 * (acbb_plot_accuracy_file) as dir/accuracy<suffix>.png and .svg, the
 * CLI's 1000 x 650 pixels. Errors, suffix and *written as above. */
acbb_status acbb_export_accuracy(const char *dir, const acbb_accuracy_row *rows, size_t n,
                                 const char *title, char *suffix, size_t slen, int *written,
                                 acbb_error *err);

/* An x-y plot (acbb_plot_xy_files) as dir/<base><suffix>.png and .svg,
 * w x h pixels; the paths written go to png and svg (len bytes each). */
acbb_status acbb_export_xy(const char *dir, const char *base, const acbb_plot_xy *p, int w, int h,
                           char png[], char svg[], size_t len, acbb_error *err);

/* A tornado chart (acbb_plot_tornado_file) likewise. */
acbb_status acbb_export_tornado(const char *dir, const char *base, const acbb_tornado_bar *bars,
                                size_t n, double mid, const char *title, const char *xlabel,
                                char png[], char svg[], size_t len, acbb_error *err);

#endif
