/* acbb — quasi-static Jones-Harris bearing equilibrium (MODEL.md section 3)
 * with centrifugal force, gyroscopic moment and the thermal terms of the
 * seed's eqs (12)-(13).
 *
 * Ownership: acbb_mech_new allocates a solver workspace (GSL multiroot
 * solvers) bound to a copy of the scene's relevant values; free it with
 * acbb_mech_free. acbb_mech_state is a caller-owned plain value that also
 * serves as the warm start of the next solve. */
#ifndef ACBB_MECHANICS_H
#define ACBB_MECHANICS_H

#include "acbb/scene.h"
#include "acbb/limits.h"
#include "acbb/status.h"
#include "hertz.h"
#include "geometry.h"
#include "kinematics.h"
#include "losses.h"


typedef struct {
    double psi;                  /* azimuth, rad */
    double X1, X2;               /* ball centre relative to the OR groove centre, m */
    double Qi, Qo;               /* N */
    double alpha_i, alpha_o;     /* rad */
    double alpha_i_lag, alpha_o_lag; /* angles of the last accepted solve (SEED projections) */
    double delta_i, delta_o;     /* contact deflections (negative: gap), m */
    acbb_hertz_const hc_i, hc_o; /* constants at the operating angles */
    double hc_alpha_i, hc_alpha_o; /* angles the constants were computed at */
    acbb_hertz_contact ct_i, ct_o;
    double Fc, Mg;               /* centrifugal force (N), gyroscopic moment (N m) */
    acbb_kin kin;
    acbb_control control;
    /* Quasi-dynamic (Level 2) coupling: when traction_valid, the ball speeds
     * come from qd_w (omega_m, wx, wy, wz) and the meridional friction from
     * the traction resultants tr_i, tr_o (forces on the ball, x' y' z', N)
     * instead of race control and the zeta split. */
    int traction_valid;
    double qd_w[4];
    double tr_i[3], tr_o[3];
    double tr_Qi, tr_Qo;         /* loads the tractions were computed at */
    int loaded;                  /* 0: both contacts open, ball frozen */
} acbb_ball_state;

typedef struct {
    double dx, dy, dz, thy, thz; /* inner-ring displacements (m) and tilts (rad) */
    double Fx, Fy, Fz, My, Mz;   /* ring reactions (N, N m) */
    int n;                       /* balls */
    int symmetric;               /* 1: every ball identical, ball 0 solved */
    int mirror;                  /* 1: ball n-j mirrors ball j, balls 0..n/2 solved */
    acbb_ball_state ball[ACBB_MAX_BALLS];
} acbb_mech_state;

/* Which balls are solved and whom they stand for (MODEL.md section 3: the
 * ring moves only in x, z and tilts about y, so with no Fy and no Mz ball
 * states are even in psi; pure thrust makes them all equal). Balls
 * 0..acbb_mech_distinct()-1 are solved; ball j carries acbb_mech_weight()
 * balls in the ring and loss sums; acbb_mech_source(j) is the solved ball
 * that ball j copies. */
static inline int acbb_mech_distinct(const acbb_mech_state *st)
{
    return st->symmetric ? 1 : st->mirror ? st->n / 2 + 1 : st->n;
}

static inline double acbb_mech_weight(const acbb_mech_state *st, int j)
{
    if (st->symmetric) return st->n;
    return st->mirror && j > 0 && 2 * j != st->n ? 2.0 : 1.0;
}

static inline int acbb_mech_source(const acbb_mech_state *st, int j)
{
    return st->symmetric ? 0 : st->mirror && j >= acbb_mech_distinct(st) ? st->n - j : j;
}

/* Copy every solved ball onto the balls it stands for (azimuth kept). */
static inline void acbb_mech_spread(acbb_mech_state *st)
{
    for (int j = acbb_mech_distinct(st); j < st->n; j++) {
        double psi = st->ball[j].psi;
        st->ball[j] = st->ball[acbb_mech_source(st, j)];
        st->ball[j].psi = psi;
    }
}

