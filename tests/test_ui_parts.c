/* Tests of the TUI's curses-free, single-threaded parts: the layout
 * function for several terminal sizes, the progress estimate, the chart
 * raster, the editor model, its recovery files, and the accuracy screen's layout and log-log
 * chart model (acc_chart.c). The thread hand-offs are tests/test_worker.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tap.h"
#include "acc_chart.h"
#include "bench.h"
#include "chart.h"
#include "editor.h"
#include "worker.h"
#include "layout.h"
#include "loss_rows.h"
#include "progress.h"
#include "recover.h"
#include "acbb/tools/scene_schema.h"

/* ---- layout ---- */

static void check_layout(int rows, int cols)
{
    acbb_layout l;
    int rc = acbb_layout_compute(rows, cols, &l);
    ok(rc == 0 && !l.too_small, "%dx%d: usable", cols, rows);
    ok(l.title.y == 0 && l.title.h == 1 && l.body.y == 1 && l.body.h == rows - 3 &&
           l.status.y == rows - 2 && l.message.y == rows - 1,
       "%dx%d: title, body, status, message stack over all %d rows", cols, rows, rows);
    const acbb_rect p[4] = { l.temps, l.losses, l.mech, l.chart };
    int inside = 1, apart = 1, area = 0;
    for (int i = 0; i < 4; i++) {
        inside &= acbb_rect_inside(p[i], rows, cols) && p[i].y >= l.body.y &&
                  p[i].y + p[i].h <= l.body.y + l.body.h;
        area += p[i].h * p[i].w;
        for (int j = i + 1; j < 4; j++) apart &= !acbb_rect_overlap(p[i], p[j]);
    }
    ok(inside, "%dx%d: overview panels inside the body", cols, rows);
    ok(apart, "%dx%d: overview panels do not overlap", cols, rows);
    ok(area == l.body.h * l.body.w, "%dx%d: overview panels tile the body (%d of %d cells)", cols,
       rows, area, l.body.h * l.body.w);
    ok(l.temps.w >= 40 && l.losses.w >= 40, "%dx%d: temperature and loss panels >= 40 wide", cols, rows);
    ok(l.chart.h >= 5, "%dx%d: overview chart keeps >= 5 rows (got %d)", cols, rows, l.chart.h);
    int sum = 0, stacked = 1;
    for (int i = 0; i < ACBB_LAYOUT_CHARTS; i++) {
        sum += l.charts[i].h;
        if (i > 0) stacked &= l.charts[i].y == l.charts[i - 1].y + l.charts[i - 1].h;
    }
    ok(sum == l.body.h && stacked && l.charts[0].y == l.body.y,
       "%dx%d: history charts stack over the body", cols, rows);
    int want_cols = cols / ACBB_LAYOUT_NODE_COL_W > 4 ? 4 : cols / ACBB_LAYOUT_NODE_COL_W;
    ok(l.node_columns == want_cols && l.node_columns * ACBB_LAYOUT_NODE_COL_W <= cols,
       "%dx%d: %d node-table columns fit", cols, rows, l.node_columns);
    ok(l.table_rows == rows - 4, "%dx%d: table rows = rows - 4", cols, rows);
}

static void test_layout(void)
{
    check_layout(24, 80);
    check_layout(30, 100);
    check_layout(60, 200);
    acbb_layout l;
    /* 80x24: two columns of 40; 8-row top panels, 4-row mechanics, 9-row chart. */
    acbb_layout_compute(24, 80, &l);
    ok(l.temps.w == 40 && l.losses.x == 40 && l.mech.y == 9 && l.chart.y == 13 && l.chart.h == 9,
       "80x24: panels at the planned places");
    acbb_layout_compute(60, 200, &l);
    ok(l.mech.y == l.temps.y && l.mech.x > l.losses.x, "200x60: mechanics is a third column");
    const int small[][2] = { { 10, 40 }, { 24, 79 }, { 23, 80 }, { 0, 0 } };
    for (int i = 0; i < 4; i++) {
        int rc = acbb_layout_compute(small[i][0], small[i][1], &l);
        ok(rc == -1 && l.too_small, "%dx%d: terminal too small", small[i][1], small[i][0]);
    }
    acbb_layout_compute(10, 40, &l);
    ok(l.message.y == 9 && l.message.w == 40, "40x10: the notice row is still the bottom row");
}

/* ---- progress ---- */

