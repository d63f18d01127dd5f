/* acbb — radial and tilting ring stiffness (stiffness.h). Each point is a
 * mechanics solve with the radial load or moment nudged, in the
 * race-control ball model at both ends of a difference. The equilibrium
 * is unique, so where it starts changes it only by solver noise: from the
 * caller's converged state (one warm solve per point, MODEL.md section 3)
 * or, without one or if that fails, by continuation in speed from rest
 * like the sim's set-up. */
#include <math.h>
#include <stdlib.h>
#include "mechanics.h"
#include "stiffness.h"

/* A converged state as the warm start of m: speeds back to race control
 * (the Level-2 tractions belong to the run's ball model, not this one). */
static void warm_start(const acbb_mech *m, const acbb_mech_state *warm, acbb_mech_state *st)
{
    acbb_mech_state_copy(st, warm);
    for (int j = 0; j < st->n; j++) st->ball[j].traction_valid = 0;
    acbb_mech_adopt_state(m, st);
}

/* What a probe holds besides the axial load: the radial probe keeps the
 * tilt at the operating point's (0 in pure thrust, the seed's radial
 * stiffness; the catalogue's, the ring guided by the shaft), the tilt
 * probes leave the ring free radially or hold it (issue 18). */
enum { PROBE_RADIAL, PROBE_TILT, PROBE_TILT_HELD };

/* The probe's mechanics for scene s: its holds set. */
static acbb_status probe_mech(const acbb_scene *s, double dx_held, const acbb_mech_state *warm,
                              int probe, acbb_mech **out)
{
    acbb_mech *m = NULL;
    acbb_status rc = acbb_mech_new(s, &m, NULL);
    if (rc != ACBB_OK) return rc;
    if (s->preload == ACBB_PRELOAD_DISPLACEMENT) acbb_mech_fix_axial(m, 1, dx_held);
    if (probe == PROBE_TILT_HELD) acbb_mech_hold_radial(m, warm ? warm->dz : 0.0);
    if (probe == PROBE_RADIAL) acbb_mech_hold_tilt(m, warm ? warm->thy : 0.0);
    acbb_mech_broyden_held(m, 1);
    /* 1e-2 of the run's tolerance: the response to a 1 % nudge is then
     * resolved to ~1e-9 (at the run's own to ~5e-7, which a path's last
     * bits moved: issue 30, BENCHMARKS.md fourth round). */
    acbb_mech_set_tol(m, 1e-2 * s->mech_tol);
    *out = m;
    return ACBB_OK;
}

/* The equilibrium st of m (built for scene s, whose load is nudged) from
 * `warm`, else by continuation from rest. */
static acbb_status solve_point(acbb_mech *m, const acbb_scene *s, const acbb_expansion *e,
                               const acbb_mech_state *warm, acbb_mech_state *st)
{
    acbb_status rc = ACBB_OK;
    int cold = 1;
    if (warm) {
        warm_start(m, warm, st);
        cold = acbb_mech_solve(m, s->inner_speed, e, st, NULL) != ACBB_OK;
    }
    if (cold) rc = acbb_mech_init_state(m, st, NULL);
    for (int k = 1; k <= 4 && rc == ACBB_OK && cold; k++)
        rc = acbb_mech_solve(m, s->inner_speed * k / 4.0, k == 4 ? e : NULL, st, NULL);
    return rc;
}

/* Central difference of the response to a load nudged by +-h around v.
 * Both ends on one mechanics (the loads are set per end): the second
 * solve starts from the first's ring Jacobian (mechanics.c ring_broyden)
 * instead of building its own (issue 30 lever 2). */
static double difference(acbb_scene *s, double *load, double h, const acbb_expansion *e,
                         double dx_held, const acbb_mech_state *warm,
                         const acbb_mech_state *start, int probe)
{
    double v = *load, r[2] = { 0, 0 };
    acbb_mech *m = NULL;
    acbb_mech_state *st = malloc(sizeof *st);
    acbb_status rc = st ? ACBB_OK : ACBB_ENOMEM;
    for (int k = 0; k < 2 && rc == ACBB_OK; k++) {
        *load = v + (k ? -h : h);
        if (k == 0) rc = probe_mech(s, dx_held, warm, probe, &m);
        else acbb_mech_set_loads(m, s->axial_load, s->radial_load, s->moment_load);
        if (rc == ACBB_OK) rc = solve_point(m, s, e, start, st);
        if (rc == ACBB_OK) r[k] = probe != PROBE_RADIAL ? st->thy : st->dz;
    }
    acbb_mech_free(m);
    free(st);
    *load = v;
    double K = 2.0 * h / (r[0] - r[1]);
    return rc == ACBB_OK && isfinite(K) ? K : NAN; /* NAN: the probe failed */
}

