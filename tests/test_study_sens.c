/* Tests of the study's robustness over the plausible ranges
 * (acbb_study_robustness, include/acbb/tools/study.h; `acbb report --sensitivity`).
 *
 * 1. A check built for the test (item 99, appended to the real table),
 *    whose deciding number is the varied input itself: the verdict, and
 *    which end turns it with which number, are known by construction.
 * 2. The shared points: each case where the robustness takes a point from
 *    the base runs instead of running it is checked bit-for-bit against a
 *    direct run, and shown not to be vacuous (the same input does change a
 *    run where the case does not apply).
 * 3. The real table on a subset of inputs: the verdicts, changed checks
 *    and their numbers under a change equal those of a study planned and
 *    run directly on the changed scene (the pool and the sharing change
 *    nothing); a trend item (13a: P_r
 *    increases with F_x) survives the hysteresis coefficient, which scales
 *    P_r (MODEL.md 6: F_R = 4 eps Q a / (3 pi D)); the sign values are the
 *    TE - WTE differences of the same runs. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "acbb/tools/study.h"
#include "acbb/tools/sensitivity.h"
#include "scene_internal.h"
#include "study_priv.h"

#include "test_study_preset.h"

static acbb_study *run_study(const acbb_scene *s)
{
    acbb_study *st = NULL;
    acbb_error err = { { 0 } };
    if (acbb_study_plan(s, &st, &err) != ACBB_OK) {
        printf("Bail out! study plan: %s\n", err.msg);
        exit(1);
    }
    acbb_study_run(st, 0, NULL);
    return st;
}

/* ---- 1. a check table known by construction ---- */

/* Item 99, held when the hysteresis coefficient of the 1000 N TE point
 * exceeds 0.008: the scene has 0.007 (not held); the plausible range
 * 0.005..0.01 (`acbb keys`) turns it at the high end only, and no other
 * input touches it. Appended to the real table for one shared run. */
#define FAKE_ITEM 99
static void fake_item(const acbb_study_runs *r, acbb_study_item *it)
{
    const acbb_study_point *p = &r->sweep[ACBB_STUDY_BASE][ACBB_STUDY_LOAD][2 * 7];
    acbb_study_check *c = &it->checks[it->n_checks++];
    snprintf(c->id, sizeof c->id, "99a");
    c->verdict = p->scene.hysteresis > 0.008 ? ACBB_VERDICT_HELD : ACBB_VERDICT_NOT_HELD;
    snprintf(c->text, sizeof c->text, "eps = %.3g; need > 0.008", p->scene.hysteresis);
}

static const acbb_study_item_rob *rob_item(const acbb_study_rob *r, int num)
{
    for (size_t k = 0; k < r->n_items; k++)
        if (r->items[k].num == num) return &r->items[k];
    return NULL;
}

static void test_constructed(const acbb_study *base, const acbb_study_rob *r)
{
    const acbb_study_item_rob *ir = rob_item(r, FAKE_ITEM);
    ok(ir && ir->verdict == ACBB_VERDICT_NOT_HELD, "eps 0.007 > 0.008 does not hold at the scene");
    if (!ir) return;
    ok(ir->n_turns == 1 && ir->n_flips == 1, "exactly one of the 5 ends turns it (%zu)",
       ir->n_turns);
    if (ir->n_flips == 1) {
        const acbb_study_flip *f = &ir->flips[0];
        ok(strcmp(f->key, "lubricant.hysteresis_loss") == 0 && strcmp(f->value, "0.01") == 0,
           "the turning end is hysteresis_loss = 0.01 (%s = %s)", f->key, f->value);
        ok(f->verdict == ACBB_VERDICT_HELD && f->turns_item, "that end makes it HELD");
        ok(f->n_checks == 1 && strstr(f->checks[0].text, "eps = 0.01;") != NULL,
           "the flip carries the deciding number there: \"%s\"",
           f->n_checks ? f->checks[0].text : "");
    }
    static const char *const bad[] = { "materials.ball_E_GPa" };
    acbb_study_rob_opts o = { .keys = bad, .n_keys = 1 };
    acbb_study_rob r2;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_study_robustness(base, &o, &r2, &err);
    ok(st == ACBB_EINVAL && strstr(err.msg, "materials.ball_E_GPa") && strstr(err.msg, "plausible"),
       "a key without a plausible range is refused: %s", err.msg);
}

/* ---- 2. the shared points, bit for bit ---- */

