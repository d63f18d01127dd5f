/* acbb TUI — the Spindle screen's own history of the nose drift over time,
 * taken from the snapshots it sees (the worker's history has no spindle
 * fields). Capped: when full, every other point is dropped, so the whole
 * run stays on the chart at half the density. No curses here. */
#ifndef ACBB_UI_DRIFT_HIST_H
#define ACBB_UI_DRIFT_HIST_H

#include <stddef.h>

#define ACBB_DRIFT_CAP 512

typedef struct {
    double t[ACBB_DRIFT_CAP];      /* simulated time, s */
    double d[ACBB_DRIFT_CAP];      /* nose drift, um */
    size_t n;
} acbb_drift_hist;

void acbb_drift_clear(acbb_drift_hist *h);
/* The drift d (um) at time t (s): a later time is appended; the same time
 * replaces the last point (a snapshot seen again, or a steady solve at the
 * transient's end time); an earlier time starts the history again (a new
 * run). A non-finite t or d is left out. */
void acbb_drift_add(acbb_drift_hist *h, double t, double d);

#endif
