/* Property test over random valid scenes (issue 20, slow suite), TAP.
 *
 * N scenes, each from one of the seed presets with every scene key tried
 * at a random value of its `acbb keys` range (log-uniform across decades,
 * every choice of an enum or bool); an edit that makes the scene invalid
 * (cross-field rules) is dropped, so the scene stays valid. Each is run
 * with fidelity.max_wall_s = 2 (the wall-clock bound is itself one of the
 * named endings) and must:
 *   - end in a named status (acbb_status_name knows it), converged or not;
 *   - give a snapshot whose published numbers are finite and JSON
 *     (acbb_json_write_run) that cJSON reads back with only finite numbers;
 *   - when converged by the direct steady solve with heating on, balance
 *     energy: heat into the fixed nodes = the heat sources within 1e-6
 *     relative (MODEL.md 7 and 18). What today's engine guarantees: a
 *     transient ends at |dT/dt| < steady_tol and may be off by sum C dT/dt
 *     (seen up to 5e-4 relative), so for it the imbalance is printed, not
 *     asserted; with effects.heating = off nothing is solved thermally;
 *   - at low speed (every fourth scene runs at 0..50 rpm, quasi-static or
 *     static, where no ball inertia acts), balance the inner ring axially:
 *     sum of Qi sin(alpha_i) over the balls = reaction_x within
 *     100 * fidelity.mech_tol relative (the solve's stated tolerance on the
 *     force residual, x100 for the sum over up to 64 balls).
 * Usage: test_property [N [SEED]] (default 80 scenes, seed 20). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/json.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "tap.h"

static const char *const seeds[] = { "presets/7008C.ini", "presets/combined-load.ini",
                                     "presets/light-load-skid.ini", "presets/teaching-7node.ini" };

/* xorshift64*: reproducible across machines (rand() is not). */
static uint64_t rng_state;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
}

/* A value of field f as text: an int or real in its range (log-uniform
 * when it spans decades above zero), a choice of an enum, on/off. */
static void random_value(const acbb_field_info *f, char *buf, size_t n)
{
    static const char *const onoff[] = { "on", "off" };
    if (f->type == ACBB_FIELD_BOOL) {
        snprintf(buf, n, "%s", onoff[uniform() < 0.5]);
        return;
    }
    if (f->type == ACBB_FIELD_ENUM) {
        int k = 0;
        while (f->choices[k]) k++;
        snprintf(buf, n, "%s", f->choices[(int)(uniform() * k) % k]);
        return;
    }
    double lo = f->min, hi = f->max, v;
    if (lo > 0 && hi / lo > 100) v = lo * pow(hi / lo, uniform());
    else if (lo >= 0 && hi > 100 && uniform() < 0.5) v = lo + pow(10, log10(hi + 1) * uniform()) - 1;
    else v = lo + (hi - lo) * uniform();
    if (f->min_open && v <= lo) v = lo + 1e-9 * (hi - lo);
    if (f->max_open && v >= hi) v = hi - 1e-9 * (hi - lo);
    if (f->type == ACBB_FIELD_INT) snprintf(buf, n, "%.0f", f->min_open || f->max_open ? round(v) : floor(v));
    else snprintf(buf, n, "%.6g", v);
}

/* Every key tried in order; an edit that leaves an invalid scene dropped. */
static int randomize(acbb_scene *s, int low_speed)
{
    int kept = 0;
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        const acbb_field_info *f = acbb_scene_field(i);
        char key[160], val[64];
        /* About a third of the keys per scene: with every key moved at
         * once most scenes fail their set-up; over N scenes every key is
         * still tried many times. */
        if (uniform() > 0.35) continue;
        snprintf(key, sizeof key, "%s.%s", f->section, f->key);
        random_value(f, val, sizeof val);
        acbb_scene trial = *s;
        acbb_error err = { { 0 } };
        if (acbb_scene_set(&trial, key, val, &err) == ACBB_OK &&
            acbb_scene_validate(&trial, &err) == ACBB_OK)
            *s = trial, kept++;
    }
    acbb_error err = { { 0 } };
    acbb_scene_set(s, "fidelity.max_wall_s", "2", &err);
    if (low_speed) {
        acbb_scene trial = *s;
        char rpm[32];
        snprintf(rpm, sizeof rpm, "%.3f", 50 * uniform());
        acbb_scene_set(&trial, "operating.inner_speed_rpm", rpm, &err);
        acbb_scene_set(&trial, "fidelity.model", uniform() < 0.5 ? "static" : "quasi-static", &err);
        if (acbb_scene_validate(&trial, &err) == ACBB_OK) *s = trial;
    }
    return kept;
}

static int finite_json(const cJSON *o)
{
    if (cJSON_IsNumber(o)) return isfinite(o->valuedouble);
    for (const cJSON *c = o ? o->child : NULL; c; c = c->next)
        if (!finite_json(c)) return 0;
    return 1;
}