acbb_status acbb_ring_stiffness(const acbb_scene *s, const acbb_expansion *e, double dx_held,
                                const acbb_mech_state *warm, acbb_stiffness *out)
{
    acbb_scene t = *s;
    /* A nudge of 1 % of the axial load (at least 1 N, 1 N m at the pitch
     * radius): small against the loads, large against solver noise. */
    double h = fmax(0.01 * fabs(s->axial_load), 1.0);
    double hm = h * 0.5 * s->pitch_diameter;
    /* Every probe starts from the race-control equilibrium at the
     * operating point's loads, solved once: the probes then move by
     * their nudge only, not also from the run's ball model to this one. */
    acbb_mech_state *start = warm ? malloc(sizeof *start) : NULL;
    acbb_mech *m0 = NULL;
    if (start && probe_mech(s, dx_held, NULL, -1, &m0) == ACBB_OK) {
        warm_start(m0, warm, start);
        if (acbb_mech_solve(m0, s->inner_speed, e, start, NULL) != ACBB_OK) {
            free(start);
            start = NULL;
        }
    }
    acbb_mech_free(m0);
    const acbb_mech_state *from = start ? start : warm;
    out->radial = difference(&t, &t.radial_load, h, e, dx_held, warm, from, PROBE_RADIAL);
    /* The tilt probes solve the tilt whatever mounting.tilt says: held
     * describes the operating point, the probe asks how the ring would
     * tilt under a moment (README: both tilt stiffnesses are reported). */
    t.tilt = ACBB_TILT_FREE;
    out->tilt = difference(&t, &t.moment_load, hm, e, dx_held, warm, from, PROBE_TILT);
    out->tilt_held = difference(&t, &t.moment_load, hm, e, dx_held, warm, from, PROBE_TILT_HELD);
    free(start);
    return ACBB_OK;
}

/* One end of the axial difference: the equilibrium with dx held, at a
 * tolerance 1e-4 times m's (the nudge's share of the displacement): at
 * m's own 1e-8 the held solve stops with a force error of ~1e-8 of the
 * load, 1e-4 of the difference it feeds (issue 30: combined-load's axial
 * stiffness landed 5e-5 off the converged derivative, by a path's last
 * bits). Should the finer solve fail, m's own tolerance. */
static acbb_status axial_point(acbb_mech *m, double omega_i, const acbb_expansion *e,
                               const acbb_mech_state *at, double dx, acbb_mech_state *st)
{
    acbb_mech_fix_axial(m, 1, dx);
    double tol = acbb_mech_set_tol(m, 0.0);
    acbb_status rc = ACBB_DIVERGED;
    for (int k = 0; k < 2 && rc != ACBB_OK; k++) {
        acbb_mech_set_tol(m, k ? tol : fmax(1e-4 * tol, 1e-14));
        acbb_mech_state_copy(st, at);
        rc = acbb_mech_solve(m, omega_i, e, st, NULL);
    }
    acbb_mech_set_tol(m, tol);
    return rc;
}

double acbb_axial_stiffness(acbb_mech *m, double omega_i, const acbb_expansion *e,
                            const acbb_mech_state *at, int held)
{
    acbb_mech_state *st = malloc(sizeof *st);
    if (!st) return NAN;
    double dx = at->dx, h = fmax(1e-9, 1e-4 * fabs(dx)), F[2] = { 0, 0 };
    acbb_status rc = ACBB_OK;
    for (int k = 0; k < 2 && rc == ACBB_OK; k++) {
        rc = axial_point(m, omega_i, e, at, dx + (k ? -h : h), st);
        F[k] = st->Fx;
    }
    acbb_mech_fix_axial(m, held, held ? dx : 0.0);
    free(st);
    double K = (F[0] - F[1]) / (2.0 * h);
    return rc == ACBB_OK && isfinite(K) ? K : NAN;
}
