/* The TUI's Spindle screen laid out without a terminal (ui/spindle_draw.c,
 * ui/drift_hist.c): a filled spindle view at 80 and 120 columns, every row
 * inside the width, the shaft's steps at the columns of its segments, both
 * sets' glyphs at the columns of their x, the numbers as printed, the
 * temperature along shaft and housing, the one line for a scene that is
 * not a spindle, and the capped drift history. Expected columns are worked
 * by hand from the picture's width (80 - 25 side - 1 - 8 gutter = 46). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tap.h"
#include "drift_hist.h"
#include "spindle_draw.h"

static acbb_scene sc;
static acbb_spindle_view v;

/* Shaft 105 mm of od 70, 245 of od 50, 50 of od 30 (400 mm); front DBT at
 * 40 mm, rear DB at 300 mm; shaft cells every 10 mm at T = 20 + 0.1 x/mm,
 * housing cells from 50 to 350 mm at 30 C; coolant 22.0 -> 24.3 C, 310 W. */
static void fill(void)
{
    memset(&sc, 0, sizeof sc);
    memset(&v, 0, sizeof v);
    sc.shaft_segments = 3;
    sc.shaft_seg[0] = (acbb_segment){ 0.105, 0.070, 0.020 };
    sc.shaft_seg[1] = (acbb_segment){ 0.245, 0.050, 0.020 };
    sc.shaft_seg[2] = (acbb_segment){ 0.050, 0.030, 0.020 };
    sc.set_arrangement = ACBB_SET_DBT;
    sc.spindle_rear_arrangement = ACBB_SET_DB;
    sc.spindle_rear_support = ACBB_REAR_SPRING;
    sc.coolant_flow = 4.0 / 60000.0;
    v.n_sets = 2;
    v.sets[0] = (acbb_spindle_set_view){ .x = 0.040, .n_bearings = 3, .preload_N = 250.0, .axial_N = 300.4,
                                         .radial_N = 120.0 };
    v.sets[1] = (acbb_spindle_set_view){ .x = 0.300, .n_bearings = 2, .preload_N = 180.0, .axial_N = -80.0,
                                         .radial_N = 60.0, .contact_lost = 1 };
    v.nose_drift_axial = 12.34e-6;
    v.nose_drift_radial = -1.5e-6;
    v.nose_k_radial = 123.4e6;
    v.nose_k_axial = 0; /* not yet known */
    v.Q_motor_W = 800;
    v.Q_bearings_W = 120;
    v.Q_coolant_W = 310;
    v.T_coolant_in_C = 22.0;
    v.T_coolant_out_C = 24.3;
    v.n_shaft = 40;
    for (int i = 0; i < 40; i++) {
        v.shaft_x[i] = (5.0 + 10.0 * i) * 1e-3;
        v.shaft_T_C[i] = 20.0 + 0.1 * (5.0 + 10.0 * i);
    }
    v.n_housing = 30;
    for (int i = 0; i < 30; i++) {
        v.housing_x[i] = (55.0 + 10.0 * i) * 1e-3;
        v.housing_T_C[i] = 30.0;
    }
}

/* Columns c of row r holding '#', as a string of '#' and ' ' (pic_w long). */
static void marks(const acbb_spindle_page *p, int r, char *out)
{
    const char *s = p->line[ACBB_SP_PROFILE + r];
    int n = (int)strlen(s);
    for (int c = 0; c < p->pic_w; c++) out[c] = p->pic_x + c < n && s[p->pic_x + c] == '#' ? '#' : ' ';
    out[p->pic_w] = '\0';
}

static int run_of(const char *m, int from, int to)
{
    for (int c = 0; m[c]; c++)
        if ((m[c] == '#') != (c >= from && c <= to)) return 0;
    return 1;
}

static void test_fits(int cols)
{
    static acbb_spindle_page p;
    ok(acbb_spindle_page_fill(&sc, &v, cols, &p) == 0, "%d columns: laid out", cols);
    int fits = 1;
    for (int r = 0; r < ACBB_SP_ROWS; r++) fits &= (int)strlen(p.line[r]) <= cols;
    ok(fits, "%d columns: every row fits", cols);
    ok(p.pic_x + p.pic_w < p.side_x && p.side_x + ACBB_SPINDLE_SIDE_W <= cols,
       "%d columns: the picture ends before the side block, which ends inside", cols);
}

