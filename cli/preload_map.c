/* acbb CLI — `acbb preload-map`: the preload window (include/acbb/
 * preload_map.h) as a table, a CSV and a gnuplot chart. */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acbb/tools/plot.h"
#include "acbb/tools/preload_map.h"
#include "commands.h"
#include "common.h"
#include "exit.h"
#include "preload_map_out.h"
#include "progress.h"
#include "say.h"

static int bad(const char *msg, const char *opt, const char *val)
{
    acbb_cli_say("preload-map: --%s %s: %s\n", opt, val, msg);
    return ACBB_EXIT_INPUT;
}

/* "LO:HI:N" (N whole, 1..ACBB_PMAP_MAX_AXIS): 0, or 2 with a message. */
static int axis(const acbb_cli_args *a, acbb_cli_opt o, double *lo, double *hi, int *n)
{
    const char *t = a->val[o], *name = acbb_cli_options[o].name;
    if (!t) return bad("required (LO:HI:N)", name, "");
    char *e1, *e2, *e3;
    errno = 0;
    *lo = strtod(t, &e1);
    if (*e1 != ':') return bad("expected LO:HI:N, e.g. 4000:16000:7", name, t);
    *hi = strtod(e1 + 1, &e2);
    if (*e2 != ':') return bad("expected LO:HI:N, e.g. 4000:16000:7", name, t);
    long k = strtol(e2 + 1, &e3, 10);
    if (*e3 || errno || k < 1 || k > ACBB_PMAP_MAX_AXIS)
        return bad("N must be a whole number 1..100", name, t);
    *n = (int)k;
    return 0;
}

/* A limit >= 0 from option o (absent: 0 = not checked). */
static int limit(const acbb_cli_args *a, acbb_cli_opt o, double *v)
{
    *v = 0.0;
    if (!a->val[o]) return 0;
    char *e;
    *v = strtod(a->val[o], &e);
    if (*e || !(*v >= 0.0) || !isfinite(*v))
        return bad("a number >= 0 (0 = not checked)", acbb_cli_options[o].name, a->val[o]);
    return 0;
}

static int options(const acbb_cli_args *a, acbb_pmap_opts *o)
{
    long jobs = 0;
    memset(o, 0, sizeof *o);
    int rc = axis(a, CLI_OPT_SPEEDS, &o->speed_lo, &o->speed_hi, &o->n_speeds);
    if (!rc) rc = axis(a, CLI_OPT_PRELOADS, &o->preload_lo, &o->preload_hi, &o->n_preloads);
    if (!rc) rc = limit(a, CLI_OPT_MAX_RISE, &o->max_rise_K);
    if (!rc) rc = limit(a, CLI_OPT_MIN_LIFE, &o->min_life_h);
    if (!rc) rc = limit(a, CLI_OPT_MIN_S0, &o->min_s0);
    if (!rc) rc = acbb_cli_count(a, CLI_OPT_JOBS, 0, 0, ACBB_CLI_MAX_JOBS, &jobs);
    o->jobs = (int)jobs;
    o->spring = a->val[CLI_OPT_SPRING] != NULL;
    return rc;
}

static void table(const acbb_pmap_opts *o, const acbb_pmap_cell *c, const acbb_pmap_row *r)
{
    printf("preload window: %s, transient from ambient\n"
           "limits: skid ratio <= 1", o->spring ? "spring (constant-force) preload"
                                                 : "displacement preload set at rest");
    if (o->max_rise_K > 0) printf(", rise <= %g K", o->max_rise_K);
    if (o->min_life_h > 0) printf(", L_nmr >= %g h", o->min_life_h);
    if (o->min_s0 > 0) printf(", s0 >= %g", o->min_s0);
    /* the legend on its own line: in the header it made 83 columns */
    printf(", no runaway\ncells: . ok, s skid, h hot, l life, 0 s0, R runaway, x failed\n\n"
           "%9s  %-*s  %s\n", "n rpm", o->n_preloads * 2, "cells", "window N");
    for (int s = 0; s < o->n_speeds; s++) {
        printf("%9.0f  ", r[s].speed_rpm);
        for (int p = 0; p < o->n_preloads; p++) {
            const char *v = acbb_pmap_verdict(&c[(size_t)s * o->n_preloads + p]);
            printf("%c ", !strcmp(v, "ok") ? '.' : !strcmp(v, "low_s0") ? '0'
                          : !strcmp(v, "runaway") ? 'R' : !strcmp(v, "failed") ? 'x'
                          : !strcmp(v, "short_life") ? 'l' : v[0]);
        }
        if (r[s].lo_N >= 0) printf(" %g .. %g\n", r[s].lo_N, r[s].hi_N);
        else printf(" none\n");
    }
    printf("\npreloads %g .. %g N in %d steps\n", o->preload_lo, o->preload_hi, o->n_preloads);
}

/* The chart (acbb_plot_pmap_chart, shared with the TUI's export): per
 * speed the skid-free floor and the limits' ceiling; a window end at the
 * grid's first or last preload is a marker of its own, not a limit. */
