/* acbb CLI — shared helpers (common.h). */
#include <errno.h>
#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/tools/study.h"
#include "common.h"
#include "exit.h"
#include "say.h"
#include "acbb/tools/scene_inactive.h"

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
        acbb_cli_say("--max-wall %s: %s\n", a->val[CLI_OPT_MAX_WALL], err.msg);
        return ACBB_EXIT_INPUT;
    }
    if (st == ACBB_OK) {
        /* A switch the scene cannot feel is said, not silently ignored. */
        acbb_inactive_effect in[8];
        size_t n = acbb_scene_inactive_effects(sc, in, 8);
        for (size_t i = 0; i < n; i++)
            acbb_cli_say("note: %s has no effect here: %s\n", in[i].key, in[i].why);
        return 0;
    }
    const char *msg = acbb_cli_err_text(&err, st);
    acbb_cli_say("%s%s\n", acbb_cli_set_prefix(msg, a->sets, a->n_sets), msg);
    return acbb_cli_exit_for(st);
}

int acbb_cli_stdout_check(long nonfinite)
{
    if (nonfinite) {
        acbb_cli_say("internal error: %ld non-finite values in the output\n",
                nonfinite);
        return ACBB_EXIT_INTERNAL;
    }
    if (fflush(stdout) != 0 || ferror(stdout)) {
        acbb_cli_say("cannot write to stdout\n");
        return ACBB_EXIT_INTERNAL;
    }
    return 0;
}

int acbb_cli_runs_failed(const char *cmd, size_t failed, size_t total, const char *first,
                         const char *kept)
{
    if (!failed) return 0;
    acbb_cli_say("%s: %zu of %zu run%s failed (first: %.*s); %s\n", cmd, failed, total,
                 total == 1 ? "" : "s", (int)strcspn(first, "\n"), first, kept);
    return ACBB_EXIT_SOLVER;
}

int acbb_cli_no_memory(const char *cmd)
{
    acbb_cli_say("%s: out of memory\n", cmd);
    return ACBB_EXIT_INTERNAL;
}

int acbb_cli_study_failed(const char *cmd, acbb_study *st, const char *kept)
{
    const acbb_study_runs *r = acbb_study_results(st);
    for (size_t i = 0; i < r->n; i++) {
        const acbb_study_point *p = &r->all[i];
        if (p->ok) continue;
        char what[700];
        snprintf(what, sizeof what, "%s: %s: %s", p->label, acbb_status_name(p->status),
                 p->message);
        return acbb_cli_runs_failed(cmd, acbb_study_n_failed(st), r->n, what, kept);
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
        acbb_cli_say("%s\n", acbb_cli_err_text(&err, st));
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
        acbb_cli_say("%s\n", acbb_cli_err_text(&err, st));
        return ACBB_EXIT_INTERNAL;
    }
    if (c->out.nonfinite) {
        acbb_cli_say("internal error: %ld non-finite values in %s\n",
                c->out.nonfinite, c->path);
        return ACBB_EXIT_INTERNAL;
    }
    return 0;
}
