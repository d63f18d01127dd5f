/* acbb — the preload window (issue 19 item 4): a bearing run over speed x
 * preload on the batch runner (batch.h), each cell judged against a skid
 * criterion from below and user limits from above.
 *
 * Each cell is the base scene with mounting.preload = displacement (set at
 * rest by the cell's preload force, then held: the rigid mounting whose
 * preload heat raises, MODEL.md 11) at the cell's inner-ring speed, run as
 * a transient from ambient (the steady solve would miss a runaway). With
 * `spring` the cell's preload is a constant axial force instead
 * (mounting.preload = force, operating.axial_load = the preload, the
 * preset's own thrust replaced): the spring-preloaded spindle, whose
 * inner contacts unload with speed, where a rigid preload's grow (the
 * centrifugal ball load and the inner ring's growth are held between the
 * rings), so that on a rigid mounting the skid ratio below levels off
 * under 1 with speed (both grow as omega^2; measured for the 7008C at
 * 30 000 rpm and 1 N, isothermal: 0.90) and the skid floor binds only with
 * a spring (tests/test_life_skid.sh).
 *
 * Skid (from the ball speeds of the traction model): the gyroscopic
 * moment the ball's orbit and spin need, M_g = J omega_m |omega_perp|
 * (MODEL.md 3; omega_perp the ball's angular velocity across the orbit's
 * axis, in the orbiting frame), must be held by friction where the inner
 * ring drives the ball, M_g <= mu Q_i D/2 (Jones's condition against
 * gyroscopic pivoting, Harris & Kotzalas, Advanced Concepts of Bearing
 * Technology, 5th ed., ch. 2 "gyroscopic moment"; taken at the inner
 * contact, which at speed is the lighter one, as the stated choice of
 * this map), with mu = lubricant.limiting_shear_ratio, the most traction
 * the film can carry (MODEL.md 5). skid = max over balls of the ratio; a
 * cell skids when skid > 1. MODEL.md 11's table states Jones's condition
 * at the outer contact (2 M_g / D > mu Q_o: pivoting under outer race
 * control); the inner contact is the stricter of the two at speed. With
 * the traction model (quasi-dynamic) M_g is the moment the two contacts'
 * traction does supply, so skid > 1 says the inner contact alone could not
 * hold it; quasi-static, M_g is race control's (omega_y' = 0).
 *
 * Upper limits (each 0 = not checked): the hottest of the rings and the
 * ball at most max_rise_K above ambient, L_nmr at least min_life_h, s0 at
 * least min_s0; a run that ends in runaway, or in any failed status, is out.
 *
 * Ownership: `cells` (n_speeds x n_preloads, speed-major) and `rows`
 * (n_speeds) are the caller's. Thread-safe as acbb_batch_run. */
#ifndef ACBB_PRELOAD_MAP_H
#define ACBB_PRELOAD_MAP_H

#include "acbb/cancel_flag.h"
#include "acbb/scene.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_PMAP_MAX_AXIS 100   /* grid points per axis */

typedef struct {
    double speed_lo, speed_hi;       /* rpm, > 0 */
    int n_speeds;                    /* 1..ACBB_PMAP_MAX_AXIS (1: speed_lo only) */
    double preload_lo, preload_hi;   /* N, > 0 */
    int n_preloads;
    double max_rise_K, min_life_h, min_s0; /* limits; 0 = not checked */
    int spring;                      /* 1: constant-force (spring) preload; 0: rigid */
    int jobs;                        /* batch workers (0: all CPUs) */
    const acbb_atomic_int *cancel;        /* may be NULL */
} acbb_pmap_opts;

/* Why a cell is outside the window (bits of acbb_pmap_cell.flags). */
enum {
    ACBB_PMAP_SKID = 1, ACBB_PMAP_HOT = 2, ACBB_PMAP_SHORT_LIFE = 4, ACBB_PMAP_LOW_S0 = 8,
    ACBB_PMAP_RUNAWAY = 16, ACBB_PMAP_FAILED = 32
};

typedef struct {
    double speed_rpm, preload_N;
    acbb_status status;       /* the run's: ACBB_OK converged, ACBB_RUNAWAY, ... */
    char status_name[32];     /* acbb_run_status_name of its last state, or the status name */
    int have;                 /* the values below come from a state (0: no Sim was built) */
    double skid;              /* max_j M_g / (mu Q_i D/2) */
    double rise_K;            /* hottest of rings and ball minus ambient */
    double Lnmr_h, s0_min;
    unsigned flags;           /* ACBB_PMAP_* bits; 0 = inside the window */
} acbb_pmap_cell;

typedef struct {
    double speed_rpm;
    double skid_free_N;       /* lowest preload that does not skid (-1: none on the grid) */
    double upper_N;           /* highest preload within the upper limits (-1: none) */
    double lo_N, hi_N;        /* the window: the first cell inside, and the last of the
                                 run of inside cells that follows it (-1: no window) */
} acbb_pmap_row;

/* Grid values: lo + (hi - lo) k / (n - 1). */
double acbb_pmap_axis(double lo, double hi, int n, int k);

/* Run the map. ACBB_EINVAL (message) for a bad grid or base scene,
 * ACBB_CANCELLED when cancelled (cells not run say so), else ACBB_OK:
 * failed cells are results, named in their status. */
acbb_status acbb_preload_map(const acbb_scene *base, const acbb_pmap_opts *o,
                             acbb_pmap_cell *cells, acbb_pmap_row *rows, acbb_error *err);

/* The first reason of a cell's flags: "ok", "skid", "hot", "short_life",
 * "low_s0", "runaway", "failed". */
const char *acbb_pmap_verdict(const acbb_pmap_cell *c);

#ifdef __cplusplus
}
#endif

#endif
