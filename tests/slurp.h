/* Test helpers (header-only): a stream's or a command's whole output as a
 * NUL-terminated string (malloc'd; NULL when it cannot be had). */
#ifndef ACBB_TEST_SLURP_H
#define ACBB_TEST_SLURP_H

#include <stdio.h>
#include <stdlib.h>

static inline char *slurp(FILE *f)
{
    size_t cap = 1 << 16, n = 0, got;
    char *buf = malloc(cap);
    while (buf && (got = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += got;
        if (n + 1 == cap) buf = realloc(buf, cap *= 2);
    }
    if (buf) buf[n] = '\0';
    return buf;
}

static inline char *slurp_cmd(const char *cmd)
{
    FILE *p = popen(cmd, "r");
    if (!p) return NULL;
    char *s = slurp(p);
    pclose(p);
    return s;
}

#endif
