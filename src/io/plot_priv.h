/* acbb — the gnuplot plumbing of src/io/plot.c shared with the plot kinds in
 * other files (src/io/plot_xy.c): the script buffer, the one way gnuplot is
 * run, the terminal line and the completeness test of an image. Not
 * installed; the public interface is include/acbb/tools/plot.h. The short names
 * are macros for prefixed symbols (no unprefixed name leaves the library). */
#ifndef ACBB_PLOT_PRIV_H
#define ACBB_PLOT_PRIV_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/tools/plot.h"

#define sb_printf acbb_plot_sb_printf
#define sb_quoted acbb_plot_sb_quoted
#define has_control_char acbb_plot_has_control_char
#define run_gnuplot acbb_plot_run_gnuplot
#define terminal_line acbb_plot_terminal_line
#define image_complete acbb_plot_image_complete
#define plot_markup acbb_plot_markup
#define key_pts_add acbb_plot_key_pts_add
#define key_place acbb_plot_key_place
#define axes_range acbb_plot_axes_range
#define axes_emit acbb_plot_axes_emit
#define axes_fit_y acbb_plot_axes_fit_y
#define title_lines acbb_plot_title_lines
#define nice_step acbb_plot_nice_step
#define series_style acbb_plot_series_style

/* A growing NUL-terminated script; oom latches the first failed growth. */
typedef struct {
    char *p;
    size_t n, cap;
    bool oom;
} sbuf;

/* Where gnuplot's output goes and what it said. */
typedef struct {
    bool to_file;         /* stdout goes to file_fd (a file we opened, not gnuplot) */
    int file_fd;
    char *out;            /* captured stdout, NULL to discard */
    size_t out_cap, out_len;
    char err[2048];       /* the start of stderr, NUL-terminated */
    size_t err_len;
    int n_extra;          /* extra[k] becomes gnuplot's descriptor 3 + k (xy plots); */
    int extra[2];         /* each must be >= 5 so the dup2s cannot clobber each other */
} gp_io;

void sb_printf(sbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A gnuplot single-quoted string (control characters become spaces). */
void sb_quoted(sbuf *b, const char *s);
bool has_control_char(const char *s);
/* Feed `script` to one gnuplot process; ACBB_OK when it exited 0. */
acbb_status run_gnuplot(const sbuf *script, gp_io *io, acbb_error *err);
/* `set terminal` (size), noenhanced, and the key position. */
void terminal_line(sbuf *b, acbb_plot_format fmt, int w, int h);
/* PNG ends with IEND, SVG with </svg>. */
bool image_complete(int fd, acbb_plot_format fmt);
/* A plain label ("omega_x' (rad/s)") as gnuplot enhanced text
 * ("ω_{x'} (rad/s)"), NUL-terminated in out[n] (plot_markup.c). */
void plot_markup(const char *plain, char *out, size_t n);

/* The points drawn, for the key's corner (plot_key.c). Owns x, y. */
typedef struct {
    double *x, *y;
    size_t n, cap;
} key_pts;
void key_pts_add(key_pts *k, double x, double y);

/* The layout of an x-y figure (plot_axes.c), in pixels of the image. */
typedef struct {
    int w, h;                /* the image */
    double em;               /* text height, acbb_plot_font_px(w) */
    int title_lines;
    double x0, x1, y0, y1;   /* the data's range */
    double xs, ys;           /* tic steps */
    double gx0, gx1, gy0, gy1; /* the axes: whole steps around the data */
    double plot_w, plot_h;   /* the plot area, estimated */
    int ychars;              /* the widest y tic label */
} xy_layout;
/* Steps and ranges of both axes from the points drawn (w, h, em and
 * title_lines set). */
void axes_range(xy_layout *L, const key_pts *k);
/* The y step and range again for [y0, max(y1, top)] over plot_h. */
void axes_fit_y(xy_layout *L, double top);
/* `set xrange`, `set yrange`, `set xtics`, `set ytics`. */
void axes_emit(sbuf *b, const xy_layout *L);
/* The smallest 1-2-5 step that spans [lo, hi] with at most max_tics tics. */
double nice_step(double lo, double hi, int max_tics);
/* `text` broken at spaces into at most 3 lines of about per_line chars. */
int title_lines(const char *text, double per_line, char lines[3][160]);
/* "with ... linewidth 2 dashtype D linecolor C pointtype P pointinterval I "
 * for series s of n points (plot_xy.c): markers by colour, filled when
 * solid, open when dashed, about eight on a dense series. */
void series_style(sbuf *b, const acbb_plot_series *s, size_t n);
/* The key of `entries` rows `chars` wide where it covers no point of k:
 * a free corner inside; else the y axis raised until a top band is free
 * (L->gy1, L->ys change); else outside below the plot. Frees k. */
void key_place(sbuf *b, key_pts *k, xy_layout *L, int entries, double chars);

#endif