static void test_progress(void)
{
    acbb_progress p;
    acbb_progress_reset(&p);
    ok(!p.valid && p.eta_s < 0, "progress: unknown before the first residual");
    /* A single mode r = e^-t, tol e^-10: the run ends at t = 10 s; at 4 s
     * the ETA is 6 s and the fraction 0.4 (elapsed / (elapsed + eta)). */
    for (int k = 0; k <= 10; k++) acbb_progress_update(&p, exp(-0.05 * k), 0.05 * k, exp(-10.0));
    ok(p.eta_s < 0, "progress: no ETA in the first half second (only fast modes are seen then)");
    for (int k = 11; k <= 80; k++) acbb_progress_update(&p, exp(-0.05 * k), 0.05 * k, exp(-10.0));
    is_close(p.eta_s, 6.0, 1e-9, 0, "progress: one mode: ETA 6 s at 4 s of a 10 s run");
    is_close(p.fraction, 0.4, 1e-9, 0, "progress: fraction = elapsed / (elapsed + eta) = 0.4");
    /* Two modes, r = 10 e^-5t + 0.01 e^-0.5t, tol 1e-4: the slow mode sets
     * the end (t = 2 ln 100 = 9.21 s). At 4.6 s the mean decay rate since
     * the start promises 1.2 s; the recent rate gives the 4.6 s left. */
    acbb_progress_reset(&p);
    double t;
    for (t = 0; t <= 4.6; t += 0.05)
        acbb_progress_update(&p, 10 * exp(-5 * t) + 0.01 * exp(-0.5 * t), t, 1e-4);
    double left = 2 * log(100.0) - (t - 0.05);
    is_close(p.eta_s, left, 0.1, 0, "progress: two modes: ETA within 10 % of the true time left");
    acbb_progress_update(&p, 1e-5, 10.0, 1e-4);
    ok(p.fraction < 1.0 && p.eta_s == 0.0,
       "progress: below tolerance the fraction stays < 1 (100%% belongs to a finished run)");
}

/* Issue 29 item 6: what the status bar shows is steady. */
static void test_progress_steady(void)
{
    acbb_progress p;
    /* The decay slows at 3 s (r = e^-t, then e^-(3 + (t-3)/10)): the end
     * is re-estimated later, and elapsed / (elapsed + eta) falls. */
    acbb_progress_reset(&p);
    double last = 0.0, drop = 0.0;
    for (double t = 0; t <= 12.0; t += 0.05) {
        double lr = t < 3 ? -t : -3 - (t - 3) / 10;
        acbb_progress_update(&p, exp(lr), t, exp(-20.0));
        drop = fmax(drop, last - p.fraction);
        last = p.fraction;
    }
    ok(drop == 0.0 && last > 0.0, "progress: the fraction shown never goes back when the decay slows");
    /* One mode ending at 10 s with a 1 s plateau at 4 s (the residual
     * stalls): the raw end jumps to minutes, the ETA shown moves little
     * and LONG is never said. */
    acbb_progress_reset(&p);
    double eta_before = -1, eta_max = 0;
    int said_long = 0;
    for (double t = 0; t <= 9.0; t += 0.05) {
        double lr = t < 4 ? -t : t < 5 ? -4 : -4 - (t - 5) * 6 / 5;
        acbb_progress_update(&p, exp(lr), t, exp(-10.0));
        if (t < 3.99) eta_before = p.eta_s;
        else if (t < 5.5) eta_max = fmax(eta_max, p.eta_s);
        said_long |= acbb_progress_long(&p);
    }
    ok(eta_before > 5.5 && eta_before < 6.5 && eta_max < 2 * eta_before + 1.0,
       "progress: a stall of 1 s moves the ETA little (%.1f s before, at most %.1f s)", eta_before, eta_max);
    ok(!said_long, "progress: a 10 s run with a stall is never called LONG");
    /* One slow mode ending at 300 s: LONG once the estimate has held. */
    acbb_progress_reset(&p);
    for (double t = 0; t <= 8.0; t += 0.05) acbb_progress_update(&p, exp(-t / 30), t, exp(-10.0));
    ok(acbb_progress_long(&p) && fabs(p.eta_s - 292.0) < 1.0,
       "progress: a steady 300 s run is LONG (ETA %.1f s)", p.eta_s);
}

/* ---- chart raster ---- */

/* Nice axes: hand-worked ranges, and an axis fed its own range plus new
 * data only widens (the Run chart must not jump from frame to frame). */
