/* acbb — the five power losses of the seed (eqs 14-18), MODEL.md section 6,
 * by Gauss-Legendre quadrature over each contact ellipse. */
#ifndef ACBB_LOSSES_H
#define ACBB_LOSSES_H

#include "acbb/scene.h"
#include "acbb/status.h"
#include "acbb/lubrication.h"

#define ACBB_QUAD_MAX 64

/* Tensor Gauss-Legendre rule on [-1,1]^2, n points per axis. */
typedef struct {
    int n;
    double x[ACBB_QUAD_MAX], w[ACBB_QUAD_MAX];
} acbb_quad;

acbb_status acbb_quad_init(acbb_quad *q, int n);

/* One contact as the loss model sees it. */
typedef struct {
    int inner;          /* 1 inner race, 0 outer race */
    double Q, a, b, pmax; /* Hertz load (N), semi-axes (m), max pressure (Pa) */
    double delta;       /* deflection, m (seed-form P_r only) */
    double alpha;       /* contact angle, rad */
    double f;           /* groove curvature factor of this race */
    double D, dm;       /* ball and pitch diameters, m */
    double Rx, kappa, E_eff; /* for the film */
    double roll;        /* omega_R cos(alpha - beta), rad/s */
    double race;        /* race speed relative to the orbiting frame, rad/s */
    double spin;        /* spin about the normal, rad/s */
    double pivot;       /* ball angular velocity omega_y' (gyroscopic pivoting), rad/s */
    double u;           /* entrainment speed, m/s */
    double omega_m;     /* orbital speed (seed-form P_L, P_r), rad/s */
} acbb_contact_in;

typedef struct {
    double P_L, P_t, P_s, P_r; /* W */
    double slide;       /* pressure-weighted mean |translational slip|, m/s */
    acbb_film film;
} acbb_contact_loss;

/* Losses of one contact; effects switched off in the scene are skipped. */
acbb_status acbb_contact_losses(const acbb_scene *s, const acbb_quad *q,
                                const acbb_contact_in *c, const acbb_oil_state *oil,
                                acbb_contact_loss *out);

/* Translational slip V_c(x'') on the major axis (MODEL.md section 4), in
 * the rolling direction; pivoting adds omega_y' h across it. */
double acbb_slip_velocity(const acbb_contact_in *c, double x);
/* Magnitude of the translational slip at x'': hypot(V_c, omega_y' h). */
double acbb_slip_speed(const acbb_contact_in *c, double x);

/* Oil-air drag force on one ball (N) and the drag loss of all balls (W),
 * F_v = pi/32 C_D rho_eff D^2 (dm omega_m)^2, P_v = Z omega_m F_v dm / 2. */
double acbb_drag_force(const acbb_scene *s, const acbb_mixture *mix, double omega_m);
double acbb_drag_loss(const acbb_scene *s, const acbb_mixture *mix, double omega_m);

#endif
