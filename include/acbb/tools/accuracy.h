/* acbb — what accuracy costs in time (DESIGN.md "Fidelity and effects").
 *
 * Every [fidelity] knob is varied one at a time around the base scene's
 * values; each setting is run to thermal steady state (acbb_sim_create,
 * acbb_sim_run, acbb_sim_snapshot) `repeats` times and the median wall time
 * (CLOCK_MONOTONIC around new + run + free, snapshot copy excluded) is kept
 * together with the results and their relative errors against the knob's
 * reference setting:
 *
 * Cost: wall time and, repeatably, work units (acbb_accuracy_work_units).
 *
 *   knob            settings (preset units)             reference
 *   model           static, quasi-static, quasi-dynamic  highest level
 *                   (+ dynamic if acbb_sim_create takes it) acbb_sim_create accepts
 *   contact_grid    4 6 8 12 16 24 32 48 64              64
 *   hertz           hb83 bh77 exact                      exact
 *   mech_tol        1e-4 1e-6 1e-8 1e-10 1e-12           1e-12
 *   steady_tol      steady_tol_K_s 1e-2 1e-3 1e-4 1e-5  1e-5
 *   thermal         time_step_s 1 5 30 (each with        transient, 1 s
 *                   thermal_mode = transient), and
 *                   thermal_mode = steady
 *   network         7 46                                 46
 *
 * Relative error of a quantity x: |x - x_ref| / |x_ref|. The temperature
 * error is that of the outer-ring temperature RISE above ambient
 * (T_outer_ring - ambient_C), not of the Celsius value, and it is scaled by
 * max(|rise_ref|, ACBB_ACCURACY_T_FLOOR_K) (below). The ball quantities
 * are those of ball 0 at its inner contact. An error is NaN when it is not
 * defined: the row or its reference did not converge, or x_ref == 0 while
 * x != 0 (clients print NaN as "-").
 *
 * The engine never prints; acbb_accuracy_run reports progress through an
 * optional callback (the TUI's progress bar, the CLI's stderr ticker).
 *
 * Ownership: the caller owns every buffer passed in (the base scene is read
 * only, rows are written in place); nothing is allocated that outlives a
 * call. Rows are plain values. Not thread-safe per call, but calls share no
 * state, so several may run on different threads. */
#ifndef ACBB_ACCURACY_H
#define ACBB_ACCURACY_H

#include <stddef.h>
#include "acbb/cancel_flag.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    ACBB_KNOB_MODEL,
    ACBB_KNOB_CONTACT_GRID,
    ACBB_KNOB_HERTZ,
    ACBB_KNOB_MECH_TOL,
    ACBB_KNOB_STEADY_TOL,
    ACBB_KNOB_THERMAL,       /* time_step_s and thermal_mode together */
    ACBB_KNOB_NETWORK,
    ACBB_KNOB_COUNT
} acbb_accuracy_knob;

/* Knob masks for acbb_accuracy_options.knobs: bit (1u << knob). */
#define ACBB_ACCURACY_KNOB_BIT(k) (1u << (unsigned)(k))
#define ACBB_ACCURACY_ALL_KNOBS ((1u << (unsigned)ACBB_KNOB_COUNT) - 1u)
/* Model-level masks for acbb_accuracy_options.model_levels. */
#define ACBB_ACCURACY_LEVEL_BIT(m) (1u << (unsigned)(m))
#define ACBB_ACCURACY_ALL_LEVELS (ACBB_ACCURACY_LEVEL_BIT(ACBB_MODEL_DYNAMIC + 1) - 1u)

#define ACBB_ACCURACY_DEFAULT_REPEATS 3
#define ACBB_ACCURACY_MAX_REPEATS 1000

/* What to run. A zero-initialised struct (or NULL) means: every knob, every
 * model level, ACBB_ACCURACY_DEFAULT_REPEATS runs per setting. */
typedef struct {
    unsigned knobs;          /* ACBB_ACCURACY_KNOB_BIT mask; 0 = all */
    unsigned model_levels;   /* levels the model knob tries (ACBB_ACCURACY_LEVEL_BIT
                                mask); 0 = all. The reference is the highest one
                                of them that acbb_sim_create accepts. */
    int repeats;             /* runs per setting, 1..ACBB_ACCURACY_MAX_REPEATS; 0 = default */
    /* Optional cancel hook (NULL = none): another thread stores non-zero to
     * stop the plan. It is read before every setting and between the coupled
     * steps of a run, so a cancel takes effect within one step (plus an
     * acbb_sim_create already under way) even in a long dynamic run. */
    const acbb_atomic_int *cancel;
    /* Ball workers of each run at the dynamic level (acbb_sim_opts.threads;
     * 0: the default). The envelope, whose points already fill the cores,
     * passes 1. The results do not depend on it. */
    int sim_threads;
} acbb_accuracy_options;