static void test_nice(void)
{
    double lo, hi, st;
    acbb_chart_nice(25.3, 33.8, 5, &lo, &hi, &st);
    ok(lo == 25.0 && hi == 35.0 && st == 2.5, "nice: 25.3..33.8 -> 25..35 step 2.5 (got %g..%g step %g)",
       lo, hi, st);
    acbb_chart_nice(0.0, 3097.4, 5, &lo, &hi, &st);
    ok(lo == 0.0 && hi == 4000.0 && st == 1000.0, "nice: 0..3097 s -> 0..4000 step 1000 (got %g..%g step %g)",
       lo, hi, st);
    double a, b, s2;
    acbb_chart_nice(lo, hi, 5, &a, &b, &s2);
    ok(a == lo && b == hi && s2 == st, "nice: a nice range maps to itself");
    /* Grow a temperature series step by step: the range never shrinks and
     * each frame's range holds the previous one. */
    int widen_only = 1;
    double plo = 25.0, phi = 25.0;
    for (int k = 0; k < 200; k++) {
        double T = 25.0 + 8.8 * (1 - exp(-k / 40.0)), nlo, nhi;
        acbb_chart_nice(fmin(plo, T), fmax(phi, T), 5, &nlo, &nhi, &st);
        if (k > 0 && (nlo > plo || nhi < phi)) widen_only = 0;
        plo = nlo;
        phi = nhi;
    }
    ok(widen_only && plo <= 25.0 && phi >= 33.8, "nice: a growing series widens the axis only (%g..%g)",
       plo, phi);
}

/* Issue 29 item 6: a spring pair's preload, 300 N with 1e-5 N of solver
 * noise, is a flat line on a 285..315 N axis, not spikes on 300.00004 N. */
static void test_nice_noise(void)
{
    double lo, hi, step;
    acbb_chart_nice(300.0, 300.00004, 5, &lo, &hi, &step);
    ok(lo <= 285.0 && hi >= 315.0 && step >= 5.0,
       "nice: 1e-5 N of noise at 300 N is a flat band (%g..%g step %g)", lo, hi, step);
    acbb_chart_nice(300.0, 300.5, 5, &lo, &hi, &step);
    ok(hi - lo < 1.0, "nice: a real 0.5 N change keeps its own axis (%g..%g)", lo, hi);
}

/* Issue 29 item 5: two curves in one cell are both kept. */
static void test_chart_shared(void)
{
    static acbb_chart c;
    const double x[2] = { 0, 1 }, y0[2] = { 0.0, 0.0 }, y1[2] = { 0.2, 0.2 }, y2[2] = { 1, 1 };
    acbb_chart_init(&c, 4, 3, 0, 1, 0, 1);
    acbb_chart_plot(&c, x, y0, 2, 0);
    ok(!acbb_chart_any_shared(&c), "chart: one series shares no cell");
    acbb_chart_plot(&c, x, y1, 2, 1); /* a different dot row, the same cell row */
    acbb_chart_plot(&c, x, y2, 2, 2); /* the top row: alone */
    ok(acbb_chart_shared(&c, 2, 0) && acbb_chart_shared(&c, 2, 3) && !acbb_chart_shared(&c, 0, 0) &&
       acbb_chart_any_shared(&c), "chart: the cells both low curves drew in are shared, the top ones not");
    /* The upper of the two (series 1, at 0.2) moves up into the empty
     * middle row. */
    int moved = -1, kept = -1;
    ok(acbb_chart_offset(&c, 2, 0, &moved, &kept) == -1 && moved == 1 && kept == 0,
       "chart: the upper curve of a shared cell moves a row up (moved %d, kept %d)", moved, kept);
    acbb_chart_plot(&c, x, y0, 2, 2); /* a third curve on the lower row */
    ok(acbb_chart_offset(&c, 2, 0, &moved, &kept) == 0, "chart: three curves in a cell: the shared mark");
}