typedef struct acbb_mech acbb_mech;

acbb_status acbb_mech_new(const acbb_scene *s, acbb_mech **out, acbb_error *err);
/* m made anew for scene s, as acbb_mech_new makes one, but in m's own
 * solver workspaces (GSL's solvers are set afresh by every solve): a
 * batch worker's runs reuse one (issue 30: 60 k instructions a run). On
 * failure m is still m's to free. */
acbb_status acbb_mech_renew(const acbb_scene *s, acbb_mech *m, acbb_error *err);
void acbb_mech_free(acbb_mech *m);
const acbb_geometry *acbb_mech_geometry(const acbb_mech *m);

/* A copy of m without its solver workspaces (NULL; acbb_mech_free frees
 * it): what m was built with and has learnt (Jacobians, predictors), to
 * compare with another workspace or to hand on (acbb_mech_adopt). NULL
 * when out of memory. */
acbb_mech *acbb_mech_keep(const acbb_mech *m);
/* 1 when a and b hold the same bits but for their solver workspaces: a
 * solve from the same state then computes the same (every input of the
 * mechanics is in the workspace; no scene is read after acbb_mech_new). */
int acbb_mech_same(const acbb_mech *a, const acbb_mech *b);
/* dst takes all of src (a kept copy) but its own solver workspaces: it
 * continues as src's workspace would (GSL's solvers are set afresh by
 * every solve). */
void acbb_mech_adopt(acbb_mech *dst, const acbb_mech *src);

/* Initial state: static thrust solution at zero speed and no expansion
 * (MODEL.md section 3 "Initial guesses"). */
acbb_status acbb_mech_init_state(acbb_mech *m, acbb_mech_state *st, acbb_error *err);

/* Make st, e.g. a converged state of another workspace with other loads
 * (the stiffness probes of stiffness.c), a warm start for m: m's ball
 * symmetry (a pure-thrust state is spread over the ring) and ring
 * freedoms (those m does not have are zeroed). */
void acbb_mech_adopt_state(const acbb_mech *m, acbb_mech_state *st);

/* Solve the equilibrium at speed omega_i with expansions e (NULL = none),
 * warm-started from and written to st. On failure st keeps its input. */
acbb_status acbb_mech_solve(acbb_mech *m, double omega_i, const acbb_expansion *e,
                            acbb_mech_state *st, acbb_error *err);

/* The loss/traction view of one contact of ball b at inner-ring speed
 * omega_i (inner != 0: inner race). */
void acbb_mech_contact_input(const acbb_geometry *g, const acbb_ball_state *b, int inner,
                             double omega_i, acbb_contact_in *c);

/* Where ball j's inner groove centre sits relative to its outer groove
 * centre (A1 axial, A2 radial) and the unloaded groove-to-ball-centre
 * lengths, thermal terms included, as in the last solve (for the dynamic
 * model, which moves the ball itself). */
typedef struct { double A1, A2, L0_i, L0_o; } acbb_ball_frame;
void acbb_mech_ball_frame(const acbb_mech *m, const acbb_mech_state *st, int j,
                          acbb_ball_frame *f);

/* What a ball's Level-2 speeds and contact losses depend on between two
 * thermal steps (MODEL.md sections 4 and 6): both loads, both contact
 * angles, both inlet viscosities and the four ball speeds (Level 2's when
 * traction_valid, else race control's) as fractions of omega_i. The speed
 * and the geometry are fixed within a run but for the small thermal
 * expansion, which acts through the loads and angles. A solver may keep a
 * ball's last results while these barely move (acbb_ball_moved). */
#define ACBB_BALL_INPUTS 10
void acbb_ball_inputs(const acbb_ball_state *b, double eta0_i, double eta0_o, double omega_i,
                      double in[ACBB_BALL_INPUTS]);

/* Largest weighted move from inputs `from` to `to`: relative for the loads
 * and viscosities, in radians for the angles, in units of omega_i for the
 * speeds, each times weight[k] (NULL: all 1, as the Level-2 skip). */
