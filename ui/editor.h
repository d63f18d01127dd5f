/* acbb TUI — the preset editor's model (no curses here).
 *
 * Edits go through acbb_scene_set on a copy of the scene, so a bad value
 * is refused with the engine's own validation message and never applied.
 * Every accepted edit pushes the previous scene on an undo stack (the
 * oldest is dropped when it is full). "Modified" compares every field, as
 * the preset file would write it, with the scene last loaded or saved, so
 * undoing back to the file clears the marker. */
#ifndef ACBB_UI_EDITOR_H
#define ACBB_UI_EDITOR_H

#include <limits.h>
#include <stddef.h>
#include "acbb/tools/outfile.h"
#include "acbb/scene.h"
#include "acbb/status.h"

#define ACBB_EDITOR_UNDO 64

typedef struct {
    char path[PATH_MAX];      /* file being edited; "" for the built-in default */
    acbb_scene scene;         /* being edited */
    acbb_scene saved;         /* as last loaded or saved */
    acbb_scene undo[ACBB_EDITOR_UNDO];
    int undo_n, undo_top;     /* entries held; index of the next push */
    int modified;
    acbb_file_stamp stamp;    /* the file as last loaded or saved (outfile.h) */
    int conflict;             /* the last save was refused: the file changed on disk */
    size_t cursor, top;       /* selected field, first field shown */
} acbb_editor;

/* Start from acbb_scene_default with no file. */
void acbb_editor_init(acbb_editor *e);
/* Load `path`; on failure the editor is unchanged and err says why. */
acbb_status acbb_editor_open(acbb_editor *e, const char *path, acbb_error *err);
/* Set field i from text (preset units). Refused values leave the scene
 * unchanged. */
acbb_status acbb_editor_set(acbb_editor *e, size_t i, const char *text, acbb_error *err);
/* Next (dir > 0) or previous choice of a bool/enum field. */
acbb_status acbb_editor_cycle(acbb_editor *e, size_t i, int dir, acbb_error *err);
/* Replace the whole scene (recovered edits) as one undoable edit. */
void acbb_editor_replace(acbb_editor *e, const acbb_scene *s);
/* Undo the last accepted edit; 0 if there was none. */
int acbb_editor_undo(acbb_editor *e);
/* Save to `path` (NULL: the current path) atomically through
 * acbb_scene_save_edits: in an existing preset only the lines of changed
 * keys are rewritten, comments and order stay. On success the editor's
 * path becomes `path` and the marker clears. The save holds the file's
 * lock (outfile.h); saving to the current path is refused (ACBB_EIO,
 * e->conflict = 1) when another program changed the file since it was
 * loaded or saved (issue 20 item 2): the caller offers reload, overwrite
 * (acbb_editor_overwrite) or save elsewhere. */
acbb_status acbb_editor_save(acbb_editor *e, const char *path, acbb_error *err);
/* Save to the current path even though it changed on disk. */
acbb_status acbb_editor_overwrite(acbb_editor *e, acbb_error *err);
/* 1 if two scenes differ in any field as the preset file would write it
 * (struct padding makes memcmp unreliable). */
int acbb_editor_differs(const acbb_scene *a, const acbb_scene *b);
/* Base name of the path for titles ("(default)" without one). */
const char *acbb_editor_name(const acbb_editor *e);

#endif
