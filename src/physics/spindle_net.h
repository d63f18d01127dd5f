/* acbb — one thermal network for a whole spindle (docs/spindle.md "Heat",
 * "Joining the bearings' networks"; internal header): the spindle's shaft,
 * housing, motor, coolant and air (shaft_thermal.h) with the front and the
 * rear bearing set's joined networks (network_set.h; a single bearing is a set
 * of one) in place of the bearing stations.
 *
 * Each member bearing joins the spindle's shaft cell and housing cell at
 * its own centre x: its fixed shaft-bore nodes and its housing's exterior
 * nodes become those cells (their edges now end in the cells, the bore's
 * film dropped), its housing films to the ambient go (the spindle housing
 * has its own), its bearing-side housing and shaft nodes keep their
 * conduction edges but not their capacity (that material is the spindle's,
 * counted once in its cells), and the set's shaft and housing joints
 * between neighbours give way to the spindle's chains. The oil-air
 * through-flow still goes to the ambient air, the end caps keep their
 * cooled faces. Node i of part p is node part_offset(p) + i, so the
 * bearing model's own node indices (network.h) still address it; the
 * nodes that became spindle cells are not unknowns any more and read the
 * cell's temperature after each solve.
 *
 * The coolant cells are fixed nodes of the symmetric acbb_tnet whose
 * temperatures come from the exact Schur complement of shaft_thermal.h
 * (the advection is not symmetric).
 *
 * Use (one thermal step of the engine):
 *     per member: acbb_network_update(mem, set_scene, &inputs);
 *     acbb_spindle_net_sync(sn, rel_tol);
 *     q[] = 0; per member: acbb_network_heat(mem, set_scene, &h, q + off + set->off[k]);
 *     acbb_spindle_net_solve(sn, q, dt, T, &err);        (T from acbb_spindle_net_init)
 *     acbb_network_part_temps(mem, acbb_spindle_net_member_T(sn, T, p, k), &parts);
 *     acbb_spindle_net_growth(sn, T, &growth); acbb_spindle_net_view(sn, T, &view);
 *
 * Ownership: acbb_spindle_net_build returns an object the caller frees
 * with acbb_spindle_net_free. It refers to the two parts' networks (not
 * owned: they and their members must outlive it) and copies what it needs
 * of the scene. Temperatures in C, x in m from the nose. */
#ifndef ACBB_SPINDLE_NET_H
#define ACBB_SPINDLE_NET_H

#include "acbb/limits.h"
#include "acbb/scene.h"
#include "acbb/spindle.h"
#include "acbb/status.h"
#include "network_set.h"

typedef struct acbb_spindle_net acbb_spindle_net;

/* The two parts, 0 = front set, 1 = rear set: each set's joined network,
 * the scene its members were built from (read during the build only: the
 * shaft bore's film) and its members' centres (member k of the set's
 * network at x[k], m from the nose; for a set of one, x[0] is its centre). */
typedef struct {
    acbb_network_set *set;
    const acbb_scene *scene;
    double x[ACBB_MAX_SET];
} acbb_spindle_net_part;

/* The thermal growth the mechanics needs, relative to the assembly
 * (ambient) temperature, m. */
typedef struct {
    /* shaft minus housing axial growth between the front and the rear set's
     * centres (+: the shaft's point at the rear set moves rearwards, +x,
     * against the housing's; what a rigid spacing between the sets feels) */
    double shift_axial;
    double radial_shaft[2];    /* shaft outer radius at each set's centre */
    double radial_housing[2];  /* housing bore radius at each set's centre */
    double nose_axial;         /* nose's growth away from the front set (forward) */
    double nose_radial;        /* shaft radius at the nose */
} acbb_spindle_growth;

/* Energy flows of the last solve, W. */
typedef struct {
    double Q_parts;            /* the parts' sources (q of the last solve) */
    double Q_motor;            /* rotor + stator */
    double Q_air;              /* into the air and the bearings' remaining fixed
                                * boundaries (end caps' cooled faces) */
    double Q_coolant_wall;     /* housing -> coolant through the jacket wall */
    double Q_advected;         /* m_dot c_p (T_out - T_in) */
    double storage_rate;       /* sum C dT/dt over the last step (0 after a steady solve) */
    double T_coolant_in, T_coolant_out;
} acbb_spindle_flows;

/* Build from the spindle scene s (shaft, housing, motor, coolant, ambient)
 * and the two parts (built from the sets' scenes, each member with
 * acbb_network_build). Every scene value is checked, with its unit and
 * range in err. */
acbb_status acbb_spindle_net_build(const acbb_scene *s, const acbb_spindle_net_part part[2],
                                   acbb_spindle_net **out, acbb_error *err);
void acbb_spindle_net_free(acbb_spindle_net *sn);

/* All nodes, the spindle's (cells, coolant, air) and both parts'. */
int acbb_spindle_net_nodes(const acbb_spindle_net *sn);
/* The spindle's own nodes (cells, coolant, air) are 0 .. own_nodes() - 1;
 * the parts' follow. */
int acbb_spindle_net_own_nodes(const acbb_spindle_net *sn);
/* What own node i is, for a message: "shaft cell at x = 180 mm",
 * "housing cell at x = ...", "coolant cell at x = 110-125 mm", "the air"
 * (x from the nose, the cell's centre). */
void acbb_spindle_net_node_name(const acbb_spindle_net *sn, int i, char *buf, size_t size);
/* Part p's node i (its set network's numbering) is node offset + i. */
int acbb_spindle_net_part_offset(const acbb_spindle_net *sn, int p);
/* Member k of part p's temperatures in T (the bearing's own numbering,
 * network.h), for acbb_network_part_temps and the like; NULL for a bad p
 * or k. */
const double *acbb_spindle_net_member_T(const acbb_spindle_net *sn, const double *T, int p, int k);
/* Capacity of a node, J/K (0 for a fixed or merged one). */
double acbb_spindle_net_capacity(const acbb_spindle_net *sn, int node);

/* Every node at the ambient, the coolant at its inlet: a start. */
void acbb_spindle_net_init(const acbb_spindle_net *sn, double *T);

/* Copy the members' state-dependent resistances (contact spots, films,
 * advection; after acbb_network_update) that moved by more than rel_tol
 * (relative) into the joined network; 0: every change. */
void acbb_spindle_net_sync(acbb_spindle_net *sn, double rel_tol);

/* dt > 0: one backward-Euler step from T (in: the start, out: the end);
 * dt == 0: the steady state (T out). q (length nodes(), read only): the
 * parts' heat at their nodes, W; the motor's losses are added inside from
 * the scene. On failure T is left as it came and err says why. */
acbb_status acbb_spindle_net_solve(acbb_spindle_net *sn, const double *q, double dt, double *T,
                                   acbb_error *err);

/* Flows for T, the state the last solve returned (its storage rate from
 * the step's start, kept inside). */
void acbb_spindle_net_flows(const acbb_spindle_net *sn, const double *T, acbb_spindle_flows *f);
void acbb_spindle_net_growth(const acbb_spindle_net *sn, const double *T, acbb_spindle_growth *g);

/* The heat and axis fields of the view for T, the state of the last solve:
 * n_shaft, n_housing, the cells' x and T, Q_motor_W, Q_bearings_W,
 * Q_coolant_W (advected), Q_air_W, T_coolant_in_C / out_C,
 * nose_drift_axial / radial, rear_shift and sets[p].x. The rest is left
 * as it was. */
void acbb_spindle_net_view(const acbb_spindle_net *sn, const double *T, acbb_spindle_view *v);

#endif
