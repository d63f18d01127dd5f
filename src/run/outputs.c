/* acbb — the table of a snapshot's scalar outputs (outputs.h).
 *
 * Rows in JSON order: the writers print a section's entries as they come.
 * The conversions are the ones the JSON has always used (MODEL.md 0: SI
 * inside, um / deg / N/um outside), written as SI * scale / div so that
 * every client computes the same double. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/limits.h"
#include "losses.h"
#include "acbb/outputs.h"
#include "acbb/units.h"

/* Inner-ring growth: thermal + centrifugal, as the seed compares
 * theta_i + theta_icen with theta_o (MODEL.md 12.4). */
static double exp_inner_ring(const acbb_snapshot *s)
{
    return s->exp_inner + s->exp_inner_cen;
}

#define OFF_S(m) ACBB_OUT_BEARING, offsetof(acbb_snapshot, m), NULL
#define OFF_B(m) ACBB_OUT_BALL, offsetof(acbb_ball_view, m), NULL
#define AS_IS 1.0, 1.0
#define TO_UM 1e6, 1.0
#define TO_MM 1e3, 1.0
#define TO_DEG 1.0, ACBB_DEG
#define TO_MRAD 1e3, 1.0

/* Set K (0 front, 1 rear) of a spindle: "spindle.sets[K].key". */
#define SPINDLE_SET(k, m) OFF_S(spindle.sets[k].m)
#define SPINDLE_SET_ROW(k, pos, key, unit, what, m, conv)                                \
    { "spindle.sets[" #k "]", key, "spindle.sets[" #k "]." key, unit, pos " set: " what, \
      SPINDLE_SET(k, m), conv }
#define SPINDLE_SET_ROWS(k, pos)                                                          \
    SPINDLE_SET_ROW(k, pos, "preload_N", "N", "preload now (no external thrust)",         \
                    preload_N, AS_IS),                                                    \
    SPINDLE_SET_ROW(k, pos, "axial_N", "N", "axial force from the shaft", axial_N, AS_IS), \
    SPINDLE_SET_ROW(k, pos, "radial_N", "N", "radial reaction", radial_N, AS_IS),         \
    SPINDLE_SET_ROW(k, pos, "moment_Nm", "N m", "moment reaction", moment_Nm, AS_IS),     \
    SPINDLE_SET_ROW(k, pos, "loss_W", "W", "losses, all its bearings", loss_W, AS_IS),    \
    SPINDLE_SET_ROW(k, pos, "T_inner_C", "C", "hottest inner ring", T_inner_C, AS_IS),    \
    SPINDLE_SET_ROW(k, pos, "T_outer_C", "C", "hottest outer ring", T_outer_C, AS_IS),    \
    SPINDLE_SET_ROW(k, pos, "T_ball_C", "C", "hottest ball", T_ball_C, AS_IS)

