/* acbb TUI — which scene the screens' results belong to (results.c). */
#ifndef ACBB_UI_RESULTS_H
#define ACBB_UI_RESULTS_H

#include <stddef.h>
#include "app.h"

/* The jobs whose scene is remembered (app.h hide.ran_on; the preload map
 * keeps its own copy, screen_preload.c) and the bits of hide.edited. */
enum { ACBB_RAN_SWEEP, ACBB_RAN_SENS, ACBB_RAN_BENCH, ACBB_RAN_COMPARE, ACBB_RAN_PRELOAD };

/* A job (ACBB_RAN_*) was started on the edited scene: its result belongs to
 * that scene and is hidden while the edited scene differs from it. */
void acbb_results_ran(acbb_app *a, int which);
/* 1 when job `which`'s result is finished (finished != 0) on a scene the
 * editor no longer holds (marked for acbb_results_note): hide it. */
int acbb_results_stale(acbb_app *a, int which, int finished);
/* Why job `which` shows no result when an edit hid it (for its idle
 * text), else NULL. */
const char *acbb_results_note(const acbb_app *a, int which);
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
