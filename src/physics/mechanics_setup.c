/* acbb — the mechanics solver's set-up, constraints and accessors
 * (mechanics.h): what a scene or a set asks of the ring's degrees of
 * freedom before a solve. Kept apart from the equilibrium solver in
 * mechanics.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_roots.h>
#include "mechanics.h"
#include "mechanics_priv.h"

/* ---- set-up ---- */

/* m (all zero) set up for scene s: what acbb_mech_new and acbb_mech_renew
 * make alike, the solver workspaces aside. */
static acbb_status setup(acbb_mech *m, const acbb_scene *s, acbb_error *err)
{
    for (int j = 0; j < ACBB_MAX_BALLS; j++) m->psi_key[j] = NAN;
    acbb_geometry_init(s, &m->g);
    if (m->g.Z > ACBB_MAX_BALLS)
        return acbb_error_set(err, ACBB_EINVAL, "bearing.n_balls = %d: at most %d supported",
                              m->g.Z, ACBB_MAX_BALLS);
    int dyn = s->model != ACBB_MODEL_STATIC;
    m->centrifugal = dyn && s->centrifugal;
    m->gyroscopic = dyn && s->gyroscopic;
    m->race = s->race_control;
    m->hertz = s->hertz;
    m->geom = s->geometry;
    m->tol = s->mech_tol;
    m->mu = s->mu_bd;
    m->Fx = s->axial_load;
    m->Fz = s->radial_load;
    m->My = s->moment_load;
    m->dof_dz = s->radial_load != 0.0 || s->moment_load != 0.0;
    /* Deep groove (nominal angle 0) without thrust or moment: the bearing is
     * mirror-symmetric about the groove plane, so the inner ring sits
     * axially centred (A1 = 0 in MODEL.md 3, dx = -A0 sin alpha0) and the
     * axial DOF is fixed by symmetry instead of solved: with clearance its
     * Jacobian row is zero until a ball touches. (SEED geometry's A0' and
     * projections break the symmetry by far less than a micrometre.) */
    m->centred = s->contact_angle0 == 0.0 && s->axial_load == 0.0 && s->moment_load == 0.0;
    if (m->centred) {
        m->fix_axial = 1;
        m->dx_fixed = -m->g.A0 * sin(m->g.alpha0);
    }
    /* mounting.tilt (issue 18): the tilt is solved whenever the ring moves
     * off-axis (auto, the default, and free), so a moment of 0 and of
     * 1e-3 N m are the same problem: M = 0 states the moment, not the tilt.
     * Without radial load or moment the tilt is 0 by symmetry and not
     * solved (pure thrust: the seed's problem, unchanged). held keeps it 0
     * (a moment is refused by the rules). A centred deep-groove ring (no
     * thrust, no moment) is mirror-symmetric about the groove plane: its
     * tilt is 0 by symmetry like its axial offset, and not solved (its
     * tilt stiffness vanishes with the contact angle). */
    m->dof_thy = s->tilt == ACBB_TILT_HELD || m->centred ? 0 : m->dof_dz;
    return ACBB_OK;
}

acbb_status acbb_mech_new(const acbb_scene *s, acbb_mech **out, acbb_error *err)
{
    acbb_mech *m = calloc(1, sizeof *m);
    if (!m) return acbb_error_set(err, ACBB_ENOMEM, "mechanics: out of memory");
    acbb_status rc = setup(m, s, err);
    if (rc != ACBB_OK) {
        free(m);
        return rc;
    }
    m->brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    m->brent_z = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    m->brent_a = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    int ok = m->brent && m->brent_z && m->brent_a;
    for (int n = 1; n <= MAX_RING_DOF; n++) {
        m->ring_solver[n] = gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, n);
        ok = ok && m->ring_solver[n];
    }
    if (!ok) {
        acbb_mech_free(m);
        return acbb_error_set(err, ACBB_ENOMEM, "mechanics: out of memory");
    }
    *out = m;
    return ACBB_OK;
}

void acbb_mech_free(acbb_mech *m)
{
    if (!m) return;
    if (m->brent) gsl_root_fsolver_free(m->brent);
    if (m->brent_z) gsl_root_fsolver_free(m->brent_z);
    if (m->brent_a) gsl_root_fsolver_free(m->brent_a);
    for (int n = 1; n <= MAX_RING_DOF; n++)
        if (m->ring_solver[n]) gsl_multiroot_fsolver_free(m->ring_solver[n]);
    free(m);
}

const acbb_geometry *acbb_mech_geometry(const acbb_mech *m) { return &m->g; }

