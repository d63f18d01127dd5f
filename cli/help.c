/* acbb CLI — `acbb help`, `acbb help CMD`, `acbb help --man`: the overview,
 * one command's usage (args.c) and the manual page, every word about a
 * command or an option taken from the two tables (args.h), so the help,
 * the man page and the parser cannot disagree (issue 16). */
#include <string.h>
#include "args.h"
#include "common.h"
#include "exit.h"
#include "say.h"

/* The exit statuses (exit.h), for the overview and EXIT STATUS. */
#define KILLED (-1)                   /* 128+N */
static const struct {
    int code;
    const char *brief, *text;
} k_exits[] = {
    { ACBB_EXIT_OK, "converged", "converged, or the command did its job" },
    { ACBB_EXIT_HANGUP, "the TUI's terminal went away",
      "the TUI only: its terminal went away without a SIGHUP" },
    { ACBB_EXIT_INPUT, "bad input or ill-posed scene", "bad input: options, preset, --set "
      "edits, an ill-posed scene, an output path that cannot be opened; the message names "
      "what to change" },
    { ACBB_EXIT_SOLVER, "solver did not reach steady state, or cancelled (SIGINT, SIGTERM)",
      "the solver did not reach steady state (output is still printed), or the command was "
      "cancelled by SIGINT (Ctrl-C) or SIGTERM: status cancelled, what finished is written, "
      "no file claims more; merge: points missing (the others are written)" },
    { ACBB_EXIT_INTERNAL, "internal error or gnuplot failure", "internal error, gnuplot "
      "missing or failing, out of memory, or an output whose write failed once open (disk "
      "full, a closed pipe; the old file is kept, a sweep's file ends with its last whole "
      "record)" },
    { KILLED, "killed by signal N", "killed by signal N: a second SIGINT or SIGTERM while a "
      "command is cancelling, or the TUI leaving on SIGTERM, SIGHUP or SIGQUIT (its edits are "
      "saved for recovery first)" },
};

static const char *exit_code(char *buf, size_t n, size_t i)
{
    if (k_exits[i].code == KILLED) snprintf(buf, n, "128+N");
    else snprintf(buf, n, "%d", k_exits[i].code);
    return buf;
}

static const char k_presets[] =
    "PRESET is a file, or a name (7008C) looked up in ~/.config/acbb/presets,\n"
    "./presets and the installed presets (`acbb presets` lists them).\n"
    "--set edits use preset units, e.g. --set operating.axial_load_N=200.\n";

void acbb_cli_print_overview(FILE *f)
{
    fputs("usage: acbb [COMMAND [ARGS]]     (no command: the TUI on 7008C)\n\ncommands:\n", f);
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        const acbb_cli_command *c = &acbb_cli_commands[i];
        char head[40];
        snprintf(head, sizeof head, "%s%s%s %s", c->name, c->sub ? " " : "",
                 c->sub ? c->sub : "", c->args);
        fprintf(f, "  %-24s%s\n", head, c->summary);
    }
    fprintf(f, "\n`acbb help COMMAND` or `acbb COMMAND --help` shows its options.\n%s"
               "\nexit status:\n", k_presets);
    char code[16];
    for (size_t i = 0; i < sizeof k_exits / sizeof k_exits[0]; i++)
        fprintf(f, "  %-5s  %s\n", exit_code(code, sizeof code, i), k_exits[i].brief);
}

/* The closest command name, or NULL when none is near. */
static const char *near_command(const char *name)
{
    size_t best = 3, len = strlen(name);
    const char *pick = NULL;
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        const char *n = acbb_cli_commands[i].name;
        size_t d = acbb_cli_distance(name, len, n, strlen(n));
        if (d < best || (d == best && !pick && d <= len / 3)) best = d, pick = n;
    }
    return pick;
}

int acbb_cli_unknown_command(const char *name)
{
    const char *near = near_command(name);
    acbb_cli_msg m;
    FILE *f = acbb_cli_msg_begin(&m);
    fprintf(f, "unknown command '%s'", name);
    if (near) fprintf(f, "; did you mean '%s'?", near);
    fputs("\n\n", f);
    acbb_cli_print_overview(f);
    acbb_cli_msg_say(&m);
    return ACBB_EXIT_INPUT;
}

