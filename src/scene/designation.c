/* acbb — bearings from their designation (designation.h).
 *
 * Boundary dimensions: ISO 15:2017 "Rolling bearings — Radial bearings —
 * Boundary dimensions, general plan", the tables of diameter series 8, 9,
 * 0, 2 and 3 (dimension series 18, 19, 10, 02, 03; ball-bearing
 * designations 618/718, 619/719, 60/70, 62/72, 63/73). The numbers below
 * were transcribed from manufacturers' catalogue tables that follow the
 * ISO general plan (e.g. the SKF deep-groove and angular-contact tables),
 * not from the ISO text itself; spot checks: 7008 = 40 x 68 x 15 (MODEL.md
 * 10), 6205/7205 = 25 x 52 x 15, 7014 = 70 x 110 x 20, 71810 = 50 x 65 x 7.
 * tests/test_new.sh cross-checks 36 more designations of all five series
 * against the SKF catalogue read separately.
 *
 * Internal geometry is not published; the rules (each written into the
 * preset next to its key, see estimate()) are:
 * - pitch diameter d_m = (d + D) / 2;
 * - ball diameter D_w = 0.30 (D - d), the middle of the 0.265..0.345 band of
 *   the usual design rule D_w = 0.5 (D - d) - (0.155..0.235)(D - d), for
 *   deep groove and angular contact alike, rounded DOWN to a standard inch
 *   ball (1/32" steps from 1/4" up, 1/64" below). Catalogue spindle
 *   bearings carry balls this size: NSK CAT. No. E1102e gives 7008 C
 *   f_0 = 15.4 and C_0r = 15 900 N, which ISO 76 (f_0 at gamma = D_w cos a /
 *   d_m; C_0 = f_0 Z D_w^2 cos a) inverts to 17 balls of 7.938 mm
 *   (0.283 (D - d)), and 7208 C f_0 = 14.1, C_0r 25 200 N to 13 balls of
 *   11.906 mm (0.298 (D - d)); the earlier 0.25 gave C 0.69-0.80 of the
 *   catalogue's (issue 19; docs/ratings.md has the comparison);
 * - ball count: deep groove by the Conrad assembly angle [HK-EC ch. 1]
 *   phi = 2 (Z - 1) asin(D_w / d_m) <= 192 deg (ASSUMED limit:
 *   it gives the 9 balls of 7.938 mm of a 6205); angular
 *   contact (counterbored outer ring) by a ball fill Z D_w <= 0.8 pi d_m
 *   (the two NSK bearings above fill 0.80 and 0.82); at most ACBB_MAX_BALLS;
 * - groove curvature f_i = 0.52, f_o = 0.53 for both types: the conformity
 *   ISO 281's f_c values (Table 2) are computed for (6.1.1), so that C of an
 *   estimated bearing is ISO 281's; wider grooves lower C (life.h);
 * - deep-groove clearance: the middle of ISO 5753-1 group N (CN) radial
 *   internal clearance for the bore;
 * - lands, cage and shaft bore in the seed 7008C's proportions (MODEL.md
 *   10): lands d_m -/+ 0.646 D_w, cage guide d_m + 0.583 D_w, cage width
 *   0.673 B, hollow-shaft bore 0.625 d; the shoulder heights (life.*) are
 *   the lands' height over the groove bottoms, 0.177 D_w;
 * - a default operating point the bearing can take (issue 19): the inner
 *   ring at a quarter of the catalogue's oil-lubrication limit n d_m of its
 *   type (a quarter, not a half: the derived surroundings cool the larger
 *   sizes by convection only (MODEL.md 13, 16), and at half the limit the
 *   200 mm bores of the 72 and 73 series ran away or did not settle within
 *   thermal.max_time_s; catalogue limits assume a cooled spindle)
 *   (NSK CAT. No. E1102e, single bearings: 7008 C 20 000 rpm on d_m 54 mm =
 *   1.08e6, 7908 A5 15 000 rpm on 51 mm = 0.77e6, 7208 B 9 000 rpm on 60 mm
 *   = 0.54e6; SKF General Catalogue 6205: limiting speed 18 000 rpm on
 *   38.5 mm = 0.69e6), the load 5 % of the estimated C_0 (ISO 76): axial for
 *   angular contact, radial for deep groove (a light load, s_0 near 20). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "acbb/tools/designation.h"
#include "acbb/limits.h"
#include "acbb/units.h"
#include "hertz.h"
#include "life.h"

/* One bore: D and B (mm) for dimension series 18, 19, 10, 02, 03. */
enum { S18, S19, S10, S02, S03, N_DIM };
typedef struct { short d; short D[N_DIM], B[N_DIM]; } dim_row;

