/* acbb — metrics: a scalar of a snapshot named by its JSON path
 * (sensitivity.h). The names, members and units are the output table's
 * (outputs.h), the same the run's JSON writes. */
#include <stdio.h>
#include "acbb/outputs.h"
#include "acbb/tools/sensitivity.h"

int acbb_metric_name(size_t i, char *buf, size_t n)
{
    acbb_output o;
    if (!acbb_output_get(i, &o)) return 0;
    acbb_output_path(&o, "i", buf, n);
    return 1;
}

acbb_status acbb_metric_check(const char *path, acbb_error *err)
{
    acbb_output o;
    long k;
    return acbb_output_find(path, &o, &k, err);
}

acbb_status acbb_metric_value(const acbb_snapshot *snap, const char *path, double *out,
                              acbb_error *err)
{
    acbb_output o;
    long k;
    acbb_status st = acbb_output_find(path, &o, &k, err);
    if (st != ACBB_OK) return st;
    if (o.row->scope == ACBB_OUT_BALL && k >= snap->n_balls)
        return acbb_error_set(err, ACBB_EINVAL, "metric '%s': ball index must be 0..%d",
                              path, snap->n_balls - 1);
    /* No value is not 0: a failed stiffness probe, a spindle's result of
     * another scene (acbb_output_missing) */
    const char *why = acbb_output_missing(&o, snap);
    if (why) return acbb_error_set(err, ACBB_EINVAL, "metric '%s' has no value: %s", path, why);
    *out = acbb_output_value(&o, snap, (int)k);
    return ACBB_OK;
}
