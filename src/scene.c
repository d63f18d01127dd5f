/* acbb — Scene: the schema table, defaults, INI load and save, validation.
 *
 * ONE table (k_fields) describes every preset key: section, key (unit in the
 * name), type, unit, where the value lives in acbb_scene, the factor to SI,
 * the default and the allowed range in preset units, enum choices and a help
 * line. Defaults, parsing, range checks, saving, acbb_scene_set and the TUI
 * editor (through acbb_scene_field) all read that table, so a key cannot be
 * parsed one way and saved another.
 *
 * Unit conversion: value_SI = value_preset * scale. No key needs an offset:
 * temperatures stay in degrees Celsius inside a Scene (see scene.h).
 *
 * Locale: numbers are read with strtod and written with snprintf, and both
 * follow LC_NUMERIC. A program using this module must leave LC_NUMERIC at
 * "C" (set only LC_CTYPE from the environment), or presets would be read and
 * written with decimal commas.
 *
 * Files are parsed with inih (Debian libinih, 200-byte line buffer). A small
 * reader wrapped around fgets counts lines (inih's handler does not get the
 * line number in this build), refuses over-long lines instead of letting
 * inih split them, and strips leading blanks so that an indented line is
 * never taken as a multi-line continuation of the previous value. */
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ini.h>

#include "acbb/scene.h"
#include "acbb/sim.h"

#define PI 3.14159265358979323846
#define RPM_TO_RAD_S (2.0 * PI / 60.0)
#define DEG_TO_RAD (PI / 180.0)

/* Enum fields are read and written through an int (memcpy, no aliasing). */
_Static_assert(sizeof(acbb_model_level) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_geom_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_race_control) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_hertz_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_visc_model) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_traction_model) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_loss_form) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_hyst_axis) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_network_kind) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_preload_mode) == sizeof(int), "enum size");
_Static_assert(sizeof(acbb_thermal_mode) == sizeof(int), "enum size");

/* Enum choices, in the order of the C enum values in scene.h. */
static const char *const k_model[] = {"static", "quasi-static", "quasi-dynamic", "dynamic", NULL};
static const char *const k_hertz[] = {"exact", "bh77", "hb83", NULL};
static const char *const k_clean_seed[] = {"clean", "seed", NULL};
static const char *const k_race[] = {"outer", "inner", "equal", "auto", NULL};
static const char *const k_hyst[] = {"major", "minor", NULL};
static const char *const k_visc[] = {"roelands", "barus", "const", NULL};
static const char *const k_traction[] = {"eyring-cap", "bair-winer", NULL};
static const char *const k_preload[] = {"force", "displacement", NULL};
static const char *const k_network[] = {"46", "7", NULL};
static const char *const k_thermal_mode[] = {"transient", "steady", NULL};

/* Range ends: closed (inclusive) or open (exclusive, "must be > 0"). */
enum { CC, OC, CO, OO };

typedef struct {
    acbb_field_info info;   /* public part, handed out by acbb_scene_field */
    size_t off;             /* offsetof the member in acbb_scene */
    double scale;           /* value_SI = value_preset * scale */
    double def;             /* default in preset units (enum: index, bool: 0/1) */
    int ends;               /* CC, OC, CO or OO */
} field;

#define REAL(sec, key, unit, member, scale, def, ends, lo, hi, help) \
    {{sec, key, ACBB_FIELD_REAL, unit, lo, hi, NULL, help}, \
     offsetof(acbb_scene, member), scale, def, ends}
#define INT(sec, key, member, def, lo, hi, help) \
    {{sec, key, ACBB_FIELD_INT, "", lo, hi, NULL, help}, \
     offsetof(acbb_scene, member), 1.0, def, CC}
#define BOOL(sec, key, member, def, help) \
    {{sec, key, ACBB_FIELD_BOOL, "", 0, 1, NULL, help}, \
     offsetof(acbb_scene, member), 1.0, def, CC}
#define ENUM(sec, key, member, choices, def, help) \
    {{sec, key, ACBB_FIELD_ENUM, "", 0, \
      (double)(sizeof(choices) / sizeof(choices[0]) - 2), choices, help}, \
     offsetof(acbb_scene, member), 1.0, def, CC}

