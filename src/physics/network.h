/* acbb — the bearing's thermal networks built on acbb_tnet:
 * the default 46-node network (MODEL.md section 8.1) and the 7-node
 * teaching network (section 8.3).
 *
 * Build once from a Scene; before each thermal step call
 * acbb_network_update with the current contact sizes and speeds so the
 * state-dependent resistances (contact spots, convection) follow the run.
 * Surroundings (housing, shaft segment, end cap) and the boundary condition
 * of each cooled face come from the scene's [surroundings]. A convective
 * shaft bore or cap puts its film in series with the conduction edge into
 * the face nodes (46-node: 28/30, 38/40/42), which then hold the coolant
 * temperature; a 7-node shaft coolant not at ambient adds node 7.
 *
 * Ownership: acbb_network_build fills a caller-owned struct whose `net`
 * the caller releases with acbb_network_free. */
#ifndef ACBB_NETWORK_H
#define ACBB_NETWORK_H

#include "acbb/scene.h"
#include "acbb/limits.h"
#include "thermal_network.h"
#include "expansion.h"

#define ACBB_NET_MAX_AVG 4

/* Heat (W) from the loss model, grouped by destination. */
typedef struct {
    double inner_contact;   /* P_L,i + P_t,i + P_r,i  (node 44 / 7-node: IR share) */
    double outer_contact;   /* P_L,o + P_t,o + P_r,o  (node 45) */
    double ball;            /* P_s,i + P_s,o          (node 15, ball centre) */
    double cavity;          /* P_v                    (node 43, cavity) */
    double cage;            /* P_c                    (node 14, cage; 7-node: node 3) */
} acbb_heat_sources;

/* State that the resistances depend on (one representative ball: mean over
 * loaded balls). Zero semi-axes mean "no contact": the spot resistance is
 * then replaced by a large but finite value (1e6 K/W). */
typedef struct {
    double a_i, b_i;        /* inner contact semi-axes, m */
    double a_o, b_o;        /* outer contact semi-axes, m */
    double omega_i;         /* inner ring speed, rad/s */
    double omega_m;         /* ball orbital (cage) speed, rad/s */
    /* surface speeds through the contact, m/s (mean over loaded balls);
     * used by thermal.contact_model = moving only */
    double v_race_i, v_ball_i, v_race_o, v_ball_o;
    /* thermal.contact_model = moving: each body's spot conductances summed
     * over the loaded balls, W/K (acbb_network_spot_add; 0 = none given).
     * A sum of each ball's own spot, so a ball entering the load zone adds
     * a conductance that starts at 0: the means above would jump. */
    double g_race_i, g_ball_i, g_race_o, g_ball_o;
    double T_cavity_C;      /* current oil-air temperature (for properties), C */
    int n_loaded_i, n_loaded_o; /* balls in contact at each race; 0 = all Z */
} acbb_net_inputs;

/* Add one loaded contact (semi-axes a, b; race and ball surface speeds) of
 * the inner (inner = 1) or outer race to in's moving-source conductance
 * sums: 1 / acbb_spot_r_moving of each body (contact_heat.h). */
void acbb_network_spot_add(acbb_net_inputs *in, const acbb_scene *s, int inner, double a, double b,
                           double v_race, double v_ball);

typedef struct {
    acbb_tnet *net;
    acbb_network_kind kind;
    int n;                              /* nodes */
    const char *const *names;           /* n node names (static strings) */
    /* key nodes */
    int node_ambient, node_outer_ring /* seed node 5 */, node_inner_ring,
        node_ball, node_housing, node_shaft, node_cavity, node_cage;
    /* where each heat source goes */
    int heat_inner, heat_outer, heat_spin, heat_drag;
    /* part averages for the expansions (MODEL.md section 7 table) */
    int avg_ball[ACBB_NET_MAX_AVG], n_avg_ball;
    int avg_inner[ACBB_NET_MAX_AVG], n_avg_inner;
    int avg_shaft[ACBB_NET_MAX_AVG], n_avg_shaft;
    int avg_housing[ACBB_NET_MAX_AVG], n_avg_housing;
    int avg_outer[ACBB_NET_MAX_AVG], n_avg_outer;
    /* lubricant inlet temperatures: mean of these node pairs (section 5) */
    int inlet_inner[2], inlet_outer[2];
    /* private: indices of state-dependent edges, geometry cache */
    int edge_sp_race_i, edge_sp_ball_i, edge_sp_race_o, edge_sp_ball_o;
    int edge_cv[16], n_edge_cv;
    double geo[32];
} acbb_network;

acbb_status acbb_network_build(const acbb_scene *s, acbb_network *out, acbb_error *err);
void acbb_network_free(acbb_network *nw);

/* Recompute state-dependent resistances. */
acbb_status acbb_network_update(acbb_network *nw, const acbb_scene *s,
                                const acbb_net_inputs *in);

/* Heat vector q (length nw->n, zeroed first) from the grouped sources.
 * The 7-node network splits contact heat with s->heat_partition. */
void acbb_network_heat(const acbb_network *nw, const acbb_scene *s,
                       const acbb_heat_sources *h, double *q);

/* Part temperatures for the expansions from node temperatures T. */
void acbb_network_part_temps(const acbb_network *nw, const double *T,
                             acbb_part_temps *out);

/* Lubricant inlet temperatures at the inner / outer contact (C). */
void acbb_network_inlet_temps(const acbb_network *nw, const double *T,
                              double *T_in_inner, double *T_in_outer);

#endif
