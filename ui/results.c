/* acbb TUI — the screens' results belong to the scene they were run on
 * (issue 29 item 2). Opening another preset cancels the background work
 * started on the last one (benchmark, sweep, sensitivity, preload map)
 * and hides what it left, and the TE/WTE comparison, so no screen shows
 * one preset's numbers under another's name. A hidden job reads as never
 * started until the next run replaces it. An edit of the open scene hides
 * a finished result too, for as long as the scene differs from the one it
 * ran on (undo brings it back; r reruns). */
#include <stdio.h>
#include <string.h>
#include "results.h"
#include "screen_preload.h"
#include "screens.h"

void acbb_results_drop(acbb_app *a)
{
    acbb_job_cancel(acbb_sweepjob_job(a->sweep));
    acbb_job_cancel(acbb_sensjob_job(a->sens));
    acbb_bench_cancel(a->bench);
    /* Fresh reads: a run started since the last frame is hidden too. */
    acbb_sweepjob_read(a->sweep, &a->swv);
    acbb_sensjob_read(a->sens, &a->snv);
    acbb_bench_read(a->bench, &a->bst);
    a->hide.sweep = a->swv.job.run_id;
    a->hide.sens = a->snv.job.run_id;
    a->hide.bench = a->bst.run_id;
    a->hide.compare = 1;
    acbb_preload_drop(a);
}

void acbb_results_ran(acbb_app *a, int which)
{
    a->hide.ran_on[which] = a->ed.scene;
}

/* A finished result of job `which` on a scene the editor no longer holds. */
static int edited_since(acbb_app *a, int which, int finished)
{
    int stale = finished && acbb_editor_differs(&a->hide.ran_on[which], &a->ed.scene);
    if (stale) a->hide.edited |= 1u << which;
    return stale;
}

void acbb_results_take(acbb_app *a)
{
    a->hide.edited = 0;
    acbb_bench_read(a->bench, &a->bst);
    if (a->bst.run_id == a->hide.bench || edited_since(a, ACBB_RAN_BENCH, a->bst.phase > ACBB_BENCH_RUNNING))
        memset(&a->bst, 0, sizeof a->bst);
    acbb_screen_accuracy_follow(a);
    acbb_sweepjob_read(a->sweep, &a->swv);
    if (a->swv.job.run_id == a->hide.sweep || edited_since(a, ACBB_RAN_SWEEP, a->swv.job.phase > ACBB_JOB_RUNNING))
        memset(&a->swv, 0, sizeof a->swv);
    acbb_screen_sweep_follow(a);
    acbb_sensjob_read(a->sens, &a->snv);
    if (a->snv.job.run_id == a->hide.sens || edited_since(a, ACBB_RAN_SENS, a->snv.job.phase > ACBB_JOB_RUNNING))
        memset(&a->snv, 0, sizeof a->snv);
    acbb_screen_sensitivity_follow(a);
    acbb_preload_take(a);
    if (a->hide.compare || edited_since(a, ACBB_RAN_COMPARE, a->st.compare.phase == ACBB_CMP_DONE))
        memset(&a->st.compare, 0, sizeof a->st.compare);
}

/* What runs, first the main run: its index in the names below, -1: none. */
static int busy_index(const acbb_app *a)
{
    const int on[] = { a->st.phase == ACBB_WORKER_RUNNING || a->st.phase == ACBB_WORKER_PAUSED,
                       a->st.compare.phase == ACBB_CMP_RUNNING, a->bst.phase == ACBB_BENCH_RUNNING,
                       a->swv.job.phase == ACBB_JOB_RUNNING, a->snv.job.phase == ACBB_JOB_RUNNING,
                       acbb_preload_running(a) };
    for (int i = 0; i < (int)(sizeof on / sizeof on[0]); i++)
        if (on[i]) return i;
    return -1;
}

const char *acbb_results_note(const acbb_app *a, int which)
{
    return a->hide.edited & (1u << which)
           ? "(the last result is hidden: the scene was edited since it ran; u undoes, r reruns)" : NULL;
}

int acbb_results_busy(const acbb_app *a, const char **subject, const char **noun)
{
    static const char *const subjects[] = { "A run", "The TE/WTE comparison", "The accuracy benchmark",
                                            "A sweep", "The sensitivity analysis", "The preload map" };
    static const char *const nouns[] = { "run", "comparison", "benchmark", "sweep", "sensitivity analysis",
                                         "preload map" };
    int i = busy_index(a);
    if (subject) *subject = i >= 0 ? subjects[i] : "";
    if (noun) *noun = i >= 0 ? nouns[i] : "";
    return i >= 0;
}
