/* acbb — internal to the dynamic level (dynamic.c, dynamic_balls.c). */
#ifndef ACBB_DYNAMIC_PRIV_H
#define ACBB_DYNAMIC_PRIV_H

#include "dynamic.h"

/* acbb_dyn_ball on worker w's traction tables (0 <= w < threads). */
acbb_status acbb_dyn_ball_on(acbb_dyn *d, int w, const acbb_dyn_env *env, acbb_mech_state *st,
                             int j, double window, double *change, acbb_error *err);

#endif
