/* acbb CLI — which sweep an output belongs to (sweep.h; issue 20 items
 * 3-4): the header line every output starts with, the fingerprint every
 * record carries, and the checks `acbb merge` and a resumed sweep make, so
 * records of another scene, grid, run mode or record version are never
 * mixed in. */
#include <cjson/cJSON.h>
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/tools/outfile.h"
#include "acbb/tools/scene_schema.h"
#include "sweep.h"

void acbb_cli_sweep_id_init(acbb_cli_sweep_id *id, const acbb_sweep *g, const acbb_scene *base,
                            int transient, const acbb_cli_metrics *metrics)
{
    memset(id, 0, sizeof *id);
    id->g = g;
    id->base = base;
    id->transient = transient;
    if (metrics) id->metrics = *metrics;
    uint64_t h = acbb_sweep_fingerprint(g, base, transient);
    for (size_t k = 0; k < id->metrics.n; k++) {
        h = acbb_hash64("metrics=", 8, h);
        h = acbb_hash64(id->metrics.path[k], strlen(id->metrics.path[k]), h);
        h = acbb_hash64("\n", 1, h);
    }
    if (id->metrics.no_stiffness) h = acbb_hash64("stiffness=off\n", 14, h);
    snprintf(id->fp, sizeof id->fp, "%016llx", (unsigned long long)h);
}

/* {"format":2,"fingerprint":..,"mode":..,"grid":{k:[v..]},"scene":{k:v..}} */
static cJSON *header_json(const acbb_cli_sweep_id *id)
{
    cJSON *h = cJSON_CreateObject(), *grid = cJSON_CreateObject(), *sc = cJSON_CreateObject();
    cJSON_AddNumberToObject(h, "format", ACBB_SWEEP_FORMAT);
    cJSON_AddStringToObject(h, "fingerprint", id->fp);
    cJSON_AddStringToObject(h, "mode", id->transient ? "transient" : "steady");
    for (size_t d = 0; d < acbb_sweep_n_dims(id->g); d++) {
        cJSON *vals = cJSON_AddArrayToObject(grid, acbb_sweep_key(id->g, d));
        size_t stride = 1;
        for (size_t e = d + 1; e < acbb_sweep_n_dims(id->g); e++)
            stride *= acbb_sweep_n_values(id->g, e);
        for (size_t v = 0; vals && v < acbb_sweep_n_values(id->g, d); v++)
            cJSON_AddItemToArray(vals, cJSON_CreateString(acbb_sweep_value(id->g, v * stride, d)));
    }
    char key[160], val[128];
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        if (!acbb_sweep_scene_key(id->g, i, key, sizeof key)) continue;
        acbb_scene_field_format(id->base, i, val, sizeof val);
        cJSON_AddStringToObject(sc, key, val);
    }
    char rows[ACBB_SWEEP_SCHEDULE_TEXT];
    acbb_sweep_schedule_text(id->base, rows, sizeof rows);
    cJSON_AddStringToObject(sc, ACBB_SWEEP_SCHEDULE_KEY, rows);
    cJSON_AddItemToObject(h, "grid", grid);
    cJSON_AddItemToObject(h, "scene", sc);
    if (id->metrics.n) { /* absent without --metric: the header it always had */
        cJSON *m = cJSON_AddArrayToObject(h, "metrics");
        for (size_t k = 0; m && k < id->metrics.n; k++)
            cJSON_AddItemToArray(m, cJSON_CreateString(id->metrics.path[k]));
    }
    if (id->metrics.no_stiffness) cJSON_AddFalseToObject(h, "stiffness");
    cJSON *top = cJSON_CreateObject();
    cJSON_AddNumberToObject(top, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddItemToObject(top, "acbb_sweep", h);
    return top;
}

void acbb_cli_sweep_header(FILE *f, acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                           int with_wall)
{
    if (fmt == ACBB_CLI_REC_JSONL || id->csv_header) {
        cJSON *h = header_json(id);
        char *text = cJSON_PrintUnformatted(h);
        cJSON_Delete(h);
        fprintf(f, "%s%s\n", fmt == ACBB_CLI_REC_CSV ? "# " : "", text ? text : "{}");
        cJSON_free(text);
    }
    if (fmt == ACBB_CLI_REC_CSV) acbb_cli_sweep_csv_header(f, id->g, &id->metrics, with_wall);
}

