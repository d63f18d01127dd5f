/* acbb — a bearing set's snapshots (MODEL.md 14, sim.h acbb_set_view):
 * bearing k's own full snapshot with the set's view beside it; the run's
 * snapshot is bearing 0's with the whole network's energy balance. */
#include <stdio.h>
#include <string.h>
#include "sim_set_priv.h"
#include "sim_struct.h"
#include "sim_priv.h"

static void set_view(const acbb_set_sim *ss, acbb_set_view *v)
{
    const acbb_set_mech *sm = &ss->sm;
    v->preload_N = acbb_snap_fin(ss->preload);
    v->preload_assembly_N = ss->s.preload_force;
    v->liftoff_thrust_N = acbb_snap_fin(ss->liftoff);
    v->liftoff_remainder_N = acbb_snap_fin(ss->lift_rest);
    v->stiffness_axial = acbb_snap_fin(ss->K_ax);
    v->stiffness_radial = acbb_snap_fin(ss->K_rad);
    v->stiffness_tilt = acbb_snap_fin(ss->K_tilt);
    v->shaft_dx = acbb_snap_fin(sm->q[0]);
    v->shaft_dz = acbb_snap_fin(sm->q[1]);
    v->shaft_tilt = acbb_snap_fin(sm->q[2]);
    v->spacer_growth = acbb_snap_fin(ss->spacer);
    for (int k = 0; k < ss->n; k++) {
        acbb_part_temps p;
        acbb_network_part_temps(&ss->b[k]->nw, ss->b[k]->T, &p);
        v->orientation[k] = sm->orient[k];
        v->axial_force[k] = acbb_snap_fin(sm->Fx[k]);
        v->contact_lost[k] = sm->lost[k];
        v->T_outer_ring[k] = acbb_snap_fin(ss->b[k]->T[ss->b[k]->nw.node_outer_ring]);
        v->T_inner_ring[k] = acbb_snap_fin(p.inner_ring);
        v->loss_total[k] = acbb_snap_fin(ss->b[k]->loss.total);
    }
}

acbb_status acbb_set_sim_bearing_snapshot(const acbb_set_sim *ss, int k, acbb_snapshot *o)
{
    if (k < 0 || k >= ss->n) return ACBB_EINVAL;
    acbb_sim_snapshot(ss->b[k], o);
    o->n_bearings = ss->n;
    set_view(ss, &o->set);
    return ACBB_OK;
}

void acbb_set_sim_snapshot(const acbb_set_sim *ss, acbb_snapshot *o)
{
    acbb_set_sim_bearing_snapshot(ss, 0, o);
    o->work.mechanics_solves += ss->sm.solves; /* the shaft equilibrium's member solves */
    o->heat_in = acbb_snap_fin(ss->heat_in);
    o->heat_out = acbb_snap_fin(ss->heat_out);
    int lost = 0;
    for (int k = 0; k < ss->n; k++) lost |= ss->sm.lost[k];
    if (lost && o->state != ACBB_RUN_FAILED) {
        size_t len = strlen(o->message);
        for (int k = 0; k < ss->n && len < sizeof o->message; k++)
            if (ss->sm.lost[k])
                len += (size_t)snprintf(o->message + len, sizeof o->message - len,
                                        "; bearing %d: contact_lost (lifted off)", k);
    }
}
