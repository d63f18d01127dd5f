/* acbb — the command-line front end: the command table and dispatch.
 *
 * A thin client of the engine API. Every command is one row below: its
 * name, positional arguments, summary, the options it accepts and its
 * handler; args.c parses every command's arguments from that row and
 * prints its usage from it. Adding a command = one row + one handler
 * (README "Working on acbb"). The locale is never set, so LC_NUMERIC stays
 * "C" and presets, CSV and JSON always use a decimal point. */
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "args.h"
#include "common.h"
#include "commands.h"
#include "exit.h"
#include "presets.h"
#include "tui.h"
#include "report.h"
#include "new.h"
#include "output.h"
#include "sweep.h"
#include "json_status.h"
#include "out_guard.h"
#include "say.h"

#ifndef ACBB_VERSION
#define ACBB_VERSION "unknown"
#endif

#define O(x) CLI_BIT(CLI_OPT_##x)
#define SCENE_OPTS O(SET)

static int cmd_version(const acbb_cli_args *a);
static int cmd_tui(const acbb_cli_args *a);
static int cmd_metrics(const acbb_cli_args *a);

const acbb_cli_command acbb_cli_commands[] = {
    { "tui", NULL, "[PRESET]", "the terminal workbench (also `acbb` alone)",
      "Environment: ACBB_TUI_EXIT_AFTER_STEADY=1 as --exit-after-steady;\n"
      "ACBB_TUI_ACCURACY_KNOBS=k1,k2 limits the knobs of the accuracy screen's\n"
      "benchmark (b). Inside, press ? for every key.\n",
      O(PACE) | O(PLOT_DIR) | O(EXIT_AFTER_STEADY) | O(NO_MOUSE), 0, 1, -1, cmd_tui },
    { "run", NULL, "PRESET", "run the coupled model to thermal steady state",
      "--csv writes one row per coupled step; --plot FILE.png writes the temperature\n"
      "plot there and the other kinds next to it (FILE-losses.png, ...).\n"
      "A [schedule] section (row = t_s, speed_rpm, axial_N, radial_N) makes the\n"
      "transient follow a run-in; with it, or with mounting.preload = displacement,\n"
      "the steady solve runs too and the output says whether both reach one branch.\n",
      SCENE_OPTS | O(JSON) | O(CSV) | O(QUIET) | O(PLOT) | O(BASELINE)
      | O(BRANCHES) | O(MAX_WALL), 1, 1, 0,
      acbb_cli_cmd_run },
    { "check", NULL, "PRESET", "validate the preset and the edits without running", NULL,
      SCENE_OPTS, 1, 1, 0, acbb_cli_cmd_check },
    { "edit", NULL, "PRESET", "apply --set edits to the preset file in place",
      "Only the lines of the changed keys are rewritten; comments, order and blank\n"
      "lines stay; new keys go at the end of their section. The file is replaced\n"
      "atomically, and only if the edited scene passes every check `acbb run` makes.\n"
      "An installed preset (shared by every user) is never rewritten: --out FILE\n"
      "writes the edited copy there instead.\n",
      SCENE_OPTS | O(OUT), 1, 1, 0, acbb_cli_cmd_edit },
    { "sweep", NULL, "PRESET", "runs over a grid of parameter values, on every core",
      "e.g. acbb sweep 7008C --grid operating.axial_load_N=200,500,1000 \\\n"
      "       --grid operating.inner_speed_rpm=2000:16000:8 \\\n"
      "       --jsonl out.jsonl\n"
      "The cartesian product of the --grid dimensions, point index row-major (the\n"
      "first --grid slowest). --jsonl/--csv get one record per point as it finishes;\n"
      "running the same command again resumes (points in the file are skipped; a\n"
      "wall_limit point runs again). One sweep per file: a second is refused (2).\n"
      "A grid value its key refuses (a typo) is refused (2) before anything runs.\n"
      "Shards: --shard K/N on N machines, then `acbb merge`. --param/--values alone:\n"
      "one dimension, printed as a table (or --json, --csv) at the end.\n"
      "--csv FILE: a plain CSV (the column names first); the sweep's header (scene,\n"
      "grid, fingerprint) goes to FILE.json beside it, or, with --csv-header, on a\n"
      "first line '# {...}' of the CSV. --metric PATH (repeatable, `acbb metrics`)\n"
      "adds that result to every record; it is part of the sweep (a resume with\n"
      "other metrics is refused). --no-stiffness skips the stiffness probes (about\n"
      "40 % of a steady point): the ring.stiffness_* and set.stiffness_* columns\n"
      "are left out of every record and the header says \"stiffness\": false.\n",
      SCENE_OPTS | O(PARAM) | O(VALUES) | O(JSON) | O(CSV) | O(JOBS) | O(GRID) | O(JSONL) |
      O(SHARD) | O(MAX_POINTS) | O(TRANSIENT) | O(MAX_WALL) | O(METRIC) | O(CSV_HEADER) |
      O(NO_STIFFNESS), 1, 1, 0, acbb_cli_cmd_sweep },
    { "merge", NULL, "OUT IN...", "join sweep outputs (shards) into the canonical table",
      "Sorted by point index, each point once, wall_ms dropped: the merge of the\n"
      "shards equals `acbb merge OUT sweep.jsonl` of a one-machine sweep byte for\n"
      "byte. JSONL or CSV (not mixed); OUT - is stdout. Exit 3 when points are\n"
      "missing (the others are written); a sweep's own output (a shard) as OUT is\n"
      "refused (2).\n",
      0, 2, CLI_MAX_POS, -1, acbb_cli_cmd_merge },
    { "sensitivity", NULL, "PRESET", "which uncertain input moves a result or flips its sign",
      "e.g. acbb sensitivity 7008C --metric balls[0].Qi_N \\\n"
      "       --delta thermal_expansion\n"
      "Every uncertain input (`acbb keys` shows its plausible range and source) is\n"
      "set to each end of its range, one at a time; the table is sorted by effect\n"
      "and FLIPS SIGN marks the inputs whose range changes the metric's sign.\n"
      "--morris R adds Morris elementary effects over all inputs together\n"
      "(R (k+1) points, k inputs; seed 1). --plot FILE.png|svg: a tornado chart.\n"
      "Exit 3 when a run did not reach steady state (the table is still printed).\n",
      SCENE_OPTS | O(METRIC) | O(DELTA) | O(MORRIS) | O(JOBS) | O(TRANSIENT) | O(JSON) | O(CSV) |
      O(PLOT) | O(MAX_WALL), 1, 1, 0, acbb_cli_cmd_sensitivity },
    { "study", NULL, "PRESET", "TE vs WTE: with and without thermal expansion",
      "Loads 50..1000 N at the preset's speed, speeds 2000..16000 rpm at 100 N\n"
      "and at 1000 N. PRESET `seed` is 7008C, the seed paper's case.\n"
      "--out DIR instead writes the seed's Figs. 7-19 (the study of `acbb report`:\n"
      "sweeps at 15000 rpm, TE and WTE) as DIR/figNN*.png, .svg and .csv, and\n"
      "DIR/REPORT.md linking them with the seed's captions and the verdicts of the\n"
      "statements that cite them.\n"
      "e.g. acbb study seed --out figs\n"
      "--size: the figures' size: column (default; 8.5 x 6.4 cm, text 8.5 pt),\n"
      "full (17.5 cm), a print width (85mm, 8.5cm, 85mmx60mm; 300 dpi) or WxH pixels.\n",
      SCENE_OPTS | O(CSV) | O(JOBS) | O(OUT) | O(SIZE) | O(MAX_WALL), 1, 1, -1, acbb_cli_cmd_study },
    { "plot", NULL, "PRESET", "run the scene and plot it through gnuplot",
      "--kind all writes every kind, FILE-<kind>.png next to --out FILE.png.\n",
      SCENE_OPTS | O(KIND) | O(OUT) | O(DUMB) | O(SIZE), 1, 1, 0, acbb_cli_plot },
    { "bench", "speed", "[PRESET]",
      "wall time of one run and of the 8-load sweep",
      "Without PRESET: 7008C. --repeat defaults to 5; 1 thread, then --jobs\n"
      "(default: every CPU the process may use).\n",
      SCENE_OPTS | O(REPEAT) | O(JOBS), 0, 1, 0, acbb_cli_cmd_bench_speed },
    { "bench", "accuracy", "PRESET",
      "error vs wall time, one fidelity knob at a time",
      "--repeat defaults to 3 (1..1000). Exit 3 when a setting did not converge,\n"
      "4 when the plot could not be made (the table is still printed).\n"
      "--envelope: every setting once at each of the seed's 48 study points (or\n"
      "--points N of them) on --jobs threads: worst/median steady and path error,\n"
      "median work units per point, and the fidelity ladder's stored-frontier rows.\n",
      SCENE_OPTS | O(REPEAT) | O(KNOBS) | O(MODELS) | O(CSV) | O(PLOT) | O(ENVELOPE) |
      O(POINTS) | O(JOBS), 1, 1, 0,
      acbb_cli_bench_accuracy },
    { "report", NULL, "PRESET",
      "the seed's conclusions: held or not",
      "The 18 statements and how each is checked: docs/physics.md section 12.\n"
      "Exit 0 whatever the verdicts (NOT HELD is a finding), 3 when a run failed.\n"
      "Cancelled (Ctrl-C, SIGTERM): no verdicts, no --md file, exit 3.\n",
      SCENE_OPTS | O(JSON) | O(MD) | O(SENSITIVITY) | O(INPUTS) | O(JOBS) | O(MAX_WALL), 1, 1, 0,
      acbb_cli_cmd_report },
    { "new", NULL, "[DESIGNATION]", "write a preset for a bearing designation (7014C, 6205)",
      "Or --series 70 --bore 70 --angle 15. Writes DESIGNATION.ini (or --out FILE,\n"
      "never over an existing file) with the ISO 15 bore, outside diameter and width;\n"
      "internal geometry is estimated and marked `; estimated:` in the file.\n",
      O(OUT) | O(SERIES) | O(BORE) | O(ANGLE), 0, 1, -1, acbb_cli_cmd_new },
    { "preload-map", NULL, "PRESET", "the preload window over speed x preload, on every core",
      "e.g. acbb preload-map preload-window --speeds 4000:16000:7 \\\n"
      "       --preloads 50:1500:8\n"
      "Each cell: mounting.preload = displacement set at rest by the preload, the\n"
      "transient from ambient. Below the window the balls skid (the gyroscopic\n"
      "moment beats the traction of the inner contact, from the ball speeds); above\n"
      "it a limit fails (--max-rise, --min-life, --min-s0) or the run runs away.\n"
      "--spring: a constant-force preload instead (a rigid one's inner contact load\n"
      "grows with speed, so on it the balls seldom skid; see preload-window-spring).\n"
      "--csv: operating.inner_speed_rpm, mounting.preload_N, status, verdict and the\n"
      "limits' values per cell (skid_ratio, temp_rise_K, life.Lnmr_h, life.s0_min);\n"
      "--json: the same cells and each speed's window as one document.\n",
      SCENE_OPTS | O(SPEEDS) | O(PRELOADS) | O(MAX_RISE) | O(MIN_LIFE) | O(MIN_S0) | O(CSV) |
      O(JSON) |
      O(SPRING) |
      O(PLOT) | O(JOBS), 1, 1, 0, acbb_cli_cmd_preload_map },
    { "presets", NULL, "[DIR]", "the preset search path and the presets in it",
      NULL, 0, 0, 1, -1, acbb_cli_cmd_presets },
    { "keys", NULL, "", "every scene key with unit, range and help", NULL, 0, 0, 0, -1,
      acbb_cli_cmd_keys },
    { "metrics", NULL, "", "every result a --metric can name, with unit and label",
      "The paths of `acbb run --json` (balls[i]: any ball index), as `acbb sensitivity\n"
      "--metric` and the TUI's Sweep and Sensitivity screens take them.\n",
      O(JSON), 0, 0, -1, cmd_metrics },
    { "schema", NULL, "", "the JSON Schema of the JSON output",
      "Every JSON document starts with \"schema_version\"; with --json, bad input\n"
      "(exit 2) is {\"status\": \"bad_input\", \"message\": ...} on stdout.\n",
      0, 0, 0, -1, acbb_cli_cmd_schema },
    { "help", NULL, "[COMMAND]", "this overview, or one command's usage",
      "--man prints the manual page (installed as acbb.1) from this same table,\n"
      "--bash-completion the bash completion script (installed as completions/acbb).\n",
      O(MAN) | O(BASH_COMPLETION), 0, 2, -1, acbb_cli_cmd_help },
    { "version", NULL, "", "print the version (also --version)", NULL, 0, 0, 0, -1,
      cmd_version },
};
const size_t acbb_cli_n_commands = sizeof acbb_cli_commands / sizeof acbb_cli_commands[0];

