/* acbb CLI — `acbb study PRESET --out DIR`: the seed's figures (cli/figures.c). */
#ifndef ACBB_CLI_FIGURES_H
#define ACBB_CLI_FIGURES_H

#include "args.h"

/* a->preset resolved, a->val[CLI_OPT_OUT] the directory (made if missing).
 * Exit status: 0; 2 bad input; 3 a run failed (files still written);
 * 4 a panel could not be drawn (gnuplot) or a file not written. */
int acbb_cli_study_figures(const acbb_cli_args *a, long jobs);

#endif
