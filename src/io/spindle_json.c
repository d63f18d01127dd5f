/* acbb — the `spindle` object of a run's JSON (spindle.h, docs/spindle.md):
 * the output table's "spindle..." rows (so the JSON, the metrics and the
 * sweeps name and convert each result once), then what the table cannot
 * hold: each set's position, bearing count and per-bearing arrays, the
 * lift-off flag, and the temperatures along the shaft and the housing. */
#include <stdio.h>
#include "acbb/tools/json.h"
#include "acbb/outputs.h"
#include "spindle_json.h"

#define M_TO_MM 1e3

static int clamp(int n, int cap) { return n < 0 ? 0 : n > cap ? cap : n; }

/* A sub-object of the table, "spindle.NAME", on one line. */
static void part(acbb_json *j, const acbb_snapshot *s, const char *name)
{
    char sec[48];
    snprintf(sec, sizeof sec, "spindle.%s", name);
    acbb_json_open(j, name, '{', true);
    acbb_json_table_rows(j, s, sec);
    acbb_json_close(j, '}');
}

/* v[0..n) as a JSON array on one line, each scaled by `scale`. */
static void array(acbb_json *j, const char *key, const double *v, int n, double scale)
{
    acbb_json_open(j, key, '[', true);
    for (int i = 0; i < n; i++) acbb_json_num(j, NULL, v[i] * scale);
    acbb_json_close(j, ']');
}

/* Set k: 0 the front set, 1 the rear set (spindle.h). */
static void set(acbb_json *j, const acbb_snapshot *s, int k)
{
    const acbb_spindle_set_view *t = &s->spindle.sets[k];
    int n = clamp(t->n_bearings, ACBB_MAX_SET);
    char sec[32];
    snprintf(sec, sizeof sec, "spindle.sets[%d]", k);
    acbb_json_open(j, NULL, '{', false);
    acbb_json_str(j, "position", k == 0 ? "front" : "rear");
    acbb_json_num(j, "x_mm", t->x * M_TO_MM);
    acbb_json_long(j, "bearings", t->n_bearings);
    acbb_json_table_rows(j, s, sec);
    array(j, "contact_angle_inner_deg", t->contact_angle_inner_deg, n, 1.0);
    array(j, "contact_angle_outer_deg", t->contact_angle_outer_deg, n, 1.0);
    array(j, "Q_max_N", t->Q_max_N, n, 1.0);
    acbb_json_bool(j, "contact_lost", t->contact_lost != 0);
    acbb_json_close(j, '}');
}

/* Cell centres (mm from the nose) and their temperatures (C). */
static void profile(acbb_json *j, const char *key, int n, const double *x, const double *T)
{
    n = clamp(n, ACBB_SPINDLE_MAX_CELLS);
    acbb_json_open(j, key, '{', false);
    array(j, "x_mm", x, n, M_TO_MM);
    array(j, "T_C", T, n, 1.0);
    acbb_json_close(j, '}');
}

void acbb_json_write_spindle(acbb_json *j, const acbb_snapshot *s)
{
    const acbb_spindle_view *v = &s->spindle;
    acbb_json_open(j, "spindle", '{', false);
    acbb_json_table_rows(j, s, "spindle");
    part(j, s, "nose_displacement_um");
    part(j, s, "heat_W");
    part(j, s, "coolant_C");
    acbb_json_open(j, "sets", '[', false);
    for (int k = 0; k < clamp(v->n_sets, ACBB_SPINDLE_SETS); k++) set(j, s, k);
    acbb_json_close(j, ']');
    profile(j, "shaft", v->n_shaft, v->shaft_x, v->shaft_T_C);
    profile(j, "housing", v->n_housing, v->housing_x, v->housing_T_C);
    acbb_json_close(j, '}');
}