static void test_chart(void)
{
    static acbb_chart c;
    char g[8];
    const double x[2] = { 0, 1 }, y[2] = { 1, 1 };
    acbb_chart_init(&c, 2, 1, 0, 1, 0, 1);
    acbb_chart_plot(&c, x, y, 2, 0);
    /* y = ymax is the top dot row: bits 0x01 | 0x08 in both cells = U+2809. */
    ok(c.dots[0][0] == 0x09 && c.dots[0][1] == 0x09, "chart: a line at ymax lights the top dots");
    acbb_chart_cell(&c, 0, 0, 1, g);
    ok(strcmp(g, "\xe2\xa0\x89") == 0, "chart: cell drawn as braille U+2809");
    int owner = acbb_chart_cell(&c, 0, 1, 0, g);
    ok(strcmp(g, "'") == 0 && owner == 0, "chart: ASCII fallback draws top dots as ' (series 0)");
    /* A flat series widens the range by 5 % and sits mid-height:
     * dot row round(0.5 * 3) = 2 -> bits 0x04 | 0x20, ASCII '.'. */
    const double y5[2] = { 5, 5 };
    acbb_chart_init(&c, 1, 1, 0, 1, 5, 5);
    is_close(c.ymax - c.ymin, 0.5, 1e-12, 0, "chart: flat range widened by +-5 %");
    acbb_chart_plot(&c, x, y5, 2, 1);
    ok(c.dots[0][0] == 0x24, "chart: a flat line sits on dot row 2");
    acbb_chart_cell(&c, 0, 0, 0, g);
    ok(strcmp(g, ".") == 0, "chart: ASCII '.' for bottom-half dots");
    /* A diagonal is joined: every dot column of a 4x2 chart has a dot. */
    acbb_chart_init(&c, 4, 2, 0, 1, 0, 1);
    acbb_chart_plot(&c, x, x, 2, 0);
    int cols_lit = 0;
    for (int dx = 0; dx < 8; dx++) {
        int lit = 0;
        for (int row = 0; row < 2; row++)
            for (int dr = 0; dr < 4; dr++) {
                static const unsigned char bit[4][2] = { { 1, 8 }, { 2, 16 }, { 4, 32 }, { 64, 128 } };
                lit |= (c.dots[row][dx / 2] & bit[dr][dx % 2]) != 0;
            }
        cols_lit += lit;
    }
    ok(cols_lit == 8, "chart: a diagonal is drawn without gaps (%d of 8 dot columns)", cols_lit);
}

/* ---- editor model ---- */

static void test_editor(void)
{
    static acbb_editor e;
    acbb_error err = { { 0 } };
    size_t idiam = 0, iload = 0, icage = 0;
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        if (strcmp(acbb_scene_field(i)->key, "ball_diameter_mm") == 0) idiam = i;
        if (strcmp(acbb_scene_field(i)->key, "axial_load_N") == 0) iload = i;
        if (strcmp(acbb_scene_field(i)->key, "cage_width_mm") == 0) icage = i;
    }
    ok(acbb_editor_open(&e, "presets/7008C.ini", &err) == ACBB_OK, "editor: opens 7008C (%s)", err.msg);
    double D = e.scene.ball_diameter;
    ok(acbb_editor_set(&e, idiam, "-3", &err) == ACBB_EINVAL, "editor: ball_diameter_mm = -3 refused");
    has_substr(err.msg, "ball_diameter_mm = -3: must be > 0", "editor: the engine's message");
    ok(e.scene.ball_diameter == D && !e.modified && e.undo_n == 0,
       "editor: a refused value is not applied and not undoable");
    ok(acbb_editor_set(&e, iload, "500", &err) == ACBB_OK && e.scene.axial_load == 500.0 && e.modified,
       "editor: axial_load_N = 500 accepted, marked modified");
    ok(acbb_editor_set(&e, iload, "700", &err) == ACBB_OK && e.undo_n == 2, "editor: second edit stacked");
    ok(acbb_editor_undo(&e) && e.scene.axial_load == 500.0 && e.modified, "editor: undo restores 500");
    ok(acbb_editor_undo(&e) && e.scene.axial_load == 1000.0 && !e.modified,
       "editor: undo back to the file clears the marker");
    ok(!acbb_editor_undo(&e), "editor: nothing left to undo");
    acbb_editor_set(&e, iload, "450", &err);
    char path[] = "/tmp/acbb-test-editor-XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    ok(acbb_editor_save(&e, path, &err) == ACBB_OK && !e.modified && strcmp(e.path, path) == 0,
       "editor: save-as writes, clears the marker, adopts the path");
    acbb_scene back;
    ok(acbb_scene_load(path, &back, &err) == ACBB_OK && back.axial_load == 450.0,
       "editor: the saved file loads back with axial_load_N = 450");
    /* issue 26 item 9: the save checks what `acbb run` checks; a cage
     * width of 1e-6 mm passes the key's range but leaves the thermal
     * network no cage volume, and was saved for run to refuse. */
    ok(acbb_editor_set(&e, icage, "1e-06", &err) == ACBB_OK && e.modified,
       "editor: cage_width_mm = 1e-06 is in the key's range");
    ok(acbb_editor_save(&e, path, &err) != ACBB_OK && e.modified,
       "editor: ... but the save refuses it, as run would");
    has_substr(err.msg, "not saved: network: balls and cage do not fit", "editor: ... saying why");
    ok(acbb_scene_load(path, &back, &err) == ACBB_OK && back.cage_width == e.saved.cage_width,
       "editor: the file keeps its cage width");
    unlink(path);
}