static void test_shaft(void)
{
    static acbb_spindle_page p;
    acbb_spindle_page_fill(&sc, &v, 80, &p);
    for (int r = 0; r < ACBB_SP_ROWS; r++) printf("# |%s\n", p.line[r]); /* the page, for the log */
    ok(p.pic_x == 8 && p.pic_w == 46 && p.side_x == 55, "80 columns: picture 8..53, side block at 55");
    is_close(p.length, 0.400, 1e-12, 0, "the picture spans the shaft's 400 mm");
    /* column c's centre (c + 0.5) * 400/46 mm: segment 1 below 105 mm is
     * c 0..11 (11.5 -> 100 mm), segment 2 below 350 mm c 12..39, segment 3 c 40..45;
     * heights round(4 od/70): 4, 3 (2.86), 2 (1.71). */
    char m[4][ACBB_SPINDLE_LINE];
    for (int r = 0; r < 4; r++) marks(&p, r, m[r]);
    ok(run_of(m[0], 0, 11), "top row: the od 70 segment only, columns 0..11: '%s'", m[0]);
    ok(run_of(m[1], 0, 39), "second row: od 70 and od 50, columns 0..39: '%s'", m[1]);
    ok(run_of(m[2], 0, 45) && run_of(m[3], 0, 45), "two rows next to the axis: the whole shaft");
    ok(strncmp(p.line[ACBB_SP_PROFILE + 3], "nose ->", 7) == 0, "the nose named at the left");
    /* sets: front 40 mm -> column floor(4.6) = 4, DBT ">><" centred there
     * (3..5); rear 300 mm -> floor(34.5) = 34, DB "><" at 34..35 */
    const char *s = p.line[ACBB_SP_SETS];
    ok(p.set_col[0] == 8 + 4 && p.set_col[1] == 8 + 34, "set centres at columns 12 and 42 (%d, %d)",
       p.set_col[0], p.set_col[1]);
    ok(strncmp(s + 8 + 3, ">><", 3) == 0 && s[8 + 2] == ' ' && s[8 + 6] == ' ',
       "front DBT drawn as >>< at columns 11..13: '%s'", s);
    ok(strncmp(s + 8 + 34, "><", 2) == 0 && s[8 + 33] == ' ' && (s[8 + 36] == ' ' || !s[8 + 36]),
       "rear DB drawn as >< at columns 42..43");
    /* x labels every 100 mm (the least of 1, 2, 5 x 10^k leaving 8 columns):
     * 0 at 8, 100 at 8 + 11, 200 at 8 + 23, 300 at 8 + 34; 400 would end past the picture */
    const char *x = p.line[ACBB_SP_SCALE];
    ok(x[8] == '0' && strncmp(x + 19, "100", 3) == 0 && strncmp(x + 31, "200", 3) == 0 &&
           strncmp(x + 42, "300", 3) == 0 && !strstr(x, "400"),
       "x mm labels at their columns: '%s'", x);
    has_substr(p.line[ACBB_SP_HEADER], "Spindle: shaft 400 mm, front DBT at 40 mm, rear DB at 300 mm (spring)",
               "header: the shaft and both sets");
}

/* s begins with want, then a blank (the side block's text comes later). */
static int starts(const char *s, const char *want)
{
    size_t n = strlen(want);
    return strncmp(s, want, n) == 0 && s[n] == ' ';
}

