/* The scene resolved once before a run (issue 27 item 3): the fidelity
 * preset / target over the knobs (fidelity.h), then a graded oil's
 * viscosities and pressure-viscosity coefficient (MODEL.md 16). The Sim's
 * constructor calls this and keeps the result (acbb_sim_scene); writers
 * and planners that build no Sim call it themselves. */
#include "acbb/tools/fidelity.h"
#include "acbb/tools/lubricant.h"
#include "lubricant_grade.h"

int acbb_scene_resolve(const acbb_scene *in, acbb_scene *out, acbb_fidelity_choice *fc)
{
    acbb_scene r = *in; /* `in` may be `out` */
    int chosen = acbb_fidelity_apply(&r, fc);
    acbb_lubricant_apply(&r);
    *out = r;
    return chosen;
}
