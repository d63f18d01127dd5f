/* acbb TUI — gnuplot export of the current run (no curses here). */
#ifndef ACBB_UI_EXPORT_H
#define ACBB_UI_EXPORT_H

#include "acbb/history.h"
#include "acbb/plot.h"

/* Write temperature, losses, loads and angles as PNG and SVG into `dir`
 * (created if missing): dir/temperature.png, dir/temperature.svg, ...
 * Stops at the first failure (e.g. gnuplot missing) with err set.
 * *written counts the files written. */
acbb_status acbb_export_plots(const char *dir, const acbb_history *h, const acbb_snapshot *s,
                              const char *title, int *written, acbb_error *err);

#endif
