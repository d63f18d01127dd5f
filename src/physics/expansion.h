/* acbb — thermal and centrifugal expansion (MODEL.md section 7, seed eqs
 * 1-11). All results are radial displacements (radius changes), m. */
#ifndef ACBB_EXPANSION_H
#define ACBB_EXPANSION_H

#include "acbb/scene.h"

/* Mean part temperatures (C) taken from the thermal network. */
typedef struct {
    double ball, inner_ring, shaft, housing, outer_ring;
} acbb_part_temps;

typedef struct {
    double ball;        /* theta_ba, eq (1): ball radius growth */
    double inner;       /* theta_i, eq (3): IR raceway growth with shaft */
    double inner_cen;   /* theta_icen, eq (9): IR centrifugal growth */
    double outer;       /* theta_o, eq (4): OR raceway growth via housing */
} acbb_expansion;

/* Eq (1), (3), (4) with delta T relative to s->ambient_C, and eq (9) at
 * s->inner_speed when s->ring_centrifugal. SEED geometry uses the bore
 * radius in eq (3)'s first term as printed in the seed. When
 * !s->thermal_expansion every term is 0, the centrifugal one too (WTE,
 * MODEL.md section 9); with TE the centrifugal term follows its switch. */
void acbb_expansion_compute(const acbb_scene *s, const acbb_part_temps *t,
                            acbb_expansion *out);

/* Single equations, exposed for tests and the seed's projections. */
double acbb_expansion_ball(double chi, double dT, double D);
double acbb_expansion_inner(double chi_i, double dT_i, double chi_s, double dT_s,
                            double nu_s, double r_bore, double r_race);
double acbb_expansion_outer(double chi_h, double dT_h, double nu_h, double r_h);
double acbb_expansion_centrifugal(double rho, double omega, double E, double nu,
                                  double r_bore, double r_outer);

/* SEED-mode projections of eqs (5)-(8), (10)-(11). */
typedef struct {
    double onl, inl;    /* eq (5), (6) */
    double ix, iz;      /* eq (7), (8) */
    double bax, baz;    /* eq (10), (11) */
} acbb_seed_projection;
void acbb_expansion_seed_project(const acbb_expansion *e, double alpha_i,
                                 double alpha_o, acbb_seed_projection *p);

#endif