static int chart(const char *path, const acbb_pmap_opts *o, const acbb_pmap_row *r)
{
    acbb_plot_pmap c;
    acbb_plot_xy p;
    acbb_plot_pmap_chart(o, r, (size_t)o->n_speeds, &c, &p);
    int fmt = acbb_plot_format_from_name(path);
    if (fmt != ACBB_PLOT_PNG && fmt != ACBB_PLOT_SVG)
        return bad("FILE.png or FILE.svg", "plot", path);
    acbb_error e = { { 0 } };
    acbb_status st = acbb_plot_xy_files(&p, fmt == ACBB_PLOT_PNG ? path : NULL,
                                        fmt == ACBB_PLOT_SVG ? path : NULL, 1000, 600, &e);
    if (st == ACBB_OK) return 0;
    acbb_cli_say("preload-map: %s\n", acbb_cli_err_text(&e, st));
    return st == ACBB_EINVAL ? ACBB_EXIT_SOLVER : ACBB_EXIT_INTERNAL;
}

static int outputs(const acbb_cli_args *a, const acbb_pmap_opts *o, const acbb_pmap_cell *c,
                   const acbb_pmap_row *r)
{
    int rc = 0;
    if (a->val[CLI_OPT_CSV]) {
        acbb_cli_file f = { 0 };
        rc = acbb_cli_file_open(&f, a->val[CLI_OPT_CSV]);
        if (!rc) {
            acbb_cli_pmap_csv(f.out.f, c, (size_t)o->n_speeds * o->n_preloads);
            rc = acbb_cli_file_close(&f);
        }
    }
    if (!rc && a->val[CLI_OPT_PLOT]) rc = chart(a->val[CLI_OPT_PLOT], o, r);
    if (a->val[CLI_OPT_JSON] && acbb_cli_pmap_json(stdout, o, c, r) != 0) rc = ACBB_EXIT_INTERNAL;
    if (a->val[CLI_OPT_JSON] || (a->val[CLI_OPT_CSV] && !strcmp(a->val[CLI_OPT_CSV], "-")))
        return acbb_cli_worst(rc, acbb_cli_stdout_check(0));
    table(o, c, r);
    return acbb_cli_worst(rc, acbb_cli_stdout_check(0));
}

/* A cell whose run neither finished nor ran away (verdict "failed", x) is
 * a run that did not reach steady state: exit 3, as for every command
 * (README "Exit codes"); a runaway is a verdict of the map, not a failure.
 * Cancelled cells are the cancel's (acbb_cli_cancelled). */
static int failed_cells(const acbb_pmap_cell *c, size_t n, acbb_status st)
{
    size_t bad = 0, first = 0;
    for (size_t i = 0; i < n; i++)
        if (strcmp(acbb_pmap_verdict(&c[i]), "failed") == 0 && c[i].status != ACBB_CANCELLED &&
            bad++ == 0)
            first = i;
    if (bad == 0 || st == ACBB_CANCELLED) return 0;
    acbb_cli_say("preload-map: %zu of %zu cells failed (x); the first, %g rpm and "
            "%g N: %s\n", bad, n, c[first].speed_rpm, c[first].preload_N, c[first].status_name);
    return ACBB_EXIT_SOLVER;
}

int acbb_cli_cmd_preload_map(const acbb_cli_args *a)
{
    acbb_pmap_opts o;
    acbb_scene base;
    int rc = options(a, &o);
    if (!rc) rc = acbb_cli_load_scene(a, &base);
    if (rc) return rc;
    if (a->val[CLI_OPT_JSON] && a->val[CLI_OPT_CSV] && !strcmp(a->val[CLI_OPT_CSV], "-"))
        return bad("stdout holds one document: --json, or --csv -, not both", "csv", "-");
    if (a->val[CLI_OPT_PLOT]) {
        int fmt = acbb_plot_format_from_name(a->val[CLI_OPT_PLOT]);
        if (fmt != ACBB_PLOT_PNG && fmt != ACBB_PLOT_SVG)
            return bad("FILE.png or FILE.svg", "plot", a->val[CLI_OPT_PLOT]);
    }
    size_t n = (size_t)o.n_speeds * o.n_preloads;
    acbb_pmap_cell *cells = calloc(n, sizeof *cells);
    acbb_pmap_row *rows = calloc((size_t)o.n_speeds, sizeof *rows);
    if (!cells || !rows) {
        free(cells);
        free(rows);
        return ACBB_EXIT_INTERNAL;
    }
    o.cancel = acbb_cli_interrupt_begin();
    acbb_error e = { { 0 } };
    acbb_status st = acbb_preload_map(&base, &o, cells, rows, &e);
    acbb_cli_interrupt_end();
    if (st == ACBB_EINVAL) {
        acbb_cli_say("preload-map: %s\n", acbb_cli_err_text(&e, st));
        rc = ACBB_EXIT_INPUT;
    } else {
        rc = acbb_cli_worst(outputs(a, &o, cells, rows), failed_cells(cells, n, st));
        if (st == ACBB_CANCELLED)
            rc = acbb_cli_worst(rc, acbb_cli_cancelled("preload-map", "the cells that finished"));
    }
    free(cells);
    free(rows);
    return rc;
}