static const acbb_output_row k_rows[] = {
    { "losses_W", NULL, "P_%s_W", "W", NULL, OFF_S(losses.P), AS_IS },
    { "losses_W", "total", "P_total_W", "W", "total power loss", OFF_S(losses.total), AS_IS },

    { "temperature_C", "outer_ring", "T_outer_ring_C", "C", "outer ring (seed node 5)",
      OFF_S(T_outer_ring), AS_IS },
    { "temperature_C", "inner_ring", "T_inner_ring_C", "C", "inner ring", OFF_S(T_inner_ring),
      AS_IS },
    { "temperature_C", "ball", "T_ball_C", "C", "ball", OFF_S(T_ball), AS_IS },
    { "temperature_C", "housing", "T_housing_C", "C", "housing", OFF_S(T_housing), AS_IS },
    { "temperature_C", "shaft", "T_shaft_C", "C", "shaft", OFF_S(T_shaft), AS_IS },
    { "temperature_C", "cavity", "T_cavity_C", "C", "oil-air in the cavity", OFF_S(T_cavity),
      AS_IS },

    { "expansion_um", "ball", "exp_ball_um", "um", "ball radial growth", OFF_S(exp_ball), TO_UM },
    { "expansion_um", "inner_ring", "exp_inner_um", "um",
      "inner ring growth, thermal + centrifugal", ACBB_OUT_BEARING, 0, exp_inner_ring, TO_UM },
    { "expansion_um", "outer_ring", "exp_outer_um", "um", "outer ring growth",
      OFF_S(exp_outer), TO_UM },
    { "expansion_um", "inner_thermal", "exp_inner_thermal_um", "um", "inner ring, thermal part",
      OFF_S(exp_inner), TO_UM },
    { "expansion_um", "inner_centrifugal", "exp_inner_centrifugal_um", "um",
      "inner ring, centrifugal part", OFF_S(exp_inner_cen), TO_UM },

    { "ring", "delta_x_um", "delta_x_um", "um", "inner ring axial displacement",
      OFF_S(delta_x), TO_UM },
    { "ring", "delta_z_um", "delta_z_um", "um", "inner ring radial displacement",
      OFF_S(delta_z), TO_UM },
    { "ring", "tilt_y_mrad", "tilt_y_mrad", "mrad", "inner ring tilt", OFF_S(tilt_y), TO_MRAD },
    { "ring", "stiffness_axial_N_per_um", "stiffness_axial_N_um", "N/um", "axial stiffness",
      OFF_S(stiffness_axial), 1e-6, 1.0 },
    { "ring", "stiffness_radial_N_per_um", "stiffness_radial_N_um", "N/um", "radial stiffness, tilt held",
      OFF_S(stiffness_radial), 1e-6, 1.0 },
    { "ring", "stiffness_tilt_Nm_per_mrad", "stiffness_tilt_Nm_mrad", "N m/mrad",
      "tilt stiffness, radial free", OFF_S(stiffness_tilt), 1e-3, 1.0 },
    { "ring", "stiffness_tilt_held_Nm_per_mrad", "stiffness_tilt_held_Nm_mrad", "N m/mrad",
      "tilt stiffness, ring held radially", OFF_S(stiffness_tilt_held), 1e-3, 1.0 },

    /* MODEL.md 13: the squeeze decomposition. */
    { "squeeze_um", "inner_thermal", "squeeze_inner_thermal_um", "um",
      "squeeze from inner ring heat", OFF_S(squeeze.inner_thermal), TO_UM },
    { "squeeze_um", "inner_centrifugal", "squeeze_inner_centrifugal_um", "um",
      "squeeze from inner ring spin", OFF_S(squeeze.inner_centrifugal), TO_UM },
    { "squeeze_um", "outer", "squeeze_outer_um", "um", "relief from outer ring growth",
      OFF_S(squeeze.outer), TO_UM },
    { "squeeze_um", "ball", "squeeze_ball_um", "um", "squeeze from ball growth",
      OFF_S(squeeze.ball), TO_UM },
    { "squeeze_um", "net", "squeeze_net_um", "um", "net squeeze (sum)", OFF_S(squeeze.net),
      TO_UM },

    { NULL, "psi_deg", "psi_deg", "deg", "ball azimuth", OFF_B(psi), TO_DEG },
    { NULL, "Qi_N", "Qi_N", "N", "inner contact load", OFF_B(Qi), AS_IS },
    { NULL, "Qo_N", "Qo_N", "N", "outer contact load", OFF_B(Qo), AS_IS },
    { NULL, "alpha_i_deg", "alpha_i_deg", "deg", "inner contact angle", OFF_B(alpha_i), TO_DEG },
    { NULL, "alpha_o_deg", "alpha_o_deg", "deg", "outer contact angle", OFF_B(alpha_o), TO_DEG },
    { NULL, "slide_i_mps", "slide_i_mps", "m/s", "inner sliding speed", OFF_B(slide_i), AS_IS },
    { NULL, "slide_o_mps", "slide_o_mps", "m/s", "outer sliding speed", OFF_B(slide_o), AS_IS },
    { NULL, "spin_i_radps", "spin_i_radps", "rad/s", "inner spin speed", OFF_B(spin_i), AS_IS },
    { NULL, "spin_o_radps", "spin_o_radps", "rad/s", "outer spin speed", OFF_B(spin_o), AS_IS },
    { NULL, "film_i_um", "film_i_um", "um", "inner central film", OFF_B(film_i), TO_UM },
    { NULL, "film_o_um", "film_o_um", "um", "outer central film", OFF_B(film_o), TO_UM },
    { NULL, "pmax_i_GPa", "pmax_i_GPa", "GPa", "inner max Hertz pressure", OFF_B(pmax_i),
      1e-9, 1.0 },
    { NULL, "pmax_o_GPa", "pmax_o_GPa", "GPa", "outer max Hertz pressure", OFF_B(pmax_o),
      1e-9, 1.0 },
    { NULL, "a_i_mm", "a_i_mm", "mm", "inner contact semi-major axis", OFF_B(a_i), TO_MM },
    { NULL, "b_i_mm", "b_i_mm", "mm", "inner contact semi-minor axis", OFF_B(b_i), TO_MM },
    { NULL, "a_o_mm", "a_o_mm", "mm", "outer contact semi-major axis", OFF_B(a_o), TO_MM },
    { NULL, "b_o_mm", "b_o_mm", "mm", "outer contact semi-minor axis", OFF_B(b_o), TO_MM },
    { NULL, "hmin_i_um", "hmin_i_um", "um", "inner minimum film", OFF_B(hmin_i), TO_UM },
    { NULL, "hmin_o_um", "hmin_o_um", "um", "outer minimum film", OFF_B(hmin_o), TO_UM },
    { NULL, "omega_m_radps", "omega_m_radps", "rad/s", "orbital speed", OFF_B(omega_m), AS_IS },
    /* The ball's angular velocity in the orbiting frame (x' along the bearing axis, z'
     * outward, MODEL.md 0): what the preload map's skid ratio is made of (preload_map.h). */
    { NULL, "omega_x_radps", "omega_x_radps", "rad/s", "ball angular velocity x'", OFF_B(omega_x),
      AS_IS },
    { NULL, "omega_y_radps", "omega_y_radps", "rad/s", "ball angular velocity y'", OFF_B(omega_y),
      AS_IS },
    { NULL, "omega_z_radps", "omega_z_radps", "rad/s", "ball angular velocity z'", OFF_B(omega_z),
      AS_IS },
    { "losses_W", NULL, "ball_P_%s_W", "W", NULL, OFF_B(loss_kind), AS_IS },
    { "losses_W", "total", "ball_P_total_W", "W", "this ball's contact losses", OFF_B(loss),
      AS_IS },

    { "energy_W", "in", "heat_in_W", "W", "heat sources", OFF_S(heat_in), AS_IS },
    { "energy_W", "out", "heat_out_W", "W", "heat into the fixed-temperature nodes",
      OFF_S(heat_out), AS_IS },

    /* A bearing set (MODEL.md 14): 0 for a single bearing. */
    { "set", "preload_N", "set_preload_N", "N", "set preload now (no external thrust)",
      OFF_S(set.preload_N), AS_IS },
    { "set", "preload_assembly_N", "set_preload_assembly_N", "N", "set preload at assembly",
      OFF_S(set.preload_assembly_N), AS_IS },
    { "set", "liftoff_thrust_N", "set_liftoff_thrust_N", "N",
      "thrust at which the other side's preload is gone", OFF_S(set.liftoff_thrust_N), AS_IS },
    { "set", "liftoff_remainder_N", "set_liftoff_remainder_N", "N",
      "what the other side keeps at lift-off (centrifugal)", OFF_S(set.liftoff_remainder_N),
      AS_IS },
    { "set", "stiffness_axial_N_per_um", "set_stiffness_axial_N_um", "N/um",
      "set axial stiffness at the nose", OFF_S(set.stiffness_axial), 1e-6, 1.0 },
    { "set", "stiffness_radial_N_per_um", "set_stiffness_radial_N_um", "N/um",
      "set radial stiffness at the nose", OFF_S(set.stiffness_radial), 1e-6, 1.0 },
    { "set", "stiffness_tilt_Nm_per_mrad", "set_stiffness_tilt_Nm_mrad", "N m/mrad",
      "set tilt stiffness", OFF_S(set.stiffness_tilt), 1e-3, 1.0 },
    { "set", "spacer_growth_um", "set_spacer_growth_um", "um",
      "inner minus outer axial growth, end to end", OFF_S(set.spacer_growth), TO_UM },
    { "set", "shaft_dx_um", "set_shaft_dx_um", "um", "shaft axial displacement",
      OFF_S(set.shaft_dx), TO_UM },
    { "set", "shaft_dz_um", "set_shaft_dz_um", "um", "shaft radial displacement at the centre",
      OFF_S(set.shaft_dz), TO_UM },
    { "set", "shaft_tilt_mrad", "set_shaft_tilt_mrad", "mrad", "shaft tilt",
      OFF_S(set.shaft_tilt), TO_MRAD },
    /* MODEL.md 15: rating life and static safety (life.h); lives capped at 1e9 h. */
    { "life", "C_N", "life_C_N", "N", "basic dynamic radial rating C_r (ISO 281)",
      OFF_S(life.C), AS_IS },
    { "life", "C0_N", "life_C0_N", "N", "basic static radial rating C_0r (ISO 76)",
      OFF_S(life.C0), AS_IS },
    { "life", "Cu_N", "life_Cu_N", "N", "fatigue load limit C_u", OFF_S(life.Cu), AS_IS },
    { "life", "P_ref_N", "life_P_ref_N", "N", "dynamic equivalent reference load (ISO/TS 16281)",
      OFF_S(life.P_ref), AS_IS },
    { "life", "L10r_Mrev", "life_L10r_Mrev", "Mrev", "reference rating life, 10^6 rev",
      OFF_S(life.L10r_Mrev), AS_IS },
    { "life", "L10r_h", "life_L10r_h", "h", "reference rating life at the speed",
      OFF_S(life.L10r_h), AS_IS },
    { "life", "Lnmr_h", "life_Lnmr_h", "h", "modified rating life a1 a_ISO L10r",
      OFF_S(life.Lnmr_h), AS_IS },
    { "life", "a1", "life_a1", "1", "reliability factor a_1", OFF_S(life.a1), AS_IS },
    { "life", "a_iso", "life_a_iso", "1", "life modification factor a_ISO", OFF_S(life.a_iso),
      AS_IS },
    { "life", "kappa", "life_kappa", "1", "viscosity ratio nu / nu1", OFF_S(life.kappa), AS_IS },
    { "life", "nu_mm2_s", "life_nu_mm2_s", "mm^2/s", "oil viscosity at the rings' mean temperature",
      OFF_S(life.nu_mm2s), AS_IS },
    { "life", "nu1_mm2_s", "life_nu1_mm2_s", "mm^2/s", "rated viscosity nu1 (ISO 281)",
      OFF_S(life.nu1_mm2s), AS_IS },
    { "life", "s0_min", "life_s0_min", "1", "least static safety (4200 MPa / p_max)^3",
      OFF_S(life.s0_min), AS_IS },
    { "life", "P0_N", "life_P0_N", "N",
      "static equivalent radial load (ISO 76 3.4) of the worst contact",
      OFF_S(life.P0), AS_IS },
    { "life", "edge_margin_deg", "life_edge_margin_deg", "deg",
      "least angle from a contact ellipse's end to its shoulder (< 0: truncated)",
      OFF_S(life.edge_margin_deg), AS_IS },
    /* A spindle (spindle.h, docs/spindle.md): missing for any other scene
     * (acbb_output_missing). The path is the name: no old column name. */
    { "spindle", "nose_drift_um", "spindle.nose_drift_um", "um",
      "nose axial thermal drift (+: away from the front set)",
      OFF_S(spindle.nose_drift_axial), TO_UM },
    { "spindle", "nose_radial_drift_um", "spindle.nose_radial_drift_um", "um",
      "shaft radial thermal growth at the nose", OFF_S(spindle.nose_drift_radial), TO_UM },
    { "spindle", "nose_tilt_urad", "spindle.nose_tilt_urad", "urad", "nose tilt under the loads",
      OFF_S(spindle.nose_theta), 1e6, 1.0 },
    { "spindle", "nose_stiffness_N_per_um", "spindle.nose_stiffness_N_per_um", "N/um",
      "radial static stiffness at the nose", OFF_S(spindle.nose_k_radial), 1e-6, 1.0 },
    { "spindle", "nose_axial_stiffness_N_per_um", "spindle.nose_axial_stiffness_N_per_um",
      "N/um", "axial static stiffness at the nose", OFF_S(spindle.nose_k_axial), 1e-6, 1.0 },
    { "spindle", "nose_tilt_stiffness_Nm_per_mrad", "spindle.nose_tilt_stiffness_Nm_per_mrad",
      "N m/mrad", "tilt static stiffness at the nose", OFF_S(spindle.nose_k_tilt), 1e-3, 1.0 },
    { "spindle", "rear_shift_um", "spindle.rear_shift_um", "um",
      "shaft minus housing axial growth between the sets", OFF_S(spindle.rear_shift), TO_UM },
    { "spindle.nose_displacement_um", "axial", "spindle.nose_displacement_um.axial", "um",
      "nose axial displacement under the loads", OFF_S(spindle.nose_u), TO_UM },
    { "spindle.nose_displacement_um", "radial", "spindle.nose_displacement_um.radial", "um",
      "nose radial displacement under the loads", OFF_S(spindle.nose_w), TO_UM },
    { "spindle.heat_W", "motor", "spindle.heat_W.motor", "W", "motor heat, rotor + stator",
      OFF_S(spindle.Q_motor_W), AS_IS },
    { "spindle.heat_W", "bearings", "spindle.heat_W.bearings", "W", "both sets' losses",
      OFF_S(spindle.Q_bearings_W), AS_IS },
    { "spindle.heat_W", "coolant", "spindle.heat_W.coolant", "W", "heat the coolant carries away",
      OFF_S(spindle.Q_coolant_W), AS_IS },
    { "spindle.heat_W", "air", "spindle.heat_W.air", "W", "heat to the air (housing, shaft ends)",
      OFF_S(spindle.Q_air_W), AS_IS },
    { "spindle.coolant_C", "inlet", "spindle.coolant_C.inlet", "C", "coolant inlet",
      OFF_S(spindle.T_coolant_in_C), AS_IS },
    { "spindle.coolant_C", "outlet", "spindle.coolant_C.outlet", "C", "coolant outlet",
      OFF_S(spindle.T_coolant_out_C), AS_IS },
    SPINDLE_SET_ROWS(0, "front"),
    SPINDLE_SET_ROWS(1, "rear"),
};
#define N_ROWS (sizeof k_rows / sizeof k_rows[0])

