/* acbb — GSL's error handler, off only while the engine works (internal). */
#ifndef ACBB_GSL_QUIET_H
#define ACBB_GSL_QUIET_H

/* GSL's default error handler calls abort(); the engine checks every GSL
 * status it gets and turns failures into named statuses, so while the
 * engine computes the handler must be off. Outside the engine it is the
 * host's business: a host that installed its own handler, or restored
 * GSL's default, gets it back when the engine call returns (issue 26).
 *
 * Every public entry point that can reach GSL brackets its work with
 * acbb_gsl_enter() ... acbb_gsl_leave() (sim.c: create, restart, step,
 * drive; ffi.c; lubricant_grade.c; the Morris design's generator in
 * sensitivity.c). Every other GSL call of the engine runs inside one of
 * these (the batch runner, the studies and the TUI reach GSL only through
 * acbb_sim_*). Calls nest (a per-thread depth), and
 * calls on several threads share one process-wide count: the handler is
 * switched off when the first engine call in the process starts and the
 * host's handler is put back when the last one ends, so two threads can
 * never restore each other's "off" half-way (a per-call save/restore
 * would: thread A saves the host's handler, B saves A's "off", A restores,
 * B restores "off" for good). Worker threads that an engine call starts
 * and joins (the dynamic level, the batch runner) run inside their
 * caller's bracket. Limit: a host thread that calls gsl_set_error_handler
 * while an engine call runs on another thread races with it, as with any
 * library that uses GSL; set the handler before or after engine calls. */
void acbb_gsl_enter(void);
void acbb_gsl_leave(void);

#endif
