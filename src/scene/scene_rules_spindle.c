/* acbb — the spindle's cross-field rules and unused keys (issue 31;
 * docs/spindle.md "Scene"). A scene is a spindle when shaft.segments >= 1;
 * [bearing], [set] and [mounting] are then its front set, the rear set is
 * of the same bearing. Every message names the keys, their values in
 * preset units and the reason, as scene_rules.c's do. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "acbb/tools/set.h"
#include "acbb/tools/surroundings.h"
#include "acbb/spindle.h"
#include "acbb/tools/scene_inactive.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"

#define show acbb_sf_show
#define FIT_TOL 1e-5     /* 0.01 mm: a ring's seat against the bearing's diameter */
#define POS_EPS 1e-9     /* m: positions closer than this coincide */

/* A stepped part: shaft (from the nose) or housing (from housing.x0_mm). */
typedef struct {
    const char *sec;
    const acbb_segment *seg;
    int n;
    double x0, x1;       /* its extent, m from the nose */
} part;

static part shaft_of(const acbb_scene *s)
{
    part p = { "shaft", s->shaft_seg, s->shaft_segments, 0.0, 0.0 };
    for (int i = 0; i < p.n; i++) p.x1 += p.seg[i].length;
    return p;
}

static part housing_of(const acbb_scene *s)
{
    part p = { "housing", s->housing_seg, s->housing_segments, s->housing_x0, s->housing_x0 };
    for (int i = 0; i < p.n; i++) p.x1 += p.seg[i].length;
    return p;
}

static bool inside(const part *p, double lo, double hi)
{
    return lo >= p->x0 - POS_EPS && hi <= p->x1 + POS_EPS;
}

/* Every segment up to `segments` given: length > 0, od > 0, bore < od. */
static acbb_status rule_segments(const acbb_scene *s, const part *p, acbb_error *err)
{
    char key[48], a[40], b[40], c[40];
    for (int i = 0; i < p->n; i++) {
        const acbb_segment *g = &p->seg[i];
        const char *what = !(g->length > 0.0) ? "length" : !(g->od > 0.0) ? "od" : NULL;
        if (what) {
            snprintf(key, sizeof key, "seg%d_%s_mm", i + 1, what);
            return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s with %s.segments = %d: segments "
                                  "1 to %d must each be given (%s > 0 mm)", p->sec, key,
                                  show(s, p->sec, key, a), p->sec, p->n, p->n, what);
        }
        if (g->bore < g->od) continue;
        snprintf(key, sizeof key, "seg%d_bore_mm", i + 1);
        snprintf(c, sizeof c, "seg%d_od_mm", i + 1);
        return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s with %s = %s: a segment's bore must "
                              "be smaller than its outer diameter", p->sec, key,
                              show(s, p->sec, key, a), c, show(s, p->sec, c, b));
    }
    return ACBB_OK;
}

/* The spindle's view holds ACBB_SPINDLE_MAX_CELLS cells of each part. */
static acbb_status rule_cells(const acbb_scene *s, const part *p, acbb_error *err)
{
    int cells = p->n * s->shaft_n_div;
    if (cells <= ACBB_SPINDLE_MAX_CELLS) return ACBB_OK;
    return acbb_error_set(err, ACBB_EINVAL, "shaft.n_div = %d with %s.segments = %d: %d cells "
                          "along the %s, at most %d (segments x n_div)", s->shaft_n_div, p->sec,
                          p->n, cells, p->sec, ACBB_SPINDLE_MAX_CELLS);
}

/* ---- the two sets ---- */

typedef struct {
    const char *name;    /* "front", "rear" */
    const char *key;     /* its x key in [spindle] */
    acbb_set_arrangement arr;
    int n;
    double x[ACBB_MAX_SET];   /* bearing centres, m from the nose */
    double lo, hi;            /* extent of its rings */
} station;

/* The front set is [set] at spindle.front_x_mm; the rear set is the same
 * bearing in spindle.rear_arrangement at rear_x_mm (acbb_set_layout on a
 * copy, so both follow the one layout rule). */
