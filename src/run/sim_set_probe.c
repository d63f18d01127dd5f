/* acbb — probes of a bearing set's converged state (MODEL.md 14): the
 * shaft solved again under other external loads at the same temperatures,
 * speed and ball speeds, for the preload with no thrust, the lift-off
 * thrust and the stiffness at the nose. */
#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include "sim_set_priv.h"

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
        if (back) acbb_mech_state_copy(acbb_simm_ms(ss->b[k]), ss->scratch[k]);
        else acbb_mech_state_copy(ss->scratch[k], acbb_simm_ms(ss->b[k]));
}

/* Solve the shaft under other external loads into *out; the members and
 * the set's own solution are put back afterwards. */
static acbb_status probe(acbb_set_sim *ss, loads L, acbb_set_mech *out)
{
    keep_members(ss, 0);
    *out = ss->sm;
    acbb_status rc = solve_loads(ss, L, out);
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
    if (probe(ss, (loads){ 0.0, ss->sm.Fr, ss->sm.M }, &p) != ACBB_OK) return 0.0;
    return acbb_set_mech_preload(&p);
}

/* Load left on `side` under thrust Fa, solved in *w from its last
 * solution (the lift-off search walks the thrust: each solve starts from
 * the previous one, not from the run's state). */
static double unloading_side(acbb_set_sim *ss, acbb_set_mech *w, double Fa, int side, int *ok)
{
    *ok = solve_loads(ss, (loads){ Fa, 0.0, 0.0 }, w) == ACBB_OK;
    double F = 0.0;
    for (int k = 0; k < w->n; k++) if (w->orient[k] == side) F += w->Fx[k];
    return F;
}

/* External thrust at which the unloading side's balls all unload, at the
 * current temperatures and speed, the radial load and moment set aside (a
 * bearing that carries radial load keeps balls loaded at any thrust; the
 * lift-off thrust is the axial preload's, as [HK-EC] states it): GSL's Brent on F^(2/3) - eps^(2/3) of the side's
 * load F, which near lift-off falls as (Fa_lift - Fa)^1.5 (Hertz), so its
 * 2/3 power is nearly linear there; to 1e-4 of the preload. A rigid
 * opposed set unloads its -1 side under +x thrust; a spring set's floating
 * side keeps the spring force, so thrust the other way unloads the +1 side
 * at the spring force. A tandem set has no opposite side: 0. */
typedef struct { acbb_set_sim *ss; acbb_set_mech w; int side, dir; double eps; } lift_ctx;

/* A thrust the set cannot carry (no shaft equilibrium: past lift-off the
 * remaining side alone may hold no moment, and a spring set's shaft is then
 * free axially) counts as lifted off; the next solve starts again from the
 * run's state. */
static double lift_fn(double Fa, void *p)
{
    lift_ctx *c = p;
    int ok;
    double F = unloading_side(c->ss, &c->w, Fa * c->dir, c->side, &ok);
    if (!ok) { /* again from the run's state before calling it lifted off */
        keep_members(c->ss, 1);
        c->w = c->ss->sm;
        F = unloading_side(c->ss, &c->w, Fa * c->dir, c->side, &ok);
    }
    if (!ok) {
        keep_members(c->ss, 1);
        c->w = c->ss->sm;
        F = 0.0;
    }
    return cbrt(F * F) - cbrt(c->eps * c->eps);
}

static double search_liftoff(lift_ctx *cp)
{
    lift_ctx c = *cp;
    acbb_set_sim *ss = c.ss;
    /* First bracket: a spring set lifts off at the spring force; a rigid
     * opposed pair near 2^1.5 times the preload it carries now (MODEL.md
     * 14, [HK-EC]; 3x: a little past it, and past it the walk doubles). */
    double est = ss->sm.spring ? ss->sm.Fp : 3.0 * fmax(acbb_set_mech_preload(&ss->sm), ss->sm.Fp);
    double lo = ss->sm.Fa * c.dir, hi = fmax(lo, 0.0) + est;
    double flo = lift_fn(lo, &c), fhi = lift_fn(hi, &c);
    if (flo <= 0.0) return 0.0;
    /* Walk out to a bracket along the secant of the nearly linear F^(2/3),
     * a quarter past its root (at least 1.25x, at most 4x a step). */
    for (int i = 0; i < 20 && fhi > 0.0; i++) {
        double next = flo > fhi ? hi + 1.25 * (hi - lo) * fhi / (flo - fhi) : 4.0 * hi;
        next = fmin(fmax(next, hi + 0.25 * fabs(hi)), hi + 3.0 * fabs(hi));
        lo = hi;
        flo = fhi;
        hi = next;
        fhi = lift_fn(hi, &c);
    }
    gsl_function F = { lift_fn, &c };
    gsl_root_fsolver *b = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    double root = 0.0;
    if (b && fhi <= 0.0 && gsl_root_fsolver_set(b, &F, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < 60; it++) {
            if (gsl_root_fsolver_iterate(b) != GSL_SUCCESS) break;
            root = gsl_root_fsolver_root(b);
            if (gsl_root_fsolver_x_upper(b) - gsl_root_fsolver_x_lower(b) < 1e-4 * ss->sm.Fp)
                break;
        }
    }
    if (b) gsl_root_fsolver_free(b);
    return root;
}

double acbb_set_liftoff(acbb_set_sim *ss)
{
    if (!has_side(&ss->sm, 1) || !has_side(&ss->sm, -1)) return 0.0;
    int side = ss->sm.spring ? 1 : -1;
    lift_ctx c = { ss, ss->sm, side, -side, 1e-6 * ss->sm.Fp };
    keep_members(ss, 0);
    double root = search_liftoff(&c);
    keep_members(ss, 1);
    return root;
}

/* Radial and tilt stiffness at the nose: central differences of the shaft
 * equilibrium in the radial force and the moment there. */
void acbb_set_nose_stiffness(acbb_set_sim *ss)
{
    double R = 0.5 * ss->s.pitch_diameter;
    double h = fmax(1e-3 * (fabs(ss->sm.Fr) + ss->sm.Fp + fabs(ss->sm.Fa)), 1.0);
    acbb_set_mech p[2];
    loads base = { ss->sm.Fa, ss->sm.Fr, ss->sm.M };
    ss->K_rad = ss->K_tilt = 0.0;
    if (probe(ss, (loads){ base.Fa, base.Fr + h, base.M }, &p[0]) == ACBB_OK
        && probe(ss, (loads){ base.Fa, base.Fr - h, base.M }, &p[1]) == ACBB_OK) {
        double xn = ss->sm.x_nose;
        double d = (p[0].q[1] - p[0].q[2] * xn) - (p[1].q[1] - p[1].q[2] * xn);
        ss->K_rad = d != 0.0 ? 2.0 * h / d : 0.0;
    }
    if (probe(ss, (loads){ base.Fa, base.Fr, base.M + h * R }, &p[0]) == ACBB_OK
        && probe(ss, (loads){ base.Fa, base.Fr, base.M - h * R }, &p[1]) == ACBB_OK) {
        double d = p[0].q[2] - p[1].q[2];
        ss->K_tilt = d != 0.0 ? 2.0 * h * R / d : 0.0;
    }
}

