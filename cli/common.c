/* acbb CLI — shared helpers (common.h). */
#include <errno.h>
#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "common.h"
#include "exit.h"

const char *acbb_cli_err_text(const acbb_error *err, acbb_status st)
{
    return err->msg[0] ? err->msg : acbb_status_name(st);
}

/* The engine names a failed edit by its text ("key=value: why"); on the
 * command line that edit was a --set option, so say so. */
const char *acbb_cli_set_prefix(const char *msg, const char *const *sets, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        size_t len = strlen(sets[i]);
        if (strncmp(msg, sets[i], len) == 0 && msg[len] == ':') return "--set ";
    }
    return "";
}

#define STDIN_PRESET_MAX (4u << 20) /* bytes; a preset is a few kB */

/* PRESET "-": stdin, read once and kept (a command may load its scene more
 * than once), named "<stdin>" in messages (issue 28 item 12). */
static acbb_status load_stdin(acbb_scene *sc, acbb_error *err)
{
    static char *text;
    static size_t len;
    static bool read_done;
    if (!read_done) {
        read_done = true;
        text = malloc(STDIN_PRESET_MAX + 1);
        if (!text) return acbb_error_set(err, ACBB_ENOMEM, "<stdin>: out of memory");
        len = fread(text, 1, STDIN_PRESET_MAX + 1, stdin);
        if (ferror(stdin))
            return acbb_error_set(err, ACBB_EIO, "<stdin>: cannot read: %s", strerror(errno));
    }
    if (!text) return acbb_error_set(err, ACBB_ENOMEM, "<stdin>: out of memory");
    if (len > STDIN_PRESET_MAX)
        return acbb_error_set(err, ACBB_EINVAL, "<stdin>: more than %u bytes (a preset is a "
                              "few kB)", STDIN_PRESET_MAX);
    return acbb_scene_load_text_n(text, len, "<stdin>", sc, err);
}

int acbb_cli_load_scene(const acbb_cli_args *a, acbb_scene *sc)
{
    acbb_error err = { { 0 } };
    acbb_status st = strcmp(a->preset, "-") == 0 ? load_stdin(sc, &err)
                                                 : acbb_scene_load(a->preset, sc, &err);
    if (st == ACBB_OK) st = acbb_scene_apply_edits(sc, a->sets, a->n_sets, &err);
    /* --max-wall is fidelity.max_wall_s, checked by the schema's range. */
    if (st == ACBB_OK && a->val[CLI_OPT_MAX_WALL] &&
        acbb_scene_set(sc, "fidelity.max_wall_s", a->val[CLI_OPT_MAX_WALL], &err) != ACBB_OK) {
        fprintf(stderr, "acbb: --max-wall %s: %s\n", a->val[CLI_OPT_MAX_WALL], err.msg);
        return ACBB_EXIT_INPUT;
    }
    if (st == ACBB_OK) {
        /* A switch the scene cannot feel is said, not silently ignored. */
        acbb_inactive_effect in[8];
        size_t n = acbb_scene_inactive_effects(sc, in, 8);
        for (size_t i = 0; i < n; i++)
            fprintf(stderr, "acbb: note: %s has no effect here: %s\n", in[i].key, in[i].why);
        return 0;
    }
    const char *msg = acbb_cli_err_text(&err, st);
    fprintf(stderr, "acbb: %s%s\n", acbb_cli_set_prefix(msg, a->sets, a->n_sets), msg);
    return acbb_cli_exit_for(st);
}

int acbb_cli_stdout_check(long nonfinite)
{
    if (nonfinite) {
        fprintf(stderr, "acbb: internal error: %ld non-finite values in the output\n",
                nonfinite);
        return ACBB_EXIT_INTERNAL;
    }
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "acbb: cannot write to stdout\n");
        return ACBB_EXIT_INTERNAL;
    }
    return 0;
}

int acbb_cli_file_open(acbb_cli_file *c, const char *path)
{
    FILE *f = NULL;
    acbb_error err = { { 0 } };
    c->path = path;
    acbb_status st = acbb_out_open(path, &c->handle, &f, &err);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: %s\n", acbb_cli_err_text(&err, st));
        c->handle = NULL;
        return ACBB_EXIT_INPUT;
    }
    acbb_cli_out_init(&c->out, f);
    return 0;
}

int acbb_cli_file_close(acbb_cli_file *c)
{
    acbb_error err = { { 0 } };
    acbb_status st = acbb_out_commit(c->handle, &err);
    c->handle = NULL;
    if (st != ACBB_OK) {
        /* Same rule for every output flag: a path that cannot be opened is
         * bad input (2), a write that fails once open (disk full) is 4. */
        fprintf(stderr, "acbb: %s\n", acbb_cli_err_text(&err, st));
        return ACBB_EXIT_INTERNAL;
    }
    if (c->out.nonfinite) {
        fprintf(stderr, "acbb: internal error: %ld non-finite values in %s\n",
                c->out.nonfinite, c->path);
        return ACBB_EXIT_INTERNAL;
    }
    return 0;
}

/* ---- outputs that would overwrite an input or each other (issue 20 item 5) ---- */

/* Where `path` would be written: the file it names (symlinks followed) if it
 * exists, else its directory resolved plus its name. */
