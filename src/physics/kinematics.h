/* acbb — ball kinematics, Level 1 race control (MODEL.md section 4). */
#ifndef ACBB_KINEMATICS_H
#define ACBB_KINEMATICS_H

typedef enum { ACBB_CONTROL_OUTER, ACBB_CONTROL_INNER } acbb_control;

typedef struct {
    double beta;                /* spin-axis angle, rad */
    double omega_m;             /* orbital speed, rad/s */
    double omega_R;             /* ball spin magnitude, rad/s */
    double wx, wy, wz;          /* ball angular velocity in the orbiting frame */
    double spin_i, spin_o;      /* spin about the contact normals, rad/s */
    double roll_i, roll_o;      /* rolling components omega_R cos(alpha - beta) */
    double u_i, u_o;            /* entrainment speeds at the contact centres, m/s */
    /* each body's surface speed through the contact (cage frame, |.|), m/s:
     * the moving-heat-source spot resistances (docs/contact_heat.md) */
    double v_race_i, v_ball_i, v_race_o, v_ball_o;
} acbb_kin;

/* Race-control kinematics for contact angles (alpha_i, alpha_o), ball
 * diameter D, pitch diameter dm, inner-ring speed omega_i. For inner
 * control only beta changes. Finite for every input, incl. omega_i = 0. */
void acbb_kinematics_race_control(double alpha_i, double alpha_o, double D, double dm,
                                  double omega_i, acbb_control control, acbb_kin *k);

/* Spins, rolling components and entrainment speeds from a given orbital
 * speed and ball angular velocity (wx, wy, wz in the orbiting frame), as
 * the quasi-dynamic model produces them (MODEL.md section 4). beta and
 * omega_R are derived from (wx, wz). */
void acbb_kinematics_from_omega(double alpha_i, double alpha_o, double D, double dm,
                                double omega_i, double omega_m, double wx, double wy,
                                double wz, acbb_kin *k);

/* The same from the angles' sines and cosines, which a caller that has
 * them (mechanics.c ball_eval: the ratios of the contact geometry) passes
 * instead of recomputing them in each (issue 30 lever 4). These leave
 * beta and omega_R as they were (the mechanics' inner loop reads neither:
 * a hypot and an atan2 per ball evaluation; issue 30's fourth round). */
typedef struct {
    double alpha_o;        /* rad (the race-control beta needs it) */
    double si, ci, so, co; /* sin, cos of alpha_i and alpha_o */
} acbb_kin_angles;
void acbb_kinematics_race_control_sc(const acbb_kin_angles *a, double D, double dm,
                                     double omega_i, acbb_control control, acbb_kin *k);
void acbb_kinematics_from_omega_sc(const acbb_kin_angles *a, double D, double dm,
                                   double omega_i, double omega_m, double wx, double wy,
                                   double wz, acbb_kin *k);

/* Jones' criterion with a +-5 % hysteresis band around the previous choice. */
acbb_control acbb_race_control_choose(double Qi, double ai, double Ei, double Qo, double ao,
                                      double Eo, double alpha_i, double alpha_o,
                                      acbb_control previous);

#endif
