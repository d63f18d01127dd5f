/* acbb CLI — gnuplot export glue: the `acbb plot` subcommand and the
 * `acbb run ... --plot FILE` writer, on top of the engine's plot module
 * (include/acbb/tools/plot.h). Private to the executable.
 *
 * Exit statuses (exit.h): 0 ok, 2 bad input, 3 the solver did not
 * reach steady state (the plot is still written, from the last good state),
 * 4 gnuplot missing or failed; then stderr says, e.g.
 *   acbb: gnuplot not found on PATH (install gnuplot-nox) — plot not written
 *
 * File naming. A kind-less request writes every kind, the siblings named
 * by inserting "-<kind>" before the extension:
 *   acbb plot P --kind all --out DIR/x.png
 *       -> DIR/x-temperature.png, DIR/x-losses.png, DIR/x-loads.png,
 *          DIR/x-angles.png, DIR/x-history-loads.png   (five files)
 *   acbb run P --plot DIR/r.png            (acbb_cli_write_plot)
 *       -> DIR/r.png is the temperature plot (the one a user asked a run
 *          for), next to it DIR/r-losses.png, DIR/r-loads.png,
 *          DIR/r-angles.png, DIR/r-history-loads.png
 * The format comes from the extension (.png or .svg, any case). */
#ifndef ACBB_CLI_PLOT_H
#define ACBB_CLI_PLOT_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/tools/history.h"
#include "args.h"
#include "acbb/sim.h"

/* `acbb plot` (options: main.c's command table): runs the scene and draws
 * --kind (default temperature; all = every kind) to --out FILE.png|.svg, or
 * with gnuplot's dumb terminal on stdout. --size defaults to 1000x600
 * pixels (or a print size, acbb_plot_parse_size), or 80x25 characters
 * for the dumb terminal. The handler itself is
 * acbb_cli_plot in commands.h. */

/* Parse --size "WxH" (whole numbers) or a print size ("column", "full",
 * "85mm", "85mmx60mm": acbb_plot_parse_size): 0, or 2 with a message on stderr.
 * The range is the plot module's to check (acbb_plot_check_size). */
int acbb_cli_parse_size(const char *text, int *w, int *h);

/* The files next to `path` a write of every kind makes (naming above):
 * `all` (plot --kind all) every kind, else (run --plot) every kind but
 * the temperature plot, which goes to `path` itself. Into out[max], each
 * CLI_PATH_MAX long (a longer one is cut); returns the count. For the
 * output guard (out_guard.h): they are outputs too. */
#define ACBB_CLI_PLOT_SIBLINGS 5
size_t acbb_cli_plot_siblings(const char *path, bool all, char (*out)[CLI_PATH_MAX], size_t max);

/* Check a `--plot FILE` argument before a run starts: 0, or 2 with a
 * message on stderr if the extension is neither .png nor .svg. */
int acbb_cli_plot_check_path(const char *path);

/* Write the plots of a finished run (naming above) at 1000x600 pixels.
 * `title` (may be NULL) heads every plot, e.g. the preset name. Returns 0,
 * 2 for a path without a .png/.svg extension, or 4 if gnuplot is missing
 * or failed or a file could not be written; the message is on stderr.
 * Stops at the first failure. */
int acbb_cli_write_plot(const char *path, const acbb_history *h, const acbb_snapshot *final,
                        const char *title);

#endif
