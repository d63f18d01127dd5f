/* acbb TUI — the Preload screen's background job (screen_preload.c):
 * acbb_preload_map (include/acbb/preload_map.h) of the edited scene on
 * its own job thread (job.h), one speed row at a time so the screen can
 * follow it. The state is owned by the app (acbb_app.pmap). */
#ifndef ACBB_UI_SCREEN_PRELOAD_H
#define ACBB_UI_SCREEN_PRELOAD_H

#include "app.h"

/* Allocate a->pmap (its job and default ranges); ACBB_ENOMEM / job errors. */
acbb_status acbb_preload_new(acbb_app *a, acbb_error *err);
/* Cancel, join, free a->pmap. NULL is a no-op. */
void acbb_preload_free(acbb_app *a);
/* The job's wake-up pipe (app.c's select loop) and its drain. */
int acbb_preload_wake_fd(const acbb_app *a);
void acbb_preload_drain(acbb_app *a);
/* Once per frame: copy the published result, announce the end of a run. */
void acbb_preload_take(acbb_app *a);
/* Another preset was opened: cancel a running map, hide the last result. */
void acbb_preload_drop(acbb_app *a);
/* 1 while a map runs (as of the last frame). */
int acbb_preload_running(const acbb_app *a);

#endif