/* The loss kinds a per-loss row lists: all for the bearing, the per-point
 * and per-contact ones for a ball (bearing-level losses have no ball share). */
static int row_has_loss(const acbb_output_row *r, int l)
{
    const acbb_loss_desc *d = &acbb_loss_table[l];
    return r->scope == ACBB_OUT_BEARING || d->point || d->contact;
}

static void fill(acbb_output *o, const acbb_output_row *r, int loss)
{
    o->row = r;
    o->loss = loss;
    o->key = loss >= 0 ? acbb_loss_table[loss].name : r->key;
    o->label = loss >= 0 ? acbb_loss_table[loss].label : r->label;
    o->unit = r->unit;
}

int acbb_output_get(size_t i, acbb_output *o)
{
    for (size_t r = 0; r < N_ROWS; r++) {
        if (k_rows[r].key) {
            if (i-- == 0) return fill(o, &k_rows[r], -1), 1;
            continue;
        }
        for (int l = 0; l < ACBB_LOSS_KINDS; l++)
            if (row_has_loss(&k_rows[r], l) && i-- == 0) return fill(o, &k_rows[r], l), 1;
    }
    return 0;
}

size_t acbb_output_count(void)
{
    acbb_output o;
    size_t n = 0;
    while (acbb_output_get(n, &o)) n++;
    return n;
}

