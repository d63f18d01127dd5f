/* acbb CLI — the output files of a streaming sweep (sweep.h, issue 26
 * items 3, 4 and 11): one writer per file, whole records only.
 *
 * - Lock: each output file is opened and locked (flock, exclusive, not
 *   waiting) before anything is read or written, and held until the sweep
 *   ends; a second sweep on the same file is refused (exit 2) naming it.
 *   Shards write different files and never meet. Where the file system
 *   has no flock (ENOLCK, ENOTSUP) the sweep goes on unlocked, saying so.
 * - Whole records: a record (and the header) is built in memory and handed
 *   to write(2) in one loop. When a write fails or comes up short (disk
 *   full, `ulimit -f`, a closed pipe) a regular file is cut back to its
 *   last whole record (ftruncate), the sink stops taking records and the
 *   sweep stops (acbb_cli_interrupt_stop): the file can be resumed as is
 *   once there is room, and the command exits 4 naming the file.
 * - A plain CSV's header lives in the sidecar PATH.json (sweep.h), written
 *   whole before the CSV's first byte and checked before a CSV with bytes
 *   in it is resumed. */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cjson/cJSON.h>
#include "acbb/tools/outfile.h"
#include "common.h"
#include "exit.h"
#include "progress.h"
#include "sweep.h"
#include "say.h"

int acbb_cli_sink_put(acbb_cli_sink *o, const char *buf, size_t len)
{
    if (o->failed) return -1;
    size_t at = 0;
    while (at < len) {
        ssize_t n = write(o->fd, buf + at, len - at);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            o->err = n < 0 ? errno : ENOSPC;
            o->failed = 1;
            /* Cut the part of the record that went out: the file ends with
             * a whole record, and a resume later appends after it. */
            if (o->regular && at > 0 && ftruncate(o->fd, (off_t)o->good_end) != 0) o->cut_failed = 1;
            acbb_cli_interrupt_stop();
            return -1;
        }
        at += (size_t)n;
    }
    o->good_end += (long long)len;
    return 0;
}

/* The header (CSV: and its column line) as one write. */
static int put_header(acbb_cli_sink *o, const acbb_cli_sweep_id *id)
{
    size_t len = 0;
    char *text = acbb_cli_sweep_header_text(o->fmt, id, 1, &len);
    if (!text) return acbb_cli_no_memory("sweep");
    acbb_cli_sink_put(o, text, len);
    free(text);
    return 0;
}

/* A plain CSV (no --csv-header) keeps its sweep's header in the sidecar
 * PATH.json (sweep.h). A CSV with bytes in it was started after its
 * sidecar was committed: the sidecar must be there and be this sweep's, or
 * the CSV is not resumed (its records' fingerprint alone could not say
 * what differs). */
static int sidecar_check(const acbb_cli_sink *o, const acbb_cli_sweep_id *id)
{
    struct stat st;
    char first[2];
    if (fstat(o->fd, &st) != 0 || st.st_size == 0) return 0;
    /* a header line first: the resume says it was written with --csv-header */
    if (pread(o->fd, first, 2, 0) == 2 && memcmp(first, "# ", 2) == 0) return 0;
    int missing = 0, rc = ACBB_EXIT_INPUT;
    cJSON *got = acbb_cli_sweep_sidecar_read(o->path, &missing), *want = acbb_cli_sweep_header_of(id);
    char diff[400];
    if (!got && missing)
        acbb_cli_say("sweep: %s: its header %s" ACBB_CLI_SIDECAR_EXT " is missing (a "
                "plain sweep CSV keeps the sweep's header there; --csv-header: on its first "
                "line); not resuming (write to another file)\n", o->path, o->path);
    else if (!got)
        acbb_cli_say("sweep: %s" ACBB_CLI_SIDECAR_EXT ": not a sweep header; not "
                "resuming %s (write to another file)\n", o->path, o->path);
    else if (acbb_cli_sweep_header_diff(got, want, diff, sizeof diff))
        acbb_cli_say("sweep: %s: written by another sweep (its header %s"
                ACBB_CLI_SIDECAR_EXT "); not resuming (write to another file). Differs (file vs "
                "now): %s\n", o->path, o->path, diff);
    else
        rc = 0;
    cJSON_Delete(got);
    cJSON_Delete(want);
    return rc;
}

/* The sidecar, committed whole (acbb_cli_file: a temporary renamed in
 * place) before the CSV's first byte. */
