/* acbb — the power losses: the seed's five (eqs 14-18) and the optional
 * cage-land shear, MODEL.md section 6. Every loss is a row of one table
 * (acbb_loss_table): its names, where its heat goes, the effect switch that
 * enables it, and its formula -- a per-point integrand over the contact
 * ellipse (Gauss-Legendre), a closed form per contact, or a closed form for
 * the whole bearing. Adding a loss is one enum value, one row, one formula;
 * every client (JSON, CSV, TUI, plots) lists the table. */
#ifndef ACBB_LOSSES_H
#define ACBB_LOSSES_H

#include "acbb/scene.h"
#include "acbb/status.h"
#include <stddef.h>
#include "acbb/loss_kinds.h"
#include "lubrication.h"

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

/* Where a loss's heat enters the thermal network (MODEL.md 8.2). */
typedef enum {
    ACBB_HEAT_CONTACT,  /* the contact's race node (44 inner / 45 outer) */
    ACBB_HEAT_BALL,     /* the ball centre (15) */
    ACBB_HEAT_CAVITY,   /* the oil-air (43) */
    ACBB_HEAT_CAGE      /* the cage body (14) */
} acbb_heat_sink;

/* What a per-point integrand sees at one quadrature point of a contact. */
typedef struct {
    const acbb_scene *s;
    const acbb_contact_in *c;
    const acbb_film *film;
    const acbb_oil_state *oil;
    int seed;               /* fidelity.loss_form = seed */
    double x, y;            /* point on the ellipse, m */
    double p;               /* Hertz pressure, Pa */
    double V;               /* translational slip speed, m/s */
    double eta;             /* pressure viscosity, Pa s (0 without film) */
    double tauV;            /* lubricant shear stress at V, Pa */
    int eyring;             /* the Eyring law: stresses via acbb_eyring_capped */
    double H;               /* film thickness floored at 1 nm (acbb_tau_lubricant's floor) */
    double tlim;            /* limiting stress Lambda_L p, Pa */
} acbb_loss_point;

/* Whole-bearing inputs of the bearing-level losses. */
typedef struct {
    const acbb_scene *s;
    const acbb_mixture *mix;
    double omega_m;         /* mean orbital (cage) speed, rad/s */
    const acbb_oil_state *oil; /* the cavity oil (churning), may be NULL: no churning */
} acbb_bearing_in;

/* What a closed form per contact sees: the scene, the contact, its inlet
 * oil and film, the entrainment speed |u| (m/s). */
typedef struct {
    const acbb_scene *s;
    const acbb_contact_in *c;
    const acbb_oil_state *oil;
    const acbb_film *film;
    double u;
} acbb_contact_form;

typedef struct {
    const char *name;       /* JSON / CSV key, e.g. "shear" */
    const char *symbol;     /* e.g. "P_L" */
    const char *label;      /* e.g. "lubricant shear" */
    const char *effect;     /* its [effects] key, e.g. "loss_shear" */
    size_t flag;            /* offsetof(acbb_scene, that bool) */
    acbb_heat_sink sink;
    /* Exactly one formula: */
    double (*point)(const acbb_loss_point *pt);      /* integrand (W/m^2) */
    double (*finish)(const acbb_contact_in *c, int seed, double integral); /* NULL: as is */
    double (*contact)(const acbb_contact_form *f);   /* W */
    double (*bearing)(const acbb_bearing_in *in);    /* W */
} acbb_loss_desc;

extern const acbb_loss_desc acbb_loss_table[ACBB_LOSS_KINDS];

typedef struct {
    double P[ACBB_LOSS_KINDS]; /* W; bearing-level kinds stay 0 here */
    int integrated;     /* 1 when the ellipse quadrature ran */
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

/* Cage-land shear (Petroff), P_c = 2 pi eta_eff r_c^3 W_c omega_c^2 / c_g with
 * r_c = d_c/2, c_g = (d_2 - d_c)/2 (outer-land guided cage), omega_c = omega_m. */
double acbb_cage_loss(const acbb_scene *s, const acbb_mixture *mix, double omega_m);

#endif