int acbb_output_path(const acbb_output *o, const char *ball, char *buf, size_t n)
{
    const acbb_output_row *r = o->row;
    char ball_part[32] = "";
    if (r->scope == ACBB_OUT_BALL) snprintf(ball_part, sizeof ball_part, "balls[%s].", ball);
    return snprintf(buf, n, "%s%s%s%s", ball_part, r->section ? r->section : "",
                    r->section ? "." : "", o->key);
}

int acbb_output_flat(const acbb_output *o, char *buf, size_t n)
{
    return acbb_output_path(o, "0", buf, n);
}

int acbb_output_old_name(const acbb_output *o, char *buf, size_t n)
{
    const char *f = o->row->flat, *at = strstr(f, "%s");
    if (!at) return snprintf(buf, n, "%s", f);
    return snprintf(buf, n, "%.*s%s%s", (int)(at - f), f, o->key, at + 2);
}

static double read_double(const void *base, size_t off)
{
    double v;
    memcpy(&v, (const char *)base + off, sizeof v);
    return v;
}

double acbb_output_value(const acbb_output *o, const acbb_snapshot *s, int k)
{
    const acbb_output_row *r = o->row;
    size_t off = r->off + (o->loss >= 0 ? (size_t)o->loss * sizeof(double) : 0);
    double si;
    if (r->scope == ACBB_OUT_BALL) {
        if (k < 0 || k >= s->n_balls || k >= ACBB_MAX_BALLS) return NAN;
        si = read_double(&s->balls[k], off);
    } else {
        si = r->get ? r->get(s) : read_double(s, off);
    }
    return si * r->scale / r->div;
}