#define ROW(d, D18, B18, D19, B19, D10, B10, D02, B02, D03, B03) \
    { d, { D18, D19, D10, D02, D03 }, { B18, B19, B10, B02, B03 } }
static const dim_row k_dims[] = {
    ROW(10, 19, 5, 22, 6, 26, 8, 30, 9, 35, 11),
    ROW(12, 21, 5, 24, 6, 28, 8, 32, 10, 37, 12),
    ROW(15, 24, 5, 28, 7, 32, 9, 35, 11, 42, 13),
    ROW(17, 26, 5, 30, 7, 35, 10, 40, 12, 47, 14),
    ROW(20, 32, 7, 37, 9, 42, 12, 47, 14, 52, 15),
    ROW(25, 37, 7, 42, 9, 47, 12, 52, 15, 62, 17),
    ROW(30, 42, 7, 47, 9, 55, 13, 62, 16, 72, 19),
    ROW(35, 47, 7, 55, 10, 62, 14, 72, 17, 80, 21),
    ROW(40, 52, 7, 62, 12, 68, 15, 80, 18, 90, 23),
    ROW(45, 58, 7, 68, 12, 75, 16, 85, 19, 100, 25),
    ROW(50, 65, 7, 72, 12, 80, 16, 90, 20, 110, 27),
    ROW(55, 72, 9, 80, 13, 90, 18, 100, 21, 120, 29),
    ROW(60, 78, 10, 85, 13, 95, 18, 110, 22, 130, 31),
    ROW(65, 85, 10, 90, 13, 100, 18, 120, 23, 140, 33),
    ROW(70, 90, 10, 100, 16, 110, 20, 125, 24, 150, 35),
    ROW(75, 95, 10, 105, 16, 115, 20, 130, 25, 160, 37),
    ROW(80, 100, 10, 110, 16, 125, 22, 140, 26, 170, 39),
    ROW(85, 110, 13, 120, 18, 130, 22, 150, 28, 180, 41),
    ROW(90, 115, 13, 125, 18, 140, 24, 160, 30, 190, 43),
    ROW(95, 120, 13, 130, 18, 145, 24, 170, 32, 200, 45),
    ROW(100, 125, 13, 140, 20, 150, 24, 180, 34, 215, 47),
    ROW(105, 130, 13, 145, 20, 160, 26, 190, 36, 225, 49),
    ROW(110, 140, 16, 150, 20, 170, 28, 200, 38, 240, 50),
    ROW(120, 150, 16, 165, 22, 180, 28, 215, 40, 260, 55),
    ROW(130, 165, 18, 180, 24, 200, 33, 230, 40, 280, 58),
    ROW(140, 175, 18, 190, 24, 210, 33, 250, 42, 300, 62),
    ROW(150, 190, 20, 210, 28, 225, 35, 270, 45, 320, 65),
    ROW(160, 200, 20, 220, 28, 240, 38, 290, 48, 340, 68),
    ROW(170, 215, 22, 230, 28, 260, 42, 310, 52, 360, 72),
    ROW(180, 225, 22, 250, 33, 280, 46, 320, 52, 380, 75),
    ROW(190, 240, 24, 260, 33, 290, 46, 340, 55, 400, 78),
    ROW(200, 250, 24, 280, 38, 310, 51, 360, 58, 420, 80),
};
#undef ROW
#define N_BORES (sizeof k_dims / sizeof k_dims[0])

/* Designation series -> dimension series column and bearing type. */
typedef struct { int series; int dim; int deep; } series_row;
static const series_row k_series[] = {
    { 718, S18, 0 }, { 719, S19, 0 }, { 70, S10, 0 }, { 72, S02, 0 }, { 73, S03, 0 },
    { 618, S18, 1 }, { 619, S19, 1 }, { 60, S10, 1 }, { 62, S02, 1 }, { 63, S03, 1 },
};

/* ISO 5753-1 group N radial internal clearance of deep-groove ball
 * bearings, um: bore over `above` up to the next row's. */
