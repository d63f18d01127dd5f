/* acbb — the run JSON's `spindle` object (spindle_json.c). Internal. */
#ifndef ACBB_SPINDLE_JSON_H
#define ACBB_SPINDLE_JSON_H

#include "acbb/tools/json.h"
#include "acbb/sim.h"

/* Write "spindle": {...} (spindle.h's view) into the open object; the
 * caller writes it only when s->spindle.n_sets > 0. */
void acbb_json_write_spindle(acbb_json *j, const acbb_snapshot *s);

/* The output table's bearing entries of `section` (outputs.h) as JSON
 * numbers in table order, a missing one as null (run_json.c). */
void acbb_json_table_rows(acbb_json *j, const acbb_snapshot *s, const char *section);

#endif
