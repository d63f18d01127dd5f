/* acbb — the FFI entry point (acbb/ffi.h): `acbb run --json` on text. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/ffi.h"
#include "acbb/tools/branches.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/json.h"
#include "acbb/tools/measure.h"
#include "acbb/sim.h"
#include "gsl_quiet.h"
#include "cancel.h"

/* The scene as `acbb run` prepares it: text, settings (the Sim resolves it). */
static acbb_status prepare(const char *text, size_t len, const char *const *settings,
                           size_t n, acbb_scene *sc, acbb_error *err)
{
    acbb_status st = acbb_scene_load_text_n(text, len, NULL, sc, err);
    if (st == ACBB_OK) st = acbb_scene_apply_edits(sc, settings, n, err);
    return st;
}

/* Run `sc` to the end (or the cancel) and write its document; the call's
 * status. As `acbb run` does, a scene that wants it (acbb_branches_wanted)
 * also solves the other branch, unless the run was cancelled, within what
 * the run left of fidelity.max_wall_s. */
static acbb_status run(acbb_json *j, const acbb_scene *given, const acbb_atomic_int *cancel)
{
    acbb_error err = { { 0 } };
    double deadline = given->max_wall_s > 0.0 ? acbb_now_ms() + 1e3 * given->max_wall_s : 0.0;
    acbb_sim *sim = NULL;
    acbb_status st = acbb_sim_create(given, &(acbb_sim_opts){ .cancel = cancel }, &sim, &err);
    acbb_scene rs; /* the scene as the run used it, echoed in the document */
    if (st != ACBB_OK) {
        acbb_scene_resolve(given, &rs, NULL); /* no Sim to ask */
        acbb_json_write_failed(j, &rs, acbb_status_name(st),
                               err.msg[0] ? err.msg : acbb_status_name(st));
        return st;
    }
    rs = *acbb_sim_scene(sim);
    const acbb_scene *sc = &rs;
    acbb_snapshot *snap = malloc(sizeof *snap);
    if (!snap) {
        acbb_sim_free(sim);
        return ACBB_ENOMEM;
    }
    st = acbb_sim_drive(sim, &(acbb_run_ctl){ .cancel = cancel });
    acbb_sim_snapshot(sim, snap);
    /* A set's bearings (MODEL.md 14), read before the Sim goes. */
    int nb = snap->n_bearings > 1 ? snap->n_bearings : 0;
    acbb_snapshot *b = nb ? malloc(sizeof *b * (size_t)nb) : NULL;
    for (int k = 0; b && k < nb; k++) acbb_sim_bearing_snapshot(sim, k, &b[k]);
    acbb_sim_free(sim);
    acbb_branches br;
    bool other = !acbb_cancelled(cancel) && acbb_branches_wanted(sc)
                 && acbb_branches_compare(sc, snap, cancel, deadline, &br, &err) == ACBB_OK;
    acbb_json_write_run_parts(j, sc, snap, b, b ? nb : 0, other ? &br : NULL);
    free(b);
    if (st == ACBB_OK && snap->state != ACBB_RUN_CONVERGED) st = ACBB_NOT_CONVERGED;
    free(snap);
    return st;
}

/* Bad input, or a scene that could not be prepared: the layout's version,
 * status and message, as every document (acbb/tools/json.h). A scene the rules
 * find ill-posed while loading is bad input, as `acbb run --json` names it
 * (exit 2); *status still says ACBB_ILL_POSED. */
static void write_refusal(acbb_json *j, acbb_status st, const acbb_error *err)
{
    acbb_json_open(j, NULL, '{', false);
    acbb_json_long(j, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    acbb_json_str(j, "status", acbb_status_name(st == ACBB_ILL_POSED ? ACBB_EINVAL : st));
    acbb_json_str(j, "message", err->msg[0] ? err->msg : acbb_status_name(st));
    acbb_json_close(j, '}');
}

char *acbb_run_preset_json(const char *preset_text, const char *const *settings,
                           size_t n_settings, int *status)
{
    size_t len = preset_text ? strlen(preset_text) : 0;
    return acbb_run_preset_json_ctl(preset_text, len, settings, n_settings, NULL, status);
}

char *acbb_run_preset_json_ctl(const char *preset_text, size_t text_len,
                               const char *const *settings, size_t n_settings,
                               const acbb_atomic_int *cancel, int *status)
{
    char *text = NULL;
    size_t len = 0;
    acbb_status st = ACBB_ENOMEM;
    acbb_scene *sc = malloc(sizeof *sc);
    FILE *m = sc ? open_memstream(&text, &len) : NULL;
    acbb_gsl_enter(); /* the whole call, scene loading included (gsl_quiet.h) */
    if (m) {
        acbb_json j;
        acbb_json_init(&j, m);
        acbb_error err = { { 0 } };
        st = prepare(preset_text, text_len, settings, n_settings, sc, &err);
        if (st == ACBB_OK) st = run(&j, sc, cancel);
        else write_refusal(&j, st, &err);
        if (j.nonfinite && st != ACBB_ENOMEM) st = ACBB_NONFINITE;
        /* A document cut short (no memory) is never handed out. */
        if (fclose(m) != 0 || st == ACBB_ENOMEM) {
            free(text);
            text = NULL;
            st = ACBB_ENOMEM;
        }
    }
    acbb_gsl_leave();
    free(sc);
    if (status) *status = st;
    return text;
}

void acbb_string_free(char *s)
{
    free(s);
}
