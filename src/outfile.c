/* acbb — atomic, non-destructive output files (outfile.h). */
#include <errno.h>
#include <fcntl.h>
#include <libgen.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/outfile.h"

struct acbb_out {
    char *target;      /* resolved path (symlinks followed) */
    char *tmp;         /* temporary file, NULL when written directly */
    FILE *f;
    int direct;        /* 1: write into the target itself (non-regular, stdout) */
    int is_stdout;
    int existed;
    struct stat st;    /* of the existing target */
};

/* Follow a symlink chain to the file it names; a dangling link's target
 * is created. Returns a malloc'd path. */
static char *resolve(const char *path)
{
    char *cur = strdup(path);
    for (int depth = 0; cur && depth < 40; depth++) {
        struct stat ls;
        if (lstat(cur, &ls) != 0 || !S_ISLNK(ls.st_mode)) return cur;
        char buf[PATH_MAX];
        ssize_t n = readlink(cur, buf, sizeof buf - 1);
        if (n < 0) return cur;
        buf[n] = '\0';
        char *next;
        if (buf[0] == '/') {
            next = strdup(buf);
        } else {
            char *copy = strdup(cur);
            if (!copy) { free(cur); return NULL; }
            const char *dir = dirname(copy);
            size_t len = strlen(dir) + strlen(buf) + 2;
            next = malloc(len);
            if (next) snprintf(next, len, "%s/%s", dir, buf);
            free(copy);
        }
        free(cur);
        cur = next;
    }
    return cur;
}

static acbb_status open_temp(acbb_out *o, acbb_error *err)
{
    /* A hidden name beside the target: the same file system for rename. */
    char *copy = strdup(o->target), *copy2 = strdup(o->target);
    if (!copy || !copy2) {
        free(copy); free(copy2);
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    }
    const char *dir = dirname(copy), *base = basename(copy2);
    size_t len = strlen(dir) + strlen(base) + 32;
    o->tmp = malloc(len);
    if (o->tmp) snprintf(o->tmp, len, "%s/.%s.acbb-XXXXXX", dir, base);
    free(copy); free(copy2);
    if (!o->tmp) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        int en = errno;
        free(o->tmp);
        o->tmp = NULL;
        return acbb_error_set(err, ACBB_EIO, "cannot write %s: cannot create a temporary file beside it: %s",
                              o->target, strerror(en));
    }
    mode_t mode;
    if (o->existed) {
        mode = o->st.st_mode & 07777;
        /* Keep the owner where we may (root replacing a user's file). */
        if (fchown(fd, o->st.st_uid, o->st.st_gid) != 0) { /* not ours to keep */ }
    } else {
        mode_t um = umask(022);
        umask(um);
        mode = 0666 & ~um;
    }
    (void)fchmod(fd, mode);
    o->f = fdopen(fd, "w");
    if (!o->f) {
        close(fd);
        unlink(o->tmp);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot open: %s", o->target, strerror(errno));
    }
    return ACBB_OK;
}

static void release(acbb_out *o)
{
    free(o->target);
    free(o->tmp);
    free(o);
}

acbb_status acbb_out_open(const char *path, acbb_out **out, FILE **f, acbb_error *err)
{
    *out = NULL;
    if (f) *f = NULL;
    if (!path || !path[0])
        return acbb_error_set(err, ACBB_EINVAL, "output path is empty");
    acbb_out *o = calloc(1, sizeof *o);
    if (!o) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    if (strcmp(path, "-") == 0) {
        o->is_stdout = o->direct = 1;
        o->target = strdup("standard output");
        o->f = stdout;
    } else {
        o->target = resolve(path);
        if (!o->target) { release(o); return acbb_error_set(err, ACBB_ENOMEM, "out of memory"); }
        o->existed = stat(o->target, &o->st) == 0;
        if (o->existed && S_ISDIR(o->st.st_mode)) {
            release(o);
            return acbb_error_set(err, ACBB_EIO, "%s: is a directory", path);
        }
        if (o->existed && access(o->target, W_OK) != 0) {
            int en = errno;
            release(o);
            return acbb_error_set(err, ACBB_EIO, "%s: not writable: %s", path, strerror(en));
        }
        o->direct = o->existed && !S_ISREG(o->st.st_mode);
        acbb_status rc = ACBB_OK;
        if (o->direct && f) {
            o->f = fopen(o->target, "w");
            if (!o->f) rc = acbb_error_set(err, ACBB_EIO, "%s: cannot open: %s", path, strerror(errno));
            else if (f) { *f = o->f; *out = o; return ACBB_OK; }
        }
        if (rc == ACBB_OK) rc = open_temp(o, err);
        if (rc != ACBB_OK) { release(o); return rc; }
    }
    *out = o;
    if (f) *f = o->f;
    return ACBB_OK;
}

const char *acbb_out_temp_path(const acbb_out *o)
{
    return o->tmp;
}

static void sync_dir(const char *path)
{
    char *copy = strdup(path);
    if (!copy) return;
    int fd = open(dirname(copy), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
    free(copy);
}

/* A non-regular target written by an external program: copy the bytes in. */
static int copy_into(const char *from, const char *to)
{
    FILE *in = fopen(from, "rb"), *out = in ? fopen(to, "wb") : NULL;
    char buf[65536];
    size_t n;
    int bad = !in || !out;
    while (!bad && (n = fread(buf, 1, sizeof buf, in)) > 0)
        bad = fwrite(buf, 1, n, out) != n;
    if (in) fclose(in);
    if (out && fclose(out) != 0) bad = 1;
    return bad ? -1 : 0;
}

acbb_status acbb_out_commit(acbb_out *o, acbb_error *err)
{
    int bad = 0, en = 0;
    if (o->f) {
        bad = fflush(o->f) != 0 || ferror(o->f);
        if (!bad && !o->direct && fsync(fileno(o->f)) != 0) bad = 1;
        en = bad ? (errno ? errno : EIO) : 0;
        if (!o->is_stdout && fclose(o->f) != 0 && !bad) bad = 1, en = errno;
        o->f = NULL;
    }
    if (!bad && o->tmp) {
        if (o->direct) {
            if (copy_into(o->tmp, o->target) != 0) bad = 1, en = errno ? errno : EIO;
            unlink(o->tmp);
        } else if (rename(o->tmp, o->target) != 0) {
            bad = 1, en = errno;
        } else {
            sync_dir(o->target);
        }
    }
    acbb_status rc = ACBB_OK;
    if (bad) {
        if (o->tmp) unlink(o->tmp);
        rc = acbb_error_set(err, ACBB_EIO, "cannot write %s: %s", o->target, strerror(en));
    }
    release(o);
    return rc;
}

void acbb_out_abort(acbb_out *o)
{
    if (!o) return;
    if (o->f && !o->is_stdout) fclose(o->f);
    if (o->tmp) unlink(o->tmp);
    release(o);
}