/* Six keys per part of [materials]. */
#define MATERIAL(part, vE, vnu, vrho, vcp, vk, vchi) \
    REAL("materials", #part "_E_GPa", "GPa", part.E, 1e9, vE, OC, 0, 1000, \
         "Young's modulus of the " #part), \
    REAL("materials", #part "_poisson", "", part.nu, 1.0, vnu, OO, 0, 0.5, \
         "Poisson ratio of the " #part), \
    REAL("materials", #part "_density_kg_m3", "kg/m^3", part.rho, 1.0, vrho, OC, 0, 30000, \
         "density of the " #part), \
    REAL("materials", #part "_cp_J_kgK", "J/(kg K)", part.cp, 1.0, vcp, OC, 0, 10000, \
         "specific heat of the " #part), \
    REAL("materials", #part "_k_W_mK", "W/(m K)", part.k, 1.0, vk, OC, 0, 1000, \
         "thermal conductivity of the " #part), \
    REAL("materials", #part "_expansion_ppm_K", "ppm/K", part.chi, 1e-6, vchi, CC, 0, 100, \
         "linear thermal expansion coefficient of the " #part)

/* The schema. Defaults: MODEL.md section 10 (the 7008C case of the seed). */
static const field k_fields[] = {
    REAL("bearing", "pitch_diameter_mm", "mm", pitch_diameter, 1e-3, 54, OC, 0, 2000,
         "pitch diameter d_m (MODEL.md section 1)"),
    REAL("bearing", "ball_diameter_mm", "mm", ball_diameter, 1e-3, 6.35, OC, 0, 100,
         "ball diameter D"),
    INT("bearing", "n_balls", n_balls, 21, 3, 64, "number of balls Z (the engine holds up to 64)"),
    REAL("bearing", "inner_groove_radius_mm", "mm", inner_groove_radius, 1e-3, 3.43, OC, 0, 100,
         "inner groove radius lambda_i (needs lambda_i / D >= 0.505)"),
    REAL("bearing", "outer_groove_radius_mm", "mm", outer_groove_radius, 1e-3, 3.43, OC, 0, 100,
         "outer groove radius lambda_o (needs lambda_o / D >= 0.505)"),
    REAL("bearing", "contact_angle_deg", "deg", contact_angle0, DEG_TO_RAD, 15, OC, 0, 45,
         "free contact angle alpha0; sets the clearance P_d (MODEL.md section 1)"),
    REAL("bearing", "bore_mm", "mm", bore, 1e-3, 40, OC, 0, 2000,
         "bearing bore (inside diameter of the inner ring)"),
    REAL("bearing", "outer_diameter_mm", "mm", outer_diameter, 1e-3, 68, OC, 0, 2000,
         "bearing outside diameter"),
    REAL("bearing", "width_mm", "mm", width, 1e-3, 15, OC, 0, 500, "ring width B_w"),
    REAL("bearing", "cage_width_mm", "mm", cage_width, 1e-3, 10.1, OC, 0, 500, "cage width W_c"),
    REAL("bearing", "cage_diameter_mm", "mm", cage_diameter, 1e-3, 57.7, OC, 0, 2000,
         "cage outside (guiding) diameter d_c"),
    REAL("bearing", "inner_land_diameter_mm", "mm", inner_land_diameter, 1e-3, 49.9, OC, 0, 2000,
         "inner ring land diameter d_1"),
    REAL("bearing", "outer_land_diameter_mm", "mm", outer_land_diameter, 1e-3, 58.1, OC, 0, 2000,
         "outer ring land diameter d_2"),
    REAL("bearing", "roughness_race_um", "um", roughness_race, 1e-6, 0.34, CC, 0, 10,
         "RMS roughness of the raceways"),
    REAL("bearing", "roughness_ball_um", "um", roughness_ball, 1e-6, 0.10, CC, 0, 10,
         "RMS roughness of the balls"),

    MATERIAL(ball, 207, 0.3, 7810, 450, 40.1, 12.5),
    MATERIAL(ring, 207, 0.3, 7810, 450, 40.1, 12.5),
    MATERIAL(shaft, 212, 0.298, 7860, 485, 42.4, 11.5),
    MATERIAL(housing, 143, 0.27, 7300, 510, 45.0, 10.5),
    MATERIAL(cage, 206, 0.254, 7830, 460, 44.0, 11.7),

    REAL("lubricant", "oil_density_kg_m3", "kg/m^3", oil_density, 1.0, 876, OC, 0, 2000,
         "oil density at 20 C"),
    REAL("lubricant", "oil_nu40_mm2_s", "mm^2/s", oil_nu40, 1e-6, 30, CC, 1, 10000,
         "oil kinematic viscosity at 40 C (Walther law, MODEL.md section 5)"),
    REAL("lubricant", "oil_nu100_mm2_s", "mm^2/s", oil_nu100, 1e-6, 5.3, CC, 1, 10000,
         "oil kinematic viscosity at 100 C (Walther law)"),
    REAL("lubricant", "oil_eta_const_Pa_s", "Pa s", oil_eta_const, 1.0, 0.2, OC, 0, 100,
         "oil viscosity used when viscosity_model = const"),
    REAL("lubricant", "oil_alpha_pv_per_GPa", "1/GPa", oil_alpha_pv, 1e-9, 20, CC, 0, 100,
         "pressure-viscosity coefficient alpha_pv"),
    REAL("lubricant", "oil_k_W_mK", "W/(m K)", oil_k, 1.0, 0.13, OC, 0, 10,
         "oil thermal conductivity"),
    REAL("lubricant", "oil_cp_J_kgK", "J/(kg K)", oil_cp, 1.0, 1950, OC, 0, 10000,
         "oil specific heat"),
    REAL("lubricant", "air_eta_Pa_s", "Pa s", air_eta, 1.0, 2e-5, OC, 0, 1e-3, "air viscosity"),
    REAL("lubricant", "air_density_kg_m3", "kg/m^3", air_density, 1.0, 1.128, OC, 0, 100,
         "air density"),
    REAL("lubricant", "air_k_W_mK", "W/(m K)", air_k, 1.0, 0.027, OC, 0, 10,
         "air thermal conductivity"),
    REAL("lubricant", "air_cp_J_kgK", "J/(kg K)", air_cp, 1.0, 1007, OC, 0, 10000,
         "air specific heat"),
    REAL("lubricant", "air_prandtl", "", air_pr, 1.0, 0.71, OC, 0, 10, "air Prandtl number"),
    REAL("lubricant", "mixture_k_W_mK", "W/(m K)", mix_k, 1.0, 0.04, OC, 0, 10,
         "oil-air mixture conductivity k_d"),
    REAL("lubricant", "air_flow_L_min", "L/min", q_air, 1e-3 / 60.0, 60, CC, 0, 10000,
         "oil-air lubrication: air flow"),
    REAL("lubricant", "oil_flow_ml_h", "ml/h", q_oil, 1e-6 / 3600.0, 0.4, CC, 0, 100000,
         "oil-air lubrication: oil flow"),
    REAL("lubricant", "boundary_friction", "", mu_bd, 1.0, 0.10, CC, 0, 1,
         "boundary (asperity) friction coefficient mu_bd"),
    REAL("lubricant", "limiting_shear_ratio", "", lambda_lim, 1.0, 0.07, OC, 0, 1,
         "limiting shear stress / pressure Lambda_L"),
    REAL("lubricant", "eyring_stress_MPa", "MPa", tau_eyring, 1e6, 5, OC, 0, 1000,
         "Eyring stress tau_E"),
    REAL("lubricant", "hysteresis_loss", "", hysteresis, 1.0, 0.007, CC, 0, 1,
         "elastic hysteresis loss coefficient epsilon"),
    REAL("lubricant", "drag_coefficient", "", drag_cd, 1.0, 0.45, CC, 0, 10,
         "drag coefficient C_D of a ball in the oil-air mixture"),
    ENUM("lubricant", "viscosity_model", visc, k_visc, ACBB_VISC_ROELANDS,
         "pressure-viscosity law (const: oil_eta_const_Pa_s everywhere)"),
    ENUM("lubricant", "traction_model", traction, k_traction, ACBB_TRACTION_EYRING_CAP,
         "film traction law (MODEL.md section 5)"),

    REAL("mounting", "shaft_bore_mm", "mm", shaft_bore, 1e-3, 25, CC, 0, 2000,
         "hollow-shaft bore d_s (0 = solid shaft)"),
    REAL("mounting", "h_fit_outer_W_m2K", "W/(m^2 K)", h_fit_outer, 1.0, 5000, OC, 0, 1e7,
         "outer ring / housing contact conductance"),
    REAL("mounting", "h_fit_inner_W_m2K", "W/(m^2 K)", h_fit_inner, 1.0, 20000, OC, 0, 1e7,
         "inner ring / shaft contact conductance"),
    REAL("mounting", "h_face_W_m2K", "W/(m^2 K)", h_face, 1.0, 3000, OC, 0, 1e7,
         "clamped ring face conductance"),
    REAL("mounting", "h_natural_W_m2K", "W/(m^2 K)", h_natural, 1.0, 10, OC, 0, 10000,
         "natural convection on the housing exterior"),
    ENUM("mounting", "preload", preload, k_preload, ACBB_PRELOAD_FORCE,
         "force: axial load applied (dx free); displacement: dx fixed by preload_N"),
    REAL("mounting", "preload_N", "N", preload_force, 1.0, 300, CC, 0, 1e6,
         "preload force (sets dx at 20 C, 0 rpm when preload = displacement)"),

    REAL("operating", "inner_speed_rpm", "rpm", inner_speed, RPM_TO_RAD_S, 15000, CC, 0, 100000,
         "inner ring speed"),
    REAL("operating", "axial_load_N", "N", axial_load, 1.0, 1000, CC, 0, 1e6,
         "axial load F_x on the inner ring"),
    REAL("operating", "radial_load_N", "N", radial_load, 1.0, 0, CC, 0, 1e6,
         "radial load F_z"),
    REAL("operating", "moment_load_Nm", "N m", moment_load, 1.0, 0, CC, -1e5, 1e5,
         "tilting moment M_y"),
    REAL("operating", "ambient_C", "C", ambient_C, 1.0, 26, CC, -50, 300,
         "ambient = assembly reference temperature"),

    BOOL("effects", "thermal_expansion", thermal_expansion, 1,
         "thermal expansion of the parts (TE; off = WTE)"),
    BOOL("effects", "centrifugal", centrifugal, 1, "ball centrifugal force"),
    BOOL("effects", "gyroscopic", gyroscopic, 1, "gyroscopic moment on the balls"),
    BOOL("effects", "ring_centrifugal", ring_centrifugal, 1,
         "centrifugal growth of the inner ring"),
    BOOL("effects", "ehl_film", ehl_film, 1, "EHL film (off: boundary friction only)"),
    BOOL("effects", "loss_shear", loss_shear, 1, "lubricant shear loss P_L"),
    BOOL("effects", "loss_slip", loss_slip, 1, "sliding loss P_t"),
    BOOL("effects", "loss_spin", loss_spin, 1, "spin loss P_s"),
    BOOL("effects", "loss_rolling", loss_rolling, 1, "rolling (hysteresis) loss P_r"),
    BOOL("effects", "loss_drag", loss_drag, 1, "drag loss P_v"),
    BOOL("effects", "loss_cage", loss_cage, 0,
         "cage-land shear loss P_c (Petroff, outer-land guided cage)"),

    ENUM("fidelity", "model", model, k_model, ACBB_MODEL_QUASI_DYNAMIC,
         "ball mechanics: static Hertz ... dynamic"),
    INT("fidelity", "contact_grid", contact_grid, 6, 2, 64,
        "Gauss points per axis of the contact ellipse"),
    ENUM("fidelity", "hertz", hertz, k_hertz, ACBB_HERTZ_BH77,
         "ellipticity: exact integrals or curve fits (MODEL.md section 2)"),
    ENUM("fidelity", "geometry", geometry, k_clean_seed, ACBB_GEOM_CLEAN,
         "clean geometry or the seed's literal eqs 12-13"),
    ENUM("fidelity", "race_control", race_control, k_race, ACBB_RACE_OUTER,
         "race control hypothesis (MODEL.md section 4)"),
    ENUM("fidelity", "loss_form", loss_form, k_clean_seed, ACBB_LOSS_CLEAN,
         "loss equations: clean or the seed's literal form (MODEL.md section 6)"),
    ENUM("fidelity", "hysteresis_axis", hyst_axis, k_hyst, ACBB_HYST_MAJOR,
         "ellipse axis used in the rolling loss P_r"),
    REAL("fidelity", "mech_tol", "", mech_tol, 1.0, 1e-8, CC, 1e-14, 1e-3,
         "relative force residual of the mechanics solve"),
    REAL("fidelity", "steady_tol_K_s", "K/s", steady_tol, 1.0, 1e-4, OC, 0, 1,
         "steady state when every |dT/dt| is below this"),
    ENUM("fidelity", "network", network, k_network, ACBB_NET_46,
         "thermal network: 46 nodes or the 7-node teaching one"),
    ENUM("fidelity", "thermal_mode", thermal_mode, k_thermal_mode, ACBB_THERMAL_TRANSIENT,
         "transient (time steps) or steady (direct) thermal solve"),
    REAL("fidelity", "time_step_s", "s", time_step, 1.0, 5, OC, 0, 3600,
         "initial thermal time step (adaptive)"),

    REAL("thermal", "max_time_s", "s", max_time, 1.0, 36000, OC, 0, 1e8,
         "simulated time limit"),
    INT("thermal", "max_steps", max_steps, 20000, 1, 10000000, "coupled step limit"),
    REAL("thermal", "temp_limit_C", "C", temp_limit_C, 1.0, 150, CC, -50, 300,
         "runaway when any node is hotter than this"),
    REAL("thermal", "contact_multiplier", "", contact_multiplier, 1.0, 1, OC, 0, 1000,
         "multiplier c_mv on the race-side spot resistances"),
    REAL("thermal", "heat_partition", "", heat_partition, 1.0, 0.5, CC, 0, 1,
         "share phi_p of contact heat to the rings (7-node network)"),
};

#define N_FIELDS (sizeof k_fields / sizeof k_fields[0])

/* ---- raw access through the table (memcpy: no type punning) ---- */

static double get_real(const acbb_scene *s, const field *f)
{
    double v;
    memcpy(&v, (const char *)s + f->off, sizeof v);
    return v;
}

static int get_int(const acbb_scene *s, const field *f)
{
    int v;
    memcpy(&v, (const char *)s + f->off, sizeof v);
    return v;
}

static bool get_bool(const acbb_scene *s, const field *f)
{
    bool v;
    memcpy(&v, (const char *)s + f->off, sizeof v);
    return v;
}

/* Store a value given in preset units (enum: index, bool: 0/1). */
static void put(acbb_scene *s, const field *f, double v)
{
    char *p = (char *)s + f->off;
    if (f->info.type == ACBB_FIELD_REAL) {
        double si = v * f->scale;
        memcpy(p, &si, sizeof si);
    } else if (f->info.type == ACBB_FIELD_BOOL) {
        bool b = v != 0.0;
        memcpy(p, &b, sizeof b);
    } else {
        int i = (int)v;
        memcpy(p, &i, sizeof i);
    }
}

static size_t n_choices(const field *f)
{
    size_t n = 0;
    while (f->info.choices[n]) n++;
    return n;
}

/* ---- number formatting ---- */

/* Cost of a candidate text: its length, exponent forms counted 2 longer so
 * that "36000" wins over "3.6e+04" but "1e-10" over "0.0000000001". */
static size_t text_cost(const char *t)
{
    return strlen(t) + (strchr(t, 'e') ? 2 : 0);
}

/* Shortest decimal text t with strtod(t) * scale == si exactly, so that
 * load(save(s)) == s. First collect the preset numbers p near si / scale
 * (a few ulps either side) with p * scale == si, then print each with
 * increasing precision. An SI value that is the image of no preset number
 * (possible when scale != 1, e.g. an rpm speed computed in rad/s) is written
 * as %.17g of si / scale and comes back within an ulp. */
#define ULP_WINDOW 4

static void format_real(double si, double scale, char *buf, size_t n)
{
    if (si == 0.0) {   /* the window would step over +0 from -0 */
        snprintf(buf, n, "0");
        return;
    }
    double exact[2 * ULP_WINDOW + 1], p = si / scale;
    int n_exact = 0;
    for (int k = 0; k < ULP_WINDOW; k++) p = nextafter(p, -INFINITY);
    for (int k = 0; k <= 2 * ULP_WINDOW; k++, p = nextafter(p, INFINITY))
        if (p * scale == si) exact[n_exact++] = p;

    char best[40] = "", t[40];
    for (int prec = 1; prec <= 17; prec++) {
        for (int c = 0; c < n_exact; c++) {
            snprintf(t, sizeof t, "%.*g", prec, exact[c]);
            bool same = strtod(t, NULL) * scale == si;
            if (same && (best[0] == '\0' || text_cost(t) < text_cost(best)))
                memcpy(best, t, sizeof t);
        }
    }
    if (best[0] == '\0') snprintf(best, sizeof best, "%.17g", si / scale);
    snprintf(buf, n, "%s", best);
}

static const char *unit_suffix(const field *f, char *buf, size_t n)
{
    snprintf(buf, n, "%s%s", f->info.unit[0] ? " " : "", f->info.unit);
    return buf;
}

/* Why v (preset units) is out of range; "" if it is inside. A value below
 * the range names the lower bound only; above it, the whole range. */
static void range_reason(const field *f, double v, char *buf, size_t n)
{
    const acbb_field_info *in = &f->info;
    bool lo_open = f->ends == OC || f->ends == OO, hi_open = f->ends == CO || f->ends == OO;
    bool below = lo_open ? v <= in->min : v < in->min;
    bool above = hi_open ? v >= in->max : v > in->max;
    char u[32];
    unit_suffix(f, u, sizeof u);
    if (below)
        snprintf(buf, n, "must be %s %.15g%s", lo_open ? ">" : ">=", in->min, u);
    else if (above && !lo_open && !hi_open)
        snprintf(buf, n, "must be between %.15g and %.15g%s", in->min, in->max, u);
    else if (above)
        snprintf(buf, n, "must be %s %.15g and %s %.15g%s", lo_open ? ">" : ">=", in->min,
                 hi_open ? "<" : "<=", in->max, u);
    else
        buf[0] = '\0';
}

/* ---- schema introspection ---- */

size_t acbb_scene_field_count(void) { return N_FIELDS; }

const acbb_field_info *acbb_scene_field(size_t i)
{
    return i < N_FIELDS ? &k_fields[i].info : NULL;
}

void acbb_scene_field_format(const acbb_scene *s, size_t i, char *buf, size_t n)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (i >= N_FIELDS) return;
    const field *f = &k_fields[i];
    switch (f->info.type) {
    case ACBB_FIELD_REAL:
        format_real(get_real(s, f), f->scale, buf, n);
        break;
    case ACBB_FIELD_INT:
        snprintf(buf, n, "%d", get_int(s, f));
        break;
    case ACBB_FIELD_BOOL:
        snprintf(buf, n, "%s", get_bool(s, f) ? "on" : "off");
        break;
    case ACBB_FIELD_ENUM: {
        int v = get_int(s, f);
        bool known = v >= 0 && (size_t)v < n_choices(f);
        snprintf(buf, n, "%s", known ? f->info.choices[v] : "?");
        break;
    }
    }
}

void acbb_scene_field_range(size_t i, char *buf, size_t n)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (i >= N_FIELDS) return;
    const field *f = &k_fields[i];
    char u[32];
    size_t used = 0;
    switch (f->info.type) {
    case ACBB_FIELD_REAL:
    case ACBB_FIELD_INT: {
        bool lo_open = f->ends == OC || f->ends == OO, hi_open = f->ends == CO || f->ends == OO;
        snprintf(buf, n, "%.15g %s x %s %.15g%s", f->info.min, lo_open ? "<" : "<=",
                 hi_open ? "<" : "<=", f->info.max, unit_suffix(f, u, sizeof u));
        break;
    }
    case ACBB_FIELD_BOOL:
        snprintf(buf, n, "on | off");
        break;
    case ACBB_FIELD_ENUM:
        for (size_t c = 0; f->info.choices[c] && used < n; c++)
            used += (size_t)snprintf(buf + used, n - used, "%s%s", c ? " | " : "",
                                     f->info.choices[c]);
        break;
    }
}

const char *acbb_model_level_name(acbb_model_level m)
{
    return m >= ACBB_MODEL_STATIC && m <= ACBB_MODEL_DYNAMIC ? k_model[m] : "unknown";
}

void acbb_scene_default(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    for (size_t i = 0; i < N_FIELDS; i++)
        put(s, &k_fields[i], k_fields[i].def);
}

/* ---- key lookup and suggestions ---- */

static const field *find_field(const char *section, const char *key)
{
    for (size_t i = 0; i < N_FIELDS; i++)
        if (strcmp(k_fields[i].info.section, section) == 0 &&
            strcmp(k_fields[i].info.key, key) == 0)
            return &k_fields[i];
    return NULL;
}

static bool section_known(const char *section)
{
    for (size_t i = 0; i < N_FIELDS; i++)
        if (strcmp(k_fields[i].info.section, section) == 0) return true;
    return false;
}

#define EDIT_MAX 128

/* Levenshtein distance (two-row dynamic programme); hand-written because no
 * library at hand offers it and the strings are short. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la >= EDIT_MAX || lb >= EDIT_MAX) return (size_t)-1;
    size_t prev[EDIT_MAX], cur[EDIT_MAX];
    for (size_t j = 0; j <= lb; j++) prev[j] = j;
    for (size_t i = 1; i <= la; i++) {
        cur[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t del = prev[j] + 1, ins = cur[j - 1] + 1;
            size_t sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            size_t m = del < ins ? del : ins;
            cur[j] = m < sub ? m : sub;
        }
        memcpy(prev, cur, (lb + 1) * sizeof prev[0]);
    }
    return prev[lb];
}

/* Nearest schema key to `name`: compared with "section.key" when
 * `dotted`, else with the bare key. NULL if nothing is reasonably close. */
static const field *nearest_field(const char *name, bool dotted)
{
    const field *best = NULL;
    size_t best_d = (size_t)-1;
    for (size_t i = 0; i < N_FIELDS; i++) {
        char full[EDIT_MAX];
        snprintf(full, sizeof full, "%s.%s", k_fields[i].info.section, k_fields[i].info.key);
        size_t d = edit_distance(name, dotted ? full : k_fields[i].info.key);
        if (d < best_d) {
            best_d = d;
            best = &k_fields[i];
        }
    }
    return best_d <= 2 + strlen(name) / 4 ? best : NULL;
}

/* " (did you mean section.key?)" or "". */
static void suggestion(const char *name, bool dotted, char *buf, size_t n)
{
    const field *f = nearest_field(name, dotted);
    if (f)
        snprintf(buf, n, " (did you mean %s.%s?)", f->info.section, f->info.key);
    else
        buf[0] = '\0';
}

/* Message for a key that is not in the schema ("section.key: ..."). */
static acbb_status unknown_key(const char *section, const char *key, acbb_error *err)
{
    char name[2 * EDIT_MAX], hint[160];
    snprintf(name, sizeof name, "%s.%s", section, key);
    if (section[0] == '\0') {
        suggestion(key, false, hint, sizeof hint);
        return acbb_error_set(err, ACBB_EINVAL, "%s: key outside any [section]%s", key, hint);
    }
    suggestion(name, true, hint, sizeof hint);
    if (!section_known(section))
        return acbb_error_set(err, ACBB_EINVAL, "%s: unknown section [%s]%s", name, section,
                              hint);
    return acbb_error_set(err, ACBB_EINVAL, "%s: unknown key%s", name, hint);
}

/* ---- value parsing ---- */

static bool word_eq(const char *a, const char *b)
{
    return strcasecmp(a, b) == 0;
}

/* Copy `text` without surrounding blanks (inih trims, acbb_scene_set may
 * not); false if it does not fit. */
static bool trim_copy(const char *text, char *out, size_t n)
{
    while (isspace((unsigned char)*text)) text++;
    size_t len = strlen(text);
    while (len > 0 && isspace((unsigned char)text[len - 1])) len--;
    bool fits = len < n;
    if (!fits) len = n - 1;
    memcpy(out, text, len);
    out[len] = '\0';
    return fits;
}

static acbb_status reason(char *why, size_t n, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static acbb_status reason(char *why, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, n, fmt, ap);
    va_end(ap);
    return ACBB_EINVAL;
}

static acbb_status parse_number(const field *f, const char *t, double *out, char *why, size_t n)
{
    char *end;
    if (t[0] == '\0') return reason(why, n, "missing value");
    double v = strtod(t, &end);
    if (end == t) return reason(why, n, "not a number");
    if (*end != '\0')
        return reason(why, n, "not a number (unexpected \"%s\" after %.*s)", end,
                      (int)(end - t), t);
    if (!isfinite(v)) return reason(why, n, "must be a finite number");
    if (f->info.type == ACBB_FIELD_INT && v != floor(v))
        return reason(why, n, "must be a whole number");
    range_reason(f, v, why, n);
    if (why[0]) return ACBB_EINVAL;
    *out = v;
    return ACBB_OK;
}

static acbb_status parse_bool(const char *t, double *out, char *why, size_t n)
{
    static const char *const yes[] = {"on", "true", "yes", "1"}, *const no[] = {"off", "false", "no", "0"};
    for (size_t i = 0; i < 4; i++) {
        if (word_eq(t, yes[i]) || word_eq(t, no[i])) {
            *out = word_eq(t, yes[i]);
            return ACBB_OK;
        }
    }
    return reason(why, n, "must be on or off (or true/false, yes/no, 1/0)");
}

static acbb_status parse_enum(const field *f, const char *t, double *out, char *why, size_t n)
{
    size_t used = (size_t)snprintf(why, n, "must be one of: ");
    for (size_t c = 0; f->info.choices[c]; c++) {
        if (word_eq(t, f->info.choices[c])) {
            *out = (double)c;
            return ACBB_OK;
        }
        if (used < n)
            used += (size_t)snprintf(why + used, n - used, "%s%s", c ? ", " : "",
                                     f->info.choices[c]);
    }
    return ACBB_EINVAL;
}

/* Parse `text` (preset units) into field f of s. s is untouched on failure;
 * the message is "section.key = text: reason". */
static acbb_status apply_value(acbb_scene *s, const field *f, const char *text, acbb_error *err)
{
    char t[256], why[256];
    double v = 0.0;
    acbb_status rc;
    if (!trim_copy(text, t, sizeof t))
        return acbb_error_set(err, ACBB_EINVAL, "%s.%s: value too long", f->info.section,
                              f->info.key);
    switch (f->info.type) {
    case ACBB_FIELD_BOOL: rc = parse_bool(t, &v, why, sizeof why); break;
    case ACBB_FIELD_ENUM: rc = parse_enum(f, t, &v, why, sizeof why); break;
    default: rc = parse_number(f, t, &v, why, sizeof why); break;
    }
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "%s.%s = %s: %s", f->info.section, f->info.key, t, why);
    put(s, f, v);
    return ACBB_OK;
}

/* ---- cross-field validation ---- */

/* Current value of section.key in preset units, for messages. */
static const char *show(const acbb_scene *s, const char *section, const char *key, char *buf)
{
    const field *f = find_field(section, key);
    acbb_scene_field_format(s, f ? (size_t)(f - k_fields) : N_FIELDS, buf, 40);
    return buf;
}

/* Raceway diameters d_i, d_o from the free contact angle (MODEL.md section 1):
 * A0 = lambda_i + lambda_o - D, P_d = 2 A0 (1 - cos alpha0). */
static void raceway_diameters(const acbb_scene *s, double *di, double *d_o)
{
    double A0 = s->inner_groove_radius + s->outer_groove_radius - s->ball_diameter;
    double Pd = 2.0 * A0 * (1.0 - cos(s->contact_angle0));
    *di = s->pitch_diameter - s->ball_diameter - 0.5 * Pd;
    *d_o = s->pitch_diameter + s->ball_diameter + 0.5 * Pd;
}

/* Every field inside its range (a Scene may be built in code, not parsed).
 * Compared in SI: x -> x * scale is monotone, so this agrees with the
 * check on the preset value at load time. */
static acbb_status rule_ranges(const acbb_scene *s, acbb_error *err)
{
    for (size_t i = 0; i < N_FIELDS; i++) {
        const field *f = &k_fields[i];
        char val[40], why[160];
        if (f->info.type == ACBB_FIELD_ENUM) {
            int v = get_int(s, f);
            if (v < 0 || (size_t)v >= n_choices(f))
                return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %d: not a valid choice",
                                      f->info.section, f->info.key, v);
            continue;
        }
        if (f->info.type == ACBB_FIELD_BOOL) continue;
        double v = f->info.type == ACBB_FIELD_REAL ? get_real(s, f) : get_int(s, f);
        if (!isfinite(v)) {
            acbb_scene_field_format(s, i, val, sizeof val);
            return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s: must be a finite number",
                                  f->info.section, f->info.key, val);
        }
        field scaled = *f;
        scaled.info.min *= f->scale;
        scaled.info.max *= f->scale;
        range_reason(&scaled, v, why, sizeof why);
        if (why[0]) {
            acbb_scene_field_format(s, i, val, sizeof val);
            range_reason(f, v / f->scale, why, sizeof why);
            return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s: %s", f->info.section,
                                  f->info.key, val, why);
        }
    }
    return ACBB_OK;
}

