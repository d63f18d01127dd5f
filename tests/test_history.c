/* Tests of the bounded run history (history.h). */
#include <string.h>
#include "tap.h"
#include "acbb/tools/history.h"

static acbb_snapshot snap;

int main(void)
{
    static acbb_history h;
    acbb_history_init(&h);
    memset(&snap, 0, sizeof snap);
    snap.n_balls = 1;
    long N = 3 * ACBB_HISTORY_CAP + 17;
    int monotone = 1, within = 1;
    for (long k = 0; k < N; k++) {
        snap.iteration = k;
        snap.time = 5.0 * k;
        snap.T_outer_ring = 26.0 + k;
        snap.balls[0].Qi = 100.0 + k;
        acbb_history_push(&h, &snap);
        within &= h.n <= ACBB_HISTORY_CAP;
        if (h.n >= 2) monotone &= h.p[h.n - 1].iteration > h.p[h.n - 2].iteration;
    }
    ok(within, "never more than the capacity");
    ok(monotone, "iterations strictly increase");
    ok(h.p[0].iteration == 0, "the first step is kept (whole run visible)");
    ok(h.p[h.n - 1].iteration == N - 1, "the last step is kept");
    ok(h.n > ACBB_HISTORY_CAP / 2, "at least half the capacity is used (%zu)", h.n);
    int on_stride = 1;
    for (size_t i = 0; i + 1 < h.n; i++) on_stride &= h.p[i].iteration % h.stride == 0;
    ok(on_stride, "stored points fall on the stride (%ld)", h.stride);
    is_close(h.p[h.n - 1].T_outer_ring, 26.0 + N - 1, 0, 0, "values travel with the point");
    is_close(h.p[h.n - 1].Qi, 100.0 + N - 1, 0, 0, "ball 0 load recorded");
    return done_testing();
}
