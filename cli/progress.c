/* acbb CLI — progress line and Ctrl-C for long runs (progress.h). */
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/tools/json.h"
#include "acbb/tools/measure.h"
#include "acbb/tools/schedule.h"
#include "acbb/units.h"
#include "exit.h"
#include "progress.h"
#include "say.h"

/* A signal handler can only reach file-scope state: the CLI's one flag
 * (the engine keeps none; it is handed the pointer). It holds the signal
 * number, so the message can name it; the engine only tests non-zero. */
static atomic_int interrupt_flag;

static void on_interrupt(int sig)
{
    atomic_store(&interrupt_flag, sig);
    /* The first SIGINT or SIGTERM asks the command to stop; the next one
     * of either finds the default action and kills at once. */
    struct sigaction dfl = { .sa_handler = SIG_DFL };
    sigemptyset(&dfl.sa_mask);
    sigaction(SIGINT, &dfl, NULL);
    sigaction(SIGTERM, &dfl, NULL);
}

/* Installed once, at a command's first long phase, and kept until the
 * process ends (issue 28 item 14): a command with several phases (study,
 * report) used to restore the default action between them and reset the
 * flag at the next, so a signal in that gap killed the process (exit 130)
 * or was forgotten (exit 0). Now a signal at any time after the first
 * phase began is a cancel, and the next one still kills (on_interrupt). */
static bool installed;

const atomic_int *acbb_cli_interrupt_begin(void)
{
    if (installed) return &interrupt_flag;
    installed = true;
    /* SA_RESTART: the cancel travels through the flag alone; a large
     * stdout write or a file commit under way must not fail with EINTR
     * and turn a cancel (exit 3) into a write error (exit 4). */
    struct sigaction sa = { .sa_handler = on_interrupt, .sa_flags = SA_RESTART };
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    return &interrupt_flag;
}

const atomic_int *acbb_cli_interrupt_flag(void) { return &interrupt_flag; }

/* The end of a long phase: the handler stays (above). */
void acbb_cli_interrupt_end(void) {}

/* A command's own stop is -1: the engine stops as on a signal, but no
 * "cancelled by" message is printed (no signal came). */
void acbb_cli_interrupt_stop(void)
{
    int none = 0;
    atomic_compare_exchange_strong(&interrupt_flag, &none, -1);
}

bool acbb_cli_interrupted(void) { return atomic_load(&interrupt_flag) > 0; }

const char *acbb_cli_interrupt_name(void)
{
    int sig = atomic_load(&interrupt_flag);
    return sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "a signal";
}

int acbb_cli_cancelled(const char *cmd, const char *kept)
{
    if (!acbb_cli_interrupted()) return 0;
    acbb_cli_say("%s: cancelled by %s%s%s\n", cmd, acbb_cli_interrupt_name(),
            kept && *kept ? "; " : "", kept ? kept : "");
    return ACBB_EXIT_CANCELLED;
}

void acbb_cli_cancelled_json(FILE *f, const char *cmd, const char *kept)
{
    /* By hand, not cJSON: test_progress links this file alone; cmd and kept
     * are the callers' constant texts (no quote or backslash to escape). */
    fprintf(f, "{\"schema_version\": %d, \"status\": \"cancelled\", \"command\": \"%s\", "
            "\"signal\": \"%s\", \"message\": \"%s\"}\n", ACBB_JSON_SCHEMA_VERSION, cmd,
            acbb_cli_interrupt_name(), kept ? kept : "");
}

bool acbb_cli_progress_wanted(FILE *f)
{
    const char *env = getenv("ACBB_PROGRESS");
    if (env && *env) return strcmp(env, "0") != 0;
    return isatty(fileno(f)) != 0;
}

/* ---- the residual's decay ---- */

/* Each new point multiplies the old weights by this: about the last 10
 * steps count, so the fit follows the run's slowest (final) decay rate. */
#define FIT_FADE 0.9
#define FIT_MIN_POINTS 10

void acbb_cli_decay_add(acbb_cli_decay_fit *fit, double t, double residual)
{
    if (!(residual > 0.0) || !isfinite(residual) || !isfinite(t)) return;
    double y = log(residual);
    fit->s0 = FIT_FADE * fit->s0 + 1.0;
    fit->sx = FIT_FADE * fit->sx + t;
    fit->sy = FIT_FADE * fit->sy + y;
    fit->sxx = FIT_FADE * fit->sxx + t * t;
    fit->sxy = FIT_FADE * fit->sxy + t * y;
    fit->n++;
}

