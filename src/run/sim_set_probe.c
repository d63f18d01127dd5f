/* acbb — probes of a bearing set's converged state (MODEL.md 14): the
 * shaft solved again under other external loads at the same temperatures,
 * speed and ball speeds, for the preload with no thrust, the lift-off
 * thrust and the stiffness at the nose. */
#include <math.h>
#include <string.h>
#include "sim_set_priv.h"
#include "sim_struct.h"

typedef struct { double Fa, Fr, M; } loads;

/* Solve the shaft under other external loads in *w (its q the warm
 * start), leaving the members there. */
static acbb_status solve_loads(acbb_set_sim *ss, loads L, acbb_set_mech *w)
{
    w->Fa = L.Fa;
    w->Fr = L.Fr;
    w->M = L.M;
    acbb_set_member mb[ACBB_MAX_SET];
    acbb_set_members(ss, mb);
    return acbb_set_mech_solve(w, mb, ss->s.inner_speed, NULL);
}

static void keep_members(acbb_set_sim *ss, int back)
{
    for (int k = 0; k < ss->n; k++)
        if (back) acbb_mech_state_copy(&ss->b[k]->ms, ss->scratch[k]);
        else acbb_mech_state_copy(ss->scratch[k], &ss->b[k]->ms);
}

/* Solve the shaft under other external loads into *out; the members and
 * the set's own solution are put back afterwards. memo (NULL: none): the
 * first evaluations of probes that start, as every probe does, from the
 * run's shaft position and members (set_mech.h acbb_set_mech_memo). */
static acbb_status probe(acbb_set_sim *ss, loads L, acbb_set_mech *out,
                         acbb_set_mech_memo *memo)
{
    keep_members(ss, 0);
    *out = ss->sm;
    out->memo = memo;
    acbb_status rc = solve_loads(ss, L, out);
    out->memo = NULL;
    keep_members(ss, 1);
    return rc;
}

static int side_of_floating(const acbb_set_sim *ss)
{
    return ss->sm.spring ? -1 : 0;
}

static int has_side(const acbb_set_mech *sm, int s)
{
    for (int k = 0; k < sm->n; k++) if (sm->orient[k] == s) return 1;
    return 0;
}

/* The axial force through the set with no external thrust (MODEL.md 14:
 * assembly preload plus the thermally induced part). */
double acbb_set_preload_now(acbb_set_sim *ss)
{
    double F = 0.0;
    if (!has_side(&ss->sm, 1) || !has_side(&ss->sm, -1)) /* tandem: only a spring preloads */
        return ss->sm.spring ? ss->sm.Fp : 0.0;
    if (side_of_floating(ss)) {
        for (int k = 0; k < ss->n; k++) if (ss->sm.orient[k] < 0) F += ss->sm.Fx[k];
        return F;
    }
    if (ss->sm.Fa == 0.0) return acbb_set_mech_preload(&ss->sm);
    acbb_set_mech p;
    if (probe(ss, (loads){ 0.0, ss->sm.Fr, ss->sm.M }, &p, NULL) != ACBB_OK) return 0.0;
    return acbb_set_mech_preload(&p);
}

/* How far the rings of `side` still squeeze their balls under thrust Fa,
 * um: the largest excess, over the side's balls, of the distance between a
 * ball's groove centres over the sum of its unloaded groove-to-ball-centre
 * lengths (MODEL.md 3, thermal terms included). Solved in *w from its
 * last solution (the search walks the thrust: each solve starts from the
 * previous one, not from the run's state). */
static double side_squeeze(acbb_set_sim *ss, acbb_set_mech *w, double Fa, int side, int *ok)
{
    *ok = solve_loads(ss, (loads){ Fa, 0.0, 0.0 }, w) == ACBB_OK;
    double g = -INFINITY;
    for (int k = 0; k < w->n; k++) {
        if (w->orient[k] != side) continue;
        const acbb_mech_state *st = &ss->b[k]->ms;
        for (int j = 0; j < st->n; j++) {
            acbb_ball_frame f;
            acbb_mech_ball_frame(ss->b[k]->mech, st, j, &f);
            g = fmax(g, hypot(f.A1, f.A2) - f.L0_i - f.L0_o);
        }
    }
    return g * 1e6;
}

