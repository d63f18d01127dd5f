/* acbb CLI — `acbb edit PRESET --set ... [--out FILE]` (commands.h).
 *
 * The edited scene passes every check `acbb run` makes before it is saved
 * (acbb_sim_check, issue 26 item 9). An installed preset, shared by every
 * user, is never rewritten: the edits go to --out FILE (issue 26 item 6).
 * A write that fails once the file was opened (disk full) is exit 4, as
 * for every output; the output guard (out_guard.h) vetted the path. */
#include <stdio.h>
#include <string.h>
#include "acbb/tools/outfile.h"
#include "acbb/sim.h"
#include "acbb/tools/scene_edit.h"
#include "commands.h"
#include "common.h"
#include "exit.h"
#include "presets.h"
#include "say.h"

#define EDIT_LOCK_S 30.0   /* wait this long for another acbb's save */
#define EDIT_TRIES 3       /* re-reads when an unlocking writer keeps changing it */

/* The preset with the edits, checked as `run` checks it: 0 or the status. */
static int edited_scene(const acbb_cli_args *a, const char *to, acbb_scene *sc)
{
    int rc = acbb_cli_load_scene(a, sc);
    if (rc) return rc;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_sim_check(sc, &err);
    if (st == ACBB_OK) return 0;
    acbb_cli_say("%s: not saved: %s\n", to, acbb_cli_err_text(&err, st));
    return acbb_cli_exit_for(st);
}

/* A failed save: a write error once open is 4, a refusal its status. */
static int save_failed(const acbb_error *err, acbb_status st)
{
    acbb_cli_say("%s\n", acbb_cli_err_text(err, st));
    return st == ACBB_EIO ? ACBB_EXIT_INTERNAL : acbb_cli_exit_for(st);
}

/* Read, apply the --set edits and save, all under the file's lock
 * (outfile.h): a second `acbb edit` or the TUI's save waits, so each one
 * applies its keys to the content the other left (issue 20 item 1). A
 * writer that takes no lock (a text editor) is caught by the stamp: the
 * file is read again and the keys applied to the new content. */
static int edit_in_place(const acbb_cli_args *a)
{
    acbb_error err = { { 0 } };
    acbb_status st = ACBB_OK;
    for (int tries = 0; tries < EDIT_TRIES; tries++) {
        acbb_file_stamp was, now;
        acbb_scene sc;
        int rc;
        if ((st = acbb_file_stamp_take(a->preset, &was, &err)) != ACBB_OK) break;
        if ((rc = edited_scene(a, a->preset, &sc))) return rc;
        if ((st = acbb_file_stamp_take(a->preset, &now, &err)) != ACBB_OK) break;
        if (!acbb_file_stamp_changed(&was, &now)) {
            st = acbb_scene_save_edits(a->preset, &sc, &err);
            return st == ACBB_OK ? 0 : save_failed(&err, st);
        }
    }
    if (st == ACBB_OK)
        st = acbb_error_set(&err, ACBB_EIO, "%s: not saved: another program kept changing "
                            "it while the edits were applied", a->preset);
    acbb_cli_say("%s\n", acbb_cli_err_text(&err, st));
    return acbb_cli_exit_for(st);
}

/* --out FILE: the preset is only read; FILE gets its text with the edits. */
static int edit_to(const acbb_cli_args *a, const char *to)
{
    acbb_scene sc;
    int rc = edited_scene(a, to, &sc);
    if (rc) return rc;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_scene_save_edits_to(a->preset, to, &sc, &err);
    return st == ACBB_OK ? 0 : save_failed(&err, st);
}

static int locked(const acbb_cli_args *a, const char *target)
{
    acbb_error err = { { 0 } };
    acbb_file_lock *lock = NULL;
    acbb_status st = acbb_file_lock_take(target, EDIT_LOCK_S, &lock, &err);
    if (st != ACBB_OK) {
        acbb_cli_say("%s\n", acbb_cli_err_text(&err, st));
        return acbb_cli_exit_for(st);
    }
    int rc = target == a->preset ? edit_in_place(a) : edit_to(a, target);
    acbb_file_lock_release(lock);
    return rc;
}

int acbb_cli_cmd_edit(const acbb_cli_args *a)
{
    const char *out = a->val[CLI_OPT_OUT];
    if (a->n_sets == 0) {
        acbb_cli_say("edit: nothing to do (give --set section.key=value)\n");
        return ACBB_EXIT_INPUT;
    }
    char dir[CLI_PATH_MAX];
    if (!out && acbb_cli_preset_installed(a->preset, dir, sizeof dir)) {
        acbb_cli_preset_dir dirs[CLI_MAX_PRESET_DIRS];
        size_t nd = acbb_cli_preset_dirs(dirs);
        bool user = nd && strcmp(dirs[0].role, "user") == 0;
        acbb_cli_say("edit: %s is an installed preset (in %s), shared by every user: "
                     "not edited; write your copy with --out FILE%s%s%s, or make a preset "
                     "with `acbb new`\n", a->preset, dir,
                     user ? " (your own presets, searched first: " : "",
                     user ? dirs[0].path : "", user ? ")" : "");
        return ACBB_EXIT_INPUT;
    }
    const char *target = out ? out : a->preset;
    int rc = locked(a, target);
    if (rc) return rc;
    if (out) printf("%s: %zu edit%s of %s saved\n", out, a->n_sets, a->n_sets == 1 ? "" : "s",
                    a->preset);
    else printf("%s: %zu edit%s saved\n", a->preset, a->n_sets, a->n_sets == 1 ? "" : "s");
    return acbb_cli_stdout_check(0);
}