/* f = lambda / D >= 0.505 (MODEL.md section 11: near-conformal grooves make
 * A -> 0); this also implies groove radius > ball radius. */
static acbb_status groove_rule(const acbb_scene *s, const char *which, double lambda,
                               acbb_error *err)
{
    double f = lambda / s->ball_diameter;
    if (f >= 0.505) return ACBB_OK;
    char key[48], a[40], b[40];
    snprintf(key, sizeof key, "%s_groove_radius_mm", which);
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.%s = %s with ball_diameter_mm = %s: groove curvature "
                          "f = radius / ball_diameter = %.4g must be >= 0.505 "
                          "(MODEL.md section 11)",
                          key, show(s, "bearing", key, a), show(s, "bearing", "ball_diameter_mm", b),
                          f);
}

static acbb_status rule_inner_groove(const acbb_scene *s, acbb_error *err)
{
    return groove_rule(s, "inner", s->inner_groove_radius, err);
}

static acbb_status rule_outer_groove(const acbb_scene *s, acbb_error *err)
{
    return groove_rule(s, "outer", s->outer_groove_radius, err);
}

/* The balls must fit on the pitch circle with a small gap for the cage. */
static acbb_status rule_balls_fit(const acbb_scene *s, acbb_error *err)
{
    double used = s->n_balls * s->ball_diameter, room = 0.98 * PI * s->pitch_diameter;
    if (used <= room) return ACBB_OK;
    char a[40], b[40], c[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.n_balls = %s with ball_diameter_mm = %s, pitch_diameter_mm = %s: "
                          "the balls do not fit on the pitch circle (n_balls * ball_diameter = "
                          "%.4g mm > 0.98 pi pitch_diameter = %.4g mm)",
                          show(s, "bearing", "n_balls", a), show(s, "bearing", "ball_diameter_mm", b),
                          show(s, "bearing", "pitch_diameter_mm", c), used * 1e3, room * 1e3);
}

