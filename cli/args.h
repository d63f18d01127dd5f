/* acbb CLI — one argument parser for every command, driven by two tables
 * (tmux's cmd_table idea, DESIGN.md "Examples"): each option is a row
 * {long name, value name or NULL for a flag, help}, each command a row
 * {name, positional arguments, summary, allowed options, handler}. The same
 * rows print `acbb help CMD`, `acbb CMD --help` and `acbb help`, so usage
 * text can never drift from what the parser accepts.
 *
 * Accepted forms: `--name`, `--name value`, `--name=value`, `-h`; `--`
 * ends the options. --set, --grid and --metric may repeat; for every other option the last one
 * wins. An unknown option is refused with exit 2 and, when a known one is
 * close (edit distance), "did you mean --x?". No user text ever reaches a
 * shell. */
#ifndef ACBB_CLI_ARGS_H
#define ACBB_CLI_ARGS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "wrap.h"

typedef enum {
    CLI_OPT_SET, CLI_OPT_JSON, CLI_OPT_CSV, CLI_OPT_QUIET, CLI_OPT_PLOT,
    CLI_OPT_PARAM, CLI_OPT_VALUES, CLI_OPT_JOBS, CLI_OPT_REPEAT, CLI_OPT_KIND,
    CLI_OPT_OUT, CLI_OPT_DUMB, CLI_OPT_SIZE, CLI_OPT_KNOBS, CLI_OPT_MODELS,
    CLI_OPT_MD, CLI_OPT_PACE, CLI_OPT_PLOT_DIR, CLI_OPT_EXIT_AFTER_STEADY,
    CLI_OPT_SERIES, CLI_OPT_BORE, CLI_OPT_ANGLE, CLI_OPT_NO_MOUSE,
    CLI_OPT_HELP, CLI_OPT_BASELINE,
    CLI_OPT_GRID, CLI_OPT_JSONL, CLI_OPT_SHARD, CLI_OPT_MAX_POINTS,
    CLI_OPT_METRIC, CLI_OPT_DELTA, CLI_OPT_MORRIS, CLI_OPT_SENSITIVITY,
    CLI_OPT_ENVELOPE, CLI_OPT_POINTS, CLI_OPT_INPUTS, CLI_OPT_MAN, CLI_OPT_TRANSIENT,
    CLI_OPT_BRANCHES,
    CLI_OPT_SPEEDS, CLI_OPT_PRELOADS, CLI_OPT_MAX_RISE, CLI_OPT_MIN_LIFE, CLI_OPT_MIN_S0,
    CLI_OPT_SPRING,
    CLI_OPT_MAX_WALL,
    CLI_OPT_BASH_COMPLETION,
    CLI_OPT_CSV_HEADER,
    CLI_OPT_NO_STIFFNESS,
    CLI_OPT_COUNT
} acbb_cli_opt;

/* The one upper bound of --jobs for every command that takes it: a sanity
 * limit on the number, not a thread cap (the batch runner never starts
 * more workers than points, batch.h). */
#define ACBB_CLI_MAX_JOBS 100000

#define CLI_BIT(o) (1ull << (unsigned)(o))
_Static_assert(CLI_OPT_COUNT <= 64, "the command table keeps options in a 64-bit mask");

typedef struct {
    const char *name;      /* long name without "--" */
    const char *metavar;   /* value name, NULL for a flag */
    const char *help;
} acbb_cli_option;

#define CLI_MAX_POS 1024              /* `acbb merge OUT IN...` */
#define CLI_PATH_MAX 4096
#define CLI_MAX_GRIDS 8                /* ACBB_SWEEP_MAX_DIMS */
#define CLI_MAX_METRICS 16             /* `sweep --metric`: ACBB_CLI_SWEEP_METRICS */

/* What the parser hands a command. Values point into argv. */
typedef struct {
    const char *cmd;                   /* "run", "bench speed": for messages */
    char cmd_buf[32];
    const char *pos[CLI_MAX_POS];      /* positional arguments */
    int n_pos;
    const char *val[CLI_OPT_COUNT];    /* last value; "" for a flag; NULL absent */
    const char **sets;                 /* every --set, in order */
    size_t n_sets;
    const char *grids[CLI_MAX_GRIDS];  /* every --grid, in order */
    size_t n_grids;
    const char *metrics[CLI_MAX_METRICS]; /* every --metric, in order */
    size_t n_metrics;
    const char *preset;                /* the PRESET positional, resolved */
    char preset_buf[CLI_PATH_MAX];
} acbb_cli_args;

typedef struct acbb_cli_command acbb_cli_command;
struct acbb_cli_command {
    const char *name;
    const char *sub;          /* second word ("bench speed"), or NULL */
    const char *args;         /* positional synopsis, e.g. "PRESET" or "[PRESET]" */
    const char *summary;      /* one line for `acbb help` */
    const char *details;      /* more text for `acbb help CMD`, or NULL */
    unsigned long long options; /* CLI_BIT() of the accepted options (CLI_OPT_COUNT <= 64) */
    int min_pos, max_pos;
    int preset_pos;           /* positional resolved as a preset, or -1 */
    int (*run)(const acbb_cli_args *a);
};

/* The option table (args.c) and the command table (main.c). */
extern const acbb_cli_option acbb_cli_options[CLI_OPT_COUNT];
extern const acbb_cli_command acbb_cli_commands[];
extern const size_t acbb_cli_n_commands;

/* Parse argv[first..argc) for `c` into *a (sets must hold argc entries).
 * Returns 0, -1 when --help/-h was given (usage already printed on
 * stdout), or 2 with the message on stderr. */
int acbb_cli_parse(const acbb_cli_command *c, int argc, char **argv, int first,
                   acbb_cli_args *a);

/* "acbb run PRESET [--set KEY=VALUE]... [--json]": the synopsis line. */
void acbb_cli_print_synopsis(FILE *f, const acbb_cli_command *c);
/* Synopsis, summary, details and every accepted option with its help. */
void acbb_cli_print_usage(FILE *f, const acbb_cli_command *c);

/* help.c: the overview of every command (`acbb help`), the exit statuses,
 * and the manual page in roff (`acbb help --man`, installed as acbb.1):
 * all from the two tables. */
void acbb_cli_print_overview(FILE *f);
void acbb_cli_print_man(FILE *f, const char *version);
/* The bash completion script from the same tables (completion/bash.c). */
void acbb_cli_print_bash_completion(FILE *f);
int acbb_cli_unknown_command(const char *name);
int acbb_cli_cmd_help(const acbb_cli_args *a);

/* Levenshtein distance, capped: the "did you mean" measure. */
size_t acbb_cli_distance(const char *a, size_t la, const char *b, size_t lb);

/* A whole number lo..hi from option `o` (default `dflt` when absent);
 * 0, or 2 with a message naming the option and the range. */
int acbb_cli_count(const acbb_cli_args *a, acbb_cli_opt o, long dflt, long lo, long hi,
                   long *out);

#endif
