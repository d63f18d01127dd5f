/* acbb — running gnuplot (plot_priv.h): the script fed on stdin of a
 * process started with posix_spawnp (never a shell or popen: popen of a
 * missing program only fails when written to, and a shell would see user
 * text), its stdin, stdout and stderr made with pipe2(O_CLOEXEC) so no
 * other thread's fork inherits them, all three serviced together with
 * poll() (a gnuplot blocked on a full pipe would never finish reading its
 * script), killed when hung. Split from plot.c, which builds the scripts.
 * Nothing here prints. */
#define _GNU_SOURCE /* pipe2 */
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "acbb/tools/plot.h"
#include "plot_priv.h"

extern char **environ;

/* gnuplot renders a few thousand points in well under a second; a process
 * still alive after this long is hung (e.g. a wrong ACBB_GNUPLOT that waits
 * on a terminal) and is killed rather than blocking the caller forever. */
#define PLOT_TIMEOUT_MS 60000

/* ---- running gnuplot ---- */

/* gp_io: plot_priv.h */

static void close_fd(int *fd)
{
    if (*fd >= 0) close(*fd);
    *fd = -1;
}

/* Append what `fd` has to `buf` (keeping at most cap-1 bytes, NUL-terminated;
 * the rest is read and dropped so gnuplot never blocks on a full pipe).
 * Closes fd at end of file or on error. */
static void drain(int *fd, char *buf, size_t cap, size_t *len)
{
    char chunk[4096];
    ssize_t r = read(*fd, chunk, sizeof chunk);
    if (r < 0 && (errno == EINTR || errno == EAGAIN)) return;
    if (r <= 0) {
        close_fd(fd);
        return;
    }
    if (buf && cap > 0) {
        size_t take = (size_t)r;
        if (take > cap - 1 - *len) take = cap - 1 - *len;
        memcpy(buf + *len, chunk, take);
        *len += take;
        buf[*len] = '\0';
    }
}

static long ms_since(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long)(t.tv_sec - t0->tv_sec) * 1000L + (t.tv_nsec - t0->tv_nsec) / 1000000L;
}

/* Feed the script and collect stdout/stderr until gnuplot closes them.
 * Returns false on timeout. *broken is set when gnuplot stopped reading. */
static bool pump(int fd_in, int fd_out, int fd_err, const sbuf *script, gp_io *io,
                 bool *broken)
{
    size_t sent = 0;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    *broken = false;
    while (fd_in >= 0 || fd_out >= 0 || fd_err >= 0) {
        struct pollfd p[3] = { { fd_in, POLLOUT, 0 }, { fd_out, POLLIN, 0 },
                               { fd_err, POLLIN, 0 } };
        long left = PLOT_TIMEOUT_MS - ms_since(&t0);
        if (left <= 0) break;
        /* poll ignores negative fds, so closed streams simply drop out. */
        int r = poll(p, 3, (int)left);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) break;
        if (p[0].revents) {
            ssize_t w = write(fd_in, script->p + sent, script->n - sent);
            if (w > 0) sent += (size_t)w;
            else if (w < 0 && errno != EAGAIN && errno != EINTR) *broken = true;
            /* EOF on stdin also ends gnuplot if the script somehow did not. */
            if (*broken || sent == script->n) close_fd(&fd_in);
        }
        if (p[1].revents) drain(&fd_out, io->out, io->out_cap, &io->out_len);
        if (p[2].revents) drain(&fd_err, io->err, sizeof io->err, &io->err_len);
    }
    bool done = fd_in < 0 && fd_out < 0 && fd_err < 0;
    close_fd(&fd_in);
    close_fd(&fd_out);
    close_fd(&fd_err);
    return done;
}

/* True if [s, e) looks like gnuplot's `line N: message` and is no warning. */
static bool is_error_line(const char *s, const char *e)
{
    for (const char *m = s; m + 6 <= e; m++) {
        if (strncmp(m, "line ", 5) != 0 || m[5] < '0' || m[5] > '9') continue;
        const char *c = m + 5 + strspn(m + 5, "0123456789");
        if (c >= e || *c != ':') continue;
        const char *w = strstr(c, "warning:");
        return !w || w >= e;
    }
    return false;
}

/* The line of gnuplot's stderr that says what went wrong: gnuplot echoes
 * the offending command and a caret line before `line N: message` (and
 * may print warnings first), so the first such line that is not a warning
 * is preferred, then the first line with any text. */
static void first_error_line(const char *text, char *out, size_t n)
{
    const char *fallback = NULL, *fallback_end = NULL;
    for (const char *l = text; *l;) {
        const char *e = l + strcspn(l, "\n");
        const char *s = l + strspn(l, " \t\r^");
        if (s < e && is_error_line(s, e)) {
            snprintf(out, n, "%.*s", (int)(e - s), s);
            return;
        }
        if (s < e && !fallback) {
            fallback = s;
            fallback_end = e;
        }
        l = *e ? e + 1 : e;
    }
    if (fallback) snprintf(out, n, "%.*s", (int)(fallback_end - fallback), fallback);
    else out[0] = '\0';
}

static acbb_status spawn_error(int rc, const char *prog, acbb_error *err)
{
    if (rc == ENOENT) {
        if (strcmp(prog, "gnuplot") == 0)
            return acbb_error_set(err, ACBB_EIO, "gnuplot not found on PATH (install gnuplot-nox)");
        return acbb_error_set(err, ACBB_EIO, "gnuplot program '%s' (ACBB_GNUPLOT) not found",
                              prog);
    }
    return acbb_error_set(err, ACBB_EIO, "cannot run %s: %s", prog, strerror(rc));
}

