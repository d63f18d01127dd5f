/* Tests of the figures' layout for print (issue 29 item 9): --size text,
 * the text size for a width, and the gnuplot script an x-y figure sends
 * (captured by a fake gnuplot that saves its stdin and fails, so no
 * gnuplot is needed): the key where no data are, tic steps that fit their
 * labels, no negative axis for a positive quantity, markers and dashes per
 * family, the factored key, the space after a subscript, the title wrap. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "tap.h"
#include "acbb/tools/plot.h"

static char dir[64], script[96];

static void test_sizes(void)
{
    int w = 0, h = 0;
    int r = acbb_plot_parse_size("column", &w, &h);
    ok(r == 0 && w == 1004 && h == 753,
       "column: 8.5 x 6.4 cm at 300 dpi = 1004 x 753 px (%dx%d)", w, h);
    r = acbb_plot_parse_size("full", &w, &h);
    ok(r == 0 && w == 2067 && h == 1034,
       "full: 17.5 x 8.75 cm at 300 dpi = 2067 x 1034 px (%dx%d)", w, h);
    r = acbb_plot_parse_size("85mm", &w, &h);
    ok(r == 0 && w == 1004 && h == 753,
       "85mm: the column width, height 3/4 (%dx%d)", w, h);
    r = acbb_plot_parse_size("8.5cm", &w, &h);
    ok(r == 0 && w == 1004, "8.5cm = 85mm (%d)", w);
    r = acbb_plot_parse_size("85mmx60mm", &w, &h);
    ok(r == 0 && w == 1004 && h == 709,
       "85mmx60mm: 60 mm = 709 px at 300 dpi (%dx%d)", w, h);
    ok(acbb_plot_parse_size("900x600", &w, &h) == 0 && w == 900 && h == 600, "900x600 pixels");
    const char *bad[] = { "85", "85mmx", "axb", "12.5x3", "900x", "column2", "-5mm", "" };
    int refused = 0;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        refused += acbb_plot_parse_size(bad[i], &w, &h) == -1;
    ok(refused == 8, "malformed sizes refused (%d of 8)", refused);
    /* 8.5 pt at 8.5 cm (241 pt): the em is 8.5/241 of the width */
    is_close(acbb_plot_font_px(1004) / 1004.0 * 241.0, 8.5, 1e-12, 0, "column: text 8.5 pt");
    is_close(acbb_plot_font_px(900) / 900.0 * 241.0, 8.5, 1e-12, 0,
             "900 px wide printed at column width: 8.5 pt (was 12 px = 3.2 pt)");
    is_close(acbb_plot_font_px(2067) * 72.0 / 300.0, 9.0, 1e-12, 0, "full: 9 pt at 300 dpi");
}

/* Run one x-y plot through the fake gnuplot; the script, malloc'd. */
static char *xy_script(const acbb_plot_xy *p, const acbb_plot_look *look, int w, int h)
{
    char png[128];
    acbb_error err = { { 0 } };
    snprintf(png, sizeof png, "%s/x.png", dir);
    unlink(script);
    acbb_plot_xy_styled(p, look, png, NULL, w, h, &err); /* the fake fails: EIO */
    FILE *f = fopen(script, "r");
    if (!f) return NULL;
    char *buf = calloc(1, 1 << 20);
    if (buf) buf[fread(buf, 1, (1 << 20) - 1, f)] = '\0';
    fclose(f);
    return buf;
}

static double range_lo(const char *s, const char *axis)
{
    char key[32];
    snprintf(key, sizeof key, "set %srange [", axis);
    const char *p = s ? strstr(s, key) : NULL;
    return p ? strtod(p + strlen(key), NULL) : NAN;
}

static double range_hi(const char *s, const char *axis)
{
    char key[32];
    snprintf(key, sizeof key, "set %srange [", axis);
    const char *p = s ? strstr(s, key) : NULL;
    p = p ? strchr(p, ':') : NULL;
    return p ? strtod(p + 1, NULL) : NAN;
}

static void test_key_free_corner(void)
{
    /* an L: along the bottom, then up the right side; top left is empty */
    double x[3] = { 0, 10, 10 }, y[3] = { 0, 0, 10 };
    acbb_plot_series s = { "an L", x, y, 3, 1, 1, 1 };
    acbb_plot_xy p = { "corner", "x (m)", "y (m)", &s, 1 };
    char *t = xy_script(&p, NULL, 1004, 753);
    has_substr(t, "set key inside top left", "the key goes to the one empty corner");
    is_close(range_hi(t, "y"), 10, 1e-12, 0, "and the y axis is not raised for it");
    free(t);
}

static void test_key_raised(void)
{
    /* two lines across the whole width at the bottom and the top */
    double x[2] = { 0, 10 }, lo[2] = { 0, 0 }, hi[2] = { 10, 10 };
    acbb_plot_series s[2] = { { "low", x, lo, 2, 1, 1, 1 }, { "high", x, hi, 2, 2, 2, 1 } };
    acbb_plot_xy p = { "full", "x (m)", "y (m)", s, 2 };
    char *t = xy_script(&p, NULL, 1004, 753);
    has_substr(t, "set key inside top right", "no empty corner: the key at the top");
    double top = range_hi(t, "y");
    /* the key's band: 2 rows of 1.45 em + 0.8 em over the plot area */
    double em = acbb_plot_font_px(1004), plot_h = 753 - (1.5 + 1.5 + 4.0) * em;
    double band = (2 * 1.45 + 0.8) * em / plot_h;
    ok(10.0 / top <= 1.0 - band, "the y axis is raised so the data (max 10) stay below the key's "
       "band (%.3f of the height): top %g", band, top);
    free(t);
}

