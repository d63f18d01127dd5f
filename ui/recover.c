/* acbb TUI — recovery files for unsaved edits (recover.h).
 *
 * Safe against another user (issue 20 item 6): the directory must be the
 * user's own and writable by no one else, else nothing is written or
 * offered there; a recovery file is created O_CREAT|O_EXCL|O_NOFOLLOW
 * under a temporary name, filled, and renamed into place (rename replaces
 * a planted symlink, never follows it); a file is offered back only when
 * it is a regular file of this user that no one else may write. Names are
 * "<base>-<16 hex>.ini", the hex an FNV-1a hash (outfile.h) of the real
 * path, so b/c.ini and b%c.ini never share one.
 *
 * The directory is opened one component at a time with O_NOFOLLOW and
 * every file is reached through its descriptor (issue 26 item 10): a
 * symlink swapped in after a check fails the open rather than redirecting
 * the write. A recovery file is offered only when strictly newer than the
 * preset by the nanosecond timestamps (seconds let one up to 1 s older
 * than an outside save through, and restoring it reverted that save). */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/tools/outfile.h"
#include "acbb/tools/scene_edit.h"
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

/* mkdir -p of the base (XDG_STATE_HOME or ~/.local/state: the user's own
 * setting; mode 0700 for what is made). */
static void make_base(const char *path)
{
    char buf[PATH_MAX];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0700) != 0 && errno != EEXIST) return;
        *p = '/';
    }
    (void)mkdir(buf, 0700);
}

