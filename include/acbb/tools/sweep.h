/* acbb — sweeps in N dimensions: a grid of scene edits, its cartesian
 * product, shards of it, and a pool of worker threads running the points.
 *
 * A grid is a list of dimensions, each a scene key (section.key, preset
 * units, as acbb_scene_set) with its values: "key=v1,v2,..." (the text as
 * given) or "key=lo:hi:n" (n evenly spaced values, both ends included,
 * printed %.10g). Point i of the product is numbered row-major: the first
 * dimension varies slowest, the last fastest, so the index names the point
 * on every machine. Shard K of N holds the points with i % N == K - 1.
 *
 * acbb_sweep_run runs the points on the batch runner (batch.h): a point's
 * result does not depend on the thread count or on which machine ran it.
 * Finished points go to `done` (the client's writer) one at a time. A
 * sweep reads each point at its steady state, so a point is the steady
 * solve (fidelity.thermal_mode = steady: `acbb run PRESET --set ... --set
 * fidelity.thermal_mode=steady` bit for bit) unless opts.transient is set
 * or the grid varies fidelity.thermal_mode, .preset or .target_error_pct.
 * The transient catches a runaway the steady solve may miss (batch.h).
 *
 * Ownership: acbb_sweep_new allocates a grid that acbb_sweep_free
 * releases; value strings returned are owned by the grid. */
#ifndef ACBB_SWEEP_H
#define ACBB_SWEEP_H

#include "acbb/cancel_flag.h"
#include <stddef.h>
#include <stdint.h>
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_SWEEP_MAX_DIMS 8
#define ACBB_SWEEP_MAX_VALUES 100000    /* per dimension */
#define ACBB_SWEEP_MAX_POINTS 100000000 /* the whole product */
#define ACBB_SWEEP_KEY 64
#define ACBB_SWEEP_VALUE 64

typedef struct acbb_sweep acbb_sweep;

acbb_status acbb_sweep_new(acbb_sweep **out);
void acbb_sweep_free(acbb_sweep *g);

/* Add a dimension from "key=v1,v2,..." or "key=lo:hi:n". The key must be a
 * scene key; the values are not checked against the key's range here (a
 * bad value is that point's failure, recorded by the run). Errors
 * (ACBB_EINVAL with a message): no '=', empty or over-long value, a range
 * that is not two finite numbers and a whole n in 1..MAX_VALUES, a key
 * given twice, too many dimensions or points. */
acbb_status acbb_sweep_add(acbb_sweep *g, const char *spec, acbb_error *err);

size_t acbb_sweep_n_dims(const acbb_sweep *g);
const char *acbb_sweep_key(const acbb_sweep *g, size_t dim);
size_t acbb_sweep_n_values(const acbb_sweep *g, size_t dim);
size_t acbb_sweep_n_points(const acbb_sweep *g);
/* Dimension dim's value text at point `index`. */
const char *acbb_sweep_value(const acbb_sweep *g, size_t index, size_t dim);

/* Value v (0..n_values-1) of dimension dim. */
const char *acbb_sweep_dim_value(const acbb_sweep *g, size_t dim, size_t v);

/* Every value of every dimension against its key alone (acbb_scene_set_value
 * on a copy of `base`: the text reads as the key's type and lies in its
 * range). A value that fails fails at every point that has it: a typo, to
 * refuse before anything runs (issue 26 item 11). The cross-field rules
 * are left to each point (a combination may be ill-posed where another is
 * not). ACBB_OK, or the first failure with *dim and *value naming it. */
acbb_status acbb_sweep_check_values(const acbb_sweep *g, const acbb_scene *base, size_t *dim,
                                    size_t *value, acbb_error *err);

/* `base` with point `index`'s edits applied (first failing edit reported). */
acbb_status acbb_sweep_scene(const acbb_sweep *g, const acbb_scene *base, size_t index,
                             acbb_scene *out, acbb_error *err);

