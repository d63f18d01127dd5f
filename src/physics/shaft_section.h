/* acbb — the stepped hollow cylinders of a spindle (shaft and housing):
 * segments along the axis, their section properties, the Timoshenko shear
 * coefficient of a hollow circle, and the axial mesh both the beam
 * (shaft_beam.c) and the thermal network (shaft_thermal.c) are built on.
 * docs/spindle.md describes the model (internal header).
 *
 * Axial coordinate x (m) runs from the shaft's front end, the nose (x = 0),
 * towards the rear; segment k spans [x_k, x_k + L_k] in the order given.
 * Ownership: acbb_shaft_mesh returns an array the caller frees with free(). */
#ifndef ACBB_SHAFT_SECTION_H
#define ACBB_SHAFT_SECTION_H

#include "acbb/status.h"

/* One segment: a hollow (or solid, d_bore = 0) circular cylinder. The beam
 * uses E and nu, the thermal network k, rho, c and alpha; a field a module
 * does not use may be zero. */
typedef struct {
    double L;        /* length, m (> 0) */
    double d_out;    /* outer diameter, m (> 0) */
    double d_bore;   /* bore diameter, m (0 <= d_bore < d_out) */
    double E;        /* Young's modulus, Pa */
    double nu;       /* Poisson's ratio (0 <= nu < 0.5) */
    double rho;      /* density, kg/m3 */
    double k;        /* thermal conductivity, W/(m K) */
    double c;        /* specific heat, J/(kg K) */
    double alpha;    /* linear expansion coefficient, 1/K */
} acbb_shaft_seg;

/* What a module needs from the segments (flags for acbb_shaft_segs_check). */
enum { ACBB_SEG_MECH = 1, ACBB_SEG_THERM = 2 };

/* Validate n >= 1 segments for the given use; the message names the
 * segment, the field, its unit and the allowed range. */
acbb_status acbb_shaft_segs_check(const char *what, const acbb_shaft_seg *s, int n,
                                  int use, acbb_error *err);

double acbb_shaft_segs_length(const acbb_shaft_seg *s, int n);
/* Index of the segment holding x (a boundary belongs to the segment behind
 * it, the last segment keeps its end); -1 outside [0, length]. */
int acbb_shaft_segs_locate(const acbb_shaft_seg *s, int n, double x);

double acbb_seg_area(const acbb_shaft_seg *s);      /* pi/4 (D^2 - d^2), m2 */
double acbb_seg_inertia(const acbb_shaft_seg *s);   /* pi/64 (D^4 - d^4), m4 */
/* Cowper (1966) shear coefficient of a hollow circle:
 * kappa = 6(1+nu)(1+m^2)^2 / ((7+6nu)(1+m^2)^2 + (20+12nu) m^2), m = d/D. */
double acbb_seg_shear_coeff(const acbb_shaft_seg *s);

/* Sorted node positions: every segment boundary, each segment cut into
 * n_div equal parts, and the extra points (stations; ignored if outside
 * the shaft). Points closer than 1e-9 of the length merge. *x_out is
 * malloc'd; *n_out >= 2. */
acbb_status acbb_shaft_mesh(const acbb_shaft_seg *s, int n, int n_div,
                            const double *extra, int n_extra,
                            double **x_out, int *n_out, acbb_error *err);

#endif
