/* acbb — numbers in the "C" locale (c_locale.h). POSIX 2008's per-thread
 * locales: newlocale builds a "C" locale object once, uselocale switches
 * the calling thread to it around one call and back, so neither the host's
 * global locale nor another thread's is touched. glibc has strtod_l but no
 * snprintf_l, hence uselocale for both. */
#include <locale.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include "c_locale.h"

/* The one "C" locale object: created once and never changed or freed (an
 * immutable value, not mutable state), shared by every thread. */
static locale_t c_loc;
static pthread_once_t c_once = PTHREAD_ONCE_INIT;

static void make_c(void)
{
    c_loc = newlocale(LC_NUMERIC_MASK, "C", (locale_t)0);
}

/* Switch this thread to "C" numbers; the locale to restore (0: none). */
static locale_t enter_c(void)
{
    pthread_once(&c_once, make_c);
    return c_loc ? uselocale(c_loc) : (locale_t)0;
}

static void leave_c(locale_t old)
{
    if (old) uselocale(old);
}

double acbb_strtod_c(const char *s, char **end)
{
    locale_t old = enter_c();
    double v = strtod(s, end);
    leave_c(old);
    return v;
}

int acbb_snprintf_c(char *buf, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    locale_t old = enter_c();
    int r = vsnprintf(buf, n, fmt, ap);
    leave_c(old);
    va_end(ap);
    return r;
}