/* Lift-off (MODEL.md 14; issue 25): the external thrust at which the rings
 * of the unloading side stop squeezing its balls, at the current
 * temperatures and speed, the radial load and moment set aside (a bearing
 * that carries radial load keeps balls loaded at any thrust; the lift-off
 * thrust is the axial preload's, as [HK-EC] states it). At rest the side's
 * reaction is zero there (2^1.5 Fp for a constant contact angle [HK-EC],
 * 3.07-3.71 Fp for the 15 deg 7008C, MODEL.md 14). At speed the centrifugal
 * force still presses each ball on the outer race, and the slope of the
 * outer groove passes part of it to the inner race (7008C pairs: 1 % of
 * the preload at 1000 rpm, 15-40 % at 8000-16 000 rpm), which vanishes
 * only microns of shaft travel later, on a rigid pair at several times
 * the thrust: that full separation is no lift-off a designer can use
 * (issue 25: it let a design carry 7 times the thrust that unloads the
 * back bearing); what the side still carries at lift-off is reported
 * beside it (ss->lift_rest, 0 at rest). The squeeze is smooth and nearly linear in
 * the thrust, so the root is found by a few secant steps.
 * A rigid opposed set unloads its -1 side under +x thrust; a spring set's
 * floating side keeps the spring force, so thrust the other way unloads
 * the +1 side at about the spring force. A tandem set has no opposite
 * side: 0. */
typedef struct {
    acbb_set_sim *ss;
    acbb_set_mech w;
    int side, dir;
    double x[2], f[2];         /* the last two thrusts tried and their squeezes */
    double rest;               /* the side's axial reaction at the last one, N */
} lift_ctx;

/* A thrust the set cannot carry (no shaft equilibrium: past lift-off the
 * remaining side alone may hold no moment, and a spring set's shaft is then
 * free axially) counts as lifted off; the next solve starts again from the
 * run's state. */
static double lift_fn(double Fa, lift_ctx *c)
{
    int ok;
    double g = side_squeeze(c->ss, &c->w, Fa * c->dir, c->side, &ok);
    if (!ok) { /* again from the run's state before calling it lifted off */
        keep_members(c->ss, 1);
        c->w = c->ss->sm;
        g = side_squeeze(c->ss, &c->w, Fa * c->dir, c->side, &ok);
    }
    c->rest = 0.0;
    if (!ok) {
        keep_members(c->ss, 1);
        c->w = c->ss->sm;
        g = -1.0;
    } else {
        for (int k = 0; k < c->w.n; k++) if (c->w.orient[k] == c->side) c->rest += c->w.Fx[k];
    }
    if (fabs(Fa - c->x[1]) > 1e-3 * fabs(Fa)) /* a slope above the solves' noise */
        c->x[0] = c->x[1], c->f[0] = c->f[1];
    c->x[1] = Fa, c->f[1] = g;
    return g;
}

/* Secant steps on the squeeze from the guess x0 (the first with the last
 * search's slope, else 2 % of x0), kept inside the bracket once the root
 * is bracketed (bisection when a step leaves it), until a step is below
 * tol. 0: lifted off with no thrust. */
static double search_liftoff(lift_ctx *c, double x0, double slope, double tol)
{
    double a = -INFINITY, b = INFINITY; /* squeezed at a, lifted off at b */
    double x = fmax(x0, tol), f = lift_fn(x, c), px = NAN, pf = NAN;
    for (int i = 0; i < 50; i++) {
        if (f > 0.0) a = fmax(a, x); else b = fmin(b, x);
        if (b <= 0.0) return 0.0;
        if (b - a <= tol) return f > 0.0 ? b : a; /* the bracket's other end */
        double sl = isfinite(pf) && pf != f ? (f - pf) / (x - px) : slope;
        double next = sl < 0.0 ? x - f / sl : x * (f > 0.0 ? 1.02 : 0.98);
        if (fabs(next - x) <= tol && next > a && next < b) return next;
        if (!isfinite(b)) next = fmin(fmax(next, a + 0.5 * tol), 4.0 * a);
        else if (!isfinite(a)) next = fmax(fmin(next, b - 0.5 * tol), 0.0);
        else if (!(next > a && next < b)) next = 0.5 * (a + b);
        px = x, pf = f;
        x = next;
        f = lift_fn(x, c);
    }
    return isfinite(b) ? b : a; /* no bracket: the last thrust tried */
}