/* The frontier's tolerance on total loss and outer-ring temperature rise. */
#define ACBB_ACCURACY_FRONTIER_TOL 0.01

/* Floor of the scale of every temperature error (steady rise and transient
 * path), K: error = |dT - dT_ref| / max(|rise_ref|, 1 K). Why: at the
 * seed's light, slow points the outer-ring rise is a few hundredths of a
 * kelvin (0.047 K at 2000 rpm, 100 N), and the 13 mK by which the default
 * settings trail the reference there on the way up read as a 27 % error
 * (BENCHMARKS.md "Accuracy over the operating range"). A rise
 * below 1 K is below what a bearing test can resolve: IEC 60584-1
 * thermocouple tolerances are +-0.5 K (type T, class 1) to +-1.5 K (type K,
 * class 1). With the floor, 1 % of a small rise means 10 mK, still 50x
 * finer than the best of those sensors. Above 1 K of rise the error is the
 * plain relative one. */
#define ACBB_ACCURACY_T_FLOOR_K 1.0

typedef struct {
    acbb_accuracy_knob knob;
    char key[48];            /* "fidelity.contact_grid" (the key shown) */
    char value[32];          /* "16", preset units */
    int is_reference;        /* 1: this knob's reference setting */
    int is_default;          /* 1: every scene field equals the base scene's */
    int skipped;             /* 1: level not available (model = dynamic); no run */
    acbb_status status;      /* ACBB_OK = converged; else the failure */
    char message[512];       /* why it failed or was skipped; "" if converged */
    long iterations;         /* coupled steps of the (first) run */
    double wall_ms;          /* median over the repeats (NaN if never run) */
    double work;             /* cost in work units of the first run (NaN if it failed) */
    /* Results of the first run; NaN when status != ACBB_OK. */
    double loss;             /* total loss, W */
    double dT_outer;         /* outer-ring temperature rise above ambient, K */
    double Qi;               /* ball 0 inner contact load, N */
    double alpha_i;          /* ball 0 inner contact angle, rad */
    double slide_i;          /* ball 0 inner sliding speed, m/s */
    double e_loss, e_T, e_Qi, e_alpha, e_slide; /* relative errors, NaN if undefined */
} acbb_accuracy_row;

typedef void (*acbb_accuracy_progress)(void *ctx, size_t done, size_t total);

/* Name of a knob ("model", "contact_grid", ..., "thermal", "network") and
 * its inverse (-1 if unknown). */
const char *acbb_accuracy_knob_name(acbb_accuracy_knob k);
int acbb_accuracy_knob_from_name(const char *name);

/* Number of rows acbb_accuracy_run writes for `opt` (NULL = defaults;
 * levels that turn out to be unavailable are included, as skipped rows). */
size_t acbb_accuracy_plan_size(const acbb_accuracy_options *opt);

/* Run the plan of `opt` (NULL = defaults) on `base`. Rows are grouped by
 * knob in enum order, settings cheapest-first as in the table above.
 * `progress(ctx, done, total)` is called after each row if non-NULL.
 * Returns ACBB_OK when the plan ran (individual settings may have failed:
 * see row.status); ACBB_EINVAL for a bad option, cap too small, or an
 * invalid base scene (message in err); nothing is run then and *n = 0.
 * When opt->cancel is set: ACBB_CANCELLED ("accuracy: cancelled after
 * k of n settings" in err); rows[0..*n) are the settings that finished, the
 * interrupted one is dropped, and every error is left NaN (an incomplete
 * knob has no trustworthy reference). */
acbb_status acbb_accuracy_run(const acbb_scene *base, const acbb_accuracy_options *opt,
                              acbb_accuracy_row *rows, size_t cap, size_t *n,
                              acbb_accuracy_progress progress, void *ctx,
                              acbb_error *err);

/* The frontier: for each knob present in rows, the converged setting with
 * the smallest cost in work units whose e_loss and e_T are both <= tol
 * (the reference itself qualifies). Work units are deterministic, so the
 * same plan picks the same settings on every run; on equal work the
 * earlier (coarser) row wins. picks[k] is the row index for knob k, or -1
 * when the knob is absent or its reference failed. `picks` must hold
 * ACBB_KNOB_COUNT entries. */
void acbb_accuracy_frontier(const acbb_accuracy_row *rows, size_t n, double tol,
                            long picks[ACBB_KNOB_COUNT]);

