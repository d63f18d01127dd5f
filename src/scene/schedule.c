/* acbb — run-in schedules (schedule.h; MODEL.md 14 "Run-in schedule").
 *
 * The rows' values are read and written through the schema rows of the
 * [operating] keys they stand for (acbb_sf_apply, acbb_scene_field_format),
 * so a row's speed is parsed, range-checked, converted and printed exactly
 * as operating.inner_speed_rpm is: one definition of each unit and range. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acbb/tools/schedule.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"
#include "c_locale.h"

/* The keys a row's columns stand for, in column order after the time. */
static const char *const k_columns[] = { "inner_speed_rpm", "axial_load_N", "radial_load_N" };
#define N_COLUMNS 3

static double *column(acbb_schedule_row *r, int c)
{
    return c == 0 ? &r->inner_speed : c == 1 ? &r->axial_load : &r->radial_load;
}

static double column_of(const acbb_schedule_row *r, int c)
{
    return c == 0 ? r->inner_speed : c == 1 ? r->axial_load : r->radial_load;
}

/* The member of acbb_scene column c is stored in. */
static double *scene_column(acbb_scene *s, int c)
{
    return c == 0 ? &s->inner_speed : c == 1 ? &s->axial_load : &s->radial_load;
}

/* ---- the operating point ---- */

static void from_scene(const acbb_scene *s, acbb_operating *op)
{
    *op = (acbb_operating){ s->inner_speed, s->axial_load, s->radial_load, 0, 0, true };
}

static void from_row(const acbb_scene *s, int i, acbb_operating *op)
{
    const acbb_schedule_row *r = &s->schedule[i];
    *op = (acbb_operating){ r->inner_speed, r->axial_load, r->radial_load, i + 1,
                            s->schedule_n, i == s->schedule_n - 1 };
}

void acbb_schedule_at(const acbb_scene *s, double t, acbb_operating *op)
{
    int n = s->schedule_n;
    if (n <= 0) {
        from_scene(s, op);
        return;
    }
    int i = 0;
    while (i + 1 < n && s->schedule[i + 1].t <= t) i++;
    from_row(s, i, op);
    if (i + 1 >= n || t <= s->schedule[i].t) return;
    /* Linear between rows i and i+1 (MODEL.md 14). */
    const acbb_schedule_row *a = &s->schedule[i], *b = &s->schedule[i + 1];
    double w = (t - a->t) / (b->t - a->t);
    op->inner_speed = a->inner_speed + w * (b->inner_speed - a->inner_speed);
    op->axial_load = a->axial_load + w * (b->axial_load - a->axial_load);
    op->radial_load = a->radial_load + w * (b->radial_load - a->radial_load);
}

void acbb_schedule_final(const acbb_scene *s, acbb_operating *op)
{
    if (s->schedule_n <= 0) from_scene(s, op);
    else from_row(s, s->schedule_n - 1, op);
}

void acbb_schedule_apply(acbb_scene *s, const acbb_operating *op)
{
    s->inner_speed = op->inner_speed;
    s->axial_load = op->axial_load;
    s->radial_load = op->radial_load;
}

double acbb_schedule_end(const acbb_scene *s)
{
    return s->schedule_n > 0 ? s->schedule[s->schedule_n - 1].t : 0.0;
}

/* ---- text ---- */

static acbb_status bad_row(acbb_error *err, const char *text, const char *fmt, const char *what)
{
    char why[200];
    snprintf(why, sizeof why, fmt, what);
    return acbb_error_set(err, ACBB_EINVAL, "schedule.row = %s: %s (a row is t_s, speed_rpm, "
                          "axial_N, radial_N)", text, why);
}

/* Time: a decimal number of seconds >= 0 (hexadecimal refused, as for
 * every preset number, scene_value.c). */
static acbb_status parse_time(const char *tok, const char *text, double *t, acbb_error *err)
{
    char *end;
    const char *d = tok + (tok[0] == '+' || tok[0] == '-');
    double v = acbb_strtod_c(tok, &end);
    bool hex = d[0] == '0' && (d[1] == 'x' || d[1] == 'X');
    if (hex || end == tok || *end != '\0' || !isfinite(v))
        return bad_row(err, text, "t_s = \"%s\": not a decimal number of seconds", tok);
    if (v < 0.0) return bad_row(err, text, "t_s = %s: must be >= 0 s", tok);
    *t = v;
    return ACBB_OK;
}

