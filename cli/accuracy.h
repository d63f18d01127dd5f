/* acbb CLI — `acbb bench accuracy`: what accuracy costs in time, on top of
 * the engine's accuracy module (include/acbb/tools/accuracy.h). Private to the
 * executable (main.c's command table routes `bench accuracy` here).
 *
 *   acbb bench accuracy PRESET [--set section.key=value]... [--repeat N]
 *        [--knobs k1,k2,...] [--models m1,m2,...] [--csv FILE]
 *        [--plot FILE.png|FILE.svg]
 *
 * stdout: a table (80 columns) of every setting with its status, median wall
 * time and relative errors in % against its knob's reference, notes for
 * failed or skipped settings, then the frontier: per knob the cheapest
 * setting within 1 % of the reference on total loss and outer-ring
 * temperature rise. --repeat defaults to 3 (1..1000); --knobs picks a subset
 * of model, contact_grid, hertz, mech_tol, steady_tol, thermal, network;
 * --models the model levels tried (static, quasi-static, quasi-dynamic,
 * dynamic; default all that acbb_sim_create accepts — dynamic can be slow).
 * --csv writes one row per setting (results by their `acbb metrics` names,
 * errors as fractions, %.17g, empty field for an undefined number)
 * atomically (include/acbb/tools/outfile.h). --plot
 * draws error vs wall time (log-log, one point set per knob) with gnuplot.
 *
 * Exit status: 0 every setting converged; 2 bad input (preset, --set,
 * options, CSV file); 3 some setting did not converge (the table shows it);
 * 4 the plot could not be made (gnuplot missing or failed; the table is
 * still printed) or stdout failed. The worst applicable one is returned.
 *
 * --envelope [--points N] [--jobs J]: acbb_accuracy_envelope instead; the
 * table has per setting the worst and median error over the points (steady
 * and transient path), the median work units per point, then the frontier
 * over the envelope and the ladder's numbers as C rows for
 * src/scene/fidelity_presets.c. Exit 3 when a setting failed at some point. */
#ifndef ACBB_CLI_ACCURACY_H
#define ACBB_CLI_ACCURACY_H

/* The handler, acbb_cli_bench_accuracy, is declared in commands.h. */

#include "acbb/scene.h"
#include "args.h"

/* `bench accuracy --envelope` (cli/accuracy_env.c). */
int acbb_cli_accuracy_envelope(const acbb_cli_args *a, const acbb_scene *base, unsigned knobs,
                               unsigned models);


#endif
