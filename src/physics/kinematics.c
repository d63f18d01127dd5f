/* acbb — Level 1 (race control) ball kinematics, MODEL.md section 4. */
#include <math.h>
#include "kinematics.h"

static acbb_kin_angles angles(double alpha_i, double alpha_o)
{
    return (acbb_kin_angles){ alpha_o, sin(alpha_i), cos(alpha_i), sin(alpha_o), cos(alpha_o) };
}

/* The spin axis (beta, omega_R) from (wx, wz): for the angle forms only.
 * The sine/cosine forms are the mechanics' inner loop, where nothing reads
 * them (a hypot and an atan2 per ball evaluation saved, issue 30). */
static void spin_axis(acbb_kin *k)
{
    k->omega_R = hypot(k->wx, k->wz);
    k->beta = atan2(k->wz, -k->wx);
}

void acbb_kinematics_race_control(double alpha_i, double alpha_o, double D, double dm,
                                  double omega_i, acbb_control control, acbb_kin *k)
{
    acbb_kin_angles a = angles(alpha_i, alpha_o);
    acbb_kinematics_race_control_sc(&a, D, dm, omega_i, control, k);
    spin_axis(k);
}

void acbb_kinematics_from_omega(double alpha_i, double alpha_o, double D, double dm,
                                double omega_i, double omega_m, double wx, double wy,
                                double wz, acbb_kin *k)
{
    acbb_kin_angles a = angles(alpha_i, alpha_o);
    acbb_kinematics_from_omega_sc(&a, D, dm, omega_i, omega_m, wx, wy, wz, k);
    spin_axis(k);
}

void acbb_kinematics_race_control_sc(const acbb_kin_angles *a, double D, double dm,
                                     double omega_i, acbb_control control, acbb_kin *k)
{
    double g = D / dm; /* gamma' */
    double si = a->si, ci = a->ci, so = a->so, co = a->co;
    double tb = control == ACBB_CONTROL_OUTER ? so / (co + g) : si / (ci - g);
    double beta = atan(tb);
    double ratio = 1.0 / (1.0 + (1.0 + g * co) * (ci + tb * si)
                                    / ((1.0 - g * ci) * (co + tb * so)));
    double wm = ratio * omega_i;
    double wR = wm * (1.0 + g * co) / (g * cos(a->alpha_o - beta));
    acbb_kinematics_from_omega_sc(a, D, dm, omega_i, wm, -wR * cos(beta), 0.0,
                                  wR * sin(beta), k);
}

void acbb_kinematics_from_omega_sc(const acbb_kin_angles *a, double D, double dm,
                                   double omega_i, double omega_m, double wx, double wy,
                                   double wz, acbb_kin *k)
{
    double si = a->si, ci = a->ci, so = a->so, co = a->co;
    double rm = 0.5 * dm, wm = omega_m;
    k->omega_m = wm;
    k->wx = wx;
    k->wy = wy;
    k->wz = wz;
    /* Relative angular velocity ball - race along each contact normal. */
    k->spin_o = (wx + wm) * so + wz * co;
    k->spin_i = (omega_i - wm) * si - wx * si - wz * ci;
    /* Rolling component: omega_b across the normal in the meridional plane,
     * omega_R cos(alpha - beta) for omega_y' = 0. */
    k->roll_o = -wx * co + wz * so;
    k->roll_i = -wx * ci + wz * si;
    k->u_o = 0.5 * (0.5 * D * k->roll_o + wm * (rm + 0.5 * D * co));
    k->u_i = 0.5 * (0.5 * D * k->roll_i + (omega_i - wm) * (rm - 0.5 * D * ci));
    /* The two terms of u_c: ball and race surface speeds relative to the
     * contact centre, which is fixed in the cage frame (MODEL.md 4). */
    k->v_ball_o = fabs(0.5 * D * k->roll_o);
    k->v_race_o = fabs(wm * (rm + 0.5 * D * co));
    k->v_ball_i = fabs(0.5 * D * k->roll_i);
    k->v_race_i = fabs((omega_i - wm) * (rm - 0.5 * D * ci));
}

acbb_control acbb_race_control_choose(double Qi, double ai, double Ei, double Qo, double ao,
                                      double Eo, double alpha_i, double alpha_o,
                                      acbb_control previous)
{
    /* Jones: outer control if Qo ao Eo cos(ai - ao) > Qi ai Ei. A +-5 % band
     * keeps the choice from chattering between steps (MODEL.md section 11). */
    double lhs = Qo * ao * Eo * cos(alpha_i - alpha_o);
    double rhs = Qi * ai * Ei;
    if (rhs <= 0.0)
        return ACBB_CONTROL_OUTER;
    double r = lhs / rhs;
    if (previous == ACBB_CONTROL_OUTER)
        return r < 0.95 ? ACBB_CONTROL_INNER : ACBB_CONTROL_OUTER;
    return r > 1.05 ? ACBB_CONTROL_OUTER : ACBB_CONTROL_INNER;
}
