/* acbb — a Scene: everything a preset file says, in SI units.
 *
 * Units inside a Scene: m, N, s, rad, rad/s, Pa, W, kg, J. Temperatures are
 * stored in degrees Celsius (only differences and the Walther law use them;
 * the Walther law converts to K itself). The preset file uses the units
 * named in each key (`ball_diameter_mm`, `inner_speed_rpm`, ...); the schema
 * table in scene.c converts both ways.
 *
 * Ownership: an acbb_scene is a plain value (no pointers); copy it freely. */
#ifndef ACBB_SCENE_H
#define ACBB_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/status.h"

typedef struct {
    double E;      /* Young's modulus, Pa */
    double nu;     /* Poisson ratio */
    double rho;    /* density, kg/m^3 */
    double cp;     /* specific heat, J/(kg K) */
    double k;      /* thermal conductivity, W/(m K) */
    double chi;    /* linear expansion coefficient, 1/K */
} acbb_material;

typedef enum { ACBB_MODEL_STATIC, ACBB_MODEL_QUASI_STATIC,
               ACBB_MODEL_QUASI_DYNAMIC, ACBB_MODEL_DYNAMIC } acbb_model_level;
typedef enum { ACBB_GEOM_CLEAN, ACBB_GEOM_SEED } acbb_geom_mode;
typedef enum { ACBB_RACE_OUTER, ACBB_RACE_INNER, ACBB_RACE_EQUAL,
               ACBB_RACE_AUTO } acbb_race_control;
typedef enum { ACBB_HERTZ_EXACT, ACBB_HERTZ_BH77, ACBB_HERTZ_HB83 } acbb_hertz_mode;
typedef enum { ACBB_VISC_ROELANDS, ACBB_VISC_BARUS, ACBB_VISC_CONST } acbb_visc_model;
typedef enum { ACBB_TRACTION_EYRING_CAP, ACBB_TRACTION_BAIR_WINER } acbb_traction_model;
typedef enum { ACBB_LOSS_CLEAN, ACBB_LOSS_SEED } acbb_loss_form;
typedef enum { ACBB_HYST_MAJOR, ACBB_HYST_MINOR } acbb_hyst_axis;
typedef enum { ACBB_NET_46, ACBB_NET_7 } acbb_network_kind;
typedef enum { ACBB_PRELOAD_FORCE, ACBB_PRELOAD_DISPLACEMENT } acbb_preload_mode;
typedef enum { ACBB_THERMAL_TRANSIENT, ACBB_THERMAL_STEADY } acbb_thermal_mode;

typedef struct {
    /* [bearing] geometry (MODEL.md section 1, section 10) */
    double pitch_diameter;       /* d_m, m */
    double ball_diameter;        /* D, m */
    int n_balls;                 /* Z */
    double inner_groove_radius;  /* lambda_i, m */
    double outer_groove_radius;  /* lambda_o, m */
    double contact_angle0;       /* alpha^0 nominal free contact angle, rad (0: deep groove) */
    double clearance;            /* P_d diametral clearance, m; 0 = derived from contact_angle0
                                  * (acbb_free_contact_angle, geometry.h, gives the angle in use) */
    double bore;                 /* bearing bore diameter, m */
    double outer_diameter;       /* bearing outside diameter, m */
    double width;                /* bearing width B_w, m */
    double cage_width;           /* W_c, m */
    double cage_diameter;        /* d_c cage guide (outer) diameter, m */
    double inner_land_diameter;  /* d_1, m */
    double outer_land_diameter;  /* d_2, m */
    double roughness_race;       /* sigma_race, m (RMS) */
    double roughness_ball;       /* sigma_ball, m (RMS) */

    /* [materials] */
    acbb_material ball, ring, shaft, housing, cage;

    /* [lubricant] (MODEL.md section 5, section 10) */
    double oil_density;          /* kg/m^3 at 20 C */
    double oil_nu40;             /* kinematic viscosity at 40 C, m^2/s */
    double oil_nu100;            /* kinematic viscosity at 100 C, m^2/s */
    double oil_eta_const;        /* constant viscosity for visc=const, Pa s */
    double oil_alpha_pv;         /* pressure-viscosity coefficient, 1/Pa */
    double oil_k;                /* W/(m K) */
    double oil_cp;               /* J/(kg K) */
    double air_eta;              /* Pa s */
    double air_density;          /* kg/m^3 */
    double air_k;                /* W/(m K) */
    double air_cp;               /* J/(kg K) */
    double air_pr;               /* Prandtl number */
    double mix_k;                /* oil-air mixture conductivity k_d, W/(m K) */
    double q_air;                /* air flow, m^3/s */
    double q_oil;                /* oil flow, m^3/s */
    double mu_bd;                /* boundary (asperity) friction coefficient */
    double lambda_lim;           /* limiting shear stress / pressure, Lambda_L */
    double tau_eyring;           /* Eyring stress tau_E, Pa */
    double hysteresis;           /* elastic hysteresis loss coefficient epsilon */
    double drag_cd;              /* sphere drag coefficient C_D */
    acbb_visc_model visc;
    acbb_traction_model traction;

    /* [mounting] */
    double shaft_bore;           /* hollow-shaft bore diameter d_s, m */
    double h_fit_outer;          /* OR/housing contact conductance, W/(m^2 K) */
    double h_fit_inner;          /* IR/shaft contact conductance, W/(m^2 K) */
    double h_face;               /* clamped face conductance, W/(m^2 K) */
    double h_natural;            /* housing exterior convection, W/(m^2 K) */
    acbb_preload_mode preload;
    double preload_force;        /* N; displacement preload set at 20 C, 0 rpm */

    /* [operating] */
    double inner_speed;          /* omega_i, rad/s (preset: rpm) */
    double axial_load;           /* F_x, N (on the IR, +x) */
    double radial_load;          /* F_z, N */
    double moment_load;          /* M_y, N m */
    double ambient_C;            /* ambient = reference temperature, C */

    /* [effects]: a disabled effect is not computed at all */
    bool heating;                /* off: isothermal at ambient, no thermal network solve */
    bool thermal_expansion;      /* TE (true) / WTE (false) */
    bool centrifugal;            /* ball centrifugal force */
    bool gyroscopic;             /* gyroscopic moment */
    bool ring_centrifugal;       /* centrifugal growth of the IR (eq 9) */
    bool ehl_film;               /* EHL film; off => boundary friction only */
    bool loss_shear;             /* P_L */
    bool loss_slip;              /* P_t */
    bool loss_spin;              /* P_s */
    bool loss_rolling;           /* P_r */
    bool loss_drag;              /* P_v */
    bool loss_cage;              /* P_c cage-land shear (MODEL.md 6 iii), default off */

    /* [fidelity] */
    acbb_model_level model;
    int contact_grid;            /* Gauss-Legendre points per axis of the ellipse */
    acbb_hertz_mode hertz;
    acbb_geom_mode geometry;     /* CLEAN (default) or SEED literal eqs 12-13 */
    acbb_race_control race_control;
    acbb_loss_form loss_form;
    acbb_hyst_axis hyst_axis;
    double mech_tol;             /* relative force residual tolerance */
    double steady_tol;           /* steady state: max dT/dt, K/s */

    /* [thermal] */
    acbb_network_kind network;
    acbb_thermal_mode thermal_mode;
    double time_step;            /* initial thermal time step, s */
    double max_time;             /* simulated time limit, s */
    int max_steps;               /* coupled step limit */
    double temp_limit_C;         /* RUNAWAY above this node temperature, C */
    double contact_multiplier;   /* c_mv on race-side spot resistances */
    double heat_partition;       /* phi_p for the 7-node network */
} acbb_scene;

