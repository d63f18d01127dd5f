/* acbb — numbers in the "C" locale whatever the host set (issue 28 item
 * 3): a host program that calls setlocale(LC_ALL, "") under de_DE would
 * otherwise make strtod stop at "6.35"'s point and snprintf write "6,35",
 * so presets, JSON and sweep files would neither read nor write. Every
 * number the engine reads from or writes to a file or document goes
 * through these; messages for people may follow the host's locale. */
#ifndef ACBB_C_LOCALE_H
#define ACBB_C_LOCALE_H

#include <stddef.h>

/* strtod reading a decimal point, never a comma. */
double acbb_strtod_c(const char *s, char **end);

/* snprintf writing a decimal point, never a comma. */
int acbb_snprintf_c(char *buf, size_t n, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