static void test_numbers(void)
{
    static acbb_spindle_page p;
    acbb_spindle_page_fill(&sc, &v, 80, &p);
    const char *side[9];
    for (int r = 0; r < 9; r++) side[r] = strlen(p.line[1 + r]) > 55 ? p.line[1 + r] + 55 : "";
    ok(strcmp(side[0], "nose drift    +12.34 um") == 0, "nose drift in um: '%s'", side[0]);
    ok(strcmp(side[1], "    radial     -1.50 um") == 0, "radial drift in um: '%s'", side[1]);
    ok(strcmp(side[2], "nose k rad     123.4 N/um") == 0, "radial nose stiffness in N/um: '%s'", side[2]);
    ok(strcmp(side[3], "     axial   pending N/um") == 0, "an unknown (0) stiffness reads pending: '%s'", side[3]);
    ok(strcmp(side[4], "front preload   250.0 N") == 0 && strcmp(side[5], " Fa   300 Fr   120 N") == 0,
       "front set: preload and loads ('%s' '%s')", side[4], side[5]);
    ok(strcmp(side[6], "rear  preload   180.0 N") == 0 && strcmp(side[7], " Fa   -80 Fr    60 N LIFT") == 0,
       "rear set: preload, loads, lifted off ('%s' '%s')", side[6], side[7]);
    ok(strcmp(side[8], "motor 800 W  sets 120 W") == 0, "heat of motor and sets: '%s'", side[8]);
    ok(starts(p.line[ACBB_SP_COOLANT], "coolant in 22.0 C  out 24.3 C  takes 310 W"),
       "coolant in, out and heat: '%s'", p.line[ACBB_SP_COOLANT]);
    /* shaft T at group centres (g + 0.5) * 6 * 400/46 mm: g = 0 26.09 mm ->
     * 22.6 C, g = 6 339.1 mm -> 53.9 C; 7 groups of 6 columns */
    const char *t = p.line[ACBB_SP_SHAFT_T];
    ok(strncmp(t, "shaft C", 7) == 0 && strncmp(t + 8, "  22.6", 6) == 0 && strncmp(t + 8 + 36, "  53.9", 6) == 0,
       "shaft T along x: '%s'", t);
    /* housing from 50 mm: group 0 (26 mm) is outside, blank; 1 (78 mm) on */
    const char *h = p.line[ACBB_SP_HOUSING_T];
    ok(strncmp(h + 8, "      ", 6) == 0 && strncmp(h + 14, "  30.0", 6) == 0, "housing T only where it is: '%s'", h);
    sc.coolant_flow = 0;
    acbb_spindle_page_fill(&sc, &v, 80, &p);
    ok(starts(p.line[ACBB_SP_COOLANT], "coolant none (spindle.coolant_flow_l_min = 0)"),
       "no coolant says which key: '%s'", p.line[ACBB_SP_COOLANT]);
    sc.coolant_flow = 4.0 / 60000.0;
}

static void test_wide(void)
{
    static acbb_spindle_page p;
    acbb_spindle_page_fill(&sc, &v, 120, &p);
    /* picture 120 - 25 - 1 - 8 = 86 columns: front floor(8.6) = 8, rear floor(64.5) = 64 */
    ok(p.pic_w == 86 && p.set_col[0] == 16 && p.set_col[1] == 72 &&
           strncmp(p.line[ACBB_SP_SETS] + 8 + 7, ">><", 3) == 0 && strncmp(p.line[ACBB_SP_SETS] + 72, "><", 2) == 0,
       "120 columns: the picture widens, the sets move to their x's columns");
}

/* The motor preset's own shaft (330 mm, 7 segments, od 60 40 48 56 48 40
 * 35 mm) with its sets at 50 and 275 mm: front floor(50/330 * 46) = 6,
 * DBT >>< at 5..7; rear floor(38.3) = 38, DB >< at 38..39. */
