/* acbb — the stored fidelity frontier and its resolution (fidelity.h).
 *
 * The numbers in k_table are GENERATED: they are the "stored frontier"
 * block printed by
 *   acbb bench accuracy presets/7008C.ini --envelope --models static,quasi-static,quasi-dynamic
 * (BENCHMARKS.md "Accuracy over the operating range" gives the run they
 * came from). Re-run it after a change to the physics or the solvers and
 * paste the block here. The knob values are the ladder the envelope
 * measures (acbb_fidelity_table order is the order they are measured in). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/accuracy.h"
#include "acbb/tools/fidelity.h"
#include "acbb/tools/scene_schema.h"

#define QS ACBB_MODEL_QUASI_STATIC
#define QD ACBB_MODEL_QUASI_DYNAMIC
#define TR ACBB_THERMAL_TRANSIENT
#define N46 ACBB_NET_46

/* name, preset, model, grid, hertz, mech_tol, steady_tol, mode, dt, network,
 * worst/median steady, worst/median path (relative; temperatures over
 * max(rise, 1 K), accuracy.h ACBB_ACCURACY_T_FLOOR_K), worst path in K,
 * work per point */
static const acbb_fidelity_point k_table[] = {
    { "fast", ACBB_FIDELITY_FAST, QS, 4, ACBB_HERTZ_HB83, 1e-6, 1e-3, TR, 30, N46,
      0.253, 0.106, 0.236, 0.109, 1.12, 26.21 },
    { "qs-6", ACBB_FIDELITY_CUSTOM, QS, 6, ACBB_HERTZ_BH77, 1e-8, 1e-4, TR, 5, N46,
      0.241, 0.122, 0.222, 0.117, 1.17, 44.69 },
    { "qd-4", ACBB_FIDELITY_CUSTOM, QD, 4, ACBB_HERTZ_BH77, 1e-8, 1e-4, TR, 5, N46,
      0.0364, 0.017, 0.0452, 0.0211, 0.232, 59.78 },
    { "balanced", ACBB_FIDELITY_BALANCED, QD, 6, ACBB_HERTZ_BH77, 1e-8, 1e-4, TR, 5, N46,
      0.0155, 0.00624, 0.0252, 0.0151, 0.0561, 83.01 },
    { "qd-8", ACBB_FIDELITY_CUSTOM, QD, 8, ACBB_HERTZ_EXACT, 1e-10, 1e-5, TR, 2, N46,
      0.00957, 0.00448, 0.00915, 0.00294, 0.0218, 181.6 },
    { "qd-12", ACBB_FIDELITY_CUSTOM, QD, 12, ACBB_HERTZ_EXACT, 1e-10, 1e-5, TR, 1, N46,
      0.00644, 0.00202, 0.0047, 0.00188, 0.031, 318.3 },
    { "reference", ACBB_FIDELITY_REFERENCE, QD, 24, ACBB_HERTZ_EXACT, 1e-12, 1e-5, TR, 1, N46,
      0, 0, 0, 0, 0, 1045 },
};

#define TABLE_N (sizeof k_table / sizeof k_table[0])

const acbb_fidelity_point *acbb_fidelity_table(size_t *n)
{
    if (n) *n = TABLE_N;
    return k_table;
}

const char *acbb_fidelity_case(void)
{
    return "7008C angular-contact bearing, axial load, the seed's 48 study points "
           "(load 50..1000 N at 15000 rpm; 2000..16000 rpm at 100 N and 1000 N; TE and WTE)";
}

const char *acbb_fidelity_preset_name(acbb_fidelity_preset p)
{
    static const char *const names[] = { "custom", "fast", "balanced", "reference" };
    return (unsigned)p < sizeof names / sizeof names[0] ? names[p] : "unknown";
}

/* NaN (never measured) counts as infinitely bad: it can meet no target. */
double acbb_fidelity_worst(const acbb_fidelity_point *p)
{
    double a = p->worst_steady, b = p->worst_path;
    if (isnan(a) || isnan(b)) return INFINITY;
    return a > b ? a : b;
}

void acbb_fidelity_set(acbb_scene *s, const acbb_fidelity_point *p)
{
    s->model = p->model;
    s->contact_grid = p->contact_grid;
    s->hertz = p->hertz;
    s->mech_tol = p->mech_tol;
    s->steady_tol = p->steady_tol;
    s->thermal_mode = p->thermal_mode;
    s->time_step = p->time_step;
    s->network = p->network;
}

