/* acbb — a scene checked as a run checks it, without running (sim.h). */
#include "acbb/sim.h"

acbb_status acbb_sim_check(const acbb_scene *s, acbb_error *err)
{
    acbb_status st = acbb_scene_validate(s, err);
    acbb_sim *sim = NULL;
    if (st == ACBB_OK) st = acbb_sim_new(s, &sim, err);
    acbb_sim_free(sim);
    return st;
}
