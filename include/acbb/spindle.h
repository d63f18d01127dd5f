/* acbb — a spindle's results as a user sees them (docs/spindle.md): the
 * shaft on a front and a rear bearing set, with its housing, motor and
 * coolant. Part of acbb_snapshot (sim.h): n_sets = 0 for a scene without
 * a spindle. Plain values, SI inside (the JSON names carry their units).
 *
 * Frames: x along the shaft from the nose (x = 0) towards the rear. Set 0
 * is the front set, set 1 the rear set. */
#ifndef ACBB_SPINDLE_H
#define ACBB_SPINDLE_H

#include "acbb/limits.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_SPINDLE_SETS 2
#define ACBB_SPINDLE_MAX_CELLS 96   /* shaft or housing cells in the view */

typedef struct {
    double x;                   /* set centre, m from the nose */
    int n_bearings;
    double preload_N;           /* axial force through the set with no external thrust, now */
    double axial_N;             /* axial force the set carries from the shaft, N */
    double radial_N;            /* radial reaction, N */
    double moment_Nm;           /* moment reaction, N m */
    double loss_W;              /* the set's losses, all of its bearings */
    double T_inner_C, T_outer_C, T_ball_C; /* hottest bearing of the set, C */
    double contact_angle_inner_deg[ACBB_MAX_SET]; /* each bearing's most loaded ball */
    double contact_angle_outer_deg[ACBB_MAX_SET];
    double Q_max_N[ACBB_MAX_SET];                 /* each bearing's largest ball load */
    int contact_lost;           /* 1: a bearing of the set has lifted off */
} acbb_spindle_set_view;

typedef struct {
    int n_sets;                 /* 0: not a spindle; else ACBB_SPINDLE_SETS */
    acbb_spindle_set_view sets[ACBB_SPINDLE_SETS];
    /* the nose (x = 0) */
    double nose_drift_axial;    /* the nose's axial move against the housing from the cold
                                 * first state to now, m (+: away from the front set,
                                 * towards -x): nose_drift_thermal less the change of
                                 * nose_u (docs/spindle.md "Nose drift") */
    double nose_drift_radial;   /* radial thermal growth of the shaft at the nose, m */
    double nose_u, nose_w, nose_theta; /* displacement under the loads: m, m, rad */
    double nose_k_axial, nose_k_radial, nose_k_tilt; /* static stiffness N/m, N/m, N m/rad */
    /* heat */
    double Q_motor_W;           /* rotor + stator */
    double Q_bearings_W;        /* both sets */
    double Q_coolant_W;         /* carried away by the coolant, m_dot c_p (T_out - T_in) */
    double Q_air_W;             /* to the air from the housing and the shaft ends */
    double T_coolant_in_C, T_coolant_out_C;
    /* temperatures along the axis, cell centres */
    int n_shaft, n_housing;
    double shaft_x[ACBB_SPINDLE_MAX_CELLS], shaft_T_C[ACBB_SPINDLE_MAX_CELLS];
    double housing_x[ACBB_SPINDLE_MAX_CELLS], housing_T_C[ACBB_SPINDLE_MAX_CELLS];
    double rear_shift;          /* shaft minus housing axial growth between the sets, m */
    double nose_drift_thermal;  /* the shaft's thermal growth from the front set to the nose
                                 * alone, m (+: away from the front set) */
    double nose_u_cold;         /* nose_u of the cold first state, m */
} acbb_spindle_view;

#ifdef __cplusplus
}
#endif

#endif
