/* acbb CLI — `acbb sweep` and `acbb merge`: the streamed point records.
 *
 * A sweep over an N-dimensional grid (include/acbb/sweep.h) writes one
 * record per point as the point finishes, in completion order:
 *
 * - JSONL: one object per line, keys in this order: index, grid (key:
 *   value, a number when the value reads as one), status, message,
 *   iterations, the scalars (acbb_cli_sweep_scalars; null when the point
 *   never ran), wall_ms. Printed by cJSON (numbers round-trip exactly).
 * - CSV: header "index,<grid keys>,status,iterations,<scalars>,message,
 *   wall_ms"; numbers %.10g, an empty field for a point that never ran,
 *   the message always quoted.
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

typedef enum { ACBB_CLI_REC_JSONL, ACBB_CLI_REC_CSV } acbb_cli_rec_format;

/* One record (with its newline) into f; returns the count of non-finite
 * numbers met (written as null / empty). */
long acbb_cli_sweep_record(FILE *f, acbb_cli_rec_format fmt, const acbb_sweep *g,
                           const acbb_sweep_result *r);
void acbb_cli_sweep_csv_header(FILE *f, const acbb_sweep *g, int with_wall);

/* Resume: read the records already in f (opened "a+"), mark count[index]++
 * for each point found, cut a trailing partial record, and write the CSV
 * header into an empty file. 0, or 2 with a message when the file holds
 * something else than records of this grid. *n_found: records read. */
int acbb_cli_sweep_resume(FILE *f, const char *path, acbb_cli_rec_format fmt,
                          const acbb_sweep *g, unsigned char *count, size_t *n_found);

int acbb_cli_cmd_merge(const acbb_cli_args *a);

#endif
