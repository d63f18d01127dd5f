/* Sensitivity (include/acbb/tools/sensitivity.h): metric lookup by JSON path,
 * the plausible ranges in the schema, one-at-a-time flips against direct
 * runs, Morris elementary effects (an input with no effect gets mu* = 0
 * exactly), option errors. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/sensitivity.h"
#include "acbb/tools/study.h"
#include "acbb/units.h"
#include "acbb/tools/scene_schema.h"
#include <gsl/gsl_errno.h>
#include "tap.h"

static void test_metrics(void)
{
    static acbb_snapshot s;
    memset(&s, 0, sizeof s);
    s.n_balls = 3;
    s.losses.total = 54.5;
    s.losses.P[ACBB_LOSS_SPIN] = 15.25;
    s.T_outer_ring = 34.75;
    s.squeeze.net = -0.46e-6;
    s.stiffness_axial = 62.5e6;
    s.balls[2].Qi = 143.5;
    s.balls[1].alpha_o = 15.0 * ACBB_DEG;
    double v = NAN;
    acbb_error err = {{0}};
    ok(acbb_metric_value(&s, "losses_W.total", &v, &err) == ACBB_OK && v == 54.5,
       "losses_W.total read");
    ok(acbb_metric_value(&s, "losses_W.spin", &v, &err) == ACBB_OK && v == 15.25,
       "losses_W.spin: a loss of the loss table by name");
    ok(acbb_metric_value(&s, "temperature_C.outer_ring", &v, &err) == ACBB_OK && v == 34.75,
       "temperature_C.outer_ring read");
    is_close(acbb_metric_value(&s, "squeeze_um.net", &v, &err) == ACBB_OK ? v : NAN, -0.46,
             1e-12, 0, "squeeze_um.net in um as the JSON");
    is_close(acbb_metric_value(&s, "ring.stiffness_axial_N_per_um", &v, &err) == ACBB_OK ? v : NAN,
             62.5, 1e-12, 0, "stiffness in N/um as the JSON");
    ok(acbb_metric_value(&s, "balls[2].Qi_N", &v, &err) == ACBB_OK && v == 143.5,
       "balls[2].Qi_N read from ball 2");
    is_close(acbb_metric_value(&s, "balls[1].alpha_o_deg", &v, &err) == ACBB_OK ? v : NAN, 15.0,
             1e-12, 0, "balls[1].alpha_o_deg in degrees");
    ok(acbb_metric_value(&s, "balls[3].Qi_N", &v, &err) == ACBB_EINVAL &&
       strstr(err.msg, "0..2"), "ball index past n_balls refused with the range: %s", err.msg);
    ok(acbb_metric_check("losses_W.totl", &err) == ACBB_EINVAL && strstr(err.msg, "unknown"),
       "unknown metric refused: %s", err.msg);
    ok(acbb_metric_check("balls[0].Qx_N", &err) == ACBB_EINVAL, "unknown ball field refused");
    ok(acbb_metric_check("balls[x].Qi_N", &err) == ACBB_EINVAL, "malformed ball index refused");
    char name[64];
    size_t n = 0, with_ball = 0;
    while (acbb_metric_name(n, name, sizeof name)) {
        with_ball += strncmp(name, "balls[i].", 9) == 0;
        n++;
    }
    ok(n > 30 && with_ball > 10, "metric names listed (%zu, %zu per ball)", n, with_ball);
}

/* Every plausible range sits inside the key's validation range, has a
 * source, and holds the default (the ranges are around MODEL.md's values). */
