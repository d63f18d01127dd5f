/* acbb — the ring's radial and tilting stiffness at an operating point
 * (issue "any bearing", outputs): central differences of the quasi-static
 * (race-control) equilibrium in radial load and in moment, at the given
 * expansions, with the axial load (or the displacement preload) held.
 * Radial: the tilt held at the operating point's (0 in pure thrust);
 * tilt: radial free, and its twin with the ring held radially (issue 18:
 * the constraint named). The
 * axial stiffness comes from the coupled state itself (sim.c). */
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

#endif
