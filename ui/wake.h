/* acbb TUI — a wake-up pipe for the UI's select() loop, written by a
 * background thread after each publication. At most one byte waits in the
 * pipe (an _Atomic flag skips writes while one is pending), so a fast
 * publisher never fills it. Ownership: the struct is embedded in its
 * owner; acbb_wake_init / acbb_wake_close pair. */
#ifndef ACBB_UI_WAKE_H
#define ACBB_UI_WAKE_H

#include <pthread.h>
#include <stdatomic.h>
#include <time.h>

typedef struct {
    int rd, wr;              /* non-blocking, close-on-exec */
    _Atomic int pending;     /* a byte sits in the pipe, not yet drained */
} acbb_wake;

int acbb_wake_init(acbb_wake *w);        /* 0, or -1 with errno */
void acbb_wake_close(acbb_wake *w);
void acbb_wake_signal(acbb_wake *w);     /* any thread */
void acbb_wake_drain(acbb_wake *w);      /* the UI thread, before reading the state */

/* The timespec of `at_ms` on acbb_now_ms's clock (CLOCK_MONOTONIC), for
 * pthread_cond_timedwait on a condition variable set to that clock. */
struct timespec acbb_wake_abstime(double at_ms);

/* Start a background thread with the terminal's signals (INT, TERM, HUP,
 * QUIT, WINCH) blocked in it, so they reach the UI thread. The thread call's
 * return value. */
int acbb_thread_start(pthread_t *t, void *(*fn)(void *), void *arg);

#endif
