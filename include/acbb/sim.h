/* acbb — the coupled thermo-mechanical stepper (seed Fig. 5, MODEL.md 9).
 *
 * acbb_sim_step advances one thermal step: mechanics at the current
 * geometry, kinematics, film, the five losses, the implicit thermal update,
 * then the expansions for the next step. A client drives it (the CLI to
 * steady state, the TUI worker while publishing snapshots).
 *
 * Ownership: acbb_sim_create allocates a Sim that owns a copy of the Scene;
 * release it with acbb_sim_free. Snapshots are plain values the caller owns.
 * A Sim is not thread-safe: one thread drives it. */
#ifndef ACBB_SIM_H
#define ACBB_SIM_H

#include "acbb/cancel_flag.h"
#include "acbb/scene.h"
#include "acbb/status.h"
#include "acbb/limits.h"
#include "acbb/spindle.h"
#include "acbb/loss_kinds.h"
#include "acbb/life.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which stiffness probes of a converged state failed (issue 30: a failed
 * probe is reported as missing, never as a plausible number). */
enum { ACBB_STIFF_AXIAL = 1, ACBB_STIFF_RADIAL = 2, ACBB_STIFF_TILT = 4, ACBB_STIFF_TILT_HELD = 8 };

/* What a user sees of one ball. Sliding speeds are the pressure-weighted
 * mean magnitude of the translational (Heathcote + gross) slip over the
 * contact ellipse; spin is the ball-race relative angular speed about the
 * contact normal. */
typedef struct {
    double psi;                 /* azimuth, rad */
    double Qi, Qo;              /* contact loads, N */
    double alpha_i, alpha_o;    /* contact angles, rad */
    double slide_i, slide_o;    /* sliding speeds, m/s */
    double spin_i, spin_o;      /* spin speeds, rad/s */
    double film_i, film_o;      /* central film thickness, m */
    double pmax_i, pmax_o;      /* max Hertz pressure, Pa */
    double a_i, b_i, a_o, b_o;  /* contact semi-axes, m */
    double omega_m;             /* orbital speed, rad/s */
    double omega_x, omega_y, omega_z; /* ball angular velocity in the orbiting frame, rad/s */
    double hmin_i, hmin_o;      /* minimum film thickness, m */
    double loss;                /* this ball's contact losses (both contacts), W */
    double loss_kind[ACBB_LOSS_KINDS]; /* the same by kind (bearing-level kinds 0), W */
} acbb_ball_view;

/* Why thermal expansion squeezes or loosens the balls (MODEL.md 13): the
 * radial move of the inner groove centre and the ball growth along the
 * contact line, as radial groove-centre equivalents (CLEAN geometry). The
 * balls are squeezed (loads up, angles down) when net > 0. */
typedef struct {
    double inner_thermal;       /* + theta_i, m */
    double inner_centrifugal;   /* + theta_icen, m */
    double outer;               /* - theta_o, m */
    double ball;                /* + 2 theta_ba cos(alpha), alpha of ball 0, m */
    double net;                 /* sum, m */
} acbb_squeeze;

/* Work each part of the model did so far (a disabled effect does none). */
typedef struct {
    long mechanics_solves;      /* ball/ring equilibrium solves */
    long traction_solves;       /* Level-2 (quasi-dynamic) or dynamic ball-speed updates */
    long loss_quadratures;      /* contact-ellipse loss integrations */
    long network_solves;        /* thermal network updates and linear solves */
    long expansion_updates;     /* thermal/centrifugal expansion evaluations */
} acbb_work;

/* The losses, W, indexed by acbb_loss_kind (loss_kinds.h names them). */
typedef struct {
    double P[ACBB_LOSS_KINDS];
    double total;
    double inner, outer; /* contact heat to the inner / outer contact nodes */
} acbb_losses;

typedef enum { ACBB_RUN_RUNNING, ACBB_RUN_CONVERGED, ACBB_RUN_FAILED } acbb_run_state;

/* A bearing set's own results (MODEL.md 14; acbb/tools/set.h). Stiffness at the
 * nose: axial dFa/d(shaft dx), radial dFr/d(nose dz), tilt dM/d(tilt),
 * each with the other shaft freedoms free (0 until converged). Per-bearing
 * entries: axial load in the bearing's own frame, contact_lost = every
 * ball of that bearing unloaded (it lifted off). */