static void test_ticks_and_zero(void)
{
    /* a speed sweep 2000..16000 rpm of a positive quantity at 450 px */
    double x[8], y[8];
    for (int i = 0; i < 8; i++) x[i] = 2000.0 * (i + 1), y[i] = 0.05 + 0.1 * i;
    acbb_plot_series s = { "H_i", x, y, 8, 1, 1, 1 };
    acbb_plot_xy p = { NULL, "inner-ring speed (rpm)", "film thickness (um)", &s, 1 };
    char *t = xy_script(&p, NULL, 450, 300);
    /* em 15.9 px; plot about 347 px; "16000" with its gap 4.5 em = 71 px: at most 4 steps */
    has_substr(t, "set xtics 5000\n", "450 px: x tics every 5000 rpm, labels that do not touch");
    double lo = range_lo(t, "y");
    ok(lo >= 0.0 && lo <= 0.05, "a positive quantity gets no negative axis (y from %g)", lo);
    is_close(range_lo(t, "x"), 2000, 1e-12, 0, "x starts at the data (2000 rpm)");
    is_close(range_hi(t, "x"), 16000, 1e-12, 0, "and ends there (16000 rpm)");
    free(t);
}

static void test_styles(void)
{
    double x[2] = { 0, 1 }, y[8][2];
    acbb_plot_series s[8];
    char labels[8][16];
    for (int k = 0; k < 8; k++) {
        y[k][0] = k, y[k][1] = k + 1;
        snprintf(labels[k], sizeof labels[k], "%d N", 50 * (k + 1));
        s[k] = (acbb_plot_series){ labels[k], x, y[k], 2, k + 1, 1 + k % 2, 1 };
    }
    acbb_plot_xy p = { NULL, "step (-)", "rise (K)", s, 8 };
    char *t = xy_script(&p, NULL, 1004, 753);
    int shapes[64] = { 0 }, n = 0;
    for (const char *c = t; c && (c = strstr(c, "pointtype ")); c += 10) {
        int pt = atoi(c + 10);
        if (pt > 0 && pt < 64 && !shapes[pt]++) n++;
    }
    ok(n == 8, "eight families, eight marker shapes: apart in grey (%d)", n);
    has_substr(t, "dashtype 2 linecolor 2 pointtype 4 ", "a dashed series has the open marker");
    has_substr(t, "dashtype 1 linecolor 1 pointtype 7 ", "a solid one the filled marker");
    free(t);
}

static void test_factored_key_and_text(void)
{
    double x[2] = { 0, 1 }, y[2] = { 0, 1 };
    acbb_plot_series s[2] = { { "P_t TE", x, y, 2, 1, 1, 1 }, { "P_t WTE", x, y, 2, 1, 2, 1 } };
    acbb_plot_series key[2] = { { .label = "P_t TE", .color = 0, .dash = 1, .points = 1 },
                                { .label = "WTE: without", .color = 0, .dash = 2, .points = 1 } };
    acbb_plot_look look = { key, 2 };
    acbb_plot_xy p = { "Differential-slip and tangential friction losses vs axial force at "
                       "15000 rpm, with and without thermal expansion",
                       "axial force F_x (N)", "power loss (W)", s, 2 };
    char *t = xy_script(&p, &look, 450, 300);
    int entries = 0, untitled = 0;
    for (const char *c = t; c && (c = strstr(c, "keyentry ")); c++) entries++;
    for (const char *c = t; c && (c = strstr(c, "notitle")); c++) untitled++;
    ok(entries == 2 && untitled == 2, "the key is its own entries (%d), the series have none (%d)",
       entries, untitled);
    has_substr(t, "'P_{t}\u00a0TE'", "a space after a subscript is a no-break space (SVG kept "
               "dropping it: \"P_tTE\")");
    has_substr(t, "F_{x}\u00a0(N)", "F_x is subscripted");
    has_substr(t, "'.\"\\n\".'", "a title too long for 450 px is broken into lines");
    free(t);
}

int main(void)
{
    snprintf(dir, sizeof dir, "/tmp/acbb-layout.XXXXXX");
    if (!mkdtemp(dir)) return 1;
    snprintf(script, sizeof script, "%s/script.gp", dir);
    char fake[128];
    snprintf(fake, sizeof fake, "%s/fakegp", dir);
    FILE *f = fopen(fake, "w");
    if (!f) return 1;
    fprintf(f, "#!/bin/sh\ncat >'%s'\nexit 1\n", script);
    fclose(f);
    chmod(fake, 0755);
    setenv("ACBB_GNUPLOT", fake, 1);
    test_sizes();
    test_key_free_corner();
    test_key_raised();
    test_ticks_and_zero();
    test_styles();
    test_factored_key_and_text();
    unlink(script);
    unlink(fake);
    rmdir(dir);
    return done_testing();
}