/* Cost of a run in work units: the Sim's work counters (acbb_snapshot.work)
 * weighted by instructions per unit, in millions, measured once with
 * callgrind (the weights scale with the contact grid, the Hertz method,
 * the model level and the network). A repeatable stand-in for wall time:
 * the same run always costs the same. */
double acbb_accuracy_work_units(const acbb_scene *sc, const acbb_work *w);

/* Index of knob k's reference row, or -1. */
long acbb_accuracy_reference(const acbb_accuracy_row *rows, size_t n, acbb_accuracy_knob k);

/* ---- the envelope: every knob over the operating range ----
 *
 * The points are the seed's 48 study points (study.h): the load sweep
 * 50..1000 N at 15000 rpm and the speed sweeps 2000..16000 rpm at 100 N
 * and at 1000 N, each with and without thermal expansion (TE / WTE).
 * Point i: sweep i / 16 (load, 100 N, 1000 N), abscissa (i % 16) / 2,
 * TE when i is even. `points` < 48 takes every (48 / points)-th point,
 * evenly spread (floor(k * 48 / points)).
 *
 * At every point the one-knob plan runs once per setting (no repeats: the
 * cost is in work units), and so does the fidelity ladder (fidelity.h),
 * each entry against the ladder's `reference`. Per setting, over the
 * points where it and its reference converged: worst and median relative
 * error of the steady total loss and outer-ring rise, and of the transient
 * path (acbb: max |T(t) - T_ref(t)| / max(rise_ref, ACBB_ACCURACY_T_FLOOR_K),
 * outer ring; NaN for the steady thermal mode, which has no path), the worst
 * absolute path difference in K, and the median cost per point.
 * Points run in parallel on `jobs` threads (one Sim per thread). */
#define ACBB_ENVELOPE_POINTS 48

typedef struct {
    unsigned knobs;          /* as acbb_accuracy_options; 0 = all */
    unsigned model_levels;   /* 0 = all (the dynamic level costs ~4 s a point) */
    int points;              /* 1..48; 0 = 48 */
    int jobs;                /* threads; <= 0: acbb_batch_cpus() */
    int ladder;              /* 1: also measure the fidelity ladder */
    const acbb_atomic_int *cancel;
} acbb_envelope_options;

typedef struct {
    acbb_accuracy_knob knob; /* ACBB_KNOB_COUNT for a ladder entry */
    char key[48];            /* "fidelity.contact_grid", or "ladder" */
    char value[32];          /* "16", or the entry's name */
    int is_reference, is_default;
    int n_points, n_ok;      /* points run; points where it and its reference converged */
    double worst_loss, median_loss, worst_T, median_T;   /* relative */
    double worst_steady, median_steady;  /* max(loss, T) per point */
    double worst_path, median_path;      /* relative (floored scale); NaN: no path */
    double worst_path_K;                 /* the largest max |T(t) - T_ref(t)|, K */
    double work;             /* median work units per point */
    double wall_ms;          /* median wall time per point (noisy; for scale only) */
} acbb_envelope_row;

/* Rows acbb_accuracy_envelope writes for `o` (NULL = defaults). */
size_t acbb_envelope_size(const acbb_envelope_options *o);
/* Operating point i of the 48: speed in rpm, axial load in N, TE flag. */
void acbb_envelope_point(size_t i, double *rpm, double *load_N, int *te);

/* Run the envelope on `base`. Rows: the plan's settings in plan order,
 * then the ladder entries. *wall_ms (may be NULL) receives the elapsed
 * time. ACBB_EINVAL for bad options (message in err), ACBB_ENOMEM,
 * ACBB_CANCELLED; otherwise ACBB_OK (failed settings are counted in n_ok). */
acbb_status acbb_accuracy_envelope(const acbb_scene *base, const acbb_envelope_options *o,
                                   acbb_envelope_row *rows, size_t cap, size_t *n,
                                   double *wall_ms, acbb_accuracy_progress progress, void *ctx,
                                   acbb_error *err);

/* The frontier over envelope rows: per knob, the cheapest (work) setting
 * whose worst steady error AND worst path error are <= tol over every point
 * (n_ok == n_points; the steady thermal mode has no path, so never);
 * ties go to the earlier row. picks as acbb_accuracy_frontier. */
void acbb_envelope_frontier(const acbb_envelope_row *rows, size_t n, double tol,
                            long picks[ACBB_KNOB_COUNT]);

/* An error (a fraction) as the tables and the TUI print it, in percent:
 * "-" when undefined, "0", "%.0e" below 0.01 % or from 1000 %, else
 * "%.2f" (one formatter, so a screen value matches the CLI digit for digit). */
void acbb_accuracy_format_pct(double e, char *buf, size_t n);

#ifdef __cplusplus
}
#endif

#endif
