/* acbb — the Sim's state, shared by the bearing (sim.c) and the
 * evaluation of one state (sim_eval.c); internal, not part of the public
 * API (acbb/sim.h keeps acbb_sim opaque). */
#ifndef ACBB_SIM_STRUCT_H
#define ACBB_SIM_STRUCT_H

#include <stdatomic.h>
#include "acbb/sim.h"
#include "mechanics.h"
#include "network.h"
#include "losses.h"
#include "expansion.h"
#include "quasi_dynamic.h"
#include "dynamic.h"
#include "stiffness.h"
#include "sim_set.h"
#include "spindle.h"
#include "steady_polish.h"
#include "life_static.h"
#include "stepper.h"
#include "sim_priv.h"

#define QD_PASSES 4            /* mechanics <-> Level-2 passes when converging a state */
#define QD_TOL 1e-9            /* relative change of omega_m that ends the passes */
#define QD_SKIP_TOL 3e-3       /* transient steps: Level-2 update skipped below this input move */
#define HERTZ_SKIP_TOL 1e-3    /* rad, transient steps: Hertz constants kept (Kc moves < 6e-5) */
#define LOSS_SKIP_TOL 3e-4     /* transient steps: a ball's loss quadrature kept below this move */
#define POLISH_SKIP_TOL ACBB_POLISH_REUSE_TOL /* steady polish: the same reuse (1e-9) */
#define DYN_WINDOW_COLD 4e-3   /* s of ball motion from the race-control start */
#define DYN_WINDOW_WARM 1e-3   /* s of ball motion per pass once warm */
#define DYN_SKIP_TOL 1e-2      /* transient steps: settled balls keep speeds below this input move */
#define DYN_THREADS 2          /* workers over the distinct balls (the answer does not depend on it) */

typedef struct {
    acbb_contact_loss in, out;
    double ref[ACBB_BALL_INPUTS]; /* the ball's inputs when in, out were computed */
    int ref_ok;
} ball_loss;

/* Everything a step changes, kept so a failed or rejected step can put the
 * last good state back exactly (not re-derived). */
typedef struct {
    acbb_mech_state ms;
    double T[ACBB_MAX_NODES];
    acbb_expansion exp;
    ball_loss bl[ACBB_MAX_BALLS];
    acbb_losses loss;
    acbb_heat_sources heat;
    double q[ACBB_MAX_NODES];
} checkpoint;

struct acbb_sim {
    acbb_scene resolved;       /* the scene as given, resolved once (acbb_sim_scene) */
    acbb_scene s;              /* `resolved` at the run's operating point */
    acbb_mech *mech;
    acbb_qd *qd;               /* quasi-dynamic workspace (NULL below that level) */
    acbb_qd *qd_idle;          /* a batch's spare Level-2 workspace while at another level */
    acbb_dyn *dyn;             /* dynamic workspace (dynamic level only) */
    acbb_mech_state ms;        /* last accepted mechanics */
    checkpoint *keep;          /* scratch for step rollback (owned) */
    checkpoint *best;          /* the steady polish's iterate of smallest residual (owned) */
    acbb_network nw;
    acbb_quad quad;
    double T[ACBB_MAX_NODES];  /* T^k */
    acbb_expansion exp;
    ball_loss bl[ACBB_MAX_BALLS];
    acbb_losses loss;
    acbb_heat_sources heat;
    double q[ACBB_MAX_NODES];
    double heat_out;
    acbb_stepper run;          /* the run as the stepper keeps it (stepper.h) */
    int transient_pass;        /* 1 while evaluating inside a transient step */
    int polishing;             /* 1 while evaluating inside the steady polish */
    int setting_up;            /* 1 while sim_init evaluates the first state */
    int no_first_state;        /* a steady set's member: the set evaluates its first state */
    double polish_relax;       /* the polish step's relaxation while it evaluates, else 1 */
    const atomic_int *cancel;  /* caller's flag (acbb_run_ctl); not owned */
    acbb_work work;            /* per-part work counters */
    double K_axial;            /* axial stiffness at the converged state, N/m */
    acbb_life_static life_basis; /* C0 of the scene (life_static.h), once per scene */
    acbb_stiffness K_ring;     /* radial and tilt stiffness at the converged state */
    int fixed_axial;           /* displacement preload: dx held at fixed_dx */
    int threads;               /* dynamic-level workers over the balls (acbb_sim_opts) */
    int skip_stiffness;        /* acbb_sim_opts.skip_stiffness */
    int skip_life;             /* acbb_sim_opts.skip_life */
    int skip_liftoff;          /* acbb_sim_opts.skip_liftoff (a set reads its members') */
    double fixed_dx;
    long reported;             /* last iteration handed to a drive hook; -1 none */
    acbb_set_sim *set;         /* a bearing set (sim_set.c, MODEL.md 14), else NULL */
    acbb_spindle_sim *spindle; /* a spindle (spindle.c, docs/spindle.md), else NULL */
    double bound_axial, bound_radial; /* loads sim->mech was built with (schedule) */
    double setup_ms;           /* computing time of the set-up (sim_init) */
    double deadline_ms;        /* fidelity.max_wall_s as a monotonic-clock deadline; 0 none */
    int keep_setup;            /* a transient keeps its set-up (acbb_simx_create_from) */
    int warm_started;          /* sim_init started from a warm state (acbb_warm) */
    int cleared_balls;         /* ms.ball and bl are zero below this (sim.c sim_alloc) */
    acbb_sim_setup *setup;     /* owned: the kept set-up, until acbb_simx_warm_save */
    const acbb_sim_setup *setup_from; /* the set-up taken (not owned), during sim_init only */
};