typedef struct {
    double preload_N;           /* axial force through the set with no external thrust, now */
    double preload_assembly_N;  /* mounting.preload_N */
    double liftoff_thrust_N;    /* external thrust at which the opposite side's rings stop
                                 * squeezing its balls (MODEL.md 14), updated while it runs */
    double liftoff_remainder_N; /* what that side still carries there: centrifugal, N */
    double stiffness_axial;     /* N/m */
    double stiffness_radial;    /* N/m */
    double stiffness_tilt;      /* N m/rad */
    double shaft_dx, shaft_dz, shaft_tilt; /* shaft displacement (m) and tilt (rad) at the centre */
    double spacer_growth;       /* inner minus outer axial growth between the end bearings, m */
    int orientation[ACBB_MAX_SET];
    double axial_force[ACBB_MAX_SET];   /* N */
    int contact_lost[ACBB_MAX_SET];
    double T_outer_ring[ACBB_MAX_SET];  /* C */
    double T_inner_ring[ACBB_MAX_SET];  /* C */
    double loss_total[ACBB_MAX_SET];    /* W */
} acbb_set_view;

typedef struct {
    acbb_run_state state;
    acbb_status status;         /* ACBB_OK while running or converged; named failure otherwise */
    char message[256];          /* why it stopped, if it did */
    long iteration;             /* coupled steps taken ("iteration step" of the seed) */
    double time;                /* simulated time, s */
    double dt;                  /* current thermal step, s */
    double residual;            /* max |dT/dt| of the last step, K/s */
    double wall_ms;             /* wall time spent in acbb_sim_step so far */
    int n_nodes;
    double T[ACBB_MAX_NODES];   /* node temperatures, C */
    const char *const *node_names; /* static strings, n_nodes of them */
    double T_outer_ring;        /* seed node 5, C */
    double T_inner_ring, T_ball, T_housing, T_shaft, T_cavity; /* C */
    acbb_losses losses;
    double exp_ball, exp_inner, exp_inner_cen, exp_outer; /* radial expansions, m */
    double delta_x, delta_z;    /* inner-ring displacement, m */
    double tilt_y;              /* inner-ring tilt about y, rad */
    double stiffness_axial;     /* dFx/d(delta_x) at the solution, N/m (0 until converged) */
    double stiffness_radial;    /* dFz/d(delta_z), N/m (stiffness.h; 0 until converged) */
    double stiffness_tilt;      /* dMy/d(theta_y), N m/rad (0 until converged) */
    double stiffness_tilt_held; /* the same with the ring held radially, N m/rad */
    unsigned stiffness_failed;  /* ACBB_STIFF_* bits: a probe whose solve failed
                                   (its value above is 0 and means nothing) */
    acbb_squeeze squeeze;
    acbb_work work;
    double reaction_x;          /* axial reaction (== load under force control), N */
    double heat_in, heat_out;   /* W: sources vs heat into fixed nodes (energy balance) */
    int n_balls;
    acbb_ball_view balls[ACBB_MAX_BALLS];
    /* A set (MODEL.md 14): the fields above describe bearing 0 (losses and
     * heat of the whole set in energy), acbb_sim_bearing_snapshot gives each
     * bearing's; n_bearings = 1 for a single bearing (set all zero). */
    int n_bearings;
    acbb_set_view set;
    acbb_life life;             /* rating life and static safety of this state (life_eval.h) */
    /* A spindle (docs/spindle.md): the fields above describe its front set;
     * spindle.n_sets = 0 for any other scene. */
    acbb_spindle_view spindle;
} acbb_snapshot;

typedef struct acbb_sim acbb_sim;

/* Release a Sim made by acbb_sim_create (NULL is a no-op). */
void acbb_sim_free(acbb_sim *sim);

/* Every check a run makes before its first step, and no step: the scene's
 * values and rules, then its compilation by acbb_sim_create (derived
 * lubricant values, the thermal network's geometry, an ill-posed first
 * equilibrium). `acbb check`, `acbb edit` and the TUI's save all use it,
 * so nothing is saved that `acbb run` then refuses (issue 26 item 9). */
acbb_status acbb_sim_check(const acbb_scene *s, acbb_error *err);

/* One coupled step. Returns ACBB_OK while running and at convergence
 * (check acbb_sim_state); a named failure otherwise, with the last good
 * state kept for the snapshot. Calling step after the run ended is a no-op
 * returning the final status. */
acbb_status acbb_sim_step(acbb_sim *sim);
acbb_run_state acbb_sim_state(const acbb_sim *sim);

/* Step until converged, failed, or the scene's max_steps / max_time. */
acbb_status acbb_sim_run(acbb_sim *sim);

