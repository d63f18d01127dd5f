/* acbb — the gnuplot plumbing of src/io/plot.c shared with the plot kinds in
 * other files (src/io/plot_xy.c): the script buffer, the one way gnuplot is
 * run, the terminal line and the completeness test of an image. Not
 * installed; the public interface is include/acbb/plot.h. The short names
 * are macros for prefixed symbols (no unprefixed name leaves the library). */
#ifndef ACBB_PLOT_PRIV_H
#define ACBB_PLOT_PRIV_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/plot.h"

#define sb_printf acbb_plot_sb_printf
#define sb_quoted acbb_plot_sb_quoted
#define has_control_char acbb_plot_has_control_char
#define run_gnuplot acbb_plot_run_gnuplot
#define terminal_line acbb_plot_terminal_line
#define image_complete acbb_plot_image_complete

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

#endif