/* Shard k (1-based) of n holds index i when i % n == k - 1; n <= 1: all. */
int acbb_sweep_in_shard(size_t index, size_t k, size_t n);

/* One finished point. status: the edit or set-up failure when !have_snap,
 * else the run's final status (snap.state says converged or not). */
typedef struct {
    size_t index;
    acbb_status status;
    int have_snap;
    char message[512];      /* the edit / set-up message when !have_snap */
    double wall_ms;         /* edits + set-up + run, CLOCK_MONOTONIC */
    acbb_snapshot snap;
} acbb_sweep_result;

/* Called with the lock held, one point at a time, in completion order. */
typedef void (*acbb_sweep_done_fn)(void *ctx, const acbb_sweep_result *r);

typedef struct {
    int jobs;                      /* threads; <= 0: acbb_batch_cpus() */
    size_t shard_k, shard_n;       /* shard_n <= 1: every point */
    const unsigned char *skip;     /* skip[i] != 0: point i is done already (may be NULL) */
    size_t max_points;             /* run at most this many (0: no limit) */
    const acbb_atomic_int *cancel;      /* set: stop; cancelled points are not reported */
    acbb_sweep_done_fn done;
    void *ctx;
    int transient;                 /* 1: each point's transient as its scene says */
    /* 1: no end-of-run stiffness probes (acbb_sim_opts.skip_stiffness),
     * a third of a steady point: for a caller whose records need no
     * stiffness (their stiffness values are then missing). */
    int skip_stiffness;
} acbb_sweep_opts;

/* Run the points of the shard not skipped, lowest index first. Returns
 * ACBB_OK (failed points are results, not errors), ACBB_ENOMEM, or
 * ACBB_CANCELLED when `cancel` stopped it. *n_run (may be NULL) receives
 * how many points were reported. */
acbb_status acbb_sweep_run(const acbb_sweep *g, const acbb_scene *base,
                           const acbb_sweep_opts *o, size_t *n_run);

/* How many points acbb_sweep_run would run with these options. */
size_t acbb_sweep_n_todo(const acbb_sweep *g, const acbb_sweep_opts *o);

/* The version of the sweep's output records (the CLI's JSONL and CSV):
 * raised whenever a record's fields change, so outputs of different
 * versions are never merged or resumed into each other. */
#define ACBB_SWEEP_FORMAT 4

/* What makes two outputs parts of one sweep (issue 20 items 3-4, issue 26
 * item 2): FNV-1a 64 (outfile.h) over the record format, the run mode
 * (opts.transient), the value of every scene key of `base` that the grid
 * does not vary (as acbb_scene_field_format writes it) except the
 * wall-clock bound fidelity.max_wall_s (it changes no result of a run it
 * does not end), the schedule's rows (acbb_sweep_schedule_text, under
 * ACBB_SWEEP_SCHEDULE_KEY) and every grid key with all its values in
 * order. Equal on every machine for the same inputs. Format 4: format 3
 * left the schedule out (two sweeps differing only in their rows mixed). */
uint64_t acbb_sweep_fingerprint(const acbb_sweep *g, const acbb_scene *base, int transient);
/* Scene key i as "section.key" into key; 0 when it is not part of the
 * fingerprint's scene (the grid varies it, or it is fidelity.max_wall_s)
 * or i is out of range. */
int acbb_sweep_scene_key(const acbb_sweep *g, size_t i, char *key, size_t n);
/* The schedule's rows as one text, "t, speed, axial, radial" each (preset
 * units, exact: acbb_schedule_format_row), joined by "; "; "" without
 * rows. buf >= ACBB_SWEEP_SCHEDULE_TEXT bytes. */
#define ACBB_SWEEP_SCHEDULE_TEXT (ACBB_SCHEDULE_MAX * 130)
#define ACBB_SWEEP_SCHEDULE_KEY "schedule.rows"
void acbb_sweep_schedule_text(const acbb_scene *s, char *buf, size_t n);

#ifdef __cplusplus
}
#endif

#endif