static int snapshot_finite(const acbb_snapshot *s)
{
    double v[] = { s->time, s->residual, s->T_outer_ring, s->T_inner_ring, s->T_ball,
                   s->losses.total, s->delta_x, s->delta_z, s->tilt_y, s->heat_in, s->heat_out,
                   s->reaction_x, s->stiffness_axial };
    for (size_t i = 0; i < sizeof v / sizeof *v; i++)
        if (!isfinite(v[i])) return 0;
    for (int n = 0; n < s->n_nodes; n++)
        if (!isfinite(s->T[n])) return 0;
    return 1;
}

/* acbb_json_write_run into memory, read back by cJSON. */
static int json_finite(const acbb_scene *sc, const acbb_snapshot *snap)
{
    char *text = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&text, &len);
    if (!m) return 0;
    acbb_json j;
    acbb_json_init(&j, m);
    acbb_json_write_run(&j, sc, snap);
    fclose(m);
    cJSON *o = cJSON_Parse(text);
    int good = o && finite_json(o) && j.nonfinite == 0;
    cJSON_Delete(o);
    free(text);
    return good;
}

static double axial_sum(const acbb_snapshot *s)
{
    double sum = 0;
    for (int k = 0; k < s->n_balls; k++) sum += s->balls[k].Qi * sin(s->balls[k].alpha_i);
    return sum;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 80;
    rng_state = argc > 2 ? strtoull(argv[2], NULL, 10) : 20;
    if (rng_state == 0) rng_state = 1;
    int converged = 0, forces = 0;
    static acbb_snapshot snap;
    for (int i = 0; i < n; i++) {
        acbb_scene s;
        acbb_error err = { { 0 } };
        const char *seed = seeds[i % 4];
        if (acbb_scene_load(seed, &s, &err) != ACBB_OK) {
            ok(0, "scene %d: %s loads (%s)", i, seed, err.msg);
            continue;
        }
        int low = i % 4 == 3;
        int kept = randomize(&s, low);
        acbb_sim *sim = NULL;
        acbb_status st = acbb_sim_new(&s, &sim, &err);
        if (st != ACBB_OK) {
            /* Set-up may refuse (ill-posed) or fail (no initial equilibrium):
             * a named status with a message is the property. */
            ok(strcmp(acbb_status_name(st), "unknown") != 0 && err.msg[0],
               "scene %d (%s, %d random keys): set-up ends %s: %s", i, seed, kept,
               acbb_status_name(st), err.msg);
            continue;
        }
        st = acbb_sim_run(sim);
        acbb_sim_snapshot(sim, &snap);
        acbb_sim_free(sim);
        int named = strcmp(acbb_status_name(snap.status), "unknown") != 0 &&
                    (snap.state == ACBB_RUN_CONVERGED) == (snap.status == ACBB_OK);
        ok(named && snapshot_finite(&snap) && json_finite(&s, &snap),
           "scene %d (%s, %d random keys, %s): ends %s, finite snapshot and JSON", i, seed, kept,
           s.model == ACBB_MODEL_DYNAMIC ? "dynamic" : "below dynamic",
           acbb_status_name(snap.status));
        if (snap.state != ACBB_RUN_CONVERGED) continue;
        converged++;
        if (!s.heating) {
            /* no thermal solve: nothing to balance */
        } else if (s.thermal_mode == ACBB_THERMAL_STEADY) {
            if (!is_close(snap.heat_out, snap.heat_in, 1e-6, 1e-9,
                          "steady solve converged: heat into the fixed nodes = heat sources (1e-6)"))
                printf("#   network %d: %s\n", (int)s.network, snap.message);
        } else {
            /* Today's transient stops at |dT/dt| < steady_tol, leaving sum C dT/dt
             * unbalanced (up to 5e-4 relative seen): reported, not asserted;
             * helper "losses" tightens the check (issue 20 brief). */
            double rel = fabs(snap.heat_out - snap.heat_in) / fmax(fabs(snap.heat_in), 1e-300);
            if (rel > 1e-6)
                printf("# scene %d: transient steady state off balance by %.2g relative "
                       "(not asserted)\n", i, rel);
        }
        if (low && snap.n_balls > 0) {
            forces++;
            /* Not exact even at 0..50 rpm: the race friction that carries each
             * ball's gyroscopic moment (2 M_g / D, ~1e-3 N at 50 rpm for a
             * 7008C ball) has an axial part, so the contact normals alone sum to
             * the reaction within ~1e-6 relative, whatever mech_tol asks. */
            if (!is_close(axial_sum(&snap), snap.reaction_x, fmax(100 * s.mech_tol, 1e-6), 1e-9,
                          "low speed: sum Qi sin(alpha_i) = the axial reaction"))
                printf("#   set %d, bearings %d, tilt %d, preload %d, mech_tol %g, model %d\n",
                       (int)s.set_arrangement, snap.n_bearings, (int)s.tilt,
                       (int)s.preload, s.mech_tol, (int)s.model);
        }
    }
    ok(converged > 0, "%d of %d scenes converged (the balance checks ran)", converged, n);
    ok(forces > 0, "%d low-speed scenes checked for force balance", forces);
    printf("1..%d\n", tap_n);
    return tap_failed != 0;
}
