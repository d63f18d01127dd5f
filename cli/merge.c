/* acbb CLI — `acbb merge OUT IN...`: sweep outputs (shards, resumed runs)
 * joined into the canonical form of sweep.h: the header, then the records
 * sorted by point index, each index once (the first met, in argument
 * order), wall_ms dropped. A single input gives the canonical form of one
 * machine's sweep, so `acbb merge a sweep.jsonl` and `acbb merge b s1.jsonl
 * s2.jsonl` compare byte for byte. JSONL lines are re-printed by cJSON
 * (numbers round-trip), CSV rows keep their text.
 *
 * Nothing is mixed (issue 20 item 3): every input starts with the header
 * of one and the same sweep (scene, grid, run mode, record format; a
 * mismatch names the keys that differ), every record carries that sweep's
 * fingerprint, a whole index in the grid's range and the grid values of
 * that index, and only finite numbers (CSV fields checked like JSONL). A
 * FIFO input is refused: merge reads whole files, and a FIFO without a
 * writer would block forever (item 7).
 *
 * Issue 28 item 9: points of the grid without a record are exit 3 (the
 * merged file written all the same), and a sweep's own output as OUT is
 * refused (OUT forgotten: `acbb merge a.csv b.csv`). Of two records of one
 * point, a result wins over a wall_limit / out_of_memory record (issue 26:
 * a resumed sweep runs those again and appends the new record). */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "acbb/tools/json.h"
#include "common.h"
#include "exit.h"
#include "output.h"
#include "sweep.h"
#include "say.h"

typedef struct {
    size_t index, seq;
    int retried;               /* wall_limit, out_of_memory: another record wins */
    char *text;                /* canonical record with its newline */
} merge_rec;

typedef struct {
    merge_rec *recs;
    size_t n, cap;
    acbb_cli_rec_format fmt;
    cJSON *header;             /* the first input's header object */
    const char *header_path;
    acbb_sweep *g;             /* the grid it describes */
    acbb_cli_metrics metrics;  /* and its --metric columns */
    int csv_header;            /* CSV: the first input's header was its first line */
    char fp[17];
} merge_set;

typedef struct {
    const char *path;
    long lineno;
    int has_wall;              /* CSV: the input carries wall_ms last */
    int plain;                 /* CSV: no header line (the sidecar IN.json) */
} merge_in;

static int add_rec(merge_set *m, size_t index, int retried, char *text)
{
    if (!text) return ACBB_EXIT_INTERNAL;
    if (m->n == m->cap) {
        size_t cap = m->cap ? 2 * m->cap : 256;
        merge_rec *r = realloc(m->recs, cap * sizeof *r);
        if (!r) return free(text), ACBB_EXIT_INTERNAL;
        m->recs = r, m->cap = cap;
    }
    m->recs[m->n] = (merge_rec){ index, m->n, retried, text };
    m->n++;
    return 0;
}