/* The workspace's solver pointers cleared and its in-solve context (the
 * expansions pointer into itself, the trial state) made its own: set
 * afresh by every solve (mechanics.c acbb_mech_solve, solve_ring). */
static void strip(acbb_mech *t, const acbb_mech *from)
{
    t->brent = t->brent_z = t->brent_a = NULL;
    for (int n = 0; n <= MAX_RING_DOF; n++) t->ring_solver[n] = NULL;
    t->e = from->e ? &t->e_copy : NULL;
    t->trial = NULL;
}

acbb_mech *acbb_mech_keep(const acbb_mech *m)
{
    acbb_mech *t = malloc(sizeof *t);
    if (!t) return NULL;
    memcpy(t, m, sizeof *t); /* the padding too: acbb_mech_same compares bytes */
    strip(t, m);
    return t;
}

int acbb_mech_same(const acbb_mech *a, const acbb_mech *b)
{
    acbb_mech *t = acbb_mech_keep(a), *u = t ? acbb_mech_keep(b) : NULL;
    int same = u && !t->e == !u->e;
    if (same) t->e = u->e = NULL; /* each into itself */
    same = same && memcmp(t, u, sizeof *t) == 0;
    acbb_mech_free(t);
    acbb_mech_free(u);
    return same;
}

/* m's solver workspaces are own's. */
static void put_solvers(acbb_mech *m, const acbb_mech *own)
{
    m->brent = own->brent;
    m->brent_z = own->brent_z;
    m->brent_a = own->brent_a;
    for (int n = 0; n <= MAX_RING_DOF; n++) m->ring_solver[n] = own->ring_solver[n];
}

acbb_status acbb_mech_renew(const acbb_scene *s, acbb_mech *m, acbb_error *err)
{
    acbb_mech own = *m;
    memset(m, 0, sizeof *m); /* as calloc leaves a new one, padding too */
    put_solvers(m, &own);
    return setup(m, s, err);
}

void acbb_mech_adopt(acbb_mech *dst, const acbb_mech *src)
{
    acbb_mech own = *dst;
    memcpy(dst, src, sizeof *dst);
    put_solvers(dst, &own);
    dst->e = src->e ? &dst->e_copy : NULL;
    dst->trial = NULL;
}

void acbb_mech_set_transient(acbb_mech *m, double angle_tol)
{
    m->hertz_tol = angle_tol > 0.0 ? angle_tol : 0.0;
}

void acbb_mech_broyden_held(acbb_mech *m, int on) { m->broyden_held = on; }

double acbb_mech_set_tol(acbb_mech *m, double tol)
{
    double old = m->tol;
    m->tol = tol;
    return old;
}

void acbb_mech_set_loads(acbb_mech *m, double Fx, double Fz, double My)
{
    m->Fx = Fx;
    m->Fz = Fz;
    m->My = My;
}

void acbb_mech_fix_axial(acbb_mech *m, int fixed, double dx)
{
    m->fix_axial = fixed;
    m->dx_fixed = dx;
    m->centred = 0; /* an explicit choice replaces the symmetry default */
}

void acbb_mech_adopt_state(const acbb_mech *m, acbb_mech_state *st)
{
    int sym = !m->dof_dz && !m->dof_thy;
    if (st->symmetric && !sym) acbb_mech_spread(st);
    st->symmetric = sym;
    st->mirror = !sym; /* Fy and Mz are not scene loads, dy and thz never move */
    st->dz = m->dof_dz ? st->dz : m->hold_radial ? m->dz_hold : 0.0;
    st->thy = m->dof_thy ? st->thy : m->hold_tilt ? m->thy_hold : 0.0;
}

/* ---- prescribed displacements (bearing sets, MODEL.md 14) ---- */

void acbb_mech_prescribe(acbb_mech *m, double dx, double dz, double thy)
{
    acbb_mech_fix_axial(m, 1, dx);
    m->prescribed = 1;
    m->dof_dz = m->dof_thy = 0;
    m->dz_fixed = dz;
    m->thy_fixed = thy;
}

void acbb_mech_hold_radial(acbb_mech *m, double dz)
{
    m->hold_radial = 1;
    m->dz_hold = dz;
    m->dof_dz = 0;
}

void acbb_mech_hold_tilt(acbb_mech *m, double thy)
{
    m->hold_tilt = 1;
    m->thy_hold = thy;
    m->dof_thy = 0;
    /* The radial offset is the probe's answer: solved even where the
     * nudged radial load is exactly 0 (issue 30: a held tilt off 0 moves
     * the ring radially under no radial load). */
    m->dof_dz = !m->hold_radial;
}
