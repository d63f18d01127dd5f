/* The atomic writer (include/acbb/tools/outfile.h, issue 16 item 5): every way of
 * naming the temporary file (/proc, linkat AT_EMPTY_PATH, a copy into a
 * named temp, a named temp from the start) gives the same file, with mode
 * 0666 & ~umask when new and the old mode when rewritten, and leaves no
 * temporary file after commit or abort. The ways are forced through the
 * internal flags (src/base/outfile_priv.h); once more in a child whose mount
 * namespace has no /proc at all (unshare; skipped where not permitted). */
#define _GNU_SOURCE /* unshare, CLONE_NEWNS */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tap.h"
#include "outfile_priv.h"

static char dir[64];

static void path_of(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

/* The directory's entries other than . and .., sorted into one
 * space-separated string (a small directory). */
static const char *listing(void)
{
    static char out[1024];
    char names[32][256];
    int n = 0;
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)) && n < 32)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            snprintf(names[n++], sizeof names[0], "%s", e->d_name);
    if (d) closedir(d);
    qsort(names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    out[0] = '\0';
    for (int i = 0; i < n; i++) {
        strncat(out, i ? " " : "", sizeof out - strlen(out) - 1);
        strncat(out, names[i], sizeof out - strlen(out) - 1);
    }
    return out;
}

static int file_is(const char *path, const char *want)
{
    char buf[256] = { 0 };
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    return n == strlen(want) && memcmp(buf, want, n) == 0;
}

static unsigned mode_of(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (unsigned)(st.st_mode & 07777) : 0u;
}

/* Write `text` to dir/name with `flags` through a stream and commit.
 * *during receives the listing while the file is open. */
static acbb_status write_one(const char *name, unsigned flags, const char *text, char *during,
                             size_t n, acbb_error *err)
{
    char path[128];
    path_of(path, sizeof path, name);
    acbb_out *o = NULL;
    FILE *f = NULL;
    acbb_status rc = acbb_out_open_ex(path, flags, &o, &f, err);
    if (rc != ACBB_OK) return rc;
    fputs(text, f);
    snprintf(during, n, "%s", listing());
    return acbb_out_commit(o, err);
}

typedef struct {
    unsigned flags;
    const char *way;
    int named_while_open; /* the temp has a name before the commit */
} way;

static const way ways[] = {
    { 0, "/proc link", 0 },
    { ACBB_OUT_NO_PROC, "AT_EMPTY_PATH link (no /proc)", 0 },
    { ACBB_OUT_NO_PROC | ACBB_OUT_NO_EMPTY_PATH, "copy into a named temp (no link)", 0 },
    { ACBB_OUT_NO_TMPFILE, "named temp from the start (no O_TMPFILE)", 1 },
};

static void test_way(const way *w, mode_t mask)
{
    acbb_error err = { { 0 } };
    char path[128], during[1024], want[64];
    umask(mask);
    unsigned new_mode = 0666u & ~(unsigned)mask;

    /* A new file. */
    snprintf(want, sizeof want, "new %s\n", w->way);
    acbb_status rc = write_one("new.txt", w->flags, want, during, sizeof during, &err);
    path_of(path, sizeof path, "new.txt");
    ok(rc == ACBB_OK && file_is(path, want), "%s, umask %03o: new file written (%s)", w->way,
       (unsigned)mask, err.msg);
    ok(mode_of(path) == new_mode, "%s, umask %03o: new file mode %03o (want 0666 & ~umask = %03o)",
       w->way, (unsigned)mask, mode_of(path), new_mode);
    int as_named = strncmp(during, ".new.txt.acbb-", 14) == 0 && !strchr(during, ' ');
    ok(w->named_while_open ? as_named : during[0] == '\0',
       "%s: while open the directory holds [%s] (%s)", w->way, during,
       w->named_while_open ? "one named temp" : "nothing: the temp is unnamed");
    ok(strcmp(listing(), "new.txt") == 0, "%s: after commit only new.txt is left [%s]", w->way, listing());

    /* An existing file keeps its own mode (0640 whatever the umask). */
    chmod(path, 0640);
    snprintf(want, sizeof want, "again %s\n", w->way);
    rc = write_one("new.txt", w->flags, want, during, sizeof during, &err);
    ok(rc == ACBB_OK && file_is(path, want) && mode_of(path) == 0640,
       "%s, umask %03o: rewritten file keeps mode 0640 (got %03o)", w->way, (unsigned)mask, mode_of(path));

    /* Abort: the old content stays, no temp file. */
    acbb_out *o = NULL;
    FILE *f = NULL;
    rc = acbb_out_open_ex(path, w->flags, &o, &f, &err);
    if (rc == ACBB_OK) {
        fputs("never\n", f);
        acbb_out_abort(o);
    }
    ok(rc == ACBB_OK && file_is(path, want) && strcmp(listing(), "new.txt") == 0,
       "%s: abort keeps the old content and leaves [%s]", w->way, listing());

    /* An external writer (no stream, the descriptor only). */
    char ext[128];
    path_of(ext, sizeof ext, "ext.dat");
    rc = acbb_out_open_ex(ext, w->flags, &o, NULL, &err);
    int wrote = rc == ACBB_OK && write(acbb_out_fd(o), "bytes\n", 6) == 6;
    rc = rc == ACBB_OK ? acbb_out_commit(o, &err) : rc;
    ok(wrote && rc == ACBB_OK && file_is(ext, "bytes\n") && mode_of(ext) == new_mode,
       "%s: an external writer's bytes land with mode %03o (%s)", w->way, mode_of(ext), err.msg);
    unlink(ext);
    unlink(path);
}

