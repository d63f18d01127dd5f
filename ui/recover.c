/* acbb TUI — recovery files for unsaved edits (recover.h). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "recover.h"

static int state_dir(char *out, size_t n)
{
    const char *x = getenv("XDG_STATE_HOME"), *home = getenv("HOME");
    int w;
    if (x && x[0] == '/') w = snprintf(out, n, "%s/acbb/recover", x);
    else if (home && home[0]) w = snprintf(out, n, "%s/.local/state/acbb/recover", home);
    else return -1;
    return w > 0 && (size_t)w < n ? 0 : -1;
}

int acbb_recover_path(const acbb_editor *e, char *out, size_t n)
{
    char dir[PATH_MAX], abs[PATH_MAX];
    if (state_dir(dir, sizeof dir) != 0) return -1;
    if (!e->path[0]) snprintf(abs, sizeof abs, "(default)");
    else if (!realpath(e->path, abs)) snprintf(abs, sizeof abs, "%s", e->path);
    for (char *p = abs; *p; p++)
        if (*p == '/') *p = '%';
    int w = snprintf(out, n, "%s/%s", dir, abs);
    return w > 0 && (size_t)w < n ? 0 : -1;
}

/* mkdir -p for the state directory (mode 0700: the edits are the user's). */
static int make_dirs(const char *path)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0700) != 0 && errno != EEXIST) return -1;
        *p = '/';
    }
    return mkdir(buf, 0700) == 0 || errno == EEXIST ? 0 : -1;
}

int acbb_recover_write(const acbb_editor *e)
{
    if (!e->modified) return 0;
    char path[PATH_MAX], dir[PATH_MAX];
    if (acbb_recover_path(e, path, sizeof path) != 0 || state_dir(dir, sizeof dir) != 0) return -1;
    if (make_dirs(dir) != 0) return -1;
    return acbb_scene_save(path, &e->scene, NULL) == ACBB_OK ? 0 : -1;
}

void acbb_recover_clear(const acbb_editor *e)
{
    char path[PATH_MAX];
    if (acbb_recover_path(e, path, sizeof path) == 0) unlink(path);
}

int acbb_recover_pending(const acbb_editor *e, char *out, size_t n)
{
    struct stat r, p;
    if (acbb_recover_path(e, out, n) != 0 || stat(out, &r) != 0) return 0;
    /* A preset saved after the recovery file was written supersedes it. */
    return !e->path[0] || stat(e->path, &p) != 0 || r.st_mtime >= p.st_mtime;
}

int acbb_recover_restore(acbb_editor *e, const char *path, char *err, size_t n)
{
    acbb_scene s;
    acbb_error er = { { 0 } };
    if (acbb_scene_load(path, &s, &er) != ACBB_OK) {
        snprintf(err, n, "%s", er.msg);
        return -1;
    }
    acbb_editor_replace(e, &s);
    return 0;
}
