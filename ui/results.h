/* acbb TUI — which scene the screens' results belong to (results.c). */
#ifndef ACBB_UI_RESULTS_H
#define ACBB_UI_RESULTS_H

#include <stddef.h>
#include "app.h"

#include "screens.h"

/* A job's result belongs to the scene it started on (the screen keeps a
 * copy, ran_on) and is hidden while the edited scene differs from it. */

/* 1 when screen s's job has a finished result (finished != 0) of ran_on and
 * the editor no longer holds that scene (marked for acbb_results_note): hide it. */
int acbb_results_stale(acbb_app *a, const acbb_screen *s, const acbb_scene *ran_on, int finished);
/* Why screen s shows no result when an edit hid it (for its idle text),
 * else NULL. */
const char *acbb_results_note(const acbb_app *a, const acbb_screen *s);
/* Another preset was opened: cancel the background work of the last one
 * and hide every screen's results of it. */
void acbb_results_drop(acbb_app *a);
/* Once per frame: copy each job's published state (hidden ones read as
 * never started) and announce the ends of runs. */
void acbb_results_take(acbb_app *a);
/* 1 while any work runs (the main run, the comparison, a benchmark,
 * sweep, sensitivity run or preload map); *subject names it to start a
 * sentence ("A sweep"), *noun after "the" ("sweep"). NULLs allowed. */
int acbb_results_busy(const acbb_app *a, const char **subject, const char **noun);

#endif
