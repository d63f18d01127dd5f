/* acbb — plots through a gnuplot pipe (DESIGN.md "Practical notes").
 *
 * One short-lived gnuplot process per plot, started with posix_spawnp (no
 * shell, so no user text ever reaches one): stdin from a CLOEXEC pipe,
 * stdout to /dev/null (or captured for the dumb terminal), stderr captured
 * for the first error line. Data travel as named datablocks written with
 * %.17g; paths are single-quoted with ' doubled; `set termoption
 * noenhanced`. SIGPIPE is ignored while writing. If gnuplot is missing or
 * fails, the call returns ACBB_EIO with a clear message and nothing else
 * happens (the caller keeps running). No printing.
 *
 * Ownership: all inputs are read only during the call. */
#ifndef ACBB_PLOT_H
#define ACBB_PLOT_H

#include <stddef.h>
#include "acbb/tools/accuracy.h"
#include "acbb/tools/history.h"
#include "acbb/tools/preload_map.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { ACBB_PLOT_PNG, ACBB_PLOT_SVG, ACBB_PLOT_DUMB } acbb_plot_format;

typedef enum {
    ACBB_PLOT_TEMPERATURE,   /* outer ring, inner ring, ball, housing vs time */
    ACBB_PLOT_LOSSES,        /* the five losses and the total vs time */
    ACBB_PLOT_LOADS,         /* Qi, Qo per ball vs azimuth (final state) */
    ACBB_PLOT_ANGLES,        /* alpha_i, alpha_o per ball vs azimuth (final state) */
    ACBB_PLOT_HISTORY_LOADS, /* Qi, Qo of ball 0 vs time */
    ACBB_PLOT_SET_PRELOAD,   /* a bearing set's preload vs time (MODEL.md 14) */
    ACBB_PLOT_SET_TEMPERATURE /* each bearing's outer ring vs time (a set) */
} acbb_plot_kind;

typedef struct {
    const acbb_history *history;     /* may be NULL for the per-ball kinds */
    const acbb_snapshot *snapshot;   /* may be NULL for the history kinds */
    const char *title;               /* plain text (noenhanced); may be NULL */
} acbb_plot_data;

/* Parse "png", "svg", "dumb" / a file name's extension; -1 if unknown. */
int acbb_plot_format_from_name(const char *name);
/* Parse "temperature", "losses", "loads", "angles", "history-loads",
 * "set-preload", "set-temperature"; -1 if unknown. */
int acbb_plot_kind_from_name(const char *name);
const char *acbb_plot_kind_name(acbb_plot_kind k);

/* Write a PNG (pngcairo) or SVG plot to `path`, width x height pixels.
 * The file is written by gnuplot to a temporary name and renamed into
 * place only on success. */
acbb_status acbb_plot_file(acbb_plot_kind kind, acbb_plot_format fmt, const char *path,
                           int width, int height, const acbb_plot_data *d, acbb_error *err);

/* Render with gnuplot's dumb terminal (cols x rows characters) into text
 * (NUL-terminated, truncated to text_len). */
acbb_status acbb_plot_dumb(acbb_plot_kind kind, int cols, int rows, const acbb_plot_data *d,
                           char *text, size_t text_len, acbb_error *err);

/* Check a plot size before doing the work that feeds the plot: pixels for
 * PNG/SVG, characters for dumb. ACBB_OK or ACBB_EINVAL with the range. */
acbb_status acbb_plot_check_size(acbb_plot_format fmt, int width, int height, acbb_error *err);

/* The accuracy-versus-time plot of `acbb bench accuracy`
 * (include/acbb/tools/accuracy.h): x = median wall time (ms), y = max(e_loss, e_T)
 * in %, both log scale; one point set per knob, each point labelled with its
 * value; a dashed line at ACBB_ACCURACY_FRONTIER_TOL. Errors below
 * 1e-10 % (the references' exact 0 among them) are drawn at 1e-10 %, which
 * the y label says. Rows that failed or were skipped are left out.
 * PNG or SVG as acbb_plot_file; ACBB_EINVAL if no row can be drawn. */
acbb_status acbb_plot_accuracy_file(const acbb_accuracy_row *rows, size_t n,
                                    acbb_plot_format fmt, const char *path, int width,
                                    int height, const char *title, acbb_error *err);

/* ---- general x-y plot (src/io/plot_xy.c; the seed's figures, figures.h) ---- */

typedef struct {
    const char *label;       /* key entry, plain text */
    const double *x, *y;     /* n points; a point with a non-finite coordinate is left out */
    size_t n;
    int color;               /* gnuplot linecolor index 1..; 0: by series order */
    int dash;                /* gnuplot dashtype: 0 or 1 solid, 2 dashed, 3 dotted, ... */
    int points;              /* 0 lines; 1 lines with markers (about 8 on a dense series);
                              * 2 markers only. The marker's shape follows the colour
                              * (eight shapes), filled when solid, open when dashed, so
                              * families stay apart in grey */
} acbb_plot_series;