/* The paths and the date meson passes in (meson.build): the prefix's own. */
#ifndef ACBB_PRESET_DIR
#define ACBB_PRESET_DIR "/usr/local/share/acbb/presets"
#endif
#ifndef ACBB_SHARE_DIR
#define ACBB_SHARE_DIR "/usr/local/share/acbb"
#endif
#ifndef ACBB_DOC_DIR
#define ACBB_DOC_DIR "/usr/local/share/doc/acbb"
#endif
#ifndef ACBB_MAN_DATE
#define ACBB_MAN_DATE ""
#endif
#ifndef ACBB_VERSION
#define ACBB_VERSION "unknown"
#endif

int acbb_cli_cmd_help(const acbb_cli_args *a)
{
    if (a->val[CLI_OPT_BASH_COMPLETION]) {
        acbb_cli_print_bash_completion(stdout);
        return acbb_cli_stdout_check(0);
    }
    if (a->val[CLI_OPT_MAN]) {
        acbb_cli_print_man(stdout, ACBB_VERSION);
        return acbb_cli_stdout_check(0);
    }
    if (a->n_pos == 0) {
        acbb_cli_print_overview(stdout);
        return acbb_cli_stdout_check(0);
    }
    bool found = false;
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        const acbb_cli_command *c = &acbb_cli_commands[i];
        if (strcmp(c->name, a->pos[0]) != 0) continue;
        if (a->n_pos > 1 && (!c->sub || strcmp(c->sub, a->pos[1]) != 0)) continue;
        if (found) fputs("\n", stdout);
        acbb_cli_print_usage(stdout, c);
        found = true;
    }
    return found ? acbb_cli_stdout_check(0) : acbb_cli_unknown_command(a->pos[0]);
}

/* ---- the manual page ---- */

/* Text as roff: backslash and minus escaped, a line that would start with
 * a control character guarded. */
static void roff(FILE *f, const char *s, size_t n)
{
    for (size_t i = 0; i < n && s[i]; i++) {
        bool bol = i == 0 || s[i - 1] == '\n';
        if (bol && (s[i] == '.' || s[i] == '\'')) fputs("\\&", f);
        if (s[i] == '\\') fputs("\\e", f);
        else if (s[i] == '-') fputs("\\-", f);
        else fputc(s[i], f);
    }
}

static void roff_s(FILE *f, const char *s) { roff(f, s, strlen(s)); }

/* "\fB--name\fR \fIVALUE\fR" */
static void roff_option(FILE *f, const acbb_cli_option *o)
{
    fputs("\\fB", f);
    roff_s(f, "--");
    roff_s(f, o->name);
    fputs("\\fR", f);
    if (o->metavar) {
        fputs("\\ \\fI", f);   /* an unbreakable space: one option, one word */
        roff_s(f, o->metavar);
        fputs("\\fR", f);
    }
}

/* "\fBacbb bench speed\fR [\fIPRESET\fR] [\fB--set\fR \fIKEY=VALUE\fR]..." */
static void roff_synopsis(FILE *f, const acbb_cli_command *c)
{
    fputs("\\fBacbb ", f);
    roff_s(f, c->name);
    if (c->sub) fprintf(f, " %s", c->sub);
    fputs("\\fR", f);
    if (c->args[0]) {
        fputs(" \\fI", f);
        roff_s(f, c->args);
        fputs("\\fR", f);
    }
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        if (!(c->options & CLI_BIT(k))) continue;
        fputs(" [", f);
        roff_option(f, &acbb_cli_options[k]);
        fputs(k == CLI_OPT_SET || k == CLI_OPT_GRID ? "]..." : "]", f);
    }
    fputc('\n', f);
}

/* A command's details: prose filled (hand-broken lines overflowed the
 * indent), an example line ("e.g. acbb ...", continued by a trailing
 * backslash) unfilled and unhyphenated, so it neither runs into the prose
 * nor breaks inside a word (issue 28 item 13). */
static void man_details(FILE *f, const char *s)
{
    fputs(".IP\n", f);
    bool example = false;
    while (*s) {
        size_t n = strcspn(s, "\n");
        bool starts = !example && strncmp(s, "e.g. ", 5) == 0;
        if (starts) fputs(".nf\n.nh\n", f);
        roff(f, s, n);
        fputc('\n', f);
        bool more = n > 0 && s[n - 1] == '\\';
        if ((starts || example) && !more) fputs(".fi\n.hy\n", f);
        example = (starts || example) && more;
        s += n + (s[n] == '\n');
    }
}

static void man_commands(FILE *f)
{
    fputs(".SH COMMANDS\n.na\n", f);   /* ragged right: long synopses */
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        const acbb_cli_command *c = &acbb_cli_commands[i];
        fputs(".TP\n", f);
        roff_synopsis(f, c);
        roff_s(f, c->summary);
        fputs(".\n", f);
        if (c->details) man_details(f, c->details);
    }
}

