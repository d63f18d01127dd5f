/* acbb — dynamic ball model (fidelity.model = dynamic): time integration
 * of each ball's motion — translation in the meridional plane (X1, X2),
 * orbital speed and the three components of its angular velocity — under
 * Hertz contact forces with viscous contact damping, traction resultants
 * (traction.h), centrifugal and Coriolis terms, gyroscopic coupling and
 * oil-air drag. The inner ring is held at its quasi-static position; there
 * is no cage contact (free balls; adequate for pure thrust, where every
 * ball is alike). Integrated with GSL odeiv2's BDF stepper (msbdf), which
 * suits the stiff contact (~3e5 rad/s) and traction (~1e9 1/s) modes; the
 * traction point tables are prepared at the window start and held over
 * the window (dynamic.c, start_tables).
 *
 * Its fixed point is the quasi-dynamic solution: at rest in the orbiting
 * frame the equations reduce to the Level-2 balances. The time-averaged
 * state over the second half of a window is what the coupled stepper uses.
 *
 * Ownership: acbb_dyn_new allocates a workspace that acbb_dyn_free frees. */
#ifndef ACBB_DYNAMIC_H
#define ACBB_DYNAMIC_H

#include <stdatomic.h>
#include "mechanics.h"
#include "traction.h"

#define ACBB_DYN_DAMPING 0.1   /* contact damping, fraction of critical (ASSUMED) */

#define ACBB_DYN_MAX_THREADS 8

/* rtol = atol of the BDF stepper on the scaled states (BENCHMARKS.md): a
 * window's averaged speeds and tractions, and so the losses the level
 * hands on, are resolved to this relative tolerance, not to mech_tol (each
 * window restarts from the last one's speeds, so two windows at the same
 * inputs differ by up to it). */
#define ACBB_DYN_RTOL 1e-4

typedef struct acbb_dyn acbb_dyn;

/* What every ball's window reads (all borrowed, read-only during a call). */
typedef struct {
    acbb_mech *m;
    const acbb_scene *s;
    const acbb_quad *quad;
    double omega_i;                       /* inner-ring speed, rad/s */
    const acbb_oil_state *oil_i, *oil_o;  /* inlet oil of each race */
    const acbb_mixture *mix;              /* oil-air mixture for the drag */
} acbb_dyn_env;

acbb_status acbb_dyn_new(int grid, acbb_dyn **out);
void acbb_dyn_free(acbb_dyn *d);

/* Worker threads for acbb_dyn_balls, 1..ACBB_DYN_MAX_THREADS (default 1);
 * ACBB_EINVAL outside that range, ACBB_ENOMEM if the tables of a new
 * worker cannot be allocated. The results do not depend on it: every ball
 * is integrated alone on one worker's tables. */
acbb_status acbb_dyn_set_threads(acbb_dyn *d, int n);
int acbb_dyn_threads(const acbb_dyn *d);

/* Attach the caller's cancel flag (may be NULL): a window in progress ends
 * with ACBB_CANCELLED within one right-hand-side evaluation. */
void acbb_dyn_set_cancel(acbb_dyn *d, const atomic_int *cancel);

/* A caller's bound beside the cancel flag (the run's wall-clock bound,
 * fidelity.max_wall_s): `stop(ctx)` is called in every right-hand-side
 * evaluation, from the worker threads (it must only read); a non-zero
 * acbb_status ends the window with that status. NULL: none. */
typedef acbb_status (*acbb_dyn_stop_fn)(const void *ctx);
void acbb_dyn_set_stop(acbb_dyn *d, acbb_dyn_stop_fn stop, const void *ctx);

/* Inside transient steps: a ball whose last window had settled (moved
 * omega_m by less than 1e-6 relative) and whose loads, contact angles and
 * inlet viscosities moved less than tol (relative; radians for the angles)
 * since that window keeps its averaged speeds and tractions. 0 (the
 * default) integrates every call, as the steady polish must. */
void acbb_dyn_set_skip(acbb_dyn *d, double tol);

/* Windows integrated by this workspace so far (skipped balls not counted). */
long acbb_dyn_windows(const acbb_dyn *d);

/* Integrate ball j of st for `window` seconds from its current position
 * (at rest) and speeds (qd_w if traction_valid, else the race-control
 * kinematics), then write the time average over the second half into the
 * ball: qd_w, tr_i, tr_o, tr_Qi, tr_Qo, traction_valid. *change returns
 * the relative change of omega_m. Loads are re-solved by the caller. */
acbb_status acbb_dyn_ball(acbb_dyn *d, acbb_mech *m, const acbb_scene *s,
                          const acbb_quad *quad, double omega_i,
                          const acbb_oil_state *oil_i, const acbb_oil_state *oil_o,
                          const acbb_mixture *mix, acbb_mech_state *st, int j,
                          double window, double *change, acbb_error *err);

/* Every distinct ball of st (acbb_mech_distinct), each over `cold` s from
 * race control or `warm` s once traction_valid, on the workspace's worker
 * threads. *change returns the largest relative change of omega_m. On a
 * failure the error of the lowest-numbered failing ball is returned. The
 * caller spreads the distinct balls (acbb_mech_spread) and re-solves loads. */
acbb_status acbb_dyn_balls(acbb_dyn *d, const acbb_dyn_env *env, acbb_mech_state *st,
                           double cold, double warm, double *change, acbb_error *err);

#endif
