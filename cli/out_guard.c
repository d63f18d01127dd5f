/* acbb CLI — the output guard (out_guard.h). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/tools/outfile.h"
#include "exit.h"
#include "out_guard.h"
#include "plot.h"
#include "presets.h"
#include "say.h"

/* The file a write to `path` lands in: a symlink chain followed to its
 * end, a dangling link's target included (the atomic writer creates that,
 * outfile.c). */
static void follow_links(const char *path, char *out, size_t n)
{
    snprintf(out, n, "%s", path);
    for (int depth = 0; depth < 40; depth++) {
        struct stat ls;
        char link[PATH_MAX];
        if (lstat(out, &ls) != 0 || !S_ISLNK(ls.st_mode)) return;
        ssize_t len = readlink(out, link, sizeof link - 1);
        if (len < 0) return;
        link[len] = '\0';
        char *slash = strrchr(out, '/');
        if (link[0] == '/' || !slash) {
            snprintf(out, n, "%s", link);
        } else {
            char dir[PATH_MAX];
            snprintf(dir, sizeof dir, "%.*s", (int)(slash - out), out);
            if (snprintf(out, n, "%s/%s", dir, link) >= (int)n) return; /* too long */
        }
    }
}

/* The canonical name of the file `path` writes (symlinks followed, the
 * directory resolved when the file does not exist yet); *exists and *st
 * for an existing one. */
static void where(const char *path, char *out, size_t n, struct stat *st, int *exists)
{
    char target[PATH_MAX], dir[PATH_MAX], buf[PATH_MAX];
    follow_links(path, target, sizeof target);
    *exists = stat(target, st) == 0;
    if (*exists && realpath(target, buf)) {
        snprintf(out, n, "%s", buf);
        return;
    }
    snprintf(dir, sizeof dir, "%s", target);
    char *slash = strrchr(dir, '/');
    const char *base = slash ? target + (slash - dir) + 1 : target;
    if (slash == dir) dir[1] = '\0';
    else if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    if (!realpath(dir, buf) || snprintf(out, n, "%s/%s", buf, base) >= (int)n)
        snprintf(out, n, "%s", target);
}

static int same_file(const char *a, const char *b)
{
    char ra[PATH_MAX], rb[PATH_MAX];
    struct stat sa, sb;
    int ea, eb;
    where(a, ra, sizeof ra, &sa, &ea);
    where(b, rb, sizeof rb, &sb, &eb);
    if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    return strcmp(ra, rb) == 0;
}

static int refuse(const char *cmd, const acbb_cli_named_path *o, const char *why)
{
    acbb_cli_say("%s: cannot write %s %s: %s\n", cmd, o->what, o->path, why);
    return ACBB_EXIT_INPUT;
}

/* A name the file system (and the writer's temporary file beside it,
 * ACBB_OUT_NAME_MAX) cannot take is said before anything runs; after a
 * run it would fail at commit (issue 26 item 11). */
static int too_long(const char *cmd, const acbb_cli_named_path *o)
{
    char target[PATH_MAX + 1], why[160];
    if (strlen(o->path) >= PATH_MAX) {
        snprintf(why, sizeof why, "the path is %zu bytes long; at most %d", strlen(o->path),
                 PATH_MAX - 1);
        return refuse(cmd, o, why);
    }
    follow_links(o->path, target, sizeof target);
    const char *names[2] = { o->path, target };
    for (int k = 0; k < 2; k++) {
        const char *last = strrchr(names[k], '/');
        last = last ? last + 1 : names[k];
        for (const char *c = names[k]; *c;) {
            size_t len = strcspn(c, "/"), max = c == last ? ACBB_OUT_NAME_MAX : NAME_MAX;
            if (len > max) {
                snprintf(why, sizeof why, "the name %.*s... is %zu bytes long; at most %zu",
                         20, c, len, max);
                return refuse(cmd, o, why);
            }
            c += len + (c[len] == '/');
        }
    }
    return 0;
}