/* Every option once, with the commands that take it. */
static void man_options(FILE *f)
{
    fputs(".ad\n.SH OPTIONS\n", f);
    for (int k = 0; k < CLI_OPT_COUNT; k++) {
        fputs(".TP\n", f);
        roff_option(f, &acbb_cli_options[k]);
        fputc('\n', f);
        roff_s(f, acbb_cli_options[k].help);
        fputs(k == CLI_OPT_HELP ? ". Every command.\n" : ". Commands:", f);
        const char *last = "";
        for (size_t i = 0; k != CLI_OPT_HELP && i < acbb_cli_n_commands; i++) {
            const acbb_cli_command *c = &acbb_cli_commands[i];
            if (!(c->options & CLI_BIT(k))) continue;
            if (strcmp(c->name, last) != 0) fprintf(f, "%s \\fB%s\\fR", *last ? "," : "", c->name);
            last = c->name;
        }
        if (k != CLI_OPT_HELP) fputs(".\n", f);
    }
    fputs(".PP\nOptions take their value as\n.BI \\-\\- name \" VALUE\"\nor\n"
          ".BI \\-\\- name = VALUE\\fR;\n.B \\-\\-\nends the options. An unknown option is "
          "refused (exit 2), with the nearest known one suggested.\n", f);
}

static void man_exit(FILE *f)
{
    char code[16];
    fputs(".SH EXIT STATUS\n", f);
    for (size_t i = 0; i < sizeof k_exits / sizeof k_exits[0]; i++) {
        fprintf(f, ".TP\n.B %s\n", exit_code(code, sizeof code, i));
        roff_s(f, k_exits[i].text);
        fputs(".\n", f);
    }
    fputs(".PP\nWhen several of 0 to 4 apply the highest is returned.\n", f);
}

/* The prose around the tables (hand-written, roff as it stands). */
static const char k_man_head[] =
    ".SH NAME\n"
    "acbb \\- angular-contact ball bearings as a coupled thermo-mechanical system\n"
    ".SH SYNOPSIS\n"
    ".B acbb\n"
    ".RI [ COMMAND \" [\" ARGS ]]\n"
    ".br\n"
    ".B acbb help\n"
    ".RI [ COMMAND ]\n"
    ".SH DESCRIPTION\n"
    ".B acbb\n"
    "simulates an angular-contact ball bearing: contact loads and angles, ball\n"
    "kinematics, an EHL film and traction model, five power losses integrated\n"
    "over every contact ellipse, a thermal network heated by them, and the\n"
    "thermal expansions that change the loads, stepped until thermal steady\n"
    "state.\n"
    "Without a command it opens the terminal workbench on the preset\n"
    ".BR 7008C .\n"
    "A scene (preset) is an INI file; every key carries its unit\n"
    ".RB ( \"acbb keys\" ).\n"
    ".PP\n"
    "Every command prints its own usage with\n"
    ".B acbb help\n"
    ".I COMMAND\n"
    "or\n"
    ".B acbb\n"
    ".I COMMAND\n"
    ".BR \\-\\-help ;\n"
    "the sections COMMANDS, OPTIONS and EXIT STATUS below are printed from the\n"
    "same tables\n"
    ".RB ( \"acbb help \\-\\-man\" ).\n"
    ".PP\n"
    "The long commands (run, sweep, study, report, sensitivity, bench) stop\n"
    "within a step on SIGINT (Ctrl\\-C) or SIGTERM: what finished is written\n"
    "(a sweep's finished points stay in its files and a re\\-run resumes),\n"
    "a cancelled report or figure set writes no file that looks complete,\n"
    "the status is\n"
    ".B cancelled\n"
    "(in the JSON where the command prints JSON) and the exit status 3.\n"
    "A second signal kills at once.\n";