/* The preload the search works at: the set's now, or the assembly one. */
static double lift_preload(const acbb_set_sim *ss)
{
    return ss->preload > 0.0 ? ss->preload : ss->sm.Fp;
}

/* The lift-off along the line through the last two searches' (preload,
 * lift-off), or the last one scaled by the preload since, else 3 Fp (a
 * little below the static ratio, MODEL.md 14) or a spring set's force. */
static double liftoff_guess(const acbb_set_sim *ss)
{
    double F = lift_preload(ss), P1 = ss->lift_preload, P0 = ss->lift_prev[0];
    if (ss->liftoff > 0.0 && ss->lift_prev[1] > 0.0 && P0 > 0.0 && fabs(P1 - P0) > 1e-3 * P1)
        return ss->liftoff + (ss->liftoff - ss->lift_prev[1]) / (P1 - P0) * (F - P1);
    if (ss->liftoff > 0.0 && P1 > 0.0) return ss->liftoff * F / P1;
    return ss->sm.spring ? ss->sm.Fp : 3.0 * F;
}

static void members_probing(acbb_set_sim *ss, int on)
{
    for (int k = 0; k < ss->n; k++) acbb_mech_probing(ss->b[k]->mech, on);
}

/* Ball k's positions, angles and Hertz constants where the last search
 * ended; its speeds and tractions the run's (the probes' premise). */
static void adopt_balls(acbb_mech_state *st, const acbb_mech_state *at)
{
    for (int j = 0; j < st->n && j < at->n; j++) {
        acbb_ball_state *b = &st->ball[j];
        const acbb_ball_state *a = &at->ball[j];
        b->X1 = a->X1, b->X2 = a->X2, b->Qi = a->Qi, b->Qo = a->Qo;
        b->alpha_i = a->alpha_i, b->alpha_o = a->alpha_o;
        b->alpha_i_lag = a->alpha_i_lag, b->alpha_o_lag = a->alpha_o_lag;
        b->delta_i = a->delta_i, b->delta_o = a->delta_o;
        b->hc_i = a->hc_i, b->hc_o = a->hc_o;
        b->hc_alpha_i = a->hc_alpha_i, b->hc_alpha_o = a->hc_alpha_o;
        b->loaded = a->loaded;
    }
}

/* Start where the last search ended (balls, shaft position and its
 * Jacobian), the run's offsets and loads; after it, keep where it ended. */
static void lift_state(acbb_set_sim *ss, acbb_set_mech *w, int save)
{
    if (save) {
        for (int k = 0; k < ss->n; k++) acbb_mech_state_copy(ss->lift_ms[k], &ss->b[k]->ms);
        ss->lift_sm = *w;
        return;
    }
    *w = ss->sm;
    if (!ss->lift_sm.n) return;
    for (int k = 0; k < ss->n; k++) adopt_balls(&ss->b[k]->ms, ss->lift_ms[k]);
    memcpy(w->q, ss->lift_sm.q, sizeof w->q);
    memcpy(w->J, ss->lift_sm.J, sizeof w->J);
    w->J_ok = ss->lift_sm.J_ok;
    w->J_n = ss->lift_sm.J_n;
}

