/* acbb CLI — the table-driven argument parser and usage printer (args.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "args.h"
#include "exit.h"
#include "presets.h"
#include "say.h"

const acbb_cli_option acbb_cli_options[CLI_OPT_COUNT] = {
    [CLI_OPT_SET] = { "set", "KEY=VALUE",
                      "edit a preset key in preset units, e.g. operating.axial_load_N=200 "
                      "(repeatable; `acbb keys` lists them)" },
    [CLI_OPT_JSON] = { "json", NULL, "print JSON on stdout instead of the table" },
    [CLI_OPT_CSV] = { "csv", "FILE", "also write CSV to FILE (written atomically; - = stdout)" },
    [CLI_OPT_QUIET] = { "quiet", NULL, "print nothing on success (the exit status says it)" },
    [CLI_OPT_PLOT] = { "plot", "FILE", "draw with gnuplot to FILE.png or FILE.svg" },
    [CLI_OPT_PARAM] = { "param", "KEY", "the swept key, section.key (1-D shorthand of --grid)" },
    [CLI_OPT_VALUES] = { "values", "V1,V2,...", "the values of --param, in preset units" },
    [CLI_OPT_JOBS] = { "jobs", "N", "parallel runs (default: the CPUs this process may use)" },
    [CLI_OPT_SPEEDS] = { "speeds", "LO:HI:N", "inner-ring speeds, rpm: N evenly spaced from LO to HI" },
    [CLI_OPT_PRELOADS] = { "preloads", "LO:HI:N", "preload forces, N: N evenly spaced from LO to HI" },
    [CLI_OPT_MAX_RISE] = { "max-rise", "K", "upper limit: rings and ball at most K above ambient (0 = off)" },
    [CLI_OPT_MIN_LIFE] = { "min-life", "H", "lower limit: modified rating life L_nmr at least H hours (0 = off)" },
    [CLI_OPT_MIN_S0] = { "min-s0", "S", "lower limit: static safety s0 at least S (0 = off)" },
    [CLI_OPT_SPRING] = { "spring", NULL, "a spring (constant-force) preload: each cell's preload "
                         "is the axial load (default: rigid, set at rest and held)" },
    [CLI_OPT_TRANSIENT] = { "transient", NULL, "run each point's transient (default: the steady "
                            "solve; only the transient catches a runaway)" },
    [CLI_OPT_REPEAT] = { "repeat", "N", "time every measurement N times, report the median" },
    [CLI_OPT_KIND] = { "kind", "KIND",
                       "temperature|losses|loads|angles|history-loads|all (default temperature); "
                       "a bearing set also set-preload|set-temperature" },
    [CLI_OPT_OUT] = { "out", "PATH", "plot: write PATH.png or .svg (default: a text chart on "
                      "stdout); new: the preset file; edit: the edited copy (the preset kept); "
                      "study: the figure directory" },
    [CLI_OPT_DUMB] = { "dumb", NULL, "a text chart on stdout (the default)" },
    [CLI_OPT_SIZE] = { "size", "WxH",
                       "WxH pixels, a print width (85mm, 8.5cm, 85mmx60mm), column (the "
                       "default) or full; characters with --dumb (80x25)" },
    [CLI_OPT_KNOBS] = { "knobs", "K1,...",
                        "model contact_grid hertz mech_tol steady_tol thermal network (default all)" },
    [CLI_OPT_MODELS] = { "models", "M1,...",
                         "static quasi-static quasi-dynamic dynamic (default all available)" },
    [CLI_OPT_MD] = { "md", "FILE", "also write the report as Markdown" },
    [CLI_OPT_PACE] = { "pace", "N", "simulated seconds per wall second (default 200, 0 = flat out)" },
    [CLI_OPT_NO_MOUSE] = { "no-mouse", NULL, "leave the mouse to the terminal (no clicks, no wheel)" },
    [CLI_OPT_PLOT_DIR] = { "plot-dir", "DIR", "where g writes PNG+SVG plots (default ./acbb-plots)" },
    [CLI_OPT_EXIT_AFTER_STEADY] = { "exit-after-steady", NULL,
                                    "start the run at once and exit when it ends "
                                    "(exit 0 converged, 3 not)" },
    [CLI_OPT_SERIES] = { "series", "S",
                         "bearing series: 70 72 73 718 719 (angular contact), 60 62 63 618 619" },
    [CLI_OPT_BORE] = { "bore", "MM", "bore diameter d in mm (10..200, ISO 15 sizes)" },
    [CLI_OPT_ANGLE] = { "angle", "DEG", "contact angle, 5..45 deg (C 15, AC 25, B 40); none for "
                                        "deep groove" },
    [CLI_OPT_HELP] = { "help", NULL, "this text (also -h)" },
    [CLI_OPT_BASELINE] = { "baseline", "FILE",
                           "compare with a saved `acbb run --json` (what-if: what changed, "
                           "absolute and %)" },
    [CLI_OPT_GRID] = { "grid", "KEY=V1,V2,...|KEY=LO:HI:N",
                       "a sweep dimension (repeatable): values, or N evenly spaced from LO to HI" },
    [CLI_OPT_JSONL] = { "jsonl", "FILE",
                        "stream one JSON line per point to FILE as it finishes (- = stdout); "
                        "an existing FILE is resumed" },
    [CLI_OPT_SHARD] = { "shard", "K/N", "run only points with index % N == K-1 (K = 1..N)" },
    [CLI_OPT_MAX_POINTS] = { "max-points", "N", "run at most N of the remaining points, then stop" },
    [CLI_OPT_METRIC] = { "metric", "M",
                         "a scalar of the run's JSON: losses_W.total, temperature_C.outer_ring, "
                         "balls[0].Qi_N, squeeze_um.net, ... (`acbb metrics` lists them)" },
    [CLI_OPT_DELTA] = { "delta", "thermal_expansion",
                        "the metric's difference TE - WTE (two runs per point)" },
    [CLI_OPT_SENSITIVITY] = { "sensitivity", NULL,
                              "also re-judge every statement with each uncertain input at each "
                              "end of its plausible range, one at a time (about 2000 more runs)" },
    [CLI_OPT_MORRIS] = { "morris", "R",
                         "also Morris elementary effects: R trajectories on a 4-level grid "
                         "(0..1000; 10 is usual)" },
    [CLI_OPT_ENVELOPE] = { "envelope", NULL,
                           "score every knob over the seed's 48 operating points, steady and "
                           "transient path" },
    [CLI_OPT_POINTS] = { "points", "N", "with --envelope: N of the 48 points, evenly spread" },
    [CLI_OPT_INPUTS] = { "inputs", "K1,...",
                         "with --sensitivity: vary only these uncertain inputs (default all; "
                         "`acbb keys` marks them plausible)" },
    [CLI_OPT_MAN] = { "man", NULL, "print the manual page (roff) made from the command table" },
    [CLI_OPT_BRANCHES] = { "branches", NULL, "also solve the other branch (the steady solve "
                           "beside the transient) and say whether they agree (automatic with a "
                           "[schedule] or mounting.preload = displacement)" },
    [CLI_OPT_MAX_WALL] = { "max-wall", "SECONDS",
                           "bound each run's computing time (fidelity.max_wall_s): a run past "
                           "it ends wall_limit with its last good state, exit 3; with "
                           "--branches the run and the other branch share it" },
    [CLI_OPT_BASH_COMPLETION] = { "bash-completion", NULL,
                                  "print the bash completion script made from the command table" },
    [CLI_OPT_CSV_HEADER] = { "csv-header", NULL,
                             "the sweep's header as a first CSV line '# {...}' instead of in "
                             "FILE.json beside the CSV" },
    [CLI_OPT_NO_STIFFNESS] = { "no-stiffness", NULL,
                               "skip the end-of-run stiffness probes (about 40 % of a steady "
                               "point): the records carry no stiffness columns" },
};

/* Optimal string alignment distance: insertions, deletions, substitutions
 * and swaps of neighbours ("josn" -> "json" is one edit). */