/* The inner ring needs material between bore and raceway. */
static acbb_status rule_inner_ring(const acbb_scene *s, acbb_error *err)
{
    double di, d_o;
    raceway_diameters(s, &di, &d_o);
    if (s->bore < di) return ACBB_OK;
    char a[40], b[40], c[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.bore_mm = %s with pitch_diameter_mm = %s, ball_diameter_mm = %s: "
                          "the inner ring has no material (bore must be < the inner raceway "
                          "diameter d_i = %.6g mm, MODEL.md section 1)",
                          show(s, "bearing", "bore_mm", a), show(s, "bearing", "pitch_diameter_mm", b),
                          show(s, "bearing", "ball_diameter_mm", c), di * 1e3);
}

static acbb_status rule_outer_ring(const acbb_scene *s, acbb_error *err)
{
    double di, d_o;
    raceway_diameters(s, &di, &d_o);
    if (s->outer_diameter > d_o) return ACBB_OK;
    char a[40], b[40], c[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.outer_diameter_mm = %s with pitch_diameter_mm = %s, "
                          "ball_diameter_mm = %s: the outer ring has no material (outer_diameter "
                          "must be > the outer raceway diameter d_o = %.6g mm, MODEL.md section 1)",
                          show(s, "bearing", "outer_diameter_mm", a),
                          show(s, "bearing", "pitch_diameter_mm", b),
                          show(s, "bearing", "ball_diameter_mm", c), d_o * 1e3);
}