/* ---- accuracy screen: layout, chart model, formats ---- */

static void check_acc_layout(int rows, int cols)
{
    acbb_layout l;
    acbb_layout_compute(rows, cols, &l);
    const acbb_rect p[3] = { l.acc_table, l.acc_frontier, l.acc_chart };
    int inside = 1, apart = 1, area = 0;
    for (int i = 0; i < 3; i++) {
        /* Below the screen's title and progress rows, inside the body. */
        inside &= acbb_rect_inside(p[i], rows, cols) && p[i].y >= l.body.y + 2 &&
                  p[i].y + p[i].h <= l.body.y + l.body.h;
        area += p[i].h * p[i].w;
        for (int j = i + 1; j < 3; j++) apart &= !acbb_rect_overlap(p[i], p[j]);
    }
    ok(inside && apart, "%dx%d: accuracy table, frontier, chart inside the body, apart", cols, rows);
    /* Wide: a one-column gap between table and chart; else they tile. */
    int gap = cols >= ACBB_LAYOUT_ACC_WIDE_COLS ? l.body.h - 2 : 0;
    ok(area + gap == (l.body.h - 2) * l.body.w, "%dx%d: accuracy panels fill the body below its 2 rows",
       cols, rows);
    ok(l.acc_table.w >= ACBB_LAYOUT_ACC_TABLE_W && l.acc_chart.h >= 7 && l.acc_table.h >= 6,
       "%dx%d: table %d wide x %d rows, chart %d rows", cols, rows, l.acc_table.w, l.acc_table.h,
       l.acc_chart.h);
}

static void test_acc_layout(void)
{
    check_acc_layout(24, 80);
    check_acc_layout(30, 100);
    check_acc_layout(60, 200);
    acbb_layout l;
    /* 80x24: body rows 1..21; rows 3..21 split: table (19 - 2) / 2 = 8,
     * frontier 2, chart 9 (title, 7 plot rows, x labels). */
    acbb_layout_compute(24, 80, &l);
    ok(l.acc_table.y == 3 && l.acc_table.h == 8 && l.acc_frontier.y == 11 && l.acc_frontier.h == 2 &&
           l.acc_chart.y == 13 && l.acc_chart.h == 9 && l.acc_chart.w == 80,
       "80x24: accuracy table 8 rows at 3, frontier at 11, chart 9 rows at 13");
    /* 200x60 (wide): table 74 wide on the left, chart from column 75. */
    acbb_layout_compute(60, 200, &l);
    ok(l.acc_table.x == 0 && l.acc_table.w == 74 && l.acc_chart.x == 75 && l.acc_chart.w == 125 &&
           l.acc_chart.h == 55 && l.acc_frontier.h == 8 && l.acc_table.h == 47,
       "200x60: table 74 x 47 + frontier 8 on the left, chart 125 x 55 on the right");
}

static acbb_accuracy_row acc_row(acbb_accuracy_knob k, double ms, double e_loss, double e_T)
{
    acbb_accuracy_row r;
    memset(&r, 0, sizeof r);
    r.knob = k;
    r.status = ACBB_OK;
    r.wall_ms = ms;
    r.e_loss = e_loss;
    r.e_T = e_T;
    return r;
}