/* The one run loop every client uses (REBOUND's heartbeat idea).
 * `hook` is called with the sim once for the initial state (iteration 0, on
 * the first drive of a sim) and after every step that advanced; it may read
 * the sim (acbb_sim_snapshot) and may sleep to pace the run. A nonzero
 * return pauses: acbb_sim_drive returns ACBB_OK with the run still going,
 * and another call resumes it. `cancel`, when set (nonzero), is honoured
 * between steps and inside long steps (dynamic ODE windows, Level-2 passes,
 * the steady polish): the run ends with ACBB_CANCELLED and the last good
 * state. Every field may be NULL. */
typedef int (*acbb_step_hook)(void *ctx, const acbb_sim *sim);
typedef struct {
    acbb_step_hook hook;
    void *ctx;
    const acbb_atomic_int *cancel;
} acbb_run_ctl;

/* Returns ACBB_OK while running (paused by the hook) or at convergence, a
 * named failure otherwise (the run's final status). */
acbb_status acbb_sim_drive(acbb_sim *sim, const acbb_run_ctl *ctl);

/* The constructor's options; all zero (or o == NULL) is the default.
 * `cancel` makes the set-up (initial mechanics: a dynamic-level window)
 * cancellable and stays attached to the sim for its later steps.
 * `threads` is the number of workers the dynamic level spreads a step's
 * distinct balls over (0: the default, 2); a pool that already keeps every
 * core busy with runs passes 1. The answer does not depend on it. */
typedef struct {
    const acbb_atomic_int *cancel;  /* not owned, may be NULL */
    int threads;
    /* 1: a caller that reads no stiffness skips the end-of-run stiffness
     * probes of a single bearing (a third of a steady run): the snapshot
     * then has stiffness_failed with every ACBB_STIFF_* bit and the values
     * 0; a set skips its members' and its nose probes (set view
     * stiffness 0). 0 (the default): computed, as `acbb run` reports them. */
    int skip_stiffness;
    /* 1: a caller that reads no rating life skips a single bearing's (its
     * static basis at the set-up and its evaluation in each snapshot): the
     * snapshot's `life` is then all zero. 0 (the default): computed. */
    int skip_life;
    /* 1: a caller that reads neither skips a bearing set's preload and
     * lift-off probes (shaft solves after every transient step and at the
     * end): the set view's preload_N and liftoff_N are then 0. */
    int skip_liftoff;
} acbb_sim_opts;
/* The one constructor: compile the scene (validated again) and set the
 * initial state: all temperatures at ambient, mechanics solved at
 * room-temperature geometry. Returns ACBB_EINVAL / ACBB_ILL_POSED with a
 * message for bad scenes, or a solver status if the initial mechanics
 * fails.
 * GSL's error handler: the engine checks GSL's statuses itself, so while
 * an acbb_sim_* call (create, restart, step, drive, run) works the
 * process-wide handler is off; when the call returns it is again what the
 * host had set (GSL's aborting default included). A host that sets its
 * handler on one thread while an engine call runs on another races with
 * it: set it before or between engine calls. */
acbb_status acbb_sim_create(const acbb_scene *s, const acbb_sim_opts *o, acbb_sim **out,
                            acbb_error *err);

/* The scene this Sim runs, resolved once by its constructor (or last
 * restart): acbb_scene_resolve (fidelity.h) of the scene given. Writers
 * echo it rather than resolving again. Valid while the Sim lives. */
const acbb_scene *acbb_sim_scene(const acbb_sim *sim);

/* Copy out what a user sees (never NaN/Inf: checked before publication). */
void acbb_sim_snapshot(const acbb_sim *sim, acbb_snapshot *out);

/* Bearing k's full single-bearing snapshot (k = 0 .. n_bearings - 1; for
 * a single bearing k = 0 is acbb_sim_snapshot). ACBB_EINVAL for another k. */
acbb_status acbb_sim_bearing_snapshot(const acbb_sim *sim, int k, acbb_snapshot *out);

/* Restart with an edited scene, keeping the current temperatures (warm)
 * or from ambient (warm == 0). The network kind must be unchanged for a
 * warm restart, else it falls back to ambient. */
acbb_status acbb_sim_restart(acbb_sim *sim, const acbb_scene *s, int warm, acbb_error *err);

/* JSON/CLI name of a finished run's status: "converged", "not_converged",
 * "runaway", "contact_lost", "diverged", "ill_posed", "nonfinite", ... */
const char *acbb_run_status_name(const acbb_snapshot *snap);

#ifdef __cplusplus
}
#endif

#endif
