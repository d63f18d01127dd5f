/* acbb — rating life, static safety and edge loading of one bearing
 * (MODEL.md 15; ISO 281:2007, ISO/TS 16281:2008, ISO 76:2006).
 *
 * A plain value computed from a scene and a snapshot (life_eval.h:
 * acbb_life_compute); every snapshot carries the one of its state
 * (acbb_snapshot.life). Lives are in hours at the operating speed, held at
 * ACBB_LIFE_CAP_H (an unloaded or standing bearing) so that no infinity
 * reaches an output. */
#ifndef ACBB_LIFE_H
#define ACBB_LIFE_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_LIFE_CAP_H 1e9     /* hours; lives above it are reported as it */

typedef enum { ACBB_RACE_IN = 0, ACBB_RACE_OUT = 1 } acbb_life_race;

typedef struct {
    double C, C0;               /* basic dynamic / static radial ratings, N (nominal angle) */
    bool C0_table;              /* C0 from ISO 76 Table 1 (grooves 0.52 / 0.53 D_w, steel);
                                   else from its 4200 MPa definition with the real grooves */
    double Cu;                  /* fatigue load limit, N (given, or ISO 281 Annex B on C0) */
    double P_ref;               /* ISO/TS 16281 dynamic equivalent reference load C/L10r^(1/3), N */
    double L10r_Mrev;           /* basic reference rating life, 10^6 rev (capped) */
    double L10r_h, Lnmr_h;      /* reference and modified rating life, h (capped) */
    double a1, a_iso;           /* reliability and life-modification factors */
    double kappa;               /* viscosity ratio nu / nu1 (not clamped) */
    bool kappa_clamped;         /* kappa < 0.1, where ISO 281 does not define a_ISO:
                                   a_iso is taken at kappa = 0.1 */
    double nu_mm2s, nu1_mm2s;   /* operating and rated viscosity, mm^2/s */
    double T_oil_C;             /* temperature nu is taken at: mean of the two rings, C */
    double ec;                  /* contamination factor e_c used */
    double s0_min;              /* least static safety (4200 MPa / p_max)^3 of any contact */
    int s0_ball;                /* its ball (-1: no loaded contact) */
    acbb_life_race s0_race;     /* and raceway */
    double P0;                  /* static equivalent radial load, N (ISO 76 3.4): the radial
                                   load whose most loaded contact reaches the worst
                                   contact's p_max; C0 / P0 = s0_min on the stress basis
                                   (0: no loaded contact) */
    double edge_margin_deg;     /* least angle between a contact ellipse's end and its
                                   shoulder edge, deg (< 0: truncated) */
    int edge_ball;              /* the contact it belongs to (-1: none loaded) */
    acbb_life_race edge_race;
    bool edge_loaded;           /* an ellipse passes its shoulder (edge_margin_deg < 0) */
    bool estimated;             /* the internal geometry is estimated (life.internals_estimated) */
} acbb_life;

#ifdef __cplusplus
}
#endif

#endif
