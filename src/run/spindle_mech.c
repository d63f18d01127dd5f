/* acbb — a spindle's mechanics (docs/spindle.md "Mechanics"; spindle_priv.h
 * for the frames): the shaft (shaft_beam.h) on its two bearing sets, each
 * a nonlinear support whose reaction is its members' ball solutions at the
 * shaft's displacement of the station (set_mech.h with the shaft position
 * held), solved together by the beam's Newton; then each set's loads are
 * its station's reaction, under which its own evaluation runs.
 *
 * The support's tangent K = -df/dd is a central difference of the
 * reaction with steps h_d (1 nm) and h_theta (1 nm over the pitch
 * radius): the members solve to fidelity.mech_tol (relative, 1e-8 by
 * default), so a step 1e-4 of a micron-scale contact deflection keeps the
 * noise at about 1e-4 of the tangent. For the same reason the shaft's
 * Newton stops at a step 100 mech_tol of its displacements, not at the
 * beam's default 1e-11, or at an absolute step of 100 mech_tol x 1 um
 * (1e-12 m: that tolerance at the set solve's unit of displacement,
 * set_mech.c's um) where the displacements themselves are noise (a
 * symmetric spindle under no load: the solution is 0, the supports'
 * noise about 1e-18 m). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "spindle_priv.h"
#include "sim_struct.h"

#define H_D 1e-9               /* m, the supports' difference step (radial, axial) */
#define FLOOR_SCALE 1e-6       /* m: the set solve's unit of displacement (set_mech.c) */

/* The members' states into the set's scratch (0) or back (1). */
static void keep(acbb_spindle_station *t, int back)
{
    acbb_set_sim *ss = t->ss;
    for (int k = 0; k < ss->n; k++)
        if (back) acbb_mech_state_copy(&ss->b[k]->ms, ss->scratch[k]);
        else acbb_mech_state_copy(ss->scratch[k], &ss->b[k]->ms);
}

/* One trial of the set's solve at thrust Fa from its q and members; on
 * failure both are put back. */
static acbb_status trial(acbb_spindle_station *t, acbb_set_member *mb, double Fa)
{
    acbb_set_mech *w = &t->w;
    double q[ACBB_SET_Q];
    memcpy(q, w->q, sizeof q);
    keep(t, 0);
    w->Fa = Fa;
    acbb_status rc = acbb_set_mech_solve(w, mb, t->ss->s.inner_speed, NULL);
    if (rc != ACBB_OK) {
        memcpy(w->q, q, sizeof q);
        keep(t, 1);
    }
    return rc;
}

/* The set's solve at the station. An axially free set (a sleeve that
 * slides, a spring) is solved for its axial position under its thrust,
 * warm-started where it last was: when it starts to slide, where it stuck
 * carrying more. The full Newton step from there towards a much lighter
 * thrust overshoots (a ball's contact force grows as its deflection to
 * the 1.5, so the linearisation at the heavier load reaches past the
 * lighter one's deflection) to where every ball unloads, and that solve
 * fails. Then the thrust is walked from the one the set carries at the
 * start to the given one, the walk's step halved on a failure and doubled
 * on a success (the solution moves continuously with the thrust). */
static acbb_status free_solve(acbb_spindle_station *t, acbb_set_member *mb)
{
    acbb_set_mech *w = &t->w;
    double target = w->Fa;
    acbb_status rc = trial(t, mb, target);
    if (rc == ACBB_OK || t->axial_held) return rc;
    w->hold[0] = 1; /* the thrust it carries where it starts */
    rc = trial(t, mb, 0.0);
    w->hold[0] = 0;
    double L[3];
    acbb_set_mech_loads(w, L);
    double F0 = L[0], a = 0.0, step = 0.5;
    while (rc == ACBB_OK && a < 1.0) {
        double b = fmin(1.0, a + step);
        if (trial(t, mb, F0 + (target - F0) * b) == ACBB_OK) {
            a = b;
            step = fmin(2.0 * step, 1.0);
        } else if ((step *= 0.5) < 1.0 / 1024.0)
            rc = ACBB_DIVERGED;
    }
    w->Fa = target;
    return rc;
}

