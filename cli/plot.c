/* acbb CLI — `acbb plot` and the `--plot FILE` writer (see plot.h).
 *
 * A thin client of the engine API: load the preset, apply --set edits,
 * step the Sim to the end of its run while every published snapshot goes
 * into an acbb_history, then hand history and final snapshot to the plot
 * module. Arguments come parsed from the command table (args.h); no user
 * text reaches a shell (the engine's plot module spawns gnuplot directly). */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/history.h"
#include "acbb/tools/plot.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "commands.h"
#include "common.h"
#include "exit.h"
#include "plot.h"
#include "say.h"

#define PLOT_FILE_W 1000
#define PLOT_FILE_H 600
#define PLOT_DUMB_W 80
#define PLOT_DUMB_H 25
#define PLOT_N_KINDS 5
_Static_assert(PLOT_N_KINDS <= ACBB_CLI_PLOT_SIBLINGS, "the guard's room for siblings");

/* The options of one `acbb plot`, as typed (NULL when absent). */
typedef struct {
    const char *kind;   /* NULL = temperature */
    const char *out;    /* NULL = dumb */
    bool dumb;
    const char *size;   /* "WxH", or NULL */
} plot_args;

static int bad_usage(const char *what, const char *arg)
{
    acbb_cli_say("plot: %s%s\ntry `acbb help plot`\n", what, arg ? arg : "");
    return ACBB_EXIT_INPUT;
}

/* "WxH" pixels, a print width ("85mm", "8.5cm", "85mmx60mm"), "column" or
 * "full" (acbb_plot_parse_size); the plot module checks the range. */
int acbb_cli_parse_size(const char *text, int *w, int *h)
{
    if (acbb_plot_parse_size(text, w, h) == 0) return 0;
    acbb_cli_say("--size %s: expected WxH pixels (e.g. 1000x600), a print width "
            "(85mm, 8.5cm, 85mmx60mm) or column (8.5 cm) / full (17.5 cm)\n", text);
    return ACBB_EXIT_INPUT;
}

/* ---- run ---- */

static int record_hook(void *ctx, const acbb_sim *sim)
{
    acbb_snapshot snap;
    acbb_sim_snapshot(sim, &snap);
    acbb_history_push(ctx, &snap);
    return 0;
}

/* Step to the end of the run, recording every published step (DESIGN.md
 * "Data flow"). The engine ends the run itself; the call budget only
 * guards against one that never stops. Returns 0, 3 or 4. */
static int run_recording(const acbb_scene *sc, acbb_history *h, acbb_snapshot *snap)
{
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_sim_create(sc, NULL, &sim, &err);
    if (st != ACBB_OK) {
        acbb_cli_say("%s\n", acbb_cli_err_text(&err, st));
        return acbb_cli_exit_for(st);
    }
    acbb_history_init(h);
    acbb_run_ctl ctl = { .hook = record_hook, .ctx = h };
    acbb_sim_drive(sim, &ctl);
    acbb_sim_snapshot(sim, snap);
    acbb_sim_free(sim);
    if (snap->state != ACBB_RUN_CONVERGED) {
        acbb_cli_say("%s: %s (plotting the last good state)\n",
                acbb_run_status_name(snap), snap->message);
        return ACBB_EXIT_SOLVER;
    }
    return 0;
}

/* ---- writing ---- */

static int plot_failed(const acbb_error *err, acbb_status st)
{
    acbb_cli_say("%s — plot not written\n",
            err->msg[0] ? err->msg : acbb_status_name(st));
    return st == ACBB_EINVAL ? ACBB_EXIT_INPUT : ACBB_EXIT_INTERNAL;
}

/* `path` with "-<kind>" inserted before its extension (dir/x.png ->
 * dir/x-losses.png). A malloc'd string, NULL when out of memory. */
