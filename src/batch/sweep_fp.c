/* acbb — the fingerprint of a sweep (sweep.h, acbb_sweep_fingerprint;
 * issue 20 items 3-4, issue 26 item 2): what makes two outputs parts of one
 * sweep. Everything that can change a point's result is in it: every scene
 * key, the schedule's rows, the grid and the run mode. The wall-clock
 * bound is not: it ends a run without changing the results of the runs it
 * does not end (README "Wall-clock bound"), and its wall_limit records are
 * run again on resume. */
#include <stdio.h>
#include <string.h>
#include "acbb/tools/outfile.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/sweep.h"
#include "acbb/tools/scene_schema.h"

static int gridded(const acbb_sweep *g, const char *key)
{
    for (size_t d = 0; d < acbb_sweep_n_dims(g); d++)
        if (strcmp(acbb_sweep_key(g, d), key) == 0) return 1;
    return 0;
}

static uint64_t add_line(uint64_t h, const char *a, const char *b)
{
    h = acbb_hash64(a, strlen(a), h);
    h = acbb_hash64("=", 1, h);
    h = acbb_hash64(b, strlen(b), h);
    return acbb_hash64("\n", 1, h);
}

int acbb_sweep_scene_key(const acbb_sweep *g, size_t i, char *key, size_t n)
{
    const acbb_field_info *f = acbb_scene_field(i);
    if (!f) return 0;
    snprintf(key, n, "%s.%s", f->section, f->key);
    return !gridded(g, key) && strcmp(key, "fidelity.max_wall_s") != 0;
}

void acbb_sweep_schedule_text(const acbb_scene *s, char *buf, size_t n)
{
    size_t len = 0;
    buf[0] = '\0';
    for (int i = 0; i < s->schedule_n && len < n; i++) {
        char row[128];
        acbb_schedule_format_row(s, i, row, sizeof row);
        len += (size_t)snprintf(buf + len, n - len, "%s%s", i ? "; " : "", row);
    }
}

uint64_t acbb_sweep_fingerprint(const acbb_sweep *g, const acbb_scene *base, int transient)
{
    char key[160], val[128];
    snprintf(val, sizeof val, "%d", ACBB_SWEEP_FORMAT);
    uint64_t h = add_line(ACBB_HASH64_SEED, "format", val);
    h = add_line(h, "mode", transient ? "transient" : "steady");
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        if (!acbb_sweep_scene_key(g, i, key, sizeof key)) continue;
        acbb_scene_field_format(base, i, val, sizeof val);
        h = add_line(h, key, val);
    }
    char rows[ACBB_SWEEP_SCHEDULE_TEXT];
    acbb_sweep_schedule_text(base, rows, sizeof rows);
    h = add_line(h, ACBB_SWEEP_SCHEDULE_KEY, rows);
    for (size_t d = 0; d < acbb_sweep_n_dims(g); d++) {
        h = add_line(h, "grid", acbb_sweep_key(g, d));
        /* Every value of the dimension, in order: the point of index i
         * on the last dimension's stride is value i. */
        size_t stride = 1;
        for (size_t e = d + 1; e < acbb_sweep_n_dims(g); e++) stride *= acbb_sweep_n_values(g, e);
        for (size_t v = 0; v < acbb_sweep_n_values(g, d); v++)
            h = add_line(h, "value", acbb_sweep_value(g, v * stride, d));
    }
    return h;
}
