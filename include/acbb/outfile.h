/* acbb — the one way acbb writes a file (presets, CSV, JSON, Markdown,
 * plots): nothing the user had is destroyed.
 *
 * - A regular file (or a new one) is written to a temporary file in the
 *   same directory, flushed with fsync and renamed over the target.
 * - Modes: a new file gets 0666 & ~umask (like `>` in a shell); an
 *   existing file keeps its mode (and, where the process may, its owner).
 * - A symbolic link is followed: its final target is replaced, the link
 *   itself stays.
 * - A non-regular target (a FIFO, a device, /dev/stdout) is written
 *   directly, never replaced; "-" means standard output.
 * - An external writer (gnuplot) writes to acbb_out_fd() (its stdout);
 *   the caller checks the result before commit moves it into place.
 * - The temporary file is unnamed (O_TMPFILE) where the file system allows:
 *   a process killed mid-write leaves no stray file. It is named at commit
 *   through /proc/self/fd; without /proc through linkat(AT_EMPTY_PATH), or
 *   else by copying it to a named temp. Where O_TMPFILE is missing, the
 *   temp is named (.NAME.acbb-PID-N, created O_EXCL) from the start.
 *   Commit and abort leave no temporary file behind.
 *
 * Ownership: acbb_out_open returns an acbb_out that exactly one of
 * acbb_out_commit / acbb_out_abort releases, and a FILE* owned by it. */
#ifndef ACBB_OUTFILE_H
#define ACBB_OUTFILE_H

#include <stdio.h>
#include "acbb/status.h"

typedef struct acbb_out acbb_out;

/* Open `path` for writing. *f (may be NULL when the caller only wants the
 * temp path for an external writer) receives the stream. Errors name the
 * path and the reason (ACBB_EIO, ACBB_EINVAL). */
acbb_status acbb_out_open(const char *path, acbb_out **out, FILE **f, acbb_error *err);

/* The descriptor an external program should write (the temporary file; for
 * a non-regular target opened without a stream, its bytes are copied into
 * the target at commit). Owned by o. */
int acbb_out_fd(const acbb_out *o);

/* Flush, fsync and move the result into place; on failure the target is
 * untouched and the temporary file removed. Releases o. */
acbb_status acbb_out_commit(acbb_out *o, acbb_error *err);

/* Drop everything written; the target is untouched. Releases o. */
void acbb_out_abort(acbb_out *o);

#endif