static acbb_status parse_column(int c, const char *tok, const char *text, acbb_schedule_row *r,
                                acbb_error *err)
{
    const acbb_sfield *f = acbb_sf_find("operating", k_columns[c]);
    acbb_scene tmp;
    acbb_scene_default(&tmp);
    acbb_error e;
    if (acbb_sf_apply(&tmp, f, tok, &e) != ACBB_OK)
        return acbb_error_set(err, ACBB_EINVAL, "schedule.row = %s: column %d is %s", text,
                              c + 2, e.msg);
    *column(r, c) = *scene_column(&tmp, c);
    return ACBB_OK;
}

acbb_status acbb_schedule_parse_row(const char *text, acbb_schedule_row *row, acbb_error *err)
{
    char buf[256], *tok[N_COLUMNS + 2];
    /* Cut short, a row would be read as another (a value's digits or a
     * fifth value dropped, silently): refused whole (issue 26 fuzzing). */
    if (strlen(text) >= sizeof buf) {
        char head[48];
        snprintf(head, sizeof head, "%.40s...", text);
        return bad_row(err, head, "%s", "longer than 255 characters");
    }
    snprintf(buf, sizeof buf, "%s", text);
    int n = 0;
    for (char *p = buf, *save = NULL; n < N_COLUMNS + 2; p = NULL) {
        char *t = strtok_r(p, ",", &save);
        if (!t) break;
        t += strspn(t, " \t");
        for (size_t l = strlen(t); l > 0 && strchr(" \t\r\n", t[l - 1]); l--) t[l - 1] = '\0';
        tok[n++] = t;
    }
    if (n != N_COLUMNS + 1)
        return bad_row(err, text, "%s", n > N_COLUMNS + 1 ? "more than 4 values"
                                                          : "fewer than 4 values");
    acbb_schedule_row r;
    acbb_status rc = parse_time(tok[0], text, &r.t, err);
    for (int c = 0; c < N_COLUMNS && rc == ACBB_OK; c++)
        rc = parse_column(c, tok[c + 1], text, &r, err);
    if (rc == ACBB_OK) *row = r;
    return rc;
}

/* A real value through a schema row's exact formatting (format_real in
 * scene_schema.c: the shortest text that reads back to the same double). */
static void format_as(const char *section, const char *key, double si, char *buf, size_t n)
{
    const acbb_sfield *f = acbb_sf_find(section, key);
    acbb_scene tmp;
    acbb_scene_default(&tmp);
    memcpy((char *)&tmp + f->off, &si, sizeof si);
    acbb_scene_field_format(&tmp, (size_t)(f - acbb_sf_table), buf, n);
}

void acbb_schedule_format_row(const acbb_scene *s, int i, char *buf, size_t n)
{
    char v[N_COLUMNS + 1][64];
    const acbb_schedule_row *r = &s->schedule[i];
    format_as("thermal", "max_time_s", r->t, v[0], sizeof v[0]);
    for (int c = 0; c < N_COLUMNS; c++)
        format_as("operating", k_columns[c], column_of(r, c), v[c + 1], sizeof v[c + 1]);
    snprintf(buf, n, "%s, %s, %s, %s", v[0], v[1], v[2], v[3]);
}

/* ---- all rows as one value (--set schedule.rows=...) ---- */

acbb_status acbb_sf_schedule_set(acbb_scene *s, const char *key, const char *value,
                                 int cross_check, acbb_error *err)
{
    if (strcmp(key, "rows") != 0)
        return acbb_error_set(err, ACBB_EINVAL, "schedule.%s: unknown key (schedule.rows = "
                              "\"t_s, speed_rpm, axial_N, radial_N; ...\", ';' between rows)", key);
    char *buf = strdup(value);
    if (!buf) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_scene trial = *s;
    trial.schedule_n = 0;
    acbb_status rc = ACBB_OK;
    for (char *save = NULL, *p = strtok_r(buf, ";", &save); p && rc == ACBB_OK;
         p = strtok_r(NULL, ";", &save)) {
        if (p[strspn(p, " \t")] == '\0') continue;   /* "" or a trailing ';' */
        if (trial.schedule_n == ACBB_SCHEDULE_MAX)
            rc = acbb_error_set(err, ACBB_EINVAL, "schedule.rows: more than %d rows",
                                ACBB_SCHEDULE_MAX);
        else
            rc = acbb_schedule_parse_row(p, &trial.schedule[trial.schedule_n++], err);
    }
    free(buf);
    if (rc == ACBB_OK && cross_check) rc = acbb_scene_validate(&trial, err);
    if (rc == ACBB_OK) *s = trial;
    else if (err && strncmp(err->msg, "schedule.rows", 13) != 0) {
        /* the key the user wrote, then which row and why */
        char why[sizeof err->msg];
        snprintf(why, sizeof why, "%s", err->msg);
        acbb_error_set(err, rc, "schedule.rows: %s", why);
    }
    return rc;
}