/* Lands: the inner land between the inner raceway and the pitch circle,
 * the outer land between the pitch circle and the outer raceway. */
static acbb_status rule_inner_land(const acbb_scene *s, acbb_error *err)
{
    double di, d_o;
    raceway_diameters(s, &di, &d_o);
    if (s->inner_land_diameter > di && s->inner_land_diameter < s->pitch_diameter) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.inner_land_diameter_mm = %s with pitch_diameter_mm = %s: the "
                          "inner land must lie between the inner raceway (d_i = %.6g mm) and "
                          "the pitch circle",
                          show(s, "bearing", "inner_land_diameter_mm", a),
                          show(s, "bearing", "pitch_diameter_mm", b), di * 1e3);
}

static acbb_status rule_outer_land(const acbb_scene *s, acbb_error *err)
{
    double di, d_o;
    raceway_diameters(s, &di, &d_o);
    if (s->outer_land_diameter > s->pitch_diameter && s->outer_land_diameter < d_o) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.outer_land_diameter_mm = %s with pitch_diameter_mm = %s: the "
                          "outer land must lie between the pitch circle and the outer raceway "
                          "(d_o = %.6g mm)",
                          show(s, "bearing", "outer_land_diameter_mm", a),
                          show(s, "bearing", "pitch_diameter_mm", b), d_o * 1e3);
}

