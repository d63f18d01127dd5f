/* acbb — the ring's radial and tilting stiffness at an operating point
 * (issue "any bearing", outputs): central differences of the quasi-static
 * (race-control) equilibrium in radial load and in moment, at the given
 * expansions, with the axial load (or the displacement preload) held.
 * Radial: the tilt held at the operating point's (0 in pure thrust);
 * tilt: radial free, and its twin with the ring held radially (issue 18:
 * the constraint named). The
 * axial stiffness comes from the coupled state itself
 * (acbb_axial_stiffness, called by sim_plant.c with the run's mechanics). */
#ifndef ACBB_STIFFNESS_H
#define ACBB_STIFFNESS_H

#include "expansion.h"
#include "mechanics.h"
#include "acbb/scene.h"
#include "acbb/status.h"

typedef struct {
    double radial;      /* dFz/d(delta_z), tilt held, N/m */
    double tilt;        /* dMy/d(theta_y), radial free, N m/rad */
    double tilt_held;   /* dMy/d(theta_y) with the ring held radially, N m/rad */
} acbb_stiffness;

/* dx_held: the axial displacement to hold when the scene's preload is a
 * displacement (ignored otherwise). warm: NULL or a converged state of the
 * scene at its speed and expansions (any ball model, e.g. the sim's), the
 * warm start of every probe; without it (or if a warm solve fails) each
 * probe is reached by continuation in speed from rest (4 solves). Either
 * value is 0 when its solves fail (a bearing with no load cannot be
 * differenced). */
acbb_status acbb_ring_stiffness(const acbb_scene *s, const acbb_expansion *e, double dx_held,
                                const acbb_mech_state *warm, acbb_stiffness *out);

/* Axial stiffness dFx/d(delta_x) of m's equilibrium at `at` (a converged
 * state of m at omega_i and e): a central difference with the axial
 * displacement held at at->dx +- max(1e-4 |dx|, 1 nm), the other ring
 * freedoms solved, ball speeds and tractions as in `at`. The two solves
 * are resolved 1e-4 times finer than m's tolerance (their difference is
 * 1e-4 of the force). Afterwards m holds the axial displacement at at->dx
 * if `held` (a displacement preload), else frees it. NAN if a solve fails. */
double acbb_axial_stiffness(acbb_mech *m, double omega_i, const acbb_expansion *e,
                            const acbb_mech_state *at, int held);

#endif
