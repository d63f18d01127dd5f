/* acbb — GSL's error handler off, once (gsl_quiet.h). GSL keeps its handler
 * in one process-global pointer; pthread_once makes setting it race-free
 * when several threads create their first Sims at once. */
#include <pthread.h>
#include <gsl/gsl_errno.h>
#include "gsl_quiet.h"

static void quiet(void) { gsl_set_error_handler_off(); }

void acbb_gsl_quiet(void)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, quiet);
}
