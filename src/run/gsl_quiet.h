/* acbb — GSL's error handler, process-wide (internal). */
#ifndef ACBB_GSL_QUIET_H
#define ACBB_GSL_QUIET_H

/* Turn off GSL's default handler (it calls abort()) once per process: the
 * engine checks every GSL status it gets and turns failures into named
 * statuses, so a library client (an FFI caller, the Python module) that
 * never heard of GSL must not be aborted by a root bracket that fails in
 * a hard case. A client that wants its own handler sets it after its
 * first acbb_sim_create. */
void acbb_gsl_quiet(void);

#endif
