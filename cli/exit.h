/* acbb — the exit statuses, defined once for every CLI command and the
 * TUI (ui/ includes this header; the engine's include/acbb does not know
 * them). `acbb help` and the man page print them from cli/help.c.
 *
 *   0  converged (or the command did its job)
 *   2  bad input: options, preset, --set edits, an ill-posed scene, an
 *      output path that cannot be opened, names an input or another
 *      output, or two formats on one stream; a FIFO with no reader
 *   3  the solver did not reach steady state (output is still printed;
 *      the --max-wall bound, status wall_limit, included),
 *      or the command was cancelled (SIGINT / SIGTERM, progress.h): what
 *      finished is written, status `cancelled`; `acbb merge`: points
 *      missing (the others are written)
 *   4  internal error: non-finite output, stdout failed (a closed pipe
 *      included), an output file's write failed (disk full), out of
 *      memory, gnuplot missing or failing
 *   1  the TUI only: its terminal went away (no SIGHUP came)
 * 128+N killed by signal N: a second SIGINT/SIGTERM during a cancel, or
 *      the TUI leaving on SIGTERM, SIGHUP or SIGQUIT (edits saved first)
 * When several apply the worst (highest) one is returned. */
#ifndef ACBB_CLI_EXIT_H
#define ACBB_CLI_EXIT_H

#include "acbb/status.h"

typedef enum {
    ACBB_EXIT_OK = 0,
    ACBB_EXIT_HANGUP = 1,
    ACBB_EXIT_INPUT = 2,
    ACBB_EXIT_SOLVER = 3,
    ACBB_EXIT_CANCELLED = 3,
    ACBB_EXIT_INTERNAL = 4,
} acbb_cli_exit;

/* The shell's status of a process ended by signal `sig`. */
#define ACBB_EXIT_SIGNAL(sig) (128 + (sig))

static inline int acbb_cli_worst(int a, int b) { return a > b ? a : b; }

/* The exit status for an engine status: input errors 2, out of memory 4,
 * every solver outcome 3. */
static inline int acbb_cli_exit_for(acbb_status st)
{
    switch (st) {
    case ACBB_OK: return ACBB_EXIT_OK;
    case ACBB_EINVAL: case ACBB_EIO: case ACBB_ILL_POSED: return ACBB_EXIT_INPUT;
    case ACBB_ENOMEM: return ACBB_EXIT_INTERNAL;
    default: return ACBB_EXIT_SOLVER;
    }
}

#endif