/* The stiffness rows and the probe each needs (issue 30). */
static const struct { size_t off; unsigned bit; } probe_rows[] = {
    { offsetof(acbb_snapshot, stiffness_axial), ACBB_STIFF_AXIAL },
    { offsetof(acbb_snapshot, stiffness_radial), ACBB_STIFF_RADIAL },
    { offsetof(acbb_snapshot, stiffness_tilt), ACBB_STIFF_TILT },
    { offsetof(acbb_snapshot, stiffness_tilt_held), ACBB_STIFF_TILT_HELD },
};

/* A spindle row ("spindle..." section) of a snapshot without a spindle. */
static int spindle_missing(const acbb_output_row *r, const acbb_snapshot *s)
{
    return r->section && strncmp(r->section, "spindle", 7) == 0 && s->spindle.n_sets == 0;
}

const char *acbb_output_missing(const acbb_output *o, const acbb_snapshot *s)
{
    const acbb_output_row *r = o->row;
    if (spindle_missing(r, s)) return "the scene is not a spindle ([shaft] segments = 0)";
    if (r->scope != ACBB_OUT_BEARING || r->get) return NULL;
    for (size_t i = 0; i < sizeof probe_rows / sizeof probe_rows[0]; i++)
        if (r->off == probe_rows[i].off && (s->stiffness_failed & probe_rows[i].bit))
            return "the stiffness probe's equilibrium solve did not converge";
    return NULL;
}

