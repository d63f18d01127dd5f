/* The kinematics from the contact angles' sines and cosines (issue 30
 * lever 4: mechanics.c passes the geometry's ratios instead of
 * recomputing them) agree with the angle forms over race control and
 * given ball speeds, including zero speed, to round-off (1e-10 of the
 * values or of 1 rad/s, m/s: spins near 0 cancel terms of 1e3). */
#include <math.h>
#include "tap.h"
#include "kinematics.h"

/* beta and omega_R: the angle forms' only (the sine/cosine forms leave
 * them, kinematics.h); they are hypot and atan2 of the compared wx, wz. */
static double worst_diff(const acbb_kin *a, const acbb_kin *b)
{
    const double x[] = { a->omega_m, a->wx, a->wz, a->spin_i, a->spin_o,
                         a->roll_i, a->roll_o, a->u_i, a->u_o, a->v_ball_i, a->v_race_i };
    const double y[] = { b->omega_m, b->wx, b->wz, b->spin_i, b->spin_o,
                         b->roll_i, b->roll_o, b->u_i, b->u_o, b->v_ball_i, b->v_race_i };
    double w = 0.0;
    for (size_t i = 0; i < sizeof x / sizeof x[0]; i++)
        w = fmax(w, fabs(x[i] - y[i]) / fmax(fabs(x[i]), 1.0));
    return w;
}

int main(void)
{
    const double D = 6.35e-3, dm = 54e-3, speeds[] = { 0.0, 1571.0 };
    double w = 0.0;
    for (int s = 0; s < 2; s++)
        for (double ai = 0.0; ai < 0.8; ai += 0.1)
            for (double ao = 0.0; ao < 0.8; ao += 0.13) {
                /* the sines and cosines as ball_eval forms them: ratios of
                 * a vector of length 3.4 mm */
                double L = 3.4e-3;
                acbb_kin_angles an = { ao, L * sin(ai) / L, L * cos(ai) / L, L * sin(ao) / L,
                                       L * cos(ao) / L };
                for (int c = 0; c < 2; c++) {
                    acbb_control ctl = c ? ACBB_CONTROL_OUTER : ACBB_CONTROL_INNER;
                    acbb_kin a, b;
                    acbb_kinematics_race_control(ai, ao, D, dm, speeds[s], ctl, &a);
                    acbb_kinematics_race_control_sc(&an, D, dm, speeds[s], ctl, &b);
                    w = fmax(w, worst_diff(&a, &b));
                }
                acbb_kin a, b;
                acbb_kinematics_from_omega(ai, ao, D, dm, speeds[s], 700.0, -3e3, 1.0, 900.0, &a);
                acbb_kinematics_from_omega_sc(&an, D, dm, speeds[s], 700.0, -3e3, 1.0, 900.0, &b);
                w = fmax(w, worst_diff(&a, &b));
            }
    ok(w < 1e-10, "race control and given speeds: the sine/cosine forms agree to %.2g", w);
    return done_testing();
}
