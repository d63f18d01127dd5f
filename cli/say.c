/* acbb CLI — the one reporter of the CLI's messages (say.h). */
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "say.h"

/* The CLI's only record of what it said: the first error, for the JSON
 * error document. A client's state (the engine keeps none), guarded. */
static pthread_mutex_t said_lock = PTHREAD_MUTEX_INITIALIZER;
static char said[4096];
static int have_said;

static int is_error(const char *msg)
{
    return strncmp(msg, "note: ", 6) != 0 && strncmp(msg, "warning: ", 9) != 0 &&
           !strstr(msg, ": note: ") && !strstr(msg, ": warning: ");
}

/* The one place a message reaches stderr (and the record). */
static void say_text(const char *msg)
{
    fprintf(stderr, "acbb: %s", msg);
    pthread_mutex_lock(&said_lock);
    if (!have_said && is_error(msg)) {
        snprintf(said, sizeof said, "%.*s", (int)strcspn(msg, "\n"), msg);
        have_said = 1;
    }
    pthread_mutex_unlock(&said_lock);
}

void acbb_cli_say(const char *fmt, ...)
{
    char msg[2048];
    va_list ap, again;
    va_start(ap, fmt);
    va_copy(again, ap);
    int n = vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    /* A long one (a list of directories) whole, not cut at the buffer. */
    char *big = n >= (int)sizeof msg ? malloc((size_t)n + 1) : NULL;
    if (big) vsnprintf(big, (size_t)n + 1, fmt, again);
    va_end(again);
    say_text(big ? big : msg);
    free(big);
}

FILE *acbb_cli_msg_begin(acbb_cli_msg *m)
{
    m->text = NULL;
    m->len = 0;
    m->f = open_memstream(&m->text, &m->len);
    if (m->f) return m->f;
    /* Out of memory: straight to stderr, unrecorded (the document then
     * says "bad input"), rather than lose the message. */
    fputs("acbb: ", stderr);
    return m->f = stderr;
}

void acbb_cli_msg_say(acbb_cli_msg *m)
{
    if (m->f == stderr) return;
    if (fclose(m->f) == 0 && m->text) say_text(m->text);
    free(m->text);
    m->text = NULL;
    m->f = NULL;
}

const char *acbb_cli_said_error(void)
{
    pthread_mutex_lock(&said_lock);
    const char *s = have_said ? said : NULL;
    pthread_mutex_unlock(&said_lock);
    return s;
}
