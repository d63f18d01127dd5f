/* acbb TUI — gnuplot export (see export.h). The plotting itself is the
 * engine's acbb_plot_file; this file only picks the set of plots. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "export.h"

#define ACC_PLOT_W 1000 /* as `acbb bench accuracy --plot` */
#define ACC_PLOT_H 650

static const struct { acbb_plot_format fmt; const char *ext; } k_fmts[] = {
    { ACBB_PLOT_PNG, "png" }, { ACBB_PLOT_SVG, "svg" } };

static acbb_status make_dir(const char *dir, acbb_error *err)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return acbb_error_set(err, ACBB_EIO, "cannot create %s: %s", dir, strerror(errno));
    return ACBB_OK;
}

/* dir/name.ext into path, EINVAL if it does not fit. */
static acbb_status plot_path(char *path, size_t len, const char *dir, const char *name,
                             const char *ext, acbb_error *err)
{
    int n = snprintf(path, len, "%s/%s.%s", dir, name, ext);
    if (n < 0 || (size_t)n >= len) return acbb_error_set(err, ACBB_EINVAL, "%s: path too long", dir);
    return ACBB_OK;
}

acbb_status acbb_export_accuracy(const char *dir, const acbb_accuracy_row *rows, size_t n,
                                 const char *title, int *written, acbb_error *err)
{
    *written = 0;
    acbb_status rc = make_dir(dir, err);
    for (size_t f = 0; rc == ACBB_OK && f < sizeof k_fmts / sizeof k_fmts[0]; f++) {
        char path[4096];
        rc = plot_path(path, sizeof path, dir, "accuracy", k_fmts[f].ext, err);
        if (rc == ACBB_OK)
            rc = acbb_plot_accuracy_file(rows, n, k_fmts[f].fmt, path, ACC_PLOT_W, ACC_PLOT_H,
                                         title, err);
        if (rc == ACBB_OK) (*written)++;
    }
    return rc;
}

acbb_status acbb_export_plots(const char *dir, const acbb_history *h, const acbb_snapshot *s,
                              const char *title, int *written, acbb_error *err)
{
    static const acbb_plot_kind kinds[] = { ACBB_PLOT_TEMPERATURE, ACBB_PLOT_LOSSES,
                                            ACBB_PLOT_LOADS, ACBB_PLOT_ANGLES,
                                            ACBB_PLOT_HISTORY_LOADS };
    *written = 0;
    acbb_status rc = make_dir(dir, err);
    if (rc != ACBB_OK) return rc;
    acbb_plot_data d = { .history = h, .snapshot = s, .title = title };
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        for (size_t f = 0; f < sizeof k_fmts / sizeof k_fmts[0]; f++) {
            char path[4096];
            rc = plot_path(path, sizeof path, dir, acbb_plot_kind_name(kinds[k]), k_fmts[f].ext, err);
            if (rc == ACBB_OK) rc = acbb_plot_file(kinds[k], k_fmts[f].fmt, path, 800, 500, &d, err);
            if (rc != ACBB_OK) return rc;
            (*written)++;
        }
    return ACBB_OK;
}
