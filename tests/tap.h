/* Minimal TAP helper for numeric tests (header-only; one plan per binary).
 * is_close(got, want, rtol, atol, name): passes if
 * |got - want| <= atol + rtol * |want|, and prints both values otherwise.
 * skip(reason, name): a check that cannot run here (TAP # SKIP). */
#ifndef ACBB_TAP_H
#define ACBB_TAP_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static int tap_n = 0, tap_failed = 0;

static inline int ok(int cond, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static inline int ok(int cond, const char *fmt, ...)
{
    va_list ap;
    tap_n++;
    printf("%s %d - ", cond ? "ok" : "not ok", tap_n);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    if (!cond) tap_failed++;
    fflush(stdout);
    return cond;
}

/* A check that cannot run here: reported as passing with a TAP "# SKIP"
 * directive and the reason, so it is counted but visibly not done. */
static inline void skip(const char *reason, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static inline void skip(const char *reason, const char *fmt, ...)
{
    va_list ap;
    tap_n++;
    printf("ok %d - ", tap_n);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf(" # SKIP %s\n", reason);
    fflush(stdout);
}

static inline int is_close(double got, double want, double rtol, double atol,
                           const char *name)
{
    int pass = isfinite(got) && fabs(got - want) <= atol + rtol * fabs(want);
    ok(pass, "%s", name);
    if (!pass)
        printf("#   got %.10g, want %.10g (rtol %g, atol %g)\n", got, want, rtol, atol);
    return pass;
}

static inline int has_substr(const char *hay, const char *needle, const char *name)
{
    int pass = hay && strstr(hay, needle) != NULL;
    ok(pass, "%s", name);
    if (!pass) printf("#   \"%s\" not found in \"%s\"\n", needle, hay ? hay : "(null)");
    return pass;
}

/* Call last: prints the plan and returns the exit status. */
static inline int done_testing(void)
{
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}

#endif
