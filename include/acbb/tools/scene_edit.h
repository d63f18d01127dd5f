/* acbb — writing a preset an editor holds (src/scene/scene_edit.c,
 * src/scene/scene_io.c): back into the user's own file, keeping its
 * comments and layout (the TUI's Save, `acbb edit`), or to a stream the
 * caller owns (the TUI's recovery files). A new file or an export is
 * acbb_scene_save (scene.h). */
#ifndef ACBB_TOOLS_SCENE_EDIT_H
#define ACBB_TOOLS_SCENE_EDIT_H

#include <stdio.h>
#include "acbb/scene.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The text acbb_scene_save writes, to an open stream the caller owns (the
 * TUI's recovery files, written through a directory descriptor). The scene
 * must pass acbb_scene_validate; ACBB_EIO when a write fails. */
acbb_status acbb_scene_write(FILE *f, const acbb_scene *s, acbb_error *err);

/* Save `s` into the preset at `path`, keeping the user's file (the way
 * `git config` writes; DESIGN.md). For the TUI's Save and `acbb edit`.
 * - `path` exists and is a regular file (a symlink is followed): only the
 *   lines of keys whose values changed are rewritten, and on such a line
 *   only the value: the key spelling, blanks and an inline comment after the
 *   value stay. A value written differently but meaning the same ("1e3" for
 *   1000, "yes" for on) is not a change. Comments, blank lines, order and
 *   line ends (LF or CRLF) stay. A key that is not in the file and whose
 *   new value differs from the default is appended at the end of its
 *   section (after the section's last key, in its last occurrence); a
 *   missing section is appended at the end of the file. Keys absent from
 *   the file whose value is the default stay absent.
 * - `path` does not exist, is empty, or is not a regular file (FIFO,
 *   device): the full preset is written as by acbb_scene_save.
 * - The existing file must itself read as a preset (syntax, known keys,
 *   each key's range; the cross-field rules of the OLD file do not
 *   matter): otherwise nothing is written and the message names the line
 *   ("PATH: not saved: PATH:3: ...").
 * `s` must pass acbb_scene_validate. Written through acbb_out (atomic, mode
 * kept, symlink followed). Returns ACBB_OK, ACBB_EINVAL/ACBB_ILL_POSED (the
 * scene or the old file), ACBB_EIO or ACBB_ENOMEM; on failure the file is
 * untouched. */
acbb_status acbb_scene_save_edits(const char *path, const acbb_scene *s, acbb_error *err);
/* The same, the file at `path` kept and the result written to `to`
 * (`acbb edit --out`: an installed preset edited into the user's copy). */
acbb_status acbb_scene_save_edits_to(const char *path, const char *to, const acbb_scene *s,
                                     acbb_error *err);

#ifdef __cplusplus
}
#endif

#endif