/* The row for argv[1] (and argv[2] for a two-word command); *first is
 * where its arguments start. NULL (message printed) when there is none. */
static const acbb_cli_command *find_command(int argc, char **argv, int *first, int *rc)
{
    bool name_known = false;
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        const acbb_cli_command *c = &acbb_cli_commands[i];
        if (strcmp(c->name, argv[1]) != 0) continue;
        name_known = true;
        if (!c->sub) {
            *first = 2;
            return c;
        }
        if (argc > 2 && strcmp(argv[2], c->sub) == 0) {
            *first = 3;
            return c;
        }
    }
    if (!name_known) {
        *rc = acbb_cli_unknown_command(argv[1]);
        return NULL;
    }
    acbb_cli_msg m;
    FILE *f = acbb_cli_msg_begin(&m);
    fprintf(f, "%s: expected one of:\n", argv[1]);
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        if (strcmp(acbb_cli_commands[i].name, argv[1]) != 0) continue;
        fputs("  ", f);
        acbb_cli_print_synopsis(f, &acbb_cli_commands[i]);
        fputc('\n', f);
    }
    acbb_cli_msg_say(&m);
    *rc = ACBB_EXIT_INPUT;
    return NULL;
}

static int cmd_metrics(const acbb_cli_args *a)
{
    if (a->val[CLI_OPT_JSON]) acbb_cli_list_metrics_json(stdout);
    else acbb_cli_list_metrics(stdout);
    return acbb_cli_stdout_check(0);
}