static void test_ranges(void)
{
    acbb_scene sc;
    acbb_scene_default(&sc);
    size_t n = acbb_scene_field_count(), k = 0, bad = 0, used = 0;
    for (size_t i = 0; i < n; i++) {
        const acbb_field_info *f = acbb_scene_field(i);
        if (!f->plaus_src) continue;
        k++;
        used += !acbb_scene_field_unused(&sc, i); /* a spindle key: no spindle here */
        int in = f->plaus_lo < f->plaus_hi && f->plaus_lo >= f->min && f->plaus_hi <= f->max &&
                 !(f->min_open && f->plaus_lo == f->min) && f->plaus_src[0];
        if (!in) printf("#   %s.%s [%g, %g]\n", f->section, f->key, f->plaus_lo, f->plaus_hi);
        bad += !in;
    }
    ok(k >= 20 && bad == 0, "%zu uncertain inputs, each range inside its validation range", k);
    acbb_sens_input in[ACBB_SENS_MAX];
    size_t m = acbb_sens_inputs(&sc, in, ACBB_SENS_MAX);
    size_t dflt_inside = 0;
    for (size_t i = 0; i < m; i++) {
        acbb_scene t = sc;
        acbb_error err = {{0}};
        char lo[64], hi[64];
        acbb_sens_apply(&t, &in[i], 0.0, &err);
        acbb_scene_field_format(&t, in[i].field, lo, sizeof lo);
        acbb_sens_apply(&t, &in[i], 1.0, &err);
        acbb_scene_field_format(&t, in[i].field, hi, sizeof hi);
        const acbb_field_info *f = acbb_scene_field(in[i].field);
        double b = atof(in[i].base);
        dflt_inside += f->type == ACBB_FIELD_ENUM ? strcmp(lo, in[i].base) == 0
                       : strcmp(lo, in[i].lo) == 0 && strcmp(hi, in[i].hi) == 0 &&
                         b >= f->plaus_lo && b <= f->plaus_hi;
    }
    ok(m == used && dflt_inside == m,
       "apply sets the ends exactly; every default lies in its range (%zu/%zu)", dflt_inside, m);
    char text[320];
    for (size_t i = 0; i < n; i++)
        if (strcmp(acbb_scene_field(i)->key, "boundary_friction") == 0)
            acbb_scene_field_plausible(i, text, sizeof text);
    has_substr(text, "[0.08, 0.13]; docs/physics.md section 5 ASSUMED 0.08-0.13",
               "boundary friction's range and source as text");
}

static const acbb_sens_row *row_of(const acbb_sens_result *r, const char *key)
{
    for (size_t i = 0; i < r->n; i++)
        if (strcmp(r->rows[i].in.key, key) == 0) return &r->rows[i];
    return NULL;
}

/* Qi(TE) - Qi(WTE) of ball 0 by two direct runs, each the steady solve
 * as the analysis runs it (sensitivity.h). */
static double direct_delta(const acbb_scene *base, const char *key, const char *value)
{
    double q[2] = {NAN, NAN};
    for (int te = 0; te < 2; te++) {
        acbb_scene sc = *base;
        acbb_error err = {{0}};
        sc.thermal_expansion = te == 0;
        sc.thermal_mode = ACBB_THERMAL_STEADY;
        if (key && acbb_scene_set(&sc, key, value, &err) != ACBB_OK) return NAN;
        acbb_sim *sim = NULL;
        if (acbb_sim_create(&sc, NULL, &sim, &err) != ACBB_OK) return NAN;
        acbb_sim_drive(sim, NULL);
        static acbb_snapshot snap;
        acbb_sim_snapshot(sim, &snap);
        if (snap.state == ACBB_RUN_CONVERGED) q[te] = snap.balls[0].Qi;
        acbb_sim_free(sim);
    }
    return q[0] - q[1];
}

/* MODEL.md 13: at 1000 N, 15000 rpm Qi(TE) < Qi(WTE) by a sub-micron
 * margin, and a convective shaft bore (h 500) turns it (about +4.6 %). */
