/* acbb — the mechanics solver's state (internal to mechanics.c and
 * mechanics_setup.c; everyone else sees the opaque acbb_mech of
 * mechanics.h). */
#ifndef ACBB_MECHANICS_PRIV_H
#define ACBB_MECHANICS_PRIV_H

#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_roots.h>
#include "mechanics.h"

#define MAX_RING_DOF 3
#define MECH_PRED_U 4   /* the predictor's inputs: the four expansions */

struct acbb_mech {
    acbb_geometry g;
    int centrifugal, gyroscopic;
    acbb_race_control race;
    acbb_hertz_mode hertz;
    acbb_geom_mode geom;
    double tol;
    double hertz_tol;           /* rad: constants kept below this angle move (0: 1e-11) */
    int broyden_held;           /* 1: held-displacement ring solves by Broyden first too */
    double mu;                  /* friction available for the gyroscopic moment */
    double Fx, Fz, My;          /* applied loads on the IR */
    int fix_axial;
    double dx_fixed;
    int centred;                /* dx fixed by symmetry (deep groove, no thrust) */
    int dof_dz, dof_thy;        /* active ring DOFs besides dx */
    int prescribed;             /* all ring DOFs held (a member of a set, MODEL.md 14) */
    double dz_fixed, thy_fixed; /* the held radial displacement (m) and tilt (rad) */
    int hold_radial;            /* dz held at dz_hold, the tilt free (stiffness.h) */
    double dz_hold;
    int hold_tilt;              /* thy held at thy_hold, dz free (stiffness.h) */
    double thy_hold;
    gsl_multiroot_fsolver *ring_solver[MAX_RING_DOF + 1];
    double ring_J[MAX_RING_DOF + 1][MAX_RING_DOF * MAX_RING_DOF]; /* last, per DOF count */
    int ring_J_ok[MAX_RING_DOF + 1];
    double ball_J[ACBB_MAX_BALLS][4]; /* last ball Jacobians (chord steps, transient mode) */
    int ball_J_ok[ACBB_MAX_BALLS];
    /* cos and sin of each solved ball's azimuth psi_key[j] (solve_balls:
     * six per ball and ring evaluation, the azimuths fixed; NAN: none) */
    double psi_key[ACBB_MAX_BALLS], psi_cos[ACBB_MAX_BALLS], psi_sin[ACBB_MAX_BALLS];
    double kept_J[ACBB_MAX_BALLS][4]; /* ball_J before the probes (acbb_mech_probing) */
    int kept_J_ok[ACBB_MAX_BALLS];
    gsl_root_fsolver *brent;
    gsl_root_fsolver *brent_z, *brent_a; /* nested fallback of the ball solve */
    /* context of the solve in progress */
    double omega;
    const acbb_expansion *e;    /* NULL or &e_copy */
    acbb_expansion e_copy;
    acbb_mech_state *trial;
    acbb_status inner_status;
    /* The last two roots of transient steps (mechanics_predict.c), newest
     * first: ring dx, dz, thy, the solved balls' X1, X2, alpha_i, alpha_o,
 * the expansions;
     * ph_n of them kept, made with ph_nb balls, these loads and speed. */
    double ph_x[2][3], ph_b[2][ACBB_MAX_BALLS][4], ph_u[2][MECH_PRED_U];
    double ph_omega, ph_F[3];
    int ph_n, ph_nb, ph_fix;
    long ring_evals;            /* ring residuals evaluated (ring_broyden's speed) */
};

/* The predicted start of a transient step's solve into st (unchanged
 * without a history that applies); a solved state into the history. */
void acbb_mechx_predict(acbb_mech *m, acbb_mech_state *st);
void acbb_mechx_remember(acbb_mech *m, const acbb_mech_state *st);

#endif
