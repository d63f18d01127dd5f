/* acbb CLI — `acbb sweep` and `acbb merge`: the streamed point records.
 *
 * A sweep over an N-dimensional grid (include/acbb/tools/sweep.h) writes one
 * record per point as the point finishes, in completion order:
 *
 * - JSONL: a header line {"acbb_sweep":{format, fingerprint, mode, grid
 *   (key: [values]), scene (key: value of every key the grid does not
 *   vary but fidelity.max_wall_s, and schedule.rows: the rows as one
 *   text), metrics (the --metric paths, when given)}}, then one object per
 *   line, keys in this order: index, fingerprint, grid (key: value, a
 *   number when the value reads as one), status, message, iterations, the
 *   scalars (acbb_cli_sweep_scalars; null when the point never ran), the
 *   --metric paths, wall_ms. Printed by cJSON (numbers
 *   round-trip exactly).
 * - CSV: the column header "index,fingerprint,<grid keys>,status,
 *   iterations,<scalars>,<--metric paths>,message,wall_ms" first, so csv
 *   readers take it as the header (issue 28 item 8); the header object in
 *   the sidecar PATH.json (the JSONL's first line, written before the CSV),
 *   or, with --csv-header, on a first line "# {...}" (the form before issue
 *   28; stdout, FIFOs and devices have no sidecar). Numbers %.17g, an empty
 *   field for a point that never ran, the message always quoted.
 * - The fingerprint (include/acbb/tools/sweep.h, acbb_sweep_fingerprint, 16 hex
 *   digits) names the record format ACBB_SWEEP_FORMAT, the run mode, the
 *   scene and the grid: `acbb merge` and a resumed sweep refuse a header
 *   or a record of another sweep, naming the keys that differ (issue 20).
 *
 * The canonical form (what `acbb merge` writes, and what shards merged
 * must equal byte for byte): records sorted by index, each index once
 * (the first record met wins), without wall_ms, the only field that
 * depends on the machine. */
#ifndef ACBB_CLI_SWEEP_H
#define ACBB_CLI_SWEEP_H

#include <stdio.h>
#include "acbb/tools/sweep.h"
#include "args.h"

#define ACBB_CLI_SWEEP_SCALARS 48
#define ACBB_CLI_SWEEP_NAME 40

/* The scalar results of a point, names and values (NAN when snap is NULL);
 * returns how many. The loss columns follow the loss kinds (loss_kinds.h). */
size_t acbb_cli_sweep_scalars(const acbb_snapshot *snap,
                              char names[][ACBB_CLI_SWEEP_NAME], double *v);


typedef enum { ACBB_CLI_REC_JSONL, ACBB_CLI_REC_CSV } acbb_cli_rec_format;

/* ---- sweep_metric.c: `--metric PATH`, results added to every record ---- */
#define ACBB_CLI_SWEEP_METRICS 16
#define ACBB_CLI_METRIC_NAME 64
typedef struct {
    size_t n;
    char path[ACBB_CLI_SWEEP_METRICS][ACBB_CLI_METRIC_NAME]; /* canonical run JSON paths */
    /* --no-stiffness: the stiffness columns (acbb_cli_sweep_dropped) are
     * left out of every record; the header says "stiffness": false. */
    int no_stiffness;
} acbb_cli_metrics;
/* Fixed column `name` is left out of the records of a sweep with m. */
int acbb_cli_sweep_dropped(const acbb_cli_metrics *m, const char *name);
/* How many of the scalars a record with m's columns carries. */
size_t acbb_cli_sweep_n_scalars(const acbb_cli_metrics *m);
/* Add `path` (an `acbb metrics` path or old name) in its canonical form;
 * 0, or -1 with the reason in msg (unknown, already a fixed column, twice). */
int acbb_cli_sweep_metric_add(acbb_cli_metrics *m, const char *path, char *msg, size_t mn);
/* The metric's value in snap (JSON units); NAN with *expected = 1 when it
 * has none on purpose (snap NULL, a ball it does not have, a failed probe,
 * set.* of one bearing), *expected = 0 otherwise. */
double acbb_cli_sweep_metric_value(const acbb_snapshot *snap, const char *path, int *expected);
struct cJSON;
/* The metrics a header lists ("metrics": [...], absent: none); -1 when
 * the list is not one a sweep writes. */
int acbb_cli_sweep_metrics_of_header(const struct cJSON *h, acbb_cli_metrics *m);

/* The sweep an output belongs to (sweep_id.c). */
typedef struct {
    const acbb_sweep *g;
    const acbb_scene *base;
    int transient;
    int csv_header;            /* CSV: the header on a first line "# {...}" (--csv-header),
                                  not in the sidecar PATH.json */
    acbb_cli_metrics metrics;  /* --metric */
    char fp[17];               /* acbb_sweep_fingerprint (and the metrics), 16 hex digits */
} acbb_cli_sweep_id;
/* The id of a sweep; metrics may be NULL (none). With metrics the
 * fingerprint goes on over "metrics=PATH" lines: a sweep without --metric
 * keeps the fingerprint it always had. */
void acbb_cli_sweep_id_init(acbb_cli_sweep_id *id, const acbb_sweep *g, const acbb_scene *base,
                            int transient, const acbb_cli_metrics *metrics);

/* One record (with its newline) into f; returns the count of non-finite
 * numbers met (written as null / empty). */
