/* acbb TUI — preset editor model (see editor.h). */
#include <stdio.h>
#include <string.h>
#include "acbb/sim.h"
#include "acbb/tools/scene_edit.h"
#include "acbb/tools/scene_schema.h"
#include "editor.h"

#define ACBB_EDITOR_LOCK_S 5.0 /* the TUI waits this long for another save */

int acbb_editor_differs(const acbb_scene *a, const acbb_scene *b)
{
    /* Field by field as text: struct padding makes memcmp unreliable, and
     * the text is what the file would hold. */
    char x[128], y[128];
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        acbb_scene_field_format(a, i, x, sizeof x);
        acbb_scene_field_format(b, i, y, sizeof y);
        if (strcmp(x, y) != 0) return 1;
    }
    return 0;
}

static void refresh_modified(acbb_editor *e)
{
    e->modified = acbb_editor_differs(&e->scene, &e->saved);
}

void acbb_editor_init(acbb_editor *e)
{
    memset(e, 0, sizeof *e);
    acbb_scene_default(&e->scene);
    e->saved = e->scene;
}

acbb_status acbb_editor_open(acbb_editor *e, const char *path, acbb_error *err)
{
    acbb_scene s;
    acbb_file_stamp stamp;
    if (strlen(path) >= sizeof e->path)
        return acbb_error_set(err, ACBB_EINVAL, "%s: path too long", path);
    /* Stamped before reading: a change in between shows as a conflict at
     * the save (the safe side), never as nothing. */
    acbb_status rc = acbb_file_stamp_take(path, &stamp, err);
    if (rc == ACBB_OK) rc = acbb_scene_load(path, &s, err);
    if (rc != ACBB_OK) return rc;
    e->stamp = stamp;
    e->conflict = 0;
    e->scene = s;
    e->saved = s;
    e->undo_n = 0;
    e->undo_top = 0;
    e->modified = 0;
    strcpy(e->path, path);
    return ACBB_OK;
}

static void push_undo(acbb_editor *e)
{
    e->undo[e->undo_top] = e->scene;
    e->undo_top = (e->undo_top + 1) % ACBB_EDITOR_UNDO;
    if (e->undo_n < ACBB_EDITOR_UNDO) e->undo_n++;
}

void acbb_editor_replace(acbb_editor *e, const acbb_scene *s)
{
    push_undo(e);
    e->scene = *s;
    refresh_modified(e);
}

acbb_status acbb_editor_set(acbb_editor *e, size_t i, const char *text, acbb_error *err)
{
    const acbb_field_info *f = acbb_scene_field(i);
    if (!f) return acbb_error_set(err, ACBB_EINVAL, "no field %zu", i);
    char key[160];
    snprintf(key, sizeof key, "%s.%s", f->section, f->key);
    acbb_scene trial = e->scene;
    acbb_status rc = acbb_scene_set(&trial, key, text, err);
    if (rc != ACBB_OK) return rc;
    /* Re-entering the current value is not an edit. */
    if (!acbb_editor_differs(&trial, &e->scene)) return ACBB_OK;
    push_undo(e);
    e->scene = trial;
    refresh_modified(e);
    return ACBB_OK;
}

acbb_status acbb_editor_cycle(acbb_editor *e, size_t i, int dir, acbb_error *err)
{
    const acbb_field_info *f = acbb_scene_field(i);
    static const char *const onoff[] = { "on", "off", NULL };
    if (!f || (f->type != ACBB_FIELD_BOOL && f->type != ACBB_FIELD_ENUM))
        return acbb_error_set(err, ACBB_EINVAL, "only on/off and choice fields cycle; press Enter to type a value");
    const char *const *ch = f->type == ACBB_FIELD_BOOL ? onoff : f->choices;
    int n = 0, cur = 0;
    char now[128];
    acbb_scene_field_format(&e->scene, i, now, sizeof now);
    for (n = 0; ch[n]; n++)
        if (strcmp(ch[n], now) == 0) cur = n;
    if (n == 0) return acbb_error_set(err, ACBB_EINVAL, "no choices");
    int next = ((cur + (dir > 0 ? 1 : -1)) % n + n) % n;
    return acbb_editor_set(e, i, ch[next], err);
}

int acbb_editor_undo(acbb_editor *e)
{
    if (e->undo_n == 0) return 0;
    e->undo_top = (e->undo_top + ACBB_EDITOR_UNDO - 1) % ACBB_EDITOR_UNDO;
    e->undo_n--;
    e->scene = e->undo[e->undo_top];
    refresh_modified(e);
    return 1;
}

/* Under the lock: refuse when the file is no longer what was read (only
 * for the file this editor read: `check`), save, stamp what was written. */
static acbb_status save_locked(acbb_editor *e, const char *p, int check, acbb_error *err)
{
    acbb_file_stamp now;
    acbb_status rc = acbb_file_stamp_take(p, &now, err);
    if (rc != ACBB_OK) return rc;
    if (check && acbb_file_stamp_changed(&e->stamp, &now)) {
        e->conflict = 1;
        return acbb_error_set(err, ACBB_EIO, "%s changed on disk since it was read", p);
    }
    /* Only the changed lines of the user's file are rewritten (comments and
     * order stay); a new file is written in full. */
    rc = acbb_scene_save_edits(p, &e->scene, err);
    if (rc == ACBB_OK) rc = acbb_file_stamp_take(p, &e->stamp, err);
    return rc;
}

static acbb_status save_to(acbb_editor *e, const char *path, int check, acbb_error *err)
{
    const char *p = path ? path : e->path;
    if (!p[0]) return acbb_error_set(err, ACBB_EINVAL, "no file name: use save-as");
    if (strlen(p) >= sizeof e->path)
        return acbb_error_set(err, ACBB_EINVAL, "%s: path too long", p);
    e->conflict = 0;
    /* The rules `acbb run` applies, as `acbb edit` (issue 26 item 9): the
     * scene's own check misses what only compiling it finds. */
    acbb_error why;
    acbb_status rc = acbb_sim_check(&e->scene, &why);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "%s: not saved: %s", p, why.msg);
    acbb_file_lock *lock = NULL;
    rc = acbb_file_lock_take(p, ACBB_EDITOR_LOCK_S, &lock, err);
    if (rc != ACBB_OK) return rc;
    rc = save_locked(e, p, check && strcmp(p, e->path) == 0, err);
    acbb_file_lock_release(lock);
    if (rc != ACBB_OK) return rc;
    if (p != e->path) memmove(e->path, p, strlen(p) + 1);
    e->saved = e->scene;
    e->modified = 0;
    return ACBB_OK;
}

acbb_status acbb_editor_save(acbb_editor *e, const char *path, acbb_error *err)
{
    return save_to(e, path, 1, err);
}

acbb_status acbb_editor_overwrite(acbb_editor *e, acbb_error *err)
{
    return save_to(e, NULL, 0, err);
}

const char *acbb_editor_name(const acbb_editor *e)
{
    if (!e->path[0]) return "(default)";
    const char *slash = strrchr(e->path, '/');
    return slash ? slash + 1 : e->path;
}