static int same_run(const acbb_snapshot *a, const acbb_snapshot *b)
{
    int same = a->iteration == b->iteration && a->time == b->time && a->n_nodes == b->n_nodes &&
               a->losses.total == b->losses.total && a->balls[0].Qi == b->balls[0].Qi &&
               a->balls[0].alpha_i == b->balls[0].alpha_i && a->delta_x == b->delta_x;
    for (int i = 0; same && i < ACBB_LOSS_KINDS; i++) same = a->losses.P[i] == b->losses.P[i];
    for (int i = 0; same && i < a->n_nodes; i++) same = a->T[i] == b->T[i];
    return same;
}

static int run_one(const acbb_scene *s, acbb_snapshot *out)
{
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    int good = acbb_sim_create(s, NULL, &sim, &err) == ACBB_OK && acbb_sim_drive(sim, NULL) == ACBB_OK;
    if (good) acbb_sim_snapshot(sim, out);
    acbb_sim_free(sim);
    return good && out->state == ACBB_RUN_CONVERGED;
}

/* Run `s` and `s` with key = value; same: whether both end identically. */
static void shared_case(acbb_scene s, const char *key, const char *value, int want_same,
                        const char *why)
{
    static acbb_snapshot a, b;
    acbb_scene t = s;
    acbb_error err = { { 0 } };
    s.inner_speed = 15000 * 2 * 3.14159265358979323846 / 60;
    s.axial_load = 1000;
    t = s;
    int set = acbb_scene_set_value(&t, key, value, &err) == ACBB_OK;
    int ran = set && run_one(&s, &a) && run_one(&t, &b);
    ok(ran && same_run(&a, &b) == want_same, "%s = %s %s: %s", key, value,
       want_same ? "leaves the run bit-for-bit unchanged" : "changes the run", why);
}

static void test_shared(void)
{
    acbb_scene s = preset(), te = s, wte = s, conv = s;
    te.thermal_expansion = true;
    wte.thermal_expansion = false;
    shared_case(wte, "materials.ring_expansion_ppm_K", "11.5", 1, "WTE has no expansion");
    shared_case(wte, "materials.housing_expansion_ppm_K", "9", 1, "WTE has no expansion");
    shared_case(te, "materials.housing_expansion_ppm_K", "9", 0, "TE does (not vacuous)");
    ok(s.bore_bc.kind != ACBB_BC_CONVECTIVE && s.cap_bc.kind != ACBB_BC_CONVECTIVE &&
       s.network == ACBB_NET_46, "the preset: bore and cap fixed, 46-node network");
    shared_case(te, "surroundings.shaft_bore_h_W_m2K", "2000", 1, "the bore is fixed");
    shared_case(te, "surroundings.cap_h_W_m2K", "50", 1, "the cap is fixed");
    shared_case(te, "thermal.heat_partition", "0.8", 1, "phi_p is the 7-node network's");
    acbb_error err = { { 0 } };
    acbb_scene_set_value(&conv, "surroundings.shaft_bore", "convective", &err);
    acbb_scene_set_value(&conv, "surroundings.cap", "convective", &err);
    shared_case(conv, "surroundings.shaft_bore_h_W_m2K", "2000", 0, "a convective bore (not vacuous)");
    shared_case(conv, "surroundings.cap_h_W_m2K", "50", 0, "a convective cap (not vacuous)");
}

/* ---- 3. the real table on a subset of inputs ---- */

static const acbb_study_flip *flip_at(const acbb_study_item_rob *ir, const char *key,
                                     const char *value)
{
    for (size_t j = 0; j < ir->n_flips; j++)
        if (strcmp(ir->flips[j].key, key) == 0 && strcmp(ir->flips[j].value, value) == 0)
            return &ir->flips[j];
    return NULL;
}

/* The check `id` of flip f, or NULL. */
static const acbb_study_check *flip_check(const acbb_study_flip *f, const char *id)
{
    for (int k = 0; f && k < f->n_checks; k++)
        if (strcmp(f->checks[k].id, id) == 0) return &f->checks[k];
    return NULL;
}

/* Item `it` of a study run directly on the changed scene against what the
 * robustness says of that end: a changed check must be in the end's flip
 * with the same verdict and text (the same numbers), an unchanged one not. */
static int item_agrees(const acbb_study_item *it, const acbb_study_item *b,
                       const acbb_study_item_rob *ir, const char *key, const char *value,
                       int *n_changed)
{
    const acbb_study_flip *f = flip_at(ir, key, value);
    int agree = (f && f->turns_item ? f->verdict : ir->verdict) == it->verdict;
    for (int k = 0; k < it->n_checks; k++) {
        const acbb_study_check *c = &it->checks[k], *fc = flip_check(f, c->id);
        if (c->info) continue;
        if (c->verdict == b->checks[k].verdict) {
            agree &= fc == NULL;
            continue;
        }
        (*n_changed)++;
        agree &= fc && fc->verdict == c->verdict && strcmp(fc->text, c->text) == 0;
    }
    return agree;
}