long acbb_cli_sweep_record(FILE *f, acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                           const acbb_sweep_result *r);
/* The header line (CSV: and the column header) an output starts with. */
void acbb_cli_sweep_header(FILE *f, acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                           int with_wall);
void acbb_cli_sweep_csv_header(FILE *f, const acbb_sweep *g, const acbb_cli_metrics *m,
                               int with_wall);

/* The same, as text in memory (malloc'd, *len bytes; NULL: out of memory):
 * a record is handed to write(2) whole (sweep_sink.c). */
char *acbb_cli_sweep_record_text(acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                                 const acbb_sweep_result *r, size_t *len, long *nonfinite);
char *acbb_cli_sweep_header_text(acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                                 int with_wall, size_t *len);

/* Resume: read the header and records already in f (opened "a+"), mark
 * count[index]++ for each point found that is a result to keep (a
 * wall_limit or out_of_memory record is not: acbb_cli_sweep_status_retried,
 * the point runs again), and cut what a writer did not finish: a partial
 * last record, or a header that stops short (a prefix of this sweep's
 * header, CSV column line included: no records yet, the file is emptied
 * and *have_header = 0, the caller writes the header). 0, or 2 with a
 * message when the file holds something else than records of this sweep
 * (the message names the keys that differ). *n_found: records read. */
int acbb_cli_sweep_resume(FILE *f, const char *path, acbb_cli_rec_format fmt,
                          const acbb_cli_sweep_id *id, unsigned char *count, size_t *n_found,
                          int *have_header);

/* A record whose status depends on the machine and not on the point alone
 * (wall_limit: the --max-wall bound, not in the fingerprint; out_of_memory)
 * is run again on resume, and `acbb merge` keeps another record of its
 * point over it. Every other status (converged, not_converged, runaway,
 * diverged, bad_input, ...) is the point's result and stays. 1 when the
 * record's status is such (line already checked by check_record). */
int acbb_cli_sweep_record_retried(const char *line, acbb_cli_rec_format fmt,
                                  const acbb_sweep *g);

/* ---- sweep_sink.c: a streaming sweep's output files (issue 26) ---- */
typedef struct {
    FILE *f;                   /* a regular file, as read for resume (owned) */
    int fd;                    /* written by write(2), whole records */
    const char *path;          /* "-": standard output */
    acbb_cli_rec_format fmt;
    int own, regular;
    long long good_end;        /* bytes up to the last whole record */
    int failed, err, cut_failed; /* a write failed (errno err) */
    size_t written;            /* records written this run */
} acbb_cli_sink;
/* Open path ("-", a regular file, a FIFO or device), lock a regular file
 * (a second sweep on it: exit 2), resume it (count, found as
 * acbb_cli_sweep_resume) and write the header where there is none. 0 or
 * the exit status, the message printed. */
int acbb_cli_sink_open(acbb_cli_sink *o, const char *path, acbb_cli_rec_format fmt,
                       const acbb_cli_sweep_id *id, unsigned char *count, size_t *found);
/* Write len bytes whole; on a failed or short write cut a regular file
 * back to its last whole record, stop taking records and stop the sweep
 * (acbb_cli_interrupt_stop). 0 or -1. */
int acbb_cli_sink_put(acbb_cli_sink *o, const char *buf, size_t len);
/* Close (the lock goes with it); a failed sink: the message, exit 4. */
int acbb_cli_sink_close(acbb_cli_sink *o);

/* ---- sweep_id.c: headers and record checks (merge, resume) ---- */
typedef struct cJSON cJSON;
/* The header object of an output line, or NULL when the line is none. */
cJSON *acbb_cli_sweep_header_parse(const char *line, acbb_cli_rec_format fmt);
/* A plain CSV's sidecar, CSV_PATH.json (issue 28 item 8): the header line
 * of the JSONL, written (atomically) before the CSV's first byte, so a CSV
 * with bytes in it has one. Its header object, or NULL (*missing: no such
 * file; else not a header). */
#define ACBB_CLI_SIDECAR_EXT ".json"
cJSON *acbb_cli_sweep_sidecar_read(const char *csv_path, int *missing);
/* This sweep's header object (owned by the caller, cJSON_Delete). */
cJSON *acbb_cli_sweep_header_of(const acbb_cli_sweep_id *id);
/* The number of differences between two headers, listed in msg
 * ("operating.axial_load_N ("100" vs "200"), grid ..."). */
int acbb_cli_sweep_header_diff(const cJSON *a, const cJSON *b, char *msg, size_t n);
/* The grid a header describes (NULL when it describes none). */
acbb_sweep *acbb_cli_sweep_from_header(const cJSON *h);
/* A record of the grid g with fingerprint fp: index a whole number in
 * range, fingerprint equal, grid values those of the index, numbers finite,
 * CSV: every field in place. 0, or -1 with *why. */
int acbb_cli_sweep_check_record(const char *line, acbb_cli_rec_format fmt, const acbb_sweep *g,
                                const acbb_cli_metrics *m, const char *fp, int with_wall,
                                size_t *index, const char **why);
/* Point index's grid as a JSON object (key: value). */
cJSON *acbb_cli_sweep_grid_json(const acbb_sweep *g, size_t index);

int acbb_cli_cmd_merge(const acbb_cli_args *a);

#endif
