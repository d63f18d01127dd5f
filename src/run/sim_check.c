/* acbb — a scene checked as a run checks it, without running (sim.h). */
#include "acbb/sim.h"

acbb_status acbb_sim_check(const acbb_scene *s, acbb_error *err)
{
    acbb_status st = acbb_scene_validate(s, err);
    acbb_sim *sim = NULL;
    /* A wall-clock bound limits a run, not whether the scene is valid:
     * `acbb edit --set fidelity.max_wall_s=0.001` must not fail on it. */
    acbb_scene unbounded = *s;
    unbounded.max_wall_s = 0.0;
    if (st == ACBB_OK) st = acbb_sim_create(&unbounded, NULL, &sim, err);
    acbb_sim_free(sim);
    return st;
}