static char *sibling_path(const char *path, acbb_plot_kind kind)
{
    const char *base = strrchr(path, '/');
    const char *dot = strrchr(base ? base + 1 : path, '.');
    size_t stem = dot ? (size_t)(dot - path) : strlen(path);
    const char *name = acbb_plot_kind_name(kind);
    size_t n = strlen(path) + strlen(name) + 2;
    char *out = malloc(n);
    if (out) snprintf(out, n, "%.*s-%s%s", (int)stem, path, name, dot ? dot : "");
    return out;
}

size_t acbb_cli_plot_siblings(const char *path, bool all, char (*out)[CLI_PATH_MAX], size_t max)
{
    size_t n = 0;
    for (int k = all ? 0 : 1; k < PLOT_N_KINDS && n < max; k++) {
        char *p = sibling_path(path, (acbb_plot_kind)k);
        if (!p) break;
        snprintf(out[n++], CLI_PATH_MAX, "%s", p);
        free(p);
    }
    return n;
}

/* Write the kinds in [first, last] to files; `own` is the kind that goes to
 * `path` itself (-1: every kind goes to a sibling). Returns 0, 2 or 4. */
static int write_files(const char *path, int own, int first, int last, int w, int h,
                       const acbb_plot_data *d)
{
    acbb_plot_format fmt = (acbb_plot_format)acbb_plot_format_from_name(path);
    for (int k = first; k <= last; k++) {
        char *target = k == own ? NULL : sibling_path(path, (acbb_plot_kind)k);
        if (k != own && !target) {
            acbb_cli_say("out of memory — plot not written\n");
            return ACBB_EXIT_INTERNAL;
        }
        acbb_error err = { { 0 } };
        acbb_status st = acbb_plot_file((acbb_plot_kind)k, fmt, target ? target : path, w, h, d,
                                        &err);
        free(target);
        if (st != ACBB_OK) return plot_failed(&err, st);
    }
    return 0;
}

static int write_dumb(int first, int last, int cols, int rows, const acbb_plot_data *d)
{
    /* Each cell is one byte in the dumb terminal's ASCII output; the slack
     * covers newlines and trailing blanks. */
    size_t cap = (size_t)(cols + 2) * (size_t)(rows + 2) + 1024;
    char *text = malloc(cap);
    if (!text) return ACBB_EXIT_INTERNAL;
    int rc = 0;
    for (int k = first; k <= last && !rc; k++) {
        acbb_error err = { { 0 } };
        acbb_status st = acbb_plot_dumb((acbb_plot_kind)k, cols, rows, d, text, cap, &err);
        if (st != ACBB_OK) {
            rc = plot_failed(&err, st);
        } else {
            /* gnuplot leaves the last row without a newline. */
            size_t len = strlen(text);
            fputs(text, stdout);
            if (len == 0 || text[len - 1] != '\n') fputc('\n', stdout);
        }
    }
    free(text);
    if (!rc && (fflush(stdout) != 0 || ferror(stdout))) {
        acbb_cli_say("cannot write to stdout\n");
        rc = ACBB_EXIT_INTERNAL;
    }
    return rc;
}

int acbb_cli_plot_check_path(const char *path)
{
    int fmt = acbb_plot_format_from_name(path);
    if (fmt != ACBB_PLOT_PNG && fmt != ACBB_PLOT_SVG) {
        acbb_cli_say("--plot %s: expected a .png or .svg file name\n", path);
        return ACBB_EXIT_INPUT;
    }
    return 0;
}

int acbb_cli_write_plot(const char *path, const acbb_history *h, const acbb_snapshot *final,
                        const char *title)
{
    int rc = acbb_cli_plot_check_path(path);
    if (rc) return rc;
    acbb_plot_data d = { h, final, title };
    return write_files(path, ACBB_PLOT_TEMPERATURE, 0, PLOT_N_KINDS - 1, PLOT_FILE_W,
                       PLOT_FILE_H, &d);
}

