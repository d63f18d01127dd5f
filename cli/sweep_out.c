/* acbb CLI — the sweep's streamed records and their resumption (sweep.h). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/tools/json.h"
#include "acbb/outputs.h"
#include "output.h"
#include "acbb/units.h"
#include "exit.h"
#include "sweep.h"
#include "say.h"

/* The scalars of a record, by their run JSON paths (one name per quantity:
 * outputs.h), ball entries of ball 0; `losses_W.*` expands to every loss
 * kind. Their values come from the output table, as `acbb run --json`
 * computes them. */
static const char *const k_scalars[] = {
    "temperature_C.outer_ring", "temperature_C.inner_ring", "temperature_C.ball",
    "temperature_C.housing", "temperature_C.shaft", "temperature_C.cavity", "losses_W.*",
    "losses_W.total", "balls[0].Qi_N", "balls[0].Qo_N", "balls[0].alpha_i_deg",
    "balls[0].alpha_o_deg", "balls[0].film_i_um", "balls[0].film_o_um", "ring.delta_x_um",
    "ring.stiffness_axial_N_per_um", "ring.stiffness_radial_N_per_um",
    "ring.stiffness_tilt_Nm_per_mrad",
};

static void put(char names[][ACBB_CLI_SWEEP_NAME], double *v, size_t *n,
                const acbb_output *e, long ball, const acbb_snapshot *snap)
{
    acbb_output_flat(e, names[*n], ACBB_CLI_SWEEP_NAME);
    /* NAN marks "never ran" (and no ball 0) */
    v[(*n)++] = snap ? acbb_output_value(e, snap, ball < 0 ? 0 : (int)ball) : NAN;
}

/* The set's metrics (MODEL.md 14; acbb metrics' set.* rows), by their
 * output-table paths: a sweep of a set carries them, a point that is one
 * bearing leaves them empty (CSV) or out (JSONL). */
static const char *const k_set_cols[] = {
    "set.preload_N", "set.preload_assembly_N", "set.liftoff_thrust_N",
    "set.liftoff_remainder_N", "set.stiffness_axial_N_per_um", "set.stiffness_radial_N_per_um",
    "set.stiffness_tilt_Nm_per_mrad", "set.spacer_growth_um",
};
#define N_SET_COLS (sizeof k_set_cols / sizeof k_set_cols[0])

static void put_set(const acbb_snapshot *snap, char names[][ACBB_CLI_SWEEP_NAME], double *v,
                    size_t *n)
{
    for (size_t c = 0; c < N_SET_COLS; c++) {
        acbb_output o;
        long ball;
        if (acbb_output_find(k_set_cols[c], &o, &ball, NULL) != ACBB_OK) abort(); /* a bug */
        acbb_output_flat(&o, names[*n], ACBB_CLI_SWEEP_NAME);
        v[(*n)++] = snap && snap->n_bearings > 1 ? acbb_output_value(&o, snap, 0) : NAN;
    }
}

/* A set column of a point that is one bearing is empty on purpose. */
static int is_set_col(const char *name) { return strncmp(name, "set.", 4) == 0; }

size_t acbb_cli_sweep_scalars(const acbb_snapshot *snap,
                              char names[][ACBB_CLI_SWEEP_NAME], double *v)
{
    size_t n = 0;
    for (size_t i = 0; i < sizeof k_scalars / sizeof k_scalars[0]; i++) {
        acbb_output e;
        long ball;
        size_t len = strlen(k_scalars[i]);
        if (strcmp(k_scalars[i] + len - 2, ".*") != 0) {
            if (acbb_output_find(k_scalars[i], &e, &ball, NULL) != ACBB_OK) abort(); /* a bug */
            put(names, v, &n, &e, ball, snap);
            continue;
        }
        for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
            char path[ACBB_CLI_SWEEP_NAME];
            snprintf(path, sizeof path, "%.*s.%s", (int)(len - 2), k_scalars[i],
                     acbb_loss_name((acbb_loss_kind)l));
            if (acbb_output_find(path, &e, &ball, NULL) != ACBB_OK) abort();
            put(names, v, &n, &e, ball, snap);
        }
    }
    snprintf(names[n], ACBB_CLI_SWEEP_NAME, "time_s");
    v[n++] = snap ? snap->time : NAN;
    put_set(snap, names, v, &n);
    return n;
}

int acbb_cli_sweep_dropped(const acbb_cli_metrics *m, const char *name)
{
    return m->no_stiffness && strstr(name, ".stiffness_") != NULL;
}