static int where(const char *path, char *out, size_t n, struct stat *st, int *exists)
{
    char buf[PATH_MAX];
    *exists = stat(path, st) == 0;
    if (*exists && realpath(path, buf)) return snprintf(out, n, "%s", buf) >= (int)n;
    char dir[PATH_MAX];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    const char *base = slash ? slash + 1 : path;
    if (slash == dir) dir[1] = '\0';
    else if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    if (!realpath(dir, buf)) return snprintf(out, n, "%s", path) >= (int)n;
    return snprintf(out, n, "%s/%s", buf, base) >= (int)n;
}

static int same_file(const char *a, const char *b)
{
    char ra[PATH_MAX], rb[PATH_MAX];
    struct stat sa, sb;
    int ea, eb;
    if (where(a, ra, sizeof ra, &sa, &ea) || where(b, rb, sizeof rb, &sb, &eb)) return 0;
    if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    return strcmp(ra, rb) == 0;
}

typedef struct {
    const char *path, *what;   /* "--csv", "the preset", ... */
} named_path;

static size_t collect(const acbb_cli_args *a, named_path *in, size_t *n_in, named_path *out)
{
    static const acbb_cli_opt outs[] = { CLI_OPT_CSV, CLI_OPT_JSONL, CLI_OPT_MD, CLI_OPT_PLOT };
    size_t n_out = 0;
    *n_in = 0;
    if (a->preset) in[(*n_in)++] = (named_path){ a->preset, "the preset" };
    if (a->val[CLI_OPT_BASELINE]) in[(*n_in)++] = (named_path){ a->val[CLI_OPT_BASELINE], "--baseline" };
    if (strcmp(a->cmd, "merge") == 0) {
        for (int i = 1; i < a->n_pos && *n_in < CLI_MAX_POS; i++)
            in[(*n_in)++] = (named_path){ a->pos[i], "a merge input" };
        if (a->n_pos > 0) out[n_out++] = (named_path){ a->pos[0], "OUT" };
    }
    /* plot --out is a file (study --out a directory, new --out never an
     * existing file). */
    if (strcmp(a->cmd, "plot") == 0 && a->val[CLI_OPT_OUT])
        out[n_out++] = (named_path){ a->val[CLI_OPT_OUT], "out" };
    for (size_t k = 0; k < sizeof outs / sizeof *outs; k++)
        if (a->val[outs[k]] && a->val[outs[k]][0])
            out[n_out++] = (named_path){ a->val[outs[k]], acbb_cli_options[outs[k]].name };
    return n_out;
}

/* An output that cannot be opened is bad input (2) for every flag alike,
 * said before anything runs (README "Exit codes"): the directory must
 * exist and be writable, an existing target writable and no directory. */
static int cannot_write(const char *cmd, const named_path *o)
{
    char dir[PATH_MAX];
    struct stat st;
    const char *why = NULL;
    snprintf(dir, sizeof dir, "%s", o->path);
    char *slash = strrchr(dir, '/');
    if (slash == dir) dir[1] = '\0';
    else if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    if (stat(o->path, &st) == 0) {
        if (S_ISDIR(st.st_mode)) why = "it is a directory";
        else if (access(o->path, W_OK) != 0) why = strerror(errno);
    } else if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        why = "its directory does not exist";
    } else if (access(dir, W_OK | X_OK) != 0) {
        why = strerror(errno);
    }
    if (!why) return 0;
    fprintf(stderr, "acbb: %s: cannot write %s%s %s: %s\n", cmd, o->what[0] == 'O' ? "" : "--",
            o->what, o->path, why);
    return ACBB_EXIT_INPUT;
}

int acbb_cli_check_paths(const acbb_cli_args *a)
{
    named_path in[CLI_MAX_POS + 2], out[9];
    size_t n_in, n_out = collect(a, in, &n_in, out), to_stdout = a->val[CLI_OPT_JSON] != NULL;
    for (size_t i = 0; i < n_out; i++) {
        if (strcmp(out[i].path, "-") == 0) {
            if (++to_stdout > 1) {
                fprintf(stderr, "acbb: %s: more than one format on stdout (--%s - with %s); "
                        "one format per stream: write the others to files\n", a->cmd, out[i].what,
                        a->val[CLI_OPT_JSON] ? "--json" : "another -");
                return ACBB_EXIT_INPUT;
            }
            continue;
        }
        if (cannot_write(a->cmd, &out[i])) return ACBB_EXIT_INPUT;
        for (size_t j = 0; j < n_in; j++)
            if (strcmp(in[j].path, "-") != 0 && same_file(out[i].path, in[j].path)) {
                fprintf(stderr, "acbb: %s: %s%s %s is %s, an input of this command: not "
                        "overwritten; write to another file\n", a->cmd, out[i].what[0] == 'O' ? "" : "--",
                        out[i].what, out[i].path, in[j].what);
                return ACBB_EXIT_INPUT;
            }
        for (size_t j = 0; j < i; j++)
            if (strcmp(out[j].path, "-") != 0 && same_file(out[i].path, out[j].path)) {
                fprintf(stderr, "acbb: %s: --%s and --%s name one file (%s): two formats "
                        "cannot share it\n", a->cmd, out[j].what, out[i].what, out[i].path);
                return ACBB_EXIT_INPUT;
            }
    }
    return 0;
}
