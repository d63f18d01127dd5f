/* A set's shaft solve replays another's first evaluations (set_mech.h
 * acbb_set_mech_memo; issue 30: the nose-stiffness probes). The 7008C QBC
 * (spring preload, 1000 N thrust, 15000 rpm) solved under its thrust, then
 * probed as sim_set_probe.c does, each probe from that state: a radial
 * load +h records its start and Jacobian, a radial load -h and a moment
 * replay them. Each replaying probe must give the bits of the same probe
 * solved without the memo (shaft position, reactions, every member's
 * state) with one member solve fewer per bearing per replayed
 * evaluation; a probe from another shaft position must not replay. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "set_mech.h"
#include "acbb/tools/scene_schema.h"

typedef struct {
    acbb_set_mech sm;
    int n;
    acbb_mech *m[ACBB_MAX_SET];
    acbb_mech_state *st[ACBB_MAX_SET], *run[ACBB_MAX_SET];
    acbb_set_member mb[ACBB_MAX_SET];
    double omega;
} set;

static double static_dx(double F, void *ctx)
{
    acbb_scene s0 = *(const acbb_scene *)ctx;
    s0.axial_load = F;
    s0.inner_speed = 0.0;
    acbb_mech *m;
    acbb_mech_state *st = malloc(sizeof *st);
    double dx = NAN;
    if (acbb_mech_new(&s0, &m, NULL) == ACBB_OK) {
        if (acbb_mech_init_state(m, st, NULL) == ACBB_OK) dx = st->dx;
        acbb_mech_free(m);
    }
    free(st);
    return dx;
}

/* The set and its run state (shaft equilibrium under the scene's loads). */
static int set_up(set *t)
{
    static acbb_scene s;
    acbb_error err = { "" };
    const char *edits[] = { "set.arrangement=QBC" };
    if (acbb_scene_load("presets/7008C.ini", &s, &err) != ACBB_OK
        || acbb_scene_apply_edits(&s, edits, 1, &err) != ACBB_OK)
        return 0;
    acbb_set_mech_init(&t->sm, &s);
    t->n = t->sm.n;
    t->omega = s.inner_speed;
    acbb_scene m = s; /* a member as sim_set.c makes it: no loads of its own */
    m.set_arrangement = ACBB_SET_SINGLE;
    m.set_n_bearings = 0;
    m.preload = ACBB_PRELOAD_FORCE;
    m.axial_load = s.preload_force / 2.0;
    m.radial_load = m.moment_load = 0.0;
    acbb_set_mech_assemble(&t->sm, static_dx, &m);
    for (int k = 0; k < t->n; k++) {
        t->st[k] = malloc(sizeof *t->st[k]);
        t->run[k] = malloc(sizeof *t->run[k]);
        if (acbb_mech_new(&m, &t->m[k], &err) != ACBB_OK
            || acbb_mech_init_state(t->m[k], t->st[k], &err) != ACBB_OK)
            return 0;
        t->mb[k] = (acbb_set_member){ t->m[k], t->st[k], NULL };
    }
    if (acbb_set_mech_solve(&t->sm, t->mb, t->omega, &err) != ACBB_OK) return 0;
    for (int k = 0; k < t->n; k++) acbb_mech_state_copy(t->run[k], t->st[k]);
    return 1;
}

/* A probe under radial load Fr and moment M from the run state (memo:
 * NULL or the one to record into / replay); its members' states into
 * out[], its member solves into *solves. */
static int probe(set *t, double Fr, double M, double dq0, acbb_set_mech_memo *memo,
                 acbb_set_mech *p, acbb_mech_state **out, long *solves)
{
    *p = t->sm;
    p->q[0] += dq0;
    p->Fr = Fr;
    p->M = M;
    p->memo = memo;
    p->solves = 0;
    for (int k = 0; k < t->n; k++) acbb_mech_state_copy(t->st[k], t->run[k]);
    int ok_ = acbb_set_mech_solve(p, t->mb, t->omega, NULL) == ACBB_OK;
    for (int k = 0; k < t->n; k++) acbb_mech_state_copy(out[k], t->st[k]);
    *solves = p->solves;
    p->memo = NULL;
    return ok_;
}

static int same(const set *t, const acbb_set_mech *a, const acbb_set_mech *b,
                acbb_mech_state *const *sa, acbb_mech_state *const *sb)
{
    int eq = !memcmp(a->q, b->q, sizeof a->q) && !memcmp(a->Fx, b->Fx, sizeof a->Fx)
             && !memcmp(a->Fz, b->Fz, sizeof a->Fz) && !memcmp(a->My, b->My, sizeof a->My);
    for (int k = 0; k < t->n; k++)
        eq = eq && !memcmp(sa[k], sb[k], offsetof(acbb_mech_state, ball))
             && !memcmp(sa[k]->ball, sb[k]->ball, sizeof sa[k]->ball[0] * (size_t)sa[k]->n);
    return eq;
}

int main(void)
{
    gsl_set_error_handler_off(); /* as the first Sim does */
    static set t;
    if (!set_up(&t)) {
        ok(0, "the 7008C QBC's run state");
        return done_testing();
    }
    acbb_mech_state *a[ACBB_MAX_SET], *b[ACBB_MAX_SET];
    acbb_set_mech_memo memo = { 0 };
    for (int k = 0; k < t.n; k++) {
        a[k] = malloc(sizeof *a[k]);
        b[k] = malloc(sizeof *b[k]);
        memo.ms[k] = malloc(sizeof *memo.ms[k]);
    }
    double h = 1.0 + 1e-3 * (t.sm.Fp + t.sm.Fa), R = 0.02;
    acbb_set_mech pa, pb;
    long na, nb;
    int first = probe(&t, h, 0.0, 0.0, &memo, &pa, a, &na);
    ok(first && memo.state == 2 && memo.n_ev == 5,
       "the first probe records its start and a 4-unknown Jacobian (%d evaluations, state %d)",
       memo.n_ev, memo.state);
    const struct { double Fr, M; const char *what; } rep[] = {
        { -h, 0.0, "radial load -h" }, { 0.0, h * R, "moment +h R" }, { 0.0, -h * R, "moment -h R" },
    };
    for (int i = 0; i < 3; i++) {
        int r1 = probe(&t, rep[i].Fr, rep[i].M, 0.0, &memo, &pa, a, &na);
        int r2 = probe(&t, rep[i].Fr, rep[i].M, 0.0, NULL, &pb, b, &nb);
        ok(r1 && r2 && same(&t, &pa, &pb, a, b) && na == nb - 5 * t.n,
           "%s replayed: the bits of its own solve, %ld member solves instead of %ld",
           rep[i].what, na, nb);
    }
    /* from another shaft position: the recorded one is not its path */
    int r1 = probe(&t, -h, 0.0, 1e-9, &memo, &pa, a, &na);
    int r2 = probe(&t, -h, 0.0, 1e-9, NULL, &pb, b, &nb);
    ok(r1 && r2 && same(&t, &pa, &pb, a, b) && na == nb,
       "a probe from another start solves its own (%ld and %ld member solves)", na, nb);
    for (int k = 0; k < t.n; k++) {
        acbb_mech_free(t.m[k]);
        free(t.st[k]);
        free(t.run[k]);
        free(a[k]);
        free(b[k]);
        free(memo.ms[k]);
    }
    return done_testing();
}
