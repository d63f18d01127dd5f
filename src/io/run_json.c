/* acbb — a run as JSON (acbb/tools/json.h): the one writer of the document
 * `acbb run --json` prints and acbb_run_preset_json (ffi.h) returns. Its
 * numbers and keys come from the output table (outputs.h), so a new output
 * row shows up here by itself. */
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/loss_kinds.h"
#include "acbb/outputs.h"
#include "acbb/tools/physics_profile.h"
#include "acbb/units.h"
#include "acbb/tools/scene_inactive.h"
#include "acbb/tools/scene_schema.h"
#include "life_json.h"
#include "spindle_json.h"

/* The table's entries of `section` (NULL: the keys directly in a ball) as
 * JSON numbers, in table order: bearing entries when k < 0, else ball k's. */
static void rows(acbb_json *j, const acbb_snapshot *s, const char *section, int k)
{
    acbb_output e;
    for (size_t i = 0; acbb_output_get(i, &e); i++) {
        const char *sec = e.row->section;
        if ((e.row->scope == ACBB_OUT_BALL) != (k >= 0)) continue;
        if (sec && section ? strcmp(sec, section) != 0 : sec != section) continue;
        if (k < 0 && acbb_output_missing(&e, s)) acbb_json_null(j, e.key);
        else acbb_json_num(j, e.key, acbb_output_value(&e, s, k));
    }
}

void acbb_json_table_rows(acbb_json *j, const acbb_snapshot *s, const char *section)
{
    rows(j, s, section, -1);
}

/* A bearing section of the table as a JSON object. */
static void section(acbb_json *j, const acbb_snapshot *s, const char *name)
{
    acbb_json_open(j, name, '{', false);
    rows(j, s, name, -1);
    acbb_json_close(j, '}');
}

/* `sc` is the resolved scene (acbb_sim_scene, or acbb_scene_resolve when
 * no Sim was built): a graded oil's viscosities as the run used them
 * (MODEL.md 16), so the keys rerun to the same result. */
static void scene(acbb_json *j, const acbb_scene *sc)
{
    acbb_json_open(j, "scene", '{', false);
    /* Every key of the schema in preset units: the run's full input, each
     * once (schema 4 dropped the headline copies beside it, issue 28 item 7). */
    acbb_json_open(j, "keys", '{', false);
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        const acbb_field_info *fi = acbb_scene_field(i);
        char key[96], val[128];
        snprintf(key, sizeof key, "%s.%s", fi->section, fi->key);
        acbb_scene_field_format(sc, i, val, sizeof val);
        acbb_json_value_text(j, key, val);
    }
    acbb_json_close(j, '}');
    acbb_json_close(j, '}');
}

static void ball(acbb_json *j, const acbb_snapshot *s, int k)
{
    acbb_json_open(j, NULL, '{', true);
    rows(j, s, NULL, k);
    acbb_json_open(j, "losses_W", '{', true);
    rows(j, s, "losses_W", k);
    acbb_json_close(j, '}');
    acbb_json_close(j, '}');
}

/* Ring displacements and stiffness, the squeeze decomposition (MODEL.md
 * 13), the work each part did, and the effects the scene cannot feel. */
static void ring_and_work(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s)
{
    acbb_json_open(j, "ring", '{', false);
    rows(j, s, "ring", -1);
    if (s->stiffness_failed) /* the nulls above are failed probes: say why */
        acbb_json_str(j, "stiffness_missing",
                      "a stiffness probe's equilibrium solve did not converge (null, not 0)");
    acbb_json_close(j, '}');
    section(j, s, "squeeze_um");
    const acbb_work *w = &s->work;
    acbb_json_open(j, "work", '{', false);
    acbb_json_long(j, "mechanics_solves", w->mechanics_solves);
    acbb_json_long(j, "traction_solves", w->traction_solves);
    acbb_json_long(j, "loss_quadratures", w->loss_quadratures);
    acbb_json_long(j, "network_solves", w->network_solves);
    acbb_json_long(j, "expansion_updates", w->expansion_updates);
    acbb_json_close(j, '}');
    acbb_inactive_effect in[8];
    size_t n = acbb_scene_inactive_effects(sc, in, 8);
    acbb_json_open(j, "effects_inactive", '[', false);
    for (size_t i = 0; i < n; i++) {
        acbb_json_open(j, NULL, '{', true);
        acbb_json_str(j, "effect", in[i].effect);
        acbb_json_str(j, "key", in[i].key);
        acbb_json_str(j, "why", in[i].why);
        acbb_json_close(j, '}');
    }
    acbb_json_close(j, ']');
}