static void test_oat_flip(void)
{
    acbb_scene sc;
    acbb_scene_default(&sc);
    acbb_sens_opts o = {.metric = "balls[0].Qi_N", .delta_te = 1, .oat = 1, .jobs = 2};
    static acbb_sens_result r;
    acbb_error err = {{0}};
    acbb_status st = acbb_sensitivity_run(&sc, &o, &r, &err);
    ok(st == ACBB_OK && r.ok0 && r.failed == 0, "OAT of Qi TE-WTE runs (%s)", err.msg);
    is_close(r.y0, direct_delta(&sc, NULL, NULL), 1e-12, 1e-12,
             "base value = Qi(TE) - Qi(WTE) of two direct runs");
    ok(r.y0 < 0, "base: Qi(TE) < Qi(WTE) at 1000 N (%.4g N)", r.y0);
    const acbb_sens_row *b = row_of(&r, "surroundings.shaft_bore");
    ok(b && b->flips && b->ok_hi && b->y_hi > 0, "convective shaft bore flips the sign");
    if (b) {
        is_close(b->y_hi, direct_delta(&sc, "surroundings.shaft_bore", "convective"), 1e-12,
                 1e-12, "its value = two direct runs with a convective bore");
        is_close(b->y_lo, r.y0, 0, 0, "its low end (fixed, the scene's) is the base value");
    }
    const acbb_sens_row *fit = row_of(&r, "mounting.h_fit_outer_W_m2K");
    ok(fit && !fit->flips && fit->y_lo < 0 && fit->y_hi < 0,
       "outer fit conductance 1e3..2e4 keeps the sign");
    int sorted = 1, flips_ok = 1;
    for (size_t i = 0; i < r.n; i++) {
        const acbb_sens_row *w = &r.rows[i];
        if (i && w->effect > r.rows[i - 1].effect) sorted = 0;
        int f = (w->ok_lo && w->y_lo * r.y0 < 0) || (w->ok_hi && w->y_hi * r.y0 < 0);
        double e = fmax(w->ok_lo ? fabs(w->y_lo - r.y0) : 0, w->ok_hi ? fabs(w->y_hi - r.y0) : 0);
        if (f != w->flips || e != w->effect) flips_ok = 0;
    }
    ok(sorted, "rows sorted by effect, largest first");
    const acbb_sens_row *cap = row_of(&r, "surroundings.cap_h_W_m2K");
    ok(cap && cap->effect == 0.0, "cap film with the cap fixed: no effect one at a time");
    ok(flips_ok, "every row's flag and effect follow from its end values");
    ok(r.runs > 2 * r.n && r.runs <= 2 * (1 + 2 * r.n), "%zu runs: ends equal to the scene's "
       "value are not rerun", r.runs);
}

/* The relative mode (delta_rel) is (TE - WTE) / |WTE| of the same two runs,
 * and the study's threshold conditions use it (items 3, 9, 14). */
static void test_relative(void)
{
    acbb_scene sc;
    acbb_scene_default(&sc);
    acbb_sens_opts o = {.metric = "balls[0].Qi_N", .delta_te = 1, .jobs = 2};
    double d = NAN, r = NAN;
    acbb_status st = acbb_sens_eval(&sc, 1, &o, &d, NULL, 0, NULL);
    o.delta_rel = 1;
    if (st == ACBB_OK) st = acbb_sens_eval(&sc, 1, &o, &r, NULL, 0, NULL);
    double want = direct_delta(&sc, NULL, NULL);
    ok(st == ACBB_OK, "relative TE effect evaluated");
    is_close(d, want, 1e-12, 1e-12, "absolute mode: Qi(TE) - Qi(WTE)");
    acbb_scene w = sc;
    w.thermal_expansion = false;
    w.thermal_mode = ACBB_THERMAL_STEADY;
    acbb_sim *sim = NULL;
    static acbb_snapshot snap;
    acbb_error err = {{0}};
    double qw = NAN;
    if (acbb_sim_create(&w, NULL, &sim, &err) == ACBB_OK && acbb_sim_drive(sim, NULL) == ACBB_OK) {
        acbb_sim_snapshot(sim, &snap);
        qw = snap.balls[0].Qi;
    }
    acbb_sim_free(sim);
    is_close(r, d / fabs(qw), 1e-9, 0, "relative mode: (TE - WTE) / |WTE| of a direct WTE run");
    size_t n;
    const acbb_study_sign *sg = acbb_study_signs(&n);
    int rel = 0;
    for (size_t k = 0; k < n; k++) rel += sg[k].rel;
    ok(rel >= 6, "the study checks %d relative-threshold conditions (items 3, 9, 14)", rel);
}