static void test_acc_chart(void)
{
    acbb_accuracy_row rows[7];
    rows[0] = acc_row(ACBB_KNOB_CONTACT_GRID, 10, 0.02, 0.01);    /* 2 %: x 1, y log10 2 */
    rows[1] = acc_row(ACBB_KNOB_CONTACT_GRID, 100, 5e-4, 1e-3);   /* 0.1 %: x 2, y -1 */
    rows[2] = acc_row(ACBB_KNOB_CONTACT_GRID, 1000, 0, 0);        /* reference: x 3, y = floor */
    rows[3] = acc_row(ACBB_KNOB_HERTZ, 20, 0.1, 0.1);
    rows[3].status = ACBB_DIVERGED;                                /* failed: left out */
    rows[4] = acc_row(ACBB_KNOB_MODEL, 30, 0.1, 0.1);
    rows[4].skipped = 1;                                           /* skipped: left out */
    rows[5] = acc_row(ACBB_KNOB_HERTZ, 40, NAN, 0.1);              /* undefined: left out */
    rows[6] = acc_row(ACBB_KNOB_NETWORK, 50, 16.5, 0.07);          /* 1650 %: y 3.217 */
    is_close(acbb_acc_error_pct(&rows[1]), 0.1, 1e-12, 0, "acc chart: error = max(e_loss, e_T) in %%");
    ok(isnan(acbb_acc_error_pct(&rows[3])) && isnan(acbb_acc_error_pct(&rows[5])),
       "acc chart: no error for a failed row or an undefined one");
    static acbb_acc_chart m;
    size_t n = acbb_acc_chart_build(rows, 7, &m);
    ok(n == 4 && m.p[0].row == 0 && m.p[1].row == 1 && m.p[2].row == 2 && m.p[3].row == 6,
       "acc chart: 4 points (rows 0 1 2 6), failed/skipped/undefined left out (n = %zu)", n);
    /* Decades: 10 .. 1000 ms -> 1 .. 3; errors 0.1 .. 1650 % -> ceil(3.217) = 4
     * at the top, floor(-1) - 1 = -2 at the bottom (the zeros' decade). */
    ok(m.xmin == 1 && m.xmax == 3 && m.ymin == -2 && m.ymax == 4,
       "acc chart: x 1..3, y -2..4 decades (got %g..%g, %g..%g)", m.xmin, m.xmax, m.ymin, m.ymax);
    is_close(m.p[0].y, 0.30102999566398120, 1e-14, 0, "acc chart: 2 %% at log10 2");
    ok(m.p[2].zero && m.p[2].y == -2 && !m.p[0].zero, "acc chart: the reference's 0 sits on the floor");
    is_close(m.p[3].y, log10(1650.0), 1e-14, 0, "acc chart: 1650 %% at log10 1650");

    /* Cells on an 11 x 4 raster (22 x 16 dots): x 1 -> dot 0, cell 0;
     * x 3 -> dot 21, cell 10; x 2 -> dot 10.5 -> cell 5 either way.
     * y log10 2: (1 - 2.30103 / 6) * 15 = 9.247 -> dot 9, row 2;
     * y -2 -> dot 15, row 3; y 4 -> dot 0, row 0. */
    static acbb_chart c;
    int row = -1, col = -1;
    acbb_chart_init(&c, 11, 4, m.xmin, m.xmax, m.ymin, m.ymax);
    ok(acbb_chart_locate(&c, 1, log10(2.0), &row, &col) && row == 2 && col == 0,
       "acc chart: (10 ms, 2 %%) in cell row 2 col 0 (got %d %d)", row, col);
    ok(acbb_chart_locate(&c, 3, -2, &row, &col) && row == 3 && col == 10,
       "acc chart: (1 s, 0) in the bottom-right cell (got %d %d)", row, col);
    ok(acbb_chart_locate(&c, 2, 4, &row, &col) && row == 0 && col == 5,
       "acc chart: (100 ms, 10^4 %%) in row 0 col 5 (got %d %d)", row, col);
    ok(!acbb_chart_locate(&c, 0.5, 0, &row, &col) && !acbb_chart_locate(&c, 2, NAN, &row, &col),
       "acc chart: points outside the ranges or NaN have no cell");
    /* The marker cell is where acbb_chart_plot put the point's dot. */
    const double px[1] = { 1 }, py[1] = { 0.30102999566398120 };
    acbb_chart_plot(&c, px, py, 1, 0);
    ok(c.dots[2][0] != 0 && c.owner[2][0] == 0, "acc chart: the plotted dot is in the located cell");

    n = acbb_acc_chart_build(rows, 0, &m);
    ok(n == 0 && m.xmax > m.xmin && m.ymin == -1 && m.ymax == 1,
       "acc chart: no points -> 1 ms..10 ms, 0.1 %%..10 %% (tolerance 1 %% inside)");

    int distinct = 1;
    for (int i = 0; i < ACBB_KNOB_COUNT; i++)
        for (int j = i + 1; j < ACBB_KNOB_COUNT; j++)
            distinct &= acbb_acc_knob_letter((acbb_accuracy_knob)i) != acbb_acc_knob_letter((acbb_accuracy_knob)j);
    ok(distinct && acbb_acc_knob_letter(ACBB_KNOB_CONTACT_GRID) == 'G', "acc chart: 7 distinct knob letters");

    char b[16];
    acbb_acc_fmt_pct(0.02205804262, b, sizeof b);
    ok(strcmp(b, "2.21") == 0, "fmt pct: 0.0220580 -> 2.21 (got %s)", b);
    acbb_acc_fmt_pct(1.724105806e-05, b, sizeof b);
    ok(strcmp(b, "2e-03") == 0, "fmt pct: 1.72e-5 -> 2e-03 (got %s)", b);
    acbb_acc_fmt_pct(0, b, sizeof b);
    ok(strcmp(b, "0") == 0, "fmt pct: exact 0 -> 0");
    acbb_acc_fmt_pct(NAN, b, sizeof b);
    ok(strcmp(b, "-") == 0, "fmt pct: NaN -> -");
    acbb_acc_fmt_pct(16.4865, b, sizeof b);
    ok(strcmp(b, "2e+03") == 0, "fmt pct: 1648.65 %% -> 2e+03 (got %s)", b);
    acbb_acc_fmt_pct_decade(0, b, sizeof b);
    int dec_ok = strcmp(b, "1%") == 0;
    acbb_acc_fmt_pct_decade(-5, b, sizeof b);
    dec_ok &= strcmp(b, "1e-05%") == 0;
    acbb_acc_fmt_ms_decade(3, b, sizeof b);
    dec_ok &= strcmp(b, "1s") == 0;
    acbb_acc_fmt_ms_decade(7, b, sizeof b);
    ok(dec_ok && strcmp(b, "1e+07ms") == 0, "decade labels: 1%%, 1e-05%%, 1s, 1e+07ms");
    acbb_accuracy_row r = acc_row(ACBB_KNOB_CONTACT_GRID, 1, 0, 0);
    snprintf(r.key, sizeof r.key, "fidelity.contact_grid");
    snprintf(r.value, sizeof r.value, "4");
    acbb_acc_setting_label(&r, b, sizeof b);
    ok(strcmp(b, "contact_grid=4") == 0, "setting label: contact_grid=4");
}

