/* acbb — what the parts of a spindle share (private to src/run/spindle*.c):
 * the plant and its set-up (spindle.c), the shaft with the sets as its
 * supports (spindle_mech.c), the snapshot's view (spindle_view.c).
 *
 * Frames (docs/spindle.md): x from the nose towards the rear; the shaft's
 * station displacement d = (u, w, theta), theta positive for w growing
 * with x. A set's own frame (set_mech.h) has its x along the shaft's and
 * its centre at the station: its shaft position q = (u + shift, w,
 * -theta) (set_mech.h's tilt turns the other way; shift, the shaft's
 * thermal growth minus the housing's between the front set and this one,
 * moves its inner rings against its outer rings as u does: 0 at the
 * located front set), and the loads the
 * shaft puts on the set (Fa, Fr, M about y at its centre) are
 * (-f_u, -f_w, +f_theta) of the reaction f the set exerts on the shaft. */
#ifndef ACBB_SPINDLE_PRIV_H
#define ACBB_SPINDLE_PRIV_H

#include "spindle.h"
#include "sim_set_priv.h"
#include "shaft_beam.h"
#include "spindle_net.h"
#include "stepper.h"

#define ACBB_SPINDLE_NMAX ACBB_STEPPER_NMAX
enum { ACBB_FRONT, ACBB_REAR };

typedef struct acbb_spindle_station acbb_spindle_station;
struct acbb_spindle_station {
    acbb_spindle_sim *sp;
    int k;                        /* ACBB_FRONT or ACBB_REAR */
    acbb_set_sim *ss;
    int axial_held;               /* 1: the station's axial position prescribed (located) */
    double Fa_given;              /* else the axial load the set carries, N */
    acbb_set_mech w;              /* the support's copy of the set's mechanics */
    double d[3];                  /* the station's displacement of the last reaction */
    double slip;                  /* floating: how far its outer rings slid in the sleeve
                                     (+x, m), in the last evaluation */
    double slip_rest;             /* the same in the state last kept or restored: where
                                     every evaluation's sleeve starts */
    int slide, slide_rest;        /* floating: the way it slides (the sign of the thrust
                                     it carries; 0 stuck), now and in that state */
    double load[3];               /* the last evaluation's loads on the set (its frame) */
    double K[9];                  /* the support's last tangent -df/dd (u, w, theta rows) */
    double landing;               /* the set's own solve minus the shaft's station: m, m, rad (max) */
};

/* One of the stepper's checkpoints (stepper.h: ACBB_KEEP_LAST, ACBB_KEEP_BEST),
 * each its own: the network's temperatures, the shaft's solution and the
 * rear sleeve's slip of the state saved there. */
typedef struct {
    double T[ACBB_SPINDLE_NMAX];
    acbb_shaft_result res;
    double slip;
    int slide;
} acbb_spindle_keep;

struct acbb_spindle_sim {
    acbb_scene s;                 /* resolved, at the run's operating point */
    int one_support;
    acbb_spindle_station st[2];
    int off[2], n;                /* set k's nodes start at off[k] of T */
    double T[ACBB_SPINDLE_NMAX], q[ACBB_SPINDLE_NMAX];
    acbb_spindle_keep keep[2];    /* by slot */
    acbb_spindle_net *net;        /* the one network: both sets, shaft, housing, motor, coolant */
    acbb_shaft_beam *beam;
    double *beam_start;           /* the shaft's warm start kept across a probe (owned) */
    acbb_mech_state probe_ms[2][ACBB_MAX_SET]; /* the members' states kept across a probe */
    double preload[2];            /* each set's preload as the view reports it, N */
    acbb_shaft_result res;
    double shift;                 /* shaft minus housing axial growth between the sets, m */
    double h_d, h_theta;          /* the supports' difference steps, m and rad */
    long beam_solves, evaluations;
    long probe_solves;            /* the supports' member solves */
    acbb_stepper run;
    const atomic_int *cancel;
    double deadline_ms;
    double total;                 /* both sets' losses, W */
    double heat_in, heat_out;     /* the bearings' sources; what leaves the network, W */
    double heat_all;              /* every source, the motor's too, W */
    double nose_u_cold;           /* the nose's axial displacement in the first state
                                     (ambient, the first loads), m */
};

/* The spindle as the stepper's plant (spindle.c; tests call its save and
 * restore). */
void acbb_spindle_plant(acbb_spindle_sim *sp, acbb_plant *p);

/* spindle_mech.c: the shaft built from the scene (its supports the two
 * stations); the shaft solved with the sets as supports at the members'
 * current expansions, then each set's loads set to its station's
 * reaction. */
acbb_status acbb_spindle_beam_build(acbb_spindle_sim *sp, acbb_error *err);
acbb_status acbb_spindle_mechanics(acbb_spindle_sim *sp, acbb_error *err);
/* Each set's axial load (its frame) at zero nose thrust, the shaft solved
 * again with everything else as it is and then put back. */
acbb_status acbb_spindle_zero_thrust(acbb_spindle_sim *sp, double Fa[2]);
/* The loads on each set from the rigid shaft's statics (the first state). */
void acbb_spindle_initial_loads(const acbb_scene *s, int one_support, double L[2][3]);
/* spindle_view.c: each set's preload (sp->preload; a one-way set's may
 * probe the shaft at zero nose thrust), then the view from the state. */
void acbb_spindle_preloads(acbb_spindle_sim *sp);
void acbb_spindle_view_fill(const acbb_spindle_sim *sp, acbb_spindle_view *v);

#endif
