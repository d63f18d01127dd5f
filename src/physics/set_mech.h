/* acbb — the mechanics of a bearing set (MODEL.md section 14): the shaft's
 * rigid-body displacement that balances the external loads against every
 * bearing's reaction, each from its own ball solution (mechanics.h in the
 * prescribed-displacement mode) at its own expansions.
 *
 * Frames: global x along the shaft, bearing k at x[k] from the set's
 * centre; bearing k's own frame (MODEL.md 3) is the global one mirrored
 * when orient[k] = -1. Shaft unknowns q = (dx, dz, tilt about y, floating
 * offset): bearing k sees dx_k = s_k (dx + u_k) + e_k (+ the floating
 * offset on the spring side), dz_k = dz - tilt x_k, tilt_k = s_k tilt
 * (a right-handed rotation about y moves a point at x by -tilt x in z, as
 * MODEL.md 3's A1 term does at the ring). MODEL.md 14 writes the tilt with
 * the opposite sign; only the name of the angle differs.
 * dy and the tilt about z stay 0, and that is exact, not an approximation,
 * for every scene acbb accepts: the scene has no load in y and no moment
 * about z (no such key), the ball azimuths 2 pi j / Z mirror about the x-z
 * plane (ball Z-j sees what ball j sees when dy = tilt_z = 0), and a
 * bearing's reaction (MODEL.md 3, 4) has no azimuthal force (the contact
 * friction acts in each ball's plane), so every bearing's Fy and Mz vanish
 * at dy = tilt_z = 0 (mechanics.c sets them exactly) and those two
 * equations hold there. A y load or a moment about z would need both
 * unknowns (acbb_mech_prescribe takes dx, dz, tilt only); tests/test_set.sh
 * checks the balls' y sums are 0 to round-off under radial load + moment.
 *
 * Ownership: a caller-owned plain value; the members (mechanics
 * workspaces and states) belong to the caller. */
#ifndef ACBB_SET_MECH_H
#define ACBB_SET_MECH_H

#include "acbb/limits.h"
#include "acbb/scene.h"
#include "acbb/status.h"
#include "mechanics.h"
#include "expansion.h"

#define ACBB_SET_Q 4

typedef struct {
    acbb_mech *m;                 /* in prescribed mode (acbb_mech_prescribe) */
    acbb_mech_state *st;          /* warm start in, solution out */
    const acbb_expansion *e;      /* this bearing's expansions, NULL = none */
} acbb_set_member;

/* The first evaluations of a solve that starts without a Jacobian (its
 * start and the forward differences of acbb_fd_jacobian: J_n + 1 sets of
 * member solves) and the members' states after them. Member reactions
 * depend on the shaft position, the members' start states, expansions and
 * speed, not on the external loads (a member's workspace carries nothing
 * from solve to solve that moves them: its chord Jacobians serve only a
 * single bearing's transient solves, acbb_mech_set_transient), so a later
 * solve from the same position, start states, expansions and speed under
 * other loads (the nose-stiffness probes, sim_set_probe.c) replays them:
 * the residuals, Jacobian and states are the bits its own solves would
 * give (issue 30). */
typedef struct {
    int state;                    /* 0 empty, 1 recording, 2 recorded */
    int n_ev, mask;               /* evaluations kept and the active unknowns' mask */
    double q[ACBB_SET_Q + 1][ACBB_SET_Q];
    double Fx[ACBB_SET_Q + 1][ACBB_MAX_SET], Fz[ACBB_SET_Q + 1][ACBB_MAX_SET];
    double My[ACBB_SET_Q + 1][ACBB_MAX_SET];
    int lost[ACBB_SET_Q + 1][ACBB_MAX_SET];
    acbb_mech_state *ms[ACBB_MAX_SET]; /* the caller's storage: the members after them */
} acbb_set_mech_memo;

typedef struct {
    int n;
    int orient[ACBB_MAX_SET];     /* s_k */
    double x[ACBB_MAX_SET];       /* centres from the set's centre, m */
    double x_nose;                /* where the external loads act, m */
    int spring;                   /* spring preload: the -1 side floats */
    double Fp;                    /* assembly preload or spring force, N */
    int across;                   /* a one-way set preloaded by Fp against another
                                     set across the shaft (scene set_mirrored) */
    double e[ACBB_MAX_SET];       /* axial offsets built in (own frame, + squeezes), m */
    double u[ACBB_MAX_SET];       /* thermal axial move of IR k against OR k (global), m */
    double Fa, Fr, M;             /* external thrust, radial force (N), moment about y (N m) */
    double tol;                   /* relative force tolerance */
    double q[ACBB_SET_Q];         /* shaft dx, dz (m), tilt (rad), floating offset (m) */
    double J[ACBB_SET_Q * ACBB_SET_Q];
    int J_ok, J_n, J_mask;        /* the kept Jacobian's unknowns (count, bit mask) */
    int hold[ACBB_SET_Q];         /* 1: unknown i held at q[i] (a spindle's station,
                                     spindle_mech.c); all 0 from init: every one free */
    double Fx[ACBB_MAX_SET], Fz[ACBB_MAX_SET], My[ACBB_MAX_SET]; /* own-frame reactions */
    int lost[ACBB_MAX_SET];       /* 1: every ball of bearing k unloaded */
    long solves;                  /* member mechanics solves done (a replay's not) */
    acbb_set_mech_memo *memo;     /* NULL (init), or record/replay the first evaluations */
} acbb_set_mech;

/* Layout, loads and preload mode from the scene; offsets e zero. */
void acbb_set_mech_init(acbb_set_mech *sm, const acbb_scene *s);

/* Rigid preload at assembly (MODEL.md 14): e_k = the axial displacement
 * one bearing takes under Fp / (bearings on its side), at rest, 20 C, no
 * expansion, so identical bearings each carry exactly their share (a
 * one-way set: 0, or with `across` Fp / n against the other set). dx1(F)
 * is that displacement for one bearing under thrust F (m). */
void acbb_set_mech_assemble(acbb_set_mech *sm, double (*dx1)(double F, void *ctx), void *ctx);

/* Solve the shaft equilibrium at inner-ring speed omega, warm-started from
 * sm->q and the members' states. On failure the members keep their last
 * trial; the caller restores them. */
acbb_status acbb_set_mech_solve(acbb_set_mech *sm, acbb_set_member *mb, double omega,
                                acbb_error *err);

/* The external loads that balance the members' last evaluation (the
 * residual's terms): thrust (N, a tandem spring's own force taken out),
 * radial force (N) and moment about y at the set's centre (N m). With
 * unknowns held (hold[]), the loads a held shaft position needs. */
void acbb_set_mech_loads(const acbb_set_mech *sm, double L[3]);

/* The axial force the set carries between its sides (the + side's sum). */
double acbb_set_mech_preload(const acbb_set_mech *sm);

#endif
