/* acbb TUI — screen layout as a pure function of the terminal size (the
 * nvtop idea: unit-tested for many sizes without a terminal). */
#ifndef ACBB_UI_LAYOUT_H
#define ACBB_UI_LAYOUT_H

#define ACBB_LAYOUT_MIN_ROWS 24
#define ACBB_LAYOUT_MIN_COLS 80
#define ACBB_LAYOUT_CHARTS 3
#define ACBB_LAYOUT_NODE_COL_W 40  /* width of one column of the node table */
#define ACBB_LAYOUT_ACC_TABLE_W 74 /* the accuracy table's line (screen_accuracy.c) */
#define ACBB_LAYOUT_ACC_WIDE_COLS (ACBB_LAYOUT_ACC_TABLE_W + 1 + 60) /* chart >= 60 wide beside it */

typedef struct { int y, x, h, w; } acbb_rect;

typedef struct {
    int rows, cols;
    int too_small;              /* below 80x24: only a notice is drawn */
    acbb_rect title;            /* tab bar, top row */
    acbb_rect body;             /* the current screen */
    acbb_rect status;           /* solver status line */
    acbb_rect message;          /* messages, prompts, key hints (bottom row) */
    /* overview screen panels, inside body */
    acbb_rect temps, losses, mech, chart;
    /* charts screen: stacked charts, inside body */
    acbb_rect charts[ACBB_LAYOUT_CHARTS];
    /* accuracy screen, inside body below its two heading rows: the table
     * (header + scrolled rows), the frontier, the error-vs-time chart;
     * side by side from ACBB_LAYOUT_ACC_WIDE_COLS, stacked below it */
    acbb_rect acc_table, acc_frontier, acc_chart;
    int table_rows;             /* data rows of the table screens (header excluded) */
    int node_columns;           /* columns of the node-temperature table */
} acbb_layout;

/* Fill `l` for a rows x cols terminal. Returns 0, or -1 if the terminal is
 * too small (then l->too_small is set and only rows/cols/message are valid). */
int acbb_layout_compute(int rows, int cols, acbb_layout *l);

/* 1 if r lies inside a rows x cols screen and is not empty. */
int acbb_rect_inside(acbb_rect r, int rows, int cols);
/* 1 if the two rectangles share a cell. */
int acbb_rect_overlap(acbb_rect a, acbb_rect b);

#endif