/* The station's reaction f on the shaft at its displacement d: the set's
 * shaft held at (u + shift - slip, w, -theta) (u free when the set is not
 * axially located: it carries Fa_given), its members solved there. */
static acbb_status reaction(acbb_spindle_station *t, const double d[3], double f[3])
{
    acbb_set_mech *w = &t->w;
    double offset = t->k == ACBB_REAR ? t->sp->shift - t->slip : 0.0;
    memcpy(t->d, d, sizeof t->d);
    if (t->axial_held) w->q[0] = d[0] + offset;
    w->q[1] = d[1];
    w->q[2] = -d[2];
    w->Fa = t->axial_held ? 0.0 : t->Fa_given;
    acbb_set_member mb[ACBB_MAX_SET];
    acbb_set_members(t->ss, mb);
    acbb_status rc = free_solve(t, mb);
    if (rc != ACBB_OK) return rc;
    double L[3];
    acbb_set_mech_loads(w, L);
    f[0] = t->axial_held ? -L[0] : -t->Fa_given;
    f[1] = -L[1];
    f[2] = L[2];
    return ACBB_OK;
}

/* acbb_shaft_support_fn: the reaction and its tangent by central
 * differences; an axially free station's axial row and column are 0 (its
 * axial load is given). The centre is solved last, so the members are
 * left at the station's displacement (the warm start of the set's own
 * solve that follows). */
static acbb_status support(void *ctx, const double d[3], double f[3], double K[9])
{
    acbb_spindle_station *t = ctx;
    const double h[3] = { t->sp->h_d, t->sp->h_d, t->sp->h_theta };
    memset(K, 0, 9 * sizeof *K);
    for (int j = t->axial_held ? 0 : 1; j < 3; j++) {
        double dp[3] = { d[0], d[1], d[2] }, fp[3], fm[3];
        dp[j] = d[j] + h[j];
        acbb_status rc = reaction(t, dp, fp);
        dp[j] = d[j] - h[j];
        if (rc == ACBB_OK) rc = reaction(t, dp, fm);
        if (rc != ACBB_OK) return rc;
        for (int i = t->axial_held ? 0 : 1; i < 3; i++)
            K[3 * i + j] = -(fp[i] - fm[i]) / (2.0 * h[j]);
    }
    memcpy(t->K, K, sizeof t->K);
    return reaction(t, d, f);
}

static void segment(const acbb_scene *s, int i, acbb_shaft_seg *g)
{
    const acbb_material *m = &s->shaft;
    *g = (acbb_shaft_seg){ s->shaft_seg[i].length, s->shaft_seg[i].od, s->shaft_seg[i].bore,
                           m->E, m->nu, m->rho, m->k, m->cp, m->chi };
}