static void test_direct(const acbb_scene *s, const acbb_study *base, const acbb_study_rob *r,
                        const char *key, const char *value, int want_changed)
{
    acbb_scene t = *s;
    acbb_error err = { { 0 } };
    if (acbb_scene_set_value(&t, key, value, &err) != ACBB_OK) {
        ok(0, "set %s = %s: %s", key, value, err.msg);
        return;
    }
    acbb_study *d = run_study(&t);
    int agree = 1, n_changed = 0;
    for (size_t i = 0; i < acbb_study_n_items(d); i++) {
        const acbb_study_item *it = acbb_study_item_at(d, i);
        const acbb_study_item_rob *ir = rob_item(r, it->num);
        if (ir && ir->varied)
            agree &= item_agrees(it, acbb_study_item_at(base, i), ir, key, value, &n_changed);
    }
    ok(agree && (n_changed > 0) == want_changed,
       "%s = %s: verdicts, changed checks and their numbers equal a study run directly on "
       "that scene (%d checks change)", key, value, n_changed);
    acbb_study_free(d);
}

static void test_table(const acbb_scene *s, acbb_study *base, const acbb_study_rob *rr,
                       size_t n_rows)
{
    const acbb_study_rob r = *rr;
    ok(r.n_items == n_rows && r.n_inputs == 3 && r.n_ends == 5 && r.n_same == 1,
       "%zu items, 3 inputs, 5 ends (shaft_bore = fixed is the scene itself)", r.n_items);
    /* Ring expansion: its 2 ends share the 24 WTE sweep points and the 4 static ones. */
    ok(r.n_shared == 2 * 28, "%zu points shared: the 24 WTE and 4 static runs of each "
       "expansion end", r.n_shared);
    ok(r.n_runs == 5 * 52 - r.n_shared, "%zu runs = 5 ends x 52 non-sanity points - shared",
       r.n_runs);
    const acbb_study_item_rob *i18 = rob_item(&r, 18), *i13 = rob_item(&r, 13);
    ok(i18 && !i18->varied && i18->n_flips == 0, "item 18 (sanity) is not varied");
    int trend_kept = i13 != NULL;
    for (size_t j = 0; i13 && j < i13->n_flips; j++)
        for (int k = 0; k < i13->flips[j].n_checks; k++)
            trend_kept &= strcmp(i13->flips[j].checks[k].id, "13a") != 0;
    ok(trend_kept, "13a (P_r increases with F_x) keeps its verdict at every end: P_r scales with "
       "the hysteresis coefficient (MODEL.md 6)");
    test_direct(s, base, &r, "materials.ring_expansion_ppm_K", "11.5", 0);
    test_direct(s, base, &r, "surroundings.shaft_bore", "convective", 1);

    /* Sign values: TE - WTE of P_T at 15000 rpm, 1000 N of the base runs. */
    const acbb_study_runs *runs = acbb_study_results(base);
    const acbb_study_point *p = &runs->sweep[ACBB_STUDY_BASE][ACBB_STUDY_LOAD][2 * 7];
    double d = p[0].last.losses.total - p[1].last.losses.total;
    ok(r.n_signs > 0 && r.signs[0].ok && r.signs[0].y == d && !r.signs[0].holds,
       "sign condition 1 (%s) = P_T(TE) - P_T(WTE) of the base runs: %.6g W, does not hold",
       r.n_signs ? r.signs[0].sign->what : "", d);
    int conv = 0;
    for (size_t t = 0; r.n_signs && t < r.signs[0].n_turns; t++)
        conv += strcmp(r.signs[0].turns[t].key, "surroundings.shaft_bore") == 0 &&
                r.signs[0].turns[t].y > 0.0;
    ok(conv == 1, "a convective shaft bore turns it (TE - WTE > 0 there)");
}

/* Progress: called once per run, the count reaching the total. */
typedef struct {
    size_t calls, last_done, total;
    int monotone;
} progress_log;

static void on_progress(void *ctx, size_t done, size_t total)
{
    progress_log *l = ctx;
    l->monotone &= done == l->last_done + 1;
    l->calls++;
    l->last_done = done;
    l->total = total;
}

/* Cancelled before it starts: ACBB_CANCELLED, an empty result. */
static void test_cancel(const acbb_study *base)
{
    static const char *const keys[] = { "lubricant.drag_coefficient" };
    atomic_int stop;
    atomic_init(&stop, 1);
    acbb_study_rob_opts o = { .keys = keys, .n_keys = 1, .cancel = &stop };
    acbb_study_rob r;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_study_robustness(base, &o, &r, &err);
    ok(st == ACBB_CANCELLED && r.n_items == 0 && r.items == NULL && r.signs == NULL,
       "a set cancel flag: ACBB_CANCELLED (%s), nothing returned", err.msg);
}

