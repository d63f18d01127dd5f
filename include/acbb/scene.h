/* acbb — a Scene: everything a preset file says, in SI units.
 *
 * Units inside a Scene: m, N, s, rad, rad/s, Pa, W, kg, J. Temperatures are
 * stored in degrees Celsius (only differences and the Walther law use them;
 * the Walther law converts to K itself). The preset file uses the units
 * named in each key (`ball_diameter_mm`, `inner_speed_rpm`, ...); the schema
 * table in src/scene/scene_schema.c converts both ways.
 *
 * Ownership: an acbb_scene is a plain value (no pointers); copy it freely. */
#ifndef ACBB_SCENE_H
#define ACBB_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

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
/* Lubrication method (MODEL.md 16): the seed's oil-air, oil jet, oil bath, grease. */
typedef enum { ACBB_LUB_OIL_AIR, ACBB_LUB_OIL_JET, ACBB_LUB_OIL_BATH, ACBB_LUB_GREASE } acbb_lub_method;
/* ISO 3448 viscosity grade (MODEL.md 16); CUSTOM: the oil_nu40/oil_nu100 keys. */
typedef enum { ACBB_GRADE_CUSTOM, ACBB_GRADE_VG2, ACBB_GRADE_VG3, ACBB_GRADE_VG5, ACBB_GRADE_VG7,
               ACBB_GRADE_VG10, ACBB_GRADE_VG15, ACBB_GRADE_VG22, ACBB_GRADE_VG32,
               ACBB_GRADE_VG46, ACBB_GRADE_VG68, ACBB_GRADE_VG100, ACBB_GRADE_VG150,
               ACBB_GRADE_VG220, ACBB_GRADE_VG320, ACBB_GRADE_VG460, ACBB_GRADE_VG680,
               ACBB_GRADE_VG1000, ACBB_GRADE_VG1500, ACBB_GRADES } acbb_oil_grade;
typedef enum { ACBB_LOSS_CLEAN, ACBB_LOSS_SEED } acbb_loss_form;
typedef enum { ACBB_HYST_MAJOR, ACBB_HYST_MINOR } acbb_hyst_axis;
/* fidelity.rolling_hysteresis: the seed's Eq. 18 force 4 eps Q a_c / (3 pi D)
 * (axis by hyst_axis) or Johnson's sphere (3/16) eps Q b / R_x (losses.c). */
typedef enum { ACBB_ROLL_HYST_SEED, ACBB_ROLL_HYST_JOHNSON } acbb_roll_hyst;
/* physics.profile (physics_profile.h): which physics a scene's loss keys
 * default to: the seed paper's, or the best-founded ("reference") set. */
typedef enum { ACBB_PROFILE_SEED, ACBB_PROFILE_REFERENCE } acbb_physics_profile;
typedef enum { ACBB_NET_46, ACBB_NET_7 } acbb_network_kind;
typedef enum { ACBB_PRELOAD_FORCE, ACBB_PRELOAD_DISPLACEMENT } acbb_preload_mode;
/* [set] arrangement (MODEL.md 14): single = one bearing (today's scenes).
 * The one table of arrangements, a row each: X(ID, name, bearings, most
 * bearings, the direction of each bearing's thrust by increasing x with
 * the last sign repeated) [HK-EC, preloading chapter]: DB (O) +-, DF (X)
 * -+, DT tandem ++.., DBT ++-, QBC ++--. acbb/tools/set.h reads it. */
#define ACBB_SET_ARRANGEMENT_TABLE(X) \
    X(SINGLE, "single", 1, 1, "+") \
    X(DB, "DB", 2, 2, "+-") \
    X(DF, "DF", 2, 2, "-+") \
    X(DT, "DT", 2, ACBB_MAX_SET, "+") \
    X(DBT, "DBT", 3, 3, "++-") \
    X(QBC, "QBC", 4, 4, "++--")
#define ACBB_SET_ENUM_ROW(id, name, n, n_max, orient) ACBB_SET_##id,
typedef enum {
    ACBB_SET_ARRANGEMENT_TABLE(ACBB_SET_ENUM_ROW)
    ACBB_SET_ARRANGEMENTS                    /* how many */
} acbb_set_arrangement;
/* mounting.tilt (issue 18): auto (default) = free: solved under any off-axis load. */
typedef enum { ACBB_TILT_AUTO, ACBB_TILT_FREE, ACBB_TILT_HELD } acbb_tilt_mode;
/* [spindle] rear_support (docs/spindle.md): how the rear set is held
 * axially. fixed: located in the housing like the front set (the shaft's
 * growth between the sets loads both); spring: its outer rings slide in a
 * sleeve pushed by springs (rear_spring_N through the rear set, reacted by
 * the front); floating: a sliding sleeve with friction rear_friction_N
 * against the shaft's growth. */
