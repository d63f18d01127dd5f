/* acbb — quasi-dynamic ball kinematics (MODEL.md section 4, Level 2):
 * per ball, the orbital speed and the three components of the ball's
 * angular velocity follow from the force balance along the orbit (traction
 * + drag) and the moment balance (traction moments = gyroscopic moment
 * required), with the contact loads held at the current equilibrium.
 *
 * Ownership: acbb_qd_new allocates a workspace (traction point tables, a
 * GSL solver) that acbb_qd_free releases. */
#ifndef ACBB_QUASI_DYNAMIC_H
#define ACBB_QUASI_DYNAMIC_H

#include "losses.h"
#include "lubrication.h"
#include "mechanics.h"
#include "traction.h"

typedef struct acbb_qd acbb_qd;

acbb_status acbb_qd_new(int grid, acbb_qd **out);
/* q made anew for grid, as acbb_qd_new makes one (every ball's Jacobian,
 * inputs, tolerances and root history cleared, skip and path off), in
 * q's own traction tables (if that size) and GSL solver, which every
 * hybrid solve sets afresh (gsl_multiroot_fdfsolver_set): a batch
 * worker's runs reuse one (issue 30: about 48 k instructions a run of
 * allocations and clearing). On failure q is still q's to free. */
acbb_status acbb_qd_renew(acbb_qd *q, int grid);
void acbb_qd_free(acbb_qd *q);
/* What q's updates leave for the next (issue 30: a perturbed transient
 * takes its first state's Level 2 from the base run's, sim_first.c):
 * every ball's record (Jacobian, flags, inputs, tolerance, root
 * history), the skip and path settings and the traction contacts'
 * scalars; not the contacts' point tables, which every solve prepares
 * before it reads them, nor the GSL solver, which every hybrid solve
 * sets afresh. A malloc'd copy (free() it; NULL when out of memory);
 * acbb_qd_restore puts it into q, which is then, for every later
 * update, the q it was saved from. */
acbb_qd *acbb_qd_save(const acbb_qd *q);
void acbb_qd_restore(acbb_qd *q, const acbb_qd *saved);

/* Solve Level 2 for every distinct ball of st at inner-ring speed omega_i,
 * writing qd_w, tr_i, tr_o and traction_valid. Balls with a contact load
 * under 1 mN keep race-control speeds (no traction to drive them). The
 * largest relative change of omega_m is returned in *change. */
/* Inside transient steps: a ball whose loads, contact angles and inlet
 * viscosities moved less than tol (relative; radians for the angles; the
 * viscosities weighted 0.3) since its last solve keeps its speeds and
 * tractions. 0 (the default) solves
 * every ball at every update, as the steady polish must. */
void acbb_qd_set_skip(acbb_qd *q, double tol);

/* 1: the next updates are a transient's steps, whose inputs drift one
 * way, so each ball starts from its secant-predicted root (issue 30);
 * 0 (the default): from its last root (the set-up, a steady solve's
 * iterates and the polish are no path). */
void acbb_qd_set_path(acbb_qd *q, int transient);

acbb_status acbb_qd_update(acbb_qd *q, const acbb_scene *s, const acbb_quad *quad,
                           const acbb_geometry *g, double omega_i,
                           const acbb_oil_state *oil_i, const acbb_oil_state *oil_o,
                           const acbb_mixture *mix, acbb_mech_state *st, double *change,
                           acbb_error *err);

/* A ball's Level-2 results before an update: speeds qd_w and tractions
 * per unit contact load (the ring equilibrium scales them with the load,
 * mechanics.c ball_friction). */
typedef struct {
    double w[4], ti[3], to[3];
    int valid;
} acbb_qd_kept;

/* Keep the Level-2 results of st's distinct balls into k[0..distinct). */
void acbb_qd_keep(const acbb_mech_state *st, acbb_qd_kept *k);

/* Under-relax an update (a damped steady polish step, steady_polish.h):
 * each distinct ball solved before and after moves only the fraction w of
 * the way from its kept speeds and tractions to the new ones. */
void acbb_qd_relax(acbb_mech_state *st, const acbb_qd_kept *k, double w);

#endif