static int cmd_version(const acbb_cli_args *a)
{
    (void)a;
    printf("acbb %s\n", ACBB_VERSION);
    return acbb_cli_stdout_check(0);
}

/* The TUI gets its options as parsed here and the preset resolved through
 * the search path (presets.h). Without one it opens 7008C from that path;
 * when none is found the TUI starts from its built-in default scene. */
static int cmd_tui(const acbb_cli_args *a)
{
    char path[CLI_PATH_MAX];
    const char *want = a->n_pos ? a->pos[0] : "7008C";
    acbb_tui_args t = { .pace = a->val[CLI_OPT_PACE], .plot_dir = a->val[CLI_OPT_PLOT_DIR],
                        .no_mouse = a->val[CLI_OPT_NO_MOUSE] != NULL,
                        .exit_after_steady = a->val[CLI_OPT_EXIT_AFTER_STEADY] != NULL,
                        .installed = acbb_cli_preset_installed };
    if (acbb_cli_resolve_preset(want, path, sizeof path, false) == 0) t.preset = path;
    else if (a->n_pos) t.preset = want;   /* the TUI reports it */
    return acbb_tui_main(&t);
}

static bool is_flag(const char *s, const char *lng, const char *shrt)
{
    return strcmp(s, lng) == 0 || (shrt && strcmp(s, shrt) == 0);
}

