/* acbb TUI — recovery files for unsaved edits (recover.h).
 *
 * Safe against another user (issue 20 item 6): the directory must be the
 * user's own and writable by no one else, else nothing is written or
 * offered there; a recovery file is created O_CREAT|O_EXCL|O_NOFOLLOW
 * under a temporary name, filled, and renamed into place (rename replaces
 * a planted symlink, never follows it); a file is offered back only when
 * it is a regular file of this user that no one else may write. Names are
 * "<base>-<16 hex>.ini", the hex an FNV-1a hash (outfile.h) of the real
 * path, so b/c.ini and b%c.ini never share one. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/outfile.h"
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
    const char *slash = strrchr(abs, '/'), *base = slash ? slash + 1 : abs;
    unsigned long long h = acbb_hash64(abs, strlen(abs), ACBB_HASH64_SEED);
    int w = snprintf(out, n, "%s/%.64s-%016llx.ini", dir, base, h);
    return w > 0 && (size_t)w < n ? 0 : -1;
}

/* Ours and writable by no one else: a file or directory we may trust. */
static int trusted(const struct stat *st)
{
    return st->st_uid == geteuid() && !(st->st_mode & (S_IWGRP | S_IWOTH));
}

/* mkdir -p for the state directory (mode 0700: the edits are the user's),
 * then the directory itself must be trusted. */
static int make_dirs(const char *path, char *why, size_t wn)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0700) != 0 && errno != EEXIST) break;
        *p = '/';
    }
    struct stat st;
    if ((mkdir(buf, 0700) != 0 && errno != EEXIST) || lstat(buf, &st) != 0) {
        snprintf(why, wn, "cannot make %s: %s", path, strerror(errno));
        return -1;
    }
    if (!S_ISDIR(st.st_mode) || !trusted(&st)) {
        snprintf(why, wn, "%s is not a directory of yours that only you may write (fix it: "
                 "chmod 700, or set XDG_STATE_HOME)", path);
        return -1;
    }
    return 0;
}

/* Write the scene to a fresh temp (O_EXCL, no symlink followed), then
 * rename it to `path`. */
static int write_file(const acbb_editor *e, const char *dir, const char *path, char *why,
                      size_t wn)
{
    char tmp[PATH_MAX + 32];
    snprintf(tmp, sizeof tmp, "%s/.recover-%ld.tmp", dir, (long)getpid());
    unlink(tmp); /* our own leftover: the name carries our pid */
    int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) {
        snprintf(why, wn, "cannot create %s: %s", tmp, strerror(errno));
        return -1;
    }
    close(fd);
    acbb_error err = { { 0 } };
    if (acbb_scene_save(tmp, &e->scene, &err) != ACBB_OK || rename(tmp, path) != 0) {
        snprintf(why, wn, "cannot write %s: %s", path, err.msg[0] ? err.msg : strerror(errno));
        unlink(tmp);
        return -1;
    }
    return 0;
}

int acbb_recover_write(const acbb_editor *e, char *why, size_t wn)
{
    char path[PATH_MAX], dir[PATH_MAX];
    why[0] = '\0';
    /* Undone back to the file: an older recovery file is stale now. */
    if (!e->modified) {
        acbb_recover_clear(e);
        return 0;
    }
    if (acbb_recover_path(e, path, sizeof path) != 0 || state_dir(dir, sizeof dir) != 0) {
        snprintf(why, wn, "no state directory (set HOME or XDG_STATE_HOME)");
        return -1;
    }
    if (make_dirs(dir, why, wn) != 0) return -1;
    return write_file(e, dir, path, why, wn);
}

void acbb_recover_clear(const acbb_editor *e)
{
    char path[PATH_MAX];
    if (acbb_recover_path(e, path, sizeof path) == 0) unlink(path);
}

int acbb_recover_pending(const acbb_editor *e, char *out, size_t n)
{
    struct stat r, p, d;
    char dir[PATH_MAX];
    if (acbb_recover_path(e, out, n) != 0 || state_dir(dir, sizeof dir) != 0) return 0;
    /* Only from a trusted directory, only a regular file of ours (a planted
     * file or symlink is never offered). */
    if (lstat(dir, &d) != 0 || !S_ISDIR(d.st_mode) || !trusted(&d)) return 0;
    if (lstat(out, &r) != 0 || !S_ISREG(r.st_mode) || !trusted(&r)) return 0;
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
