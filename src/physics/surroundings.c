/* acbb — the surroundings the thermal network puts around a bearing, and
 * the boundary each cooled face takes (MODEL.md 8.1, 13; acbb/scene.h).
 * Physics derives them from the scene's data; the scene's validation
 * (scene_rules.c) calls them from the layer above (README "Source tree"). */
#include <math.h>

#include "acbb/scene.h"
#include "acbb/tools/surroundings.h"

/* An unset (0) size is the seed rig's value scaled by dim / ref; ref is
 * written as the schema computes a preset value (mm * 1e-3) so the 7008C
 * scene scales by exactly 1 and keeps the seed's network bit for bit. */
static double scaled(double set, double seed_m, double dim, double ref_mm)
{
    return set > 0.0 ? set : seed_m * (dim / (ref_mm * 1e-3));
}

void acbb_scene_surroundings(const acbb_scene *s, acbb_surroundings *o)
{
    /* outer-ring face height (land to OD); the seed's is 4.95 mm */
    double face = 0.5 * s->outer_diameter - 0.5 * s->outer_land_diameter;
    double face0 = 0.5 * (68 * 1e-3) - 0.5 * (58.1 * 1e-3);
    o->housing_od = scaled(s->housing_od, 0.120, s->outer_diameter, 68);
    o->housing_length = scaled(s->housing_length, 0.045, s->width, 15);
    o->shaft_bore = scaled(s->shaft_bore, 0.025, s->bore, 40);
    o->shaft_length = scaled(s->shaft_length, 0.045, s->width, 15);
    o->cap_od = s->cap_od > 0.0 ? s->cap_od : o->housing_od;
    o->cap_thickness = scaled(s->cap_thickness, 0.010, s->width, 15);
    o->shoulder_thickness = scaled(0.0, 0.010, s->width, 15);
    o->shoulder_inset = 0.004 * (face / face0);
    o->cap_inset = 0.006 * (face / face0);
    o->x_end_wall = 0.017 * (o->housing_length / 0.045);
    o->cage_clearance = scaled(0.0, 0.0015, s->ball_diameter, 6.35);
}

/* Is the scene the seed's rig: the 7008C envelope (bore 40, OD 68, width
 * 15 mm) inside the rig's housing, shaft and cap (MODEL.md 8.1)? */
static int seed_rig(const acbb_scene *s)
{
    acbb_surroundings u;
    acbb_scene_surroundings(s, &u);
    const double got[] = { s->bore, s->outer_diameter, s->width, u.housing_od, u.housing_length,
                           u.shaft_bore, u.shaft_length, u.cap_od, u.cap_thickness };
    const double rig[] = { 0.040, 0.068, 0.015, 0.120, 0.045, 0.025, 0.045, 0.120, 0.010 };
    for (size_t i = 0; i < sizeof rig / sizeof rig[0]; i++)
        if (fabs(got[i] - rig[i]) > 1e-9 * rig[i]) return 0;
    return 1;
}

acbb_bc_kind acbb_face_bc_kind(const acbb_scene *s, const acbb_face_bc *bc)
{
    if (bc->kind != ACBB_BC_DERIVED) return bc->kind;
    return seed_rig(s) ? ACBB_BC_FIXED : ACBB_BC_CONVECTIVE;
}
