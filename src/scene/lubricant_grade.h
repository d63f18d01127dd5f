/* acbb — lubricants by grade (MODEL.md 16): ISO 3448 midpoints, the
 * viscosity index of ASTM D2270 and the Wooster pressure-viscosity
 * correlation. The entry points are declared in acbb/tools/lubricant.h
 * (acbb_lubricant_apply, acbb_grade_midpoint, acbb_viscosity_index,
 * acbb_nu100_from_vi); this header only names the grade table. */
#ifndef ACBB_LUBRICANT_GRADE_H
#define ACBB_LUBRICANT_GRADE_H

#include "acbb/tools/lubricant.h"

/* Wooster's pressure-viscosity coefficient (1/Pa) for a mineral oil of
 * dynamic viscosity eta (Pa s) at ambient pressure. */
double acbb_wooster_alpha(double eta);

#endif