/* Kept open to the end: the command's own open then finds the reader the
 * guard found (a reader sees EOF only when every writer is gone). */
static int held_fifo[8];
static size_t n_held;

/* Whether the file can be written at all, said before anything runs. */
static int cannot_write(const char *cmd, const acbb_cli_named_path *o)
{
    char target[PATH_MAX], dir[PATH_MAX];
    struct stat st;
    follow_links(o->path, target, sizeof target);
    snprintf(dir, sizeof dir, "%s", target);
    char *slash = strrchr(dir, '/');
    if (slash == dir) dir[1] = '\0';
    else if (slash) *slash = '\0';
    else snprintf(dir, sizeof dir, ".");
    if (stat(target, &st) != 0) {
        if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
            return refuse(cmd, o, "its directory does not exist");
        return access(dir, W_OK | X_OK) == 0 ? 0 : refuse(cmd, o, strerror(errno));
    }
    if (S_ISDIR(st.st_mode)) return refuse(cmd, o, "it is a directory");
    if (S_ISBLK(st.st_mode) || S_ISSOCK(st.st_mode))
        return refuse(cmd, o, "a block device or socket, not a file or stream");
    if (access(target, W_OK) != 0) return refuse(cmd, o, strerror(errno));
    if (!S_ISFIFO(st.st_mode)) return 0;
    int fd = acbb_out_open_special(target);
    if (fd < 0)
        return refuse(cmd, o, errno == ENXIO ? "a FIFO with no reader (start the reader first)"
                                             : strerror(errno));
    if (n_held < sizeof held_fifo / sizeof *held_fifo) held_fifo[n_held++] = fd;
    else close(fd);
    return 0;
}

int acbb_cli_guard_paths(const char *cmd, const acbb_cli_named_path *in, size_t n_in,
                         const acbb_cli_named_path *out, size_t n_out, bool json)
{
    size_t to_stdout = json;
    for (size_t i = 0; i < n_out; i++) {
        const acbb_cli_named_path *o = &out[i];
        if (strcmp(o->path, "-") == 0) {
            if (++to_stdout < 2) continue;
            acbb_cli_say("%s: more than one format on stdout (%s - with %s); "
                    "one format per stream: write the others to files\n", cmd, o->what,
                    json ? "--json" : "another -");
            return ACBB_EXIT_INPUT;
        }
        if (too_long(cmd, o) || cannot_write(cmd, o)) return ACBB_EXIT_INPUT;
        for (size_t j = 0; j < n_in; j++)
            if (strcmp(in[j].path, "-") != 0 && same_file(o->path, in[j].path)) {
                acbb_cli_say("%s: %s %s is %s (%s), an input of this command: not "
                        "overwritten; write to another file\n", cmd, o->what, o->path,
                        in[j].what, in[j].path);
                return ACBB_EXIT_INPUT;
            }
        for (size_t j = 0; j < i; j++)
            if (strcmp(out[j].path, "-") != 0 && same_file(o->path, out[j].path)) {
                acbb_cli_say("%s: %s %s and %s %s name one file: two outputs "
                        "cannot share it\n", cmd, out[j].what, out[j].path, o->what, o->path);
                return ACBB_EXIT_INPUT;
            }
    }
    return 0;
}

/* ---- the inputs and outputs of each command ---- */

#define MAX_OUT (9 + ACBB_CLI_PLOT_SIBLINGS)

/* The plots written next to --plot FILE (run) or --out FILE (plot --kind
 * all): outputs too, so their names are checked before the run. */