typedef enum { ACBB_REAR_FIXED, ACBB_REAR_SPRING, ACBB_REAR_FLOATING } acbb_rear_support;
#define ACBB_SPINDLE_MAX_SEG 8  /* segments of the shaft and of the housing */
/* One stepped-cylinder segment of a spindle's shaft or housing, m. The
 * housing's bore is the bore its bearings sit in. */
typedef struct {
    double length, od, bore;
} acbb_segment;
typedef enum { ACBB_THERMAL_TRANSIENT, ACBB_THERMAL_STEADY } acbb_thermal_mode;
/* thermal.contact_model (docs/contact_heat.md): stationary = isothermal spot
 * constriction on both bodies (MODEL.md 8.1 SP, the seed); moving = each
 * body's surface passes through the contact (Archard / Tian-Kennedy). */
typedef enum { ACBB_CONTACT_STATIONARY, ACBB_CONTACT_MOVING } acbb_contact_model;
/* fidelity.preset (fidelity.h): custom = the individual knobs. */
typedef enum { ACBB_FIDELITY_CUSTOM, ACBB_FIDELITY_FAST, ACBB_FIDELITY_BALANCED,
               ACBB_FIDELITY_REFERENCE } acbb_fidelity_preset;
/* Boundary condition of a cooled face (MODEL.md 8.1, 13 "Surroundings"). */
typedef enum { ACBB_BC_FIXED, ACBB_BC_DERIVED, ACBB_BC_CONVECTIVE } acbb_bc_kind;

typedef struct {
    acbb_bc_kind kind;   /* fixed: face at the coolant temperature; convective: film h */
    double h;            /* film coefficient, W/(m^2 K) (convective only) */
    double dT;           /* coolant temperature minus ambient_C, K */
} acbb_face_bc;

/* One row of a run-in schedule (MODEL.md 14 "Run-in schedule"; schedule.h):
 * from time t on, the operating point moves linearly to the next row's. */