/* sim_first.c: the first state's mechanics and Level-2 passes of a
 * transient that took its set-up (setup_from) from a run that kept them,
 * when every input of those passes is the same bits: 1 if taken (sim's
 * state, mechanics and Level-2 workspaces as the passes would leave
 * them), 0 (nothing changed) if they are to be made. _keep: the passes
 * just made, into sim's own kept set-up. */
int acbb_simx_first_take(acbb_sim *sim, const acbb_oil_state *oi, const acbb_oil_state *oo,
                         const acbb_mixture *mix);
void acbb_simx_first_keep(acbb_sim *sim, const acbb_oil_state *oi, const acbb_oil_state *oo,
                          const acbb_mixture *mix);
void acbb_simx_first_free(acbb_sim_first *f);

/* sim_eval.c: one evaluation of the mechanical/tribological state at T^k
 * (expansions, mechanics, losses, network, heat sources); its inputs to
 * the network; every published value finite. */
acbb_status acbb_simx_evaluate(acbb_sim *sim, acbb_error *err);
void acbb_simx_network_inputs(const acbb_sim *sim, acbb_net_inputs *in);
int acbb_simx_outputs_finite(const acbb_sim *sim);
/* sim.c: the caller's cancel flag, then the wall-clock bound. */
acbb_status acbb_simx_stop_check(const acbb_sim *sim, acbb_error *err);
/* sim_plant.c: the bearing as a plant of the stepper (stepper.h); a view,
 * valid until the Sim is restarted. The heat flows of the state reached
 * into heat_out (0 with heating off: no network is solved). */
void acbb_simx_plant(acbb_sim *sim, acbb_plant *p);
void acbb_simx_energy(acbb_sim *sim);

/* A bearing of a set (sim_set.c drives it, MODEL.md 14). Its wall-clock
 * deadline (acbb_now_ms; 0 none): the set's, so that b's own inner loops
 * (its ball-speed passes, every right-hand side of the dynamic level) stop
 * at the set's fidelity.max_wall_s (issue 26 item 7). sim.c. */
void acbb_simx_deadline(acbb_sim *b, double deadline_ms);
/* The parts of acbb_simx_evaluate the set runs between its own shaft
 * solves (sim_eval.c): the expansions at b's temperatures; one Level-2 or
 * dynamic pass over b's balls (*change: the largest relative move); the
 * losses, network resistances and heat sources q. */
void acbb_simx_expand(acbb_sim *b);
acbb_status acbb_simx_traction(acbb_sim *b, double *change, acbb_error *err);
acbb_status acbb_simx_heat(acbb_sim *b, acbb_error *err);

#endif
