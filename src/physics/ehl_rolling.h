/* acbb — EHL (hydrodynamic) rolling resistance of a ball-race contact
 * (MODEL.md 16): the inlet pressure of the film opposes rolling with a
 * force F_R; the contact dissipates F_R u. */
#ifndef ACBB_EHL_ROLLING_H
#define ACBB_EHL_ROLLING_H

#include "acbb/scene.h"

/* Isothermal, fully flooded rolling force (N) from the Hamrock-Dowson
 * groups U = eta0 u/(E' Rx), G = alpha E', W = Q/(E' Rx^2) and the
 * ellipticity kappa: F_R = 2.86 E' Rx^2 kappa^0.348 G^0.022 U^0.66 W^0.47. */
double acbb_ehl_rolling_force(double E_eff, double Rx, double kappa, double U, double G,
                              double W);

/* Kinematic replenishment / starvation factor of the bearing, in (0, 1]:
 * exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))), nu (mm^2/s) the oil's
 * at the contact inlet, n the inner-ring speed (rpm), d, D bore and OD
 * (mm); K_rs by lubrication method, K_Z by bearing type. */
double acbb_starvation_factor(const acbb_scene *s, double nu_mm2_s);

#endif