/* The table's temperatures and every node's. */
static void temperatures(acbb_json *j, const acbb_snapshot *s)
{
    acbb_json_open(j, "temperature_C", '{', false);
    rows(j, s, "temperature_C", -1);
    acbb_json_open(j, "nodes", '[', true);
    for (int i = 0; i < s->n_nodes && i < ACBB_MAX_NODES; i++) acbb_json_num(j, NULL, s->T[i]);
    acbb_json_close(j, ']');
    acbb_json_close(j, '}');
}

/* One bearing of a set: its single-bearing results (MODEL.md 14). */
static void bearing(acbb_json *j, const acbb_snapshot *b, const acbb_set_view *v, int k)
{
    acbb_json_open(j, NULL, '{', false);
    acbb_json_long(j, "index", k);
    acbb_json_long(j, "orientation", v->orientation[k]);
    acbb_json_num(j, "axial_force_N", v->axial_force[k]);
    acbb_json_bool(j, "contact_lost", v->contact_lost[k] != 0);
    section(j, b, "losses_W");
    temperatures(j, b);
    section(j, b, "expansion_um");
    section(j, b, "ring");
    section(j, b, "squeeze_um");
    acbb_json_write_life(j, b); /* MODEL.md 15: each bearing its own life */
    acbb_json_open(j, "balls", '[', false);
    for (int i = 0; i < b->n_balls && i < ACBB_MAX_BALLS; i++) ball(j, b, i);
    acbb_json_close(j, ']');
    acbb_json_close(j, '}');
}

/* A set's `bearings` (when their snapshots are given) and `set`. */
static void set_part(acbb_json *j, const acbb_snapshot *s, const acbb_snapshot *b, int n)
{
    if (b) {
        acbb_json_open(j, "bearings", '[', false);
        for (int k = 0; k < n; k++) bearing(j, &b[k], &s->set, k);
        acbb_json_close(j, ']');
    }
    section(j, s, "set");
}

void acbb_json_write_run(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s)
{
    acbb_json_write_run_parts(j, sc, s, NULL, 0, NULL);
}

void acbb_json_write_run_parts(acbb_json *j, const acbb_scene *sc, const acbb_snapshot *s,
                               const acbb_snapshot *b, int n, const acbb_branches *br)
{
    acbb_json_open(j, NULL, '{', false);
    acbb_json_long(j, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    acbb_json_str(j, "status", acbb_run_status_name(s));
    acbb_json_str(j, "message", s->message);
    acbb_json_long(j, "iterations", s->iteration);
    acbb_json_num(j, "time_s", s->time);
    acbb_json_num(j, "wall_ms", s->wall_ms);

    section(j, s, "losses_W");
    acbb_json_str(j, "loss_set", acbb_loss_set(sc)); /* MODEL.md 16: seed | extended */
    acbb_json_str(j, "profile", acbb_profile_name(sc->profile)); /* physics.profile */

    temperatures(j, s);

    section(j, s, "expansion_um");

    ring_and_work(j, sc, s);

    acbb_json_open(j, "balls", '[', false);
    for (int k = 0; k < s->n_balls && k < ACBB_MAX_BALLS; k++) ball(j, s, k);
    acbb_json_close(j, ']');

    section(j, s, "energy_W");
    acbb_json_write_life(j, s);
    if (s->n_bearings > 1) set_part(j, s, n == s->n_bearings ? b : NULL, s->n_bearings);
    if (s->spindle.n_sets > 0) acbb_json_write_spindle(j, s); /* docs/spindle.md */
    if (sc->schedule_n > 0) acbb_json_write_schedule(j, sc, s);
    if (br) acbb_json_write_branches(j, br);

    scene(j, sc);
    acbb_json_close(j, '}');
}

void acbb_json_write_failed(acbb_json *j, const acbb_scene *sc, const char *status,
                            const char *message)
{
    acbb_json_open(j, NULL, '{', false);
    acbb_json_long(j, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    acbb_json_str(j, "status", status);
    acbb_json_str(j, "message", message);
    acbb_json_long(j, "iterations", 0);
    scene(j, sc);
    acbb_json_close(j, '}');
}
