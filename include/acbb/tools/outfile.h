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

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct acbb_out acbb_out;

/* Open `path` for writing. *f (may be NULL when the caller only wants the
 * temp path for an external writer) receives the stream. Errors name the
 * path and the reason (ACBB_EIO, ACBB_EINVAL). */
acbb_status acbb_out_open(const char *path, acbb_out **out, FILE **f, acbb_error *err);

/* The longest file name (last path component) the writer takes: NAME_MAX
 * less what the temporary file's name adds (".NAME.acbb-PID-N"). */
#define ACBB_OUT_NAME_MAX (NAME_MAX - 24)

/* The descriptor an external program should write (the temporary file; for
 * a non-regular target opened without a stream, its bytes are copied into
 * the target at commit). Owned by o. */
int acbb_out_fd(const acbb_out *o);

/* Flush, fsync and move the result into place; on failure the target is
 * untouched and the temporary file removed. Releases o. */
acbb_status acbb_out_commit(acbb_out *o, acbb_error *err);

/* Drop everything written; the target is untouched. Releases o. */
void acbb_out_abort(acbb_out *o);

/* Open an existing non-regular file (FIFO, device) for writing without
 * waiting for a reader: -1 with errno ENXIO at once when a FIFO has none.
 * The descriptor is blocking once open. */
int acbb_out_open_special(const char *path);

/* ---- read-modify-write without lost edits (src/base/file_lock.c) ----
 * A caller that reads a file, changes it and writes it back (`acbb edit`,
 * the TUI's save) holds acbb_file_lock around the three steps and keeps an
 * acbb_file_stamp of what it read: if the stamp taken again before the
 * write differs, someone changed the file meanwhile. */

/* What a file held when it was read. "Changed" means other content
 * (size or FNV-1a hash of the bytes), or the file appeared, vanished or
 * became non-regular; a new mtime over the same bytes loses nothing and
 * is not a change. A non-regular file (FIFO) is not read. */
typedef struct {
    int exists, regular;
    long long size, mtime_ns;
    uint64_t hash;
} acbb_file_stamp;

/* Stamp `path` now; a missing file gives exists = 0 and ACBB_OK. */
acbb_status acbb_file_stamp_take(const char *path, acbb_file_stamp *s, acbb_error *err);
/* 1 when the content differs between the two stamps. */
int acbb_file_stamp_changed(const acbb_file_stamp *was, const acbb_file_stamp *now);

/* An exclusive advisory lock (flock) on the file `path` names, held until
 * release; another acbb process taking the same lock waits. A missing or
 * non-regular file gets an empty lock (nothing to lose). Waits at most
 * timeout_s seconds, then ACBB_EIO naming the path. Ownership: *out is
 * released by acbb_file_lock_release (NULL is fine). */
typedef struct acbb_file_lock acbb_file_lock;
acbb_status acbb_file_lock_take(const char *path, double timeout_s, acbb_file_lock **out,
                                acbb_error *err);
void acbb_file_lock_release(acbb_file_lock *l);

/* FNV-1a 64 of n bytes continuing from h (ACBB_HASH64_SEED to start):
 * the content stamp and the sweep fingerprint. */
#define ACBB_HASH64_SEED 14695981039346656037ULL
uint64_t acbb_hash64(const void *data, size_t n, uint64_t h);

#ifdef __cplusplus
}
#endif

#endif