acbb_status acbb_spindle_beam_build(acbb_spindle_sim *sp, acbb_error *err)
{
    const acbb_scene *s = &sp->s;
    acbb_shaft_seg seg[ACBB_SPINDLE_MAX_SEG];
    int n_seg = s->shaft_segments;
    if (n_seg < 1 || n_seg > ACBB_SPINDLE_MAX_SEG)
        return acbb_error_set(err, ACBB_EINVAL, "shaft.segments = %d: 1..%d for a spindle",
                              n_seg, ACBB_SPINDLE_MAX_SEG);
    for (int i = 0; i < n_seg; i++) segment(s, i, &seg[i]);
    acbb_shaft_support sup[2];
    double x[2] = { s->spindle_front_x, s->spindle_rear_x };
    int n_sup = sp->one_support ? 1 : 2;
    for (int k = 0; k < n_sup; k++)
        sup[k] = (acbb_shaft_support){ .x = x[k], .fn = support, .ctx = &sp->st[k] };
    const double nose = 0.0;
    acbb_status rc = acbb_shaft_beam_build(seg, n_seg, sup, n_sup,
                                           s->shaft_n_div > 0 ? s->shaft_n_div : 4, &nose, 1,
                                           &sp->beam, err);
    if (rc != ACBB_OK) return rc;
    free(sp->beam_start); /* a rebuilt shaft (tests) */
    sp->beam_start = malloc(3 * (size_t)acbb_shaft_beam_nodes(sp->beam) * sizeof(double));
    if (!sp->beam_start) return acbb_error_set(err, ACBB_ENOMEM, "spindle: out of memory");
    acbb_shaft_beam_set_tol(sp->beam, 100.0 * s->mech_tol);
    acbb_shaft_beam_set_floor(sp->beam, 100.0 * s->mech_tol * FLOOR_SCALE);
    double dm = acbb_mech_geometry(sp->st[ACBB_FRONT].ss->b[0]->mech)->dm;
    sp->h_d = H_D;
    sp->h_theta = H_D / (0.5 * dm);
    return ACBB_OK;
}

/* How each station holds the shaft axially (acbb_rear_support): the
 * front set is located; the rear one too when fixed, and when floating
 * while its sleeve sticks (where it has slid to: slip); on a spring it
 * carries the spring's force (pushing its outer rings towards the nose:
 * its thrust along +x, as a single bearing's "+" side carries it). */
static void axial_mode(acbb_spindle_sim *sp, acbb_spindle_station *t)
{
    const acbb_scene *s = &sp->s;
    int spring = t->k == ACBB_REAR && s->spindle_rear_support == ACBB_REAR_SPRING;
    t->axial_held = !spring;
    t->Fa_given = spring ? s->spindle_rear_spring : 0.0;
}

/* A floating rear set's sleeve (Coulomb friction rear_friction_N): it
 * sticks while the thrust the held set needs stays within the friction,
 * else it slides and the set carries the friction force in the thrust's
 * direction. 1: it slides (the caller solves the shaft again). */
static int slides(acbb_spindle_sim *sp, acbb_spindle_station *t)
{
    const acbb_scene *s = &sp->s;
    if (t->k != ACBB_REAR || sp->one_support || s->spindle_rear_support != ACBB_REAR_FLOATING)
        return 0;
    double need = -sp->res.reaction[ACBB_REAR][0]; /* the thrust the stuck set carries */
    if (fabs(need) <= s->spindle_rear_friction) return 0;
    t->axial_held = 0;
    t->slide = need > 0.0 ? 1 : -1;
    t->Fa_given = t->slide * s->spindle_rear_friction;
    return 1;
}

/* Where the sliding set came to rest in its sleeve: its outer rings moved
 * by the shaft's u plus the shift less its inner rings' move against
 * them. */
static void slid(acbb_spindle_sim *sp, acbb_spindle_station *t)
{
    t->slip = t->d[0] + sp->shift - t->w.q[0];
}

/* The support's copy of the set's mechanics (its offsets and spacer
 * moves), its axial position warm-started from the station's last (a
 * sliding or spring-held set's: a set's own last solve may have been
 * under other loads, a one-way set's far out where no ball is loaded). */
static void hold(acbb_spindle_station *t)
{
    double q0 = t->w.q[0];
    int warm = t->w.n > 0;
    t->w = t->ss->sm;
    if (warm) t->w.q[0] = q0;
    t->w.hold[0] = t->axial_held;
    t->w.hold[1] = t->w.hold[2] = 1;
    t->w.hold[3] = 0;
    t->w.solves = 0;
}

