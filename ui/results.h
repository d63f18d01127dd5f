/* acbb TUI — which scene the screens' results belong to (results.c). */
#ifndef ACBB_UI_RESULTS_H
#define ACBB_UI_RESULTS_H

#include <stddef.h>
#include "app.h"

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
