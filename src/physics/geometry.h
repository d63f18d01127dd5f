/* acbb — derived bearing geometry (MODEL.md section 1) and the thermal
 * geometry terms of the seed's eqs (12)-(13) (MODEL.md section 3 table). */
#ifndef ACBB_GEOMETRY_H
#define ACBB_GEOMETRY_H

#include "acbb/scene.h"
#include "expansion.h"

typedef struct {
    double D, dm;               /* ball and pitch diameter, m */
    int Z;                      /* balls */
    double lambda_i, lambda_o;  /* groove radii, m */
    double f_i, f_o;            /* groove curvature factors */
    double A0;                  /* groove-centre distance lambda_i + lambda_o - D, m */
    double alpha0;              /* free contact angle, rad */
    double Pd;                  /* diametral clearance 2 A0 (1 - cos alpha0), m */
    double d_i, d_o;            /* raceway diameters, m */
    double Re_i, Re_o;          /* loci of groove curvature centres (radius), m */
    double E_eff;               /* ball-ring effective modulus, Pa */
    double mass, J;             /* ball mass (kg) and polar inertia (kg m^2) */
} acbb_geometry;

void acbb_geometry_init(const acbb_scene *s, acbb_geometry *g);

/* The geometry is given by the free contact angle OR by the diametral
 * clearance (MODEL.md section 1: cos alpha0 = 1 - P_d / (2 A0), A0 =
 * lambda_i + lambda_o - D): with bearing.clearance_um = 0 the clearance
 * follows from contact_angle_deg, with clearance_um > 0 the angle follows
 * from the clearance (scene_rules.c refuses an angle that disagrees, except
 * 0, the deep-groove bearing's nominal angle). Both in SI (rad, m). */
double acbb_free_contact_angle(const acbb_scene *s);
double acbb_diametral_clearance(const acbb_scene *s);

/* Thermal offsets entering the compatibility equations for one ball. */
typedef struct {
    double A0;      /* groove-centre distance used in A1, A2 (SEED: with f') */
    double dA1;     /* added to A1 */
    double dA2;     /* added to A2 */
    double dL_i;    /* subtracted from the inner groove-to-ball-centre length */
    double dL_o;    /* subtracted from the outer groove-to-ball-centre length */
} acbb_thermal_offsets;

/* CLEAN: dA2 = th_i + th_icen - th_o, dL_i = dL_o = th_ba. SEED: the literal seed
 * projections, evaluated at the ball's current angles (lagged). */
void acbb_geometry_offsets(const acbb_geometry *g, acbb_geom_mode mode,
                           const acbb_expansion *e, double alpha_i, double alpha_o,
                           acbb_thermal_offsets *out);

#endif
