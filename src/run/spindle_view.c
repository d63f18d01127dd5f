/* acbb — a spindle's snapshot (spindle.h): the front set's snapshot (its
 * bearing 0 with the set's view, as a set scene's) with the run's state,
 * the whole network's heat flows and the spindle's view
 * (include/acbb/spindle.h). Every value through acbb_snap_fin: no NaN/Inf. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "spindle_priv.h"
#include "sim_struct.h"
#include "sim_priv.h"

#define DEG (180.0 / M_PI)

static int opposed(const acbb_set_mech *sm)
{
    int plus = 0, minus = 0;
    for (int k = 0; k < sm->n; k++) {
        plus |= sm->orient[k] > 0;
        minus |= sm->orient[k] < 0;
    }
    return plus && minus;
}

/* Set k's preload (docs/spindle.md "Preload"): the axial force between
 * its rings with no thrust at the nose. An opposed set's is its own (the
 * set at zero thrust of its own, sim_set_probe.c), whatever the other set
 * carries, as a set scene reports it. A one-way set (single, tandem) has
 * none of its own: the other set (an "O" pair of fixed sets), the rear
 * spring or the sleeve's friction preloads it through the shaft, and its
 * preload is the thrust it carries then, along the way its bearings face.
 * A spring rear carries its spring and a floating one what its sleeve
 * holds whatever the nose thrust (the located front set takes that): the
 * thrust they carry now. With a fixed rear both sets share the nose
 * thrust: under one the shaft is solved again without it (a steady
 * solve's iterates wait for the converged state, as a set's own preload
 * does; a failed probe keeps the last value). */
void acbb_spindle_preloads(acbb_spindle_sim *sp)
{
    double Fa[2] = { sp->st[ACBB_FRONT].load[0], sp->st[ACBB_REAR].load[0] };
    int own[2], probe = 0;
    for (int k = 0; k < 2; k++) own[k] = opposed(&sp->st[k].ss->sm);
    int shared = sp->s.spindle_rear_support == ACBB_REAR_FIXED && (!own[0] || !own[1])
                 && sp->s.axial_load != 0.0;
    int steady_iterate = sp->s.thermal_mode == ACBB_THERMAL_STEADY && sp->run.iter > 0
                         && sp->run.state == ACBB_RUN_RUNNING; /* no state passed through */
    if (shared) probe = !steady_iterate && acbb_spindle_zero_thrust(sp, Fa) == ACBB_OK ? 1 : -1;
    for (int k = 0; k < 2; k++) {
        const acbb_set_sim *ss = sp->st[k].ss;
        if (own[k]) sp->preload[k] = ss->preload;
        else if (probe >= 0) sp->preload[k] = ss->sm.orient[0] * Fa[k];
    }
}

/* Bearing b's most loaded ball: its contact angles (deg) and load (N). */
static void most_loaded(const acbb_mech_state *ms, double *ai, double *ao, double *Q)
{
    int jm = 0;
    for (int j = 1; j < ms->n; j++)
        if (ms->ball[j].Qi > ms->ball[jm].Qi) jm = j;
    *ai = acbb_snap_fin(ms->ball[jm].alpha_i * DEG);
    *ao = acbb_snap_fin(ms->ball[jm].alpha_o * DEG);
    *Q = 0.0;
    for (int j = 0; j < ms->n; j++) *Q = fmax(*Q, fmax(ms->ball[j].Qi, ms->ball[j].Qo));
    *Q = acbb_snap_fin(*Q);
}

static void set_view(const acbb_spindle_sim *sp, int k, acbb_spindle_set_view *v)
{
    const acbb_spindle_station *t = &sp->st[k];
    const acbb_set_sim *ss = t->ss;
    v->x = k == ACBB_FRONT ? sp->s.spindle_front_x : sp->s.spindle_rear_x;
    v->n_bearings = ss->n;
    v->preload_N = acbb_snap_fin(sp->preload[k]);
    v->axial_N = acbb_snap_fin(t->load[0]);
    v->radial_N = acbb_snap_fin(t->load[1]);
    v->moment_Nm = acbb_snap_fin(t->load[2]);
    v->loss_W = acbb_snap_fin(ss->total);
    v->T_inner_C = v->T_outer_C = v->T_ball_C = -INFINITY;
    v->contact_lost = 0;
    for (int b = 0; b < ss->n; b++) {
        const acbb_sim *m = ss->b[b];
        acbb_part_temps p;
        acbb_network_part_temps(&m->nw, m->T, &p);
        v->T_inner_C = fmax(v->T_inner_C, p.inner_ring);
        v->T_outer_C = fmax(v->T_outer_C, m->T[m->nw.node_outer_ring]);
        v->T_ball_C = fmax(v->T_ball_C, p.ball);
        most_loaded(&m->ms, &v->contact_angle_inner_deg[b], &v->contact_angle_outer_deg[b],
                    &v->Q_max_N[b]);
        v->contact_lost |= ss->sm.lost[b];
    }
    v->T_inner_C = acbb_snap_fin(v->T_inner_C);
    v->T_outer_C = acbb_snap_fin(v->T_outer_C);
    v->T_ball_C = acbb_snap_fin(v->T_ball_C);
}