/* ---- rules ---- */

static acbb_status row_fail_code(const acbb_scene *s, int i, acbb_status code, acbb_error *err,
                                 const char *why)
{
    char t[64];
    format_as("thermal", "max_time_s", s->schedule[i].t, t, sizeof t);
    return acbb_error_set(err, code, "schedule row %d (t = %s s): %s", i + 1, t, why);
}

static acbb_status row_fail(const acbb_scene *s, int i, acbb_error *err, const char *why)
{
    return row_fail_code(s, i, ACBB_EINVAL, err, why);
}

/* Order and count of the rows, and the run long enough to reach the last. */
static acbb_status check_times(const acbb_scene *s, acbb_error *err)
{
    char why[200], a[64];
    if (s->schedule_n < 0 || s->schedule_n > ACBB_SCHEDULE_MAX)
        return acbb_error_set(err, ACBB_EINVAL, "schedule: %d rows; at most %d", s->schedule_n,
                              ACBB_SCHEDULE_MAX);
    if (s->schedule[0].t != 0.0)
        return row_fail(s, 0, err, "the first row is the start of the run: its t_s must be 0");
    for (int i = 1; i < s->schedule_n; i++) {
        if (s->schedule[i].t > s->schedule[i - 1].t) continue;
        format_as("thermal", "max_time_s", s->schedule[i - 1].t, a, sizeof a);
        snprintf(why, sizeof why, "times must increase strictly (the row before is at %s s)", a);
        return row_fail(s, i, err, why);
    }
    if (acbb_schedule_end(s) < s->max_time) return ACBB_OK;
    format_as("thermal", "max_time_s", s->max_time, a, sizeof a);
    snprintf(why, sizeof why, "the last row must come before thermal.max_time_s = %s s (the run "
             "would stop before the schedule ends)", a);
    return row_fail(s, s->schedule_n - 1, err, why);
}

/* Row i's values against their keys' ranges, then the scene's rules at
 * row i's operating point (a copy without rows: no recursion). */
static acbb_status check_row(const acbb_scene *s, int i, acbb_error *err)
{
    char why[256];
    for (int c = 0; c < N_COLUMNS; c++) {
        const acbb_sfield *f = acbb_sf_find("operating", k_columns[c]);
        acbb_sf_range_reason(f, column_of(&s->schedule[i], c) / f->scale, why, sizeof why);
        if (why[0]) {
            char m[300];
            snprintf(m, sizeof m, "%s (as operating.%s)", why, k_columns[c]);
            return row_fail(s, i, err, m);
        }
    }
    acbb_scene at = *s;
    at.schedule_n = 0;
    acbb_operating op;
    acbb_schedule_at(s, s->schedule[i].t, &op);
    acbb_schedule_apply(&at, &op);
    acbb_error e;
    acbb_status rc = acbb_scene_validate(&at, &e);
    return rc == ACBB_OK ? ACBB_OK : row_fail_code(s, i, rc, err, e.msg);
}

acbb_status acbb_sf_schedule_check(const acbb_scene *s, int *row, acbb_error *err)
{
    *row = -1;
    if (s->schedule_n == 0) return ACBB_OK;
    acbb_status rc = check_times(s, err);
    if (rc != ACBB_OK) *row = s->schedule_n > 0 && s->schedule_n <= ACBB_SCHEDULE_MAX
                                  ? s->schedule_n - 1 : -1;
    for (int i = 0; i < s->schedule_n && rc == ACBB_OK; i++)
        if ((rc = check_row(s, i, err)) != ACBB_OK) *row = i;
    return rc;
}

acbb_status acbb_schedule_validate(const acbb_scene *s, acbb_error *err)
{
    int row;
    return acbb_sf_schedule_check(s, &row, err);
}
