/* acbb TUI — the nose drift over time (drift_hist.h). */
#include <math.h>
#include "drift_hist.h"

void acbb_drift_clear(acbb_drift_hist *h)
{
    h->n = 0;
}

/* Keep points 0, 2, 4, ... and the last one (the newest stays shown). */
static void halve(acbb_drift_hist *h)
{
    size_t k = 0;
    for (size_t i = 0; i < h->n; i += 2, k++) {
        h->t[k] = h->t[i];
        h->d[k] = h->d[i];
    }
    if (h->n % 2 == 0) { /* the last was dropped: put it back in place of its neighbour */
        h->t[k - 1] = h->t[h->n - 1];
        h->d[k - 1] = h->d[h->n - 1];
    }
    h->n = k;
}

void acbb_drift_add(acbb_drift_hist *h, double t, double d)
{
    if (!isfinite(t) || !isfinite(d)) return;
    if (h->n > 0 && t < h->t[h->n - 1]) h->n = 0;
    if (h->n > 0 && t == h->t[h->n - 1]) {
        h->d[h->n - 1] = d;
        return;
    }
    if (h->n == ACBB_DRIFT_CAP) halve(h);
    h->t[h->n] = t;
    h->d[h->n] = d;
    h->n++;
}