static acbb_status rule_cage_diameter(const acbb_scene *s, acbb_error *err)
{
    if (s->cage_diameter > s->inner_land_diameter && s->cage_diameter < s->outer_land_diameter)
        return ACBB_OK;
    char a[40], b[40], c[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.cage_diameter_mm = %s with inner_land_diameter_mm = %s, "
                          "outer_land_diameter_mm = %s: the cage must lie between the two lands",
                          show(s, "bearing", "cage_diameter_mm", a),
                          show(s, "bearing", "inner_land_diameter_mm", b),
                          show(s, "bearing", "outer_land_diameter_mm", c));
}

static acbb_status rule_ring_width(const acbb_scene *s, acbb_error *err)
{
    if (s->width > s->ball_diameter) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.width_mm = %s with ball_diameter_mm = %s: the rings must be "
                          "wider than the balls",
                          show(s, "bearing", "width_mm", a), show(s, "bearing", "ball_diameter_mm", b));
}

static acbb_status rule_cage_width(const acbb_scene *s, acbb_error *err)
{
    if (s->cage_width <= s->width) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.cage_width_mm = %s with width_mm = %s: the cage must not be "
                          "wider than the rings",
                          show(s, "bearing", "cage_width_mm", a), show(s, "bearing", "width_mm", b));
}