static char *jsonl_canonical(const char *line)
{
    cJSON *o = cJSON_Parse(line);
    cJSON_DeleteItemFromObjectCaseSensitive(o, "wall_ms");
    acbb_cli_json_exact(o); /* the record's digits, not cJSON's 15 */
    char *text = o ? cJSON_PrintUnformatted(o) : NULL;
    cJSON_Delete(o);
    if (!text) return NULL;
    size_t len = strlen(text);
    char *rec = malloc(len + 2);
    if (rec) memcpy(rec, text, len), rec[len] = '\n', rec[len + 1] = '\0';
    cJSON_free(text);
    return rec;
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

static int refuse(const merge_in *in, const char *why)
{
    acbb_cli_say("merge: %s:%ld: %s\n", in->path, in->lineno, why);
    return ACBB_EXIT_INPUT;
}

/* A plain CSV (its first line the column header, issue 28 item 8): the
 * header from its sidecar IN.json. */
static int is_plain_csv(const char *line) { return strncmp(line, "index,fingerprint,", 18) == 0; }

static cJSON *sidecar_header(merge_in *in)
{
    int missing = 0;
    cJSON *h = strcmp(in->path, "-") ? acbb_cli_sweep_sidecar_read(in->path, &missing) : NULL;
    if (!h)
        acbb_cli_say("merge: %s: a plain sweep CSV whose header %s" ACBB_CLI_SIDECAR_EXT
                " is %s (the sweep writes it beside the CSV; keep the two together)\n",
                in->path, strcmp(in->path, "-") ? in->path : "FILE",
                missing || !strcmp(in->path, "-") ? "missing" : "not a sweep header");
    return h;
}

/* Line 1: the header (of a plain CSV: its sidecar's); the first input's
 * becomes the reference. */
static int header_line(merge_set *m, merge_in *in, const char *line)
{
    int plain = is_plain_csv(line);
    acbb_cli_rec_format fmt = line[0] == '#' || plain ? ACBB_CLI_REC_CSV : ACBB_CLI_REC_JSONL;
    cJSON *h = plain ? sidecar_header(in) : acbb_cli_sweep_header_parse(line, fmt);
    if (!h && plain) return ACBB_EXIT_INPUT;
    if (!h) {
        char why[160];
        snprintf(why, sizeof why, "no sweep header (an acbb sweep output of record format %d "
                 "starts with one)", ACBB_SWEEP_FORMAT);
        return refuse(in, why);
    }
    char diff[400];
    int rc = 0;
    if (!m->header) {
        const cJSON *fp = cJSON_GetObjectItemCaseSensitive(h, "fingerprint");
        m->g = acbb_cli_sweep_from_header(h);
        if (!m->g) return cJSON_Delete(h), refuse(in, "the header's grid is not a grid");
        if (acbb_cli_sweep_metrics_of_header(h, &m->metrics) != 0)
            return cJSON_Delete(h), refuse(in, "the header's metrics are not metrics");
        snprintf(m->fp, sizeof m->fp, "%s", fp->valuestring);
        m->header = h, m->header_path = in->path, m->fmt = fmt, m->csv_header = !plain;
        return 0;
    }
    if (fmt != m->fmt) rc = refuse(in, "JSONL and CSV cannot be merged into one file");
    else if (acbb_cli_sweep_header_diff(m->header, h, diff, sizeof diff)) {
        acbb_cli_say("merge: %s is another sweep than %s; differs (%s vs %s): %s\n",
                in->path, m->header_path, m->header_path, in->path, diff);
        rc = ACBB_EXIT_INPUT;
    }
    cJSON_Delete(h);
    return rc;
}

/* CSV line 2: the column header, with or without wall_ms. */
static int columns_line(const merge_set *m, merge_in *in, const char *line)
{
    for (int wall = 1; wall >= 0; wall--) {
        char *want = NULL;
        size_t cap = 0;
        FILE *h = open_memstream(&want, &cap);
        if (!h) return ACBB_EXIT_INTERNAL;
        acbb_cli_sweep_csv_header(h, m->g, &m->metrics, wall);
        fclose(h);
        int same = strcmp(line, want) == 0;
        free(want);
        if (same) return in->has_wall = wall, 0;
    }
    return refuse(in, "not the column header of this sweep");
}

static int record_line(merge_set *m, merge_in *in, const char *line)
{
    size_t index = 0;
    const char *why = "";
    if (acbb_cli_sweep_check_record(line, m->fmt, m->g, &m->metrics, m->fp, in->has_wall, &index,
                                    &why)) {
        char msg[160];
        snprintf(msg, sizeof msg, "not a record of this sweep: %s", why);
        return refuse(in, msg);
    }
    return add_rec(m, index, acbb_cli_sweep_record_retried(line, m->fmt, m->g),
                   m->fmt == ACBB_CLI_REC_CSV ? csv_cut(line, in->has_wall)
                                              : jsonl_canonical(line));
}

static FILE *open_input(const char *path)
{
    if (strcmp(path, "-") == 0) return stdin;
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        acbb_cli_say("merge: %s: not a regular file (a FIFO or device could block "
                "forever); copy it to a file first\n", path);
        return NULL;
    }
    FILE *f = fopen(path, "r");
    if (!f) acbb_cli_say("merge: %s: cannot read\n", path);
    return f;
}

