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
#include "screens.h"

void acbb_results_drop(acbb_app *a)
{
    for (int i = 0; i < acbb_screen_count; i++)
        if (acbb_screens[i]->drop) acbb_screens[i]->drop(a);
}

int acbb_results_stale(acbb_app *a, const acbb_screen *s, const acbb_scene *ran_on, int finished)
{
    int stale = finished && acbb_editor_differs(ran_on, &a->ed.scene);
    if (stale) a->edit_hid |= 1u << acbb_screen_index(s);
    return stale;
}

void acbb_results_take(acbb_app *a)
{
    a->edit_hid = 0;
    for (int i = 0; i < acbb_screen_count; i++)
        if (acbb_screens[i]->poll) acbb_screens[i]->poll(a);
}

const char *acbb_results_note(const acbb_app *a, const acbb_screen *s)
{
    return a->edit_hid & (1u << acbb_screen_index(s))
           ? "(the last result is hidden: the scene was edited since it ran; u undoes, r reruns)" : NULL;
}

int acbb_results_busy(const acbb_app *a, const char **subject, const char **noun)
{
    const char *sub = "A run", *nn = "run"; /* the main run first, then the screens' jobs */
    int busy = a->st.phase == ACBB_WORKER_RUNNING || a->st.phase == ACBB_WORKER_PAUSED;
    for (int i = 0; !busy && i < acbb_screen_count; i++) {
        const acbb_screen *s = acbb_screens[i];
        if (s->running && s->running(a)) {
            sub = s->job_subject;
            nn = s->job_noun;
            busy = 1;
        }
    }
    if (subject) *subject = busy ? sub : "";
    if (noun) *noun = busy ? nn : "";
    return busy;
}
