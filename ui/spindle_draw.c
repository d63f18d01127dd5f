/* acbb TUI — the Spindle screen's rows (spindle_draw.h). The shaft is a
 * half section along x: one column per pic_w-th of its length, each
 * segment's outer diameter a height in ACBB_SPINDLE_PROFILE steps (nearest) of the
 * largest (docs/spindle.md "Geometry: segments"); a set's glyph is its
 * bearings' thrust directions ('>' for +x, '<' for -x, so DB reads "><"). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/set.h"
#include "spindle_draw.h"

const char acbb_spindle_none_text[] =
    "Not a spindle. Open one: o (presets), or acbb tui presets/spindle-motor-DBT.ini";

int acbb_spindle_column(double x, double length, int w)
{
    if (w <= 0) return 0;
    int c = length > 0 && isfinite(x) ? (int)floor(x / length * w) : 0;
    return c < 0 ? 0 : c >= w ? w - 1 : c;
}

double acbb_spindle_T_at(const double *xs, const double *T, int n, double x)
{
    if (n <= 0) return NAN;
    if (n == 1) return T[0];
    double h0 = 0.5 * (xs[1] - xs[0]), h1 = 0.5 * (xs[n - 1] - xs[n - 2]);
    if (x < xs[0]) return x >= xs[0] - h0 ? T[0] : NAN;
    if (x > xs[n - 1]) return x <= xs[n - 1] + h1 ? T[n - 1] : NAN;
    int i = 0;
    while (i < n - 2 && x > xs[i + 1]) i++;
    double d = xs[i + 1] - xs[i], f = d > 0 ? (x - xs[i]) / d : 0;
    return T[i] + f * (T[i + 1] - T[i]);
}

/* Text at column x of row s (cols wide, blank filled), clipped at cols. */
static void put(char *s, int cols, int x, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static void put(char *s, int cols, int x, const char *fmt, ...)
{
    char buf[ACBB_SPINDLE_LINE];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    for (int i = 0; buf[i] && x + i < cols; i++)
        if (x + i >= 0) s[x + i] = buf[i];
}

static double shaft_length(const acbb_scene *sc)
{
    double L = 0;
    for (int i = 0; i < sc->shaft_segments && i < ACBB_SPINDLE_MAX_SEG; i++) L += sc->shaft_seg[i].length;
    return L;
}

/* The outer diameter of the shaft at x (the segment holding it). */
static double od_at(const acbb_scene *sc, double x)
{
    double x0 = 0;
    int n = sc->shaft_segments < ACBB_SPINDLE_MAX_SEG ? sc->shaft_segments : ACBB_SPINDLE_MAX_SEG;
    for (int i = 0; i < n; i++) {
        x0 += sc->shaft_seg[i].length;
        if (x < x0 || i == n - 1) return sc->shaft_seg[i].od;
    }
    return 0;
}

static void profile(const acbb_scene *sc, acbb_spindle_page *p)
{
    double odmax = 0;
    for (int i = 0; i < sc->shaft_segments && i < ACBB_SPINDLE_MAX_SEG; i++)
        if (sc->shaft_seg[i].od > odmax) odmax = sc->shaft_seg[i].od;
    for (int c = 0; c < p->pic_w && odmax > 0; c++) {
        double od = od_at(sc, (c + 0.5) * p->length / p->pic_w);
        int h = (int)lround(od / odmax * ACBB_SPINDLE_PROFILE); /* nearest step; at least 1 */
        if (h < 1) h = 1;
        for (int k = 0; k < h && k < ACBB_SPINDLE_PROFILE; k++)
            p->line[ACBB_SP_PROFILE + ACBB_SPINDLE_PROFILE - 1 - k][p->pic_x + c] = '#';
    }
    put(p->line[ACBB_SP_PROFILE + ACBB_SPINDLE_PROFILE - 1], p->cols, 0, "nose ->");
}

/* A set's glyph: one '>' (+x) or '<' (-x) per bearing, as the
 * arrangement's orientations (acbb_set_kinds), the last repeated. */
static void glyph(acbb_set_arrangement arr, int n, char *g, size_t len)
{
    const char *o = arr < ACBB_SET_ARRANGEMENTS ? acbb_set_kinds[arr].orient : "+";
    if (n < 1) n = arr < ACBB_SET_ARRANGEMENTS ? acbb_set_kinds[arr].n : 1;
    size_t k = 0, no = strlen(o);
    for (; k < (size_t)n && k + 1 < len; k++) g[k] = o[k < no ? k : no - 1] == '-' ? '<' : '>';
    g[k] = '\0';
}

static void sets(const acbb_scene *sc, const acbb_spindle_view *v, acbb_spindle_page *p)
{
    char *s = p->line[ACBB_SP_SETS];
    put(s, p->cols, 0, "sets");
    for (int k = 0; k < ACBB_SPINDLE_SETS; k++) {
        char g[ACBB_MAX_SET + 1];
        glyph(k == 0 ? sc->set_arrangement : sc->spindle_rear_arrangement, v->sets[k].n_bearings, g, sizeof g);
        int c = acbb_spindle_column(v->sets[k].x, p->length, p->pic_w), n = (int)strlen(g);
        int start = c - (n - 1) / 2;
        if (start > p->pic_w - n) start = p->pic_w - n;
        if (start < 0) start = 0;
        p->set_col[k] = p->pic_x + c;
        put(s, p->pic_x + p->pic_w, p->pic_x + start, "%s", g);
    }
}

/* Labels of x in mm at a step of 1, 2 or 5 times a power of ten that
 * leaves at least 8 columns between them, each at the column of its x. */
static void scale(acbb_spindle_page *p)
{
    char *s = p->line[ACBB_SP_SCALE];
    put(s, p->cols, 0, "x mm");
    double Lmm = p->length * 1e3, step = 1;
    static const double mult[3] = { 1, 2, 5 };
    for (double dec = 1; dec < 1e9; dec *= 10) {
        int m = 0;
        while (m < 3 && mult[m] * dec / Lmm * p->pic_w < 8) m++;
        if (m < 3) {
            step = mult[m] * dec;
            break;
        }
    }
    int next = 0; /* first free column */
    for (double x = 0; x <= Lmm + 1e-9; x += step) {
        int c = acbb_spindle_column(x * 1e-3, p->length, p->pic_w);
        char lab[16];
        int n = snprintf(lab, sizeof lab, "%g", x);
        if (c < next || c + n > p->pic_w) continue;
        put(s, p->pic_x + p->pic_w, p->pic_x + c, "%s", lab);
        next = c + n + 1;
    }
}

/* T along x at the centres of ACBB_SPINDLE_T_CELL-column groups. */
static void temps(acbb_spindle_page *p, int row, const char *label, const double *xs, const double *T, int n)
{
    char *s = p->line[row];
    if (n > ACBB_SPINDLE_MAX_CELLS) n = ACBB_SPINDLE_MAX_CELLS;
    put(s, p->cols, 0, "%s", label);
    for (int g = 0; (g + 1) * ACBB_SPINDLE_T_CELL <= p->pic_w; g++) {
        double x = (g + 0.5) * ACBB_SPINDLE_T_CELL * p->length / p->pic_w;
        double t = acbb_spindle_T_at(xs, T, n, x);
        if (!isfinite(t)) continue;
        put(s, p->cols, p->pic_x + g * ACBB_SPINDLE_T_CELL, fabs(t) < 999.95 ? "%6.1f" : "%6.0f", t);
    }
}

static void coolant(const acbb_scene *sc, const acbb_spindle_view *v, acbb_spindle_page *p)
{
    char *s = p->line[ACBB_SP_COOLANT];
    put(s, p->cols, 0, "coolant");
    if (sc->coolant_flow > 0)
        put(s, p->side_x - 1, p->pic_x, "in %.1f C  out %.1f C  takes %.0f W", v->T_coolant_in_C,
            v->T_coolant_out_C, v->Q_coolant_W);
    else
        put(s, p->side_x - 1, p->pic_x, "none (spindle.coolant_flow_l_min = 0)");
}

/* "%8.1f" of v, or "pending" while it is not known (0 before the
 * converged state's stiffness, or not finite). */
static void known(char *buf, size_t n, double v, double scale)
{
    if (isfinite(v) && v > 0) snprintf(buf, n, "%8.1f", v * scale);
    else snprintf(buf, n, " pending");
}

static void side(const acbb_spindle_view *v, acbb_spindle_page *p)
{
    char kr[32], ka[32];
    known(kr, sizeof kr, v->nose_k_radial, 1e-6);
    known(ka, sizeof ka, v->nose_k_axial, 1e-6);
    int x = p->side_x, r = ACBB_SP_PROFILE, w = p->cols;
    put(p->line[r++], w, x, "nose drift  %+8.2f um", v->nose_drift_axial * 1e6);
    put(p->line[r++], w, x, "    radial  %+8.2f um", v->nose_drift_radial * 1e6);
    put(p->line[r++], w, x, "nose k rad  %s N/um", kr);
    put(p->line[r++], w, x, "     axial  %s N/um", ka);
    static const char *const name[ACBB_SPINDLE_SETS] = { "front", "rear " };
    for (int k = 0; k < ACBB_SPINDLE_SETS; k++) {
        const acbb_spindle_set_view *sv = &v->sets[k];
        put(p->line[r++], w, x, "%s preload %7.1f N", name[k], sv->preload_N);
        put(p->line[r++], w, x, " Fa %5.0f Fr %5.0f N%s", sv->axial_N, sv->radial_N,
            sv->contact_lost ? " LIFT" : "");
    }
    put(p->line[r], w, x, "motor %.0f W  sets %.0f W", v->Q_motor_W, v->Q_bearings_W);
}

static void header(const acbb_scene *sc, const acbb_spindle_view *v, acbb_spindle_page *p)
{
    static const char *const support[] = { "fixed", "spring", "floating" };
    unsigned rs = (unsigned)sc->spindle_rear_support;
    put(p->line[ACBB_SP_HEADER], p->cols, 0, "Spindle: shaft %.0f mm, front %s at %.0f mm, rear %s at %.0f mm (%s)",
        p->length * 1e3, acbb_set_arrangement_name(sc->set_arrangement), v->sets[0].x * 1e3,
        acbb_set_arrangement_name(sc->spindle_rear_arrangement), v->sets[1].x * 1e3,
        rs < 3 ? support[rs] : "?");
}

int acbb_spindle_page_fill(const acbb_scene *sc, const acbb_spindle_view *v, int cols, acbb_spindle_page *p)
{
    memset(p, 0, sizeof *p);
    if (v->n_sets == 0 || sc->shaft_segments <= 0) return -1;
    if (cols > ACBB_SPINDLE_LINE - 1) cols = ACBB_SPINDLE_LINE - 1;
    p->cols = cols;
    p->side_x = cols - ACBB_SPINDLE_SIDE_W;
    p->pic_x = ACBB_SPINDLE_GUTTER;
    p->pic_w = p->side_x - 1 - p->pic_x;
    p->length = shaft_length(sc);
    for (int r = 0; r < ACBB_SP_ROWS; r++) memset(p->line[r], ' ', (size_t)cols);
    header(sc, v, p);
    profile(sc, p);
    sets(sc, v, p);
    scale(p);
    temps(p, ACBB_SP_SHAFT_T, "shaft C", v->shaft_x, v->shaft_T_C, v->n_shaft);
    temps(p, ACBB_SP_HOUSING_T, "hous. C", v->housing_x, v->housing_T_C, v->n_housing);
    coolant(sc, v, p);
    side(v, p);
    for (int r = 0; r < ACBB_SP_ROWS; r++) {
        int n = cols;
        while (n > 0 && p->line[r][n - 1] == ' ') n--;
        p->line[r][n] = '\0';
    }
    return 0;
}