/* The reactions into each set's loads (its frame, at its centre). */
static void set_loads(acbb_spindle_sim *sp)
{
    for (int k = 0; k < 2; k++) {
        acbb_spindle_station *t = &sp->st[k];
        double L[3] = { 0.0, 0.0, 0.0 };
        if (k == ACBB_FRONT || !sp->one_support) {
            const double *R = sp->res.reaction[k];
            L[0] = t->axial_held ? -R[0] : t->Fa_given;
            L[1] = -R[1];
            L[2] = R[2];
        }
        memcpy(t->load, L, sizeof L);
        /* A located set's own solve keeps the station's axial position (a
         * one-way set's position under no thrust is no equilibrium of its
         * own; spindle.c frees it again after the set's evaluation). */
        t->ss->sm.hold[0] = t->axial_held && (k == ACBB_FRONT || !sp->one_support);
        if (k == ACBB_FRONT || !sp->one_support) /* its solve starts at the station */
            memcpy(t->ss->sm.q, t->w.q, sizeof t->w.q);
        t->ss->sm.Fa = L[0];
        t->ss->sm.Fr = L[1];
        t->ss->sm.M = L[2];
        t->ss->sm.x_nose = 0.0;
    }
}

/* Which set lost every ball of a bearing, for the message; -1 none. */
static int lost_set(const acbb_spindle_sim *sp, int *bearing)
{
    for (int k = 0; k < 2; k++)
        for (int b = 0; b < sp->st[k].w.n; b++)
            if (sp->st[k].w.lost[b]) {
                *bearing = b;
                return k;
            }
    return -1;
}

/* The shaft with the stations as they hold it now. */
static acbb_status solve_shaft(acbb_spindle_sim *sp, acbb_error *err)
{
    const acbb_scene *s = &sp->s;
    const acbb_shaft_load nose = { 0.0, s->axial_load, s->radial_load, -s->moment_load };
    for (int k = 0; k < 2; k++) hold(&sp->st[k]);
    sp->beam_solves++;
    acbb_status rc = acbb_shaft_beam_solve(sp->beam, &nose, 1, &sp->res, err);
    sp->probe_solves += sp->st[ACBB_FRONT].w.solves + sp->st[ACBB_REAR].w.solves;
    return rc;
}

/* A sleeve that slid in the state kept mostly goes on sliding the same
 * way (the shaft's growth goes on pushing it): solved sliding first, one
 * shaft solve instead of two (the stuck one, then the slide; the belt
 * spindle's warm-up slides nearly throughout: 2.0 shaft solves an
 * evaluation, BENCHMARKS.md "Spindle"). The slide stands when the sleeve
 * moved on the way its thrust pushes it: the thrust (along +x) a held set
 * carries falls as its outer rings slide along +x (the set's axial
 * stiffness is positive), so a slide at +friction to past where it rested
 * means the set held there would have needed more than the friction, the
 * test `slides` makes (likewise at -friction). Else, or when that solve fails, the
 * evaluation decides from the stuck set. 1: it slides, solved. */
static int slide_on(acbb_spindle_sim *sp, acbb_spindle_station *t, acbb_error *err)
{
    if (!t->slide_rest || sp->one_support) return 0;
    t->axial_held = 0;
    t->Fa_given = t->slide_rest * sp->s.spindle_rear_friction;
    if (solve_shaft(sp, err) == ACBB_OK) {
        slid(sp, t);
        if (t->slide_rest * (t->slip - t->slip_rest) > 0.0) {
            t->slide = t->slide_rest;
            return 1;
        }
    }
    t->slip = t->slip_rest;
    axial_mode(sp, t);
    return 0;
}

/* The shaft with the stations as they hold it, a floating rear's sleeve
 * decided from where it rests. */