static const char k_man_tail[] =
    ".SH FILES\n"
    "A\n"
    ".I PRESET\n"
    "argument that names an existing file, or contains a /, is used as it is.\n"
    "Any other name, e.g.\n"
    ".B 7008C\n"
    "or\n"
    ".BR 7008C.ini ,\n"
    "is looked up as NAME and NAME.ini in, first match wins:\n"
    ".TP\n"
    ".I $XDG_CONFIG_HOME/acbb/presets\n"
    "the user's own presets (default\n"
    ".IR ~/.config/acbb/presets );\n"
    ".TP\n"
    ".I ./presets\n"
    "the source tree;\n"
    ".TP\n"
    ".I " ACBB_PRESET_DIR "\n"
    "the installed presets, also found relative to the binary when the\n"
    "installation was moved.\n"
    ".PP\n"
    "Unsaved edits in the TUI are kept every few seconds, and on SIGTERM,\n"
    "SIGHUP or SIGQUIT, in\n"
    ".I $XDG_STATE_HOME/acbb/recover\n"
    "(default\n"
    ".IR ~/.local/state/acbb/recover );\n"
    "opening the preset again offers them back.\n"
    ".PP\n"
    "Installed with them:\n"
    ".TP\n"
    ".I " ACBB_SHARE_DIR "/schema/acbb.schema.json\n"
    "the JSON Schema of the JSON output (also printed by\n"
    ".BR \"acbb schema\" );\n"
    ".TP\n"
    ".I " ACBB_SHARE_DIR "/contrib\n"
    "the Slurm and GNU parallel sweep recipes;\n"
    ".TP\n"
    ".I " ACBB_DOC_DIR "\n"
    "README, BENCHMARKS, LICENSE and, in\n"
    ".IR docs/ ,\n"
    "the documents they cite: the seed report, the spindle, contact heat,\n"
    "ratings and loss validation notes, and\n"
    ".IR docs/physics.md ,\n"
    "the physics reference (equations, units, sources, assumptions) whose\n"
    "numbered sections the help, the messages and the presets cite.\n"
    ".PP\n"
    "Output files (CSV, Markdown, plots) are written to a temporary file and\n"
    "renamed into place: an existing file is never left half written.\n"
    ".SH ENVIRONMENT\n"
    ".TP\n"
    ".B XDG_CONFIG_HOME\n"
    "Where the user's presets live (acbb/presets below it; default $HOME/.config).\n"
    ".TP\n"
    ".B ACBB_GNUPLOT\n"
    "The gnuplot program to run (default: gnuplot on PATH).\n"
    ".TP\n"
    ".B ACBB_PROGRESS\n"
    "1: draw the progress line on stderr even when it is not a terminal; 0: never.\n"
    ".TP\n"
    ".B ACBB_TUI_EXIT_AFTER_STEADY\n"
    "Non-zero: the TUI starts the run and exits when it ends.\n"
    ".TP\n"
    ".B ACBB_TUI_ACCURACY_KNOBS\n"
    "Knobs the TUI's accuracy benchmark varies, e.g. contact_grid.\n"
    ".TP\n"
    ".B NO_COLOR\n"
    "The TUI draws without colour: each chart series then has its own mark.\n"
    ".TP\n"
    ".B ACBB_ASCII\n"
    "Non-empty: the TUI draws with ASCII only, even in a UTF-8 locale.\n"
    ".TP\n"
    ".B XDG_STATE_HOME\n"
    "Where the TUI keeps unsaved edits (acbb/recover below it; default $HOME/.local/state).\n"
    ".TP\n"
    ".B TERM\n"
    "The terminal type the TUI draws for; unset or dumb: the TUI refuses to start.\n";

static const char k_man_examples[] =
    ".SH EXAMPLES\n"
    ".nf\n"
    "acbb run 7008C \\-\\-set operating.axial_load_N=200 \\-\\-json\n"
    "acbb sweep 7008C \\-\\-param operating.axial_load_N \\-\\-values 50,200,1000\n"
    "acbb sweep 7008C \\-\\-grid operating.axial_load_N=50,200,1000 \\e\n"
    "    \\-\\-grid operating.inner_speed_rpm=2000:16000:8 \\-\\-jsonl out.jsonl\n"
    "acbb merge all.jsonl shard\\-1.jsonl shard\\-2.jsonl\n"
    "acbb plot 7008C \\-\\-kind losses \\-\\-out losses.svg\n"
    "acbb report 7008C \\-\\-md report.md\n"
    ".fi\n"
    ".SH SEE ALSO\n"
    ".BR gnuplot (1)\n";

void acbb_cli_print_man(FILE *f, const char *version)
{
    fprintf(f, ".\\\" Generated by `acbb help --man` from the command table (cli/main.c,\n"
               ".\\\" cli/args.c); edit those, not this file.\n"
               ".TH ACBB 1 \"%s\" \"acbb %s\" \"User Commands\"\n", ACBB_MAN_DATE, version);
    fputs(k_man_head, f);
    man_commands(f);
    man_options(f);
    fputs(k_man_tail, f);
    man_exit(f);
    fputs(k_man_examples, f);
}
