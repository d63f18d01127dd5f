/* acbb CLI — output writers: the plain summary table, JSON and CSV.
 *
 * Private to the executable (cli/); not part of the engine API.
 * Every writer goes through an acbb_cli_out, which counts the non-finite
 * numbers it was asked to print: the engine promises finite snapshots, so a
 * non-zero count after writing is an internal error for the caller to
 * report. JSON prints such a number as null, CSV as an empty field. */
#ifndef ACBB_CLI_OUTPUT_H
#define ACBB_CLI_OUTPUT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "acbb/outputs.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/tools/branches.h"

#define ACBB_CLI_COLS 64                 /* columns of one flat (CSV) list */
#define ACBB_CLI_COLSETS 4               /* run CSV (three parts), sweep */

/* A flat output's column: an entry of the output table and its ball. */
typedef struct {
    acbb_output e;
    int ball;                            /* -1 for a bearing entry */
} acbb_cli_col;

/* A column list resolved against the output table, kept for the next row. */
typedef struct {
    const char *const *spec;             /* the static list it came from (NULL: free) */
    size_t n;
    acbb_cli_col c[ACBB_CLI_COLS];
} acbb_cli_colset;

typedef struct {
    FILE *f;
    long nonfinite;                      /* NaN/Inf values met so far */
    acbb_cli_colset cols[ACBB_CLI_COLSETS];
    int set_n;                           /* a set's bearings (run CSV columns); 0/1: one */
    bool spindle;                        /* a spindle (run CSV columns) */
} acbb_cli_out;

/* One run of a sweep or study: the scene it ran and what came out. */
typedef struct {
    char value[64];          /* the swept value as typed, or the study x */
    acbb_scene scene;
    acbb_status status;      /* acbb_sim_create's status, else the last step's */
    bool have_snap;          /* false if acbb_sim_create failed */
    bool internal_error;     /* the driver had to stop a runaway loop */
    char message[512];       /* acbb_sim_create's message when !have_snap */
    double wall_ms;          /* sim_new + stepping, CLOCK_MONOTONIC */
    acbb_snapshot snap;
} acbb_cli_point;

/* A block of the TE/WTE study: pairs [first, first + count) of the point
 * array, pair k being points 2k (TE) and 2k+1 (WTE). */
typedef struct {
    const char *name;        /* CSV `sweep` column, e.g. "load" */
    const char *title;       /* table heading */
    const char *x_label;     /* "Fx N" or "n rpm" */
    size_t first, count;
} acbb_cli_study_block;

void acbb_cli_out_init(acbb_cli_out *o, FILE *f);

/* True when the run reached steady state. */
bool acbb_cli_point_ok(const acbb_cli_point *p);
/* "converged", "not_converged", ..., or the sim_new failure name. */
const char *acbb_cli_point_status(const acbb_cli_point *p);

/* `acbb run`: summary table (fits 80 columns) and the JSON object. */
void acbb_cli_print_summary(acbb_cli_out *o, const char *preset,
                            const acbb_scene *sc, const acbb_snapshot *snap);
/* Its spindle block (output_spindle.c): nothing when s->spindle.n_sets = 0. */
void acbb_cli_print_spindle(acbb_cli_out *o, const acbb_snapshot *s);
/* A number in the summary's style: `width` wide (a cell: with a leading
 * blank), "-" and counted in o->nonfinite when not finite. */
void acbb_cli_num(acbb_cli_out *o, int width, int prec, char conv, double v);
void acbb_cli_cell(acbb_cli_out *o, int width, int prec, char conv, double v);
void acbb_cli_json_run(acbb_cli_out *o, const acbb_scene *sc,
                       const acbb_snapshot *snap);
/* The same with its optional parts (acbb_json_write_run_parts): a set's
 * bearings[0..s->n_bearings) (NULL: one bearing), the branches (NULL: none). */
void acbb_cli_json_run_parts(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s,
                             const acbb_snapshot *bearings, const acbb_branches *br);
/* JSON for a run that never started (acbb_sim_create failed). */
void acbb_cli_json_failed(acbb_cli_out *o, const acbb_scene *sc,
                          const char *status, const char *message);

/* `acbb metrics`: every output table entry (outputs.h) as "path unit label". */
void acbb_cli_list_metrics(FILE *f);
/* The same as one JSON document (`acbb metrics --json`): schema_version and
 * "metrics", one {path, column, unit, label} per output (column: the name of
 * the quantity in CSV and sweep records). */
void acbb_cli_list_metrics_json(FILE *f);

/* A JSON number as %.17g, the double itself (acbb/tools/json.h); null when not
 * finite. Not cJSON_CreateNumber: cJSON 1.7 prints 15 digits whenever they
 * read back within one ulp, so its numbers may be off by one ulp. */
struct cJSON *acbb_cli_json_number(double v);
/* Every number in the tree `o` re-made by acbb_cli_json_number (a parsed
 * record printed again: cJSON's parser reads the double exactly). */
void acbb_cli_json_exact(struct cJSON *o);

/* `acbb run --csv`: one row per coupled step. */
void acbb_cli_csv_header(acbb_cli_out *o);
void acbb_cli_csv_row(acbb_cli_out *o, const acbb_snapshot *snap);

/* `acbb sweep`: table, JSON array, CSV. */
void acbb_cli_sweep_table(acbb_cli_out *o, const char *param,
                          const acbb_cli_point *pts, size_t n);
void acbb_cli_sweep_json(acbb_cli_out *o, const char *param,
                         const acbb_cli_point *pts, size_t n);
void acbb_cli_sweep_csv(acbb_cli_out *o, const char *param,
                        const acbb_cli_point *pts, size_t n);

/* `acbb study`: TE and WTE side by side. */
void acbb_cli_study_table(acbb_cli_out *o, const acbb_cli_point *pts,
                          const acbb_cli_study_block *blocks, size_t nb);
void acbb_cli_study_csv(acbb_cli_out *o, const acbb_cli_point *pts,
                        const acbb_cli_study_block *blocks, size_t nb);

#endif