size_t acbb_cli_sweep_n_scalars(const acbb_cli_metrics *m)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(NULL, names, v), kept = 0;
    for (size_t k = 0; k < n; k++) kept += !acbb_cli_sweep_dropped(m, names[k]);
    return kept;
}

/* "200" -> the number 200; "quasi-static" -> a string (as --set reads it). */
static cJSON *value_json(const char *text)
{
    char *end = NULL;
    double v = strtod(text, &end);
    if (end != text && *end == '\0' && isfinite(v)) return cJSON_CreateNumber(v);
    return cJSON_CreateString(text);
}

cJSON *acbb_cli_sweep_grid_json(const acbb_sweep *g, size_t index)
{
    cJSON *o = cJSON_CreateObject();
    for (size_t d = 0; o && d < acbb_sweep_n_dims(g); d++)
        cJSON_AddItemToObject(o, acbb_sweep_key(g, d), value_json(acbb_sweep_value(g, index, d)));
    return o;
}

static const char *status_text(const acbb_sweep_result *r)
{
    return r->have_snap ? acbb_run_status_name(&r->snap) : acbb_status_name(r->status);
}

static const char *message_text(const acbb_sweep_result *r)
{
    return r->have_snap ? r->snap.message : r->message;
}

static long record_jsonl(FILE *f, const acbb_cli_sweep_id *id, const acbb_sweep_result *r)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(r->have_snap ? &r->snap : NULL, names, v);
    /* NAN is on purpose only for a point that never ran or has no balls. */
    int checked = r->have_snap && r->snap.n_balls > 0;
    long nonfinite = 0;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddNumberToObject(o, "index", (double)r->index);
    cJSON_AddStringToObject(o, "fingerprint", id->fp);
    cJSON_AddItemToObject(o, "grid", acbb_cli_sweep_grid_json(id->g, r->index));
    cJSON_AddStringToObject(o, "status", status_text(r));
    cJSON_AddStringToObject(o, "message", message_text(r));
    cJSON_AddNumberToObject(o, "iterations", r->have_snap ? (double)r->snap.iteration : 0.0);
    int set = r->have_snap && r->snap.n_bearings > 1;
    for (size_t k = 0; k < n; k++) {
        if ((is_set_col(names[k]) && !set) || acbb_cli_sweep_dropped(&id->metrics, names[k]))
            continue;
        cJSON_AddItemToObject(o, names[k], acbb_cli_json_number(v[k]));
        nonfinite += checked && !isfinite(v[k]);
    }
    for (size_t k = 0; k < id->metrics.n; k++) {
        int expected = 1;
        double x = acbb_cli_sweep_metric_value(r->have_snap ? &r->snap : NULL,
                                               id->metrics.path[k], &expected);
        cJSON_AddItemToObject(o, id->metrics.path[k], acbb_cli_json_number(x));
        nonfinite += !expected && !isfinite(x);
    }
    cJSON_AddItemToObject(o, "wall_ms", acbb_cli_json_number(r->wall_ms));
    char *text = cJSON_PrintUnformatted(o);
    cJSON_Delete(o);
    if (!text) return 1;
    fprintf(f, "%s\n", text);
    cJSON_free(text);
    return nonfinite;
}

/* RFC 4180: quoted, quotes doubled; a newline becomes a blank (one record
 * per line). */
static void csv_text(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"') fputs("\"\"", f);
        else fputc(*s == '\n' || *s == '\r' ? ' ' : *s, f);
    }
    fputc('"', f);
}

/* "index,fingerprint,v1,...,vn,". */
static void csv_prefix(char *buf, size_t cap, const acbb_cli_sweep_id *id, size_t index)
{
    const acbb_sweep *g = id->g;
    size_t len = (size_t)snprintf(buf, cap, "%zu,%s,", index, id->fp);
    for (size_t d = 0; d < acbb_sweep_n_dims(g) && len < cap; d++)
        len += (size_t)snprintf(buf + len, cap - len, "%s,", acbb_sweep_value(g, index, d));
}