static acbb_status rule_shaft_bore(const acbb_scene *s, acbb_error *err)
{
    if (s->shaft_bore < s->bore) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "mounting.shaft_bore_mm = %s with bearing.bore_mm = %s: the shaft bore "
                          "must be smaller than the bearing bore",
                          show(s, "mounting", "shaft_bore_mm", a), show(s, "bearing", "bore_mm", b));
}

/* Oil thins when heated: the Walther law needs nu100 < nu40 (MODEL.md section 5). */
static acbb_status rule_viscosity(const acbb_scene *s, acbb_error *err)
{
    if (s->oil_nu100 < s->oil_nu40) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "lubricant.oil_nu100_mm2_s = %s with oil_nu40_mm2_s = %s: the viscosity "
                          "at 100 C must be lower than at 40 C",
                          show(s, "lubricant", "oil_nu100_mm2_s", a),
                          show(s, "lubricant", "oil_nu40_mm2_s", b));
}

static acbb_status rule_time_step(const acbb_scene *s, acbb_error *err)
{
    if (s->time_step <= s->max_time) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "fidelity.time_step_s = %s with thermal.max_time_s = %s: the time step must not "
                          "exceed the time limit",
                          show(s, "fidelity", "time_step_s", a), show(s, "thermal", "max_time_s", b));
}

static acbb_status rule_temp_limit(const acbb_scene *s, acbb_error *err)
{
    if (s->temp_limit_C > s->ambient_C) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "thermal.temp_limit_C = %s with operating.ambient_C = %s: the runaway "
                          "limit must be above the ambient temperature",
                          show(s, "thermal", "temp_limit_C", a), show(s, "operating", "ambient_C", b));
}

/* Pure radial load on one angular-contact bearing with a free axial DOF has
 * no equilibrium (MODEL.md section 11): require F_x >= 1.25 F_r tan(alpha0). */
static acbb_status rule_radial_load(const acbb_scene *s, acbb_error *err)
{
    double need = 1.25 * s->radial_load * tan(s->contact_angle0);
    if (s->preload != ACBB_PRELOAD_FORCE || s->axial_load >= need) return ACBB_OK;
    char a[40], b[40];
    return acbb_error_set(err, ACBB_ILL_POSED,
                          "operating.radial_load_N = %s with axial_load_N = %s: a single "
                          "angular-contact bearing needs axial_load_N >= %.4g N "
                          "(1.25 Fr tan(alpha0)) or mounting.preload = displacement",
                          show(s, "operating", "radial_load_N", a),
                          show(s, "operating", "axial_load_N", b), need);
}

typedef acbb_status (*rule_fn)(const acbb_scene *, acbb_error *);

/* Order matters: ranges first (later rules divide by them), the grooves
 * before anything that uses the raceway diameters, ill-posedness last. */
static const rule_fn k_rules[] = {
    rule_ranges, rule_inner_groove, rule_outer_groove, rule_balls_fit, rule_inner_ring,
    rule_outer_ring, rule_inner_land, rule_outer_land, rule_cage_diameter, rule_ring_width,
    rule_cage_width, rule_shaft_bore, rule_viscosity, rule_time_step, rule_temp_limit,
    rule_radial_load,
};