static int read_input(merge_set *m, const char *path)
{
    FILE *f = open_input(path);
    if (!f) return ACBB_EXIT_INPUT;
    merge_in in = { .path = path };
    char *line = NULL;
    size_t cap = 0;
    ssize_t len;
    int rc = 0;
    while (!rc && (len = getline(&line, &cap, f)) > 0) {
        in.lineno++;
        if (line[len - 1] != '\n') {
            acbb_cli_say("merge: %s:%ld: unfinished last record skipped\n", path,
                    in.lineno);
            break;
        }
        if (in.lineno == 1) {
            in.plain = is_plain_csv(line); /* its column line first, the header beside */
            rc = header_line(m, &in, line);
            if (!rc && in.plain) rc = columns_line(m, &in, line);
        } else if (in.lineno == 2 && m->fmt == ACBB_CLI_REC_CSV && !in.plain)
            rc = columns_line(m, &in, line);
        else rc = record_line(m, &in, line);
    }
    if (in.lineno == 0) acbb_cli_say("merge: %s: empty, skipped\n", path);
    free(line);
    if (f != stdin) fclose(f);
    return rc;
}

static int by_index(const void *a, const void *b)
{
    const merge_rec *x = a, *y = b;
    if (x->index != y->index) return x->index < y->index ? -1 : 1;
    /* A point's result before a record its resume runs again (wall_limit). */
    if (x->retried != y->retried) return x->retried - y->retried;
    return x->seq < y->seq ? -1 : x->seq > y->seq;
}