#define ACBB_SCHEDULE_MAX 32
typedef struct {
    double t;                    /* s from the start of the run */
    double inner_speed;          /* rad/s (preset: rpm) */
    double axial_load, radial_load; /* N */
} acbb_schedule_row;

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
    acbb_lub_method lub_method;  /* starvation factor and drag medium (MODEL.md 16) */
    acbb_oil_grade oil_grade;    /* ISO VG: nu40 midpoint, nu100 from oil_vi (tools/lubricant.h) */
    double oil_vi;               /* viscosity index (ASTM D2270) of a graded oil */
    double jet_speed;            /* oil-jet exit speed, m/s (method oil-jet) */
    double bath_level;           /* oil level above the lowest outer-raceway point, m (oil-bath) */
    double grease_nu40;          /* grease base-oil nu40, m^2/s; 0 = the oil's (method grease) */

    /* [mounting] */
    double shaft_bore;           /* hollow-shaft bore diameter d_s, m */
    double h_fit_outer;          /* OR/housing contact conductance, W/(m^2 K) */
    double h_fit_inner;          /* IR/shaft contact conductance, W/(m^2 K) */
    double h_face;               /* clamped face conductance, W/(m^2 K) */
    double h_natural;            /* housing exterior convection, W/(m^2 K) */
    acbb_preload_mode preload;
    double preload_force;        /* N; displacement preload set at 20 C, 0 rpm */
    acbb_tilt_mode tilt;         /* inner-ring tilt: auto, free or held */
    /* [set] (MODEL.md 14): bearings on one shaft. For a set, preload =
     * displacement is rigid (spacers), force is a spring on the floating
     * side; preload_force is the assembly preload; axial/radial/moment
     * loads act on the shaft at the nose. */
    acbb_set_arrangement set_arrangement;
    int set_n_bearings;          /* DT: tandem bearings 2..4; 0 = the arrangement's count */
    double set_spacing;          /* centre distance of neighbours, m; 0 = adjacent (width) */
    double set_load_offset;      /* nose x_F minus the set's centre x_0, m */
    double set_spacer_chi;       /* both spacers' expansion, 1/K; 0 = inner as the shaft,
                                  * outer as the housing (MODEL.md 14 chi_s, chi_h) */
    double set_inner_spacer;     /* inner spacer length L_s, m; 0 = spacing - width (matched) */
    double set_outer_spacer;     /* outer spacer length L_h, m; 0 = spacing - width (matched) */

    /* [shaft] [housing] [motor] [spindle] (docs/spindle.md): a spindle is a
     * scene with shaft_segments > 0. [bearing], [set] and [mounting]
     * describe its front set; operating.axial_load_N / radial_load_N act at
     * the nose (x = 0, x grows towards the rear); the shaft and the housing
     * use materials.shaft and materials.housing. */
    int shaft_segments;          /* 0: no spindle (a bearing or a set, as before) */
    acbb_segment shaft_seg[ACBB_SPINDLE_MAX_SEG]; /* from the nose */
    int shaft_n_div;             /* beam elements and thermal cells per segment */
    int housing_segments;
    acbb_segment housing_seg[ACBB_SPINDLE_MAX_SEG];
    double housing_x0;           /* where the housing starts, m from the nose */
    double housing_h_outer;      /* outer surface film to the air, W/(m^2 K) */
    double motor_rotor_loss;     /* W, on the shaft cells under the rotor */
    double motor_stator_loss;    /* W, on the housing cells under the stator */
    double motor_x0, motor_x1;   /* rotor and stator span, m from the nose (x1 = x0: no motor) */
    double motor_gap_G;          /* rotor <-> stator across the air gap, W/K */
    double spindle_front_x;      /* front set centre, m from the nose */
    double spindle_rear_x;       /* rear set centre, m from the nose */
    acbb_rear_support spindle_rear_support;
    acbb_set_arrangement spindle_rear_arrangement; /* the rear set, of the same bearing */
    double spindle_rear_spacing; /* its centre distance of neighbours, m; 0 = adjacent */
    double spindle_rear_preload; /* rear pair's rigid (spacer) preload at assembly, N */
    double spindle_rear_spring;  /* spring: axial force on the rear set, N */
    double spindle_rear_friction;/* floating: sleeve friction, N */
    double coolant_flow;         /* jacket flow, m^3/s (preset: l/min); 0 = no coolant */
    double coolant_inlet_dT;     /* inlet minus ambient_C, K */
    double coolant_rho, coolant_cp; /* kg/m^3, J/(kg K) */
    double jacket_x0, jacket_x1; /* jacket span on the housing, m from the nose */
    double jacket_hA;            /* jacket wall conductance, whole jacket, W/K */
    int coolant_cells;           /* well-mixed coolant cells along the jacket */
    double shaft_h_end;          /* shaft end faces to the air, W/(m^2 K) */

    /* [surroundings] (MODEL.md 8.1, 13): sizes 0 = derived from the bearing
     * (tools/surroundings.h); housing and cap use materials.housing */
    double housing_od;           /* housing outer diameter, m */
    double housing_length;       /* housing length (centred on the bearing), m */
    acbb_bc_kind housing_bc;     /* exterior: convective (h_natural, to ambient) or fixed */
    double shaft_length;         /* shaft segment carried by the network, m */
    acbb_face_bc bore_bc;        /* hollow-shaft bore face (seed: fixed at ambient) */
    double cap_od;               /* end cap outer diameter, m */
    double cap_thickness;        /* end cap thickness, m */
    acbb_face_bc cap_bc;         /* end cap outer face (seed: fixed at ambient) */

    /* [operating] */
    double inner_speed;          /* omega_i, rad/s (preset: rpm) */
    double axial_load;           /* F_x, N (on the IR, +x) */
    double radial_load;          /* F_z, N */
    double moment_load;          /* M_y, N m */
    double ambient_C;            /* ambient = reference temperature, C */
    /* [schedule]: 0 rows = none; else the rows set speed, axial and radial
     * load over time (schedule.h) and the [operating] values of those are unused */
    int schedule_n;
    acbb_schedule_row schedule[ACBB_SCHEDULE_MAX];

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
    bool loss_ehl_rolling;       /* P_e EHL rolling resistance (MODEL.md 16), default off */
    bool loss_churning;          /* P_ch oil churning / jet momentum (MODEL.md 16), default off */

    /* [fidelity] */
    acbb_model_level model;
    int contact_grid;            /* Gauss-Legendre points per axis of the ellipse */
    acbb_hertz_mode hertz;
    acbb_geom_mode geometry;     /* CLEAN (default) or SEED literal eqs 12-13 */
    acbb_race_control race_control;
    acbb_loss_form loss_form;
    acbb_hyst_axis hyst_axis;
    acbb_roll_hyst roll_hyst;    /* rolling hysteresis force: seed Eq. 18 or Johnson */
    double mech_tol;             /* relative force residual tolerance */
    double steady_tol;           /* steady state: max dT/dt, K/s */

    /* [thermal] */
    acbb_network_kind network;
    acbb_thermal_mode thermal_mode;
    double time_step;            /* initial thermal time step, s */
    acbb_fidelity_preset fidelity_preset; /* overrides the knobs above (fidelity.h) */
    double target_error;         /* fidelity.target_error_pct as a fraction, 0 = off */
    double max_wall_s;           /* fidelity.max_wall_s: a run's computing time bound, 0 = none */
    double max_time;             /* simulated time limit, s */
    int max_steps;               /* coupled step limit */
    double temp_limit_C;         /* RUNAWAY above this node temperature, C */
    double contact_multiplier;   /* c_mv on race-side spot resistances */
    acbb_contact_model contact_model; /* spot resistances: stationary or moving source */
    double heat_partition;       /* phi_p for the 7-node network */

    /* [life] rating life and static safety (MODEL.md 15, life.h) */
    double life_reliability;     /* reliability for L_nm, % (ISO 281 Table 12) */
    double life_ec;              /* contamination factor e_c (ISO 281 Table 13) */
    double life_Cu;              /* fatigue load limit C_u, N; 0 = ISO 281 Annex B from C0 */
    double life_shoulder_inner;  /* inner shoulder height above the groove bottom, m;
                                  * 0 = from inner_land_diameter */
    double life_shoulder_outer;  /* outer shoulder height, m; 0 = from outer_land_diameter */
    bool life_estimated;         /* internal geometry estimated (`acbb new`), ratings too */

    /* [physics] (physics_profile.h) */
    acbb_physics_profile profile; /* the defaults of the profile's keys */
    unsigned profile_given;      /* bit k: the profile table's row k was given explicitly
                                  * (in the preset or by acbb_scene_set): the profile
                                  * does not move it */
} acbb_scene;

