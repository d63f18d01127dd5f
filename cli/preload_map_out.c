/* acbb CLI — `acbb preload-map`'s files: the CSV and the --json document,
 * one column / key per quantity named as everywhere else (issue 28 item
 * 7): the scene keys the map varies (operating.inner_speed_rpm,
 * mounting.preload_N), `acbb metrics` paths for the results it reads
 * (life.Lnmr_h, life.s0_min), and the map's own skid_ratio and
 * temp_rise_K; numbers with 17 significant digits (the double itself). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include "acbb/tools/json.h"
#include "output.h"
#include "preload_map_out.h"

static const char *const k_cols[] = { "operating.inner_speed_rpm", "mounting.preload_N",
                                      "status", "verdict", "skid_ratio", "temp_rise_K",
                                      "life.Lnmr_h", "life.s0_min" };

static void num(FILE *f, double v)
{
    fputc(',', f);
    if (isfinite(v)) fprintf(f, "%.17g", v);
}

void acbb_cli_pmap_csv(FILE *f, const acbb_pmap_cell *c, size_t n)
{
    for (size_t k = 0; k < sizeof k_cols / sizeof k_cols[0]; k++)
        fprintf(f, "%s%s", k ? "," : "", k_cols[k]);
    fputc('\n', f);
    for (size_t i = 0; i < n; i++) {
        fprintf(f, "%.17g,%.17g,%s,%s", c[i].speed_rpm, c[i].preload_N, c[i].status_name,
                acbb_pmap_verdict(&c[i]));
        if (c[i].have) {
            num(f, c[i].skid);
            num(f, c[i].rise_K);
            num(f, c[i].Lnmr_h);
            num(f, c[i].s0_min);
            fputc('\n', f);
        } else {
            fputs(",,,,\n", f);
        }
    }
}

static cJSON *cell_json(const acbb_pmap_cell *c)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, k_cols[0], acbb_cli_json_number(c->speed_rpm));
    cJSON_AddItemToObject(o, k_cols[1], acbb_cli_json_number(c->preload_N));
    cJSON_AddStringToObject(o, k_cols[2], c->status_name);
    cJSON_AddStringToObject(o, k_cols[3], acbb_pmap_verdict(c));
    double v[4] = { c->skid, c->rise_K, c->Lnmr_h, c->s0_min };
    for (int k = 0; k < 4; k++)
        cJSON_AddItemToObject(o, k_cols[4 + k], acbb_cli_json_number(c->have ? v[k] : NAN));
    return o;
}

/* -1 (none on the grid) is null. */
static cJSON *preload(double v) { return acbb_cli_json_number(v >= 0 ? v : NAN); }

static cJSON *row_json(const acbb_pmap_row *r)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, k_cols[0], acbb_cli_json_number(r->speed_rpm));
    cJSON_AddItemToObject(o, "skid_free_N", preload(r->skid_free_N));
    cJSON_AddItemToObject(o, "upper_N", preload(r->upper_N));
    cJSON_AddItemToObject(o, "window_lo_N", preload(r->lo_N));
    cJSON_AddItemToObject(o, "window_hi_N", preload(r->hi_N));
    return o;
}

/* A limit of 0 is not checked: null. */
static cJSON *limit(double v) { return acbb_cli_json_number(v > 0 ? v : NAN); }

long acbb_cli_pmap_json(FILE *f, const acbb_pmap_opts *o, const acbb_pmap_cell *c,
                        const acbb_pmap_row *r)
{
    cJSON *top = cJSON_CreateObject(), *m = cJSON_CreateObject();
    cJSON_AddNumberToObject(top, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddStringToObject(m, "preload", o->spring ? "spring" : "rigid");
    cJSON *lim = cJSON_AddObjectToObject(m, "limits");
    cJSON_AddItemToObject(lim, "skid_ratio", acbb_cli_json_number(1.0));
    cJSON_AddItemToObject(lim, "max_rise_K", limit(o->max_rise_K));
    cJSON_AddItemToObject(lim, "min_life_h", limit(o->min_life_h));
    cJSON_AddItemToObject(lim, "min_s0", limit(o->min_s0));
    cJSON *cells = cJSON_AddArrayToObject(m, "cells"), *rows = cJSON_AddArrayToObject(m, "rows");
    for (size_t i = 0; i < (size_t)o->n_speeds * o->n_preloads; i++)
        cJSON_AddItemToArray(cells, cell_json(&c[i]));
    for (int s = 0; s < o->n_speeds; s++) cJSON_AddItemToArray(rows, row_json(&r[s]));
    cJSON_AddItemToObject(top, "preload_map", m);
    char *text = cJSON_Print(top);
    cJSON_Delete(top);
    if (!text) return -1;
    fprintf(f, "%s\n", text);
    cJSON_free(text);
    return 0;
}