/* Issue 30: a perturbed study planned from the base study's points
 * (acbb_study_plan_end) has, at every point of every end of every
 * uncertain input, the scene, label and flags of the study planned from
 * the edited scene (acbb_study_plan_runs), every key to the bit. */
static int same_scene(const acbb_scene *a, const acbb_scene *b)
{
    for (size_t i = 0; i < acbb_sf_n; i++) {
        const acbb_sfield *f = &acbb_sf_table[i];
        size_t n = f->info.type == ACBB_FIELD_REAL ? sizeof(double)
                   : f->info.type == ACBB_FIELD_BOOL ? sizeof(bool) : sizeof(int);
        if (memcmp((const char *)a + f->off, (const char *)b + f->off, n) != 0) return 0;
    }
    return 1;
}

static void test_plan_end(const acbb_scene *s)
{
    acbb_study *st = NULL;
    acbb_error err = { { 0 } };
    if (!ok(acbb_study_plan(s, &st, &err) == ACBB_OK, "plan the base study (%s)", err.msg)) return;
    const acbb_study_runs *b = acbb_study_results(st);
    acbb_sens_input in[ACBB_SENS_MAX];
    size_t n = acbb_sens_inputs(s, in, ACBB_SENS_MAX), points = 0, moved = 0;
    int same = n > 0;
    for (size_t i = 0; i < n && same; i++)
        for (int hi = 0; hi < 2 && same; hi++) {
            acbb_scene t = *s;
            acbb_study_runs old = { 0 }, now = { 0 };
            same = acbb_sens_apply(&t, &in[i], hi, &err) == ACBB_OK
                   && acbb_study_plan_runs(&old, &t) == ACBB_OK
                   && acbb_study_plan_end(&now, b, &in[i], hi) && old.n == now.n
                   && now.zero - now.all == old.zero - old.all
                   && now.statics - now.all == old.statics - old.all;
            for (size_t k = 0; same && k < old.n; k++, points++) {
                const acbb_study_point *p = &old.all[k], *q = &now.all[k];
                same = p->skip == q->skip && p->record == q->record
                       && strcmp(p->label, q->label) == 0 && same_scene(&p->scene, &q->scene);
                moved += !same_scene(&q->scene, &b->all[k].scene);
            }
            acbb_study_free_runs(&old);
            acbb_study_free_runs(&now);
        }
    ok(same && moved > 0, "a perturbed study planned from the base's points: %zu points of %zu "
       "inputs' ends, each scene the one planned from the edited scene, bit for bit (%zu "
       "differ from the base's)", points, n, moved);
    acbb_study_free(st);
}

int main(void)
{
    /* No gsl_set_error_handler_off here: the engine turns GSL's aborting
     * handler off itself while it works (src/base/gsl_quiet.h). */
    acbb_scene s = preset();
    test_plan_end(&s);
    acbb_study *base = run_study(&s);
    ok(acbb_study_n_failed(base) == 0, "the base study ran");
    /* One robustness run over 3 inputs, the real table plus item 99. */
    size_t n;
    const acbb_study_row *table = acbb_study_table(&n);
    acbb_study_row rows[32];
    if (n >= 32) {
        printf("Bail out! the check table has %zu rows, the test holds 31\n", n);
        return 1;
    }
    memcpy(rows, table, n * sizeof *rows);
    rows[n] = (acbb_study_row){ FAKE_ITEM, 0, fake_item, "fake: eps > 0.008" };
    static const char *const keys[] = { "materials.ring_expansion_ppm_K",
                                        "lubricant.hysteresis_loss", "surroundings.shaft_bore" };
    progress_log pl = { .monotone = 1 };
    acbb_study_rob_opts o = { .keys = keys, .n_keys = 3, .rows = rows, .n_rows = n + 1,
                              .progress = on_progress, .ctx = &pl };
    acbb_study_rob r;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_study_robustness(base, &o, &r, &err);
    ok(st == ACBB_OK, "robustness over 3 inputs runs (%s)", err.msg);
    ok(pl.calls == r.n_runs && pl.last_done == r.n_runs && pl.total == r.n_runs && pl.monotone,
       "progress: %zu calls counting 1..%zu of %zu runs", pl.calls, pl.last_done, pl.total);
    if (st == ACBB_OK) {
        test_constructed(base, &r);
        test_table(&s, base, &r, n + 1);
        acbb_study_rob_free(&r);
    }
    test_shared();
    test_cancel(base);
    acbb_study_free(base);
    return done_testing();
}
