/* acbb — the spindle's axisymmetric thermal network along the axis
 * (docs/spindle.md "Heat"; internal header).
 *
 * Shaft and housing are chains of cells (axial_chain.h) in one acbb_tnet
 * (thermal_network.h, reused as is). Each bearing station is a node tied to
 * the shaft cell and the housing cell at its x through given conductances
 * (the later integration joins the bearing's own network there). The motor
 * puts its rotor heat on the shaft cells under the rotor and its stator
 * heat on the housing cells under the stator (shares by overlap length),
 * with an optional rotor-stator air-gap conductance. A coolant jacket is a
 * chain of well-mixed coolant cells along the housing: cell m receives the
 * flow at the previous cell's temperature (upwind advection, capacity rate
 * m_dot c_p), so the coolant warms along the jacket. Air (a fixed node)
 * takes heat from the housing's outer surface and the shaft's end faces.
 *
 * Advection is not symmetric, so the coolant cells are fixed nodes of the
 * symmetric acbb_tnet and their temperatures come from an exact Schur
 * complement: the solid's response to each coolant temperature is affine,
 * found by n_cool + 1 solves with the cached factorisation, and the coolant
 * balances are then one small dense LU (shaft_thermal_solve.c).
 *
 * Steady and transient (backward Euler, the same step as the bearing's
 * network). Temperatures in C; x in m from the nose.
 * Ownership: acbb_spindle_thermal_build returns an object the caller frees
 * with acbb_spindle_thermal_free; the definition's arrays are copied. */
#ifndef ACBB_SHAFT_THERMAL_H
#define ACBB_SHAFT_THERMAL_H

#include "acbb/status.h"
#include "shaft_section.h"

#define ACBB_SPINDLE_MAX_STATIONS 8
#define ACBB_SPINDLE_MAX_COOL 64

typedef struct {
    double x;            /* station, m from the nose */
    double G_shaft;      /* bearing node <-> shaft cell, W/K (> 0) */
    double G_housing;    /* bearing node <-> housing cell, W/K (> 0) */
    double C;            /* bearing node capacity, J/K (>= 0) */
} acbb_spindle_station;

typedef struct {
    double x0, x1;       /* axial extent, m (x1 = x0: absent) */
} acbb_span;

typedef struct {
    const acbb_shaft_seg *shaft; int n_shaft;       /* from the nose */
    const acbb_shaft_seg *housing; int n_housing;   /* d_bore = the housing bore */
    double housing_x0;                              /* housing start, m */
    int n_div;                                      /* cells per segment */
    const acbb_spindle_station *station; int n_station;
    int fixed_station;        /* the axially located bearing (growth reference) */
    acbb_span rotor, stator;  /* motor parts */
    double G_gap;             /* rotor <-> stator across the air gap, W/K (>= 0) */
    acbb_span jacket;         /* coolant jacket on the housing */
    int n_cool;               /* coolant cells (0 = no coolant) */
    double m_dot, c_p;        /* kg/s, J/(kg K) */
    double T_in;              /* coolant inlet, C */
    double hA;                /* jacket wall conductance (whole jacket), W/K */
    double C_cool;            /* coolant held in the jacket, J/K (>= 0) */
    double T_air;             /* ambient air, C */
    double h_housing;         /* housing outer surface, W/(m2 K) (>= 0) */
    double h_shaft_end;       /* shaft end faces, W/(m2 K) (>= 0) */
    double T_ref;             /* assembly temperature for the growth, C */
} acbb_spindle_thermal_def;

typedef struct {
    double rotor, stator;                            /* W */
    double bearing[ACBB_SPINDLE_MAX_STATIONS];       /* W per station */
} acbb_spindle_heat;

typedef struct {
    double Q_in;                    /* all sources, W */
    double Q_air_shaft;             /* to air from the shaft ends, W */
    double Q_air_housing;           /* to air from the housing, W */
    double Q_coolant_wall;          /* housing -> coolant, W */
    double Q_advected;              /* m_dot c_p (T_out - T_in), W */
    double storage_rate;            /* sum C dT/dt of the last step (0 after steady), W */
    double T_coolant_out;           /* C (T_in without coolant) */
    double growth_axial;            /* nose moves forward (away from the fixed bearing), m */
    /* axial shift of the shaft against the housing at each station, both
     * located at the fixed bearing: shaft growth minus housing growth
     * between the two, m (positive: the shaft's point moves rearwards,
     * +x, relative to the housing's; 0 at the fixed bearing) */
    double shift_axial[ACBB_SPINDLE_MAX_STATIONS];
    double growth_radial_shaft[ACBB_SPINDLE_MAX_STATIONS];   /* shaft radius, m */
    double growth_radial_housing[ACBB_SPINDLE_MAX_STATIONS]; /* housing bore radius, m */
    double T_station[ACBB_SPINDLE_MAX_STATIONS];             /* bearing nodes, C */
    double Q_to_shaft[ACBB_SPINDLE_MAX_STATIONS];   /* bearing node -> shaft, W */
    double Q_to_housing[ACBB_SPINDLE_MAX_STATIONS]; /* bearing node -> housing, W */
} acbb_spindle_thermal_result;

typedef enum {
    ACBB_SPINDLE_SHAFT, ACBB_SPINDLE_HOUSING, ACBB_SPINDLE_COOLANT
} acbb_spindle_part;

typedef struct acbb_spindle_thermal acbb_spindle_thermal;

acbb_status acbb_spindle_thermal_build(const acbb_spindle_thermal_def *def,
                                       acbb_spindle_thermal **out, acbb_error *err);
void acbb_spindle_thermal_free(acbb_spindle_thermal *sp);

/* Every node (and the coolant) at T, C: the transient's start. */
void acbb_spindle_thermal_set_uniform(acbb_spindle_thermal *sp, double T);

acbb_status acbb_spindle_thermal_steady(acbb_spindle_thermal *sp, const acbb_spindle_heat *h,
                                        acbb_error *err);
acbb_status acbb_spindle_thermal_step(acbb_spindle_thermal *sp, const acbb_spindle_heat *h,
                                      double dt, acbb_error *err);

/* Flows, growth and station temperatures of the current state (for the
 * heat of the last solve). */
void acbb_spindle_thermal_results(const acbb_spindle_thermal *sp,
                                  acbb_spindle_thermal_result *res);

/* Cells of a part and the centre x (m) and temperature (C) of cell i. */
int acbb_spindle_thermal_cells(const acbb_spindle_thermal *sp, acbb_spindle_part part);
acbb_status acbb_spindle_thermal_cell(const acbb_spindle_thermal *sp, acbb_spindle_part part,
                                      int i, double *x, double *T);

#endif
