/* acbb — two branches: the steady solve and the transient compared
 * (MODEL.md 14 "Run-in schedule": a rigid 7008C at 1000 N jumped to speed
 * from cold runs away while the direct steady solve finds a benign state;
 * which one a spindle reaches depends on how it is started).
 *
 * Given a finished run of a scene, acbb_branches_compare runs the same scene
 * in the other thermal mode (the steady solve for a transient run, the
 * transient for a steady one; a schedule's steady solve uses its last row,
 * schedule.h) and says whether both reach the same state. Pure: no state;
 * the caller owns `out`. */
#ifndef ACBB_BRANCHES_H
#define ACBB_BRANCHES_H

#include "acbb/cancel_flag.h"
#include <stdbool.h>
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What one branch ended in (finite numbers only; 0 where a run never
 * started). The ball is the most loaded one (largest Qi). */
typedef struct {
    char status[24];             /* acbb_run_status_name: "converged", "runaway", ... */
    char message[256];
    long iterations;
    double time_s;               /* simulated time (0 for the steady solve) */
    double Qi_N, Qo_N, alpha_i_deg;
    double reaction_x_N;         /* axial reaction */
    double loss_total_W;
    double T_outer_ring_C, T_inner_ring_C, T_ball_C;
} acbb_branch_state;

typedef struct {
    acbb_branch_state steady, transient;
    bool agree;                  /* the criterion below holds */
    double max_dT_K;             /* largest node temperature difference */
    double loss_rel;             /* |P_steady - P_transient| / P_steady */
    const char *criterion;       /* static text: what "agree" means */
} acbb_branches;

/* Scenes where the two may differ, for which a client compares them
 * unasked: a [schedule], or mounting.preload = displacement (MODEL.md 14),
 * heating on. */
bool acbb_branches_wanted(const acbb_scene *s);

/* Run s in the other thermal mode and compare with `run`, the finished
 * snapshot of s as it was run. `s` is the run's resolved scene
 * (acbb_sim_scene, or acbb_scene_resolve in fidelity.h). ACBB_OK also when the other run fails (its
 * status says how); ACBB_CANCELLED when `cancel` (may be NULL) stopped it;
 * ACBB_ENOMEM.
 * deadline_ms: when s->max_wall_s > 0, the bound's deadline for the run
 * and the other branch together (acbb_now_ms; the CLI's is the command's
 * start plus the bound): the other branch gets what is left, not a second
 * budget, and when nothing is left it is not started (its status
 * wall_limit). 0: the other branch gets s->max_wall_s of its own. */
acbb_status acbb_branches_compare(const acbb_scene *s, const acbb_snapshot *run,
                                  const acbb_atomic_int *cancel, double deadline_ms,
                                  acbb_branches *out, acbb_error *err);

/* One run of s as it is, to its end, into `snap` (a run that never
 * started: state failed, its status and message), without what no branch
 * summary reads: the end-of-run stiffness (reported missing, as
 * acbb_sim_opts.skip_stiffness) and the rating life (zero, skip_life).
 * ACBB_OK also when the run fails; ACBB_CANCELLED, ACBB_ENOMEM. */
acbb_status acbb_branch_run(const acbb_scene *s, const acbb_atomic_int *cancel, acbb_snapshot *snap);

/* The summary above of a finished run. */
void acbb_branch_summarize(const acbb_snapshot *r, acbb_branch_state *b);

#ifdef __cplusplus
}
#endif

#endif