double acbb_set_liftoff(acbb_set_sim *ss, double rel_tol)
{
    if (!has_side(&ss->sm, 1) || !has_side(&ss->sm, -1)) return 0.0;
    int side = ss->sm.spring ? 1 : -1;
    lift_ctx c = { .ss = ss, .side = side, .dir = -side, .x = { NAN, NAN }, .f = { NAN, NAN } };
    keep_members(ss, 0);
    members_probing(ss, 1);
    lift_state(ss, &c.w, 0);
    double x0 = liftoff_guess(ss);
    double root = search_liftoff(&c, x0, ss->lift_slope, fmax(rel_tol * x0, 1e-4 * ss->sm.Fp));
    lift_state(ss, &c.w, 1);
    ss->lift_rest = c.rest;
    double s = (c.f[1] - c.f[0]) / (c.x[1] - c.x[0]);
    if (isfinite(s) && s < 0.0) ss->lift_slope = s; /* else the last one's */
    members_probing(ss, 0);
    keep_members(ss, 1);
    ss->lift_prev[0] = ss->lift_preload;
    ss->lift_prev[1] = ss->liftoff;
    ss->lift_preload = lift_preload(ss);
    ss->lift_speed = ss->s.inner_speed;
    return root;
}

/* Probes at loads a and b into p[0], p[1]. */
static acbb_status probe_pair(acbb_set_sim *ss, loads a, loads b, acbb_set_mech p[2])
{
    acbb_status rc = probe(ss, a, &p[0], &ss->memo);
    if (rc == ACBB_OK) rc = probe(ss, b, &p[1], &ss->memo);
    return rc;
}

/* The nose probes' solves 100 times finer than the run's (on: keep the
 * set's and the members' tolerances in keep; off: put them back). At the
 * run's own (the shaft to 10 mech_tol of its loads) a nudge of 1e-3 of
 * the loads left the radial difference resolved to ~1e-5: pair-DB-heated's
 * set radial stiffness moved 1e-5 with the last bits of the state it
 * started from (issue 30, BENCHMARKS.md fourth round). */
static void fine_tol(acbb_set_sim *ss, int on, double keep[ACBB_MAX_SET + 1])
{
    if (on) keep[0] = ss->sm.tol;
    ss->sm.tol = on ? 1e-2 * keep[0] : keep[0];
    for (int k = 0; k < ss->n; k++) {
        double t = acbb_mech_set_tol(ss->b[k]->mech, 0.0);
        if (on) keep[1 + k] = t;
        acbb_mech_set_tol(ss->b[k]->mech, on ? 1e-2 * t : keep[1 + k]);
    }
}

/* Radial and tilt stiffness at the nose: central differences of the shaft
 * equilibrium in the radial force and the moment there. A radial load or
 * moment frees shaft freedoms that the run under pure thrust keeps still,
 * so each probe starts with a finite-difference Jacobian at the run's
 * shaft position: the same member solves in all four, made by the first
 * and replayed by the others (issue 30: bit for bit the four solves'
 * own). */
void acbb_set_nose_stiffness(acbb_set_sim *ss)
{
    double R = 0.5 * ss->s.pitch_diameter;
    double h = fmax(1e-3 * (fabs(ss->sm.Fr) + ss->sm.Fp + fabs(ss->sm.Fa)), 1.0);
    acbb_set_mech p[2];
    loads base = { ss->sm.Fa, ss->sm.Fr, ss->sm.M };
    double keep[ACBB_MAX_SET + 1];
    ss->K_rad = ss->K_tilt = 0.0;
    fine_tol(ss, 1, keep);
    ss->memo.state = 0;
    if (probe_pair(ss, (loads){ base.Fa, base.Fr + h, base.M },
                   (loads){ base.Fa, base.Fr - h, base.M }, p) == ACBB_OK) {
        double xn = ss->sm.x_nose;
        double d = (p[0].q[1] - p[0].q[2] * xn) - (p[1].q[1] - p[1].q[2] * xn);
        ss->K_rad = d != 0.0 ? 2.0 * h / d : 0.0;
    }
    if (probe_pair(ss, (loads){ base.Fa, base.Fr, base.M + h * R },
                   (loads){ base.Fa, base.Fr, base.M - h * R }, p) == ACBB_OK) {
        double d = p[0].q[2] - p[1].q[2];
        ss->K_tilt = d != 0.0 ? 2.0 * h * R / d : 0.0;
    }
    ss->memo.state = 0;
    fine_tol(ss, 0, keep);
}
