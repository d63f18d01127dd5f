/* acbb — the JSON writer behind every JSON document acbb writes: the run
 * (`acbb run --json`, acbb_run_preset_json in ffi.h) and the CLI's sweep
 * array. One writer, one style: two-space indent (or one line per
 * container when asked), numbers as %.17g (they round-trip exactly: the
 * double printed is the double computed), strings escaped, and a non-finite number written as null and
 * counted, never as nan/inf (the engine promises finite snapshots, so a
 * nonzero count is an internal error for the caller to report).
 *
 * The writer prints only to the FILE it is given (the caller's file, or a
 * memory stream); it holds no global state. The fields are the writer's
 * state: read `nonfinite`, leave the rest to the functions. */
#ifndef ACBB_JSON_H
#define ACBB_JSON_H

#include <stdbool.h>
#include <stdio.h>
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/tools/branches.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The version of the JSON documents' layout, their first key
 * "schema_version"; docs/schema/acbb.schema.json (`acbb schema`) describes
 * it. Bumped when a key is renamed or removed, not when one is added. */
#define ACBB_JSON_SCHEMA_VERSION 4

#define ACBB_JSON_DEPTH 8        /* deepest nesting; deeper is a bug (counted in misuse) */

typedef struct {
    FILE *f;                     /* not owned */
    long nonfinite;              /* NaN/Inf numbers met (written as null) */
    long misuse;                 /* opens past ACBB_JSON_DEPTH or closes at the top:
                                  * a caller's bug, ignored (the text is then invalid) */
    int depth;
    bool first[ACBB_JSON_DEPTH]; /* no element written yet at this depth */
    bool inline_[ACBB_JSON_DEPTH]; /* container written on one line */
} acbb_json;

void acbb_json_init(acbb_json *j, FILE *f);

/* Open a container ('{' or '[') as the element `key` (NULL inside an array
 * or at the top), on one line when `one_line`; close it with '}' or ']'.
 * Closing the top level ends the line. */
void acbb_json_open(acbb_json *j, const char *key, char bracket, bool one_line);
void acbb_json_close(acbb_json *j, char bracket);

/* One element; `key` NULL inside an array. */
void acbb_json_num(acbb_json *j, const char *key, double v);
void acbb_json_long(acbb_json *j, const char *key, long v);
void acbb_json_str(acbb_json *j, const char *key, const char *s);
void acbb_json_bool(acbb_json *j, const char *key, bool b);
void acbb_json_null(acbb_json *j, const char *key);
/* A value typed as text (a preset value, a swept value): a JSON number when
 * the whole text is a finite number, else a string. The parsed value is
 * written, not the text (strtod accepts forms JSON does not: "1.", "0x10"). */
void acbb_json_value_text(acbb_json *j, const char *key, const char *text);

/* A finished run as one JSON object, exactly what `acbb run --json` prints:
 * status, message, iterations, time_s, wall_ms, the output table's sections
 * (outputs.h), work counters, inactive effects, balls, and the scene with
 * every preset key. */
void acbb_json_write_run(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s);
/* The run with its optional parts: b[0..n) a bearing set's snapshots
 * (acbb_sim_bearing_snapshot, bearing 0 first; n <= 1 or b NULL: one
 * bearing) add `bearings` (each bearing's single-bearing results) and `set`
 * (the output table's "set" entries, MODEL.md 14; b NULL: a set's document
 * has `set` but no `bearings`); br (branches.h; NULL:
 * none) adds `branches`. A scene with a schedule also gets `schedule`, a
 * spindle (s->spindle.n_sets > 0, spindle.h) `spindle`. */
void acbb_json_write_run_parts(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s,
                               const acbb_snapshot *b, int n, const acbb_branches *br);
/* The run's `schedule` object (schedule.h: the rows, the row reached, whether
 * it finished, the operating point there) and the `branches` object;
 * acbb_json_write_run writes the first when the scene has rows. */
void acbb_json_write_schedule(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s);
void acbb_json_write_branches(acbb_json *j, const acbb_branches *b);
/* A run that never started (acbb_sim_create failed): status, message,
 * iterations 0 and the scene. */
void acbb_json_write_failed(acbb_json *j, const acbb_scene *sc, const char *status,
                            const char *message);

#ifdef __cplusplus
}
#endif

#endif
