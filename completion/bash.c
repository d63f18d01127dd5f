/* acbb — the bash completion script, printed by `acbb help
 * --bash-completion` from the command table (cli/main.c), the option
 * table (cli/args.c), the preset key table and the value lists the parser
 * takes, so it offers exactly what the parser accepts; meson installs it as
 * DATADIR/bash-completion/completions/acbb (issue 21 item 12). Option
 * values are completed too (issue 28 item 12): --set/--grid keys and their
 * choices, --kind, --metric, --models, --knobs, --series; a file for a
 * FILE, PATH or DIR; nothing for a number. */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/accuracy.h"
#include "acbb/outputs.h"
#include "acbb/tools/plot.h"
#include "acbb/scene.h"
#include "acbb/tools/scene_schema.h"
#include "../cli/args.h"

/* The options of command c, "--name" separated by blanks. */
static void options(FILE *f, const acbb_cli_command *c)
{
    for (int k = 0; k < CLI_OPT_COUNT; k++)
        if (c->options & CLI_BIT(k)) fprintf(f, " --%s", acbb_cli_options[k].name);
    fputs(" --help", f);
}

/* Command names once each, in table order. */
static void names(FILE *f)
{
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        bool seen = false;
        for (size_t j = 0; j < i; j++)
            seen |= strcmp(acbb_cli_commands[j].name, acbb_cli_commands[i].name) == 0;
        if (!seen) fprintf(f, " %s", acbb_cli_commands[i].name);
    }
}

/* What a command's positional words are: "preset" (a file, a name on the
 * search path or - for stdin), "file", "dir", "command" or "none". */
static const char *positional(const acbb_cli_command *c)
{
    if (strstr(c->args, "PRESET")) return "preset";
    if (strstr(c->args, "IN...")) return "file";
    if (strstr(c->args, "DIR")) return "dir";
    if (strstr(c->args, "COMMAND")) return "command";
    return "none";
}

static void command_case(FILE *f, const char *indent, const char *word,
                         const acbb_cli_command *c)
{
    fprintf(f, "%s%s) opts=\"", indent, word);
    options(f, c);
    fprintf(f, "\" pos=%s ;;\n", positional(c));
}

/* The per-command case: options and positional kind; two-word commands
 * first complete their second word. */
static void commands(FILE *f)
{
    fputs("    case $cmd in\n", f);
    for (size_t i = 0; i < acbb_cli_n_commands; i++)
        if (!acbb_cli_commands[i].sub)
            command_case(f, "    ", acbb_cli_commands[i].name, &acbb_cli_commands[i]);
    for (size_t i = 0; i < acbb_cli_n_commands; i++) {
        const acbb_cli_command *c = &acbb_cli_commands[i];
        if (!c->sub || (i > 0 && acbb_cli_commands[i - 1].sub &&
                        strcmp(acbb_cli_commands[i - 1].name, c->name) == 0))
            continue;
        fprintf(f, "    %s)\n        if [ \"$cword\" -eq 2 ]; then\n"
                   "            COMPREPLY=($(compgen -W \"", c->name);
        for (size_t j = i; j < acbb_cli_n_commands; j++)
            if (acbb_cli_commands[j].sub && strcmp(acbb_cli_commands[j].name, c->name) == 0)
                fprintf(f, " %s", acbb_cli_commands[j].sub);
        fputs("\" -- \"$cur\"))\n            return\n        fi\n        case $sub in\n", f);
        for (size_t j = i; j < acbb_cli_n_commands; j++)
            if (acbb_cli_commands[j].sub && strcmp(acbb_cli_commands[j].name, c->name) == 0)
                command_case(f, "        ", acbb_cli_commands[j].sub, &acbb_cli_commands[j]);
        fputs("        esac ;;\n", f);
    }
    fputs("    esac\n", f);
}

/* _acbb_keys: every preset key; _acbb_values KEY: its choices (enum, on/off). */
static void keys(FILE *f)
{
    size_t n = acbb_scene_field_count();
    fputs("_acbb_keys=\"", f);
    for (size_t i = 0; i < n; i++) {
        const acbb_field_info *fi = acbb_scene_field(i);
        if (fi) fprintf(f, "%s%s.%s", i ? " " : "", fi->section, fi->key);
    }
    fputs("\"\n_acbb_values()\n{\n    case $1 in\n", f);
    for (size_t i = 0; i < n; i++) {
        const acbb_field_info *fi = acbb_scene_field(i);
        if (!fi || (fi->type != ACBB_FIELD_ENUM && fi->type != ACBB_FIELD_BOOL)) continue;
        fprintf(f, "    %s.%s) echo \"", fi->section, fi->key);
        if (fi->type == ACBB_FIELD_BOOL) fputs("on off", f);
        for (int k = 0; fi->type == ACBB_FIELD_ENUM && fi->choices[k]; k++)
            fprintf(f, "%s%s", k ? " " : "", fi->choices[k]);
        fputs("\" ;;\n", f);
    }
    fputs("    esac\n}\n", f);
}

/* The value lists of --kind, --metric, --models and --knobs, from the
 * parsers' own tables. */
static void value_lists(FILE *f)
{
    fputs("_acbb_kinds=\"", f);
    for (int k = 0; k <= ACBB_PLOT_SET_TEMPERATURE; k++)
        fprintf(f, "%s ", acbb_plot_kind_name((acbb_plot_kind)k));
    fputs("all\"\n_acbb_metrics=\"", f);
    acbb_output o;
    char buf[128];
    for (size_t i = 0; acbb_output_get(i, &o); i++) {
        acbb_output_flat(&o, buf, sizeof buf);
        fprintf(f, "%s%s", i ? " " : "", buf);
    }
    fputs("\"\n_acbb_models=\"", f);
    for (int m = ACBB_MODEL_STATIC; m <= ACBB_MODEL_DYNAMIC; m++)
        fprintf(f, "%s%s", m ? " " : "", acbb_model_level_name((acbb_model_level)m));
    fputs("\"\n_acbb_knobs=\"", f);
    for (int k = 0; k < ACBB_KNOB_COUNT; k++)
        fprintf(f, "%s%s", k ? " " : "", acbb_accuracy_knob_name((acbb_accuracy_knob)k));
    fputs("\"\n", f);
}

