/* acbb CLI — `acbb run`'s two branches and schedule lines (branches.h of
 * the CLI): the steady solve beside the transient (acbb/tools/branches.h), and
 * where a [schedule] left the run (acbb/tools/schedule.h). */
#include <math.h>
#include <stdio.h>
#include "acbb/tools/json.h"
#include "acbb/tools/schedule.h"
#include "acbb/units.h"
#include "branches.h"
#include "wrap.h"

bool acbb_cli_branches_wanted(const acbb_cli_args *a, const acbb_scene *sc)
{
    return a->val[CLI_OPT_BRANCHES] != NULL || acbb_branches_wanted(sc);
}

/* One branch within 80 columns (78): its simulated time is the summary's
 * own for the transient and none for the steady solve (the JSON has it);
 * a branch that never reached a state (0 steps, all zero) shows "-". */
static bool no_state(const acbb_branch_state *b)
{
    return b->iterations == 0 && b->Qi_N == 0.0 && b->loss_total_W == 0.0;
}

static void branch_row(acbb_cli_out *o, const char *name, const acbb_branch_state *b)
{
    const double v[] = { b->Qi_N, b->reaction_x_N, b->loss_total_W,
                         b->T_outer_ring_C, b->T_inner_ring_C, b->T_ball_C };
    bool none = no_state(b);
    fprintf(o->f, "%-10s%-14s", name, b->status);
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++) {
        if (!isfinite(v[i])) o->nonfinite++;
        if (none) fprintf(o->f, "%9s", "-");
        else fprintf(o->f, "%9.2f", isfinite(v[i]) ? v[i] : 0.0);
    }
    fputc('\n', o->f);
}

void acbb_cli_print_branches(acbb_cli_out *o, const acbb_branches *b)
{
    FILE *f = o->f;
    char line[320];
    fprintf(f, "\n%-13s", "branches");
    bool none = no_state(&b->steady) || no_state(&b->transient);
    fputs(none ? no_state(&b->steady) ? "not compared: the steady solve reached no state"
                                      : "not compared: the transient reached no state"
          : b->agree ? "the steady solve and the transient reach the same state"
                     : "DIFFERENT: steady solve and transient end on different branches", f);
    /* With a branch that never reached a state there is nothing to
     * compare: its zeros would read as differences. */
    if (none)
        snprintf(line, sizeof line, "%s", b->criterion);
    else
        snprintf(line, sizeof line, "%s; max node difference %.3g K, total loss %.3g relative",
                 b->criterion, b->max_dT_K, b->loss_rel);
    fprintf(f, "\n%-13s", "agree if");
    acbb_cli_wrap(f, line, 13, 13);
    fprintf(f, "\n%-10s%-14s%9s%9s%9s%9s%9s%9s\n", "", "status", "Qi N", "Fx N", "loss W",
            "T_or C", "T_ir C", "T_ball C");
    branch_row(o, "steady", &b->steady);
    branch_row(o, "transient", &b->transient);
    /* the transient's time (the table has no room for it; a steady run
     * shows no other) */
    if (!no_state(&b->transient))
        fprintf(f, "%-10sthe transient ran to t = %.1f s simulated\n", "", b->transient.time_s);
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
    char line[256];
    snprintf(line, sizeof line, "row %d/%d at %.0f rpm, Fx %g N, Fr %g N, %s (last row at "
             "t = %g s)", op.row, op.n_rows, acbb_rads_to_rpm(op.inner_speed), op.axial_load,
             op.radial_load, steady ? "steady solve at the last row"
                             : op.finished ? "finished" : "not finished",
             acbb_schedule_end(sc));
    fprintf(o->f, "%-13s", "schedule");
    acbb_cli_wrap(o->f, line, 13, 13);
    fputc('\n', o->f);
}
