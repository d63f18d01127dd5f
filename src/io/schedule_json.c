/* acbb — the run JSON's `schedule` and `branches` objects (json.h). */
#include "acbb/tools/json.h"
#include "acbb/tools/schedule.h"
#include "acbb/units.h"

/* Where the run left the schedule: a steady solve (or an isothermal run)
 * is at the last row (schedule.h); a transient at its simulated time. */
static void reached(const acbb_scene *sc, const acbb_snapshot *s, acbb_operating *op)
{
    if (sc->thermal_mode == ACBB_THERMAL_STEADY || !sc->heating) acbb_schedule_final(sc, op);
    else acbb_schedule_at(sc, s->time, op);
}

void acbb_json_write_schedule(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s)
{
    acbb_operating op;
    reached(sc, s, &op);
    acbb_json_open(j, "schedule", '{', false);
    acbb_json_open(j, "rows", '[', false);
    for (int i = 0; i < sc->schedule_n; i++) {
        const acbb_schedule_row *r = &sc->schedule[i];
        acbb_json_open(j, NULL, '{', true);
        acbb_json_num(j, "t_s", r->t);
        acbb_json_num(j, "inner_speed_rpm", acbb_rads_to_rpm(r->inner_speed));
        acbb_json_num(j, "axial_load_N", r->axial_load);
        acbb_json_num(j, "radial_load_N", r->radial_load);
        acbb_json_close(j, '}');
    }
    acbb_json_close(j, ']');
    acbb_json_long(j, "row", op.row);
    acbb_json_long(j, "n_rows", op.n_rows);
    acbb_json_bool(j, "finished", op.finished);
    acbb_json_num(j, "end_s", acbb_schedule_end(sc));
    acbb_json_num(j, "inner_speed_rpm", acbb_rads_to_rpm(op.inner_speed));
    acbb_json_num(j, "axial_load_N", op.axial_load);
    acbb_json_num(j, "radial_load_N", op.radial_load);
    acbb_json_close(j, '}');
}

static void branch(acbb_json *j, const char *key, const acbb_branch_state *b)
{
    acbb_json_open(j, key, '{', false);
    acbb_json_str(j, "status", b->status);
    acbb_json_str(j, "message", b->message);
    acbb_json_long(j, "iterations", b->iterations);
    acbb_json_num(j, "time_s", b->time_s);
    acbb_json_num(j, "Qi_N", b->Qi_N);
    acbb_json_num(j, "Qo_N", b->Qo_N);
    acbb_json_num(j, "alpha_i_deg", b->alpha_i_deg);
    acbb_json_num(j, "reaction_x_N", b->reaction_x_N);
    acbb_json_num(j, "loss_total_W", b->loss_total_W);
    acbb_json_num(j, "T_outer_ring_C", b->T_outer_ring_C);
    acbb_json_num(j, "T_inner_ring_C", b->T_inner_ring_C);
    acbb_json_num(j, "T_ball_C", b->T_ball_C);
    acbb_json_close(j, '}');
}

void acbb_json_write_branches(acbb_json *j, const acbb_branches *b)
{
    acbb_json_open(j, "branches", '{', false);
    branch(j, "steady", &b->steady);
    branch(j, "transient", &b->transient);
    acbb_json_bool(j, "agree", b->agree);
    acbb_json_num(j, "max_dT_K", b->max_dT_K);
    acbb_json_num(j, "loss_rel", b->loss_rel);
    acbb_json_str(j, "criterion", b->criterion);
    acbb_json_close(j, '}');
}