typedef struct { short above, lo, hi; } clearance_row;
static const clearance_row k_cn[] = {
    { 6, 2, 13 }, { 10, 3, 18 }, { 18, 5, 20 }, { 30, 6, 20 }, { 40, 6, 23 },
    { 50, 8, 28 }, { 65, 10, 30 }, { 80, 12, 36 }, { 100, 15, 41 }, { 120, 18, 48 },
    { 140, 18, 53 }, { 160, 20, 61 }, { 180, 25, 71 },
};

static const series_row *find_series(int series)
{
    for (size_t i = 0; i < sizeof k_series / sizeof k_series[0]; i++)
        if (k_series[i].series == series) return &k_series[i];
    return NULL;
}

static const char *suffix_of(double angle_deg)
{
    if (fabs(angle_deg - 15.0) < 1e-9) return "C";
    if (fabs(angle_deg - 25.0) < 1e-9) return "AC";
    if (fabs(angle_deg - 40.0) < 1e-9) return "B";
    return NULL;
}

/* Bore code of the designation: 00 10, 01 12, 02 15, 03 17, else d / 5. */
static int bore_code(int d)
{
    static const int small[] = { 10, 12, 15, 17 };
    for (int i = 0; i < 4; i++)
        if (d == small[i]) return i;
    return d / 5;
}

acbb_status acbb_designation_make(int series, double bore_mm, double angle_deg,
                                  acbb_designation *d, acbb_error *err)
{
    const series_row *sr = find_series(series);
    if (!sr)
        return acbb_error_set(err, ACBB_EINVAL,
                              "series %d: not supported (angular contact 70, 72, 73, 718, 719; "
                              "deep groove 60, 62, 63, 618, 619)", series);
    const dim_row *r = NULL;
    for (size_t i = 0; i < N_BORES; i++)
        if (fabs(bore_mm - k_dims[i].d) < 1e-9) r = &k_dims[i];
    if (!r)
        return acbb_error_set(err, ACBB_EINVAL,
                              "bore %g mm: not in the ISO 15 table (10, 12, 15, 17, then 20..110 "
                              "in 5 mm steps, 120..200 in 10 mm steps)", bore_mm);
    if (angle_deg < 0.0) angle_deg = 0.0;
    if (sr->deep && angle_deg != 0.0)
        return acbb_error_set(err, ACBB_EINVAL,
                              "series %d is deep groove: no contact angle (got %g deg)", series,
                              angle_deg);
    if (!sr->deep && !(angle_deg >= 5.0 && angle_deg <= 45.0))
        return acbb_error_set(err, ACBB_EINVAL,
                              "series %d is angular contact: the angle must be 5..45 deg "
                              "(C = 15, AC = 25, B = 40), got %g", series, angle_deg);
    memset(d, 0, sizeof *d);
    d->series = series;
    d->deep_groove = sr->deep;
    d->angle = angle_deg * ACBB_DEG;
    d->bore = r->d * 1e-3;
    d->outer_diameter = r->D[sr->dim] * 1e-3;
    d->width = r->B[sr->dim] * 1e-3;
    const char *suf = sr->deep ? "" : suffix_of(angle_deg);
    if (suf)
        snprintf(d->name, sizeof d->name, "%d%02d%s", series, bore_code(r->d), suf);
    else
        snprintf(d->name, sizeof d->name, "%d%02d-%gdeg", series, bore_code(r->d), angle_deg);
    return ACBB_OK;
}

acbb_status acbb_designation_parse(const char *text, acbb_designation *d, acbb_error *err)
{
    size_t nd = strspn(text, "0123456789");
    const char *suf = text + nd;
    if (nd != 4 && nd != 5)
        return acbb_error_set(err, ACBB_EINVAL,
                              "designation \"%s\": expected 4 or 5 digits and an angle suffix, "
                              "e.g. 7014C, 71810AC, 7205B, 6205", text);
    char head[4] = { 0 };
    memcpy(head, text, nd - 2);
    int series = atoi(head), code = atoi(text + nd - 2);
    int bore = code < 4 ? (int[]){ 10, 12, 15, 17 }[code] : 5 * code;
    double angle = -1.0;
    if (!strcmp(suf, "C") || !strcmp(suf, "c")) angle = 15.0;
    else if (!strcmp(suf, "AC") || !strcmp(suf, "ac")) angle = 25.0;
    else if (!strcmp(suf, "B") || !strcmp(suf, "b")) angle = 40.0;
    else if (*suf)
        return acbb_error_set(err, ACBB_EINVAL,
                              "designation \"%s\": unknown suffix \"%s\" (C = 15 deg, AC = 25 "
                              "deg, B = 40 deg; none for deep groove)", text, suf);
    const series_row *sr = find_series(series);
    if (sr && !sr->deep && angle < 0.0)
        return acbb_error_set(err, ACBB_EINVAL,
                              "designation \"%s\": an angular-contact bearing needs an angle "
                              "suffix (C = 15 deg, AC = 25 deg, B = 40 deg)", text);
    acbb_error e;
    acbb_status rc = acbb_designation_make(series, bore, angle, d, &e);
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "designation \"%s\": %s", text, e.msg);
    return ACBB_OK;
}

