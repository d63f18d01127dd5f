/* acbb CLI — the what-if baseline (baseline.h). */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cjson/cJSON.h>
#include "baseline.h"
#include "exit.h"
#include "output.h"
#include "say.h"

#define MAX_FILE (16 << 20)  /* a run's JSON is ~10 kB; refuse anything absurd */

/* A saved document is a regular file: a FIFO or a device would block the
 * read (a FIFO with no writer, for ever; issue 26 item 7) or never end.
 * Opened without blocking, then refused unless regular; read up to
 * MAX_FILE. NULL with errno set (EINVAL: not a regular file). */
static char *slurp(const char *path)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return NULL;
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        errno = EINVAL;
        return NULL;
    }
    char *buf = malloc(MAX_FILE + 1);
    size_t n = 0;
    ssize_t got = 1;
    while (buf && n < MAX_FILE && (got = read(fd, buf + n, MAX_FILE - n)) > 0) n += (size_t)got;
    close(fd);
    if (buf) buf[n] = '\0';
    return buf;
}

static int unreadable(const char *path)
{
    if (errno == EINVAL)
        acbb_cli_say("--baseline %s: not a regular file (a saved `acbb run --json`)\n",
                path);
    else
        acbb_cli_say("--baseline %s: cannot read: %s\n", path, strerror(errno));
    return ACBB_EXIT_INPUT;
}

int acbb_cli_baseline_check(const char *path)
{
    char *text = slurp(path);
    if (!text) return unreadable(path);
    free(text);
    return ACBB_EXIT_OK;
}

/* This run as the JSON `acbb run --json` prints, parsed. */
static cJSON *run_json(const acbb_scene *sc, const acbb_snapshot *snap)
{
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (!m) return NULL;
    acbb_cli_out o;
    acbb_cli_out_init(&o, m);
    acbb_cli_json_run(&o, sc, snap);
    fclose(m);
    cJSON *doc = cJSON_Parse(text);
    free(text);
    return doc;
}

/* Paths that are bookkeeping, not results or inputs. */
static bool skipped(const char *path)
{
    static const char *const skip[] = { "wall_ms", "message", "work.", "iterations", "time_s" };
    for (size_t i = 0; i < sizeof skip / sizeof skip[0]; i++)
        if (strncmp(path, skip[i], strlen(skip[i])) == 0) return true;
    return false;
}

static void add_row(cJSON *rows, const char *path, const cJSON *was, const cJSON *now)
{
    cJSON *r = cJSON_CreateObject();
    cJSON_AddStringToObject(r, "path", path);
    if (cJSON_IsNumber(was) && cJSON_IsNumber(now)) {
        double a = was->valuedouble, b = now->valuedouble;
        cJSON_AddNumberToObject(r, "baseline", a);
        cJSON_AddNumberToObject(r, "now", b);
        /* No inf or nan in any output (issue 20 item 9): a change or a
         * percentage that overflows (a baseline of 1e-320 or 1e308) is null. */
        double d = b - a, pct = a != 0.0 ? 100.0 * d / fabs(a) : NAN;
        if (isfinite(d)) cJSON_AddNumberToObject(r, "change", d);
        else cJSON_AddNullToObject(r, "change");
        if (isfinite(pct)) cJSON_AddNumberToObject(r, "change_pct", pct);
        else cJSON_AddNullToObject(r, "change_pct");
    } else {
        cJSON_AddItemToObject(r, "baseline", cJSON_Duplicate(was, 1));
        cJSON_AddItemToObject(r, "now", cJSON_Duplicate(now, 1));
    }
    cJSON_AddItemToArray(rows, r);
}

/* Walk the baseline; a leaf present in both documents that differs is a row
 * (numbers beyond a relative 1e-12, strings and booleans when unequal). */
static void diff(const cJSON *was, const cJSON *now, const char *path, cJSON *rows)
{
    if (!now || skipped(path)) return;
    if (cJSON_IsObject(was) || cJSON_IsArray(was)) {
        int i = 0;
        for (const cJSON *c = was->child; c; c = c->next, i++) {
            char sub[256];
            const cJSON *n = cJSON_IsObject(was) ? cJSON_GetObjectItemCaseSensitive(now, c->string)
                                                 : cJSON_GetArrayItem(now, i);
            if (cJSON_IsObject(was))
                snprintf(sub, sizeof sub, "%s%s%s", path, path[0] ? "." : "", c->string);
            else
                snprintf(sub, sizeof sub, "%s[%d]", path, i);
            diff(c, n, sub, rows);
        }
        return;
    }
    if (cJSON_IsNumber(was) && !isfinite(was->valuedouble)) {
        return; /* cJSON reads 1e999 as inf: not a value a run can have written */
    } else if (cJSON_IsNumber(was) && cJSON_IsNumber(now)) {
        double a = was->valuedouble, b = now->valuedouble;
        if (fabs(b - a) > 1e-12 * fmax(fabs(a), fabs(b))) add_row(rows, path, was, now);
    } else if (!cJSON_Compare(was, now, 1)) {
        add_row(rows, path, was, now);
    }
}

