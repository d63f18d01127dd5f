/* acbb CLI — the one reporter of the CLI's messages (say.h). */
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "say.h"

/* The CLI's only record of what it said: the first error, for the JSON
 * error document. A client's state (the engine keeps none), guarded. */
static pthread_mutex_t said_lock = PTHREAD_MUTEX_INITIALIZER;
static char said[1024];
static int have_said;

static int is_error(const char *msg)
{
    return strncmp(msg, "note: ", 6) != 0 && strncmp(msg, "warning: ", 9) != 0 &&
           !strstr(msg, ": note: ") && !strstr(msg, ": warning: ");
}

void acbb_cli_say(const char *fmt, ...)
{
    char msg[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    fprintf(stderr, "acbb: %s", msg);
    pthread_mutex_lock(&said_lock);
    if (!have_said && is_error(msg)) {
        snprintf(said, sizeof said, "%.*s", (int)strcspn(msg, "\n"), msg);
        have_said = 1;
    }
    pthread_mutex_unlock(&said_lock);
}

const char *acbb_cli_said_error(void)
{
    pthread_mutex_lock(&said_lock);
    const char *s = have_said ? said : NULL;
    pthread_mutex_unlock(&said_lock);
    return s;
}
