/* acbb CLI — `acbb sweep` and `acbb merge`: the streamed point records.
 *
 * A sweep over an N-dimensional grid (include/acbb/sweep.h) writes one
 * record per point as the point finishes, in completion order:
 *
 * - JSONL: a header line {"acbb_sweep":{format, fingerprint, mode, grid
 *   (key: [values]), scene (key: value of every key the grid does not
 *   vary)}}, then one object per line, keys in this order: index,
 *   fingerprint, grid (key: value, a number when the value reads as one),
 *   status, message, iterations, the scalars (acbb_cli_sweep_scalars; null
 *   when the point never ran), wall_ms. Printed by cJSON (numbers
 *   round-trip exactly).
 * - CSV: the same header object on a first line "# {...}", the column
 *   header "index,fingerprint,<grid keys>,status,iterations,<scalars>,
 *   message,wall_ms"; numbers %.10g, an empty field for a point that never
 *   ran, the message always quoted.
 * - The fingerprint (include/acbb/sweep.h, acbb_sweep_fingerprint, 16 hex
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
#include "acbb/sweep.h"
#include "args.h"

#define ACBB_CLI_SWEEP_SCALARS 48
#define ACBB_CLI_SWEEP_NAME 40

/* The scalar results of a point, names and values (NAN when snap is NULL);
 * returns how many. The loss columns follow the loss kinds (loss_kinds.h). */
size_t acbb_cli_sweep_scalars(const acbb_snapshot *snap,
                              char names[][ACBB_CLI_SWEEP_NAME], double *v);

size_t acbb_cli_sweep_n_scalars(void);

typedef enum { ACBB_CLI_REC_JSONL, ACBB_CLI_REC_CSV } acbb_cli_rec_format;

/* The sweep an output belongs to (sweep_id.c). */
typedef struct {
    const acbb_sweep *g;
    const acbb_scene *base;
    int transient;
    char fp[17];               /* acbb_sweep_fingerprint, 16 hex digits */
} acbb_cli_sweep_id;
void acbb_cli_sweep_id_init(acbb_cli_sweep_id *id, const acbb_sweep *g, const acbb_scene *base,
                            int transient);

/* One record (with its newline) into f; returns the count of non-finite
 * numbers met (written as null / empty). */
long acbb_cli_sweep_record(FILE *f, acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                           const acbb_sweep_result *r);
/* The header line (CSV: and the column header) an output starts with. */
void acbb_cli_sweep_header(FILE *f, acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                           int with_wall);
void acbb_cli_sweep_csv_header(FILE *f, const acbb_sweep *g, int with_wall);

/* Resume: read the header and records already in f (opened "a+"), mark
 * count[index]++ for each point found, cut a trailing partial record, and
 * write the header into an empty file. 0, or 2 with a message when the
 * file holds something else than records of this sweep (the message names
 * the keys that differ). *n_found: records read. */
int acbb_cli_sweep_resume(FILE *f, const char *path, acbb_cli_rec_format fmt,
                          const acbb_cli_sweep_id *id, unsigned char *count, size_t *n_found);

/* ---- sweep_id.c: headers and record checks (merge, resume) ---- */
typedef struct cJSON cJSON;
/* The header object of an output line, or NULL when the line is none. */
cJSON *acbb_cli_sweep_header_parse(const char *line, acbb_cli_rec_format fmt);
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
                                const char *fp, int with_wall, size_t *index, const char **why);
/* Point index's grid as a JSON object (key: value). */
cJSON *acbb_cli_sweep_grid_json(const acbb_sweep *g, size_t index);

int acbb_cli_cmd_merge(const acbb_cli_args *a);

#endif
