/* Shared set-up of the Level-2 module tests (test_quasi_dynamic,
 * test_dynamic): the default 7008C scene solved quasi-statically at one
 * speed and thrust, with oil and oil-air mixture at ambient temperature
 * (MODEL.md sections 3-5). Header-only, static functions. */
#ifndef ACBB_BALL_FIXTURE_H
#define ACBB_BALL_FIXTURE_H

#include <stdio.h>
#include "mechanics.h"
#include "quasi_dynamic.h"
#include "acbb/units.h"

typedef struct {
    acbb_scene s;
    acbb_mech *m;
    const acbb_geometry *g;
    acbb_mech_state st;
    acbb_quad q;
    acbb_oil_state oil;     /* both inlets at ambient */
    acbb_mixture mix;
    double wi;              /* inner-ring speed, rad/s */
} ball_fixture;

/* s must already hold the scene; rpm and Fx are applied here. */
static int fixture_setup(ball_fixture *f, double rpm, double Fx)
{
    acbb_error err = { "" };
    f->wi = rpm * ACBB_RPM;
    f->s.inner_speed = f->wi;
    f->s.axial_load = Fx;
    f->m = NULL;
    if (acbb_mech_new(&f->s, &f->m, &err) != ACBB_OK
        || acbb_mech_init_state(f->m, &f->st, &err) != ACBB_OK
        || acbb_mech_solve(f->m, f->wi, NULL, &f->st, &err) != ACBB_OK) {
        printf("# set-up: %s\n", err.msg);
        return 0;
    }
    f->g = acbb_mech_geometry(f->m);
    acbb_quad_init(&f->q, f->s.contact_grid);
    acbb_oil_at(&f->s, f->s.ambient_C, &f->oil);
    acbb_mixture_at(&f->s, &f->oil, &f->mix);
    return 1;
}

/* Level 1 <-> Level 2 iteration of MODEL.md section 4 (ball speeds from
 * traction, then the equilibrium with the traction resultants) until the
 * orbital speed moves by less than tol; returns the passes used or -1. */
static int fixture_level2(ball_fixture *f, acbb_qd *qd, double tol)
{
    acbb_error err = { "" };
    for (int pass = 1; pass <= 30; pass++) {
        double change;
        if (acbb_qd_update(qd, &f->s, &f->q, f->g, f->wi, &f->oil, &f->oil, &f->mix, &f->st,
                           &change, &err) != ACBB_OK
            || acbb_mech_solve(f->m, f->wi, NULL, &f->st, &err) != ACBB_OK) {
            printf("# level 2: %s\n", err.msg);
            return -1;
        }
        if (change < tol) return pass;
    }
    return -1;
}

#endif
