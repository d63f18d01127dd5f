/* Run a preset to steady state with the installed engine library:
 *   cc run_preset.c $(pkg-config --cflags --libs acbb) -o run_preset
 *   ./run_preset presets/7008C.ini
 * Prints four results under the names `acbb run --json` gives them (JSON
 * schema 3 paths). Exits 0 when the run converged, 1 when it did not, 2 on
 * bad input. Installed as PREFIX/share/doc/acbb/examples/run_preset.c. */
#include <stdio.h>
#include <stdlib.h>
#include <acbb/acbb.h>

int main(int argc, char **argv)
{
    acbb_scene scene;
    acbb_error err = { { 0 } };
    acbb_sim *sim = NULL;
    if (argc != 2) {
        fprintf(stderr, "usage: %s PRESET.ini\n", argv[0]);
        return 2;
    }
    if (acbb_scene_load(argv[1], &scene, &err) != ACBB_OK ||
        acbb_sim_create(&scene, &(acbb_sim_opts){ 0 }, &sim, &err) != ACBB_OK) {
        fprintf(stderr, "%s\n", err.msg);
        return 2;
    }
    acbb_sim_drive(sim, NULL);                 /* the run loop, to the end */
    acbb_snapshot *s = malloc(sizeof *s);      /* large: not on the stack */
    if (!s) {
        acbb_sim_free(sim);
        return 2;
    }
    acbb_sim_snapshot(sim, s);
    acbb_sim_free(sim);
    printf("status %s\ntemperature_C.outer_ring %.17g\nlosses_W.total %.17g\nballs[0].Qi_N %.17g\n",
           acbb_run_status_name(s), s->T_outer_ring, s->losses.total,
           s->n_balls > 0 ? s->balls[0].Qi : 0.0);
    int rc = s->state == ACBB_RUN_CONVERGED ? 0 : 1;
    free(s);
    return rc;
}
