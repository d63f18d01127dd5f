/* acbb — what the accuracy benchmark's parts share (src/accuracy*.c). */
#ifndef ACBB_ACCURACY_PRIV_H
#define ACBB_ACCURACY_PRIV_H

#include "acbb/tools/accuracy.h"

/* The outer-ring temperature rise above ambient at each coupled step
 * (the transient path the TUI shows), owned by the caller: free(t), free(y). */
typedef struct {
    double *t, *y;
    size_t n, cap;
    int oom;
} acbb_acc_path;

void acbb_acc_path_free(acbb_acc_path *p);

/* acbb_accuracy_run with optional paths (one per planned row, or NULL).
 * `o` is resolved already (no zero fields). */
acbb_status acbb_acc_run_plan(const acbb_scene *base, const acbb_accuracy_options *o,
                              acbb_accuracy_row *rows, acbb_acc_path *paths, size_t *n,
                              acbb_accuracy_progress progress, void *ctx);

/* Options with defaults filled in (ACBB_EINVAL with a message if bad). */
acbb_status acbb_acc_resolve(const acbb_accuracy_options *opt, acbb_accuracy_options *o,
                             acbb_error *err);

/* One run of `sc` (no repeats) recording its path; results and work in r
 * (r->knob, key, value set by the caller). */
void acbb_acc_run_one(const acbb_scene *sc, const _Atomic int *cancel, int threads,
                      acbb_accuracy_row *r, acbb_acc_path *path);

/* Relative error |x - ref| / |ref|; NaN when undefined. */
double acbb_acc_rel_err(double x, double ref);

/* Error of a temperature rise dT against dT_ref, K:
 * |dT - dT_ref| / max(|dT_ref|, ACBB_ACCURACY_T_FLOOR_K); NaN if either is
 * not finite. */
double acbb_acc_temp_err(double dT, double dT_ref);

/* max |a(t) - ref(t)| in K over the union of both sample times, each path
 * held at its last value after it ends; NaN when either path has no
 * simulated time (steady mode) or is empty. */
double acbb_acc_path_gap(const acbb_acc_path *a, const acbb_acc_path *ref);

/* acbb_acc_path_gap on the scale of acbb_acc_temp_err: the gap over
 * max(|ref final|, ACBB_ACCURACY_T_FLOOR_K). */
double acbb_acc_path_err(const acbb_acc_path *a, const acbb_acc_path *ref);

#endif