double acbb_ball_moved(const double from[ACBB_BALL_INPUTS], const double to[ACBB_BALL_INPUTS],
                       const double *weight);

/* The weights for a ball's contact losses (MODEL.md section 6): the slip of
 * a nearly rolling contact is a small difference of ball and race surface
 * speeds, so its losses move ~100 times faster with the ball speeds and ~3
 * times faster with the contact angles than with the loads (measured in
 * tests/test_losses.c). */
extern const double acbb_ball_loss_weights[ACBB_BALL_INPUTS];

/* Probes of another load case between a run's steps (a bearing set's
 * lift-off while it runs, sim_set_probe.c): on keeps the last ball
 * Jacobians that the run's transient chord steps reuse, off puts them
 * back, so the run's own numbers do not depend on the probes. */
void acbb_mech_probing(acbb_mech *m, int on);

/* Copy a state (header and the n balls in use). */
void acbb_mech_state_copy(acbb_mech_state *dst, const acbb_mech_state *src);

/* Inside transient thermal steps: each ball keeps its Hertz constants
 * while its contact angles moved less than angle_tol (rad) since they were
 * computed (Kc moves ~0.06 per rad, MODEL.md section 3), and a solve ends
 * when no constant changed. 0 (the default) refreshes them whenever an
 * angle moved 1e-11 rad, as the set-up, the steady polish and every
 * independent solve (stiffness) must. */
void acbb_mech_set_transient(acbb_mech *m, double angle_tol);

/* 1: a ring solve with the axial displacement held tries Broyden from
 * the last ring Jacobian first, as a free one does; 0 (default): GSL's
 * hybrid at once, whose noise the 0.3 nm axial-stiffness difference and
 * the displacement preload's runs were measured with. For the radial
 * and tilt stiffness probes (a 1 % load nudge; issue 30 lever 2). */
void acbb_mech_broyden_held(acbb_mech *m, int on);

/* The relative tolerance of the next solves (fidelity.mech_tol when
 * made: MODEL.md section 3); returns the previous one. For a probe that
 * resolves a difference finer than the run's solves (stiffness.c). */
double acbb_mech_set_tol(acbb_mech *m, double tol);

/* New applied loads (N, N, N m) for the next solves, the unknowns kept:
 * for loads whose radial load and moment are nonzero as the built ones
 * were (a stiffness probe's other end); its Jacobians stay. */
void acbb_mech_set_loads(acbb_mech *m, double Fx, double Fz, double My);

/* Fix the axial displacement (displacement-controlled preload) or free it. */
void acbb_mech_fix_axial(acbb_mech *m, int fixed, double dx);

/* Hold every ring DOF (a bearing of a set, MODEL.md 14): the next solves
 * return the reactions Fx, Fz, My of the ball solutions at inner-ring
 * displacement dx, dz (m) and tilt thy (rad). A ring whose balls all
 * unload is not an error here (the set names it): the reactions are 0. */
void acbb_mech_prescribe(acbb_mech *m, double dx, double dz, double thy);

/* Hold the ring's radial displacement at dz (m), the other DOFs as the
 * scene says: the radial-held tilt stiffness (stiffness.h). */
void acbb_mech_hold_radial(acbb_mech *m, double dz);

/* Hold the ring's tilt at thy (rad) and solve its radial offset (even
 * under no radial load), the axial DOF as the scene says: the radial
 * stiffness at the operating tilt (stiffness.h). */
void acbb_mech_hold_tilt(acbb_mech *m, double thy);

/* Combined inner-outer stiffness K_n and the static closed-form angle for
 * a pure thrust Fx at zero speed (independent reference used by tests and
 * for the initial guess): solves Fx = Z K_n A0^1.5 (cos a0/cos a - 1)^1.5 sin a. */
double acbb_static_thrust_angle(double Fx, int Z, double Kn, double A0, double alpha0);

#endif