static station station_of(const acbb_scene *s, bool rear)
{
    acbb_scene t = *s;
    if (rear) {
        t.set_arrangement = s->spindle_rear_arrangement;
        t.set_spacing = s->spindle_rear_spacing;
        t.set_n_bearings = 0;
    }
    station st = { rear ? "rear" : "front", rear ? "rear_x_mm" : "front_x_mm",
                   t.set_arrangement, 0, { 0 }, 0, 0 };
    st.n = acbb_set_layout(&t, NULL, st.x);
    if (st.n > ACBB_MAX_SET) st.n = ACBB_MAX_SET;
    double c = rear ? s->spindle_rear_x : s->spindle_front_x;
    for (int k = 0; k < st.n; k++) st.x[k] += c;
    st.lo = st.x[0] - 0.5 * s->width;
    st.hi = st.x[st.n - 1] + 0.5 * s->width;
    return st;
}

/* The set's rings on the shaft and inside the housing. */
static acbb_status rule_station_room(const acbb_scene *s, const station *st, const part *p,
                                     acbb_error *err)
{
    if (inside(p, st->lo, st->hi)) return ACBB_OK;
    char a[40];
    return acbb_error_set(err, ACBB_EINVAL, "spindle.%s = %s: the %s set (%s, %d x "
                          "bearing.width_mm) spans %.6g to %.6g mm; the %s (%.6g to %.6g mm) must "
                          "hold it", st->key, show(s, "spindle", st->key, a), st->name,
                          acbb_set_arrangement_name(st->arr), st->n, st->lo * 1e3, st->hi * 1e3,
                          p->sec, p->x0 * 1e3, p->x1 * 1e3);
}

/* Under each ring the seat's diameter equals the bearing's: the shaft's
 * od = bearing.bore_mm (inner rings), the housing's bore =
 * bearing.outer_diameter_mm (outer rings), within 0.01 mm. */
static acbb_status rule_seat(const acbb_scene *s, const station *st, const part *p, bool outer,
                             acbb_error *err)
{
    double want = outer ? s->outer_diameter : s->bore, x = p->x0;
    for (int i = 0; i < p->n; x += p->seg[i].length, i++) {
        double have = outer ? p->seg[i].bore : p->seg[i].od;
        for (int k = 0; k < st->n; k++) {
            double lo = st->x[k] - 0.5 * s->width, hi = st->x[k] + 0.5 * s->width;
            bool under = x < hi - POS_EPS && x + p->seg[i].length > lo + POS_EPS;
            if (!under || fabs(have - want) <= FIT_TOL * (1.0 + 1e-9)) continue;
            char key[48], a[40], b[40];
            snprintf(key, sizeof key, "seg%d_%s_mm", i + 1, outer ? "bore" : "od");
            const char *bkey = outer ? "outer_diameter_mm" : "bore_mm";
            return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s at the %s set's bearing %d "
                                  "(centre %.6g mm) with bearing.%s = %s: the %s rings sit %s "
                                  "the %s, so its %s there must equal the bearing's %s (within "
                                  "0.01 mm)", p->sec, key, show(s, p->sec, key, a), st->name,
                                  k + 1, st->x[k] * 1e3, bkey, show(s, "bearing", bkey, b),
                                  outer ? "outer" : "inner", outer ? "in" : "on", p->sec,
                                  outer ? "bore" : "outer diameter",
                                  outer ? "outer diameter" : "bore");
        }
    }
    return ACBB_OK;
}

/* Opposed: carries thrust both ways (DB, DF, DBT, QBC). */
static bool opposed(acbb_set_arrangement a)
{
    const char *o = acbb_set_kinds[a].orient;
    return strchr(o, '+') && strchr(o, '-');
}

/* With a spring or floating rear, the front set alone locates the shaft
 * axially: it must carry thrust both ways. A fixed rear locates it too, so
 * any front set is accepted then. */
static acbb_status rule_front_locates(const acbb_scene *s, acbb_error *err)
{
    if (s->spindle_rear_support == ACBB_REAR_FIXED || opposed(s->set_arrangement)) return ACBB_OK;
    char a[40];
    return acbb_error_set(err, ACBB_EINVAL, "set.arrangement = %s with spindle.rear_support = "
                          "%s: the front set is then the shaft's only axial location and must "
                          "carry thrust both ways (DB, DF, DBT or QBC), or use "
                          "spindle.rear_support = fixed",
                          acbb_set_arrangement_name(s->set_arrangement),
                          show(s, "spindle", "rear_support", a));
}

