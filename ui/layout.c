/* acbb TUI — layout (see layout.h). No curses here: pure arithmetic. */
#include <string.h>
#include "layout.h"

#define TOP_PANEL_H 8   /* header + six key values + a spare line */
#define MECH_PANEL_H 4  /* header + three lines of mechanics */
#define WIDE_COLS 120   /* from here the overview has three columns */

static acbb_rect rect(int y, int x, int h, int w)
{
    acbb_rect r = { y, x, h, w };
    return r;
}

int acbb_rect_inside(acbb_rect r, int rows, int cols)
{
    return r.h > 0 && r.w > 0 && r.y >= 0 && r.x >= 0 && r.y + r.h <= rows && r.x + r.w <= cols;
}

int acbb_rect_overlap(acbb_rect a, acbb_rect b)
{
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

static void overview(acbb_layout *l)
{
    acbb_rect b = l->body;
    if (l->cols >= WIDE_COLS) {
        int w = b.w / 3;
        l->temps = rect(b.y, b.x, TOP_PANEL_H, w);
        l->losses = rect(b.y, b.x + w, TOP_PANEL_H, w);
        l->mech = rect(b.y, b.x + 2 * w, TOP_PANEL_H, b.w - 2 * w);
        l->chart = rect(b.y + TOP_PANEL_H, b.x, b.h - TOP_PANEL_H, b.w);
    } else {
        int w = b.w / 2;
        l->temps = rect(b.y, b.x, TOP_PANEL_H, w);
        l->losses = rect(b.y, b.x + w, TOP_PANEL_H, b.w - w);
        l->mech = rect(b.y + TOP_PANEL_H, b.x, MECH_PANEL_H, b.w);
        l->chart = rect(b.y + TOP_PANEL_H + MECH_PANEL_H, b.x,
                        b.h - TOP_PANEL_H - MECH_PANEL_H, b.w);
    }
}

static void charts(acbb_layout *l)
{
    acbb_rect b = l->body;
    int y = b.y;
    for (int i = 0; i < ACBB_LAYOUT_CHARTS; i++) {
        /* Spread the remainder over the first charts. */
        int h = b.h / ACBB_LAYOUT_CHARTS + (i < b.h % ACBB_LAYOUT_CHARTS);
        l->charts[i] = rect(y, b.x, h, b.w);
        y += h;
    }
}

#define ACC_HEAD_H 2        /* accuracy screen: title and progress rows */
#define ACC_FRONTIER_NARROW 2 /* the frontier as wrapped text */
#define ACC_FRONTIER_WIDE 8 /* header + one line per knob */

static void accuracy(acbb_layout *l)
{
    acbb_rect b = l->body;
    int y = b.y + ACC_HEAD_H, h = b.h - ACC_HEAD_H;
    if (l->cols >= ACBB_LAYOUT_ACC_WIDE_COLS) {
        int tw = ACBB_LAYOUT_ACC_TABLE_W, fh = ACC_FRONTIER_WIDE < h / 2 ? ACC_FRONTIER_WIDE : h / 2;
        l->acc_table = rect(y, b.x, h - fh, tw);
        l->acc_frontier = rect(y + h - fh, b.x, fh, tw);
        l->acc_chart = rect(y, b.x + tw + 1, h, b.w - tw - 1);
    } else {
        /* Half of what is left for the table, the rest for the chart. */
        int th = (h - ACC_FRONTIER_NARROW) / 2;
        l->acc_table = rect(y, b.x, th, b.w);
        l->acc_frontier = rect(y + th, b.x, ACC_FRONTIER_NARROW, b.w);
        l->acc_chart = rect(y + th + ACC_FRONTIER_NARROW, b.x, h - th - ACC_FRONTIER_NARROW, b.w);
    }
}

int acbb_layout_compute(int rows, int cols, acbb_layout *l)
{
    memset(l, 0, sizeof *l);
    l->rows = rows;
    l->cols = cols;
    if (rows < ACBB_LAYOUT_MIN_ROWS || cols < ACBB_LAYOUT_MIN_COLS) {
        l->too_small = 1;
        if (rows > 0 && cols > 0) l->message = rect(rows - 1, 0, 1, cols);
        return -1;
    }
    l->title = rect(0, 0, 1, cols);
    l->body = rect(1, 0, rows - 3, cols);
    l->status = rect(rows - 2, 0, 1, cols);
    l->message = rect(rows - 1, 0, 1, cols);
    overview(l);
    charts(l);
    accuracy(l);
    l->table_rows = l->body.h - 1;
    l->node_columns = cols / ACBB_LAYOUT_NODE_COL_W;
    if (l->node_columns > 4) l->node_columns = 4;
    return 0;
}