char *acbb_cli_sweep_header_text(acbb_cli_rec_format fmt, const acbb_cli_sweep_id *id,
                                 int with_wall, size_t *len)
{
    char *text = NULL;
    FILE *m = open_memstream(&text, len);
    if (!m) return NULL;
    acbb_cli_sweep_header(m, fmt, id, with_wall);
    if (fclose(m) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

cJSON *acbb_cli_sweep_header_parse(const char *line, acbb_cli_rec_format fmt)
{
    if (fmt == ACBB_CLI_REC_CSV && strncmp(line, "# ", 2) != 0) return NULL;
    cJSON *o = cJSON_Parse(fmt == ACBB_CLI_REC_CSV ? line + 2 : line);
    cJSON *h = cJSON_DetachItemFromObjectCaseSensitive(o, "acbb_sweep");
    cJSON_Delete(o);
    if (cJSON_IsObject(h) && cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(h, "format")) &&
        cJSON_IsString(cJSON_GetObjectItemCaseSensitive(h, "fingerprint")) &&
        cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(h, "grid")) &&
        cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(h, "scene")))
        return h;
    cJSON_Delete(h);
    return NULL;
}

cJSON *acbb_cli_sweep_sidecar_read(const char *csv_path, int *missing)
{
    char side[4200];
    *missing = 1;
    if (snprintf(side, sizeof side, "%s" ACBB_CLI_SIDECAR_EXT, csv_path) >= (int)sizeof side)
        return NULL;
    FILE *f = fopen(side, "r");
    if (!f) return NULL;
    *missing = 0;
    char *line = NULL;
    size_t cap = 0;
    cJSON *h = getline(&line, &cap, f) > 0 ? acbb_cli_sweep_header_parse(line, ACBB_CLI_REC_JSONL)
                                           : NULL;
    free(line);
    fclose(f);
    return h;
}

cJSON *acbb_cli_sweep_header_of(const acbb_cli_sweep_id *id)
{
    cJSON *top = header_json(id);
    cJSON *h = cJSON_DetachItemFromObjectCaseSensitive(top, "acbb_sweep");
    cJSON_Delete(top);
    return h;
}

/* Append "name (a vs b)" to the message. */
static void say(char *msg, size_t n, size_t *len, int *count, const char *name, const cJSON *a,
                const cJSON *b)
{
    char *ta = a ? cJSON_PrintUnformatted(a) : NULL, *tb = b ? cJSON_PrintUnformatted(b) : NULL;
    if (*len < n)
        *len += (size_t)snprintf(msg + *len, n - *len, "%s%s (%s vs %s)", *count ? ", " : "",
                                 name, ta ? ta : "absent", tb ? tb : "absent");
    ++*count;
    cJSON_free(ta);
    cJSON_free(tb);
}

/* Every member of `a` that `b` lacks or holds otherwise, and the members of
 * b that a lacks; names prefixed. */
static void diff_members(const cJSON *a, const cJSON *b, const char *prefix, char *msg, size_t n,
                         size_t *len, int *count)
{
    char name[200];
    const cJSON *it;
    cJSON_ArrayForEach(it, a) {
        const cJSON *o = cJSON_GetObjectItemCaseSensitive(b, it->string);
        snprintf(name, sizeof name, "%s%s", prefix, it->string);
        if (!o || !cJSON_Compare(it, o, 1)) say(msg, n, len, count, name, it, o);
    }
    cJSON_ArrayForEach(it, b) {
        snprintf(name, sizeof name, "%s%s", prefix, it->string);
        if (!cJSON_GetObjectItemCaseSensitive(a, it->string)) say(msg, n, len, count, name, NULL, it);
    }
}