static void header_object(FILE *f, const merge_set *m, const char *prefix)
{
    cJSON *top = cJSON_CreateObject();
    cJSON_AddNumberToObject(top, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddItemToObject(top, "acbb_sweep", cJSON_Duplicate(m->header, 1));
    char *text = cJSON_PrintUnformatted(top);
    cJSON_Delete(top);
    fprintf(f, "%s%s\n", prefix, text ? text : "{}");
    cJSON_free(text);
}

/* The merged CSV takes the first input's form: plain with the sidecar
 * OUT.json (committed first; none for stdout), or the header line. */
static int write_header(FILE *f, const merge_set *m, const char *out)
{
    int plain = m->fmt == ACBB_CLI_REC_CSV && !m->csv_header;
    if (!plain) header_object(f, m, m->fmt == ACBB_CLI_REC_CSV ? "# " : "");
    if (m->fmt == ACBB_CLI_REC_CSV) acbb_cli_sweep_csv_header(f, m->g, &m->metrics, 0);
    if (!plain || strcmp(out, "-") == 0) return 0;
    char side[4200];
    if (snprintf(side, sizeof side, "%s" ACBB_CLI_SIDECAR_EXT, out) >= (int)sizeof side) {
        acbb_cli_say("merge: %s: path too long for its header file\n", out);
        return ACBB_EXIT_INPUT;
    }
    acbb_cli_file file = { 0 };
    int rc = acbb_cli_file_open(&file, side);
    if (!rc) header_object(file.out.f, m, ""), rc = acbb_cli_file_close(&file);
    return rc;
}

/* Points of the grid without a record: exit 3 (the merged file is written,
 * as a cancelled sweep keeps what finished), so a pipeline notices (issue
 * 28 item 9). m->recs is sorted. */
static int missing(const merge_set *m, size_t kept)
{
    size_t total = acbb_sweep_n_points(m->g);
    if (kept >= total) return 0;
    char list[200];
    size_t len = 0, shown = 0, r = 0;
    list[0] = '\0';
    for (size_t i = 0; i < total && shown < 8; i++) {
        while (r < m->n && m->recs[r].index < i) r++;
        if (r < m->n && m->recs[r].index == i) continue;
        len += (size_t)snprintf(list + len, sizeof list - len, "%s%zu", shown ? ", " : "", i);
        shown++;
    }
    acbb_cli_say("merge: %zu of the %zu points are missing (index %s%s); the merged "
            "file holds the other %zu: run the missing shards or resume their sweeps, then "
            "merge again\n", total - kept, total, list, total - kept > shown ? ", ..." : "",
            kept);
    return ACBB_EXIT_SOLVER;
}

static int write_merged(const char *out, merge_set *m)
{
    if (!m->header) {
        acbb_cli_say("merge: no sweep output among the inputs\n");
        return ACBB_EXIT_INPUT;
    }
    if (m->n > 1) qsort(m->recs, m->n, sizeof *m->recs, by_index);
    acbb_cli_file file = { 0 };
    int rc = acbb_cli_file_open(&file, out);
    if (rc) return rc;
    if ((rc = write_header(file.out.f, m, out)) != 0) {
        acbb_out_abort(file.handle);
        return rc;
    }
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
    if (dup) acbb_cli_say("merge: %zu repeated records dropped\n", dup);
    return rc ? rc : missing(m, kept);
}

/* A CSV column line whose last column is wall_ms. */
static int ends_with_wall(const char *line)
{
    size_t len = strlen(line);
    return (len >= 8 && strcmp(line + len - 8, ",wall_ms") == 0) ||
           (len >= 9 && strcmp(line + len - 9, ",wall_ms\n") == 0);
}

/* OUT is a sweep's own output, not a merge's: its column line (CSV) or
 * its first record (JSONL) carries wall_ms, which merge drops. `acbb merge
 * a.csv b.csv` (OUT forgotten) would replace the shard a.csv by b's
 * points (issue 28 item 9); an earlier merge's output may be replaced. */
static int out_is_shard(const char *path)
{
    struct stat st;
    if (strcmp(path, "-") == 0 || stat(path, &st) != 0 || !S_ISREG(st.st_mode)) return 0;
    FILE *f = fopen(path, "r");
    if (!f) return 0;
    char *line = NULL;
    size_t cap = 0;
    int yes = 0;
    acbb_cli_rec_format fmt = ACBB_CLI_REC_JSONL;
    for (long n = 1; n <= 2 && getline(&line, &cap, f) > 0; n++) {
        if (n == 1 && is_plain_csv(line)) { /* the column line is this one */
            yes = ends_with_wall(line);
            break;
        } else if (n == 1) {
            fmt = line[0] == '#' ? ACBB_CLI_REC_CSV : ACBB_CLI_REC_JSONL;
            cJSON *h = acbb_cli_sweep_header_parse(line, fmt);
            cJSON_Delete(h);
            if (!h) break;
        } else if (fmt == ACBB_CLI_REC_CSV) {
            yes = ends_with_wall(line);
        } else {
            cJSON *o = cJSON_Parse(line);
            yes = cJSON_GetObjectItemCaseSensitive(o, "wall_ms") != NULL;
            cJSON_Delete(o);
        }
    }
    free(line);
    fclose(f);
    if (yes)
        acbb_cli_say("merge: %s is a sweep's own output (a shard: its records carry "
                "wall_ms), not an earlier merge's; merge writes OUT anew and would lose it. "
                "Usage: acbb merge OUT IN... (OUT first, a new file)\n", path);
    return yes;
}

int acbb_cli_cmd_merge(const acbb_cli_args *a)
{
    merge_set m = { .fmt = ACBB_CLI_REC_JSONL };
    int rc = out_is_shard(a->pos[0]) ? ACBB_EXIT_INPUT : 0;
    for (int i = 1; !rc && i < a->n_pos; i++) rc = read_input(&m, a->pos[i]);
    if (!rc) rc = write_merged(a->pos[0], &m);
    for (size_t i = 0; i < m.n; i++) free(m.recs[i].text);
    free(m.recs);
    cJSON_Delete(m.header);
    acbb_sweep_free(m.g);
    return rc;
}
