/* acbb CLI — the sweep's streamed records and their resumption (sweep.h). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "acbb/units.h"
#include "exit.h"
#include "sweep.h"

#define CLI_UM 1e6 /* m -> um */

static void put(char names[][ACBB_CLI_SWEEP_NAME], double *v, size_t *n, const char *name,
                double x)
{
    snprintf(names[*n], ACBB_CLI_SWEEP_NAME, "%s", name);
    v[(*n)++] = x;
}

size_t acbb_cli_sweep_scalars(const acbb_snapshot *snap,
                              char names[][ACBB_CLI_SWEEP_NAME], double *v)
{
    static const acbb_snapshot none;
    const acbb_snapshot *s = snap ? snap : &none;
    const acbb_ball_view *b = &s->balls[0];
    double nan_ = snap ? 0.0 : NAN; /* added to every value: NAN marks "never ran" */
    double ball = snap && s->n_balls > 0 ? 0.0 : NAN;
    size_t n = 0;
    put(names, v, &n, "T_outer_ring_C", s->T_outer_ring + nan_);
    put(names, v, &n, "T_inner_ring_C", s->T_inner_ring + nan_);
    put(names, v, &n, "T_ball_C", s->T_ball + nan_);
    put(names, v, &n, "T_housing_C", s->T_housing + nan_);
    put(names, v, &n, "T_shaft_C", s->T_shaft + nan_);
    put(names, v, &n, "T_cavity_C", s->T_cavity + nan_);
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        char key[ACBB_CLI_SWEEP_NAME];
        snprintf(key, sizeof key, "P_%s_W", acbb_loss_name((acbb_loss_kind)l));
        put(names, v, &n, key, s->losses.P[l] + nan_);
    }
    put(names, v, &n, "P_total_W", s->losses.total + nan_);
    put(names, v, &n, "Qi_N", b->Qi + ball);
    put(names, v, &n, "Qo_N", b->Qo + ball);
    put(names, v, &n, "alpha_i_deg", acbb_rad_to_deg(b->alpha_i) + ball);
    put(names, v, &n, "alpha_o_deg", acbb_rad_to_deg(b->alpha_o) + ball);
    put(names, v, &n, "film_i_um", b->film_i * CLI_UM + ball);
    put(names, v, &n, "film_o_um", b->film_o * CLI_UM + ball);
    put(names, v, &n, "delta_x_um", s->delta_x * CLI_UM + nan_);
    put(names, v, &n, "stiffness_axial_N_um", s->stiffness_axial / CLI_UM + nan_);
    put(names, v, &n, "stiffness_radial_N_um", s->stiffness_radial / CLI_UM + nan_);
    put(names, v, &n, "stiffness_tilt_Nm_mrad", s->stiffness_tilt * 1e-3 + nan_);
    put(names, v, &n, "time_s", s->time + nan_);
    return n;
}

/* "200" -> the number 200; "quasi-static" -> a string (as --set reads it). */
static cJSON *value_json(const char *text)
{
    char *end = NULL;
    double v = strtod(text, &end);
    if (end != text && *end == '\0' && isfinite(v)) return cJSON_CreateNumber(v);
    return cJSON_CreateString(text);
}

static cJSON *grid_json(const acbb_sweep *g, size_t index)
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

static long record_jsonl(FILE *f, const acbb_sweep *g, const acbb_sweep_result *r)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(r->have_snap ? &r->snap : NULL, names, v);
    /* NAN is on purpose only for a point that never ran or has no balls. */
    int checked = r->have_snap && r->snap.n_balls > 0;
    long nonfinite = 0;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "index", (double)r->index);
    cJSON_AddItemToObject(o, "grid", grid_json(g, r->index));
    cJSON_AddStringToObject(o, "status", status_text(r));
    cJSON_AddStringToObject(o, "message", message_text(r));
    cJSON_AddNumberToObject(o, "iterations", r->have_snap ? (double)r->snap.iteration : 0.0);
    for (size_t k = 0; k < n; k++) {
        if (isfinite(v[k])) cJSON_AddNumberToObject(o, names[k], v[k]);
        else cJSON_AddNullToObject(o, names[k]);
        nonfinite += checked && !isfinite(v[k]);
    }
    cJSON_AddNumberToObject(o, "wall_ms", r->wall_ms);
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

/* "index,v1,...,vn," : also what resumption compares a row against. */
static void csv_prefix(char *buf, size_t cap, const acbb_sweep *g, size_t index)
{
    size_t len = (size_t)snprintf(buf, cap, "%zu,", index);
    for (size_t d = 0; d < acbb_sweep_n_dims(g) && len < cap; d++)
        len += (size_t)snprintf(buf + len, cap - len, "%s,", acbb_sweep_value(g, index, d));
}

