/* acbb — the dynamic level's windows of every distinct ball, on worker
 * threads (dynamic.h, acbb_dyn_balls). Why threads: a combined load has up
 * to n/2 + 1 distinct balls whose windows are independent (each ball is
 * integrated alone with the others' loads fixed, MODEL.md section 4), and a
 * window is seconds of work at worst. Each worker owns its traction tables;
 * a ball's result does not depend on which worker ran it, so the answer is
 * the same bit for bit for any thread count (tests/test_dynamic.c). */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include "dynamic_priv.h"

typedef struct {
    acbb_dyn *d;
    const acbb_dyn_env *env;
    acbb_mech_state *st;
    double cold, warm;
    int nb;
    atomic_int *next;        /* next ball to take (shared) */
    int w;                   /* this worker */
    double change;           /* largest over its balls */
    int fail_j;              /* first failing ball, -1: none */
    acbb_status rc;
    acbb_error err;
} worker;

/* Balls are handed out in increasing order, and a worker stops at its
 * first failure: every ball below a failing one was taken, so the lowest
 * failing ball over all workers is the one a serial loop would report. */
static void *work(void *p)
{
    worker *k = p;
    for (;;) {
        int j = atomic_fetch_add(k->next, 1);
        if (j >= k->nb) break;
        double window = k->st->ball[j].traction_valid ? k->warm : k->cold, c;
        acbb_status rc = acbb_dyn_ball_on(k->d, k->w, k->env, k->st, j, window, &c, &k->err);
        if (rc != ACBB_OK) {
            k->rc = rc;
            k->fail_j = j;
            break;
        }
        k->change = fmax(k->change, c);
    }
    return NULL;
}

acbb_status acbb_dyn_balls(acbb_dyn *d, const acbb_dyn_env *env, acbb_mech_state *st,
                           double cold, double warm, double *change, acbb_error *err)
{
    int nb = acbb_mech_distinct(st), T = acbb_dyn_threads(d);
    if (T > nb) T = nb > 0 ? nb : 1;
    atomic_int next = 0;
    worker k[ACBB_DYN_MAX_THREADS];
    pthread_t tid[ACBB_DYN_MAX_THREADS];
    int started[ACBB_DYN_MAX_THREADS] = { 0 };
    for (int w = 0; w < T; w++)
        k[w] = (worker){ .d = d, .env = env, .st = st, .cold = cold, .warm = warm, .nb = nb,
                         .next = &next, .w = w, .fail_j = -1, .rc = ACBB_OK };
    /* Worker 0 is this thread; a worker that cannot start leaves its share
     * to the others (the counter hands every ball to someone). */
    for (int w = 1; w < T; w++) started[w] = pthread_create(&tid[w], NULL, work, &k[w]) == 0;
    work(&k[0]);
    for (int w = 1; w < T; w++)
        if (started[w]) pthread_join(tid[w], NULL);
    int f = -1;
    *change = 0.0;
    for (int w = 0; w < T; w++) {
        *change = fmax(*change, k[w].change);
        if (k[w].fail_j >= 0 && (f < 0 || k[w].fail_j < k[f].fail_j)) f = w;
    }
    if (f < 0) return ACBB_OK;
    *err = k[f].err;
    return k[f].rc;
}
