/* acbb — the steady polish's iteration control (internal).
 *
 * After a run has settled, the stepper (stepper.c) iterates the direct steady solve of the
 * network with the losses of the state it reached (Picard, MODEL.md
 * section 9) so the reported state balances energy to round-off. The
 * lagged coupling can overshoot: with a rigid preload, heat that expands
 * the outer ring unloads the contacts, so the next losses fall, and the
 * map's gain can be below -1 (issue 18: about -1.5, a two-state cycle
 * between 43 W and 1 W). This file decides the relaxation of each
 * iteration and when to stop; the caller owns the state and the map. */
#ifndef ACBB_STEADY_POLISH_H
#define ACBB_STEADY_POLISH_H

#include "acbb/scene.h"
#include "acbb/status.h"

#define ACBB_POLISH_ITERS 100   /* iteration cap (60, undamped, before issue 18) */
#define ACBB_POLISH_TOL_K 1e-9  /* an undamped polish converges below this move, K */
#define ACBB_POLISH_RELAX_MIN (1.0 / 64) /* damps gains down to about -127 */
/* Undamped residuals wander up to about the resolution (below) before
 * they land (warm-shaft preset: 3.6e-7 K at a resolution of 3.6e-7 K):
 * growth is judged as overshoot only above this many resolutions. */
#define ACBB_POLISH_NOISE_FACTOR 10.0

/* Relative tolerance below which the polish reuses a ball's results
 * (sim.c POLISH_SKIP_TOL, below mech_tol 1e-8). */
#define ACBB_POLISH_REUSE_TOL 1e-9

/* The relative tolerance the scene's losses are resolved to: mech_tol, or
 * at the dynamic level the integrator's (dynamic.h ACBB_DYN_RTOL), whose
 * windows differ by up to it from one evaluation to the next; with
 * mech_tol there, the polish took that noise for overshoot, damped to its
 * floor and ended diverged (combined-load, issue 26 item 11). */
double acbb_polish_loss_rtol(const acbb_scene *s);

/* The resolution of a polish over temperatures T[0..n) whose losses are
 * resolved to mech_tol relative (or the reuse tolerance): that fraction
 * of the temperatures' spread, K (the network is linear in its sources). */
double acbb_polish_resolution(double mech_tol, const double *T, int n);

/* One iteration at relaxation `relax` (0 < relax <= 1): from the current
 * state T the direct steady solve T_s, *res = max_n |T_s - T| (K, the
 * undamped residual), *turn = the cosine between this undamped move
 * T_s - T and the previous one (acbb_polish_turn; < 0: the map
 * overshoots, its gain is negative), the move T += relax (T_s - T) and the
 * evaluation there. Any status but ACBB_OK ends the polish with it; the
 * callee keeps its last good state then. */
typedef acbb_status (*acbb_polish_step)(void *ctx, double relax, double *res, double *turn,
                                        acbb_error *err);

/* The cosine between the undamped move (Tn - T) / relax of n nodes and
 * prev[0..n) (0 when either is zero: the first step), and that move into
 * prev for the next step. */
double acbb_polish_turn(double *prev, const double *T, const double *Tn, double relax, int n);

/* The steady solve (stepper.c) is quiet once a move is below this
 * (K) with the losses still to 1e-9 relative, three times running. It
 * judges every growing residual (floor 0): undamped, its residuals and
 * losses can wander in the mechanics' noise band and never turn quiet
 * (a slow growth, gain about -1.2, from 5e-8 K to 1e-6 K at mech_tol
 * 1e-6; or a six-step cycle of the losses between 1e-9 and 5e-9 at
 * 200 N), where halving the relaxation settles them. */
#define ACBB_STEADY_QUIET_K 1e-7

/* The relaxation rule shared by the polish and the steady solve (issue
 * 30 lever 1): start undamped, halve when the undamped residual grows
 * (see acbb_polish_iterate). Fill with acbb_relax_start. */
