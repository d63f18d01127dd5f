/* acbb — scene cross-field validation: every rule names the keys involved,
 * their values in preset units and the reason. */
#include <fnmatch.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geometry.h"
#include "acbb/units.h"
#include "scene_internal.h"
#include "acbb/tools/set.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/scene_inactive.h"
#include "acbb/tools/scene_schema.h"
#include "acbb/tools/surroundings.h"

#define show acbb_sf_show

/* ---- cross-field validation ---- */

/* Current value of section.key in preset units, for messages
 * (scene_internal.h; `show` here and in scene_rules_spindle.c). */
const char *acbb_sf_show(const acbb_scene *s, const char *section, const char *key, char *buf)
{
    const acbb_sfield *f = acbb_sf_find(section, key);
    acbb_scene_field_format(s, f ? (size_t)(f - acbb_sf_table) : acbb_sf_n, buf, 40);
    return buf;
}

/* Raceway diameters d_i, d_o from the clearance (MODEL.md section 1):
 * P_d given, or 2 A0 (1 - cos alpha0) with A0 = lambda_i + lambda_o - D. */
static void raceway_diameters(const acbb_scene *s, double *di, double *d_o)
{
    double Pd = acbb_diametral_clearance(s);
    *di = s->pitch_diameter - s->ball_diameter - 0.5 * Pd;
    *d_o = s->pitch_diameter + s->ball_diameter + 0.5 * Pd;
}

/* Every field inside its range (a Scene may be built in code, not parsed).
 * Compared in SI: x -> x * scale is monotone, so this agrees with the
 * check on the preset value at load time. */
