/* acbb TUI — progress and ETA towards thermal steady state (pure).
 *
 * The run ends when the residual max|dT/dt| falls below steady_tol. Late
 * in a thermal transient only the slowest mode is left and ln(residual)
 * falls linearly in time (MODEL.md 9: implicit network, one dominant time
 * constant), but early on faster modes make it fall much faster. So the
 * ETA extrapolates the RECENT log-decay rate (a window of the last third
 * of the run, at least WINDOW_MIN_S), not the mean since the start, which
 * promised a 13 s run would end at 6 s. The fraction shown is elapsed /
 * (elapsed + eta), so the bar and the ETA tell the same story, and it
 * stays below 1 until the run has actually ended (the caller says so). */
#ifndef ACBB_UI_PROGRESS_H
#define ACBB_UI_PROGRESS_H

#define ACBB_PROGRESS_SAMPLES 256

typedef struct {
    int valid;            /* a first residual has been seen */
    double log_r0;        /* ln of the first residual */
    double wall0;         /* wall time then, s */
    double fraction;      /* 0..0.99 while running */
    double eta_s;         /* seconds left; < 0 when unknown */
    int n;                /* samples kept (oldest dropped by halving) */
    double t[ACBB_PROGRESS_SAMPLES], lr[ACBB_PROGRESS_SAMPLES];
} acbb_progress;

void acbb_progress_reset(acbb_progress *p);
/* Feed the latest residual (K/s, > 0), run wall time (s) and tolerance. */
void acbb_progress_update(acbb_progress *p, double residual, double wall_s, double tol);

#endif