/* The recommendation does not follow timing noise: of two settings within
 * tolerance, the one earlier in the (cheapest-first) plan is picked even
 * when its measured time came out longer. */
static void test_bench_frontier(void)
{
    static acbb_accuracy_row rows[4];
    const double err[4] = { 0.02, 0.005, 0.002, 0.0 }, wall[4] = { 30, 50, 40, 200 };
    memset(rows, 0, sizeof rows);
    for (int i = 0; i < 4; i++) {
        rows[i].knob = ACBB_KNOB_CONTACT_GRID;
        rows[i].status = ACBB_OK;
        rows[i].is_reference = i == 3;
        rows[i].e_loss = rows[i].e_T = err[i];
        rows[i].wall_ms = wall[i];
    }
    long by_time[ACBB_KNOB_COUNT], by_plan[ACBB_KNOB_COUNT];
    acbb_accuracy_frontier(rows, 4, ACBB_ACCURACY_FRONTIER_TOL, by_time);
    acbb_bench_frontier(rows, 4, by_plan);
    /* The engine ranks by work units, not wall time (equal work here: the
     * coarser setting wins), so it and the screen agree on row 1. */
    ok(by_time[ACBB_KNOB_CONTACT_GRID] == 1 && by_plan[ACBB_KNOB_CONTACT_GRID] == 1,
       "frontier: the engine picks row %ld despite the timing noise, the screen row %ld",
       by_time[ACBB_KNOB_CONTACT_GRID], by_plan[ACBB_KNOB_CONTACT_GRID]);
    ok(rows[1].wall_ms == 50 && rows[2].wall_ms == 40, "frontier: the rows' times are left as measured");
}

/* The pace (issue 21 item 7): simulated time over the pace, with a floor
 * per step so the runaway's 78 steps in 24 simulated s stay watchable. */
static void test_pace(void)
{
    ok(fabs(acbb_worker_step_ms(100.0, 200) - 500.0) < 1e-9, "a 100 s step at x200 lasts 500 ms");
    ok(fabs(acbb_worker_step_ms(0.3, 200) - 100.0) < 1e-9, "a 0.3 s step at x200 lasts the 100 ms floor");
    ok(acbb_worker_step_ms(5.0, 0) == 0.0, "flat out: no wait");
    double total = 0.0;
    for (int i = 0; i < 78; i++) total += acbb_worker_step_ms(24.0 / 78, 200);
    ok(total >= 7000.0, "78 steps over 24 simulated s at x200 take %.1f s (was 0.12 s)", total / 1e3);
}


/* ---- recovery files (issue 26 item 10) ---- */

static void set_mtime(const char *path, time_t sec, long nsec)
{
    struct timespec t[2] = { { sec, nsec }, { sec, nsec } };
    utimensat(AT_FDCWD, path, t, 0);
}