/* Largest standard inch ball not above x (m): 1/32" steps from 1/4"
 * (6.35 mm) up, 1/64" below. */
static double standard_ball(double x)
{
    const double inch = 25.4e-3;
    double step = x >= 0.25 * inch ? inch / 32.0 : inch / 64.0;
    return floor(x / step + 1e-9) * step;
}

static double cn_clearance(double bore)
{
    const clearance_row *r = &k_cn[0];
    for (size_t i = 0; i < sizeof k_cn / sizeof k_cn[0]; i++)
        if (bore * 1e3 > k_cn[i].above) r = &k_cn[i];
    return 0.5 * (r->lo + r->hi) * 1e-6;
}

static size_t note(acbb_estimate *notes, size_t n, size_t cap, const char *key,
                   const char *fmt, double v)
{
    if (n >= cap) return n;
    notes[n].key = key;
    snprintf(notes[n].rule, sizeof notes[n].rule, fmt, v);
    return n + 1;
}

/* Ball count: Conrad assembly angle (deep groove) or ball fill. */
static int ball_count(const acbb_designation *d, double Dw, double dm)
{
    double z = d->deep_groove ? floor(192.0 * ACBB_DEG / (2.0 * asin(Dw / dm))) + 1.0
                              : floor(0.8 * ACBB_PI * dm / Dw);
    return (int)fmin(z, ACBB_MAX_BALLS);
}

/* A length (m) on a 1 um grid, stored as the parser would store its value
 * in mm (value * 1e-3), so the preset shows "3.429", not 3.4290000000000003. */
static double um_grid(double m)
{
    return round(m * 1e6) / 1e3 * 1e-3;
}

/* A quarter of the catalogue's oil limit n d_m (rpm mm) by type (header
 * comment). */
static double ndm_default(const acbb_designation *d)
{
    double deg = d->angle / ACBB_DEG;
    if (d->deep_groove) return 0.25 * 0.69e6;
    return deg < 20.0 ? 0.25 * 1.08e6 : deg < 32.5 ? 0.25 * 0.77e6 : 0.25 * 0.54e6;
}

/* The default operating point (header comment): speed on a 100 rpm grid,
 * load 5 % of C_0 on a 10 N grid. */
static size_t operating_point(const acbb_designation *d, acbb_scene *s, acbb_estimate *notes,
                              size_t n, size_t cap)
{
    double Dw = s->ball_diameter, E = acbb_effective_modulus(s->ball.E, s->ball.nu, s->ring.E,
                                                              s->ring.nu);
    double ndm = ndm_default(d), C0 = acbb_iso_C0(Dw, s->n_balls, d->angle, s->pitch_diameter,
                                                   s->inner_groove_radius / Dw,
                                                   s->outer_groove_radius / Dw, E);
    double rpm = fmax(100.0, round(ndm / (s->pitch_diameter * 1e3) / 100.0) * 100.0);
    double load = fmax(10.0, round(0.05 * C0 / 10.0) * 10.0);
    s->inner_speed = rpm * ACBB_RPM;
    s->axial_load = d->deep_groove ? 0.0 : load;
    s->radial_load = d->deep_groove ? load : 0.0;
    /* The default 10 h bound suits the seed rig (D 68 mm); a 420 mm bearing
     * cooled by convection takes longer to settle (7340C: 11 h): allow
     * 10 h per 68 mm of outside diameter, never less than the default. */
    s->max_time = fmax(s->max_time, round(s->max_time * d->outer_diameter / 0.068 / 3600.0) * 3600.0);
    n = note(notes, n, cap, "thermal.max_time_s",
             "10 h of simulated time per 68 mm of outside diameter (seed rig), %.0f s",
             s->max_time);
    n = note(notes, n, cap, "operating.inner_speed_rpm",
             "n d_m = %.3g rpm mm, a quarter of the catalogue oil limit of the type", ndm);
    return note(notes, n, cap, d->deep_groove ? "operating.radial_load_N" : "operating.axial_load_N",
                "5 %% of the estimated C_0 (ISO 76) = %.0f N", C0);
}

