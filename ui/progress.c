/* acbb TUI — progress estimate (see progress.h). */
#include <math.h>
#include "progress.h"

void acbb_progress_reset(acbb_progress *p)
{
    p->valid = 0;
    p->log_r0 = 0.0;
    p->wall0 = 0.0;
    p->fraction = 0.0;
    p->eta_s = -1.0;
}

void acbb_progress_update(acbb_progress *p, double residual, double wall_s, double tol)
{
    if (!(residual > 0) || !(tol > 0) || !isfinite(residual)) return;
    double lr = log(residual), lt = log(tol);
    if (!p->valid) {
        p->valid = 1;
        p->log_r0 = lr;
        p->wall0 = wall_s;
    }
    double span = p->log_r0 - lt;
    if (!(span > 0)) {
        p->fraction = lr <= lt ? 1.0 : 0.0;
        p->eta_s = -1.0;
        return;
    }
    double f = (p->log_r0 - lr) / span;
    p->fraction = f < 0 ? 0 : f > 1 ? 1 : f;
    double dt = wall_s - p->wall0, done = p->log_r0 - lr;
    p->eta_s = (dt > 0 && done > 0) ? (lr - lt > 0 ? (lr - lt) * dt / done : 0.0) : -1.0;
}