static void test_recover(void)
{
    static acbb_editor e;
    acbb_error err = { { 0 } };
    char root[] = "/tmp/acbb-test-recover-XXXXXX", preset[128], state[128], path[4096];
    char why[512], cmd[512];
    if (!mkdtemp(root)) return;
    snprintf(preset, sizeof preset, "%s/mine.ini", root);
    snprintf(state, sizeof state, "%s/state", root);
    snprintf(cmd, sizeof cmd, "cp presets/7008C.ini %s", preset);
    ok(system(cmd) == 0, "recover: a preset to edit");
    setenv("XDG_STATE_HOME", state, 1);
    acbb_editor_init(&e);
    ok(acbb_editor_open(&e, preset, &err) == ACBB_OK, "recover: editor opens it (%s)", err.msg);
    size_t iload = 0;
    for (size_t i = 0; i < acbb_scene_field_count(); i++)
        if (strcmp(acbb_scene_field(i)->key, "axial_load_N") == 0) iload = i;
    acbb_editor_set(&e, iload, "750", &err);
    ok(acbb_recover_write(&e, why, sizeof why) == 0, "recover: written (%s)", why);
    ok(acbb_recover_pending(&e, path, sizeof path), "recover: offered while newer than the preset");
    /* An outside save 0.5 s after the recovery file, in the same second:
     * offered before (seconds compared, >=), and restoring it reverted it. */
    struct stat st;
    stat(path, &st);
    set_mtime(path, st.st_mtim.tv_sec, 100000000);
    set_mtime(preset, st.st_mtim.tv_sec, 600000000);
    ok(!acbb_recover_pending(&e, path, sizeof path),
       "recover: a recovery file 0.5 s older than an outside save is not offered");
    set_mtime(path, st.st_mtim.tv_sec, 700000000);
    ok(acbb_recover_pending(&e, path, sizeof path), "recover: 0.1 s newer: offered again");
    static acbb_editor back;
    acbb_editor_init(&back);
    acbb_editor_open(&back, preset, &err);
    char msg[256];
    ok(acbb_recover_restore(&back, path, msg, sizeof msg) == 0 && back.scene.axial_load == 750.0,
       "recover: restored through the directory's descriptor (axial load 750)");
    /* A symlink in the directory's path: "acbb" swapped for a link to a
     * directory of the attacker's choosing. Only the last component was
     * checked (lstat), so the write went through the link. */
    snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s %s/elsewhere && ln -s %s/elsewhere %s/acbb",
             state, state, root, root, state);
    ok(system(cmd) == 0, "recover: state/acbb is a symlink");
    why[0] = '\0';
    ok(acbb_recover_write(&e, why, sizeof why) != 0 && strstr(why, "symbolic link"),
       "recover: not written through a symlinked component (%s)", why);
    snprintf(cmd, sizeof cmd, "%s/elsewhere/recover", root);
    ok(access(cmd, F_OK) != 0, "recover: nothing made behind the link");
    ok(!acbb_recover_pending(&e, path, sizeof path), "recover: nothing offered through it");
    snprintf(cmd, sizeof cmd, "rm -rf %s", root);
    if (system(cmd) != 0) fprintf(stderr, "# could not remove %s\n", root);
    unsetenv("XDG_STATE_HOME");
}

/* ---- the compare screen's loss rows come from the loss table ---- */

static void test_loss_rows(void)
{
    static acbb_editor e;
    acbb_error err = { { 0 } };
    ok(acbb_editor_open(&e, "presets/7008C.ini", &err) == ACBB_OK, "loss rows: opens 7008C (%s)", err.msg);
    acbb_loss_kind k[ACBB_LOSS_KINDS];
    char label[32];
    int n = acbb_loss_rows(&e.scene, k);
    acbb_loss_row_label(k[0], label, sizeof label);
    ok(n == 5 && k[0] == ACBB_LOSS_SHEAR && k[4] == ACBB_LOSS_DRAG && strcmp(label, "  shear P_L W") == 0,
       "loss rows: 7008C lists the seed's five, shear first (%d, '%s')", n, label);
    e.scene.loss_cage = e.scene.loss_ehl_rolling = e.scene.loss_churning = true;
    e.scene.loss_spin = false;
    n = acbb_loss_rows(&e.scene, k);
    acbb_loss_row_label(k[n - 1], label, sizeof label);
    ok(n == 7 && k[2] == ACBB_LOSS_ROLLING && k[4] == ACBB_LOSS_CAGE && strcmp(label, "  churning P_ch W") == 0,
       "loss rows: cage, EHL rolling and churning listed, spin dropped (%d, last '%s')", n, label);
}

int main(void)
{
    test_pace();
    test_bench_frontier();
    test_layout();
    test_progress();
    test_progress_steady();
    test_nice_noise();
    test_chart_shared();
    test_chart();
    test_nice();
    test_editor();
    test_loss_rows();
    test_recover();
    test_acc_layout();
    test_acc_chart();
    return done_testing();
}