static int sidecar_write(const acbb_cli_sink *o, const acbb_cli_sweep_id *id)
{
    char side[4200];
    if (snprintf(side, sizeof side, "%s" ACBB_CLI_SIDECAR_EXT, o->path) >= (int)sizeof side) {
        acbb_cli_say("sweep: %s: path too long for its header file\n", o->path);
        return ACBB_EXIT_INPUT;
    }
    size_t len = 0;
    char *text = acbb_cli_sweep_header_text(ACBB_CLI_REC_JSONL, id, 1, &len);
    if (!text) return acbb_cli_no_memory("sweep");
    acbb_cli_file file = { 0 };
    int rc = acbb_cli_file_open(&file, side);
    if (!rc) {
        fwrite(text, 1, len, file.out.f);
        rc = acbb_cli_file_close(&file);
    }
    free(text);
    return rc;
}

/* A FIFO or device: written from the header on, nothing to resume (reading
 * it back would block), and no waiting for a reader that may never come. */
static int open_special(acbb_cli_sink *o, const acbb_cli_sweep_id *id)
{
    o->fd = acbb_out_open_special(o->path);
    if (o->fd < 0) {
        acbb_cli_say("sweep: %s: cannot open for writing: %s\n", o->path,
                errno == ENXIO ? "a FIFO with no reader (start the reader first)" : strerror(errno));
        return ACBB_EXIT_INPUT;
    }
    o->own = 1;
    return put_header(o, id);
}

/* The one writer of a regular file (issue 26 item 3). */
static int lock_file(acbb_cli_sink *o)
{
    if (flock(o->fd, LOCK_EX | LOCK_NB) == 0) return 0;
    if (errno == EWOULDBLOCK) {
        acbb_cli_say("sweep: %s: another sweep is writing this file (it holds the "
                "file's lock); not writing it (wait for that sweep to end, or write to another "
                "file)\n", o->path);
        return ACBB_EXIT_INPUT;
    }
    acbb_cli_say("sweep: %s: warning: cannot lock (%s); a second sweep on this file "
            "would not be refused\n", o->path, strerror(errno));
    return 0;
}

int acbb_cli_sink_open(acbb_cli_sink *o, const char *path, acbb_cli_rec_format fmt,
                       const acbb_cli_sweep_id *id, unsigned char *count, size_t *found)
{
    memset(o, 0, sizeof *o);
    o->path = path;
    o->fmt = fmt;
    o->fd = -1;
    *found = 0;
    if (strcmp(path, "-") == 0) {
        fflush(stdout);
        o->fd = STDOUT_FILENO; /* nothing to resume */
        return put_header(o, id);
    }
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) return open_special(o, id);
    o->f = fopen(path, "a+");
    if (!o->f) {
        acbb_cli_say("sweep: %s: cannot open for writing: %s\n", path, strerror(errno));
        return ACBB_EXIT_INPUT;
    }
    o->own = 1;
    o->regular = 1;
    o->fd = fileno(o->f);
    int have_header = 0, sidecar = fmt == ACBB_CLI_REC_CSV && !id->csv_header;
    int rc = lock_file(o);
    if (!rc && sidecar) rc = sidecar_check(o, id);
    if (!rc) rc = acbb_cli_sweep_resume(o->f, path, fmt, id, count, found, &have_header);
    if (!rc && sidecar && !have_header) rc = sidecar_write(o, id);
    if (rc) return rc;
    /* Writes go to the descriptor (O_APPEND) from here on. */
    o->good_end = (long long)lseek(o->fd, 0, SEEK_END);
    return have_header ? 0 : put_header(o, id);
}

int acbb_cli_sink_close(acbb_cli_sink *o)
{
    int bad = o->failed;
    if (!bad && o->fd >= 0 && o->regular && fsync(o->fd) != 0 && errno != EINVAL) {
        o->err = errno;
        bad = 1;
    }
    if (o->f) fclose(o->f); /* drops the lock */
    else if (o->own && o->fd >= 0) close(o->fd);
    o->f = NULL;
    o->fd = -1;
    if (!bad) return 0;
    const char *name = strcmp(o->path, "-") ? o->path : "standard output";
    if (o->regular)
        acbb_cli_say("sweep: cannot write %s: %s; %s (%zu written this run); make room "
                "and run the same command again to resume\n", name, strerror(o->err),
                o->cut_failed ? "the file could not be cut back to its last whole record"
                              : "the file ends with its last whole record",
                o->written);
    else
        acbb_cli_say("sweep: cannot write %s: %s; the sweep stopped after %zu "
                "record%s\n", name, strerror(o->err), o->written, o->written == 1 ? "" : "s");
    return ACBB_EXIT_INTERNAL;
}
