/* acbb TUI — progress estimate (see progress.h). */
#include <math.h>
#include "progress.h"

#define WINDOW_MIN_S 0.5  /* shortest window for the recent decay rate */
#define WINDOW_FRAC 0.33  /* window = this share of the elapsed wall time */
#define SETTLE_S (2 * WINDOW_MIN_S) /* wall time before any ETA */
#define FRACTION_CAP 0.99 /* "100%" belongs to a run that has ended */
#define SMOOTH_S 0.5      /* time constant of the predicted end's smoothing */
#define STABLE_S 3.0      /* the smoothed ETA stayed over LONG_S this long before "LONG" */
#define LONG_S 60.0       /* a run with more than a minute left is long */

void acbb_progress_reset(acbb_progress *p)
{
    p->valid = 0;
    p->log_r0 = 0.0;
    p->wall0 = 0.0;
    p->fraction = 0.0;
    p->eta_s = -1.0;
    p->end_s = -1.0;
    p->stable_since = 0.0;
    p->prev_el = 0.0;
    p->n = 0;
}

/* Keep (t, ln r); when full, drop every other old sample (the window only
 * needs coarse history). */
static void keep(acbb_progress *p, double t, double lr)
{
    if (p->n > 0 && t <= p->t[p->n - 1]) { /* same frame: replace */
        p->lr[p->n - 1] = lr;
        return;
    }
    if (p->n == ACBB_PROGRESS_SAMPLES) {
        for (int i = 0; i < ACBB_PROGRESS_SAMPLES / 2; i++) {
            p->t[i] = p->t[2 * i];
            p->lr[i] = p->lr[2 * i];
        }
        p->n = ACBB_PROGRESS_SAMPLES / 2;
    }
    p->t[p->n] = t;
    p->lr[p->n] = lr;
    p->n++;
}

/* Decay rate of ln r per wall second over the recent window (> 0 when the
 * residual falls), 0 if unknown. */
static double recent_rate(const acbb_progress *p)
{
    if (p->n < 2) return 0.0;
    double now = p->t[p->n - 1], el = now - p->wall0;
    double win = fmax(WINDOW_MIN_S, WINDOW_FRAC * el);
    int i = p->n - 2;
    while (i > 0 && now - p->t[i] < win) i--;
    double dt = now - p->t[i];
    return dt > 0 ? (p->lr[i] - p->lr[p->n - 1]) / dt : 0.0;
}

/* The raw estimate eta (s left, < 0 unknown) at elapsed el into the shown
 * one: the predicted end el + eta smoothed exponentially in wall time. */
static void steady_eta(acbb_progress *p, double eta, double el)
{
    double dt = fmax(el - p->prev_el, 0.0);
    p->prev_el = el;
    if (eta < 0) {
        p->eta_s = p->end_s >= 0 ? fmax(0.0, p->end_s - el) : -1.0;
        p->stable_since = el;
        return;
    }
    double end = el + eta;
    if (p->end_s < 0) {
        p->end_s = end;
    } else {
        p->end_s += (end - p->end_s) * (1.0 - exp(-dt / SMOOTH_S));
    }
    p->eta_s = fmax(0.0, p->end_s - el);
    if (p->eta_s <= LONG_S) p->stable_since = el; /* long since then, if it stays so */
}

void acbb_progress_update(acbb_progress *p, double residual, double wall_s, double tol)
{
    if (!(residual > 0) || !(tol > 0) || !isfinite(residual) || !isfinite(wall_s)) return;
    double lr = log(residual), lt = log(tol);
    if (!p->valid) {
        p->valid = 1;
        p->log_r0 = lr;
        p->wall0 = wall_s;
    }
    keep(p, wall_s, lr);
    double rate = recent_rate(p), el = wall_s - p->wall0;
    if (lr <= lt) { /* below the tolerance: only the final steady solve is left */
        p->eta_s = 0.0;
        p->fraction = FRACTION_CAP;
        return;
    }
    /* No ETA from the first instants: the fast modes alone decay then
     * (a 5.5 s run promised to end at 1 s). */
    double eta = rate > 0 && el >= SETTLE_S ? (lr - lt) / rate : -1.0;
    steady_eta(p, eta, el);
    double f;
    if (p->eta_s >= 0 && el > 0) f = el / (el + p->eta_s);
    else f = p->log_r0 > lt ? (p->log_r0 - lr) / (p->log_r0 - lt) : 0.0;
    f = f < 0 ? 0 : f > FRACTION_CAP ? FRACTION_CAP : f;
    if (f > p->fraction) p->fraction = f; /* never backwards */
}

int acbb_progress_long(const acbb_progress *p)
{
    if (!p->valid || p->eta_s <= LONG_S || p->n == 0) return 0;
    return p->t[p->n - 1] - p->wall0 - p->stable_since >= STABLE_S;
}
