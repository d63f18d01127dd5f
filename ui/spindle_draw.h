/* acbb TUI — the Spindle screen's text, laid out without curses (so a
 * unit test can read it): the shaft drawn along x in characters, the nose
 * at the left, the front and rear sets at their x with their arrangement,
 * the temperature along the shaft and the housing under it, the coolant,
 * and a side block with the nose drift, the nose stiffness and each set's
 * preload and loads. The screen (screen_spindle.c) puts these rows in the
 * body and draws the drift-over-time chart below them.
 *
 * Everything is plain ASCII: it reads the same without UTF-8 or colour. */
#ifndef ACBB_UI_SPINDLE_DRAW_H
#define ACBB_UI_SPINDLE_DRAW_H

#include "acbb/scene.h"
#include "acbb/spindle.h"

#define ACBB_SPINDLE_LINE 256      /* bytes of one row (the widest terminal laid out, + NUL) */
#define ACBB_SPINDLE_GUTTER 8      /* the row labels left of the picture ("shaft C ") */
#define ACBB_SPINDLE_SIDE_W 25     /* the side block at the right */
#define ACBB_SPINDLE_PROFILE 4     /* rows of the shaft's half section */
#define ACBB_SPINDLE_T_CELL 6      /* columns of one temperature value (" 123.4") */

/* The rows, top to bottom. */
enum {
    ACBB_SP_HEADER,
    ACBB_SP_PROFILE,                                   /* its first row (the outermost radius) */
    ACBB_SP_SETS = ACBB_SP_PROFILE + ACBB_SPINDLE_PROFILE, /* the sets' glyphs */
    ACBB_SP_SCALE,                                     /* x in mm */
    ACBB_SP_SHAFT_T,
    ACBB_SP_HOUSING_T,
    ACBB_SP_COOLANT,
    ACBB_SP_ROWS
};

typedef struct {
    int cols;                      /* the width laid out */
    int pic_x, pic_w;              /* the picture's columns: the nose (x = 0) at pic_x */
    int side_x;                    /* the side block's first column */
    double length;                 /* m of shaft across pic_w columns */
    int set_col[ACBB_SPINDLE_SETS];/* the column (absolute) of each set's centre */
    char line[ACBB_SP_ROWS][ACBB_SPINDLE_LINE]; /* trailing blanks trimmed */
} acbb_spindle_page;

/* The column (0 .. w-1) of the picture that holds x (m) when `length`
 * metres span w columns; x outside the shaft lands on its end column. */
int acbb_spindle_column(double x, double length, int w);

/* T(x) from cells at ascending xs[0..n): linear between cell centres,
 * each end cell's value out to half its spacing beyond it, NAN outside
 * (a housing shorter than the shaft) or when n == 0. */
double acbb_spindle_T_at(const double *xs, const double *T, int n, double x);

/* Lay out the screen's rows for `cols` columns (>= 80, at most
 * ACBB_SPINDLE_LINE - 1) from the run's scene and its spindle view.
 * 0 on success; -1 when the scene is not a spindle (v->n_sets == 0 or no
 * shaft segments): the caller says so instead. */
int acbb_spindle_page_fill(const acbb_scene *sc, const acbb_spindle_view *v, int cols,
                           acbb_spindle_page *p);

/* The one line shown instead when the scene is not a spindle. */
extern const char acbb_spindle_none_text[];

#endif