/* Fill `s` with the 7008C defaults of MODEL.md section 10. */
void acbb_scene_default(acbb_scene *s);

/* Load a preset: starts from acbb_scene_default, then applies every key.
 * On failure returns ACBB_EIO or ACBB_EINVAL and writes
 * "path:line: section.key = value: reason" into err. Only a regular file
 * is read (a FIFO or device is refused at once, without blocking). Numbers
 * are decimal only (no 0x10). Control characters quoted from the file are
 * shown escaped (\x1b) in every message of this module. */
acbb_status acbb_scene_load(const char *path, acbb_scene *s, acbb_error *err);

/* acbb_scene_load from preset text in memory (NUL-terminated), with the
 * same checks and messages, the source named "<text>" ("<text>:3: ..."). */
acbb_status acbb_scene_load_text(const char *text, acbb_scene *s, acbb_error *err);
/* The same from `len` bytes of text (no terminator needed): a NUL byte
 * inside them is refused ("<text>:2: NUL byte in line 2 ..."), as in a
 * file, where the NUL-terminated form would end the text there. Messages
 * name the source `name` ("<stdin>:3: ..."; NULL: "<text>"). */
acbb_status acbb_scene_load_text_n(const char *text, size_t len, const char *name,
                                   acbb_scene *s, acbb_error *err);

/* Write the whole preset: every schema key, with its unit in the key name
 * and a comment line (help and range) above it. Written through acbb_out
 * (outfile.h): temp file beside the target, fsync, rename; the mode is
 * kept, a symlink is followed (the link stays), a non-regular target (FIFO,
 * /dev/stdout) is written directly. An invalid scene is not written
 * (message "PATH: not saved: reason"). Use this for "save as" to a new file
 * or an export; to save back into the user's own preset, use
 * acbb_scene_save_edits (tools/scene_edit.h). */
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

#ifdef __cplusplus
}
#endif

#endif
