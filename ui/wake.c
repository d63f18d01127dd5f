/* acbb TUI — wake-up pipe (see wake.h). */
#include <signal.h>
#include <fcntl.h>
#include <unistd.h>
#include "wake.h"

int acbb_wake_init(acbb_wake *w)
{
    int fd[2];
    if (pipe(fd) != 0) return -1;
    for (int i = 0; i < 2; i++) {
        int fl = fcntl(fd[i], F_GETFL);
        if (fl < 0 || fcntl(fd[i], F_SETFL, fl | O_NONBLOCK) < 0
            || fcntl(fd[i], F_SETFD, FD_CLOEXEC) < 0) {
            close(fd[0]);
            close(fd[1]);
            return -1;
        }
    }
    w->rd = fd[0];
    w->wr = fd[1];
    atomic_init(&w->pending, 0);
    return 0;
}

void acbb_wake_close(acbb_wake *w)
{
    close(w->rd);
    close(w->wr);
}

void acbb_wake_signal(acbb_wake *w)
{
    /* One byte is enough to wake select(); skip the write while one waits. */
    if (atomic_exchange(&w->pending, 1) == 0) {
        char b = 1;
        ssize_t r = write(w->wr, &b, 1);
        (void)r; /* EAGAIN means a byte is already there: also fine */
    }
}

void acbb_wake_drain(acbb_wake *w)
{
    char buf[64];
    /* Empty the pipe, then clear the flag. A publication between the two
     * skips its write but is seen by the read that follows the drain; any
     * later one writes a fresh byte. (Clearing first could lose a wake-up:
     * its byte would be drained while the flag stays set.) */
    while (read(w->rd, buf, sizeof buf) > 0) {}
    atomic_store(&w->pending, 0);
}

struct timespec acbb_wake_abstime(double at_ms)
{
    struct timespec ts;
    if (!(at_ms > 0.0)) at_ms = 0.0;
    ts.tv_sec = (time_t)(at_ms / 1e3);
    ts.tv_nsec = (long)((at_ms - 1e3 * (double)ts.tv_sec) * 1e6);
    if (ts.tv_nsec >= 1000000000L) { ts.tv_sec++; ts.tv_nsec -= 1000000000L; }
    if (ts.tv_nsec < 0) ts.tv_nsec = 0;
    return ts;
}

int acbb_thread_start(pthread_t *t, void *(*fn)(void *), void *arg)
{
    sigset_t block, old;
    sigemptyset(&block);
    int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGWINCH };
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) sigaddset(&block, sigs[i]);
    pthread_sigmask(SIG_BLOCK, &block, &old);
    int rc = pthread_create(t, NULL, fn, arg);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    return rc;
}