static int run_command(int argc, char **argv);

int main(int argc, char **argv)
{
    /* The default GSL handler aborts the process (common rules). */
    gsl_set_error_handler_off();
    char *tui_alone[] = { argv[0], "tui", NULL };
    if (argc < 2) {
        argc = 2;
        argv = tui_alone;
    }
    if (is_flag(argv[1], "--help", "-h")) {
        acbb_cli_print_overview(stdout);
        return acbb_cli_stdout_check(0);
    }
    if (is_flag(argv[1], "--version", NULL)) return cmd_version(NULL);
    acbb_cli_json_status js;
    acbb_cli_json_status_begin(&js, argc, argv);
    int rc = run_command(argc, argv);
    return acbb_cli_json_status_end(&js, rc);
}

/* The command argv names, parsed and run: its exit status. */
static int run_command(int argc, char **argv)
{
    int first = 2, rc = 0;
    const acbb_cli_command *c = find_command(argc, argv, &first, &rc);
    if (!c) return rc;
    acbb_cli_args *a = calloc(1, sizeof *a);
    const char **sets = calloc((size_t)argc, sizeof *sets);
    if (!a || !sets) {
        free(a);
        free(sets);
        return ACBB_EXIT_INTERNAL;
    }
    a->sets = sets;
    rc = acbb_cli_parse(c, argc, argv, first, a);
    if (rc == 0) rc = acbb_cli_out_guard(a); /* every output checked before anything runs */
    if (rc == 0) rc = c->run(a);
    else if (rc < 0) rc = 0;     /* --help was printed */
    free(sets);
    free(a);
    return rc;
}