static acbb_status shaft(acbb_spindle_sim *sp, acbb_error *err)
{
    acbb_spindle_station *rear = &sp->st[ACBB_REAR];
    /* Every evaluation of a step (or of a steady or isothermal solve's
     * iterations) starts from where the sleeve was at the last state kept
     * or restored (spindle.c plant_save, plant_restore): an evaluation's
     * ball speeds are those of the pass before, so a slide decided on them
     * is a trial, not history. */
    rear->slip = rear->slip_rest;
    rear->slide = 0;
    for (int k = 0; k < 2; k++) axial_mode(sp, &sp->st[k]);
    acbb_error e2 = { "" };
    if (slide_on(sp, rear, &e2)) return ACBB_OK;
    acbb_status rc = solve_shaft(sp, &e2);
    if (rc == ACBB_OK && slides(sp, rear)) {
        rc = solve_shaft(sp, &e2);
        if (rc == ACBB_OK) slid(sp, rear);
    }
    if (rc != ACBB_OK) {
        int b, k = lost_set(sp, &b);
        if (k >= 0)
            return acbb_error_set(err, ACBB_CONTACT_LOST, "spindle: the %s set's bearing %d "
                                  "lost contact (every ball unloaded; %s)",
                                  k == ACBB_FRONT ? "front" : "rear", b, e2.msg);
        return acbb_error_set(err, rc, "spindle: %s", e2.msg);
    }
    return ACBB_OK;
}

acbb_status acbb_spindle_mechanics(acbb_spindle_sim *sp, acbb_error *err)
{
    acbb_status rc = shaft(sp, err);
    if (rc == ACBB_OK) set_loads(sp);
    return rc;
}

/* The sets' members' states into the probe's keep (0) or back (1). */
static void keep_members(acbb_spindle_sim *sp, int back)
{
    for (int k = 0; k < 2; k++)
        for (int b = 0; b < sp->st[k].ss->n; b++) {
            acbb_mech_state *ms = &sp->st[k].ss->b[b]->ms, *kept = &sp->probe_ms[k][b];
            if (back) acbb_mech_state_copy(ms, kept);
            else acbb_mech_state_copy(kept, ms);
        }
}

/* The shaft solved again without the nose thrust (the same temperatures,
 * ball speeds, radial load and moment; a floating rear's sleeve from where
 * it rests): each set's axial load in its frame into Fa; the stations,
 * members, shaft result and the shaft's warm start put back. */
acbb_status acbb_spindle_zero_thrust(acbb_spindle_sim *sp, double Fa[2])
{
    acbb_spindle_station st[2];
    memcpy(st, sp->st, sizeof st);
    acbb_shaft_result res = sp->res;
    acbb_shaft_beam_start(sp->beam, sp->beam_start, 0);
    keep_members(sp, 0);
    double thrust = sp->s.axial_load;
    sp->s.axial_load = 0.0;
    acbb_status rc = shaft(sp, NULL);
    for (int k = 0; k < 2 && rc == ACBB_OK; k++) {
        const acbb_spindle_station *t = &sp->st[k];
        Fa[k] = t->axial_held ? -sp->res.reaction[k][0] : t->Fa_given;
    }
    sp->s.axial_load = thrust;
    keep_members(sp, 1);
    acbb_shaft_beam_start(sp->beam, sp->beam_start, 1);
    sp->res = res;
    memcpy(sp->st, st, sizeof st);
    return rc;
}

/* Rigid shaft on two point supports (one: the front set takes all): the
 * loads on each set, its frame, from the nose loads; the first state's
 * warm start only. */
void acbb_spindle_initial_loads(const acbb_scene *s, int one_support, double L[2][3])
{
    double a = s->spindle_front_x, l = s->spindle_rear_x - s->spindle_front_x;
    double S = s->spindle_rear_support == ACBB_REAR_SPRING ? s->spindle_rear_spring : 0.0;
    memset(L, 0, 2 * sizeof L[0]);
    if (one_support || !(l > 0.0)) {
        L[0][0] = s->axial_load;
        L[0][1] = s->radial_load;
        L[0][2] = s->moment_load + a * s->radial_load;
        return;
    }
    L[0][0] = s->axial_load - S;
    L[1][0] = S;
    L[0][1] = s->radial_load * (a + l) / l;
    L[1][1] = -s->radial_load * a / l;
}