int acbb_cli_sweep_header_diff(const cJSON *a, const cJSON *b, char *msg, size_t n)
{
    size_t len = 0;
    int count = 0;
    msg[0] = '\0';
    static const char *const top[] = { "format", "mode", "metrics", "stiffness" };
    for (size_t k = 0; k < 4; k++) {
        const cJSON *x = cJSON_GetObjectItemCaseSensitive(a, top[k]);
        const cJSON *y = cJSON_GetObjectItemCaseSensitive(b, top[k]);
        int optional = k >= 2; /* metrics, stiffness: absent in both is the same */
        if ((x || y || !optional) && (!x || !y || !cJSON_Compare(x, y, 1)))
            say(msg, n, &len, &count, top[k], x, y);
    }
    diff_members(cJSON_GetObjectItemCaseSensitive(a, "grid"),
                 cJSON_GetObjectItemCaseSensitive(b, "grid"), "grid ", msg, n, &len, &count);
    diff_members(cJSON_GetObjectItemCaseSensitive(a, "scene"),
                 cJSON_GetObjectItemCaseSensitive(b, "scene"), "", msg, n, &len, &count);
    /* The fingerprint alone differing means a header edited by hand. */
    const cJSON *fa = cJSON_GetObjectItemCaseSensitive(a, "fingerprint");
    const cJSON *fb = cJSON_GetObjectItemCaseSensitive(b, "fingerprint");
    if (!count && !cJSON_Compare(fa, fb, 1)) say(msg, n, &len, &count, "fingerprint", fa, fb);
    return count;
}

acbb_sweep *acbb_cli_sweep_from_header(const cJSON *h)
{
    acbb_sweep *g = NULL;
    if (acbb_sweep_new(&g) != ACBB_OK) return NULL;
    const cJSON *dim;
    cJSON_ArrayForEach(dim, cJSON_GetObjectItemCaseSensitive(h, "grid")) {
        size_t len = strlen(dim->string) + 2;
        const cJSON *v;
        int ok = cJSON_IsArray(dim) && cJSON_GetArraySize(dim) > 0;
        cJSON_ArrayForEach(v, dim) {
            ok = ok && cJSON_IsString(v) && !strchr(v->valuestring, ',');
            if (ok) len += strlen(v->valuestring) + 1;
        }
        char *spec = ok ? malloc(len) : NULL;
        if (spec) {
            size_t at = (size_t)snprintf(spec, len, "%s=", dim->string);
            cJSON_ArrayForEach(v, dim)
                at += (size_t)snprintf(spec + at, len - at, "%s%s", at > strlen(dim->string) + 1 ? "," : "",
                                       v->valuestring);
        }
        acbb_error err;
        ok = spec && acbb_sweep_add(g, spec, &err) == ACBB_OK;
        free(spec);
        if (!ok) {
            acbb_sweep_free(g);
            return NULL;
        }
    }
    return g;
}

/* ---- one record against the sweep it claims ---- */

/* A whole number in 0..n-1 written as digits only. */
static int index_text(const char *s, size_t len, size_t n, size_t *index)
{
    if (len == 0 || len > 19) return 0;
    unsigned long long v = 0;
    for (size_t k = 0; k < len; k++) {
        if (!isdigit((unsigned char)s[k])) return 0;
        v = v * 10 + (unsigned long long)(s[k] - '0');
    }
    *index = (size_t)v;
    return v < n;
}

static int finite_text(const char *s, size_t len, int empty_ok)
{
    if (len == 0) return empty_ok;
    char buf[64];
    if (len >= sizeof buf) return 0;
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *end = NULL;
    double v = strtod(buf, &end);
    return end == buf + len && isfinite(v) && !isalpha((unsigned char)buf[0]);
}

/* A key twice at the top: cJSON would read the first, merge keep both. */
static int has_duplicate(const cJSON *o)
{
    for (const cJSON *a = o->child; a; a = a->next)
        for (const cJSON *b = a->next; b; b = b->next)
            if (a->string && b->string && strcmp(a->string, b->string) == 0) return 1;
    return 0;
}

static int check_jsonl(const char *line, const acbb_sweep *g, const char *fp, size_t *index,
                       const char **why)
{
    cJSON *o = cJSON_Parse(line);
    const cJSON *ix = cJSON_GetObjectItemCaseSensitive(o, "index");
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(o, "fingerprint");
    int rc = -1;
    if (!cJSON_IsObject(o)) *why = "not a JSON object";
    else if (has_duplicate(o)) *why = "a key given twice";
    else if (!cJSON_IsNumber(ix) || ix->valuedouble < 0 || ix->valuedouble != floor(ix->valuedouble) ||
             ix->valuedouble >= (double)acbb_sweep_n_points(g))
        *why = "index is not a whole number in the grid's range";
    else if (!cJSON_IsString(f) || strcmp(f->valuestring, fp) != 0)
        *why = "fingerprint is not this sweep's";
    else if (!cJSON_IsString(cJSON_GetObjectItemCaseSensitive(o, "status")))
        *why = "no status";
    else {
        *index = (size_t)ix->valuedouble;
        cJSON *want = acbb_cli_sweep_grid_json(g, *index);
        *why = "grid values are not those of its index";
        if (cJSON_Compare(want, cJSON_GetObjectItemCaseSensitive(o, "grid"), 1)) rc = 0;
        cJSON_Delete(want);
        const cJSON *it;
        cJSON_ArrayForEach(it, o) /* numbers finite (cJSON reads 1e999 as inf) */
            if (!rc && cJSON_IsNumber(it) && !isfinite(it->valuedouble)) rc = -1, *why = "a number is not finite";
    }
    cJSON_Delete(o);
    return rc;
}

