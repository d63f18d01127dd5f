/* acbb_mech_solve works in place on the caller's state (issue 30 lever
 * 4: no copy of every ball record in and out) and keeps its contract: a
 * solve that fails leaves the state as it was, bit for bit, every ball
 * (the images of the solved ones included); one that succeeds leaves
 * every image a copy of its solved ball. On the 7008C (21 balls, pure
 * thrust: one ball solved) and under a radial load (mirror: 11). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "mechanics.h"
#include "acbb/scene.h"

static int same_state(const acbb_mech_state *a, const acbb_mech_state *b)
{
    return memcmp(a, b, offsetof(acbb_mech_state, ball)) == 0
           && memcmp(a->ball, b->ball, sizeof a->ball[0] * (size_t)a->n) == 0;
}

static void check(double radial)
{
    acbb_scene s;
    acbb_error err = { "" };
    ok(acbb_scene_load("presets/7008C.ini", &s, &err) == ACBB_OK, "preset: %s", err.msg);
    s.radial_load = radial;
    acbb_mech *m = NULL;
    acbb_mech_state *st = malloc(sizeof *st), *was = malloc(sizeof *was);
    acbb_status rc = acbb_mech_new(&s, &m, &err);
    if (rc == ACBB_OK) rc = acbb_mech_init_state(m, st, &err);
    if (rc == ACBB_OK) rc = acbb_mech_solve(m, s.inner_speed, NULL, st, &err);
    ok(rc == ACBB_OK, "%g N radial: solved (%s)", radial, err.msg);
    int images = 1;
    for (int j = acbb_mech_distinct(st); j < st->n && rc == ACBB_OK; j++) {
        const acbb_ball_state *b = &st->ball[j], *src = &st->ball[acbb_mech_source(st, j)];
        images = images && b->Qi == src->Qi && b->alpha_o == src->alpha_o
                 && b->ct_i.a == src->ct_i.a && b->kin.omega_m == src->kin.omega_m;
    }
    ok(images, "%g N radial: %d balls solved, every other one a copy of its solved ball", radial,
       acbb_mech_distinct(st));
    memcpy(was, st, sizeof *st);
    /* a non-finite expansion: the solve fails (non-finite or diverged)
     * after moving the state */
    acbb_expansion e = { 0.0, 0.0, 0.0, NAN };
    rc = acbb_mech_solve(m, s.inner_speed, &e, st, &err);
    ok(rc != ACBB_OK && same_state(st, was),
       "%g N radial: a failed solve (%s) leaves the state as it was, bit for bit", radial,
       acbb_status_name(rc));
    acbb_mech_free(m);
    free(st);
    free(was);
}

int main(void)
{
    gsl_set_error_handler_off(); /* as the first Sim does: the engine checks GSL's statuses */
    check(0.0);
    check(500.0);
    return done_testing();
}
