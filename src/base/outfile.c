#define _GNU_SOURCE /* O_TMPFILE, linkat AT_EMPTY_PATH (Linux) */
/* acbb — atomic, non-destructive output files (outfile.h).
 *
 * The temporary file is an unnamed O_TMPFILE inode in the target's
 * directory where the file system offers it: a kill before the commit
 * leaves nothing behind. It gets a name only at commit, just before the
 * rename: through /proc/self/fd, else linkat(AT_EMPTY_PATH) (no /proc;
 * needs CAP_DAC_READ_SEARCH on older kernels), else its bytes are copied
 * into a named temp (issue 16 item 5). Without O_TMPFILE a named temp
 * (.NAME.acbb-PID-N, O_EXCL) is used from the start. Both are created
 * with mode 0666, so the kernel applies the umask; only an existing
 * target's mode is set explicitly. */
#include <errno.h>
#include <fcntl.h>
#include <libgen.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "outfile_priv.h"

struct acbb_out {
    char *target;      /* resolved path (symlinks followed) */
    char *tmp;         /* the temporary file's name once it has one, else NULL */
    int fd;            /* the temporary file, or the target when direct; -1 none */
    FILE *f;
    unsigned flags;    /* ACBB_OUT_NO_* (outfile_priv.h) */
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

/* dir and base of the target as two malloc'd strings. */
static int split(const char *path, char **dir, char **base)
{
    char *a = strdup(path), *b = strdup(path);
    *dir = a ? strdup(dirname(a)) : NULL;
    *base = b ? strdup(basename(b)) : NULL;
    free(a);
    free(b);
    if (*dir && *base) return 0;
    free(*dir);
    free(*base);
    return -1;
}

/* An existing target's mode and owner go to the temp file; a new file
 * keeps the 0666 & ~umask it was created with. The owner only where we
 * may (root replacing a user's file). */
static void keep_mode(const acbb_out *o, int fd)
{
    if (!o->existed) return;
    (void)fchmod(fd, o->st.st_mode & 07777);
    if (fchown(fd, o->st.st_uid, o->st.st_gid) != 0) { /* not ours to keep */ }
}

/* A new named temp file beside the target (O_EXCL: never an existing
 * one); its name goes to o->tmp. -1 with errno on failure. */
static int named_temp(acbb_out *o, const char *dir, const char *base)
{
    size_t len = strlen(dir) + strlen(base) + 48;
    for (int attempt = 0; attempt < 100; attempt++) {
        free(o->tmp);
        if (!(o->tmp = malloc(len))) return -1;
        snprintf(o->tmp, len, "%s/.%s.acbb-%ld-%d", dir, base, (long)getpid(), attempt);
        int fd = open(o->tmp, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
        if (fd >= 0) return fd;
        if (errno != EEXIST) break;
    }
    int en = errno;
    free(o->tmp);
    o->tmp = NULL;
    errno = en;
    return -1;
}

static acbb_status open_temp(acbb_out *o, acbb_error *err)
{
    char *dir, *base;
    if (split(o->target, &dir, &base) != 0)
        return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    int fd = -1, no_tmpfile = (o->flags & ACBB_OUT_NO_TMPFILE) != 0;
    if (!no_tmpfile) fd = open(dir, O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
    if (fd < 0 && (no_tmpfile || (errno != ENOENT && errno != EACCES && errno != EROFS)))
        fd = named_temp(o, dir, base); /* no O_TMPFILE on this file system */
    int en = errno;
    free(dir);
    free(base);
    if (fd < 0)
        return acbb_error_set(err, ACBB_EIO, "cannot write %s: cannot create a temporary file "
                              "beside it: %s", o->target, strerror(en));
    keep_mode(o, fd);
    o->fd = fd;
    return ACBB_OK;
}

static void release(acbb_out *o)
{
    free(o->target);
    free(o->tmp);
    free(o);
}

static acbb_status open_target(acbb_out *o, const char *path, int want_stream, acbb_error *err)
{
    o->target = resolve(path);
    if (!o->target) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    o->existed = stat(o->target, &o->st) == 0;
    if (o->existed && S_ISDIR(o->st.st_mode))
        return acbb_error_set(err, ACBB_EIO, "cannot write %s: it is a directory", path);
    if (o->existed && access(o->target, W_OK) != 0)
        return acbb_error_set(err, ACBB_EIO, "cannot write %s: %s", path, strerror(errno));
    o->direct = o->existed && !S_ISREG(o->st.st_mode);
    if (o->direct && want_stream) {
        o->fd = acbb_out_open_special(o->target);
        if (o->fd < 0)
            return acbb_error_set(err, ACBB_EIO, "cannot write %s: %s", path,
                                  errno == ENXIO ? "a FIFO with no reader (start the reader "
                                  "first)" : strerror(errno));
        return ACBB_OK;
    }
    return open_temp(o, err);
}

acbb_status acbb_out_open(const char *path, acbb_out **out, FILE **f, acbb_error *err)
{
    return acbb_out_open_ex(path, 0, out, f, err);
}

acbb_status acbb_out_open_ex(const char *path, unsigned flags, acbb_out **out, FILE **f,
                             acbb_error *err)
{
    *out = NULL;
    if (f) *f = NULL;
    if (!path || !path[0]) return acbb_error_set(err, ACBB_EINVAL, "output path is empty");
    acbb_out *o = calloc(1, sizeof *o);
    if (!o) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    o->fd = -1;
    o->flags = flags;
    if (strcmp(path, "-") == 0) {
        o->is_stdout = o->direct = 1;
        o->target = strdup("standard output");
        o->f = stdout;
    } else {
        acbb_status rc = open_target(o, path, f != NULL, err);
        if (rc == ACBB_OK && f && !(o->f = fdopen(o->fd, "w")))
            rc = acbb_error_set(err, ACBB_EIO, "cannot write %s: %s", path, strerror(errno));
        if (rc != ACBB_OK) {
            if (o->fd >= 0) close(o->fd);
            if (o->tmp) unlink(o->tmp);
            release(o);
            return rc;
        }
        if (o->f) o->fd = -1; /* the stream owns it now */
    }
    *out = o;
    if (f) *f = o->f;
    return ACBB_OK;
}

int acbb_out_fd(const acbb_out *o)
{
    return o->f ? fileno(o->f) : o->fd;
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

/* Copy everything in `from` (from its start) to `out`. */
static int copy_fd(int from, int out)
{
    char buf[65536];
    if (lseek(from, 0, SEEK_SET) != 0) return -1;
    for (;;) {
        ssize_t n = read(from, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? -1 : 0;
        /* A FIFO or a signal may take the bytes in parts. */
        for (ssize_t off = 0; off < n;) {
            ssize_t w = write(out, buf + off, (size_t)(n - off));
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) return -1;
            off += w;
        }
    }
}

/* A FIFO opened for writing blocks until a reader comes, maybe forever
 * (issue 20 item 7): opened non-blocking, it fails at once with ENXIO when
 * none is there; then writes block again as a pipe's should. */
int acbb_out_open_special(const char *path)
{
    int fd = open(path, O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    int flags = fd >= 0 ? fcntl(fd, F_GETFL) : -1;
    if (flags >= 0) (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    return fd;
}

/* A non-regular target written by an external program: copy the bytes in. */
static int copy_into(int from, const char *to)
{
    int out = acbb_out_open_special(to);
    int bad = out < 0 || copy_fd(from, out) != 0;
    if (out >= 0 && close(out) != 0) bad = 1;
    return bad ? -1 : 0;
}

/* Give the unnamed file `fd` the name `name`: through /proc (any user),
 * else AT_EMPTY_PATH (ENOENT/EPERM where the kernel wants
 * CAP_DAC_READ_SEARCH). -1 with errno; EEXIST means "try another name". */
static int link_fd(int fd, const char *name, unsigned flags)
{
    int en = ENOTSUP;
    if (!(flags & ACBB_OUT_NO_PROC)) {
        char proc[64];
        snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd);
        if (linkat(AT_FDCWD, proc, AT_FDCWD, name, AT_SYMLINK_FOLLOW) == 0) return 0;
        if (errno == EEXIST) return -1;
        en = errno;
    }
    if (!(flags & ACBB_OUT_NO_EMPTY_PATH)) {
        if (linkat(fd, "", AT_FDCWD, name, AT_EMPTY_PATH) == 0) return 0;
        if (errno == EEXIST) return -1;
        en = errno;
    }
    errno = en;
    return -1;
}

/* The last resort for an unnamed temp no link can name: its bytes go to
 * a named temp (same mode rule), flushed. */
static int copy_to_named(acbb_out *o, int fd, const char *dir, const char *base)
{
    int t = named_temp(o, dir, base);
    if (t < 0) return -1;
    keep_mode(o, t);
    int bad = copy_fd(fd, t) != 0 || fsync(t) != 0;
    int en = errno;
    if (close(t) != 0) bad = 1;
    errno = bad ? en : 0;
    return bad ? -1 : 0;
}

/* Name the unnamed temporary file beside the target (o->tmp). */
static int name_temp(acbb_out *o, int fd)
{
    char *dir, *base;
    if (split(o->target, &dir, &base) != 0) return -1;
    size_t len = strlen(dir) + strlen(base) + 48;
    int rc = -1;
    for (int attempt = 0; attempt < 100; attempt++) {
        free(o->tmp);
        if (!(o->tmp = malloc(len))) break;
        snprintf(o->tmp, len, "%s/.%s.acbb-%ld-%d", dir, base, (long)getpid(), attempt);
        if ((rc = link_fd(fd, o->tmp, o->flags)) == 0 || errno != EEXIST) break;
    }
    if (rc != 0) {
        free(o->tmp);
        o->tmp = NULL;
        rc = copy_to_named(o, fd, dir, base);
    }
    free(dir);
    free(base);
    return rc;
}

/* Name the temporary file if it has no name yet and rename it over the
 * target. */
static int link_and_rename(acbb_out *o, int fd)
{
    if (!o->tmp && name_temp(o, fd) != 0) return -1;
    return rename(o->tmp, o->target);
}

acbb_status acbb_out_commit(acbb_out *o, acbb_error *err)
{
    int bad = 0, en = 0, fd = acbb_out_fd(o);
    if (o->f) bad = fflush(o->f) != 0 || ferror(o->f);
    if (!bad && !o->direct && fd >= 0 && fsync(fd) != 0) bad = 1;
    en = bad ? (errno ? errno : EIO) : 0;
    if (!bad && !o->is_stdout && !o->direct) {
        if (link_and_rename(o, fd) != 0) bad = 1, en = errno ? errno : EIO;
        else sync_dir(o->target);
    } else if (!bad && o->direct && !o->f && fd >= 0) {
        if (copy_into(fd, o->target) != 0) bad = 1, en = errno ? errno : EIO;
    }
    if (o->f && !o->is_stdout && fclose(o->f) != 0 && !bad) bad = 1, en = errno;
    if (!o->f && fd >= 0) close(fd);
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
    else if (!o->f && o->fd >= 0) close(o->fd);
    if (o->tmp) unlink(o->tmp);
    release(o);
}