/* Fill `s` with the 7008C defaults of MODEL.md section 10. */
void acbb_scene_default(acbb_scene *s);

/* Load a preset: starts from acbb_scene_default, then applies every key.
 * On failure returns ACBB_EIO or ACBB_EINVAL and writes
 * "path:line: section.key = value: reason" into err. */
acbb_status acbb_scene_load(const char *path, acbb_scene *s, acbb_error *err);

/* Save atomically (temp file in the same directory, fsync, rename).
 * Every schema key is written, with its unit in the key name. */
acbb_status acbb_scene_save(const char *path, const acbb_scene *s, acbb_error *err);

/* Set one value from text, "section.key" and "value" in preset units
 * (as `--set` on the CLI and the TUI editor do). Validates the value;
 * `s` is unchanged on failure. Unknown keys suggest the nearest key. */
acbb_status acbb_scene_set(acbb_scene *s, const char *dotted_key,
                           const char *value, acbb_error *err);

/* As acbb_scene_set, but only the key's own range is checked: for a batch of
 * edits (several --set on the CLI) that is consistent only as a whole; call
 * acbb_scene_validate once after the last one. */
acbb_status acbb_scene_set_value(acbb_scene *s, const char *dotted_key, const char *value,
                                 acbb_error *err);

/* A batch of "section.key=value" edits (the CLI's --set list): each is
 * range-checked as it is applied, the cross-field rules run once at the end,
 * so the order of the edits does not matter. `s` is unchanged on failure;
 * the message starts with "--set EDIT:" for an edit's own error. */
acbb_status acbb_scene_apply_edits(acbb_scene *s, const char *const *edits, size_t n,
                                   acbb_error *err);

/* Cross-field consistency (balls fit on the pitch circle, groove radius >
 * ball radius, ...). Returns ACBB_EINVAL with the reason in err. */
acbb_status acbb_scene_validate(const acbb_scene *s, acbb_error *err);

/* ---- schema introspection (for the TUI editor and help output) ---- */
typedef enum { ACBB_FIELD_REAL, ACBB_FIELD_INT, ACBB_FIELD_BOOL,
               ACBB_FIELD_ENUM } acbb_field_type;

typedef struct {
    const char *section;     /* "bearing" */
    const char *key;         /* "ball_diameter_mm" (unit in the name) */
    acbb_field_type type;
    const char *unit;        /* "mm", "rpm", "" */
    double min, max;         /* allowed range in preset units (inclusive) */
    const char *const *choices; /* NULL-terminated, for ENUM */
    const char *help;        /* one line */
} acbb_field_info;

size_t acbb_scene_field_count(void);
const acbb_field_info *acbb_scene_field(size_t i);
/* Current value of field i, formatted in preset units (buf >= 64 bytes). */
void acbb_scene_field_format(const acbb_scene *s, size_t i, char *buf, size_t n);
/* Allowed values of field i as text (buf >= 160 bytes), e.g.
 * "0 < x <= 100 mm", "on | off", "static | quasi-static | ...". Says which
 * range ends are exclusive, which acbb_field_info cannot. */
void acbb_scene_field_range(size_t i, char *buf, size_t n);

const char *acbb_model_level_name(acbb_model_level m);

/* Effect switches that do nothing in this scene (at its model level, or
 * because another switch overrides them): their [effects] key names,
 * static strings, at most `cap` of them; returns how many. A client says so
 * instead of ignoring the switch silently. */
size_t acbb_scene_inactive_effects(const acbb_scene *s, const char **names, size_t cap);

#endif