static long record_csv(FILE *f, const acbb_sweep *g, const acbb_sweep_result *r)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(r->have_snap ? &r->snap : NULL, names, v);
    /* NAN is on purpose only for a point that never ran or has no balls. */
    int checked = r->have_snap && r->snap.n_balls > 0;
    char prefix[ACBB_SWEEP_MAX_DIMS * (ACBB_SWEEP_VALUE + 1) + 32];
    csv_prefix(prefix, sizeof prefix, g, r->index);
    fprintf(f, "%s%s,%ld,", prefix, status_text(r), r->have_snap ? r->snap.iteration : 0L);
    long nonfinite = 0;
    for (size_t k = 0; k < n; k++) {
        if (isfinite(v[k])) fprintf(f, "%.10g", v[k]);
        else nonfinite += checked;
        fputc(',', f);
    }
    csv_text(f, message_text(r));
    fprintf(f, ",%.10g\n", r->wall_ms);
    return nonfinite;
}

long acbb_cli_sweep_record(FILE *f, acbb_cli_rec_format fmt, const acbb_sweep *g,
                           const acbb_sweep_result *r)
{
    return fmt == ACBB_CLI_REC_JSONL ? record_jsonl(f, g, r) : record_csv(f, g, r);
}

void acbb_cli_sweep_csv_header(FILE *f, const acbb_sweep *g, int with_wall)
{
    char names[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t n = acbb_cli_sweep_scalars(NULL, names, v);
    fputs("index", f);
    for (size_t d = 0; d < acbb_sweep_n_dims(g); d++) fprintf(f, ",%s", acbb_sweep_key(g, d));
    fputs(",status,iterations", f);
    for (size_t k = 0; k < n; k++) fprintf(f, ",%s", names[k]);
    fprintf(f, ",message%s\n", with_wall ? ",wall_ms" : "");
}

/* The point a complete record names, checked against the grid: 0, or 2. */
static int parse_record(const char *line, acbb_cli_rec_format fmt, const acbb_sweep *g,
                        size_t *index)
{
    if (fmt == ACBB_CLI_REC_CSV) {
        char *end = NULL;
        unsigned long long i = strtoull(line, &end, 10);
        char want[ACBB_SWEEP_MAX_DIMS * (ACBB_SWEEP_VALUE + 1) + 32];
        if (end == line || *end != ',' || i >= acbb_sweep_n_points(g)) return ACBB_EXIT_INPUT;
        csv_prefix(want, sizeof want, g, (size_t)i);
        *index = (size_t)i;
        return strncmp(line, want, strlen(want)) == 0 ? 0 : ACBB_EXIT_INPUT;
    }
    cJSON *o = cJSON_Parse(line);
    const cJSON *ix = cJSON_GetObjectItemCaseSensitive(o, "index");
    int rc = ACBB_EXIT_INPUT;
    if (cJSON_IsNumber(ix) && ix->valuedouble >= 0 &&
        ix->valuedouble < (double)acbb_sweep_n_points(g) &&
        ix->valuedouble == floor(ix->valuedouble)) {
        *index = (size_t)ix->valuedouble;
        cJSON *want = grid_json(g, *index);
        if (cJSON_Compare(want, cJSON_GetObjectItemCaseSensitive(o, "grid"), 1)) rc = 0;
        cJSON_Delete(want);
    }
    cJSON_Delete(o);
    return rc;
}

/* Cut a record the writer did not finish (killed mid-line). */
static int cut_partial(FILE *f, const char *path, long good_end)
{
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > good_end &&
        ftruncate(fileno(f), good_end) != 0) {
        fprintf(stderr, "acbb: sweep: %s: cannot cut the unfinished last record\n", path);
        return ACBB_EXIT_INPUT;
    }
    return 0;
}

int acbb_cli_sweep_resume(FILE *f, const char *path, acbb_cli_rec_format fmt,
                          const acbb_sweep *g, unsigned char *count, size_t *n_found)
{
    char *line = NULL, *header = NULL;
    size_t cap = 0, hcap = 0;
    ssize_t len;
    long good_end = 0, lineno = 0;
    int rc = 0;
    *n_found = 0;
    rewind(f);
    FILE *h = open_memstream(&header, &hcap);
    if (h) acbb_cli_sweep_csv_header(h, g, 1);
    if (h) fclose(h);
    while (!rc && (len = getline(&line, &cap, f)) > 0) {
        lineno++;
        if (line[len - 1] != '\n') break; /* unfinished: cut below */
        size_t index = 0;
        if (fmt == ACBB_CLI_REC_CSV && lineno == 1) {
            if (!header || strcmp(line, header) != 0) rc = ACBB_EXIT_INPUT;
        } else if (parse_record(line, fmt, g, &index) == 0) {
            if (count[index] < 255) count[index]++;
            ++*n_found;
        } else {
            rc = ACBB_EXIT_INPUT;
        }
        if (rc)
            fprintf(stderr, "acbb: sweep: %s:%ld: not a %s of this sweep's grid; not "
                    "resuming (write to another file)\n", path, lineno,
                    lineno == 1 && fmt == ACBB_CLI_REC_CSV ? "header" : "record");
        good_end += len;
    }
    free(line);
    if (!rc) rc = cut_partial(f, path, good_end);
    fseek(f, 0, SEEK_END); /* from reading to (appending) writing */
    if (!rc && good_end == 0 && fmt == ACBB_CLI_REC_CSV && header) fputs(header, f);
    free(header);
    return rc;
}
