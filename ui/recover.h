/* acbb TUI — nothing typed is lost: unsaved preset edits are kept in a
 * recovery file (an editor's swap file) every few seconds, on SIGHUP,
 * SIGTERM and SIGQUIT, and when a second Ctrl-C leaves without saving;
 * opening that preset again offers to restore them.
 *
 * Where: $XDG_STATE_HOME/acbb/recover/ (default ~/.local/state/...), one
 * file per preset, "<base name>-<hash of the real path>.ini"; the
 * directory must be the user's and writable by no one else (else nothing
 * is written or offered: recover.c). A recovery file is a full preset
 * (acbb_scene_save). */
#ifndef ACBB_UI_RECOVER_H
#define ACBB_UI_RECOVER_H

#include <stddef.h>
#include "editor.h"

/* The recovery file of the editor's preset (the default scene has one
 * too, under the name "(default)"). 0, or -1 when no path can be made. */
int acbb_recover_path(const acbb_editor *e, char *out, size_t n);
/* Write the edits if the editor holds unsaved ones (0: written or nothing
 * to write; -1: could not write, `why` says why and where). Without
 * unsaved edits (undone back to the file) an older recovery file is
 * removed: it would be a stale offer. */
int acbb_recover_write(const acbb_editor *e, char *why, size_t wn);
/* Forget the recovery file (after a save, or edits the user discarded). */
void acbb_recover_clear(const acbb_editor *e);
/* A recovery file newer than the preset itself exists: 1 and its path. */
int acbb_recover_pending(const acbb_editor *e, char *out, size_t n);
/* Put the recovered edits into the editor (an undoable edit). */
int acbb_recover_restore(acbb_editor *e, const char *path, char *err, size_t n);

#endif
