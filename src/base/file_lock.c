/* acbb — read-modify-write without lost edits (outfile.h: acbb_file_lock,
 * acbb_file_stamp; issue 20 items 1-2).
 *
 * The lock is flock(2) on the preset file itself, so no lock file is left
 * behind. A save replaces the file by rename (outfile.c): a waiter may
 * then hold the lock on the old, unlinked inode. So after flock succeeds
 * the path is stat'ed again and the lock is retaken until the locked inode
 * is the one the path names (the usual idiom for rename-replaced files).
 * Waiting polls LOCK_NB every 10 ms up to the caller's timeout, so a hung
 * holder gives an error, never a hang. Only regular files are locked: a
 * FIFO or a device has no content to lose.
 *
 * The content hash is FNV-1a 64 (Fowler, Noll, Vo; public domain), hand
 * written: none of the project's libraries (GSL, inih, cJSON) offers a
 * hash, and it only has to tell two versions of a few-kB file apart. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "acbb/tools/outfile.h"

#define LOCK_POLL_NS 10000000L /* 10 ms */

struct acbb_file_lock {
    int fd; /* -1: nothing to lock (no file yet, or not a regular file) */
};

uint64_t acbb_hash64(const void *data, size_t n, uint64_t h)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 1099511628211ULL; /* FNV-1a 64 prime */
    }
    return h;
}

static int same_inode(const struct stat *a, const struct stat *b)
{
    return a->st_dev == b->st_dev && a->st_ino == b->st_ino;
}

/* Try once: 1 locked (the inode the path names now), 0 busy or stale,
 * -1 error (errno). */
static int try_lock(const char *path, int *fd)
{
    *fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (*fd < 0) return -1;
    struct stat held, now;
    if (flock(*fd, LOCK_EX | LOCK_NB) != 0) {
        int en = errno;
        close(*fd);
        *fd = -1;
        errno = en;
        return en == EWOULDBLOCK ? 0 : -1;
    }
    if (fstat(*fd, &held) == 0 && stat(path, &now) == 0 && same_inode(&held, &now)) return 1;
    close(*fd); /* replaced while we waited: lock the new one */
    *fd = -1;
    return 0;
}

acbb_status acbb_file_lock_take(const char *path, double timeout_s, acbb_file_lock **out,
                                acbb_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    (*out)->fd = -1;
    struct timespec poll = { 0, LOCK_POLL_NS };
    for (double waited = 0;; waited += 1e-9 * LOCK_POLL_NS) {
        struct stat st;
        if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) return ACBB_OK;
        int r = try_lock(path, &(*out)->fd);
        if (r == 1) return ACBB_OK;
        if (r < 0 && errno != ENOENT) {
            int en = errno;
            free(*out);
            *out = NULL;
            return acbb_error_set(err, ACBB_EIO, "%s: cannot lock: %s", path, strerror(en));
        }
        if (waited >= timeout_s) break;
        nanosleep(&poll, NULL);
    }
    free(*out);
    *out = NULL;
    return acbb_error_set(err, ACBB_EIO, "%s: not saved: another program holds its lock "
                          "(still locked after %.0f s)", path, timeout_s);
}

void acbb_file_lock_release(acbb_file_lock *l)
{
    if (!l) return;
    if (l->fd >= 0) close(l->fd); /* closing the descriptor drops the flock */
    free(l);
}

/* FNV-1a of the whole file; -1 with errno on a read error. */
static int hash_file(int fd, uint64_t *h)
{
    char buf[8192];
    *h = ACBB_HASH64_SEED;
    for (;;) {
        ssize_t n = read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return -1;
        if (n == 0) return 0;
        *h = acbb_hash64(buf, (size_t)n, *h);
    }
}

acbb_status acbb_file_stamp_take(const char *path, acbb_file_stamp *s, acbb_error *err)
{
    memset(s, 0, sizeof *s);
    struct stat st;
    if (stat(path, &st) != 0) {
        if (errno == ENOENT) return ACBB_OK; /* exists = 0 */
        return acbb_error_set(err, ACBB_EIO, "%s: %s", path, strerror(errno));
    }
    s->exists = 1;
    s->regular = S_ISREG(st.st_mode);
    s->size = (long long)st.st_size;
    s->mtime_ns = (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec;
    if (!s->regular) return ACBB_OK; /* a FIFO is not read here: it would block */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    int bad = fd < 0 || hash_file(fd, &s->hash) != 0;
    int en = errno;
    if (fd >= 0) close(fd);
    return bad ? acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(en))
               : ACBB_OK;
}

int acbb_file_stamp_changed(const acbb_file_stamp *was, const acbb_file_stamp *now)
{
    if (was->exists != now->exists || was->regular != now->regular) return 1;
    if (!was->regular) return 0;
    return was->size != now->size || was->hash != now->hash;
}