typedef struct {
    double relax;   /* the relaxation in force */
    double prev;    /* the last residual judged, K */
    double made_by; /* relaxation of the move that led to the last state */
    int judged;     /* residuals judged so far */
} acbb_relax_ctl;

void acbb_relax_start(acbb_relax_ctl *c);

/* Judge `residual` (the undamped move, K, of the state a move at
 * relaxation `w` led to); halve c->relax if it grew above `floor_K`. */
void acbb_relax_judge(acbb_relax_ctl *c, double w, double residual, double floor_K);

/* A steady move whose evaluation failed with `rc` (the mechanics lost
 * its contacts or did not converge at the state the move reached) is
 * rejected and retried at half the relaxation, as the transient halves
 * its step: 1 if so (c->relax halved), 0 if `rc` is final. */
int acbb_relax_reject(acbb_relax_ctl *c, acbb_status rc);

typedef struct {
    int iterations;  /* steps taken */
    double residual; /* the last step's undamped residual, K */
    double relax;    /* the relaxation reached */
} acbb_polish_result;

/* Iterate `step` from relaxation 1 (plain Picard: a contracting polish
 * takes exactly the undamped path, to ACBB_POLISH_TOL_K) and halve the
 * relaxation whenever the residual grows above ACBB_POLISH_NOISE_FACTOR
 * times `resolution_K` (a gain
 * g < -1 becomes 1 - w + w g, inside the unit circle once w < 2 / (1 - g)).
 *
 * Halve too on an overshoot that contracts too slowly: moves that reverse
 * (turn < 0) with residuals shrinking by a ratio r = |rho| > 1/3 a step
 * (rho = 1 - w + w g < -1/3, where halving w, which makes rho (1 + rho) / 2,
 * shrinks |rho|) that at that rate would not reach the tolerance within
 * the cap. A polish that converges undamped within the cap keeps its path
 * bit for bit. The case: `acbb new 6232` (deep groove, 11 kN radial at
 * 800 rpm, reference profile), whose two balls at the load zone's edge
 * (1.6 N inner, 29 N outer, mostly their centrifugal force) swing in
 * speed and load from one Level-2 pass to the next (factor about -0.94 a
 * pass); with one pass per undamped step the polish's residual fell only
 * 3.4 % a step and reversed every step, 0.55 K to 3.9e-4 K in 100. A
 * damped step relaxes those speeds and tractions by its relaxation too
 * (sim_eval.c level2_pass()): relaxing the temperatures alone left the
 * 6232 reversing every step at 1/64.
 *
 * `resolution_K` is how finely the map resolves its fixed point: the
 * losses behind it are resolved to a relative tolerance (the mechanics'),
 * which moves the steady temperatures by that fraction of their rise.
 * An undamped step on a map that is constant below it lands on the fixed
 * point; a damped step only approaches it and is knocked back by up to
 * the resolution whenever a reused ball result expires, so a damped
 * polish is converged once its residual is below `resolution_K`.
 *
 * Undamped residuals can also stall in the noise band, reset whenever a
 * reused ball result expires (a 100 mm bore scaled from the 7008C:
 * 3e-7 to 2e-6 K for 90 steps at a resolution of 1e-6 K): a polish whose
 * last residual after ACBB_POLISH_ITERS steps is within
 * ACBB_POLISH_NOISE_FACTOR resolutions is converged too.
 *
 * ACBB_OK when converged; else ACBB_DIVERGED with the residual in err
 * (the caller says which state it keeps). `out` may be NULL. */
acbb_status acbb_polish_iterate(acbb_polish_step step, void *ctx, double resolution_K,
                                acbb_polish_result *out, acbb_error *err);

/* MODEL.md 12 item 18: a steady state's network balances its sources,
 * |in - out| within ACBB_BALANCE_TOL of in or ACBB_BALANCE_FLOOR_W.
 * ACBB_OK, else ACBB_UNBALANCED with both heats in err. */
acbb_status acbb_balance_check(double in, double out, acbb_error *err);

#endif
