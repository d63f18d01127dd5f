/* acbb — the atomic writer's ways of naming its temporary file, as flags
 * (outfile.c). Not installed; the public interface is include/acbb/tools/outfile.h.
 * A flag turns one way off, so a test can force the fallbacks a machine
 * without /proc (or without O_TMPFILE) takes, with no global switch. */
#ifndef ACBB_OUTFILE_PRIV_H
#define ACBB_OUTFILE_PRIV_H

#include "acbb/tools/outfile.h"

enum {
    ACBB_OUT_NO_PROC = 1u,       /* do not link through /proc/self/fd/N */
    ACBB_OUT_NO_EMPTY_PATH = 2u, /* do not link with linkat(fd, "", AT_EMPTY_PATH) */
    ACBB_OUT_NO_TMPFILE = 4u     /* no O_TMPFILE: a named temp from the start */
};

/* acbb_out_open with some ways turned off; acbb_out_open(...) is
 * acbb_out_open_ex(..., 0). */
acbb_status acbb_out_open_ex(const char *path, unsigned flags, acbb_out **out, FILE **f,
                             acbb_error *err);

#endif