static long record_csv(FILE *f, const acbb_cli_sweep_id *id, const acbb_sweep_result *r)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(r->have_snap ? &r->snap : NULL, names, v);
    /* NAN is on purpose only for a point that never ran or has no balls. */
    int checked = r->have_snap && r->snap.n_balls > 0;
    char prefix[ACBB_SWEEP_MAX_DIMS * (ACBB_SWEEP_VALUE + 1) + 64];
    csv_prefix(prefix, sizeof prefix, id, r->index);
    fprintf(f, "%s%s,%ld,", prefix, status_text(r), r->have_snap ? r->snap.iteration : 0L);
    long nonfinite = 0;
    int set = r->have_snap && r->snap.n_bearings > 1;
    for (size_t k = 0; k < n; k++) {
        if (acbb_cli_sweep_dropped(&id->metrics, names[k])) continue;
        if (isfinite(v[k])) fprintf(f, "%.17g", v[k]);
        else nonfinite += checked && (set || !is_set_col(names[k]));
        fputc(',', f);
    }
    for (size_t k = 0; k < id->metrics.n; k++) {
        int expected = 1;
        double x = acbb_cli_sweep_metric_value(r->have_snap ? &r->snap : NULL,
                                               id->metrics.path[k], &expected);
        if (isfinite(x)) fprintf(f, "%.17g", x);
        else nonfinite += !expected;
        fputc(',', f);
    }
    csv_text(f, message_text(r));
    fprintf(f, ",%.17g\n", r->wall_ms);
    return nonfinite;
}

long acbb_cli_sweep_record(FILE *f, acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                           const acbb_sweep_result *r)
{
    return fmt == ACBB_CLI_REC_JSONL ? record_jsonl(f, id, r) : record_csv(f, id, r);
}

char *acbb_cli_sweep_record_text(acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                                 const acbb_sweep_result *r, size_t *len, long *nonfinite)
{
    char *text = NULL;
    FILE *m = open_memstream(&text, len);
    if (!m) return NULL;
    *nonfinite += acbb_cli_sweep_record(m, fmt, id, r);
    if (fclose(m) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

void acbb_cli_sweep_csv_header(FILE *f, const acbb_sweep *g, const acbb_cli_metrics *m,
                               int with_wall)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(NULL, names, v);
    fputs("index,fingerprint", f);
    for (size_t d = 0; d < acbb_sweep_n_dims(g); d++) fprintf(f, ",%s", acbb_sweep_key(g, d));
    fputs(",status,iterations", f);
    for (size_t k = 0; k < n; k++)
        if (!acbb_cli_sweep_dropped(m, names[k])) fprintf(f, ",%s", names[k]);
    for (size_t k = 0; k < m->n; k++) fprintf(f, ",%s", m->path[k]);
    fprintf(f, ",message%s\n", with_wall ? ",wall_ms" : "");
}

/* Cut what the writer did not finish (killed mid-line, a failed write). */
static int cut_partial(FILE *f, const char *path, long good_end)
{
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > good_end &&
        ftruncate(fileno(f), good_end) != 0) {
        acbb_cli_say("sweep: %s: cannot cut the unfinished last record\n", path);
        return ACBB_EXIT_INPUT;
    }
    return 0;
}

/* Line `line` (no newline: the writer stopped in it) is the start of this
 * sweep's header text at byte `at`: the header was cut short, nothing
 * else is in the file. */
static int header_prefix(const acbb_cli_sweep_id *id, acbb_cli_rec_format fmt, size_t at,
                         const char *line)
{
    size_t len = 0, n = strlen(line);
    char *mine = acbb_cli_sweep_header_text(fmt, id, 1, &len);
    int yes = mine && at + n <= len && memcmp(mine + at, line, n) == 0;
    free(mine);
    return yes;
}

/* The CSV column line `cols` (n bytes, lineno): 0 this sweep's; 1 a
 * prefix of it that the writer did not finish; -1 another, said. */
static int resume_columns(const char *path, const acbb_cli_sweep_id *id, const char *cols,
                          ssize_t n, long lineno)
{
    char *mine = NULL;
    size_t mcap = 0;
    int rc = 0;
    FILE *h = open_memstream(&mine, &mcap);
    if (h) acbb_cli_sweep_csv_header(h, id->g, &id->metrics, 1), fclose(h);
    if (mine && (n <= 0 || (cols[n - 1] != '\n' && strncmp(cols, mine, (size_t)n) == 0)))
        rc = 1; /* killed before the column line was whole */
    else if (!mine || strcmp(cols, mine) != 0) {
        acbb_cli_say("sweep: %s:%ld: not this sweep's column header; not resuming "
                "(write to another file)\n", path, lineno);
        rc = -1;
    }
    free(mine);
    return rc;
}

/* A CSV whose header form (sidecar or first line, --csv-header) is not
 * the one asked for: said, so the user adds or drops the option. */