static void test_morris(void)
{
    acbb_scene sc;
    acbb_scene_default(&sc);
    sc.axial_load = 200;
    acbb_sens_opts o = {.metric = "losses_W.total", .morris_r = 3, .jobs = 2, .seed = 7};
    static acbb_sens_result r, r2;
    acbb_error err = {{0}};
    acbb_status st = acbb_sensitivity_run(&sc, &o, &r, &err);
    ok(st == ACBB_OK && r.failed == 0, "Morris r = 3 runs (%s)", err.msg);
    ok(r.runs == 3 * (r.n + 1) && r.morris_delta == 4.0 / 6.0,
       "%zu runs = r (k + 1); Delta = p / (2 (p - 1)) = 2/3", r.runs);
    int all_r = 1;
    for (size_t i = 0; i < r.n; i++) all_r &= r.rows[i].n_ee == 3;
    ok(all_r, "one elementary effect per input per trajectory");
    /* The race share applies only to the 7-node network (MODEL.md 8.3). */
    const acbb_sens_row *phi = row_of(&r, "thermal.heat_partition");
    ok(phi && phi->mu_star == 0.0 && phi->sigma == 0.0,
       "heat partition on the 46-node network: mu* = 0 exactly");
    /* The cap film counts only where a trajectory made the cap convective:
     * no effect one at a time (test_oat_flip), an interaction here. */
    const acbb_sens_row *cap = row_of(&r, "surroundings.cap_h_W_m2K");
    ok(cap && cap->mu_star > 0.0, "cap film: mu* > 0 through its interaction with the cap's "
       "boundary kind (%.3g W)", cap ? cap->mu_star : NAN);
    const acbb_sens_row *eps = row_of(&r, "lubricant.hysteresis_loss");
    ok(eps && eps->mu_star > 0.5 && eps->mu > 0,
       "hysteresis raises the total loss in every trajectory (mu = %.3g W)", eps ? eps->mu : NAN);
    ok(r.rows[0].mu_star >= r.rows[r.n - 1].mu_star, "Morris-only rows sorted by mu*");
    st = acbb_sensitivity_run(&sc, &o, &r2, &err);
    int same = st == ACBB_OK;
    for (size_t i = 0; same && i < r.n; i++)
        same = strcmp(r.rows[i].in.key, r2.rows[i].in.key) == 0 &&
               r.rows[i].mu_star == r2.rows[i].mu_star && r.rows[i].sigma == r2.rows[i].sigma;
    ok(same, "the same seed gives the same effects (1 thread vs 2 would too: runs are private)");
}

static void test_errors(void)
{
    acbb_scene sc;
    acbb_scene_default(&sc);
    static acbb_sens_result r;
    acbb_error err = {{0}};
    acbb_sens_opts o = {.metric = "nope", .oat = 1};
    ok(acbb_sensitivity_run(&sc, &o, &r, &err) == ACBB_EINVAL, "bad metric refused: %s", err.msg);
    acbb_sens_opts p = {.metric = "losses_W.total", .morris_r = 2, .morris_p = 3};
    ok(acbb_sensitivity_run(&sc, &p, &r, &err) == ACBB_EINVAL && strstr(err.msg, "even"),
       "odd Morris level count refused: %s", err.msg);
    acbb_sens_opts q = {.metric = "losses_W.total"};
    ok(acbb_sensitivity_run(&sc, &q, &r, &err) == ACBB_EINVAL, "nothing to do refused");
    atomic_int cancel = 1;
    acbb_sens_opts c = {.metric = "losses_W.total", .oat = 1, .cancel = &cancel};
    ok(acbb_sensitivity_run(&sc, &c, &r, &err) == ACBB_CANCELLED, "a set cancel flag stops it");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_metrics();
    test_relative();
    test_ranges();
    test_oat_flip();
    test_morris();
    test_errors();
    return done_testing();
}