static size_t plot_siblings(const acbb_cli_args *a, acbb_cli_named_path *out)
{
    static char names[ACBB_CLI_PLOT_SIBLINGS][CLI_PATH_MAX];
    const char *kind = a->val[CLI_OPT_KIND];
    bool run = strcmp(a->cmd, "run") == 0 && a->val[CLI_OPT_PLOT];
    bool all = strcmp(a->cmd, "plot") == 0 && a->val[CLI_OPT_OUT] && kind &&
               strcmp(kind, "all") == 0;
    if (!run && !all) return 0;
    size_t n = acbb_cli_plot_siblings(run ? a->val[CLI_OPT_PLOT] : a->val[CLI_OPT_OUT], all,
                                      names, ACBB_CLI_PLOT_SIBLINGS);
    for (size_t i = 0; i < n; i++)
        out[i] = (acbb_cli_named_path){ names[i], run ? "a --plot sibling" : "a --out sibling" };
    return n;
}

static size_t collect(const acbb_cli_args *a, char *study_preset, acbb_cli_named_path *in,
                      size_t *n_in, acbb_cli_named_path *out)
{
    static const acbb_cli_opt outs[] = { CLI_OPT_CSV, CLI_OPT_JSONL, CLI_OPT_MD, CLI_OPT_PLOT };
    static const char *const out_names[] = { "--csv", "--jsonl", "--md", "--plot" };
    size_t n_out = 0;
    *n_in = 0;
    const char *preset = a->preset;
    /* study resolves its PRESET itself (`seed`); resolved here the same way. */
    if (strcmp(a->cmd, "study") == 0 && a->n_pos > 0 &&
        acbb_cli_resolve_preset(acbb_cli_study_preset_name(a->pos[0]), study_preset,
                                CLI_PATH_MAX, false) == 0)
        preset = study_preset;
    if (preset) in[(*n_in)++] = (acbb_cli_named_path){ preset, "the preset" };
    if (a->val[CLI_OPT_BASELINE])
        in[(*n_in)++] = (acbb_cli_named_path){ a->val[CLI_OPT_BASELINE], "--baseline" };
    if (strcmp(a->cmd, "merge") == 0) {
        for (int i = 1; i < a->n_pos && *n_in < CLI_MAX_POS; i++)
            in[(*n_in)++] = (acbb_cli_named_path){ a->pos[i], "a merge input" };
        if (a->n_pos > 0) out[n_out++] = (acbb_cli_named_path){ a->pos[0], "OUT" };
    }
    /* --out is a file for plot, new and edit (study's is a directory). */
    if (a->val[CLI_OPT_OUT] && strcmp(a->cmd, "study") != 0)
        out[n_out++] = (acbb_cli_named_path){ a->val[CLI_OPT_OUT], "--out" };
    for (size_t k = 0; k < sizeof outs / sizeof *outs; k++)
        if (a->val[outs[k]] && a->val[outs[k]][0])
            out[n_out++] = (acbb_cli_named_path){ a->val[outs[k]], out_names[k] };
    /* a sweep's plain CSV has its header beside it (cli/sweep.h): --jsonl
     * X.csv.json --csv X.csv would write one file twice */
    static char side[CLI_PATH_MAX];
    const char *csv = a->val[CLI_OPT_CSV];
    if (strcmp(a->cmd, "sweep") == 0 && csv && csv[0] && strcmp(csv, "-") != 0 &&
        !a->val[CLI_OPT_CSV_HEADER] &&
        snprintf(side, sizeof side, "%s.json", csv) < (int)sizeof side)
        out[n_out++] = (acbb_cli_named_path){ side, "the --csv header file (FILE.json)" };
    return n_out + plot_siblings(a, out + n_out);
}

int acbb_cli_out_guard(const acbb_cli_args *a)
{
    static acbb_cli_named_path in[CLI_MAX_POS + 2];
    static char study_preset[CLI_PATH_MAX];
    acbb_cli_named_path out[MAX_OUT];
    size_t n_in, n_out = collect(a, study_preset, in, &n_in, out);
    return acbb_cli_guard_paths(a->cmd, in, n_in, out, n_out, a->val[CLI_OPT_JSON] != NULL);
}