/* The options that take a file or directory, then those that take another
 * value with no list (a number, a range): nothing is offered for them. */
static void value_options(FILE *f)
{
    fputs("    --set|--grid) _acbb_key_value; return ;;\n"
          "    --param|--inputs) COMPREPLY=($(compgen -W \"$_acbb_keys\" -- \"$cur\")); return ;;\n"
          "    --kind) COMPREPLY=($(compgen -W \"$_acbb_kinds\" -- \"$cur\")); return ;;\n"
          "    --metric) COMPREPLY=($(compgen -W \"$_acbb_metrics\" -- \"$cur\")); return ;;\n"
          "    --models) COMPREPLY=($(compgen -W \"$_acbb_models\" -- \"$cur\")); return ;;\n"
          "    --knobs) COMPREPLY=($(compgen -W \"$_acbb_knobs\" -- \"$cur\")); return ;;\n"
          "    --series) COMPREPLY=($(compgen -W \"70 72 73 718 719 60 62 63 618 619\" -- \"$cur\"));"
          " return ;;\n", f);
    const char *files[] = { "FILE", "PATH", "DIR" };
    for (int pass = 0; pass < 2; pass++) {
        bool first = true;
        for (int k = 0; k < CLI_OPT_COUNT; k++) {
            const acbb_cli_option *o = &acbb_cli_options[k];
            static const char *const listed[] = { "set", "grid", "param", "inputs", "kind",
                                                  "metric", "models", "knobs", "series" };
            bool skip = !o->metavar;
            for (size_t i = 0; i < sizeof listed / sizeof listed[0]; i++)
                skip |= strcmp(o->name, listed[i]) == 0;
            bool file = false;
            for (size_t i = 0; o->metavar && i < 3; i++) file |= strcmp(o->metavar, files[i]) == 0;
            if (skip || file != (pass == 0)) continue;
            fprintf(f, "%s--%s", first ? "    " : "|", o->name);
            first = false;
        }
        fputs(pass == 0 ? ") COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n"
                        : ") return ;;\n", f);
    }
}

void acbb_cli_print_bash_completion(FILE *f)
{
    fputs("# bash completion for acbb, generated by `acbb help --bash-completion`\n"
          "# from the command, option and key tables; do not edit.\n", f);
    keys(f);
    value_lists(f);
    /* bash splits the word at = and : (COMP_WORDBREAKS): the replies lose
     * what it already took as written. */
    fputs("_acbb_trim()\n{\n"
          "    local pre=${cur%\"${cur##*[=:]}\"}\n"
          "    [ -n \"$pre\" ] && COMPREPLY=(\"${COMPREPLY[@]#\"$pre\"}\")\n"
          "}\n"
          "# KEY= (no space after), then KEY=CHOICE for a key with choices\n"
          "_acbb_key_value()\n{\n"
          "    if [[ $cur == *=* ]]; then\n"
          "        local key=${cur%%=*}\n"
          "        COMPREPLY=($(compgen -P \"$key=\" -W \"$(_acbb_values \"$key\")\" -- \"${cur#*=}\"))\n"
          "    else\n"
          "        COMPREPLY=($(compgen -S = -W \"$_acbb_keys\" -- \"$cur\"))\n"
          "        compopt -o nospace 2>/dev/null\n"
          "    fi\n"
          "    _acbb_trim\n"
          "}\n"
          "_acbb()\n{\n"
          "    local line=${COMP_LINE-${COMP_WORDS[*]}} words cword cur prev cmd sub opts= pos=none\n"
          "    line=${line:0:${COMP_POINT:-${#line}}}\n"
          "    read -ra words <<<\"$line\"\n"
          "    [[ -z $line || $line == *[[:space:]] ]] && words+=(\"\")\n"
          "    cword=$((${#words[@]} - 1)) cur=${words[cword]} prev=${words[cword - 1]}\n"
          "    cmd=${words[1]} sub=${words[2]}\n"
          "    COMPREPLY=()\n"
          "    if [ \"$cword\" -eq 1 ]; then\n"
          "        COMPREPLY=($(compgen -W \"", f);
    names(f);
    fputs("\" -- \"$cur\"))\n        return\n    fi\n    case $prev in\n", f);
    value_options(f);
    fputs("    esac\n", f);
    commands(f);
    fputs("    if [[ $cur == -* && $cur != - ]]; then\n"
          "        COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
          "        return\n"
          "    fi\n"
          "    case $pos in\n"
          "    preset)\n"
          "        # a file, a name on the search path (`acbb presets`), or - (stdin)\n"
          "        COMPREPLY=($(compgen -f -- \"$cur\") $(compgen -W \"- $(acbb presets 2>/dev/null"
          " | sed -n 's/^  *\\([^ /]*\\)\\.ini.*/\\1/p')\" -- \"$cur\")) ;;\n"
          "    file) COMPREPLY=($(compgen -f -- \"$cur\")) ;;\n"
          "    dir) COMPREPLY=($(compgen -d -- \"$cur\")) ;;\n"
          "    command) COMPREPLY=($(compgen -W \"", f);
    names(f);
    fputs("\" -- \"$cur\")) ;;\n"
          "    esac\n"
          "}\n"
          "complete -o filenames -F _acbb acbb\n", f);
}
