/* acbb CLI — `acbb merge OUT IN...`: sweep outputs (shards, resumed runs)
 * joined into the canonical form of sweep.h: sorted by point index, each
 * index once (the first met, in argument order), wall_ms dropped. A single
 * input gives the canonical form of one machine's sweep, so
 * `acbb merge a sweep.jsonl` and `acbb merge b s1.jsonl s2.jsonl` compare
 * byte for byte. JSONL lines are re-printed by cJSON (numbers round-trip),
 * CSV rows keep their text. */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>
#include "common.h"
#include "exit.h"
#include "sweep.h"

typedef struct {
    size_t index, seq;
    char *text;                /* canonical record with its newline */
} merge_rec;

typedef struct {
    merge_rec *recs;
    size_t n, cap;
    int csv;                   /* -1 unknown yet */
    char *header;              /* CSV: canonical header */
    char *grid_keys;           /* JSONL: the first record's grid keys */
} merge_set;

static int add_rec(merge_set *m, size_t index, char *text)
{
    if (m->n == m->cap) {
        size_t cap = m->cap ? 2 * m->cap : 256;
        merge_rec *r = realloc(m->recs, cap * sizeof *r);
        if (!r) return free(text), ACBB_EXIT_INTERNAL;
        m->recs = r, m->cap = cap;
    }
    m->recs[m->n] = (merge_rec){ index, m->n, text };
    m->n++;
    return 0;
}

/* "k1,k2,..." of a record's grid: records of another grid are refused. */
static char *grid_keys(const cJSON *o)
{
    size_t len = 1;
    const cJSON *it;
    cJSON_ArrayForEach(it, cJSON_GetObjectItemCaseSensitive(o, "grid")) len += strlen(it->string) + 1;
    char *s = calloc(len, 1);
    cJSON_ArrayForEach(it, cJSON_GetObjectItemCaseSensitive(o, "grid")) {
        if (!s) break;
        strcat(s, it->string);
        strcat(s, ",");
    }
    return s;
}

static int jsonl_line(merge_set *m, const char *line)
{
    cJSON *o = cJSON_Parse(line);
    const cJSON *ix = cJSON_GetObjectItemCaseSensitive(o, "index");
    if (!cJSON_IsNumber(ix) || ix->valuedouble < 0 || !cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(o, "grid"))) {
        cJSON_Delete(o);
        return ACBB_EXIT_INPUT;
    }
    char *keys = grid_keys(o);
    int same = keys && (!m->grid_keys || strcmp(keys, m->grid_keys) == 0);
    if (same && !m->grid_keys) m->grid_keys = keys, keys = NULL;
    free(keys);
    cJSON_DeleteItemFromObjectCaseSensitive(o, "wall_ms");
    char *text = same ? cJSON_PrintUnformatted(o) : NULL;
    size_t index = (size_t)ix->valuedouble;
    cJSON_Delete(o);
    if (!text) return ACBB_EXIT_INPUT;
    size_t len = strlen(text);
    char *rec = malloc(len + 2);
    if (rec) memcpy(rec, text, len), rec[len] = '\n', rec[len + 1] = '\0';
    cJSON_free(text);
    return rec ? add_rec(m, index, rec) : ACBB_EXIT_INTERNAL;
}

/* Text up to the last comma when the file carries wall_ms last. */
static char *csv_cut(const char *line, int has_wall)
{
    size_t len = strlen(line);
    if (has_wall) {
        const char *c = strrchr(line, ',');
        if (!c) return NULL;
        len = (size_t)(c - line) + 1;
    }
    char *s = malloc(len + 1);
    if (!s) return NULL;
    memcpy(s, line, len);
    if (has_wall) s[len - 1] = '\n';
    s[len] = '\0';
    return s;
}

static int csv_line(merge_set *m, const char *line, long lineno, int *has_wall)
{
    if (lineno == 1) {
        size_t len = strlen(line);
        *has_wall = len > 9 && strcmp(line + len - 9, ",wall_ms\n") == 0;
        char *h = csv_cut(line, *has_wall);
        if (!h || strncmp(h, "index,", 6) != 0 || (m->header && strcmp(h, m->header) != 0))
            return free(h), ACBB_EXIT_INPUT;
        if (!m->header) m->header = h;
        else free(h);
        return 0;
    }
    char *end = NULL;
    unsigned long long index = strtoull(line, &end, 10);
    if (end == line || *end != ',') return ACBB_EXIT_INPUT;
    char *rec = csv_cut(line, *has_wall);
    return rec ? add_rec(m, (size_t)index, rec) : ACBB_EXIT_INTERNAL;
}

static int read_input(merge_set *m, const char *path)
{
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (!f) {
        fprintf(stderr, "acbb: merge: %s: cannot read\n", path);
        return ACBB_EXIT_INPUT;
    }
    char *line = NULL;
    size_t cap = 0;
    ssize_t len;
    long lineno = 0;
    int rc = 0, has_wall = 0;
    while (!rc && (len = getline(&line, &cap, f)) > 0) {
        lineno++;
        if (line[len - 1] != '\n') {
            fprintf(stderr, "acbb: merge: %s:%ld: unfinished last record skipped\n", path, lineno);
            break;
        }
        int csv = lineno == 1 ? line[0] != '{' : m->csv;
        if (m->csv >= 0 && csv != m->csv) rc = ACBB_EXIT_INPUT;
        m->csv = csv;
        if (!rc) rc = csv ? csv_line(m, line, lineno, &has_wall) : jsonl_line(m, line);
        if (rc == ACBB_EXIT_INPUT)
            fprintf(stderr, "acbb: merge: %s:%ld: not a record of the same sweep (acbb sweep "
                    "--jsonl or --csv, one grid)\n", path, lineno);
    }
    free(line);
    if (f != stdin) fclose(f);
    return rc;
}

static int by_index(const void *a, const void *b)
{
    const merge_rec *x = a, *y = b;
    if (x->index != y->index) return x->index < y->index ? -1 : 1;
    return x->seq < y->seq ? -1 : x->seq > y->seq;
}

static int write_merged(const char *out, merge_set *m)
{
    qsort(m->recs, m->n, sizeof *m->recs, by_index);
    acbb_cli_file file = { 0 };
    int rc = acbb_cli_file_open(&file, out);
    if (rc) return rc;
    if (m->csv == 1 && m->header) fputs(m->header, file.out.f);
    size_t kept = 0, dup = 0;
    for (size_t i = 0; i < m->n; i++) {
        if (i > 0 && m->recs[i].index == m->recs[i - 1].index) {
            dup++;
            continue;
        }
        fputs(m->recs[i].text, file.out.f);
        kept++;
    }
    rc = acbb_cli_file_close(&file);
    size_t top = m->n ? m->recs[m->n - 1].index + 1 : 0;
    if (top > kept)
        fprintf(stderr, "acbb: merge: warning: %zu of the indices 0..%zu are missing\n",
                top - kept, top - 1);
    if (dup) fprintf(stderr, "acbb: merge: %zu repeated records dropped\n", dup);
    return rc;
}

int acbb_cli_cmd_merge(const acbb_cli_args *a)
{
    merge_set m = { .csv = -1 };
    int rc = 0;
    for (int i = 1; !rc && i < a->n_pos; i++) rc = read_input(&m, a->pos[i]);
    if (!rc) rc = write_merged(a->pos[0], &m);
    for (size_t i = 0; i < m.n; i++) free(m.recs[i].text);
    free(m.recs);
    free(m.header);
    free(m.grid_keys);
    return rc;
}