/* A temperature's change in % of its rise above ambient, as the TUI's Run
 * screen shows it (a % of a Celsius value depends on where 0 C is; issue
 * 21 item 7). The ambient is the baseline scene's. */
static void temperature_rises(cJSON *rows, const cJSON *was)
{
    const cJSON *keys = cJSON_GetObjectItem(cJSON_GetObjectItem(was, "scene"), "keys");
    const cJSON *amb = cJSON_GetObjectItem(keys, "operating.ambient_C");
    if (!cJSON_IsNumber(amb)) return;
    cJSON *r;
    cJSON_ArrayForEach(r, rows) {
        const char *p = cJSON_GetObjectItem(r, "path")->valuestring;
        const cJSON *a = cJSON_GetObjectItem(r, "baseline"), *b = cJSON_GetObjectItem(r, "now");
        if (strncmp(p, "temperature_C.", 14) != 0 || !cJSON_IsNumber(a) || !cJSON_IsNumber(b)) continue;
        double rise = a->valuedouble - amb->valuedouble;
        double v = 100.0 * (b->valuedouble - a->valuedouble) / fabs(rise);
        /* No inf or nan (issue 20 item 9): an overflowing share is null. */
        cJSON *pct = fabs(rise) > 1e-12 && isfinite(v) ? cJSON_CreateNumber(v) : cJSON_CreateNull();
        cJSON_ReplaceItemInObject(r, "change_pct", pct);
        cJSON_AddStringToObject(r, "change_pct_of", "rise above ambient");
    }
}

static void print_row(const cJSON *r)
{
    const cJSON *a = cJSON_GetObjectItem(r, "baseline"), *b = cJSON_GetObjectItem(r, "now");
    const char *p = cJSON_GetObjectItem(r, "path")->valuestring;
    if (strncmp(p, "scene.keys.", 11) == 0) p += 11; /* the inputs block says what it is */
    if (cJSON_IsNumber(a)) {
        const cJSON *pct = cJSON_GetObjectItem(r, "change_pct");
        const cJSON *d = cJSON_GetObjectItem(r, "change");
        printf("  %-34.34s %12.6g %12.6g", p, a->valuedouble, b->valuedouble);
        if (cJSON_IsNumber(d)) printf(" %+11.4g", d->valuedouble);
        else printf(" %11s", "-");
        if (cJSON_IsNumber(pct)) printf(" %+7.2f%%\n", pct->valuedouble);
        else printf(" %8s\n", "-");
        return;
    }
    char *sa = cJSON_PrintUnformatted(a), *sb = cJSON_PrintUnformatted(b);
    printf("  %-34.34s %12.12s %12.12s\n", p, sa ? sa : "?", sb ? sb : "?");
    free(sa);
    free(sb);
}

/* The text table keeps to what fits a screen: the inputs that changed, then
 * the results with ball 0 standing for the balls and without the node list
 * (the JSON has every row). */
static void print_table(const cJSON *rows, const char *path)
{
    printf("\nchange against the baseline %s\n", path);
    if (cJSON_GetArraySize(rows) == 0) {
        printf("  (no value changed)\n");
        return;
    }
    printf("  %-34s %12s %12s %11s %8s\n", "value", "baseline", "now", "change", "%");
    printf("  (temperatures: %% of the rise above ambient, as the TUI shows it)\n");
    for (int pass = 0; pass < 2; pass++) {
        const cJSON *r;
        cJSON_ArrayForEach(r, rows) {
            const char *p = cJSON_GetObjectItem(r, "path")->valuestring;
            bool input = strncmp(p, "scene.keys.", 11) == 0;
            bool brief = strncmp(p, "balls[", 6) != 0 || strncmp(p, "balls[0]", 8) == 0;
            if (input == (pass == 0) && brief && !strstr(p, "nodes[")) print_row(r);
        }
    }
}

int acbb_cli_baseline(const char *path, const acbb_scene *sc, const acbb_snapshot *snap,
                      bool json, bool quiet)
{
    char *text = slurp(path);
    if (!text) return unreadable(path);
    cJSON *was = cJSON_Parse(text);
    free(text);
    if (!cJSON_IsObject(was) || !cJSON_GetObjectItem(was, "losses_W")) {
        acbb_cli_say("--baseline %s: not the JSON of `acbb run --json`\n", path);
        cJSON_Delete(was);
        return ACBB_EXIT_INPUT;
    }
    cJSON *now = run_json(sc, snap), *rows = cJSON_CreateArray();
    int rc = now && rows ? ACBB_EXIT_OK : ACBB_EXIT_INTERNAL;
    if (rc == ACBB_EXIT_OK) {
        diff(was, now, "", rows);
        temperature_rises(rows, was);
        if (json) {
            cJSON_AddItemToObject(now, "vs_baseline", rows);
            rows = NULL;
            char *out = cJSON_Print(now);
            if (out) puts(out);
            else rc = ACBB_EXIT_INTERNAL;
            free(out);
        } else if (!quiet) {
            print_table(rows, path);
        }
    }
    cJSON_Delete(rows);
    cJSON_Delete(now);
    cJSON_Delete(was);
    return rc;
}