/* openat of one component, never through a symlink. */
static int open_comp(int at, const char *name)
{
    int fd = openat(at, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (at >= 0) close(at);
    return fd;
}

/* The recovery directory's descriptor, or -1 with `why`: the base resolved
 * (realpath), then walked from "/" component by component, then "acbb"
 * and "recover" below it (made 0700 when `create`), each ours and
 * writable by no one else. */
static int open_state_dir(int create, char *why, size_t wn)
{
    char dir[PATH_MAX], base[PATH_MAX], real[PATH_MAX];
    if (state_dir(dir, sizeof dir) != 0) {
        snprintf(why, wn, "no state directory (set HOME or XDG_STATE_HOME)");
        return -1;
    }
    snprintf(base, sizeof base, "%.*s", (int)(strlen(dir) - strlen("/acbb/recover")), dir);
    if (create) make_base(base);
    if (!realpath(base, real)) {
        snprintf(why, wn, "cannot make %s: %s", dir, strerror(errno));
        return -1;
    }
    int fd = open("/", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    for (char *c = strtok(real, "/"); c && fd >= 0; c = strtok(NULL, "/")) fd = open_comp(fd, c);
    static const char *const own[2] = { "acbb", "recover" };
    for (int k = 0; k < 2 && fd >= 0; k++) {
        struct stat st;
        if (create && mkdirat(fd, own[k], 0700) != 0 && errno != EEXIST) {
            int en = errno;
            close(fd);
            fd = -1;
            errno = en;
            break;
        }
        if ((fd = open_comp(fd, own[k])) < 0) break;
        if (fstat(fd, &st) != 0 || !trusted(&st)) {
            close(fd);
            snprintf(why, wn, "%s is not a directory of yours that only you may write (fix "
                     "it: chmod 700, or set XDG_STATE_HOME)", dir);
            return -1;
        }
    }
    if (fd < 0 && why[0] == '\0')
        snprintf(why, wn, "cannot open %s: %s%s", dir, strerror(errno),
                 errno == ELOOP || errno == ENOTDIR ? " (a symbolic link in its path is not "
                 "followed)" : "");
    return fd;
}

/* The recovery file's name inside the directory. */
static const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* Write the scene to a fresh temp (O_EXCL, no symlink followed) inside
 * the directory `dfd`, then rename it to `name` there. */
static int write_file(const acbb_editor *e, int dfd, const char *path, char *why, size_t wn)
{
    char tmp[64];
    snprintf(tmp, sizeof tmp, ".recover-%ld.tmp", (long)getpid());
    unlinkat(dfd, tmp, 0); /* our own leftover: the name carries our pid */
    int fd = openat(dfd, tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        snprintf(why, wn, "cannot create %s beside %s: %s", tmp, path, strerror(errno));
        if (fd >= 0) close(fd);
        return -1;
    }
    acbb_error err = { { 0 } };
    int bad = acbb_scene_write(f, &e->scene, &err) != ACBB_OK || fsync(fd) != 0;
    bad |= fclose(f) != 0;
    if (bad || renameat(dfd, tmp, dfd, file_name(path)) != 0) {
        snprintf(why, wn, "cannot write %s: %s", path, err.msg[0] ? err.msg : strerror(errno));
        unlinkat(dfd, tmp, 0);
        return -1;
    }
    return 0;
}

int acbb_recover_write(const acbb_editor *e, char *why, size_t wn)
{
    char path[PATH_MAX];
    why[0] = '\0';
    /* Undone back to the file: an older recovery file is stale now. */
    if (!e->modified) {
        acbb_recover_clear(e);
        return 0;
    }
    if (acbb_recover_path(e, path, sizeof path) != 0) {
        snprintf(why, wn, "no state directory (set HOME or XDG_STATE_HOME)");
        return -1;
    }
    int dfd = open_state_dir(1, why, wn);
    if (dfd < 0) return -1;
    int rc = write_file(e, dfd, path, why, wn);
    close(dfd);
    return rc;
}

void acbb_recover_clear(const acbb_editor *e)
{
    char path[PATH_MAX], why[8] = "";
    int dfd = acbb_recover_path(e, path, sizeof path) == 0 ? open_state_dir(0, why, 0) : -1;
    if (dfd < 0) return;
    unlinkat(dfd, file_name(path), 0);
    close(dfd);
}

/* a later than b */
static int newer(const struct timespec *a, const struct timespec *b)
{
    return a->tv_sec != b->tv_sec ? a->tv_sec > b->tv_sec : a->tv_nsec > b->tv_nsec;
}

int acbb_recover_pending(const acbb_editor *e, char *out, size_t n)
{
    struct stat r, p;
    char why[8] = "";
    if (acbb_recover_path(e, out, n) != 0) return 0;
    /* Only from a trusted directory, only a regular file of ours (a planted
     * file or symlink is never offered). */
    int dfd = open_state_dir(0, why, 0);
    if (dfd < 0) return 0;
    int ok = fstatat(dfd, file_name(out), &r, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(r.st_mode) &&
             trusted(&r);
    close(dfd);
    if (!ok) return 0;
    /* A preset saved after the recovery file was written supersedes it. */
    return !e->path[0] || stat(e->path, &p) != 0 || newer(&r.st_mtim, &p.st_mtim);
}

/* The recovery file's text through the directory's descriptor (malloc'd). */
static char *read_file(const char *path, char *err, size_t n)
{
    int dfd = open_state_dir(0, err, n);
    int fd = dfd >= 0 ? openat(dfd, file_name(path), O_RDONLY | O_NOFOLLOW | O_CLOEXEC) : -1;
    if (dfd >= 0) close(dfd);
    struct stat st;
    char *text = NULL;
    if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && trusted(&st) &&
        (text = calloc(1, (size_t)st.st_size + 1)) != NULL) {
        size_t got = 0;
        for (ssize_t r = 1; r > 0 && got < (size_t)st.st_size; got += r > 0 ? (size_t)r : 0)
            r = read(fd, text + got, (size_t)st.st_size - got);
    }
    if (!text && err[0] == '\0') snprintf(err, n, "cannot read %s", path);
    if (fd >= 0) close(fd);
    return text;
}

int acbb_recover_restore(acbb_editor *e, const char *path, char *err, size_t n)
{
    acbb_scene s;
    acbb_error er = { { 0 } };
    err[0] = '\0';
    char *text = read_file(path, err, n);
    if (!text) return -1;
    acbb_status st = acbb_scene_load_text(text, &s, &er);
    free(text);
    if (st != ACBB_OK) {
        snprintf(err, n, "%s", er.msg);
        return -1;
    }
    acbb_editor_replace(e, &s);
    return 0;
}
