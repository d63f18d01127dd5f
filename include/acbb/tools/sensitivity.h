/* acbb — what-if at scale: how a scalar result depends on the uncertain
 * inputs (MODEL.md ASSUMED / UNSURE items and the surroundings, each with
 * a plausible range in the schema: acbb_field_info.plaus_*).
 *
 * A metric is any scalar of the run's JSON, named by its path
 * ("losses_W.total", "temperature_C.outer_ring", "balls[0].Qi_N",
 * "squeeze_um.net", ...; acbb_metric_name lists them), in the JSON's units.
 * With `delta_te` the metric is metric(TE) - metric(WTE): two runs per
 * point, identical but for effects.thermal_expansion.
 *
 * One at a time (OAT): each uncertain input is set to each end of its
 * plausible range, the others at the scene's values; the rows are sorted
 * by effect = max |y(end) - y0|, and a row `flips` when an end gives a
 * metric of the other sign than y0 (MODEL.md 13: the TE/WTE sign at heavy
 * load rests on a sub-micron balance).
 *
 * Morris elementary effects (Morris 1991, the radial-step trajectory
 * design of Campolongo et al. 2007 without the space-filling selection):
 * r trajectories on a p-level grid over the unit cube of the inputs' ranges,
 * step Delta = p / (2 (p - 1)); each trajectory moves one input at a time,
 * in a random order, k + 1 runs. EE_j = (y(x + Delta e_j) - y(x)) / Delta
 * in metric units per whole plausible range; mu* = mean |EE|, sigma = its
 * standard deviation (nonlinearity or interaction). A two-level input
 * takes its first choice below 0.5, its second at or above. GSL's mt19937
 * with a fixed seed: the design, hence the result, is reproducible.
 *
 * Runs are independent Sims on the batch runner (batch.h), each the steady
 * solve (a metric is read at the steady state; `acbb run --set
 * fidelity.thermal_mode=steady` bit for bit) unless `transient`; the
 * engine prints nothing. A run that fails (not converged, runaway, bad
 * combination) gives no value: its row says how many ends failed, and a
 * Morris effect that needs it is left out (n_ee counts those kept). */
#ifndef ACBB_SENSITIVITY_H
#define ACBB_SENSITIVITY_H

#include "acbb/cancel_flag.h"
#include <stddef.h>
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_SENS_MAX 64         /* uncertain inputs at most */
#define ACBB_SENS_METRIC 64      /* metric path length */
#define ACBB_SENS_MORRIS_MAX 1000 /* trajectories */

/* ---- metrics ---- */

/* The value of `path` in `snap` into *out (JSON units). Returns ACBB_OK,
 * or ACBB_EINVAL with the reason (unknown name, ball index out of range,
 * no value in this snapshot: acbb_output_missing). */
acbb_status acbb_metric_value(const acbb_snapshot *snap, const char *path, double *out,
                              acbb_error *err);
/* Metric name i into buf (ball fields as "balls[i].X"); 0 past the end. */
int acbb_metric_name(size_t i, char *buf, size_t n);
/* Whether `path` names a metric (ball index not checked against a run). */
acbb_status acbb_metric_check(const char *path, acbb_error *err);

/* ---- inputs ---- */

typedef struct {
    size_t field;                /* schema row (acbb_scene_field) */
    char key[64];                /* "section.key" */
    char base[64], lo[64], hi[64]; /* values as preset text */
    const char *src;             /* acbb_field_info.plaus_src */
} acbb_sens_input;

/* The uncertain inputs of the schema with the scene's values (at most
 * `cap`); returns how many. */
size_t acbb_sens_inputs(const acbb_scene *s, acbb_sens_input *out, size_t cap);

/* `base` with input `in` set to its range position x in [0, 1] (a REAL:
 * lo + x (hi - lo); a two-level input: lo below 0.5, hi from 0.5). */
acbb_status acbb_sens_apply(acbb_scene *s, const acbb_sens_input *in, double x,
                            acbb_error *err);

/* ---- the analysis ---- */

typedef void (*acbb_sens_progress_fn)(void *ctx, size_t done, size_t total);

typedef struct {
    char metric[ACBB_SENS_METRIC];
    int delta_te;                /* metric(TE) - metric(WTE) */
    int delta_rel;               /* with delta_te: (TE - WTE) / |WTE| instead */
    int oat;                     /* one-at-a-time table */
    int morris_r;                /* trajectories (0: no Morris) */
    int morris_p;                /* grid levels (even, >= 2; 0: 4) */
    unsigned long seed;          /* design seed (0: 1) */
    int jobs;                    /* threads (<= 0: acbb_batch_cpus()) */
    const acbb_atomic_int *cancel;    /* set: stop (ACBB_CANCELLED) */
    acbb_sens_progress_fn progress; /* called from worker threads, under a lock */
    void *ctx;
    int transient;               /* 1: each run's transient as its scene says */
} acbb_sens_opts;

typedef struct {
    acbb_sens_input in;
    double y_lo, y_hi;           /* metric at the ends (valid when ok_lo / ok_hi) */
    int ok_lo, ok_hi;
    double effect;               /* max |y(end) - y0| over the ends that ran */
    int ok_effect;               /* effect measured: y0 and an end, or both ends
                                    ran (else effect 0 means nothing) */
    int flips;                   /* an end has the other sign than y0 */
    double mu, mu_star, sigma;   /* Morris (n_ee > 0) */
    int n_ee;                    /* elementary effects kept */
} acbb_sens_row;

typedef struct {
    char metric[ACBB_SENS_METRIC];
    int delta_te;
    double y0;                   /* at the scene's values */
    int ok0;
    char fail0[256];             /* why the base run failed */
    size_t n;                    /* inputs */
    acbb_sens_row rows[ACBB_SENS_MAX]; /* OAT: sorted by effect, largest first */
    int morris_r, morris_p;
    double morris_delta;
    size_t runs, failed;         /* Sims run (TE and WTE counted apart) */
    double wall_ms;
} acbb_sens_result;

/* Run the analysis on `base`. Errors: ACBB_EINVAL (metric, options, a
 * scene whose inputs cannot be set), ACBB_ENOMEM, ACBB_CANCELLED. A base
 * run that fails is not an error: ok0 = 0 and fail0 says why. */
acbb_status acbb_sensitivity_run(const acbb_scene *base, const acbb_sens_opts *o,
                                 acbb_sens_result *out, acbb_error *err);

/* ---- the pool (shared by the analyses) ---- */

/* y[i] = metric of scenes[i] (NAN when the run failed: status[i] and, for
 * the first failure, `first_fail` say why). With delta_te each scene runs
 * twice. Returns ACBB_OK, ACBB_ENOMEM or ACBB_CANCELLED. */
acbb_status acbb_sens_eval(const acbb_scene *scenes, size_t n, const acbb_sens_opts *o,
                           double *y, char *first_fail, size_t fail_n, size_t *runs);

#ifdef __cplusplus
}
#endif

#endif
