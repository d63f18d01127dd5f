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
 * stays below 1 until the run has actually ended (the caller says so).
 *
 * What is shown is steadied (issue 29 item 6): the fraction never goes
 * below the last one shown (a slowing decay re-estimates the end later,
 * and the bar went 64 % -> 33 %); the ETA follows the predicted end time
 * smoothed over SMOOTH_S of wall time, so one odd window does not make it
 * jump; and a run is called long only once that ETA has stayed over a
 * minute for STABLE_S (a plateau of the residual promised minutes to 8 s
 * runs). */
#ifndef ACBB_UI_PROGRESS_H
#define ACBB_UI_PROGRESS_H

#define ACBB_PROGRESS_SAMPLES 256

typedef struct {
    int valid;            /* a first residual has been seen */
    double log_r0;        /* ln of the first residual */
    double wall0;         /* wall time then, s */
    double fraction;      /* 0..0.99 while running */
    double eta_s;         /* seconds left (smoothed); < 0 when unknown */
    double end_s;         /* smoothed predicted end, s of run wall time; < 0 unknown */
    double stable_since;  /* elapsed s since which the ETA shown stayed over a minute */
    double prev_el;       /* elapsed s at the last update */
    int n;                /* samples kept (oldest dropped by halving) */
    double t[ACBB_PROGRESS_SAMPLES], lr[ACBB_PROGRESS_SAMPLES];
} acbb_progress;

void acbb_progress_reset(acbb_progress *p);
/* Feed the latest residual (K/s, > 0), run wall time (s) and tolerance. */
void acbb_progress_update(acbb_progress *p, double residual, double wall_s, double tol);
/* 1 when the run will take long (ETA over a minute) and the estimate has
 * been steady long enough to say so. */
int acbb_progress_long(const acbb_progress *p);

#endif