typedef struct {
    const char *title, *xlabel, *ylabel; /* plain text (noenhanced); title may be NULL */
    const acbb_plot_series *series;
    size_t n_series;
} acbb_plot_xy;

/* A figure's key made of its own entries (issue 29 item 9): when series
 * differ in two ways (a quantity and a load, TE and WTE), one entry per
 * value of each (the loads by colour and marker, TE solid and WTE dashed)
 * instead of one per series. Each entry is drawn as a sample only: label,
 * color (<= 0: black), dash and points of an acbb_plot_series (x, y, n
 * unused). With a key the series themselves have no entry. */
typedef struct {
    const acbb_plot_series *key;
    size_t n_key;
} acbb_plot_look;

/* Write one x-y plot as PNG to `png_path` and as SVG to `svg_path` (either
 * may be NULL, not both), width x height pixels, from ONE gnuplot process:
 * gnuplot writes the images to its descriptors 3 and 4, which are our
 * temporary files (acbb_out), so no path reaches its script. A file is
 * replaced only when both images are complete. ACBB_EINVAL if no series
 * has a finite point or a label has a control character. */
acbb_status acbb_plot_xy_files(const acbb_plot_xy *p, const char *png_path,
                               const char *svg_path, int width, int height, acbb_error *err);

/* The preload window's chart (`acbb preload-map --plot`, the TUI's Preload
 * export): per speed the no-skid floor and the limits' ceiling. A window
 * end at the grid's first or last preload found no limit inside the grid:
 * it is a series of markers of its own ("grid bottom, no skid", "grid top,
 * no limit"), never drawn as a limit line. rows[0..n), n at most
 * ACBB_PMAP_MAX_AXIS (more are left out); a row with lo_N < 0 has no
 * window (no point). *p points into *c, which the caller keeps. */
enum { ACBB_PLOT_PMAP_FLOOR, ACBB_PLOT_PMAP_CEIL, ACBB_PLOT_PMAP_GRID_LO,
       ACBB_PLOT_PMAP_GRID_HI, ACBB_PLOT_PMAP_N };
typedef struct {
    double x[ACBB_PMAP_MAX_AXIS], y[ACBB_PLOT_PMAP_N][ACBB_PMAP_MAX_AXIS];
    acbb_plot_series series[ACBB_PLOT_PMAP_N];
} acbb_plot_pmap;
void acbb_plot_pmap_chart(const acbb_pmap_opts *o, const acbb_pmap_row *rows, size_t n,
                          acbb_plot_pmap *c, acbb_plot_xy *p);
/* As acbb_plot_xy_files, with the key of `look` (may be NULL). */
acbb_status acbb_plot_xy_styled(const acbb_plot_xy *p, const acbb_plot_look *look,
                                const char *png_path, const char *svg_path, int width,
                                int height, acbb_error *err);

/* One bar of a tornado chart: the metric at the low and the high end of an
 * input's range (NaN: that end failed and is not drawn). */
typedef struct {
    const char *label;               /* plain text, e.g. "mounting.h_face_W_m2K" */
    double lo, hi;
} acbb_tornado_bar;

/* The tornado chart of `acbb sensitivity`: one horizontal bar pair per
 * input, in the given order from the top (sort them by effect first),
 * each from the scene's value `base` (dashed line) to the metric at the
 * low end (colour 1) and at the high end (colour 2) of the input's range;
 * a solid line at 0 shows which inputs change the metric's sign. PNG or
 * SVG as acbb_plot_file; ACBB_EINVAL when there is nothing to draw. */
acbb_status acbb_plot_tornado_file(const acbb_tornado_bar *bars, size_t n, double base,
                                   acbb_plot_format fmt, const char *path, int width,
                                   int height, const char *title, const char *xlabel,
                                   acbb_error *err);

/* Figure sizes for print (src/io/plot_size.c). `--size` text: "WxH"
 * pixels, a width "85mm" / "8.5cm" / "3.3in" (height 3/4 of it) or
 * "85mmx60mm", or "column" (8.5 x 6.4 cm) and "full" (17.5 x 8.75 cm), the
 * physical ones at 300 dpi. 0 with *w, *h in pixels, or -1. The range is
 * acbb_plot_check_size's. */
int acbb_plot_parse_size(const char *text, int *w, int *h);
/* The text height (em, pixels) of a figure `width` pixels wide: 8.5 pt
 * when it is printed 8.5 cm wide (a journal column), at most 9 pt at
 * 300 dpi (full width), at least 10 px. */
double acbb_plot_font_px(int width);

/* The gnuplot program to run: $ACBB_GNUPLOT if set, else "gnuplot". */
const char *acbb_plot_program(void);

#ifdef __cplusplus
}
#endif

#endif
