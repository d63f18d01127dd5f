/* acbb — the parts around a bearing that its thermal network carries
 * (MODEL.md 8.1, 13 "Surroundings"; src/physics/surroundings.c): sizes
 * derived from the bearing where the scene leaves them 0, and the boundary
 * a cooled face has. The network, the scene's rules and the study use them;
 * a run reports its temperatures (acbb_snapshot). */
#ifndef ACBB_TOOLS_SURROUNDINGS_H
#define ACBB_TOOLS_SURROUNDINGS_H

#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The surroundings the thermal network puts around the bearing (MODEL.md
 * 8.1), m: the scene's [surroundings] values, each unset (0) size derived by
 * scaling the seed's 7008C rig (OD 68, width 15, bore 40 mm) with the
 * bearing: diameters outside the bearing by OD/68, axial sizes by width/15,
 * insets on the outer-ring face by its height (OD - outer land)/2 / 4.95 mm,
 * the cage bore clearance by D/6.35 mm. The 7008C scene gets the seed rig
 * exactly (housing 120 x 45, shoulder 10, cap 10, shaft bore 25, shaft 45). */
typedef struct {
    double housing_od, housing_length, shaft_bore, shaft_length, cap_od, cap_thickness;
    double shoulder_thickness;   /* rear housing shoulder wall (10 mm for 7008C) */
    double shoulder_inset;       /* shoulder reaches this far inside the OD radius (4) */
    double cap_inset;            /* cap bore radius = OD/2 - cap_inset (6) */
    double x_end_wall;           /* |x| of the housing end-wall body node 36 (17) */
    double cage_clearance;       /* cage bore radius = d_m/2 - this (1.5) */
} acbb_surroundings;

void acbb_scene_surroundings(const acbb_scene *s, acbb_surroundings *out);

/* The boundary a cooled face (s->bore_bc or s->cap_bc) has in this scene:
 * fixed or convective as set; `derived` (the default) is [S]'s fixed face
 * on the seed's own rig (the 7008C envelope with the rig's surroundings,
 * [S] section 3) and convective at the face's h for every other bearing:
 * a fixed face is an unlimited heat sink, which only the rig measured
 * (MODEL.md 13 "Surroundings", issue 18). */
acbb_bc_kind acbb_face_bc_kind(const acbb_scene *s, const acbb_face_bc *bc);

#ifdef __cplusplus
}
#endif

#endif
