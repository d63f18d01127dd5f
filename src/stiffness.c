/* acbb — radial and tilting ring stiffness (stiffness.h). Each point is a
 * fresh mechanics solve with the radial load or moment nudged, reached by
 * continuation in speed like the sim's set-up, so both ends of a difference
 * use the same (race-control) ball model. */
#include <math.h>
#include <stdlib.h>
#include "acbb/mechanics.h"
#include "acbb/stiffness.h"

/* delta_z and theta_y of the equilibrium of scene s. */
static acbb_status solve_point(const acbb_scene *s, const acbb_expansion *e, double dx_held,
                               double *dz, double *thy)
{
    acbb_mech *m = NULL;
    acbb_mech_state *st = malloc(sizeof *st);
    acbb_status rc = st ? acbb_mech_new(s, &m, NULL) : ACBB_ENOMEM;
    if (rc == ACBB_OK && s->preload == ACBB_PRELOAD_DISPLACEMENT)
        acbb_mech_fix_axial(m, 1, dx_held);
    if (rc == ACBB_OK) rc = acbb_mech_init_state(m, st, NULL);
    for (int k = 1; k <= 4 && rc == ACBB_OK; k++)
        rc = acbb_mech_solve(m, s->inner_speed * k / 4.0, k == 4 ? e : NULL, st, NULL);
    if (rc == ACBB_OK) {
        *dz = st->dz;
        *thy = st->thy;
    }
    acbb_mech_free(m);
    free(st);
    return rc;
}

/* Central difference of the response to a load nudged by +-h around v. */
static double difference(acbb_scene *s, double *load, double h, const acbb_expansion *e,
                         double dx_held, int tilt)
{
    double v = *load, r[2] = { 0, 0 }, other;
    acbb_status rc = ACBB_OK;
    for (int k = 0; k < 2 && rc == ACBB_OK; k++) {
        *load = v + (k ? -h : h);
        rc = tilt ? solve_point(s, e, dx_held, &other, &r[k])
                  : solve_point(s, e, dx_held, &r[k], &other);
    }
    *load = v;
    double K = 2.0 * h / (r[0] - r[1]);
    return rc == ACBB_OK && isfinite(K) ? K : 0.0;
}

acbb_status acbb_ring_stiffness(const acbb_scene *s, const acbb_expansion *e, double dx_held,
                                acbb_stiffness *out)
{
    acbb_scene t = *s;
    /* A nudge of 1 % of the axial load (at least 1 N, 1 N m at the pitch
     * radius): small against the loads, large against solver noise. */
    double h = fmax(0.01 * fabs(s->axial_load), 1.0);
    out->radial = difference(&t, &t.radial_load, h, e, dx_held, 0);
    out->tilt = difference(&t, &t.moment_load, h * 0.5 * s->pitch_diameter, e, dx_held, 1);
    return ACBB_OK;
}
