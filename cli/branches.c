/* acbb CLI — `acbb run`'s two branches and schedule lines (branches.h of
 * the CLI): the steady solve beside the transient (acbb/tools/branches.h), and
 * where a [schedule] left the run (acbb/tools/schedule.h). */
#include <math.h>
#include <stdio.h>
#include "acbb/tools/json.h"
#include "acbb/tools/schedule.h"
#include "acbb/units.h"
#include "branches.h"

bool acbb_cli_branches_wanted(const acbb_cli_args *a, const acbb_scene *sc)
{
    return a->val[CLI_OPT_BRANCHES] != NULL || acbb_branches_wanted(sc);
}

static void branch_row(acbb_cli_out *o, const char *name, const acbb_branch_state *b)
{
    const double v[] = { b->time_s, b->Qi_N, b->reaction_x_N, b->loss_total_W,
                         b->T_outer_ring_C, b->T_inner_ring_C, b->T_ball_C };
    fprintf(o->f, "  %-13s%-14s", name, b->status);
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        if (!isfinite(v[i])) o->nonfinite++;
        fprintf(o->f, "%9.2f", isfinite(v[i]) ? v[i] : 0.0);
    }
    fputc('\n', o->f);
}

void acbb_cli_print_branches(acbb_cli_out *o, const acbb_branches *b)
{
    FILE *f = o->f;
    fprintf(f, "\n%-13s%s\n", "branches", b->agree
            ? "the steady solve and the transient reach the same state"
            : "DIFFERENT: the steady solve and the transient end on different branches");
    fprintf(f, "%-13s%s\n%-13smax node difference %.3g K, total loss %.3g relative\n",
            "agree if", b->criterion, "", b->max_dT_K, b->loss_rel);
    fprintf(f, "  %-13s%-14s%9s%9s%9s%9s%9s%9s%9s\n", "", "status", "time s", "Qi N", "Fx N",
            "loss W", "T_or C", "T_ir C", "T_ball C");
    branch_row(o, "steady solve", &b->steady);
    branch_row(o, "transient", &b->transient);
}

void acbb_cli_schedule_shown(const acbb_scene *sc, acbb_scene *shown)
{
    *shown = *sc;
    acbb_operating op;
    acbb_schedule_final(sc, &op);
    acbb_schedule_apply(shown, &op);
}

void acbb_cli_print_schedule(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s)
{
    if (sc->schedule_n == 0) return;
    acbb_operating op;
    bool steady = sc->thermal_mode == ACBB_THERMAL_STEADY || !sc->heating;
    if (steady) acbb_schedule_final(sc, &op);
    else acbb_schedule_at(sc, s->time, &op);
    fprintf(o->f, "%-13srow %d/%d at %.0f rpm, Fx %g N, Fr %g N, %s (last row at t = %g s)\n",
            "schedule", op.row, op.n_rows, acbb_rads_to_rpm(op.inner_speed), op.axial_load,
            op.radial_load, steady ? "steady solve at the last row"
                            : op.finished ? "finished" : "not finished",
            acbb_schedule_end(sc));
}