/* Next CSV field of `s` from *at: its span (quotes kept); *at past the comma. */
static int csv_field(const char *s, size_t *at, size_t *start, size_t *len)
{
    size_t p = *at;
    if (s[p] == '\0' || s[p] == '\n') return 0;
    *start = p;
    if (s[p] == '"') {
        for (p++; s[p] && !(s[p] == '"' && s[p + 1] != '"'); p += s[p] == '"' ? 2 : 1) {}
        if (s[p] != '"') return 0;
        p++;
    } else {
        while (s[p] && s[p] != ',' && s[p] != '\n') p++;
    }
    *len = p - *start;
    *at = s[p] == ',' ? p + 1 : p;
    return 1;
}

static int check_csv(const char *line, const acbb_sweep *g, const acbb_cli_metrics *m,
                     const char *fp, int with_wall, size_t *index, const char **why)
{
    size_t dims = acbb_sweep_n_dims(g);
    size_t n_cols = 1 + 1 + dims + 2 + acbb_cli_sweep_n_scalars(m) + m->n + 1 + (size_t)with_wall;
    size_t at = 0, st, len, col = 0;
    *why = "a field is out of place";
    for (; csv_field(line, &at, &st, &len); col++) {
        const char *s = line + st;
        int ok = 1;
        if (col == 0) ok = index_text(s, len, acbb_sweep_n_points(g), index), *why = "index is not a whole number in the grid's range";
        else if (col == 1) ok = len == strlen(fp) && strncmp(s, fp, len) == 0, *why = "fingerprint is not this sweep's";
        else if (col < 2 + dims) {
            const char *v = acbb_sweep_value(g, *index, col - 2);
            ok = len == strlen(v) && strncmp(s, v, len) == 0, *why = "grid values are not those of its index";
        } else if (col == 2 + dims) ok = len > 0 && isalpha((unsigned char)s[0]), *why = "no status";
        else if (col == n_cols - 1 - (size_t)with_wall) ok = len >= 2 && s[0] == '"', *why = "message not quoted";
        else ok = finite_text(s, len, col != 3 + dims && col != n_cols - 1), *why = "a number is not finite";
        if (!ok || col >= n_cols) return -1;
    }
    *why = "wrong number of fields";
    return col == n_cols && (line[at] == '\n' || line[at] == '\0') ? 0 : -1;
}

/* The statuses of acbb_cli_sweep_record_retried. */
static int retried_status(const char *s, size_t len)
{
    static const char *const k[] = { "wall_limit", "out_of_memory" };
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++)
        if (len == strlen(k[i]) && strncmp(s, k[i], len) == 0) return 1;
    return 0;
}

int acbb_cli_sweep_record_retried(const char *line, acbb_cli_rec_format fmt,
                                  const acbb_sweep *g)
{
    if (fmt == ACBB_CLI_REC_JSONL) {
        cJSON *o = cJSON_Parse(line);
        const cJSON *st = cJSON_GetObjectItemCaseSensitive(o, "status");
        int yes = cJSON_IsString(st) && retried_status(st->valuestring, strlen(st->valuestring));
        cJSON_Delete(o);
        return yes;
    }
    size_t at = 0, start = 0, len = 0, status_col = 2 + acbb_sweep_n_dims(g);
    for (size_t col = 0; csv_field(line, &at, &start, &len); col++)
        if (col == status_col) return retried_status(line + start, len);
    return 0;
}

int acbb_cli_sweep_check_record(const char *line, acbb_cli_rec_format fmt, const acbb_sweep *g,
                                const acbb_cli_metrics *m, const char *fp, int with_wall,
                                size_t *index, const char **why)
{
    return fmt == ACBB_CLI_REC_CSV ? check_csv(line, g, m, fp, with_wall, index, why)
                                   : check_jsonl(line, g, fp, index, why);
}
