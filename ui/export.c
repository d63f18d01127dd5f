/* acbb TUI — gnuplot export (see export.h). The plotting itself is the
 * engine's acbb_plot_file; this file only picks the set of plots. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include "export.h"

acbb_status acbb_export_plots(const char *dir, const acbb_history *h, const acbb_snapshot *s,
                              const char *title, int *written, acbb_error *err)
{
    static const acbb_plot_kind kinds[] = { ACBB_PLOT_TEMPERATURE, ACBB_PLOT_LOSSES,
                                            ACBB_PLOT_LOADS, ACBB_PLOT_ANGLES };
    static const struct { acbb_plot_format fmt; const char *ext; } fmts[] = {
        { ACBB_PLOT_PNG, "png" }, { ACBB_PLOT_SVG, "svg" } };
    *written = 0;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return acbb_error_set(err, ACBB_EIO, "cannot create %s: %s", dir, strerror(errno));
    acbb_plot_data d = { .history = h, .snapshot = s, .title = title };
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++)
        for (size_t f = 0; f < sizeof fmts / sizeof fmts[0]; f++) {
            char path[4096];
            int n = snprintf(path, sizeof path, "%s/%s.%s", dir, acbb_plot_kind_name(kinds[k]),
                             fmts[f].ext);
            if (n < 0 || (size_t)n >= sizeof path)
                return acbb_error_set(err, ACBB_EINVAL, "%s: path too long", dir);
            acbb_status rc = acbb_plot_file(kinds[k], fmts[f].fmt, path, 800, 500, &d, err);
            if (rc != ACBB_OK) return rc;
            (*written)++;
        }
    return ACBB_OK;
}
