/* acbb CLI — `acbb preload-map`'s CSV and JSON (preload_map_out.c). */
#ifndef ACBB_CLI_PRELOAD_MAP_OUT_H
#define ACBB_CLI_PRELOAD_MAP_OUT_H

#include <stdio.h>
#include "acbb/tools/preload_map.h"

/* The CSV: a column header, one row per cell (speed-major). */
void acbb_cli_pmap_csv(FILE *f, const acbb_pmap_cell *c, size_t n);
/* {"schema_version", "preload_map": {preload, limits, cells, rows}}; -1:
 * out of memory. */
long acbb_cli_pmap_json(FILE *f, const acbb_pmap_opts *o, const acbb_pmap_cell *c,
                        const acbb_pmap_row *r);

#endif