static void test_preset(void)
{
    static acbb_scene ps;
    static acbb_spindle_page p;
    acbb_error err = { { 0 } };
    if (acbb_scene_load("presets/spindle-motor-DBT.ini", &ps, &err) != ACBB_OK) {
        ok(0, "presets/spindle-motor-DBT.ini loads: %s", err.msg);
        return;
    }
    acbb_spindle_view pv = v;
    pv.sets[0].x = ps.spindle_front_x;
    pv.sets[1].x = ps.spindle_rear_x;
    ok(acbb_spindle_page_fill(&ps, &pv, 80, &p) == 0, "the motor preset is laid out");
    for (int r = 0; r < ACBB_SP_ROWS; r++) printf("# |%s\n", p.line[r]);
    is_close(p.length, 0.330, 1e-12, 0, "its shaft spans 330 mm");
    const char *s = p.line[ACBB_SP_SETS];
    ok(strncmp(s + 8 + 5, ">><", 3) == 0 && strncmp(s + 8 + 38, "><", 2) == 0,
       "front DBT at columns 13..15, rear DB at 46..47: '%s'", s);
    /* top row: od >= 52.5 mm (4 of 4 steps at 60): the flange (0-20 mm,
     * columns 0..2) and the rotor seat (110-230 mm, columns 15..31) */
    char m[ACBB_SPINDLE_LINE];
    marks(&p, 0, m);
    char want[ACBB_SPINDLE_LINE];
    for (int c = 0; c < 46; c++) want[c] = c <= 2 || (c >= 15 && c <= 31) ? '#' : ' ';
    want[46] = '\0';
    ok(strcmp(m, want) == 0, "flange and rotor seat on top: '%s'", m);
}

static void test_none(void)
{
    static acbb_spindle_page p;
    acbb_spindle_view none = { 0 };
    ok(acbb_spindle_page_fill(&sc, &none, 80, &p) == -1, "n_sets = 0: not a spindle, nothing laid out");
    ok(strlen(acbb_spindle_none_text) <= 80 && strstr(acbb_spindle_none_text, "acbb tui presets/spindle-motor-DBT.ini"),
       "its one line fits 80 columns and names a spindle preset");
}

static void test_T_at(void)
{
    const double x[3] = { 0.01, 0.02, 0.04 }, T[3] = { 10, 20, 40 };
    is_close(acbb_spindle_T_at(x, T, 3, 0.03), 30, 1e-12, 0, "T between cells: linear");
    is_close(acbb_spindle_T_at(x, T, 3, 0.006), 10, 1e-12, 0, "T within half a spacing before the first");
    ok(isnan(acbb_spindle_T_at(x, T, 3, 0.004)), "NAN farther before the first cell");
    ok(isnan(acbb_spindle_T_at(x, T, 3, 0.051)) && acbb_spindle_T_at(x, T, 3, 0.049) == 40,
       "NAN past half a spacing after the last cell, its value within");
    ok(isnan(acbb_spindle_T_at(x, T, 0, 0.02)), "NAN without cells");
    ok(acbb_spindle_column(0.0, 0.4, 46) == 0 && acbb_spindle_column(0.4, 0.4, 46) == 45 &&
           acbb_spindle_column(-1, 0.4, 46) == 0 && acbb_spindle_column(NAN, 0.4, 46) == 0,
       "columns: the nose at 0, the end and beyond on the last, NAN at the nose");
}

static void test_drift(void)
{
    static acbb_drift_hist h;
    acbb_drift_clear(&h);
    for (int i = 0; i < 2000; i++) acbb_drift_add(&h, i, 0.5 * i);
    int rising = 1;
    for (size_t i = 1; i < h.n; i++) rising &= h.t[i] > h.t[i - 1];
    ok(h.n <= ACBB_DRIFT_CAP && h.n >= ACBB_DRIFT_CAP / 2, "2000 points kept within the cap (%zu)", h.n);
    ok(h.t[0] == 0 && h.t[h.n - 1] == 1999 && h.d[h.n - 1] == 999.5 && rising,
       "the first and the newest point kept, times rising");
    acbb_drift_add(&h, 1999, 7);
    ok(h.t[h.n - 1] == 1999 && h.d[h.n - 1] == 7, "the same time replaces the last point");
    size_t n = h.n;
    acbb_drift_add(&h, 2000, NAN);
    ok(h.n == n, "a non-finite drift is left out");
    acbb_drift_add(&h, 3, 1);
    ok(h.n == 1 && h.t[0] == 3, "an earlier time starts a new history");
}

int main(void)
{
    fill();
    test_fits(80);
    test_fits(120);
    test_fits(400);
    test_shaft();
    test_numbers();
    test_wide();
    test_preset();
    test_none();
    test_T_at();
    test_drift();
    return done_testing();
}
