/* The progress line's ETA (cli/progress.c): a log-linear fit of the
 * residual over wall time. For r(t) = r0 exp(-t/tau) the time to reach the
 * target is tau ln(r(now)/target) exactly (hand calculation below). And the
 * one SIGINT+SIGTERM handler (issue 16): the first signal sets the flag
 * and leaves both at their default action, so a second one kills; the
 * handler outlives a phase's end and the flag a phase's begin. */
#include <math.h>
#include <signal.h>
#include <string.h>
#include "tap.h"
#include "../cli/progress.h"

static bool is_default(int sig)
{
    struct sigaction sa;
    sigaction(sig, NULL, &sa);
    return sa.sa_handler == SIG_DFL;
}

/* Raised in-process: deterministic, unlike two kill(1)s racing the exit. */
static void handler_tests(void)
{
    const atomic_int *flag = acbb_cli_interrupt_begin();
    ok(!is_default(SIGINT) && !is_default(SIGTERM) && atomic_load(flag) == 0 &&
       acbb_cli_cancelled("x", NULL) == 0, "begin: both caught, flag clear, not cancelled");
    /* Between two phases (issue 28 item 14): end, then a signal before the
     * next begin is a cancel that the next phase sees, not a kill. */
    acbb_cli_interrupt_end();
    ok(!is_default(SIGINT) && !is_default(SIGTERM), "end of a phase: both still caught");
    raise(SIGTERM);
    ok(atomic_load(flag) == SIGTERM && acbb_cli_interrupted() &&
       flag == acbb_cli_interrupt_flag(), "SIGTERM between phases sets the one flag");
    ok(acbb_cli_interrupt_begin() == flag && atomic_load(flag) == SIGTERM,
       "the next phase's begin keeps it: the cancel is not forgotten");
    ok(is_default(SIGINT) && is_default(SIGTERM),
       "after the first signal both are at their default: a second one kills");
    ok(strcmp(acbb_cli_interrupt_name(), "SIGTERM") == 0, "the signal is named");
    ok(acbb_cli_cancelled("x", "kept") == 3, "cancelled: exit status 3");
    acbb_cli_interrupt_end();
}

int main(void)
{
    acbb_cli_decay_fit fit = { 0 };
    const double r0 = 2.0, tau = 3.0, target = 1e-4;
    ok(acbb_cli_decay_eta(&fit, 0.0, target) < 0, "no points: ETA unknown");
    for (int k = 0; k < 4; k++) acbb_cli_decay_add(&fit, 0.5 * k, r0 * exp(-0.5 * k / tau));
    ok(acbb_cli_decay_eta(&fit, 1.5, target) < 0, "4 points: still unknown (too few)");
    for (int k = 4; k < 30; k++) acbb_cli_decay_add(&fit, 0.5 * k, r0 * exp(-0.5 * k / tau));
    double now = 14.5, want = tau * log(r0 * exp(-now / tau) / target);
    is_close(acbb_cli_decay_eta(&fit, now, target), want, 1e-9, 0,
             "exponential decay: ETA = tau ln(r(now)/target) (= 15.21 s)");
    is_close(acbb_cli_decay_eta(&fit, 40.0, target), 0.0, 0, 0,
             "past the fitted crossing: ETA 0, never negative");

    acbb_cli_decay_fit rising = { 0 };
    for (int k = 0; k < 20; k++) acbb_cli_decay_add(&rising, k, 1e-3 * exp(0.1 * k));
    ok(acbb_cli_decay_eta(&rising, 19.0, target) < 0, "a rising residual: ETA unknown");

    acbb_cli_decay_fit junk = { 0 };
    for (int k = 0; k < 20; k++) {
        acbb_cli_decay_add(&junk, k, 0.0);
        acbb_cli_decay_add(&junk, k, NAN);
        acbb_cli_decay_add(&junk, k, -1.0);
    }
    ok(junk.n == 0, "zero, negative and NaN residuals are not fitted");

    /* Older points fade: after a change of rate the recent one dominates. */
    acbb_cli_decay_fit two = { 0 };
    for (int k = 0; k < 200; k++) {
        double t = 0.1 * k, r = t < 10 ? exp(-t) : exp(-10 - (t - 10) / 20.0);
        acbb_cli_decay_add(&two, t, r);
    }
    double eta = acbb_cli_decay_eta(&two, 19.9, 1e-8);
    double slow = 20.0 * log(exp(-10 - 9.9 / 20.0) / 1e-8);
    ok(eta > 0.8 * slow && eta < 1.25 * slow,
       "after the decay slows, the ETA follows the slow rate (%.1f s vs %.1f s)", eta, slow);

    handler_tests();
    printf("1..%d\n", tap_n);
    return tap_failed != 0;
}
