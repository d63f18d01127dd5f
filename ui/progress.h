/* acbb TUI — progress and ETA towards thermal steady state (pure).
 *
 * The run ends when the residual max|dT/dt| falls below steady_tol; in a
 * linear-ish thermal transient it decays roughly exponentially, so
 * progress is measured on a log scale from the run's first residual:
 *   fraction = ln(r0 / r) / ln(r0 / tol),
 * and the ETA extrapolates the run's mean log-decay rate per wall second. */
#ifndef ACBB_UI_PROGRESS_H
#define ACBB_UI_PROGRESS_H

typedef struct {
    int valid;            /* a first residual has been seen */
    double log_r0;        /* ln of the first residual */
    double wall0;         /* wall time then, s */
    double fraction;      /* 0..1 */
    double eta_s;         /* seconds left; < 0 when unknown */
} acbb_progress;

void acbb_progress_reset(acbb_progress *p);
/* Feed the latest residual (K/s, > 0), run wall time (s) and tolerance. */
void acbb_progress_update(acbb_progress *p, double residual, double wall_s, double tol);

#endif