/* ---- no /proc at all: a child in its own mount namespace ---- */

enum { NOPROC_OK = 0, NOPROC_FAIL = 1, NOPROC_SKIP = 77 };

static int child_without_proc(unsigned flags)
{
    if (unshare(CLONE_NEWNS) != 0) return NOPROC_SKIP;
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0) return NOPROC_SKIP;
    if (umount2("/proc", MNT_DETACH) != 0 && errno != EINVAL) return NOPROC_SKIP;
    if (access("/proc/self/fd", F_OK) == 0) return NOPROC_SKIP;
    acbb_error err = { { 0 } };
    char path[128], during[1024];
    path_of(path, sizeof path, "noproc.txt");
    if (write_one("noproc.txt", flags, "no proc\n", during, sizeof during, &err) != ACBB_OK)
        return NOPROC_FAIL;
    return file_is(path, "no proc\n") && mode_of(path) == 0644 && strcmp(listing(), "noproc.txt") == 0
               ? NOPROC_OK
               : NOPROC_FAIL;
}

static void test_without_proc(unsigned flags, const char *what)
{
    umask(022);
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) _exit(child_without_proc(flags));
    int status = 0;
    int code = pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    char path[128];
    path_of(path, sizeof path, "noproc.txt");
    if (code == NOPROC_SKIP)
        skip("cannot unmount /proc here (unshare/mount not permitted)", "no /proc: %s", what);
    else
        ok(code == NOPROC_OK && file_is(path, "no proc\n"),
           "no /proc mounted: %s writes the file, mode 644, nothing else left (child %d)", what, code);
    unlink(path);
}

/* ACBB_OUT_NAME_MAX (outfile.h): the longest name every way writes, its
 * temporary ".NAME.acbb-PID-N" included; a name the file system takes but
 * the temporary's does not fails only at commit, after a run (issue 26
 * item 11): the CLI's output guard refuses it before. */
static void test_longest_name(void)
{
    static const size_t lens[2] = { ACBB_OUT_NAME_MAX, NAME_MAX - 5 };
    for (size_t l = 0; l < 2; l++) {
        char name[NAME_MAX + 1], path[NAME_MAX + 80];
        memset(name, 'n', lens[l]);
        name[lens[l]] = '\0';
        snprintf(path, sizeof path, "%s/%s", dir, name);
        for (size_t i = 0; i < sizeof ways / sizeof ways[0]; i++) {
            acbb_error err = { { 0 } };
            acbb_out *o = NULL;
            FILE *f = NULL;
            acbb_status rc = acbb_out_open_ex(path, ways[i].flags, &o, &f, &err);
            if (rc == ACBB_OK) {
                fputs("long\n", f);
                rc = acbb_out_commit(o, &err);
            }
            if (l == 0)
                ok(rc == ACBB_OK && file_is(path, "long\n"), "%s: a %zu-byte name (ACBB_OUT_NAME_MAX) "
                   "is written", ways[i].way, lens[l]);
            else
                ok(rc != ACBB_OK && access(path, F_OK) != 0, "%s: a %zu-byte name fails (its "
                   "temporary's name is too long): %s", ways[i].way, lens[l], err.msg);
            unlink(path);
        }
    }
}

int main(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/acbb-outfile-XXXXXX", base && strlen(base) < 30 ? base : "/tmp");
    if (!mkdtemp(dir)) {
        ok(0, "mkdtemp %s: %s", dir, strerror(errno));
        return done_testing();
    }
    const mode_t masks[] = { 022, 077 };
    for (size_t i = 0; i < sizeof ways / sizeof ways[0]; i++)
        for (size_t m = 0; m < 2; m++) test_way(&ways[i], masks[m]);

    test_without_proc(0, "the public acbb_out_open");
    test_without_proc(ACBB_OUT_NO_EMPTY_PATH, "the copy into a named temp");
    test_longest_name();

    /* A missing directory: a clear error naming the path, nothing created. */
    acbb_error err = { { 0 } };
    char bad[160];
    snprintf(bad, sizeof bad, "%s/no/such/x.txt", dir);
    for (size_t i = 0; i < sizeof ways / sizeof ways[0]; i++) {
        acbb_out *o = NULL;
        acbb_status rc = acbb_out_open_ex(bad, ways[i].flags, &o, NULL, &err);
        ok(rc == ACBB_EIO && o == NULL && strstr(err.msg, bad) && strstr(err.msg, "No such file"),
           "%s: missing directory refused: %s", ways[i].way, err.msg);
    }
    ok(strcmp(listing(), "") == 0, "the test directory is empty at the end [%s]", listing());
    rmdir(dir);
    return done_testing();
}
