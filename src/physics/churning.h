/* acbb — the oil the lubrication method puts in the bearing's way
 * (MODEL.md 16): churning of the balls through an oil bath, and the
 * momentum given to an oil jet. Heat goes to the cavity oil. */
#ifndef ACBB_CHURNING_H
#define ACBB_CHURNING_H

#include "acbb/scene.h"
#include "lubrication.h"

/* Fraction of the ball volume below the bath level, averaged over one
 * orbit (0 unless method = oil-bath). */
double acbb_bath_immersion(const acbb_scene *s);

/* Standard sphere drag curve C_D(Re), Clift & Gauvin 1970. */
double acbb_sphere_cd(double Re);

/* The churning / jet loss of the whole bearing (W) at orbital speed
 * omega_m (rad/s) with the cavity oil `oil`. */
double acbb_churning_loss(const acbb_scene *s, const acbb_oil_state *oil, double omega_m);

#endif