size_t acbb_cli_distance(const char *a, size_t la, const char *b, size_t lb)
{
    enum { N = 64 };
    if (la >= N || lb >= N) return N;
    static const size_t none = (size_t)-1 / 2;
    size_t d[3][N];                 /* rows i-2, i-1, i (rolling) */
    for (size_t j = 0; j <= lb; j++) d[1][j] = j, d[0][j] = none;
    for (size_t i = 1; i <= la; i++) {
        size_t *cur = d[(i + 1) % 3], *up = d[i % 3], *up2 = d[(i + 2) % 3];
        cur[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t best = up[j - 1] + (a[i - 1] != b[j - 1]);
            if (up[j] + 1 < best) best = up[j] + 1;
            if (cur[j - 1] + 1 < best) best = cur[j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                up2[j - 2] + 1 < best)
                best = up2[j - 2] + 1;
            cur[j] = best;
        }
    }
    return d[(la + 1) % 3][lb];
}

/* "try `acbb help CMD`", the second line of a usage error. */
static const char *try_help(const acbb_cli_command *c, char *buf, size_t n)
{
    snprintf(buf, n, "try `acbb help %s%s%s`", c->name, c->sub ? " " : "", c->sub ? c->sub : "");
    return buf;
}

/* Unknown `--name`: the closest accepted option when it is near enough. */
static int unknown_option(const acbb_cli_command *c, const char *arg, size_t len)
{
    char hint[128];
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        if (strlen(acbb_cli_options[k].name) != len ||
            strncmp(acbb_cli_options[k].name, arg, len) != 0)
            continue;
        acbb_cli_say("%s: --%.*s is not an option of this command\n%s\n", c->name,
                (int)len, arg, try_help(c, hint, sizeof hint));
        return ACBB_EXIT_INPUT;
    }
    size_t best = (size_t)-1;
    int pick = -1;
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        if (!(c->options & CLI_BIT(k))) continue;
        const char *n = acbb_cli_options[k].name;
        size_t d = acbb_cli_distance(arg, len, n, strlen(n));
        if (d < best) best = d, pick = k;
    }
    /* Near enough: 1 edit in a short name, up to 3 in a long one. */
    size_t limit = 1 + len / 4 > 3 ? 3 : 1 + len / 4;
    bool near = pick >= 0 && best <= limit;
    acbb_cli_say("%s: unknown option --%.*s%s%s%s\n%s\n", c->name, (int)len, arg,
                 near ? "; did you mean --" : "", near ? acbb_cli_options[pick].name : "",
                 near ? "?" : "", try_help(c, hint, sizeof hint));
    return ACBB_EXIT_INPUT;
}