/* Does "section.key" (or "key" without a section) name row r (with loss
 * kind l for a per-loss row)? */
static int names(const acbb_output_row *r, int l, const char *name)
{
    if (r->section) {
        size_t n = strlen(r->section);
        if (strncmp(name, r->section, n) != 0 || name[n] != '.') return 0;
        name += n + 1;
    }
    return strcmp(name, l >= 0 ? acbb_loss_table[l].name : r->key) == 0;
}

/* The entry `name` names among the rows of `scope` (a row scan: the CSV
 * writer looks its columns up at every step). */
static int find_row(acbb_output_scope scope, const char *name, acbb_output *o)
{
    for (size_t i = 0; i < N_ROWS; i++) {
        const acbb_output_row *r = &k_rows[i];
        if (r->scope != scope) continue;
        if (r->key && names(r, -1, name)) return fill(o, r, -1), 1;
        for (int l = 0; !r->key && l < ACBB_LOSS_KINDS; l++)
            if (row_has_loss(r, l) && names(r, l, name)) return fill(o, r, l), 1;
    }
    return 0;
}

/* The entry whose old column name is `name` (a ball entry: ball 0, as the
 * old sweep columns were). */
static int find_old_name(const char *name, acbb_output *o, long *ball)
{
    for (size_t i = 0; acbb_output_get(i, o); i++) {
        char old[64];
        acbb_output_old_name(o, old, sizeof old);
        if (strcmp(old, name) != 0) continue;
        *ball = o->row->scope == ACBB_OUT_BALL ? 0 : -1;
        return 1;
    }
    return 0;
}

static acbb_status unknown(const char *path, acbb_error *err)
{
    return acbb_error_set(err, ACBB_EINVAL,
                          "metric '%s' is unknown (e.g. losses_W.total, "
                          "temperature_C.outer_ring, balls[0].Qi_N)", path);
}

acbb_status acbb_output_find(const char *path, acbb_output *o, long *ball, acbb_error *err)
{
    acbb_output_scope scope = ACBB_OUT_BEARING;
    const char *name = path;
    *ball = -1;
    if (strncmp(path, "balls[", 6) == 0) {
        char *end;
        *ball = strtol(path + 6, &end, 10);
        if (end == path + 6 || end[0] != ']' || end[1] != '.') return unknown(path, err);
        if (*ball < 0 || *ball >= ACBB_MAX_BALLS)
            return acbb_error_set(err, ACBB_EINVAL, "metric '%s': ball index must be 0..%d",
                                  path, ACBB_MAX_BALLS - 1);
        scope = ACBB_OUT_BALL;
        name = end + 2;
    }
    if (find_row(scope, name, o)) return ACBB_OK;
    return scope == ACBB_OUT_BEARING && find_old_name(path, o, ball) ? ACBB_OK
                                                                    : unknown(path, err);
}
