/* acbb CLI — `acbb sweep --metric PATH` (issue 28 item 8): any result
 * `acbb metrics` lists added to every record, after the fixed scalars.
 *
 * A path is kept in its canonical form (the run JSON's path: an old column
 * name such as T_outer_ring_C becomes temperature_C.outer_ring), so a
 * record never holds one quantity twice: a metric that is already a fixed
 * column, or given twice, is refused. The metrics are part of the sweep:
 * its header lists them and its fingerprint covers them (sweep_id.c), so a
 * resume or a merge with another set is refused naming "metrics" (the
 * records of the two would not have the same fields). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acbb/outputs.h"
#include "sweep.h"

/* The canonical path of `path` into buf; 0, or -1 with the reason in msg. */
static int canonical(const char *path, char *buf, size_t n, char *msg, size_t mn)
{
    acbb_output o;
    long ball = -1;
    acbb_error err = { { 0 } };
    if (acbb_output_find(path, &o, &ball, &err) != ACBB_OK) {
        snprintf(msg, mn, "%s (`acbb metrics` lists the names)", err.msg);
        return -1;
    }
    char k[24];
    snprintf(k, sizeof k, "%ld", ball < 0 ? 0 : ball);
    if (acbb_output_path(&o, k, buf, n) >= (int)n) {
        snprintf(msg, mn, "name too long");
        return -1;
    }
    return 0;
}

int acbb_cli_sweep_metric_add(acbb_cli_metrics *m, const char *path, char *msg, size_t mn)
{
    char name[ACBB_CLI_METRIC_NAME];
    if (m->n == ACBB_CLI_SWEEP_METRICS)
        return snprintf(msg, mn, "at most %d metrics", ACBB_CLI_SWEEP_METRICS), -1;
    if (canonical(path, name, sizeof name, msg, mn) != 0) return -1;
    if (m->no_stiffness && strstr(name, "stiffness"))
        return snprintf(msg, mn, "%s: --no-stiffness computes no stiffness", name), -1;
    char fixed[ACBB_CLI_SWEEP_SCALARS][ACBB_CLI_SWEEP_NAME];
    double v[ACBB_CLI_SWEEP_SCALARS];
    size_t nf = acbb_cli_sweep_scalars(NULL, fixed, v);
    for (size_t k = 0; k < nf; k++)
        if (strcmp(fixed[k], name) == 0)
            return snprintf(msg, mn, "%s is already in every record", name), -1;
    for (size_t k = 0; k < m->n; k++)
        if (strcmp(m->path[k], name) == 0)
            return snprintf(msg, mn, "%s given twice", name), -1;
    snprintf(m->path[m->n++], ACBB_CLI_METRIC_NAME, "%s", name);
    return 0;
}

double acbb_cli_sweep_metric_value(const acbb_snapshot *snap, const char *path, int *expected)
{
    acbb_output o;
    long ball = -1;
    *expected = 1;
    if (!snap || acbb_output_find(path, &o, &ball, NULL) != ACBB_OK) return NAN;
    /* No value on purpose: a ball the bearing does not have, a probe that
     * failed (acbb_output_missing), a set's metric of a single bearing. */
    if ((o.row->scope == ACBB_OUT_BALL && ball >= snap->n_balls) ||
        acbb_output_missing(&o, snap) ||
        (strncmp(path, "set.", 4) == 0 && snap->n_bearings <= 1))
        return NAN;
    *expected = 0;
    return acbb_output_value(&o, snap, ball < 0 ? 0 : (int)ball);
}

int acbb_cli_sweep_metrics_of_header(const cJSON *h, acbb_cli_metrics *m)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(h, "metrics"), *it;
    const cJSON *stiff = cJSON_GetObjectItemCaseSensitive(h, "stiffness");
    char msg[200];
    m->n = 0;
    m->no_stiffness = cJSON_IsFalse(stiff);
    if (stiff && !cJSON_IsFalse(stiff)) return -1; /* only false is written */
    if (!list) return 0;
    if (!cJSON_IsArray(list)) return -1;
    cJSON_ArrayForEach(it, list) {
        if (!cJSON_IsString(it) || acbb_cli_sweep_metric_add(m, it->valuestring, msg, sizeof msg) ||
            strcmp(m->path[m->n - 1], it->valuestring) != 0)
            return -1;
    }
    return 0;
}