static int bad(const acbb_cli_command *c, const char *what, const char *arg)
{
    char hint[128];
    acbb_cli_say("%s: %s%s\n%s\n", c->name, what, arg ? arg : "", try_help(c, hint, sizeof hint));
    return ACBB_EXIT_INPUT;
}

/* One `--name`, `--name value` or `--name=value` at argv[*i]. */
static int parse_option(const acbb_cli_command *c, int argc, char **argv, int *i,
                        acbb_cli_args *a)
{
    const char *arg = argv[*i] + 2;
    const char *eq = strchr(arg, '=');
    size_t len = eq ? (size_t)(eq - arg) : strlen(arg);
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        const acbb_cli_option *o = &acbb_cli_options[k];
        if (!(c->options & CLI_BIT(k)) && k != CLI_OPT_HELP) continue;
        if (strlen(o->name) != len || strncmp(arg, o->name, len) != 0) continue;
        const char *val = "";
        if (o->metavar) {
            if (eq) val = eq + 1;
            else if (*i + 1 < argc) val = argv[++*i];
            else return bad(c, "option needs a value: ", argv[*i]);
        } else if (eq) {
            return bad(c, "option takes no value: ", argv[*i]);
        }
        if (k == CLI_OPT_SET) a->sets[a->n_sets++] = val;
        if (k == CLI_OPT_GRID && a->n_grids == CLI_MAX_GRIDS)
            return bad(c, "too many --grid (at most 8): ", val);
        if (k == CLI_OPT_GRID) a->grids[a->n_grids++] = val;
        if (k == CLI_OPT_METRIC && a->n_metrics == CLI_MAX_METRICS)
            return bad(c, "too many --metric (at most 16): ", val);
        if (k == CLI_OPT_METRIC) a->metrics[a->n_metrics++] = val;
        a->val[k] = val;
        return 0;
    }
    return unknown_option(c, arg, len);
}