acbb_status acbb_scene_validate(const acbb_scene *s, acbb_error *err)
{
    for (size_t i = 0; i < sizeof k_rules / sizeof k_rules[0]; i++) {
        acbb_status rc = k_rules[i](s, err);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

/* ---- acbb_scene_set ---- */

static acbb_status set_one(acbb_scene *s, const char *dotted_key, const char *value,
                           int cross_check, acbb_error *err)
{
    char section[EDIT_MAX], hint[160];
    const char *dot = strchr(dotted_key, '.');
    if (!dot) {
        suggestion(dotted_key, false, hint, sizeof hint);
        return acbb_error_set(err, ACBB_EINVAL, "%s: expected section.key%s", dotted_key, hint);
    }
    size_t len = (size_t)(dot - dotted_key);
    if (len >= sizeof section) len = sizeof section - 1;
    memcpy(section, dotted_key, len);
    section[len] = '\0';
    const field *f = find_field(section, dot + 1);
    if (!f) return unknown_key(section, dot + 1, err);

    acbb_scene trial = *s;
    acbb_status rc = apply_value(&trial, f, value, err);
    if (rc == ACBB_OK && cross_check) rc = acbb_scene_validate(&trial, err);
    if (rc == ACBB_OK) *s = trial;
    return rc;
}

acbb_status acbb_scene_set(acbb_scene *s, const char *dotted_key, const char *value,
                           acbb_error *err)
{
    return set_one(s, dotted_key, value, 1, err);
}

acbb_status acbb_scene_set_value(acbb_scene *s, const char *dotted_key, const char *value,
                                 acbb_error *err)
{
    return set_one(s, dotted_key, value, 0, err);
}

/* ---- loading ---- */

typedef struct {
    const char *path;
    FILE *file;
    acbb_scene scene;
    int line;                   /* line number of the line inih is handling */
    int n_keys;
    int first_line[N_FIELDS];   /* where each key was set, 0 = not yet */
    int err_line;               /* first error found by us, 0 = none */
    acbb_status err_code;
    acbb_error err;
} load_ctx;

static void load_fail(load_ctx *c, acbb_status code, const char *msg)
{
    if (c->err_line) return;
    c->err_line = c->line;
    c->err_code = code;
    acbb_error_set(&c->err, code, "%s:%d: %s", c->path, c->line, msg);
}

/* fgets for inih that counts lines, stops on a line that does not fit the
 * buffer (inih would silently split it into two lines), and strips leading
 * blanks so no line is read as a continuation of the previous value. */
static char *read_line(char *str, int num, void *stream)
{
    load_ctx *c = stream;
    if (c->err_line || !fgets(str, num, c->file)) return NULL;
    c->line++;
    size_t len = strlen(str);
    if (len == 0 || str[len - 1] != '\n') {
        int ch = fgetc(c->file);
        if (ch != EOF) {
            char msg[96];
            snprintf(msg, sizeof msg, "line too long (at most %d characters)", num - 3);
            load_fail(c, ACBB_EINVAL, msg);
            return NULL;
        }
    }
    size_t skip = strspn(str, " \t");
    memmove(str, str + skip, strlen(str + skip) + 1);
    return str;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    load_ctx *c = user;
    if (c->err_line) return 1;
    acbb_error e;
    c->n_keys++;
    const field *f = find_field(section, name);
    if (!f) {
        unknown_key(section, name, &e);
        load_fail(c, ACBB_EINVAL, e.msg);
        return 0;
    }
    size_t i = (size_t)(f - k_fields);
    if (c->first_line[i]) {
        snprintf(e.msg, sizeof e.msg, "%s.%s: set twice (first at line %d)", section, name,
                 c->first_line[i]);
        load_fail(c, ACBB_EINVAL, e.msg);
        return 0;
    }
    c->first_line[i] = c->line;
    if (apply_value(&c->scene, f, value, &e) != ACBB_OK) {
        load_fail(c, ACBB_EINVAL, e.msg);
        return 0;
    }
    return 1;
}

acbb_status acbb_scene_load(const char *path, acbb_scene *s, acbb_error *err)
{
    load_ctx *c = calloc(1, sizeof *c);
    if (!c) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    c->path = path;
    acbb_scene_default(&c->scene);
    c->file = fopen(path, "r");
    if (!c->file) {
        int e = errno;
        free(c);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot open: %s", path, strerror(e));
    }

    int ret = ini_parse_stream(read_line, c, on_key, c);
    int read_errno = ferror(c->file) ? errno : 0;
    bool read_error = ferror(c->file) != 0;
    fclose(c->file);

    acbb_status rc = ACBB_OK;
    if (read_error) {
        rc = acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(read_errno));
    } else if (ret < 0) {
        rc = acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    } else if (ret > 0 && (c->err_line == 0 || ret < c->err_line)) {
        rc = acbb_error_set(err, ACBB_EINVAL,
                            "%s:%d: malformed line (expected key = value or [section])", path, ret);
    } else if (c->err_line) {
        rc = acbb_error_set(err, c->err_code, "%s", c->err.msg);
    } else if (c->n_keys == 0) {
        rc = acbb_error_set(err, ACBB_EINVAL, "%s: empty preset (no keys)", path);
    } else {
        acbb_error e;
        rc = acbb_scene_validate(&c->scene, &e);
        if (rc != ACBB_OK)
            acbb_error_set(err, rc, "%s: %s", path, e.msg);
        else
            *s = c->scene;
    }
    free(c);
    return rc;
}

/* ---- saving ---- */

static int write_preset(FILE *f, const acbb_scene *s)
{
    const char *section = "";
    int bad = fprintf(f, "; acbb preset (bearing scene). Units are in the key names; decimal "
                         "point '.'.\n; Every key is listed; a key left out of a preset takes "
                         "its default (presets/7008C.ini).\n") < 0;
    for (size_t i = 0; i < N_FIELDS && !bad; i++) {
        const acbb_field_info *in = &k_fields[i].info;
        char range[160], val[64];
        if (strcmp(section, in->section) != 0) {
            section = in->section;
            bad |= fprintf(f, "\n[%s]\n", section) < 0;
        }
        acbb_scene_field_range(i, range, sizeof range);
        acbb_scene_field_format(s, i, val, sizeof val);
        bad |= fprintf(f, "; %s [%s]\n%s = %s\n", in->help, range, in->key, val) < 0;
    }
    return bad ? -1 : 0;
}

/* Flush the rename to disk; best effort (the file itself is already safe). */
static void sync_parent_dir(const char *path)
{
    char *dir = strdup(path);
    if (!dir) return;
    char *slash = strrchr(dir, '/');
    const char *d = ".";
    if (slash) {
        slash[slash == dir ? 1 : 0] = '\0';
        d = dir;
    }
    int fd = open(d, O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
    free(dir);
}

acbb_status acbb_scene_save(const char *path, const acbb_scene *s, acbb_error *err)
{
    acbb_error e;
    acbb_status rc = acbb_scene_validate(s, &e);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "%s: not saved: %s", path, e.msg);

    size_t n = strlen(path) + sizeof ".tmp.XXXXXX";
    char *tmp = malloc(n);
    if (!tmp) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    snprintf(tmp, n, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        int en = errno;
        free(tmp);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot save (temporary file): %s", path,
                              strerror(en));
    }
    /* mkstemp makes the file 0600; keep the mode of the file we replace. */
    struct stat st;
    (void)fchmod(fd, stat(path, &st) == 0 ? (st.st_mode & 07777) : 0644);

    const char *step = "write";
    FILE *f = fdopen(fd, "w");
    bool ok = f != NULL;
    if (!ok) close(fd);
    if (ok) ok = write_preset(f, s) == 0 && fflush(f) == 0;
    if (ok && fsync(fileno(f)) != 0) ok = false, step = "fsync";
    int en = errno;
    if (f && fclose(f) != 0 && ok) ok = false, en = errno;
    if (ok && rename(tmp, path) != 0) ok = false, en = errno, step = "rename";
    if (!ok) {
        unlink(tmp);
        free(tmp);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot save (%s): %s", path, step,
                              strerror(en));
    }
    free(tmp);
    sync_parent_dir(path);
    return ACBB_OK;
}

acbb_status acbb_scene_apply_edits(acbb_scene *s, const char *const *edits, size_t n,
                                   acbb_error *err)
{
    acbb_scene trial = *s;
    for (size_t i = 0; i < n; i++) {
        const char *text = edits[i], *eq = strchr(text, '=');
        char key[EDIT_MAX];
        if (!eq || eq == text || (size_t)(eq - text) >= sizeof key)
            return acbb_error_set(err, ACBB_EINVAL, "--set %s: expected section.key=value", text);
        memcpy(key, text, (size_t)(eq - text));
        key[eq - text] = '\0';
        acbb_error e = { "" };
        acbb_status rc = set_one(&trial, key, eq + 1, 0, &e);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "--set %s: %s", text, e.msg);
    }
    /* Cross-field rules once, on the scene as a whole. */
    acbb_status rc = acbb_scene_validate(&trial, err);
    if (rc == ACBB_OK) *s = trial;
    return rc;
}

/* The schema's ball-count range must match what the engine holds. */
_Static_assert(ACBB_MAX_BALLS == 64, "bearing.n_balls range in the schema is 3..64");