static int other_form(const char *path, const acbb_cli_sweep_id *id, const char *line)
{
    int headed = strncmp(line, "# ", 2) == 0;
    if (headed == id->csv_header) return 0;
    acbb_cli_say("sweep: %s: %s; not resuming (run the same command %s, or write to "
            "another file)\n", path,
            headed ? "its first line is the sweep's header (written with --csv-header)"
                   : "a plain CSV (the sweep's header beside it, in .json)",
            headed ? "with --csv-header" : "without --csv-header");
    return -1;
}

/* The first line(s) of an existing output: 0 this sweep's header; 1 this
 * sweep's header cut short (the CSV column line unfinished); -1 another
 * sweep's, with a message naming what differs. A plain CSV (no
 * --csv-header) starts with its column line: its header, the sidecar, was
 * checked when the file was opened (sweep_sink.c). */
static int resume_header(FILE *f, const char *path, acbb_cli_rec_format fmt,
                         const acbb_cli_sweep_id *id, const char *line, long *lineno)
{
    if (fmt == ACBB_CLI_REC_CSV && other_form(path, id, line)) return -1;
    if (fmt == ACBB_CLI_REC_CSV && !id->csv_header)
        return resume_columns(path, id, line, (ssize_t)strlen(line), *lineno);
    cJSON *got = acbb_cli_sweep_header_parse(line, fmt), *want = acbb_cli_sweep_header_of(id);
    char diff[400];
    int rc = -1;
    if (!got)
        acbb_cli_say("sweep: %s:%ld: no sweep header (an output of record format %d "
                "starts with one); not resuming (write to another file)\n", path, *lineno,
                ACBB_SWEEP_FORMAT);
    else if (acbb_cli_sweep_header_diff(got, want, diff, sizeof diff))
        acbb_cli_say("sweep: %s: written by another sweep; not resuming (write to "
                "another file). Differs (file vs now): %s\n", path, diff);
    else
        rc = 0;
    cJSON_Delete(got);
    cJSON_Delete(want);
    if (rc || fmt != ACBB_CLI_REC_CSV) return rc;
    /* CSV: the column header follows. */
    char *cols = NULL;
    size_t cap = 0;
    ++*lineno;
    ssize_t n = getline(&cols, &cap, f);
    rc = resume_columns(path, id, cols ? cols : "", n, *lineno);
    free(cols);
    return rc;
}

/* One record line: counted when its result is kept. */
static int resume_record(const char *line, const char *path, long lineno,
                         acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                         unsigned char *count)
{
    size_t index = 0;
    const char *why = "";
    if (acbb_cli_sweep_check_record(line, fmt, id->g, &id->metrics, id->fp, 1, &index, &why) != 0) {
        acbb_cli_say("sweep: %s:%ld: not a record of this sweep (%s); not "
                "resuming (write to another file)\n", path, lineno, why);
        return ACBB_EXIT_INPUT;
    }
    if (!acbb_cli_sweep_record_retried(line, fmt, id->g) && count[index] < 255) count[index]++;
    return 0;
}

int acbb_cli_sweep_resume(FILE *f, const char *path, acbb_cli_rec_format fmt,
                          const acbb_cli_sweep_id *id, unsigned char *count, size_t *n_found,
                          int *have_header)
{
    char *line = NULL;
    size_t cap = 0;
    ssize_t len;
    long good_end = 0, lineno = 0;
    int rc = 0;
    *n_found = 0;
    *have_header = 0;
    rewind(f);
    while (!rc && (len = getline(&line, &cap, f)) > 0) {
        lineno++;
        if (line[len - 1] != '\n') { /* unfinished: cut below */
            if (lineno == 1 && !header_prefix(id, fmt, 0, line)) {
                acbb_cli_say("sweep: %s:1: neither a sweep header nor the start of "
                        "this sweep's; not resuming (write to another file)\n", path);
                rc = ACBB_EXIT_INPUT;
            }
            break;
        }
        if (lineno == 1) {
            int h = resume_header(f, path, fmt, id, line, &lineno);
            if (h < 0) rc = ACBB_EXIT_INPUT;
            if (h) break; /* h == 1: a header cut short, no records: written again */
            good_end = ftell(f);
            *have_header = 1;
            continue;
        }
        rc = resume_record(line, path, lineno, fmt, id, count);
        if (!rc) ++*n_found, good_end += len;
    }
    free(line);
    if (!rc) rc = cut_partial(f, path, good_end);
    fseek(f, 0, SEEK_END); /* from reading to (appending) writing */
    return rc;
}