static int check_positionals(const acbb_cli_command *c, acbb_cli_args *a)
{
    if (a->n_pos < c->min_pos) {
        char hint[128];
        acbb_cli_say("%s: missing %s\n%s\n", a->cmd, c->args, try_help(c, hint, sizeof hint));
        return ACBB_EXIT_INPUT;
    }
    if (c->preset_pos >= 0 && c->preset_pos < a->n_pos) {
        if (acbb_cli_resolve_preset(a->pos[c->preset_pos], a->preset_buf,
                                    sizeof a->preset_buf, true) != 0)
            return ACBB_EXIT_INPUT;
        a->preset = a->preset_buf;
    }
    return 0;
}

int acbb_cli_parse(const acbb_cli_command *c, int argc, char **argv, int first,
                   acbb_cli_args *a)
{
    snprintf(a->cmd_buf, sizeof a->cmd_buf, "%s%s%s", c->name, c->sub ? " " : "",
             c->sub ? c->sub : "");
    a->cmd = a->cmd_buf;
    bool options_done = false;
    for (int i = first; i < argc; i++) {
        const char *arg = argv[i];
        if (!options_done && strcmp(arg, "--") == 0) {
            options_done = true;
        } else if (!options_done && strncmp(arg, "--", 2) == 0) {
            int rc = parse_option(c, argc, argv, &i, a);
            if (rc) return rc;
        } else if (!options_done && strcmp(arg, "-h") == 0) {
            a->val[CLI_OPT_HELP] = "";
        } else if (!options_done && arg[0] == '-' && arg[1] != '\0') {
            return bad(c, "unknown option ", arg);
        } else if (a->n_pos < c->max_pos) {
            a->pos[a->n_pos++] = arg;
        } else {
            return bad(c, "unexpected argument ", arg);
        }
    }
    if (a->val[CLI_OPT_HELP]) {
        acbb_cli_print_usage(stdout, c);
        return -1;
    }
    return check_positionals(c, a);
}

void acbb_cli_print_synopsis(FILE *f, const acbb_cli_command *c)
{
    char word[96];
    snprintf(word, sizeof word, "acbb %s%s%s%s%s", c->name, c->sub ? " " : "",
             c->sub ? c->sub : "", c->args[0] ? " " : "", c->args);
    size_t col = acbb_cli_wrap(f, word, 7, 9);
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        if (!(c->options & CLI_BIT(k))) continue;
        const acbb_cli_option *o = &acbb_cli_options[k];
        /* One option is one word for wrapping: no break inside it. */
        snprintf(word, sizeof word, "[--%s%s%s]%s", o->name, o->metavar ? "\x01" : "",
                 o->metavar ? o->metavar : "", k == CLI_OPT_SET ? "..." : "");
        if (col + 1 + strlen(word) > 79) {
            fprintf(f, "\n%9s", "");
            col = 9;
        }
        for (char *p = word; *p; p++) if (*p == '\x01') *p = ' ';
        fprintf(f, " %s", word);
        col += 1 + strlen(word);
    }
}

void acbb_cli_print_usage(FILE *f, const acbb_cli_command *c)
{
    fputs("usage: ", f);
    acbb_cli_print_synopsis(f, c);
    fprintf(f, "\n\n%s\n", c->summary);
    if (c->details) fprintf(f, "\n%s", c->details);
    fputs("\noptions:\n", f);
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        if (!(c->options & CLI_BIT(k)) && k != CLI_OPT_HELP) continue;
        const acbb_cli_option *o = &acbb_cli_options[k];
        char head[64];
        snprintf(head, sizeof head, "--%s%s%s", o->name, o->metavar ? " " : "",
                 o->metavar ? o->metavar : "");
        if (strlen(head) > 20) fprintf(f, "  %s\n%24s", head, "");
        else fprintf(f, "  %-20s  ", head);
        acbb_cli_wrap(f, o->help, 24, 24);
        fputc('\n', f);
    }
}

int acbb_cli_count(const acbb_cli_args *a, acbb_cli_opt o, long dflt, long lo, long hi,
                   long *out)
{
    const char *text = a->val[o];
    if (!text) {
        *out = dflt;
        return 0;
    }
    char *end = NULL;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (errno || end == text || *end || v < lo || v > hi) {
        acbb_cli_say("%s: --%s %s: expected a whole number %ld..%ld\n", a->cmd,
                acbb_cli_options[o].name, text, lo, hi);
        return ACBB_EXIT_INPUT;
    }
    *out = v;
    return 0;
}