static acbb_status rule_ranges(const acbb_scene *s, acbb_error *err)
{
    for (size_t i = 0; i < acbb_sf_n; i++) {
        const acbb_sfield *f = &acbb_sf_table[i];
        char val[40], why[160];
        if (f->info.type == ACBB_FIELD_ENUM) {
            int v = acbb_sf_get_int(s, f);
            if (v < 0 || (size_t)v >= acbb_sf_n_choices(f))
                return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %d: not a valid choice",
                                      f->info.section, f->info.key, v);
            continue;
        }
        if (f->info.type == ACBB_FIELD_BOOL) continue;
        double v = f->info.type == ACBB_FIELD_REAL ? acbb_sf_get_real(s, f) : acbb_sf_get_int(s, f);
        if (!isfinite(v)) {
            acbb_scene_field_format(s, i, val, sizeof val);
            return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s: must be a finite number",
                                  f->info.section, f->info.key, val);
        }
        if (acbb_sf_out_of_range_si(f, v)) {
            acbb_scene_field_format(s, i, val, sizeof val);
            acbb_sf_range_reason(f, v / f->scale, why, sizeof why);
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
                          "(docs/physics.md section 11)",
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

/* Geometry by the free angle OR by the clearance (MODEL.md section 1,
 * geometry.h): a clearance > 0 gives cos alpha0 = 1 - P_d / (2 A0); the
 * angle key must then be 0 (deep groove, nominal angle) or that angle. */
static acbb_status rule_clearance(const acbb_scene *s, acbb_error *err)
{
    if (!(s->clearance > 0.0)) return ACBB_OK;
    double A0 = s->inner_groove_radius + s->outer_groove_radius - s->ball_diameter;
    double c = 1.0 - s->clearance / (2.0 * A0), a0 = acos(fmax(-1.0, c)) / ACBB_DEG;
    char a[40], b[40];
    if (!(a0 <= 45.0))
        return acbb_error_set(err, ACBB_EINVAL,
                              "bearing.clearance_um = %s with groove-centre distance A0 = %.4g "
                              "mm: the free contact angle acos(1 - P_d/(2 A0)) = %.4g deg is "
                              "above 45 deg (docs/physics.md section 1)",
                              show(s, "bearing", "clearance_um", a), A0 * 1e3, a0);
    double given = s->contact_angle0 / ACBB_DEG;
    if (given == 0.0 || fabs(given - a0) <= 0.05) return ACBB_OK;
    return acbb_error_set(err, ACBB_EINVAL,
                          "bearing.clearance_um = %s and contact_angle_deg = %s disagree: the "
                          "clearance gives a free contact angle of %.4f deg (cos a0 = 1 - "
                          "P_d/(2 A0), docs/physics.md section 1); set contact_angle_deg = 0 (deep "
                          "groove) or %.4f, or clearance_um = 0 (geometry from the angle)",
                          show(s, "bearing", "clearance_um", a),
                          show(s, "bearing", "contact_angle_deg", b), a0, a0);
}

/* The balls must fit on the pitch circle with a small gap for the cage. */
static acbb_status rule_balls_fit(const acbb_scene *s, acbb_error *err)
{
    double used = s->n_balls * s->ball_diameter, room = 0.98 * ACBB_PI * s->pitch_diameter;
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
                          "diameter d_i = %.6g mm, docs/physics.md section 1)",
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
                          "must be > the outer raceway diameter d_o = %.6g mm, docs/physics.md section 1)",
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

/* The housing, cap and shaft segment must hold the bearing; a coolant must
 * stay below the runaway limit. */
static acbb_status rule_surroundings(const acbb_scene *s, acbb_error *err)
{
    acbb_surroundings u;
    acbb_scene_surroundings(s, &u);
    char a[40], b[40];
    /* The bearing OD is formatted only for a message: every validation
     * formatted it (each `--set`-style edit of a study point validates the
     * scene), 2 % of a perturbed study of `report --sensitivity` (issue 30). */
    if (s->housing_bc == ACBB_BC_DERIVED)
        return acbb_error_set(err, ACBB_EINVAL, "surroundings.housing_exterior = derived: only "
                              "the shaft bore and the end cap derive their boundary; the housing "
                              "exterior is convective (the seed's) or fixed");
    if (!(u.housing_od > s->outer_diameter))
        return acbb_error_set(err, ACBB_EINVAL, "surroundings.housing_outer_diameter_mm = %s "
                              "with bearing.outer_diameter_mm = %s: the housing must be larger "
                              "than the bearing (0 = derive %.4g mm)",
                              show(s, "surroundings", "housing_outer_diameter_mm", a),
                              show(s, "bearing", "outer_diameter_mm", b),
                              0.120e3 * s->outer_diameter / (68 * 1e-3));
    if (!(u.cap_od > s->outer_diameter))
        return acbb_error_set(err, ACBB_EINVAL, "surroundings.cap_outer_diameter_mm = %s with "
                              "bearing.outer_diameter_mm = %s: the end cap must cover the outer "
                              "ring face and reach the housing (> the bearing OD; 0 = the housing "
                              "outer diameter)", show(s, "surroundings", "cap_outer_diameter_mm", a),
                              show(s, "bearing", "outer_diameter_mm", b));
    double need = s->width + 2.0 * fmax(u.shoulder_thickness, u.cap_thickness);
    if (u.housing_length < need * (1.0 - 1e-12))
        return acbb_error_set(err, ACBB_EINVAL, "surroundings.housing_length_mm = %s (%.4g mm "
                              "used) with bearing.width_mm = %s: the housing must hold the bearing "
                              "and, each side, the rear shoulder (%.4g mm) or end cap (%.4g mm): "
                              "length >= %.4g mm",
                              show(s, "surroundings", "housing_length_mm", a), u.housing_length * 1e3,
                              show(s, "bearing", "width_mm", b), u.shoulder_thickness * 1e3,
                              u.cap_thickness * 1e3, need * 1e3);
    if (u.shaft_length < s->width)
        return acbb_error_set(err, ACBB_EINVAL, "surroundings.shaft_length_mm = %s with "
                              "bearing.width_mm = %s: the shaft segment must be at least as long "
                              "as the inner ring", show(s, "surroundings", "shaft_length_mm", a),
                              show(s, "bearing", "width_mm", b));
    const acbb_face_bc *bc[2] = {&s->bore_bc, &s->cap_bc};
    static const char *const key[2] = {"shaft_bore_coolant_dT_K", "cap_coolant_dT_K"};
    for (int i = 0; i < 2; i++)
        if (s->ambient_C + bc[i]->dT >= s->temp_limit_C)
            return acbb_error_set(err, ACBB_EINVAL, "surroundings.%s = %s with "
                                  "operating.ambient_C = %s: the coolant (%.4g C) must be below "
                                  "thermal.temp_limit_C = %.4g C", key[i],
                                  show(s, "surroundings", key[i], a),
                                  show(s, "operating", "ambient_C", b),
                                  s->ambient_C + bc[i]->dT, s->temp_limit_C);
    return ACBB_OK;
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
 * no equilibrium (MODEL.md section 11): require F_x >= 1.25 F_r tan(alpha0).
 * A moment is the same case: each Q sin(alpha) of the loaded side pushes
 * the same way, and its moment arm is at most d_m/2, so the thrust must
 * carry 2|M|/d_m too (with less, the engine's only equilibria put loaded
 * balls at alpha < 0, on the low shoulder). The two add (conservative: the
 * worst ball sees both); a deep-groove bearing (alpha0 = 0) has two
 * shoulders and needs no thrust for a moment. */
static acbb_status rule_radial_load(const acbb_scene *s, acbb_error *err)
{
    if (s->set_arrangement != ACBB_SET_SINGLE) return ACBB_OK; /* a set carries it (rule_set) */
    if (s->shaft_segments > 0) return ACBB_OK; /* a spindle: both sets carry it */
    double radial = s->radial_load * tan(s->contact_angle0);
    double moment = s->contact_angle0 > 0.0 ? 2.0 * fabs(s->moment_load) / s->pitch_diameter : 0.0;
    double need = 1.25 * (radial + moment);
    if (s->preload != ACBB_PRELOAD_FORCE || s->axial_load >= need) return ACBB_OK;
    char a[40], b[40], c[40];
    if (moment == 0.0)
        return acbb_error_set(err, ACBB_ILL_POSED,
                              "operating.radial_load_N = %s with axial_load_N = %s: a single "
                              "angular-contact bearing needs axial_load_N >= %.4g N "
                              "(1.25 Fr tan(alpha0)) or mounting.preload = displacement",
                              show(s, "operating", "radial_load_N", a),
                              show(s, "operating", "axial_load_N", b), need);
    return acbb_error_set(err, ACBB_ILL_POSED,
                          "operating.moment_load_Nm = %s with axial_load_N = %s, radial_load_N = "
                          "%s: a single angular-contact bearing needs axial_load_N >= %.4g N "
                          "(1.25 (Fr tan(alpha0) + 2 |M| / pitch diameter)) or mounting.preload "
                          "= displacement",
                          show(s, "operating", "moment_load_Nm", c),
                          show(s, "operating", "axial_load_N", b),
                          show(s, "operating", "radial_load_N", a), need);
}

/* A displacement preload fixes the axial offset dx to what preload_N
 * produces at 20 C, 0 rpm (MODEL.md section 1, preload modes); with
 * preload_N = 0 that offset leaves every ball unloaded, so no run could
 * find contact. */
static acbb_status rule_preload(const acbb_scene *s, acbb_error *err)
{
    if (s->preload != ACBB_PRELOAD_DISPLACEMENT || s->preload_force > 0.0) return ACBB_OK;
    char a[40];
    return acbb_error_set(err, ACBB_EINVAL,
                          "mounting.preload = displacement with preload_N = %s: a displacement "
                          "preload is set by the force that makes it; preload_N must be > 0 N "
                          "(or use preload = force)",
                          show(s, "mounting", "preload_N", a));
}

/* The inner and outer spacers sit in the gap between neighbouring rings
 * (centre distance minus one width); the rest of the gap, if any, is a
 * shaft collar / housing shoulder (MODEL.md 14 L_s, L_h). */
static acbb_status rule_spacers(const acbb_scene *s, acbb_error *err)
{
    static const char *const key[2] = { "inner_spacer_mm", "outer_spacer_mm" };
    const double L[2] = { s->set_inner_spacer, s->set_outer_spacer };
    double gap = acbb_set_pitch(s) - s->width;
    char a[40], b[40], c[40];
    for (int i = 0; i < 2; i++)
        if (L[i] > 0.0 && L[i] > gap * (1.0 + 1e-12))
            return acbb_error_set(err, ACBB_EINVAL, "set.%s = %s is longer than the gap between "
                                  "neighbouring rings (set.spacing_mm = %s minus bearing.width_mm "
                                  "= %s: %.6g mm): a spacer sits in that gap (0 = the whole gap)",
                                  key[i], show(s, "set", key[i], a), show(s, "set", "spacing_mm", b),
                                  show(s, "bearing", "width_mm", c), gap * 1e3);
    return ACBB_OK;
}

/* A bearing set (MODEL.md 14): at most four bearings, the count the
 * arrangement has (DT: 2-4 in tandem), neighbours that do not overlap, and
 * a preload or thrust that loads every bearing's balls: a tandem set
 * carries thrust one way only, so with rigid spacers and no thrust nothing
 * holds it; an opposed set needs a preload > 0 (by spacers or by spring). */
static acbb_status rule_set(const acbb_scene *s, acbb_error *err)
{
    char a[40], b[40], c[40];
    int n = acbb_set_layout(s, NULL, NULL);
    const char *arr = acbb_set_arrangement_name(s->set_arrangement);
    if (n > ACBB_MAX_SET)
        return acbb_error_set(err, ACBB_EINVAL, "set.n_bearings = %d: a set has at most %d "
                              "bearings (docs/physics.md section 14)", n, ACBB_MAX_SET);
    int dt = s->set_arrangement == ACBB_SET_DT;
    const acbb_set_kind *kind = &acbb_set_kinds[s->set_arrangement];
    if (s->set_n_bearings > 0 && (n < kind->n || n > kind->n_max))
        return acbb_error_set(err, ACBB_EINVAL, "set.n_bearings = %d with set.arrangement = %s: "
                              "%s has %s%d bearings (0 = the arrangement's count)", n, arr, arr,
                              kind->n < kind->n_max ? (snprintf(a, sizeof a, "%d to ", kind->n), a) : "",
                              kind->n_max);
    if (n == 1) return ACBB_OK;
    if (s->set_spacing > 0.0 && s->set_spacing < s->width)
        return acbb_error_set(err, ACBB_EINVAL, "set.spacing_mm = %s is shorter than "
                              "bearing.width_mm = %s: neighbouring bearings would overlap; the "
                              "centre distance is at least one width (0 = adjacent)",
                              show(s, "set", "spacing_mm", a), show(s, "bearing", "width_mm", b));
    acbb_status rc = rule_spacers(s, err);
    if (rc != ACBB_OK) return rc;
    if (dt && s->preload == ACBB_PRELOAD_DISPLACEMENT && s->axial_load == 0.0)
        return acbb_error_set(err, ACBB_ILL_POSED, "set.arrangement = DT with mounting.preload = "
                              "displacement and operating.axial_load_N = %s: a tandem set carries "
                              "thrust one way only; give it an axial load or a spring "
                              "(mounting.preload = force with preload_N > 0)",
                              show(s, "operating", "axial_load_N", c));
    if (!dt && s->preload_force <= 0.0)
        return acbb_error_set(err, ACBB_EINVAL, "set.arrangement = %s with mounting.preload_N = "
                              "%s: an opposed set needs a preload > 0 N (spacers or spring)", arr,
                              show(s, "mounting", "preload_N", a));
    if (dt && s->preload == ACBB_PRELOAD_FORCE && s->preload_force <= 0.0 && s->axial_load == 0.0)
        return acbb_error_set(err, ACBB_ILL_POSED, "set.arrangement = DT with mounting.preload = "
                              "force, preload_N = %s and operating.axial_load_N = 0: nothing loads "
                              "the tandem set; give a spring force or an axial load",
                              show(s, "mounting", "preload_N", a));
    return ACBB_OK;
}

/* A held tilt cannot take a moment (issue 18: the constraint is named). */
static acbb_status rule_tilt(const acbb_scene *s, acbb_error *err)
{
    if (s->tilt != ACBB_TILT_HELD || s->moment_load == 0.0) return ACBB_OK;
    char a[40];
    return acbb_error_set(err, ACBB_ILL_POSED, "operating.moment_load_Nm = %s with mounting.tilt "
                          "= held: a held ring takes no moment; use mounting.tilt = free",
                          show(s, "operating", "moment_load_Nm", a));
}

typedef acbb_status (*rule_fn)(const acbb_scene *, acbb_error *);

/* Order matters: ranges first (later rules divide by them), the grooves
 * before anything that uses the raceway diameters, ill-posedness last. */
static const rule_fn k_rules[] = {
    rule_ranges, rule_inner_groove, rule_outer_groove, rule_clearance, rule_balls_fit,
    rule_inner_ring, rule_outer_ring, rule_inner_land, rule_outer_land, rule_cage_diameter, rule_ring_width,
    rule_cage_width, rule_shaft_bore, rule_viscosity, rule_time_step, rule_temp_limit,
    rule_preload, rule_surroundings, rule_radial_load,
    rule_set, rule_tilt,
    acbb_sf_spindle_rules, /* [shaft] [housing] [motor] [spindle] (scene_rules_spindle.c) */
    acbb_schedule_validate, /* [schedule] rows, each at its operating point (schedule.c) */
};

acbb_status acbb_scene_validate(const acbb_scene *s, acbb_error *err)
{
    for (size_t i = 0; i < sizeof k_rules / sizeof k_rules[0]; i++) {
        acbb_status rc = k_rules[i](s, err);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

/* The end cap's keys differ from the defaults (only the 46-node network
 * has a cap, MODEL.md 8.1). */
static bool cap_set(const acbb_scene *s, const acbb_scene *d)
{
    return s->cap_od != d->cap_od || s->cap_thickness != d->cap_thickness
        || s->cap_bc.kind != d->cap_bc.kind || s->cap_bc.h != d->cap_bc.h
        || s->cap_bc.dT != d->cap_bc.dT;
}

/* The cage's elastic constants or expansion differ from the defaults. */
static bool cage_solid_set(const acbb_scene *s, const acbb_scene *d)
{
    return s->cage.E != d->cage.E || s->cage.nu != d->cage.nu || s->cage.chi != d->cage.chi;
}

/* Which switches a scene cannot feel (issue: every effect honest). Static
 * Hertz has no ball speeds, so no centrifugal force or gyroscopic moment;
 * WTE forces every expansion to zero (MODEL.md 9), the centrifugal ring
 * growth included; without heating the temperatures stay at ambient. The
 * 7-node network has no end cap; the heat partition phi_p is a 7-node
 * parameter (on the 46-node network the spot resistances split the
 * contact heat, MODEL.md 8.3). */
size_t acbb_scene_inactive_effects(const acbb_scene *s, acbb_inactive_effect *out, size_t cap)
{
    acbb_scene d;
    acbb_scene_default(&d);
    bool single = s->set_arrangement == ACBB_SET_SINGLE;
    const struct {
        bool when;
        acbb_inactive_effect e;
    } rows[] = {
        { s->model == ACBB_MODEL_STATIC && s->centrifugal,
          { "centrifugal", "fidelity.model = static has no ball speeds",
            "effects.centrifugal = on" } },
        { s->model == ACBB_MODEL_STATIC && s->gyroscopic,
          { "gyroscopic", "fidelity.model = static has no ball speeds",
            "effects.gyroscopic = on" } },
        { !s->thermal_expansion && s->ring_centrifugal,
          { "ring_centrifugal", "effects.thermal_expansion = off (WTE) zeroes every expansion",
            "effects.ring_centrifugal = on" } },
        { s->heating && s->network == ACBB_NET_7 && cap_set(s, &d),
          { "end_cap", "fidelity.network = 7 has no end cap (only the 46-node network does)",
            "surroundings.cap_*" } },
        { s->heating && s->network == ACBB_NET_46 && s->heat_partition != d.heat_partition,
          { "heat_partition", "the 46-node network splits the contact heat by its spot "
            "resistances; heat_partition applies to fidelity.network = 7 only "
            "(docs/physics.md section 8.3)",
            "thermal.heat_partition" } },
        { s->schedule_n > 0,
          { "operating point", "the [schedule] rows set the speed and the axial and radial "
            "loads (the steady solve uses the last row)",
            "operating.inner_speed_rpm, axial_load_N, radial_load_N" } },
        { cage_solid_set(s, &d),
          { "cage_solid", "the model has no cage mechanics or cage expansion "
            "(docs/physics.md section 7); only the cage's density, specific heat and conductivity "
            "enter (the network)",
            "the cage's E, Poisson ratio or expansion (materials.cage_*)" } },
        /* A loss on because the physics profile has it on is not the user's
         * input: no note when it finds nothing to do (physics_profile.h). */
        { s->loss_churning && s->lub_method != ACBB_LUB_OIL_BATH
              && s->lub_method != ACBB_LUB_OIL_JET
              && acbb_sf_profile_own(s, "effects", "loss_churning"),
          { "loss_churning", "oil-air and grease put no bulk oil in the bearing: churning needs "
            "lubricant.method = oil-bath or oil-jet (docs/physics.md section 16)",
            "effects.loss_churning = on" } },
        { s->roll_hyst == ACBB_ROLL_HYST_JOHNSON && s->hyst_axis != d.hyst_axis,
          { "hysteresis_axis", "fidelity.rolling_hysteresis = johnson uses the rolling-direction "
            "semi-axis; the axis choice applies to rolling_hysteresis = seed",
            "fidelity.hysteresis_axis" } },
        { s->loss_ehl_rolling && !s->ehl_film && acbb_sf_profile_own(s, "effects", "loss_ehl_rolling"),
          { "loss_ehl_rolling", "effects.ehl_film = off: no film, no EHL rolling resistance",
            "effects.loss_ehl_rolling = on" } },
        /* One bearing (issue 29 item 1): a force preload is the axial load
         * itself; a displacement preload holds the ring where preload_N put
         * it at rest, so the thrust goes to the fixture. A set uses both. */
        { single && s->preload == ACBB_PRELOAD_FORCE && s->preload_force != d.preload_force,
          { "preload_N", "mounting.preload = force: the axial load (operating.axial_load_N) "
            "preloads a single bearing; preload_N acts under mounting.preload = displacement",
            "mounting.preload_N" } },
        /* Not in a spindle: its nose thrust goes through the shaft to
         * the front set (a fixed rear shares it), whatever the preload. */
        { single && s->preload == ACBB_PRELOAD_DISPLACEMENT && s->axial_load != 0.0
              && s->shaft_segments == 0,
          { "axial_load", "mounting.preload = displacement holds the ring where "
            "mounting.preload_N put it at rest: the thrust goes to the fixture; the axial load "
            "acts under mounting.preload = force",
            "operating.axial_load_N" } },
    };
    size_t n = 0;
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        if (rows[i].when && n < cap) out[n++] = rows[i].e;
    return n + acbb_sf_spindle_inactive(s, &d, out + n, cap - n);
}

/* Does one name of an inactive row ("effects.centrifugal = on",
 * "surroundings.cap_*", "shaft.seg[4-8]_*", "axial_load_N" after a
 * sectioned first name) name the key "section.name"? Names are fnmatch
 * patterns. */
static bool names_key(const char *part, size_t len, const char *section, const char *key)
{
    const char *eq = memchr(part, ' ', len); /* drop " = on" */
    size_t n = eq ? (size_t)(eq - part) : len;
    char want[96];
    if (memchr(part, '.', n)) snprintf(want, sizeof want, "%s", key);
    else snprintf(want, sizeof want, "%s", strchr(key, '.') ? strchr(key, '.') + 1 : key);
    char pat[96];
    snprintf(pat, sizeof pat, "%.*s", (int)n, part);
    (void)section;
    return fnmatch(pat, want, 0) == 0;
}

bool acbb_scene_key_inactive(const acbb_scene *s, const char *key, acbb_inactive_effect *out)
{
    acbb_inactive_effect in[32];
    size_t n = acbb_scene_inactive_effects(s, in, 32);
    for (size_t i = 0; i < n; i++) {
        const char *p = in[i].key;
        while (*p) {
            size_t len = strcspn(p, ",");
            if (names_key(p, len, NULL, key)) {
                if (out) *out = in[i];
                return true;
            }
            p += len;
            while (*p == ',' || *p == ' ') p++;
        }
    }
    return false;
}