static acbb_status rule_rear(const acbb_scene *s, acbb_error *err)
{
    char a[40], b[40];
    if (s->spindle_rear_support == ACBB_REAR_SPRING && !(s->spindle_rear_spring > 0.0))
        return acbb_error_set(err, ACBB_EINVAL, "spindle.rear_support = spring with "
                              "rear_spring_N = %s: the springs must push (rear_spring_N > 0 N), "
                              "or use rear_support = floating",
                              show(s, "spindle", "rear_spring_N", a));
    if (s->spindle_rear_spacing > 0.0 && s->spindle_rear_spacing < s->width)
        return acbb_error_set(err, ACBB_EINVAL, "spindle.rear_spacing_mm = %s is shorter than "
                              "bearing.width_mm = %s: neighbouring rear bearings would overlap; "
                              "the centre distance is at least one width (0 = adjacent)",
                              show(s, "spindle", "rear_spacing_mm", a),
                              show(s, "bearing", "width_mm", b));
    bool across = s->spindle_rear_support == ACBB_REAR_FIXED && !opposed(s->set_arrangement)
               && !opposed(s->spindle_rear_arrangement);
    if (across && !(s->spindle_rear_preload > 0.0))
        return acbb_error_set(err, ACBB_EINVAL, "set.arrangement = %s, spindle.rear_arrangement "
                              "= %s, rear_support = fixed, rear_preload_N = %s: the two one-way "
                              "sets face each other (an \"O\" spindle, the rear set turned "
                              "round) and locate the shaft only when preloaded against each "
                              "other: rear_preload_N > 0 N",
                              acbb_set_arrangement_name(s->set_arrangement),
                              acbb_set_arrangement_name(s->spindle_rear_arrangement),
                              show(s, "spindle", "rear_preload_N", a));
    if (opposed(s->spindle_rear_arrangement) && !(s->spindle_rear_preload > 0.0))
        return acbb_error_set(err, ACBB_EINVAL, "spindle.rear_arrangement = %s with "
                              "rear_preload_N = %s: an opposed rear set needs a preload > 0 N "
                              "(its spacers)", acbb_set_arrangement_name(s->spindle_rear_arrangement),
                              show(s, "spindle", "rear_preload_N", a));
    return ACBB_OK;
}

/* Where the two sets sit: front nearer the nose, each on the shaft and in
 * the housing, apart, and each ring on its seat. */