size_t acbb_designation_scene(const acbb_designation *d, acbb_scene *s, acbb_estimate *notes,
                              size_t cap)
{
    size_t n = 0;
    acbb_scene_default(s);
    s->bore = d->bore;
    s->outer_diameter = d->outer_diameter;
    s->width = d->width;
    s->contact_angle0 = d->angle;
    double section = d->outer_diameter - d->bore, k = 0.30;
    s->pitch_diameter = um_grid(0.5 * (d->bore + d->outer_diameter));
    s->ball_diameter = um_grid(standard_ball(k * section));
    s->n_balls = ball_count(d, s->ball_diameter, s->pitch_diameter);
    double fi = 0.52, fo = 0.53;
    double dm = s->pitch_diameter, Dw = s->ball_diameter;
    s->inner_groove_radius = um_grid(fi * Dw);
    s->outer_groove_radius = um_grid(fo * Dw);
    /* 0.1 um grid, in um as the parser stores it */
    s->clearance = d->deep_groove ? round(cn_clearance(d->bore) * 1e7) / 10.0 * 1e-6 : 0.0;
    s->inner_land_diameter = um_grid(dm - 0.646 * Dw);
    s->outer_land_diameter = um_grid(dm + 0.646 * Dw);
    s->cage_diameter = um_grid(dm + 0.583 * Dw);
    s->cage_width = um_grid(0.673 * d->width);
    s->shaft_bore = um_grid(0.625 * d->bore);
    s->life_shoulder_inner = um_grid(0.5 * (s->inner_land_diameter - (dm - Dw)));
    s->life_shoulder_outer = um_grid(0.5 * (dm + Dw - s->outer_land_diameter));
    s->life_estimated = true;
    n = note(notes, n, cap, "bearing.pitch_diameter_mm", "(d + D) / 2", 0);
    n = note(notes, n, cap, "bearing.ball_diameter_mm",
             "%.2f (D - d), rounded down to a standard inch ball", k);
    n = note(notes, n, cap, "bearing.n_balls",
             d->deep_groove ? "Conrad assembly angle 2 (Z - 1) asin(D_w / d_m) <= 192 deg"
                            : "ball fill Z D_w <= 0.8 pi d_m", 0);
    n = note(notes, n, cap, "bearing.inner_groove_radius_mm",
             "f_i = %.2f ball diameters (ISO 281 Table 2 basis)", fi);
    n = note(notes, n, cap, "bearing.outer_groove_radius_mm",
             "f_o = %.2f ball diameters (ISO 281 Table 2 basis)", fo);
    if (d->deep_groove)
        n = note(notes, n, cap, "bearing.clearance_um",
                 "middle of ISO 5753-1 group N (CN) for the bore: %.1f um", s->clearance * 1e6);
    n = note(notes, n, cap, "bearing.cage_width_mm", "%.3f B (the seed 7008C's proportion)",
             0.673);
    n = note(notes, n, cap, "bearing.cage_diameter_mm", "d_m + %.3f D_w (seed 7008C)", 0.583);
    n = note(notes, n, cap, "bearing.inner_land_diameter_mm", "d_m - %.3f D_w (seed 7008C)",
             0.646);
    n = note(notes, n, cap, "bearing.outer_land_diameter_mm", "d_m + %.3f D_w (seed 7008C)",
             0.646);
    n = note(notes, n, cap, "mounting.shaft_bore_mm", "%.3f d (seed: 25 mm in a 40 mm bore)",
             0.625);
    n = note(notes, n, cap, "life.inner_shoulder_mm", "the land's height over the groove, "
             "%.3f D_w (seed 7008C)", 0.177);
    n = note(notes, n, cap, "life.outer_shoulder_mm", "the land's height over the groove, "
             "%.3f D_w (seed 7008C)", 0.177);
    n = note(notes, n, cap, "life.internals_estimated", "C and C0 come from the estimates above",
             0);
    return operating_point(d, s, notes, n, cap);
}
