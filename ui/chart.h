/* acbb TUI — line charts rasterised into terminal cells (no curses here).
 *
 * Each cell holds a 2x4 dot matrix: with UTF-8 a cell is drawn as the
 * braille character with those dots (U+2800 + bits, as htop's graph
 * meters do); without UTF-8 the dots collapse to ASCII ' . : shapes.
 * Each cell also remembers which series drew in it last, for colour. */
#ifndef ACBB_UI_CHART_H
#define ACBB_UI_CHART_H

#include <stddef.h>

#define ACBB_CHART_MAX_W 320
#define ACBB_CHART_MAX_H 64

typedef struct {
    int w, h;                           /* cells */
    double xmin, xmax, ymin, ymax;
    unsigned char dots[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W];
    signed char owner[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W]; /* -1: empty */
    unsigned char seen[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W]; /* bit s: series s drew here */
    /* The series of the topmost and of the bottom-most dot in each cell
     * (-1: empty), and those dots' rows 0..3: where two curves share a
     * cell, which one runs above. */
    signed char top_s[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W], bot_s[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W];
    unsigned char top_dy[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W], bot_dy[ACBB_CHART_MAX_H][ACBB_CHART_MAX_W];
} acbb_chart;

/* The mark of a cell two or more series drew in (issue 29 item 5): one
 * colour or one mark per cell would hide all but the last series there. */
#define ACBB_CHART_SHARED_MARK "&"

/* Clear a w x h (clamped to the maxima) chart with the given ranges; a
 * degenerate range is widened so a flat line sits mid-height. */
void acbb_chart_init(acbb_chart *c, int w, int h, double xmin, double xmax, double ymin,
                     double ymax);
/* Draw the polyline (x[k], y[k]) as series `series` (0..), joining points. */
void acbb_chart_plot(acbb_chart *c, const double *x, const double *y, size_t n, int series);
/* The glyph of cell (row, col) into buf (>= 8 bytes); returns the owner. */
int acbb_chart_cell(const acbb_chart *c, int row, int col, int utf8, char *buf);
/* 1 if two or more series drew in cell (row, col). */
int acbb_chart_shared(const acbb_chart *c, int row, int col);
/* 1 if any cell is shared. */
int acbb_chart_any_shared(const acbb_chart *c);
/* Where two curves share cell (row, col) (issue 29 item 5), the upper one
 * is shown one row up when that cell is empty, else the lower one a row
 * down: returns -1 (up) or +1 (down) with the moved series in *moved and
 * the one left in *kept; 0 when neither can move (the shared mark then). */
int acbb_chart_offset(const acbb_chart *c, int row, int col, int *moved, int *kept);
/* The cell (row, col) holding the dot that acbb_chart_plot draws for the
 * point (x, y); 0 (row/col unchanged) if the point is non-finite or outside
 * the ranges. Lets a caller write a marker where a point was plotted. */
int acbb_chart_locate(const acbb_chart *c, double x, double y, int *row, int *col);
/* A "nice" axis covering [lo, hi] with about `ticks` ticks: a step of
 * 1, 2, 2.5 or 5 times a power of ten and ends on multiples of it
 * (Heckbert, "Nice numbers for graph labels", Graphics Gems 1990).
 * A nice range maps to itself, so feeding back the union of the last
 * range and the data gives an axis that only widens and never jitters. */
void acbb_chart_nice(double lo, double hi, int ticks, double *nlo, double *nhi, double *step);
/* The glyph that stands for series `series` where colour cannot (NO_COLOR,
 * a monochrome terminal): "o", "+", "x", "#", cycling. Drawn in the
 * series' cells and in its legend swatch, so curves stay apart in print. */
const char *acbb_chart_mark(int series);
/* Smallest and largest finite value of v[0..n) into *lo, *hi (unchanged if none). */
void acbb_chart_extend(const double *v, size_t n, double *lo, double *hi);

#endif