static acbb_status rule_stations(const acbb_scene *s, const part *sh, const part *ho,
                                 acbb_error *err)
{
    char a[40], b[40];
    if (!(s->spindle_front_x < s->spindle_rear_x))
        return acbb_error_set(err, ACBB_EINVAL, "spindle.front_x_mm = %s with rear_x_mm = %s: "
                              "the front set must be nearer the nose (front_x_mm < rear_x_mm)",
                              show(s, "spindle", "front_x_mm", a),
                              show(s, "spindle", "rear_x_mm", b));
    station st[2] = { station_of(s, false), station_of(s, true) };
    if (st[0].hi > st[1].lo + POS_EPS)
        return acbb_error_set(err, ACBB_EINVAL, "spindle.front_x_mm = %s with rear_x_mm = %s: "
                              "the front set reaches %.6g mm, past the rear set's start at %.6g "
                              "mm: the sets overlap", show(s, "spindle", "front_x_mm", a),
                              show(s, "spindle", "rear_x_mm", b), st[0].hi * 1e3, st[1].lo * 1e3);
    for (int i = 0; i < 2; i++) {
        acbb_status rc = rule_station_room(s, &st[i], sh, err);
        if (rc == ACBB_OK) rc = rule_station_room(s, &st[i], ho, err);
        if (rc == ACBB_OK) rc = rule_seat(s, &st[i], sh, false, err);
        if (rc == ACBB_OK) rc = rule_seat(s, &st[i], ho, true, err);
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

/* The segment of a part under x (-1: none). */
static int segment_at(const part *p, double x)
{
    double a = p->x0;
    for (int i = 0; i < p->n; a += p->seg[i].length, i++)
        if (x >= a - POS_EPS && x <= a + p->seg[i].length + POS_EPS) return i;
    return -1;
}

/* The bearing's own model of its shaft and housing (mounting.shaft_bore_mm
 * for the fits and the shaft's conduction, the [surroundings] housing's
 * outer diameter for its housing network) is the spindle's at the front
 * set's centre, within 0.01 mm: both sets take these values. */
static acbb_status rule_front_model(const acbb_scene *s, const part *sh, const part *ho,
                                    acbb_error *err)
{
    int i = segment_at(sh, s->spindle_front_x), j = segment_at(ho, s->spindle_front_x);
    acbb_surroundings u;
    acbb_scene_surroundings(s, &u);
    char key[48], a[40], b[40];
    if (i >= 0 && fabs(s->shaft_bore - sh->seg[i].bore) > FIT_TOL * (1.0 + 1e-9)) {
        snprintf(key, sizeof key, "seg%d_bore_mm", i + 1);
        return acbb_error_set(err, ACBB_EINVAL, "mounting.shaft_bore_mm = %s with shaft.%s = %s "
                              "under the front set: the bearings' fits and shaft conduction use "
                              "mounting.shaft_bore_mm (0 = solid), so it must be the spindle "
                              "shaft's bore there (within 0.01 mm)",
                              show(s, "mounting", "shaft_bore_mm", a), key,
                              show(s, "shaft", key, b));
    }
    if (j >= 0 && fabs(u.housing_od - ho->seg[j].od) > FIT_TOL * (1.0 + 1e-9)) {
        snprintf(key, sizeof key, "seg%d_od_mm", j + 1);
        return acbb_error_set(err, ACBB_EINVAL, "surroundings.housing_outer_diameter_mm = %s "
                              "(%.6g mm) with housing.%s = %s under the front set: the bearings' "
                              "housing network uses the [surroundings] housing, so its outer "
                              "diameter must be the spindle housing's there (within 0.01 mm)",
                              show(s, "surroundings", "housing_outer_diameter_mm", a),
                              u.housing_od * 1e3, key, show(s, "housing", key, b));
    }
    return ACBB_OK;
}

/* A span x0..x1 (motor, jacket): x1 >= x0 (equal: absent), and when
 * present on the parts that carry it. */
static acbb_status rule_span(const acbb_scene *s, const char *sec, const char *k0,
                             const char *k1, const char *what, const part *on[2], acbb_error *err)
{
    char a[40], b[40];
    const acbb_sfield *f0 = acbb_sf_find(sec, k0), *f1 = acbb_sf_find(sec, k1);
    double x0 = acbb_sf_get_real(s, f0), x1 = acbb_sf_get_real(s, f1);
    if (x1 < x0)
        return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s with %s = %s: the %s's rear end "
                              "must not lie in front of its front end (%s >= %s; equal: no %s)",
                              sec, k1, show(s, sec, k1, a), k0, show(s, sec, k0, b), what, k1, k0,
                              what);
    for (int i = 0; i < 2 && x1 > x0; i++)
        if (on[i] && !inside(on[i], x0, x1))
            return acbb_error_set(err, ACBB_EINVAL, "%s.%s = %s, %s = %s: the %s (%.6g to "
                                  "%.6g mm) must lie on the %s (%.6g to %.6g mm)", sec, k0,
                                  show(s, sec, k0, a), k1, show(s, sec, k1, b), what, x0 * 1e3,
                                  x1 * 1e3, on[i]->sec, on[i]->x0 * 1e3, on[i]->x1 * 1e3);
    return ACBB_OK;
}

static acbb_status rule_motor(const acbb_scene *s, const part *sh, const part *ho,
                              acbb_error *err)
{
    const part *on[2] = { sh, ho };
    acbb_status rc = rule_span(s, "motor", "x0_mm", "x1_mm", "motor", on, err);
    if (rc != ACBB_OK || s->motor_x1 > s->motor_x0) return rc;
    const char *key = s->motor_rotor_loss > 0.0 ? "rotor_loss_W"
                    : s->motor_stator_loss > 0.0 ? "stator_loss_W" : NULL;
    char a[40], b[40], c[40];
    if (!key) return ACBB_OK;
    return acbb_error_set(err, ACBB_EINVAL, "motor.%s = %s with x0_mm = %s, x1_mm = %s: the "
                          "losses need the motor's span (x1_mm > x0_mm)", key,
                          show(s, "motor", key, a), show(s, "motor", "x0_mm", b),
                          show(s, "motor", "x1_mm", c));
}

static acbb_status rule_coolant(const acbb_scene *s, const part *ho, acbb_error *err)
{
    const part *on[2] = { ho, NULL };
    acbb_status rc = rule_span(s, "spindle", "jacket_x0_mm", "jacket_x1_mm", "jacket", on, err);
    if (rc != ACBB_OK || !(s->coolant_flow > 0.0)) return rc;
    char a[40], b[40], c[40];
    const char *flow = show(s, "spindle", "coolant_flow_l_min", a);
    if (!(s->jacket_x1 > s->jacket_x0))
        return acbb_error_set(err, ACBB_EINVAL, "spindle.coolant_flow_l_min = %s with "
                              "jacket_x0_mm = %s, jacket_x1_mm = %s: coolant needs a jacket "
                              "(jacket_x1_mm > jacket_x0_mm)", flow,
                              show(s, "spindle", "jacket_x0_mm", b),
                              show(s, "spindle", "jacket_x1_mm", c));
    if (!(s->jacket_hA > 0.0))
        return acbb_error_set(err, ACBB_EINVAL, "spindle.coolant_flow_l_min = %s with "
                              "jacket_hA_W_K = 0: the jacket wall must pass heat (jacket_hA_W_K "
                              "> 0 W/K: film coefficient times wetted area)", flow);
    if (s->ambient_C + s->coolant_inlet_dT < s->temp_limit_C) return ACBB_OK;
    return acbb_error_set(err, ACBB_EINVAL, "spindle.coolant_inlet_dT_K = %s with "
                          "operating.ambient_C = %s: the coolant (%.4g C) must be below "
                          "thermal.temp_limit_C = %.4g C", show(s, "spindle", "coolant_inlet_dT_K", b),
                          show(s, "operating", "ambient_C", c), s->ambient_C + s->coolant_inlet_dT,
                          s->temp_limit_C);
}

acbb_status acbb_sf_spindle_rules(const acbb_scene *s, acbb_error *err)
{
    if (s->shaft_segments == 0) return ACBB_OK;
    char a[40];
    if (s->housing_segments == 0)
        return acbb_error_set(err, ACBB_EINVAL, "shaft.segments = %s with housing.segments = 0: "
                              "a spindle needs a housing (housing.segments >= 1)",
                              show(s, "shaft", "segments", a));
    /* the shaft beam's range (shaft_section.c: E in [1e8, 1e13] Pa), the
     * schema's upper bound kept */
    if (!(s->shaft.E >= 1e8))
        return acbb_error_set(err, ACBB_EINVAL, "materials.shaft_E_GPa = %s with shaft.segments "
                              "= %d: a spindle's shaft is a beam whose Young's modulus must be in "
                              "[0.1, 1000] GPa", show(s, "materials", "shaft_E_GPa", a),
                              s->shaft_segments);
    part sh = shaft_of(s), ho = housing_of(s);
    acbb_status rc = rule_segments(s, &sh, err);
    if (rc == ACBB_OK) rc = rule_segments(s, &ho, err);
    if (rc == ACBB_OK) rc = rule_cells(s, &sh, err);
    if (rc == ACBB_OK) rc = rule_cells(s, &ho, err);
    if (rc == ACBB_OK) rc = rule_rear(s, err);
    if (rc == ACBB_OK) rc = rule_front_locates(s, err);
    if (rc == ACBB_OK) rc = rule_stations(s, &sh, &ho, err);
    if (rc == ACBB_OK) rc = rule_front_model(s, &sh, &ho, err);
    if (rc == ACBB_OK) rc = rule_motor(s, &sh, &ho, err);
    if (rc == ACBB_OK) rc = rule_coolant(s, &ho, err);
    return rc;
}

/* ---- keys that do nothing in this scene ---- */

/* Some key of `sec` (other than `but`) differs from the default. */
static bool section_set(const acbb_scene *s, const acbb_scene *d, const char *sec, const char *but)
{
    for (size_t i = 0; i < acbb_sf_n; i++) {
        const acbb_field_info *in = &acbb_sf_table[i].info;
        if (strcmp(in->section, sec) != 0 || (but && strcmp(in->key, but) == 0)) continue;
        char v[64], w[64];
        acbb_scene_field_format(s, i, v, sizeof v);
        acbb_scene_field_format(d, i, w, sizeof w);
        if (strcmp(v, w) != 0) return true;
    }
    return false;
}

/* A segment past `segments` holds a value. */
static bool beyond_set(const acbb_segment *g, int n)
{
    for (int i = n; i < ACBB_SPINDLE_MAX_SEG; i++)
        if (g[i].length != 0.0 || g[i].od != 0.0 || g[i].bore != 0.0) return true;
    return false;
}

/* Key patterns (fnmatch) of the segments past a count, by the count. */
static const char *const k_beyond[2][ACBB_SPINDLE_MAX_SEG] = {
    { "shaft.seg[1-8]_*", "shaft.seg[2-8]_*", "shaft.seg[3-8]_*", "shaft.seg[4-8]_*",
      "shaft.seg[5-8]_*", "shaft.seg[6-8]_*", "shaft.seg[7-8]_*", "shaft.seg8_*" },
    { "housing.seg[1-8]_*", "housing.seg[2-8]_*", "housing.seg[3-8]_*", "housing.seg[4-8]_*",
      "housing.seg[5-8]_*", "housing.seg[6-8]_*", "housing.seg[7-8]_*", "housing.seg8_*" },
};
_Static_assert(ACBB_SPINDLE_MAX_SEG == 8, "k_beyond lists 8 segments");

static const char *beyond_key(int part, int n)
{
    return n >= 0 && n < ACBB_SPINDLE_MAX_SEG ? k_beyond[part][n] : "";
}

static bool changed(const acbb_scene *s, const acbb_scene *d, const char *sec, const char *key)
{
    const acbb_sfield *f = acbb_sf_find(sec, key);
    return f && acbb_sf_get_real(s, f) != acbb_sf_get_real(d, f);
}

/* Coolant keys other than the flow differ from the defaults. */
static bool coolant_set(const acbb_scene *s, const acbb_scene *d)
{
    return s->coolant_inlet_dT != d->coolant_inlet_dT || s->coolant_rho != d->coolant_rho
        || s->coolant_cp != d->coolant_cp || s->coolant_cells != d->coolant_cells
        || s->jacket_x0 != d->jacket_x0 || s->jacket_x1 != d->jacket_x1
        || s->jacket_hA != d->jacket_hA;
}

size_t acbb_sf_spindle_inactive(const acbb_scene *s, const acbb_scene *d,
                                acbb_inactive_effect *out, size_t cap)
{
    bool sp = s->shaft_segments > 0;
    int nh = s->housing_segments;
    const struct {
        bool when;
        acbb_inactive_effect e;
    } rows[] = {
        { !sp && (section_set(s, d, "shaft", "segments") || section_set(s, d, "housing", NULL)
                  || section_set(s, d, "motor", NULL) || section_set(s, d, "spindle", NULL)),
          { "spindle", "shaft.segments = 0 is no spindle; the [shaft], [housing], [motor] and "
            "[spindle] keys act when shaft.segments >= 1 (docs/spindle.md)",
            "shaft.seg*_mm, shaft.n_div, shaft.end_film_W_m2K, housing.*, motor.*, spindle.*" } },
        { sp && s->shaft_segments < ACBB_SPINDLE_MAX_SEG
              && beyond_set(s->shaft_seg, s->shaft_segments),
          { "shaft segments", "past shaft.segments: only segments 1 to shaft.segments make the "
            "shaft", beyond_key(0, s->shaft_segments) } },
        { sp && nh >= 0 && nh < ACBB_SPINDLE_MAX_SEG && beyond_set(s->housing_seg, nh),
          { "housing segments", "past housing.segments: only segments 1 to housing.segments "
            "make the housing", beyond_key(1, nh) } },
        { sp && s->spindle_rear_support != ACBB_REAR_SPRING
              && changed(s, d, "spindle", "rear_spring_N"),
          { "rear_spring_N", "the springs push under spindle.rear_support = spring only",
            "spindle.rear_spring_N" } },
        { sp && s->spindle_rear_support != ACBB_REAR_FLOATING
              && changed(s, d, "spindle", "rear_friction_N"),
          { "rear_friction_N", "the sleeve slides under spindle.rear_support = floating only",
            "spindle.rear_friction_N" } },
        { sp && !opposed(s->spindle_rear_arrangement)
              && s->spindle_rear_support != ACBB_REAR_FIXED
              && changed(s, d, "spindle", "rear_preload_N"),
          { "rear_preload_N", "a one-way rear set (single, DT) that is not fixed has no "
            "preload; rear_preload_N acts on a DB, DF, DBT or QBC rear set, or on a fixed "
            "one-way rear set (preloaded against the front)", "spindle.rear_preload_N" } },
        { sp && s->spindle_rear_arrangement == ACBB_SET_SINGLE
              && changed(s, d, "spindle", "rear_spacing_mm"),
          { "rear_spacing_mm", "spindle.rear_arrangement = single: one rear bearing has no "
            "neighbour to space", "spindle.rear_spacing_mm" } },
        { sp && s->coolant_flow == 0.0 && coolant_set(s, d),
          { "coolant", "spindle.coolant_flow_l_min = 0: no coolant flows",
            "spindle.coolant_inlet_dT_K, coolant_density_kg_m3, coolant_cp_J_kgK, coolant_cells, "
            "jacket_*" } },
        { sp && !(s->motor_x1 > s->motor_x0) && changed(s, d, "motor", "gap_conductance_W_K"),
          { "motor gap", "motor.x1_mm = x0_mm: no motor, no air gap", "motor.gap_conductance_W_K" } },
        { sp && s->set_load_offset != d->set_load_offset,
          { "load_offset", "in a spindle the loads act at the nose (x = 0); set.load_offset_mm "
            "places them for a set on a rigid shaft", "set.load_offset_mm" } },
    };
    size_t n = 0;
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        if (rows[i].when && n < cap) out[n++] = rows[i].e;
    return n;
}

/* ---- keys that are no input of this scene (sensitivity) ---- */

static bool is(const acbb_field_info *f, const char *sec, const char *key)
{
    return strcmp(f->section, sec) == 0 && (!key || strcmp(f->key, key) == 0);
}

/* A key of the spindle's parts that this spindle does not have: varying
 * it changes nothing, or makes the scene one the rules refuse (a coolant
 * flow without a jacket, motor losses without a span). */
static bool part_missing(const acbb_scene *s, const acbb_field_info *f)
{
    bool motor = s->motor_x1 > s->motor_x0, coolant = s->coolant_flow > 0.0;
    acbb_rear_support rear = s->spindle_rear_support;
    if (is(f, "motor", NULL)) return !motor && !is(f, "motor", "x0_mm") && !is(f, "motor", "x1_mm");
    if (!is(f, "spindle", NULL)) return false;
    if (strncmp(f->key, "coolant_", 8) == 0 || strncmp(f->key, "jacket_", 7) == 0)
        return !coolant;
    if (is(f, "spindle", "rear_spring_N")) return rear != ACBB_REAR_SPRING;
    if (is(f, "spindle", "rear_friction_N")) return rear != ACBB_REAR_FLOATING;
    if (is(f, "spindle", "rear_preload_N"))
        return !opposed(s->spindle_rear_arrangement) && rear != ACBB_REAR_FIXED;
    if (is(f, "spindle", "rear_spacing_mm")) return s->spindle_rear_arrangement == ACBB_SET_SINGLE;
    return false;
}

/* A bearing key a spindle replaces: the bearing's films to the ambient
 * and its shaft bore's coolant go, the spindle's housing and shaft have
 * their own (docs/spindle.md "Joining the bearings' networks"). */
static bool replaced(const acbb_scene *s, const acbb_field_info *f)
{
    return s->shaft_segments > 0 && (is(f, "mounting", "h_natural_W_m2K")
                                     || (is(f, "surroundings", NULL)
                                         && strncmp(f->key, "shaft_bore", 10) == 0));
}

bool acbb_scene_field_unused(const acbb_scene *s, size_t i)
{
    if (i >= acbb_sf_n) return false;
    const acbb_field_info *f = &acbb_sf_table[i].info;
    if (replaced(s, f)) return true;
    if (!is(f, "shaft", NULL) && !is(f, "housing", NULL) && !is(f, "motor", NULL)
        && !is(f, "spindle", NULL))
        return false;
    return s->shaft_segments == 0 || part_missing(s, f);
}
