/* acbb TUI — gnuplot export (see export.h). The plotting itself is the
 * engine's; this file picks the set of plots and their file names. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "export.h"

#define ACC_PLOT_W 1000 /* as `acbb bench accuracy --plot` */
#define ACC_PLOT_H 650
#define SUFFIX_MAX 999  /* exports of one name kept side by side */

static const struct { acbb_plot_format fmt; const char *ext; } k_fmts[] = {
    { ACBB_PLOT_PNG, "png" }, { ACBB_PLOT_SVG, "svg" } };
#define N_FMTS (sizeof k_fmts / sizeof k_fmts[0])

/* dir/name suffix.ext into path, EINVAL if it does not fit. */
static acbb_status plot_path(char *path, size_t len, const char *dir, const char *name,
                             const char *suffix, const char *ext, acbb_error *err)
{
    int n = snprintf(path, len, "%s/%s%s.%s", dir, name, suffix, ext);
    if (n < 0 || (size_t)n >= len) return acbb_error_set(err, ACBB_EINVAL, "%s: path too long", dir);
    return ACBB_OK;
}

/* 1 if any dir/<base><suffix>.<png|svg> exists (or cannot be named). */
static int taken(const char *dir, const char *const *bases, size_t n, const char *suffix)
{
    for (size_t b = 0; b < n; b++)
        for (size_t f = 0; f < N_FMTS; f++) {
            char path[4096];
            acbb_error err = { { 0 } };
            if (plot_path(path, sizeof path, dir, bases[b], suffix, k_fmts[f].ext, &err) != ACBB_OK ||
                access(path, F_OK) == 0)
                return 1;
        }
    return 0;
}

acbb_status acbb_export_suffix(const char *dir, const char *const *bases, size_t n, char *suffix,
                               size_t len, acbb_error *err)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return acbb_error_set(err, ACBB_EIO, "cannot create %s: %s", dir, strerror(errno));
    snprintf(suffix, len, "%s", "");
    for (int k = 2; taken(dir, bases, n, suffix); k++) {
        if (k > SUFFIX_MAX)
            return acbb_error_set(err, ACBB_EIO, "%s already holds %d exports of %s: move some away", dir,
                                  SUFFIX_MAX, bases[0]);
        snprintf(suffix, len, "-%d", k);
    }
    return ACBB_OK;
}

acbb_status acbb_export_accuracy(const char *dir, const acbb_accuracy_row *rows, size_t n,
                                 const char *title, char *suffix, size_t slen, int *written,
                                 acbb_error *err)
{
    static const char *const base[1] = { "accuracy" };
    *written = 0;
    acbb_status rc = acbb_export_suffix(dir, base, 1, suffix, slen, err);
    for (size_t f = 0; rc == ACBB_OK && f < N_FMTS; f++) {
        char path[4096];
        rc = plot_path(path, sizeof path, dir, base[0], suffix, k_fmts[f].ext, err);
        if (rc == ACBB_OK)
            rc = acbb_plot_accuracy_file(rows, n, k_fmts[f].fmt, path, ACC_PLOT_W, ACC_PLOT_H,
                                         title, err);
        if (rc == ACBB_OK) (*written)++;
    }
    return rc;
}

acbb_status acbb_export_plots(const char *dir, const acbb_history *h, const acbb_snapshot *s,
                              const char *title, char *suffix, size_t slen, int *written,
                              acbb_error *err)
{
    static const acbb_plot_kind kinds[] = { ACBB_PLOT_TEMPERATURE, ACBB_PLOT_LOSSES,
                                            ACBB_PLOT_LOADS, ACBB_PLOT_ANGLES,
                                            ACBB_PLOT_HISTORY_LOADS };
    const size_t nk = sizeof kinds / sizeof kinds[0];
    const char *names[sizeof kinds / sizeof kinds[0]];
    for (size_t k = 0; k < nk; k++) names[k] = acbb_plot_kind_name(kinds[k]);
    *written = 0;
    acbb_status rc = acbb_export_suffix(dir, names, nk, suffix, slen, err);
    if (rc != ACBB_OK) return rc;
    acbb_plot_data d = { .history = h, .snapshot = s, .title = title };
    for (size_t k = 0; k < nk; k++)
        for (size_t f = 0; f < N_FMTS; f++) {
            char path[4096];
            rc = plot_path(path, sizeof path, dir, names[k], suffix, k_fmts[f].ext, err);
            if (rc == ACBB_OK) rc = acbb_plot_file(kinds[k], k_fmts[f].fmt, path, 800, 500, &d, err);
            if (rc != ACBB_OK) return rc;
            (*written)++;
        }
    return ACBB_OK;
}

acbb_status acbb_export_xy(const char *dir, const char *base, const acbb_plot_xy *p, int w, int h,
                           char png[], char svg[], size_t len, acbb_error *err)
{
    char suffix[16];
    acbb_status rc = acbb_export_suffix(dir, &base, 1, suffix, sizeof suffix, err);
    if (rc == ACBB_OK) rc = plot_path(png, len, dir, base, suffix, "png", err);
    if (rc == ACBB_OK) rc = plot_path(svg, len, dir, base, suffix, "svg", err);
    if (rc == ACBB_OK) rc = acbb_plot_xy_files(p, png, svg, w, h, err);
    return rc;
}

acbb_status acbb_export_tornado(const char *dir, const char *base, const acbb_tornado_bar *bars,
                                size_t n, double mid, const char *title, const char *xlabel,
                                char png[], char svg[], size_t len, acbb_error *err)
{
    char suffix[16];
    acbb_status rc = acbb_export_suffix(dir, &base, 1, suffix, sizeof suffix, err);
    if (rc == ACBB_OK) rc = plot_path(png, len, dir, base, suffix, "png", err);
    if (rc == ACBB_OK) rc = plot_path(svg, len, dir, base, suffix, "svg", err);
    /* The size of `acbb sensitivity --plot`: a bar of 22 pixels per input. */
    for (size_t f = 0; rc == ACBB_OK && f < N_FMTS; f++)
        rc = acbb_plot_tornado_file(bars, n, mid, k_fmts[f].fmt, f == 0 ? png : svg, 1000,
                                    200 + 22 * (int)n, title, xlabel, err);
    return rc;
}