void acbb_spindle_view_fill(const acbb_spindle_sim *sp, acbb_spindle_view *v)
{
    memset(v, 0, sizeof *v);
    v->n_sets = ACBB_SPINDLE_SETS;
    for (int k = 0; k < 2; k++) set_view(sp, k, &v->sets[k]);
    const acbb_shaft_result *r = &sp->res;
    v->nose_u = acbb_snap_fin(r->nose[0]);
    v->nose_w = acbb_snap_fin(r->nose[1]);
    v->nose_theta = acbb_snap_fin(r->nose[2]);
    v->nose_k_axial = acbb_snap_fin(r->k_axial);
    v->nose_k_radial = acbb_snap_fin(r->k_radial);
    v->nose_k_tilt = acbb_snap_fin(r->k_tilt);
    /* heat and growth: the network's (no heat flows with heating off) */
    if (sp->s.heating) acbb_spindle_net_view(sp->net, sp->T, v);
    else v->T_coolant_in_C = v->T_coolant_out_C = sp->s.ambient_C + sp->s.coolant_inlet_dT;
    v->rear_shift = sp->shift;
    /* The nose's move against the housing: the shaft's growth in front of
     * the located front set plus the elastic move since the cold first
     * state (the sets' contacts stiffening or easing, the shaft's own
     * compression), in the drift's sign (+ towards the nose: -x). */
    v->nose_drift_thermal = v->nose_drift_axial;
    v->nose_u_cold = sp->nose_u_cold;
    v->nose_drift_axial = v->nose_drift_thermal - (r->nose[0] - sp->nose_u_cold);
    double *f[] = { &v->nose_drift_axial, &v->nose_drift_radial, &v->Q_motor_W, &v->Q_bearings_W,
                    &v->Q_coolant_W, &v->Q_air_W, &v->T_coolant_in_C, &v->T_coolant_out_C,
                    &v->rear_shift, &v->nose_drift_thermal, &v->nose_u_cold };
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) *f[i] = acbb_snap_fin(*f[i]);
    for (int i = 0; i < v->n_shaft; i++) v->shaft_T_C[i] = acbb_snap_fin(v->shaft_T_C[i]);
    for (int i = 0; i < v->n_housing; i++) v->housing_T_C[i] = acbb_snap_fin(v->housing_T_C[i]);
}

/* The run's outcome over the front set's snapshot; a lost contact named
 * with its set. */
static void run_fields(const acbb_spindle_sim *sp, acbb_snapshot *o)
{
    o->state = sp->run.state;
    o->status = sp->run.status;
    snprintf(o->message, sizeof o->message, "%s", sp->run.msg);
    o->iteration = sp->run.iter;
    o->time = sp->run.time;
    o->dt = sp->run.dt;
    o->residual = acbb_snap_fin(sp->run.residual);
    o->wall_ms = sp->run.wall_ms;
    o->heat_in = acbb_snap_fin(sp->heat_all); /* the motor's too (0 with heating off) */
    o->heat_out = acbb_snap_fin(sp->heat_out);
    if (o->state == ACBB_RUN_FAILED) return;
    size_t len = strlen(o->message);
    for (int k = 0; k < 2; k++)
        for (int b = 0; b < sp->st[k].ss->n && len < sizeof o->message; b++)
            if (sp->st[k].ss->sm.lost[b])
                len += (size_t)snprintf(o->message + len, sizeof o->message - len,
                                        "; %s set bearing %d: contact_lost (lifted off)",
                                        k ? "rear" : "front", b);
}

void acbb_spindle_sim_snapshot(const acbb_spindle_sim *sp, acbb_snapshot *o)
{
    acbb_set_sim_snapshot(sp->st[ACBB_FRONT].ss, o);
    o->work.mechanics_solves += sp->st[ACBB_REAR].ss->sm.solves + sp->probe_solves;
    run_fields(sp, o);
    acbb_spindle_view_fill(sp, &o->spindle);
}

acbb_status acbb_spindle_sim_bearing_snapshot(const acbb_spindle_sim *sp, int k,
                                              acbb_snapshot *o)
{
    const acbb_set_sim *front = sp->st[ACBB_FRONT].ss;
    acbb_status rc = k < front->n ? acbb_set_sim_bearing_snapshot(front, k, o)
                                  : acbb_set_sim_bearing_snapshot(sp->st[ACBB_REAR].ss,
                                                                  k - front->n, o);
    if (rc != ACBB_OK) return rc;
    acbb_spindle_view_fill(sp, &o->spindle);
    return ACBB_OK;
}