/* The preset's file name without directory and ".ini": the plot title. */
static void preset_title(const char *preset, char *buf, size_t n)
{
    const char *base = strrchr(preset, '/');
    base = base ? base + 1 : preset;
    size_t len = strlen(base);
    if (len > 4 && strcmp(base + len - 4, ".ini") == 0) len -= 4;
    snprintf(buf, n, "%.*s", (int)len, base);
}

/* Options checked before the (possibly long) run. */
static int check_plot_args(const plot_args *a, int *first, int *last, int *w, int *h)
{
    if (!a->kind || strcmp(a->kind, "all") != 0) {
        int k = a->kind ? acbb_plot_kind_from_name(a->kind) : ACBB_PLOT_TEMPERATURE;
        if (k < 0) return bad_usage("unknown --kind ", a->kind);
        *first = *last = k;
    }
    if (a->out) {
        int fmt = acbb_plot_format_from_name(a->out);
        if (fmt != ACBB_PLOT_PNG && fmt != ACBB_PLOT_SVG)
            return bad_usage("--out needs a .png or .svg file name: ", a->out);
    }
    *w = a->out ? PLOT_FILE_W : PLOT_DUMB_W;
    *h = a->out ? PLOT_FILE_H : PLOT_DUMB_H;
    if (!a->size) return 0;
    if (acbb_cli_parse_size(a->size, w, h)) return ACBB_EXIT_INPUT;
    if (!a->out && strspn(a->size, "0123456789xX") != strlen(a->size)) {
        acbb_cli_say("plot: --size %s: with --dumb the size is WxH characters\n", a->size);
        return ACBB_EXIT_INPUT;
    }
    acbb_error err = { { 0 } };
    int fmt = a->out ? acbb_plot_format_from_name(a->out) : ACBB_PLOT_DUMB;
    if (acbb_plot_check_size((acbb_plot_format)fmt, *w, *h, &err) != ACBB_OK) {
        acbb_cli_say("plot: --size: %s\n", err.msg);
        return ACBB_EXIT_INPUT;
    }
    return 0;
}

int acbb_cli_plot(const acbb_cli_args *args)
{
    plot_args a = { args->val[CLI_OPT_KIND], args->val[CLI_OPT_OUT],
                    args->val[CLI_OPT_DUMB] != NULL, args->val[CLI_OPT_SIZE] };
    int first = 0, last = PLOT_N_KINDS - 1, w = 0, h = 0;
    int rc = a.out && a.dumb ? bad_usage("--out and --dumb exclude each other", NULL) : 0;
    if (!rc) rc = check_plot_args(&a, &first, &last, &w, &h);
    acbb_scene *sc = rc ? NULL : malloc(sizeof *sc);
    acbb_history *hist = rc ? NULL : malloc(sizeof *hist);
    acbb_snapshot *snap = rc ? NULL : malloc(sizeof *snap);
    if (!rc && (!sc || !hist || !snap)) rc = ACBB_EXIT_INTERNAL;
    if (!rc) rc = acbb_cli_load_scene(args, sc);
    /* A set's "all" takes its two plots as well (issue 29 item 8). */
    if (!rc && last == PLOT_N_KINDS - 1 && first != last && sc->set_arrangement != ACBB_SET_SINGLE)
        last = ACBB_PLOT_SET_TEMPERATURE;
    if (!rc) {
        int run_rc = run_recording(sc, hist, snap);
        /* A run that stopped early still has a last good state to show. */
        if (run_rc == 0 || run_rc == ACBB_EXIT_SOLVER) {
            char title[128];
            preset_title(args->preset, title, sizeof title);
            acbb_plot_data d = { hist, snap, title };
            int prc = a.out ? write_files(a.out, first == last ? first : -1, first, last, w, h,
                                          &d)
                            : write_dumb(first, last, w, h, &d);
            rc = acbb_cli_worst(prc, run_rc);
        } else {
            rc = run_rc;
        }
    }
    free(sc);
    free(hist);
    free(snap);
    return rc;
}
