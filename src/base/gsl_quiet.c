/* acbb — GSL's error handler off while the engine works (gsl_quiet.h). */
#include <pthread.h>
#include <gsl/gsl_errno.h>
#include "gsl_quiet.h"

/* The one guarded piece of process-wide mutable state in the library, and
 * only because GSL's handler itself is process-wide (gsl_quiet.h): how many
 * threads are inside an engine call, and the host's handler to put back
 * when the last one leaves. Both only under `lock`. */
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static long users;
static gsl_error_handler_t *host_handler;

/* This thread's nesting: only the outermost call touches the count. */
static _Thread_local int depth;

void acbb_gsl_enter(void)
{
    if (depth++ > 0) return;
    pthread_mutex_lock(&lock);
    if (users++ == 0) host_handler = gsl_set_error_handler_off();
    pthread_mutex_unlock(&lock);
}

void acbb_gsl_leave(void)
{
    if (--depth > 0) return;
    pthread_mutex_lock(&lock);
    if (--users == 0) gsl_set_error_handler(host_handler);
    pthread_mutex_unlock(&lock);
}
