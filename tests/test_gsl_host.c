/* A host program that keeps GSL's error handler its own (issue 26 item 5).
 *
 * GSL's handler is process-wide and its default aborts. The library turns
 * it off only while one of its calls works and puts the host's back after
 * (src/base/gsl_quiet.h). Checked here from the host's side:
 * - with GSL's default (aborting) handler restored, a library call whose
 *   root bracket fails inside GSL (acbb_nu100_from_vi with a NaN viscosity
 *   index: gsl_root_fsolver_set meets a NaN end, GSL_EBADFUNC) returns NaN
 *   instead of killing the process, and the handler is the default again;
 * - acbb_run_preset_json on a scene that runs and on one that is refused
 *   returns a document, and the host's handler (default, then a counting
 *   one) is what the host set, and was never called;
 * - the case: after a first call, the host restores GSL's default
 *   handler and runs a scene whose ball solve meets a failed root bracket
 *   inside GSL (a DB pair with a nearly flat outer groove under 361 kN:
 *   the fallback's Brent bracket on the outer deflection does not straddle
 *   zero, gsl_root_fsolver_set calls the handler); before, the library had
 *   turned the handler off once, on its first Sim, so this call aborted;
 *   now the document comes back (diverged) and the handler is the default;
 * - two threads running documents at once, then the host's handler again
 *   (the process-wide count: neither thread leaves it off). */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "acbb/ffi.h"
#include "acbb/scene.h"
#include "acbb/tools/lubricant.h"
#include "slurp.h"
#include "tap.h"

static int host_calls;

static void host_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason, (void)file, (void)line, (void)gsl_errno;
    host_calls++;
}

static char *preset_text(const char *path)
{
    FILE *f = fopen(path, "r");
    char *s = f ? slurp(f) : NULL;
    if (f) fclose(f);
    return s;
}

/* The handler now, left in place. */
static gsl_error_handler_t *current_handler(void)
{
    gsl_error_handler_t *h = gsl_set_error_handler(NULL);
    gsl_set_error_handler(h);
    return h;
}

static int has_status(const char *doc, const char *status)
{
    char want[64];
    snprintf(want, sizeof want, "\"status\": \"%s\"", status);
    return doc && strstr(doc, want) != NULL;
}

static void test_failed_bracket(void)
{
    gsl_set_error_handler(NULL); /* GSL's default: abort() on any error */
    double y = acbb_nu100_from_vi(100.0, NAN);
    ok(isnan(y), "a NaN viscosity index: the failed bracket gives NaN, no abort (got %g)", y);
    ok(current_handler() == NULL, "after it GSL's default handler is back");
}

static const char *const k_static[] = { "fidelity.model=static" };
static const char *const k_ill[] = { "operating.axial_load_N=0", "operating.radial_load_N=500" };
static const char *const k_bracket[] = { "fidelity.model=static",
                                         "bearing.outer_groove_radius_mm=69.7003",
                                         "operating.axial_load_N=360784" };

static void run_doc(const char *text, const char *const *set, size_t n, const char *want,
                    gsl_error_handler_t *host, const char *what)
{
    gsl_set_error_handler(host);
    host_calls = 0;
    int st;
    char *doc = acbb_run_preset_json(text, set, n, &st);
    ok(has_status(doc, want), "%s: a document with status %s", what, want);
    ok(current_handler() == host && host_calls == 0,
       "%s: the host's handler is in place after the call and was never called (%d)", what,
       host_calls);
    acbb_string_free(doc);
}

static void *thread_run(void *text)
{
    int st;
    char *doc = acbb_run_preset_json(text, k_static, 1, &st);
    int good = has_status(doc, "converged");
    acbb_string_free(doc);
    return good ? text : NULL;
}

static void test_threads(const char *text)
{
    gsl_set_error_handler(host_handler);
    pthread_t t[2];
    int started = 0;
    for (int i = 0; i < 2; i++)
        started += pthread_create(&t[i], NULL, thread_run, (void *)text) == 0;
    int good = 0;
    for (int i = 0; i < started; i++) {
        void *r;
        pthread_join(t[i], &r);
        good += r != NULL;
    }
    ok(started == 2 && good == 2, "two threads at once: both documents converged");
    ok(current_handler() == host_handler, "after both threads the host's handler is in place");
}

int main(void)
{
    test_failed_bracket();
    char *text = preset_text("presets/7008C.ini");
    if (!text) {
        printf("Bail out! presets/7008C.ini not readable\n");
        return 1;
    }
    run_doc(text, k_static, 1, "converged", NULL, "default handler, a run");
    run_doc(text, k_ill, 2, "bad_input", NULL, "default handler, a refused scene"); /* the CLI's name for it (issue 28 item 4) */
    run_doc(text, k_static, 1, "converged", host_handler, "host handler, a run");
    char *pair = preset_text("presets/pair-DB-heated.ini");
    if (pair) run_doc(pair, k_bracket, 3, "diverged", NULL, "default handler, a failed bracket");
    else ok(0, "presets/pair-DB-heated.ini readable");
    test_threads(text);
    free(pair);
    free(text);
    return done_testing();
}
