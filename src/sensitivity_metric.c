/* acbb — metrics: a scalar of a snapshot named by its JSON path
 * (sensitivity.h). The names and units follow `acbb run --json` (cli
 * output): lengths in um, angles in deg, stiffness in N/um. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/losses.h"
#include "acbb/sensitivity.h"
#include "acbb/units.h"

#define UM 1e6

typedef struct {
    const char *name;
    size_t off;
    double scale;
} metric_row;

#define S(name, member, scale) {name, offsetof(acbb_snapshot, member), scale}
static const metric_row k_snap[] = {
    S("losses_W.total", losses.total, 1.0),
    S("temperature_C.outer_ring", T_outer_ring, 1.0),
    S("temperature_C.inner_ring", T_inner_ring, 1.0),
    S("temperature_C.ball", T_ball, 1.0),
    S("temperature_C.housing", T_housing, 1.0),
    S("temperature_C.shaft", T_shaft, 1.0),
    S("temperature_C.cavity", T_cavity, 1.0),
    S("expansion_um.ball", exp_ball, UM),
    S("expansion_um.outer_ring", exp_outer, UM),
    S("expansion_um.inner_thermal", exp_inner, UM),
    S("expansion_um.inner_centrifugal", exp_inner_cen, UM),
    S("ring.delta_x_um", delta_x, UM),
    S("ring.delta_z_um", delta_z, UM),
    S("ring.tilt_y_mrad", tilt_y, 1e3),
    S("ring.stiffness_axial_N_per_um", stiffness_axial, 1e-6),
    S("ring.stiffness_radial_N_per_um", stiffness_radial, 1e-6),
    S("ring.stiffness_tilt_Nm_per_mrad", stiffness_tilt, 1e-3),
    S("squeeze_um.inner_thermal", squeeze.inner_thermal, UM),
    S("squeeze_um.inner_centrifugal", squeeze.inner_centrifugal, UM),
    S("squeeze_um.outer", squeeze.outer, UM),
    S("squeeze_um.ball", squeeze.ball, UM),
    S("squeeze_um.net", squeeze.net, UM),
    S("energy_W.in", heat_in, 1.0),
    S("energy_W.out", heat_out, 1.0),
};
#undef S

#define B(name, member, scale) {name, offsetof(acbb_ball_view, member), scale}
static const metric_row k_ball[] = {
    B("Qi_N", Qi, 1.0),
    B("Qo_N", Qo, 1.0),
    B("alpha_i_deg", alpha_i, 1.0 / ACBB_DEG),
    B("alpha_o_deg", alpha_o, 1.0 / ACBB_DEG),
    B("slide_i_mps", slide_i, 1.0),
    B("slide_o_mps", slide_o, 1.0),
    B("spin_i_radps", spin_i, 1.0),
    B("spin_o_radps", spin_o, 1.0),
    B("film_i_um", film_i, UM),
    B("film_o_um", film_o, UM),
    B("hmin_i_um", hmin_i, UM),
    B("hmin_o_um", hmin_o, UM),
    B("omega_m_radps", omega_m, 1.0),
    B("losses_W.total", loss, 1.0),
};
#undef B

#define N_SNAP (sizeof k_snap / sizeof k_snap[0])
#define N_BALL (sizeof k_ball / sizeof k_ball[0])

static double read_at(const void *base, size_t off, double scale)
{
    double v;
    memcpy(&v, (const char *)base + off, sizeof v);
    return v * scale;
}

int acbb_metric_name(size_t i, char *buf, size_t n)
{
    if (i < N_SNAP) return snprintf(buf, n, "%s", k_snap[i].name), 1;
    i -= N_SNAP;
    if (i < ACBB_LOSS_KINDS) return snprintf(buf, n, "losses_W.%s", acbb_loss_table[i].name), 1;
    i -= ACBB_LOSS_KINDS;
    if (i < N_BALL) return snprintf(buf, n, "balls[i].%s", k_ball[i].name), 1;
    return 0;
}

/* Parse "balls[K].X": K into *k, the field row into *row. 0 when not a ball path. */
static int ball_path(const char *path, long *k, const metric_row **row)
{
    if (strncmp(path, "balls[", 6) != 0) return 0;
    char *end;
    *k = strtol(path + 6, &end, 10);
    if (end == path + 6 || end[0] != ']' || end[1] != '.') return -1;
    *row = NULL;
    for (size_t i = 0; i < N_BALL; i++)
        if (strcmp(end + 2, k_ball[i].name) == 0) *row = &k_ball[i];
    return *row ? 1 : -1;
}

static acbb_status unknown(const char *path, acbb_error *err)
{
    return acbb_error_set(err, ACBB_EINVAL,
                          "metric '%s' is unknown (e.g. losses_W.total, "
                          "temperature_C.outer_ring, balls[0].Qi_N; `acbb sensitivity "
                          "--help` lists them)", path);
}

static int loss_index(const char *path)
{
    if (strncmp(path, "losses_W.", 9) != 0) return -1;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        if (strcmp(path + 9, acbb_loss_table[l].name) == 0) return l;
    return -1;
}

acbb_status acbb_metric_check(const char *path, acbb_error *err)
{
    long k;
    const metric_row *row;
    int b = ball_path(path, &k, &row);
    if (b == 1) return k >= 0 && k < ACBB_MAX_BALLS ? ACBB_OK
        : acbb_error_set(err, ACBB_EINVAL, "metric '%s': ball index must be 0..%d", path,
                         ACBB_MAX_BALLS - 1);
    if (b < 0) return unknown(path, err);
    if (loss_index(path) >= 0) return ACBB_OK;
    for (size_t i = 0; i < N_SNAP; i++)
        if (strcmp(path, k_snap[i].name) == 0) return ACBB_OK;
    return unknown(path, err);
}

acbb_status acbb_metric_value(const acbb_snapshot *snap, const char *path, double *out,
                              acbb_error *err)
{
    long k;
    const metric_row *row;
    int b = ball_path(path, &k, &row);
    if (b == 1) {
        if (k < 0 || k >= snap->n_balls)
            return acbb_error_set(err, ACBB_EINVAL, "metric '%s': ball index must be 0..%d",
                                  path, snap->n_balls - 1);
        *out = read_at(&snap->balls[k], row->off, row->scale);
        return ACBB_OK;
    }
    int l = loss_index(path);
    if (b == 0 && l >= 0) {
        *out = snap->losses.P[l];
        return ACBB_OK;
    }
    for (size_t i = 0; b == 0 && i < N_SNAP; i++)
        if (strcmp(path, k_snap[i].name) == 0) {
            *out = read_at(snap, k_snap[i].off, k_snap[i].scale);
            return ACBB_OK;
        }
    return unknown(path, err);
}