static acbb_status exit_error(int wstatus, bool timed_out, const gp_io *io, acbb_error *err)
{
    char line[256];
    first_error_line(io->err, line, sizeof line);
    if (timed_out)
        return acbb_error_set(err, ACBB_EIO, "gnuplot failed: no answer after %d s",
                              PLOT_TIMEOUT_MS / 1000);
    if (line[0]) return acbb_error_set(err, ACBB_EIO, "gnuplot failed: %s", line);
    /* Where posix_spawnp is fork + exec (some libcs, valgrind), a missing
     * program shows up as the child's exit 127 rather than ENOENT. */
    if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 127 && !io->err[0])
        return acbb_error_set(err, ACBB_EIO, "gnuplot not found on PATH (install gnuplot-nox)");
    if (WIFSIGNALED(wstatus))
        return acbb_error_set(err, ACBB_EIO, "gnuplot failed: killed by signal %d",
                              WTERMSIG(wstatus));
    return acbb_error_set(err, ACBB_EIO, "gnuplot failed: exit status %d",
                          WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
}

/* Start gnuplot with the three pipes (stdout to /dev/null unless captured). */
static acbb_status spawn(const char *prog, int in[2], int out[2], int errp[2], pid_t *pid,
                         const gp_io *io, acbb_error *err)
{
    posix_spawn_file_actions_t fa;
    int rc = posix_spawn_file_actions_init(&fa);
    if (rc) return acbb_error_set(err, ACBB_ENOMEM, "cannot start gnuplot: %s", strerror(rc));
    /* dup2 clears FD_CLOEXEC on the copies; the CLOEXEC originals vanish at exec. */
    rc = posix_spawn_file_actions_adddup2(&fa, in[0], STDIN_FILENO);
    if (!rc && out[1] >= 0) rc = posix_spawn_file_actions_adddup2(&fa, out[1], STDOUT_FILENO);
    else if (!rc && io->to_file)
        rc = posix_spawn_file_actions_adddup2(&fa, io->file_fd, STDOUT_FILENO);
    else if (!rc)
        rc = posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    if (!rc) rc = posix_spawn_file_actions_adddup2(&fa, errp[1], STDERR_FILENO);
    for (int k = 0; !rc && k < io->n_extra; k++)
        rc = posix_spawn_file_actions_adddup2(&fa, io->extra[k], 3 + k);
    char *argv[] = { (char *)prog, NULL };
    if (!rc) rc = posix_spawnp(pid, prog, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    return rc ? spawn_error(rc, prog, err) : ACBB_OK;
}

/* SIGPIPE (gnuplot exiting before it read the whole script) must not kill
 * the caller. The signal is blocked in this thread only, rather than set to
 * SIG_IGN process-wide and restored: a disposition is shared by all
 * threads, so two concurrent exports (or an export racing the TUI) could
 * restore each other's saved action in the wrong order. A SIGPIPE raised by
 * our write is thread-directed; it is consumed before the mask is restored,
 * so nothing is left changed. */
static void sigpipe_block(sigset_t *old)
{
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &s, old);
}

static void sigpipe_restore(const sigset_t *old, bool raised)
{
    if (raised && !sigismember(old, SIGPIPE)) {
        sigset_t s, pending;
        sigemptyset(&s);
        sigaddset(&s, SIGPIPE);
        if (sigpending(&pending) == 0 && sigismember(&pending, SIGPIPE)) {
            struct timespec zero = { 0, 0 };
            sigtimedwait(&s, NULL, &zero);
        }
    }
    pthread_sigmask(SIG_SETMASK, old, NULL);
}

acbb_status run_gnuplot(const sbuf *script, gp_io *io, acbb_error *err)
{
    int in[2] = { -1, -1 }, out[2] = { -1, -1 }, errp[2] = { -1, -1 };
    if (pipe2(in, O_CLOEXEC) || pipe2(errp, O_CLOEXEC) || (io->out && pipe2(out, O_CLOEXEC))) {
        int e = errno;
        for (int i = 0; i < 2; i++) {
            close_fd(&in[i]);
            close_fd(&out[i]);
            close_fd(&errp[i]);
        }
        return acbb_error_set(err, ACBB_EIO, "cannot create a pipe for gnuplot: %s",
                              strerror(e));
    }
    const char *prog = acbb_plot_program();
    pid_t pid = -1;
    acbb_status st = spawn(prog, in, out, errp, &pid, io, err);
    close_fd(&in[0]);
    close_fd(&out[1]);
    close_fd(&errp[1]);
    if (st != ACBB_OK) {
        close_fd(&in[1]);
        close_fd(&out[0]);
        close_fd(&errp[0]);
        return st;
    }
    /* Only the parent's end is non-blocking: gnuplot reads a normal pipe. */
    fcntl(in[1], F_SETFL, fcntl(in[1], F_GETFL) | O_NONBLOCK);
    sigset_t old;
    bool broken = false;
    sigpipe_block(&old);
    bool done = pump(in[1], out[0], errp[0], script, io, &broken);
    sigpipe_restore(&old, broken);
    if (!done) kill(pid, SIGKILL);
    int wstatus = 0;
    while (waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {}
    if (done && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0) return ACBB_OK;
    return exit_error(wstatus, !done, io, err);
}