/* "quasi-dynamic, 6x6 grid, bh77, mech_tol 1e-08, ..." */
static void describe(const acbb_fidelity_point *p, char *buf, size_t n)
{
    static const char *const hz[] = { "exact", "bh77", "hb83" };
    snprintf(buf, n, "%s, %dx%d grid, hertz %s, mech_tol %g, steady_tol %g K/s, %s %g s, "
             "%s-node network", acbb_model_level_name(p->model), p->contact_grid,
             p->contact_grid, hz[p->hertz], p->mech_tol, p->steady_tol,
             p->thermal_mode == ACBB_THERMAL_STEADY ? "steady, step" : "time step", p->time_step,
             p->network == ACBB_NET_7 ? "7" : "46");
}

/* Append " -> knob values" to the note. */
static void add_knobs(acbb_fidelity_choice *c)
{
    char k[200];
    describe(c->point, k, sizeof k);
    size_t len = strlen(c->note);
    snprintf(c->note + len, sizeof c->note - len, "; %s (stored frontier of the 7008C envelope)",
             k);
}

static const acbb_fidelity_point *by_preset(acbb_fidelity_preset p)
{
    for (size_t i = 0; i < TABLE_N; i++)
        if (k_table[i].preset == p) return &k_table[i];
    return NULL;
}

/* The cheapest entry whose stored worst error is within the target; the
 * table is cheapest first, so the first that qualifies. */
static void resolve_target(double target, acbb_fidelity_choice *c)
{
    for (size_t i = 0; i < TABLE_N; i++) {
        /* The reference's zero is its definition, not a measurement. */
        if (k_table[i].preset == ACBB_FIDELITY_REFERENCE) continue;
        if (acbb_fidelity_worst(&k_table[i]) > target) continue;
        c->point = &k_table[i];
        c->target_met = 1;
        snprintf(c->note, sizeof c->note,
                 "fidelity: target %g %%: chose '%s', the cheapest stored setting whose "
                 "worst error over the envelope is %.3g %% (steady %.3g %%, path %.3g %%, at most "
                 "%.2g K; temperatures over max(rise, %g K))",
                 100.0 * target, k_table[i].name, 100.0 * acbb_fidelity_worst(&k_table[i]),
                 100.0 * k_table[i].worst_steady, 100.0 * k_table[i].worst_path,
                 k_table[i].worst_path_K, ACBB_ACCURACY_T_FLOOR_K);
        return;
    }
    c->point = by_preset(ACBB_FIDELITY_REFERENCE);
    snprintf(c->note, sizeof c->note,
             "fidelity: target %g %%: no measured setting is that close to the reference "
             "(the finest stored settings, which define the error); chose 'reference', whose "
             "own error is unknown, not zero",
             100.0 * target);
}

int acbb_fidelity_resolve(const acbb_scene *s, acbb_fidelity_choice *c)
{
    memset(c, 0, sizeof *c);
    if (s->target_error > 0.0) {
        resolve_target(s->target_error, c);
        add_knobs(c);
        return 1;
    }
    if (s->fidelity_preset == ACBB_FIDELITY_CUSTOM) return 0;
    c->point = by_preset(s->fidelity_preset);
    if (!c->point) return 0;
    snprintf(c->note, sizeof c->note,
             "fidelity: preset '%s': worst error over the envelope %.3g %% (steady %.3g %%, "
             "path %.3g %%, at most %.2g K; temperatures over max(rise, %g K))",
             c->point->name, 100.0 * acbb_fidelity_worst(c->point),
             100.0 * c->point->worst_steady, 100.0 * c->point->worst_path,
             c->point->worst_path_K, ACBB_ACCURACY_T_FLOOR_K);
    add_knobs(c);
    return 1;
}

int acbb_fidelity_apply(acbb_scene *s, acbb_fidelity_choice *c)
{
    acbb_fidelity_choice local;
    if (!c) c = &local;
    if (!acbb_fidelity_resolve(s, c)) return 0;
    acbb_fidelity_set(s, c->point);
    s->fidelity_preset = ACBB_FIDELITY_CUSTOM;
    s->target_error = 0.0;
    return 1;
}
