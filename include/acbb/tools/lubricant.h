/* acbb — lubricants by grade (MODEL.md 16; src/scene/lubricant_grade.c):
 * the ISO 3448 midpoint of a grade, the viscosity index of ASTM D2270 and
 * the oil a graded scene derives. A run derives it itself (its constructor
 * resolves the scene, fidelity.h), so a program that only runs scenes
 * needs none of this; the CLI's and the TUI's messages and the tests do. */
#ifndef ACBB_TOOLS_LUBRICANT_H
#define ACBB_TOOLS_LUBRICANT_H

#include "acbb/scene.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Lubricants by grade (MODEL.md 16, src/scene/lubricant_grade.c). A graded
 * scene (lubricant.grade, or method grease with a base-oil nu40) gets
 * oil_nu40 (ISO 3448 midpoint), oil_nu100 (from oil_vi, ASTM D2270) and
 * oil_alpha_pv (Wooster) written into `s`, except where those keys hold
 * other than their defaults; a custom oil is left as given. A run applies
 * it to its own copy (acbb_sim_create). */
void acbb_lubricant_apply(acbb_scene *s);
double acbb_grade_midpoint(acbb_oil_grade g);          /* mm^2/s at 40 C; 0 for custom */
/* A failed check `rc` of a scene after acbb_lubricant_apply: when a graded
 * oil's derived value is what failed (VG2 at viscosity_index 100 derives
 * nu100 < 1 mm^2/s), the message names the grade and index the user set,
 * not only the key they never wrote. Returns rc. */
acbb_status acbb_lubricant_explain(const acbb_scene *s, acbb_status rc, acbb_error *err);
double acbb_viscosity_index(double nu40, double nu100); /* ASTM D2270, mm^2/s; NAN: nu100 < 2 */
double acbb_nu100_from_vi(double nu40, double vi);     /* mm^2/s: VI(nu40, result) = vi */

#ifdef __cplusplus
}
#endif

#endif