double acbb_cli_decay_eta(const acbb_cli_decay_fit *fit, double now, double target)
{
    if (fit->n < FIT_MIN_POINTS || !(target > 0.0)) return -1.0;
    double mx = fit->sx / fit->s0, my = fit->sy / fit->s0;
    double vxx = fit->sxx / fit->s0 - mx * mx, vxy = fit->sxy / fit->s0 - mx * my;
    if (!(vxx > 1e-12)) return -1.0;        /* all points at one instant */
    double slope = vxy / vxx;               /* d ln(residual) / dt, 1/s */
    if (!(slope < 0.0)) return -1.0;        /* not decaying (yet) */
    double y_now = my + slope * (now - mx);
    double eta = (log(target) - y_now) / slope;
    if (eta < 0.0) eta = 0.0;
    return isfinite(eta) && eta < 1e7 ? eta : -1.0;
}

/* ---- the line ---- */

void acbb_cli_progress_init(acbb_cli_progress *p, FILE *f, double steady_tol)
{
    memset(p, 0, sizeof *p);
    p->f = f;
    p->target = steady_tol;
    p->on = acbb_cli_progress_wanted(f);
    p->t0_ms = acbb_now_ms();
    p->last_ms = -1e9;
}

static void format_eta(char *buf, size_t n, double eta)
{
    if (eta < 0.0) snprintf(buf, n, "ETA ?");
    else if (eta < 120.0) snprintf(buf, n, "ETA %.0f s", eta);
    else if (eta < 7200.0) snprintf(buf, n, "ETA %.0f min", eta / 60.0);
    else snprintf(buf, n, "ETA %.1f h", eta / 3600.0);
}

/* Write `line` over the previous one (padding instead of an ANSI erase). */
static void show_line(acbb_cli_progress *p, const char *line, int len)
{
    if (len < 0) return;
    fprintf(p->f, "\r%s%*s", line, p->shown > len ? p->shown - len : 0, "");
    fflush(p->f);
    p->shown = len;
}

void acbb_cli_progress_note(acbb_cli_progress *p, const char *fmt, ...)
{
    if (!p->on) return;
    char line[160];
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    show_line(p, line, len < (int)sizeof line ? len : (int)sizeof line - 1);
}

void acbb_cli_progress_step(acbb_cli_progress *p, const acbb_snapshot *snap)
{
    if (!p->on) return;
    double now_ms = acbb_now_ms(), now = (now_ms - p->t0_ms) / 1e3;
    if (snap->iteration > 0) acbb_cli_decay_add(&p->fit, now, snap->residual);
    if (now_ms - p->last_ms < 250.0) return;   /* at most ~4 redraws a second */
    p->last_ms = now_ms;
    char eta[32], line[200], sched[64] = "";
    acbb_operating op = { .finished = true };
    if (p->schedule) acbb_schedule_at(p->schedule, snap->time, &op);
    /* The residual decays only once the schedule has ended: no ETA before. */
    double e = op.finished ? acbb_cli_decay_eta(&p->fit, now, p->target) : -1.0;
    format_eta(eta, sizeof eta, e);
    if (p->schedule)
        snprintf(sched, sizeof sched, "  row %d/%d %.0f rpm%s", op.row, op.n_rows,
                 acbb_rads_to_rpm(op.inner_speed), op.finished ? " (done)" : "");
    /* Over a minute to go (a dynamic-level run, issue 20 item 8): say how
     * to bound it. */
    int len = snprintf(line, sizeof line,
                       "step %ld  residual %.2e / %.1e K/s  t %.0f s%s  %s  (Ctrl-C stops%s)",
                       snap->iteration, snap->residual, p->target, snap->time, sched, eta,
                       e > 60.0 ? "; long run: --max-wall S bounds it" : "");
    show_line(p, line, len < (int)sizeof line ? len : (int)sizeof line - 1);
}

void acbb_cli_progress_end(acbb_cli_progress *p)
{
    if (!p->on || p->shown == 0) return;
    fprintf(p->f, "\r%*s\r", p->shown, "");
    fflush(p->f);
    p->shown = 0;
}

void acbb_cli_progress_draw(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fflush(stderr);
}

void acbb_cli_counter_init(acbb_cli_counter *c, const char *name)
{
    *c = (acbb_cli_counter){ .show = acbb_cli_progress_wanted(stderr), .t0_ms = acbb_now_ms(),
                             .name = name };
}

void acbb_cli_counter_step(acbb_cli_counter *c, size_t done, size_t total)
{
    double now = acbb_now_ms(), s = 1e-3 * (now - c->t0_ms);
    if (!c->show || (done < total && now - c->last_ms < 200.0)) return;
    c->last_ms = now;
    double rate = s > 0.0 ? (double)done / s : 0.0;
    fprintf(stderr, "\r%s: %zu/%zu runs, %.1f runs/s", c->name, done, total, rate);
    if (done < total && rate > 0.0) fprintf(stderr, ", ETA %.0f s", (double)(total - done) / rate);
    fputs(done >= total ? "\n" : "   ", stderr);
}
