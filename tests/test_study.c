/* Tests of the seed study (include/acbb/tools/study.h, MODEL.md section 12).
 *
 * 1. The check table against run results built by hand, where the verdict
 *    is known by construction: held, not held, not evaluable (a failed run,
 *    an undefined ratio).
 * 2. The sanity statements that need the physics recomputed below the sim
 *    API (they used to be report checks 18c and 18e): the static thrust
 *    solution against the closed form of MODEL.md section 3, and backward
 *    Euler with dt -> infinity against the direct steady solve.
 * 3. The whole study: results independent of the number of threads, no
 *    NaN/Inf in any evidence (issue 11: axial load 0), cancellation.
 * 4. The TE/WTE comparison table (`acbb study PRESET`, issue 16): the plan's
 *    count, order, pairing, speeds and loads, and its run against a Sim
 *    driven here on the same scene. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "geometry.h"
#include "hertz.h"
#include "network.h"
#include "acbb/batch.h"
#include "acbb/sim.h"
#include "acbb/tools/study.h"
#include "acbb/units.h"

#include "study_priv.h"
#include "sim_priv.h"
#include "sim_struct.h"
#include "test_study_preset.h"
#include "study_priv.h"

/* ---- 1. the check table on constructed results ---- */

static const acbb_study_row *row(int num)
{
    size_t n;
    const acbb_study_row *t = acbb_study_table(&n);
    for (size_t i = 0; i < n; i++)
        if (t[i].num == num) return &t[i];
    return NULL;
}

/* Every point converged with an empty state (one ball, no nodes). */
static void reset(acbb_study_runs *r)
{
    for (size_t i = 0; i < r->n; i++) {
        acbb_study_point *p = &r->all[i];
        memset(&p->first, 0, sizeof p->first);
        memset(&p->last, 0, sizeof p->last);
        p->first.n_balls = p->last.n_balls = 1;
        p->ok = 1;
        p->status = ACBB_OK;
        p->min_loss = 0.0;
    }
}

static acbb_snapshot *last(acbb_study_runs *r, int lv, int blk, int k, int m)
{
    return &r->sweep[lv][blk][2 * k + m].last;
}

static acbb_study_item eval(int num, const acbb_study_runs *r)
{
    acbb_study_item it;
    acbb_study_eval_row(row(num), r, &it);
    return it;
}

static const acbb_study_check *check(const acbb_study_item *it, const char *id)
{
    for (int k = 0; k < it->n_checks; k++)
        if (strcmp(it->checks[k].id, id) == 0) return &it->checks[k];
    return NULL;
}

static int has_nonfinite_text(const acbb_study_item *it)
{
    for (int k = 0; k < it->n_checks; k++)
        if (strstr(it->checks[k].text, "nan") || strstr(it->checks[k].text, "inf ")
            || strstr(it->checks[k].text, "inf%") || strstr(it->checks[k].text, "infx"))
            return 1;
    return 0;
}

static void test_table_shape(void)
{
    size_t n, nc;
    const acbb_study_row *t = acbb_study_table(&n);
    const acbb_study_conclusion *c = acbb_study_conclusions(&nc);
    int in_order = n == 18;
    for (size_t i = 0; i < n; i++)
        in_order = in_order && t[i].num == (int)i + 1 && t[i].fn && t[i].statement[0];
    ok(in_order, "the table has MODEL.md section 12's items 1..18, each with a statement");
    ok(nc == 7, "seven seed conclusions (seed section 5)");
    ok(row(10)->l2 && row(12)->l2 && row(15)->l2 && row(16)->l2 && row(17)->l2 && !row(1)->l2,
       "the (L2) items are 10, 12, 15, 16, 17");
    (void)c;
}

/* Item 1: P_T(WTE) > P_T(TE) at light loads, < at large loads. */
static void test_item1(acbb_study_runs *r)
{
    reset(r);
    for (int k = 0; k < ACBB_STUDY_NPTS; k++) {
        double w = 10.0 + k, light = k < ACBB_STUDY_NLIGHT;
        last(r, 0, ACBB_STUDY_LOAD, k, ACBB_STUDY_TE)->losses.total = light ? w - 0.5 : w + 0.5;
        last(r, 0, ACBB_STUDY_LOAD, k, ACBB_STUDY_WTE)->losses.total = w;
    }
    acbb_study_item it = eval(1, r);
    ok(it.verdict == ACBB_VERDICT_HELD, "item 1 held when WTE > TE light, TE > WTE large");
    ok(it.n_values == 16 && fabs(it.values[0].v - 9.5) < 1e-12
           && strcmp(it.values[0].key, "P_T_TE_W_50N") == 0,
       "item 1 keeps the 16 losses as values (P_T_TE_W_50N = 9.5)");
    last(r, 0, ACBB_STUDY_LOAD, 7, ACBB_STUDY_TE)->losses.total = 16.0; /* 1000 N: TE < WTE */
    it = eval(1, r);
    const acbb_study_check *b = check(&it, "1b");
    ok(it.verdict == ACBB_VERDICT_NOT_HELD && b && b->verdict == ACBB_VERDICT_NOT_HELD
           && check(&it, "1a")->verdict == ACBB_VERDICT_HELD,
       "item 1 not held when TE < WTE at 1000 N (1a held, 1b not)");
    has_substr(b ? b->text : NULL, "at 3 of 4 large loads", "1b counts 3 of 4");
}

/* Item 7: node-5 temperature rising with F_x from 200 N. */
static void test_item7(acbb_study_runs *r)
{
    reset(r);
    for (int k = 0; k < ACBB_STUDY_NPTS; k++)
        for (int m = 0; m < 2; m++) last(r, 0, ACBB_STUDY_LOAD, k, m)->T_outer_ring = 30.0 + k;
    ok(eval(7, r).verdict == ACBB_VERDICT_HELD, "item 7 held for a rising T5");
    last(r, 0, ACBB_STUDY_LOAD, 6, ACBB_STUDY_WTE)->T_outer_ring = 40.0; /* 800 N above 1000 N */
    ok(eval(7, r).verdict == ACBB_VERDICT_NOT_HELD, "item 7 not held when WTE T5 falls at 1000 N");
}

/* Item 9: < 5 % at 2000 rpm, 100 N; > 10 % at 16000 rpm, 1000 N. */
static void test_item9(acbb_study_runs *r)
{
    reset(r);
    last(r, 0, ACBB_STUDY_S100, 0, ACBB_STUDY_TE)->losses.total = 1.01;
    last(r, 0, ACBB_STUDY_S100, 0, ACBB_STUDY_WTE)->losses.total = 1.0;
    last(r, 0, ACBB_STUDY_S1000, 7, ACBB_STUDY_TE)->losses.total = 60.0;
    last(r, 0, ACBB_STUDY_S1000, 7, ACBB_STUDY_WTE)->losses.total = 50.0;
    acbb_study_item it = eval(9, r);
    ok(it.verdict == ACBB_VERDICT_HELD, "item 9 held: 1 %% at low speed, 20 %% at high");
    is_close(it.values[1].v, 20.0, 1e-12, 0, "item 9 value: 20 % at 16000 rpm, 1000 N");
    last(r, 0, ACBB_STUDY_S1000, 7, ACBB_STUDY_TE)->losses.total = 52.0;
    it = eval(9, r);
    ok(it.verdict == ACBB_VERDICT_NOT_HELD && check(&it, "9b")->verdict == ACBB_VERDICT_NOT_HELD,
       "item 9 not held: 4 %% at 16000 rpm, 1000 N");
}

/* Item 14: film thickness TE vs WTE within 5 %. */
static void test_item14(acbb_study_runs *r)
{
    reset(r);
    for (size_t i = 0; i < r->n; i++) r->all[i].last.balls[0].film_i = 1e-6;
    for (size_t i = 0; i < r->n; i++) r->all[i].last.balls[0].film_o = 2e-6;
    ok(eval(14, r).verdict == ACBB_VERDICT_HELD, "item 14 held for equal films");
    last(r, 0, ACBB_STUDY_S100, 3, ACBB_STUDY_TE)->balls[0].film_o = 2.2e-6;
    acbb_study_item it = eval(14, r);
    ok(it.verdict == ACBB_VERDICT_NOT_HELD, "item 14 not held for a 10 %% film change");
    is_close(it.values[0].v, 10.0, 1e-9, 0, "item 14 reports the 10 % worst change");
    has_substr(check(&it, "14a")->text, "outer contact, 8000 rpm of the 100 N speed sweep",
               "item 14 names where the worst change is");
}

/* A failed run makes the items that need it NOT EVALUATED, naming it. */
static void test_failed_run(acbb_study_runs *r)
{
    reset(r);
    acbb_study_point *p = &r->sweep[0][ACBB_STUDY_LOAD][2 * 5 + ACBB_STUDY_WTE];
    p->ok = 0;
    p->status = ACBB_DIVERGED;
    snprintf(p->message, sizeof p->message, "constructed failure");
    acbb_study_item it = eval(1, r);
    ok(it.verdict == ACBB_VERDICT_NOT_EVALUATED && it.n_checks == 1,
       "item 1 not evaluated when a load-sweep run failed");
    has_substr(it.checks[0].text, "600 N, WTE", "the check names the failed run");
    has_substr(it.checks[0].text, "constructed failure", "and gives its message");
    for (int m = 0; m < 2; m++) {
        last(r, 0, ACBB_STUDY_S100, 0, m)->losses.total = 1.0;
        last(r, 0, ACBB_STUDY_S1000, 7, m)->losses.total = 1.0;
    }
    ok(eval(9, r).verdict == ACBB_VERDICT_NOT_HELD, "item 9 (speed sweeps) is still judged");
}

/* Undefined numbers never reach the evidence: no loss difference at all
 * (item 2) and no drag at all (item 3b) are not evaluable. */
static void test_undefined(acbb_study_runs *r)
{
    reset(r);
    acbb_study_item it = eval(2, r);
    ok(it.verdict == ACBB_VERDICT_NOT_EVALUATED, "item 2 with TE == WTE: not evaluated");
    ok(!has_nonfinite_text(&it), "item 2: no nan/inf in the evidence");
    has_substr(it.checks[0].text, "n/a", "item 2: the undefined share reads n/a");
    it = eval(3, r);
    ok(check(&it, "3a")->verdict == ACBB_VERDICT_HELD
           && check(&it, "3b")->verdict == ACBB_VERDICT_NOT_EVALUATED,
       "item 3 with no drag: 3a held (no difference), 3b not evaluated");
    ok(!has_nonfinite_text(&it), "item 3: no nan/inf in the evidence");
    int clean = 1;
    size_t n;
    acbb_study_table(&n);
    for (int i = 1; i <= (int)n; i++) {
        it = eval(i, r);
        clean = clean && !has_nonfinite_text(&it);
        if (has_nonfinite_text(&it)) printf("#   item %d printed a non-finite number\n", i);
    }
    ok(clean, "all-zero results: no item prints nan or inf");
}

/* Issue 30, sixth round: the check table without its texts
 * (acbb_study_eval_verdicts, the perturbed studies') gives the item's and
 * every check's verdict the texts give, or says it is not sure: where a
 * number would print non-finite (sanitize turns that check NOT
 * EVALUATED) it must not be. */
static int same_verdicts(const acbb_study_item *a, const acbb_study_item *b)
{
    int same = a->verdict == b->verdict && a->n_checks == b->n_checks;
    for (int k = 0; same && k < a->n_checks; k++)
        same = strcmp(a->checks[k].id, b->checks[k].id) == 0
               && a->checks[k].verdict == b->checks[k].verdict
               && a->checks[k].info == b->checks[k].info;
    return same;
}

static void text_free_case(const acbb_study_runs *r, const char *what, int *n_sure, int *n_bad)
{
    static acbb_study_item full, fast;
    size_t n;
    acbb_study_table(&n);
    for (int i = 1; i <= (int)n; i++) {
        acbb_study_eval_row(row(i), r, &full);
        int sure = acbb_study_eval_verdicts(row(i), r, &fast);
        *n_sure += sure;
        if (sure && !same_verdicts(&full, &fast)) {
            (*n_bad)++;
            printf("#   %s: item %d's verdicts differ without text\n", what, i);
        }
    }
}

static void test_text_free(acbb_study_runs *r)
{
    int sure0 = 0, bad = 0, sure1 = 0;
    reset(r); /* all zero: ratios 0/0 print nan */
    text_free_case(r, "all zero", &sure0, &bad);
    static acbb_study_item it;
    int item2_sure = acbb_study_eval_verdicts(row(2), r, &it);
    for (size_t i = 0; i < r->n; i++) { /* numbers that differ point to point */
        acbb_snapshot *s = &r->all[i].last;
        double x = 1.0 + 0.37 * (double)i;
        for (int l = 0; l < ACBB_LOSS_KINDS; l++) s->losses.P[l] = x * (1.0 + 0.1 * l);
        s->losses.total = 7.0 * x;
        s->T_outer_ring = 30.0 + x;
        s->balls[0].Qi = 100.0 + x;
        s->balls[0].Qo = 120.0 + x;
        s->balls[0].film_i = 1e-7 * x;
        r->all[i].first = *s;
    }
    text_free_case(r, "varied", &sure1, &bad);
    ok(bad == 0 && !item2_sure && sure1 >= 12,
       "check table without texts: every verdict the texts' where sure (%d + %d of 36 rows); "
       "not sure where a number prints nan (item 2 on all-zero results)", sure0, sure1);
}

/* Item 18 from what the snapshots publish. */
static void test_item18(acbb_study_runs *r)
{
    reset(r);
    for (size_t i = 0; i < r->n; i++) {
        r->all[i].last.heat_in = r->all[i].last.heat_out = 5.0;
        r->all[i].min_loss = 0.25;
    }
    r->zero->last.heat_in = r->zero->last.heat_out = 0.0;
    acbb_study_item it = eval(18, r);
    ok(it.verdict == ACBB_VERDICT_HELD, "item 18 held: no loss at 0 rpm, balance, losses >= 0");
    ok(check(&it, "18c")->info && check(&it, "18e")->info,
       "18c and 18e (recomputed physics) are info rows pointing at this test");
    r->all[3].last.heat_out = 5.0 * (1.0 + 1e-5);
    it = eval(18, r);
    ok(check(&it, "18b")->verdict == ACBB_VERDICT_NOT_HELD && it.verdict == ACBB_VERDICT_NOT_HELD,
       "item 18 not held for a 1e-5 energy imbalance");
    r->all[3].last.heat_out = 5.0;
    r->all[7].min_loss = -1e-3;
    it = eval(18, r);
    ok(check(&it, "18d")->verdict == ACBB_VERDICT_NOT_HELD, "18d not held for a negative loss");
    r->zero->last.losses.total = 1e-3;
    it = eval(18, r);
    ok(check(&it, "18a")->verdict == ACBB_VERDICT_NOT_HELD, "18a not held for a loss at 0 rpm");
}

static void test_constructed(void)
{
    acbb_scene s = preset();
    acbb_study *st = NULL;
    acbb_error err = { { 0 } };
    ok(acbb_study_plan(&s, &st, &err) == ACBB_OK, "plan the study of %s", PRESET);
    acbb_study_runs *r = acbb_study_results(st);
    size_t want = (s.model == ACBB_MODEL_QUASI_DYNAMIC ? 1 : 2) * 48 + 1 + 4;
    ok(r->n == want, "run set: %zu points (%zu planned)", want, r->n);
    ok(r->zero->scene.inner_speed == 0.0 && r->statics[3].scene.axial_load == 200.0
           && !r->statics[3].scene.thermal_expansion,
       "zero-speed points at the preset's load and WTE at the light loads");
    test_item1(r);
    test_item7(r);
    test_item9(r);
    test_item14(r);
    test_failed_run(r);
    test_undefined(r);
    test_item18(r);
    test_text_free(r);
    /* Conclusion (2) maps onto 9a and 9b: evaluate the study as a whole. */
    reset(r);
    last(r, 0, ACBB_STUDY_S100, 0, ACBB_STUDY_TE)->losses.total = 1.0;
    last(r, 0, ACBB_STUDY_S100, 0, ACBB_STUDY_WTE)->losses.total = 1.0;
    last(r, 0, ACBB_STUDY_S1000, 7, ACBB_STUDY_TE)->losses.total = 2.0;
    last(r, 0, ACBB_STUDY_S1000, 7, ACBB_STUDY_WTE)->losses.total = 1.0;
    acbb_study_evaluate(st);
    ok(acbb_study_conclusion_verdict(st, 1) == ACBB_VERDICT_HELD
           && acbb_study_item_in_conclusion(st, 8, 1) && !acbb_study_item_in_conclusion(st, 0, 1),
       "conclusion (2) follows checks 9a, 9b and maps onto item 9 only");
    acbb_study_free(st);
}

/* ---- 2. recomputed physics (formerly report checks 18c, 18e) ---- */

/* The static thrust relation of MODEL.md section 3 ("Initial guesses")
 * solved independently of the mechanics module: bisection on alpha of
 * Z K_n(alpha) [A0 (cos alpha0 / cos alpha - 1)]^1.5 sin alpha = F_x, with
 * the Hertz constants at the operating angle as the engine uses them. */
static double kn_at(const acbb_geometry *g, acbb_hertz_mode mode, double alpha)
{
    double Rx, Ry;
    acbb_hertz_const hi, ho;
    acbb_contact_radii(g->D, g->dm, alpha, g->f_i, 1, &Rx, &Ry);
    if (acbb_hertz_const_compute(Rx, Ry, g->E_eff, mode, &hi) != ACBB_OK) return NAN;
    acbb_contact_radii(g->D, g->dm, alpha, g->f_o, 0, &Rx, &Ry);
    if (acbb_hertz_const_compute(Rx, Ry, g->E_eff, mode, &ho) != ACBB_OK) return NAN;
    return pow(pow(hi.Kc, -2.0 / 3.0) + pow(ho.Kc, -2.0 / 3.0), -1.5);
}

static double thrust_of(const acbb_geometry *g, acbb_hertz_mode mode, double alpha)
{
    double dn = g->A0 * (cos(g->alpha0) / cos(alpha) - 1.0);
    return g->Z * kn_at(g, mode, alpha) * pow(fmax(dn, 0.0), 1.5) * sin(alpha);
}

/* Static contact angle (rad) and ball load (N) under thrust F > 0. Returns
 * 0 when there is none (F <= 0: no contact to solve), leaving both 0. */
static int static_angle(const acbb_scene *s, double F, double *alpha, double *Q)
{
    acbb_geometry g;
    acbb_geometry_init(s, &g);
    double lo = g.alpha0, hi = 89.0 * ACBB_DEG;
    *alpha = *Q = 0.0;
    if (!(F > 0.0) || !(thrust_of(&g, s->hertz, hi) > F)) return 0;
    for (int it = 0; it < 200 && hi - lo > 1e-15; it++) {
        double mid = 0.5 * (lo + hi), f = thrust_of(&g, s->hertz, mid);
        if (!isfinite(f)) return 0;
        if (f < F) lo = mid;
        else hi = mid;
    }
    *alpha = 0.5 * (lo + hi);
    *Q = F / (g.Z * sin(*alpha));
    return 1;
}

static acbb_status run_to_end(const acbb_scene *s, acbb_snapshot *out)
{
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_sim_create(s, NULL, &sim, &err);
    if (st != ACBB_OK) return st;
    st = acbb_sim_drive(sim, &(acbb_run_ctl){ 0 });
    acbb_sim_snapshot(sim, out);
    acbb_sim_free(sim);
    return st == ACBB_OK && out->state != ACBB_RUN_CONVERGED ? ACBB_NOT_CONVERGED : st;
}

static void test_closed_form(void)
{
    static acbb_snapshot snap;
    static const double loads[] = { 50.0, 200.0, 1000.0 };
    acbb_scene s = preset();
    s.inner_speed = 0.0;
    for (size_t i = 0; i < sizeof loads / sizeof loads[0]; i++) {
        s.axial_load = loads[i];
        double a, Q;
        int have = static_angle(&s, loads[i], &a, &Q);
        acbb_status st = run_to_end(&s, &snap);
        ok(have && st == ACBB_OK, "0 rpm, %g N: closed form and engine both solve", loads[i]);
        char name[96];
        snprintf(name, sizeof name, "0 rpm, %g N: engine alpha_i = closed form to 1e-4", loads[i]);
        is_close(snap.balls[0].alpha_i, a, 1e-4, 0, name);
        snprintf(name, sizeof name, "0 rpm, %g N: engine Q_i = closed form to 1e-4", loads[i]);
        is_close(snap.balls[0].Qi, Q, 1e-4, 0, name);
    }
    /* Issue 11: no thrust, no closed-form angle, and nothing left unset. */
    double a = -1.0, Q = -1.0;
    ok(!static_angle(&s, 0.0, &a, &Q) && a == 0.0 && Q == 0.0,
       "F_x = 0: the closed form reports no solution and sets both outputs");
}

/* BE with a huge step against the direct steady solve on the network of a
 * converged run, with its final contact sizes, speeds and heat sources. */
static void test_be_vs_steady(void)
{
    static acbb_snapshot f;
    acbb_scene s = preset();
    s.inner_speed = 15000.0 * ACBB_RPM;
    s.axial_load = 1000.0;
    s.thermal_expansion = 1;
    ok(run_to_end(&s, &f) == ACBB_OK, "15000 rpm, 1000 N, TE converges");
    acbb_network nw;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_network_build(&s, &nw, &err);
    ok(st == ACBB_OK, "network builds");
    if (st != ACBB_OK) return;
    acbb_net_inputs in = { .a_i = f.balls[0].a_i, .b_i = f.balls[0].b_i,
                           .a_o = f.balls[0].a_o, .b_o = f.balls[0].b_o,
                           .omega_i = s.inner_speed, .omega_m = f.balls[0].omega_m,
                           .T_cavity_C = f.T_cavity };
    acbb_heat_sources h = { f.losses.inner, f.losses.outer, f.losses.P[ACBB_LOSS_SPIN],
                            f.losses.P[ACBB_LOSS_DRAG], f.losses.P[ACBB_LOSS_CAGE] };
    double q[ACBB_MAX_NODES], Tbe[ACBB_MAX_NODES], Tss[ACBB_MAX_NODES];
    st = acbb_network_update(&nw, &s, &in);
    if (st == ACBB_OK) {
        acbb_network_heat(&nw, &s, &h, q);
        for (int i = 0; i < nw.n; i++) Tbe[i] = s.ambient_C;
        st = acbb_tnet_step(nw.net, q, 1e12, Tbe);
    }
    if (st == ACBB_OK) st = acbb_tnet_steady(nw.net, q, Tss);
    ok(st == ACBB_OK && nw.n == f.n_nodes, "BE step and steady solve succeed on %d nodes", nw.n);
    double diff = 0.0, rise = 0.0, vs_run = 0.0;
    for (int i = 0; st == ACBB_OK && i < nw.n && i < f.n_nodes; i++) {
        diff = fmax(diff, fabs(Tbe[i] - Tss[i]));
        rise = fmax(rise, Tss[i] - s.ambient_C);
        vs_run = fmax(vs_run, fabs(Tss[i] - f.T[i]));
    }
    ok(rise > 1.0, "the run heats the bearing (%.3g K rise)", rise);
    ok(diff <= 1e-6 * rise, "BE with dt = 1e12 s equals the steady solve (%.3g K)", diff);
    ok(vs_run <= 1e-6 * rise, "the run's final temperatures are that steady solution (%.3g K)",
       vs_run);
    acbb_network_free(&nw);
}

/* ---- 3. the whole study ---- */

static int same_items(const acbb_study *a, const acbb_study *b)
{
    if (acbb_study_n_items(a) != acbb_study_n_items(b)) return 0;
    for (size_t i = 0; i < acbb_study_n_items(a); i++) {
        const acbb_study_item *x = acbb_study_item_at(a, i), *y = acbb_study_item_at(b, i);
        if (x->verdict != y->verdict || x->n_checks != y->n_checks || x->n_values != y->n_values)
            return 0;
        for (int k = 0; k < x->n_checks; k++)
            if (strcmp(x->checks[k].text, y->checks[k].text) != 0) return 0;
        for (int k = 0; k < x->n_values; k++)
            if (memcmp(&x->values[k].v, &y->values[k].v, sizeof(double)) != 0) return 0;
    }
    return 1;
}

static acbb_study *run_study(const acbb_scene *s, int jobs, const atomic_int *cancel,
                             acbb_status *st)
{
    acbb_study *study = NULL;
    acbb_error err = { { 0 } };
    *st = acbb_study_plan(s, &study, &err);
    if (*st == ACBB_OK) *st = acbb_study_run(study, jobs, cancel);
    return study;
}

static void test_whole(void)
{
    acbb_scene s = preset();
    acbb_status s1, s2, s0;
    acbb_study *a = run_study(&s, 1, NULL, &s1), *b = run_study(&s, 2, NULL, &s2);
    ok(a && b && s1 == ACBB_OK && s2 == ACBB_OK, "the study of %s runs (1 and 2 threads)", PRESET);
    ok(a && b && same_items(a, b), "1 and 2 threads give identical results");
    const acbb_study_item *it18 = a ? acbb_study_item_at(a, 17) : NULL;
    ok(it18 && it18->verdict == ACBB_VERDICT_HELD, "item 18 (sanity) holds on %s", PRESET);
    acbb_study_free(a);
    acbb_study_free(b);

    /* Issue 11: axial load 0 printed nan (an unset closed-form load). */
    s.axial_load = 0.0;
    acbb_study *z = run_study(&s, 0, NULL, &s0);
    int clean = z != NULL, finite = z != NULL;
    for (size_t i = 0; z && i < acbb_study_n_items(z); i++) {
        const acbb_study_item *it = acbb_study_item_at(z, i);
        clean = clean && !has_nonfinite_text(it);
        for (int k = 0; k < it->n_values; k++) finite = finite && isfinite(it->values[k].v);
    }
    ok(clean, "axial load 0: no nan/inf in any evidence");
    ok(finite, "axial load 0: every value finite");
    acbb_study_free(z);

    atomic_int cancel;
    atomic_init(&cancel, 1);
    acbb_study *c = run_study(&s, 2, &cancel, &s0);
    int counts[3] = { 0 };
    if (c) acbb_study_counts(c, counts);
    ok(c && s0 == ACBB_CANCELLED && counts[ACBB_VERDICT_NOT_EVALUATED] == 18,
       "cancelled before any run: ACBB_CANCELLED, all 18 items not evaluated");
    acbb_study_free(c);
}

/* ---- 4. the TE/WTE comparison table ---- */

/* `b` with `a`'s speed, load and thermal expansion is `a` field by field. */
static int same_but_op(const acbb_scene *a, const acbb_scene *b)
{
    acbb_scene c = *b;
    c.inner_speed = a->inner_speed;
    c.axial_load = a->axial_load;
    c.thermal_expansion = a->thermal_expansion;
    return memcmp(&c, a, sizeof c) == 0;
}

static void test_compare_plan(const acbb_scene *base, const acbb_study_compare *c)
{
    static const char *const names[] = { "load", "speed_100N", "speed_1000N" };
    int blocks = 1, order = 1, pairs = 1, ops = 1, rest = 1;
    for (int b = 0; b < ACBB_STUDY_NSWEEPS; b++) {
        const acbb_study_compare_block *k = &c->blocks[b];
        blocks = blocks && k->sweep == b && strcmp(k->name, names[b]) == 0
                 && k->first == (size_t)b * ACBB_STUDY_NPTS && k->count == ACBB_STUDY_NPTS;
    }
    ok(blocks, "compare: three blocks load, speed_100N, speed_1000N of %d pairs each",
       ACBB_STUDY_NPTS);
    ok(strcmp(c->blocks[0].title, "load sweep at 12345 rpm") == 0
       && strcmp(c->blocks[1].title, "speed sweep at 100 N") == 0
       && strcmp(c->blocks[2].title, "speed sweep at 1000 N") == 0,
       "compare: titles name the load sweep's speed and the speed sweeps' loads (%s)",
       c->blocks[0].title);
    for (size_t i = 0; i < ACBB_STUDY_COMPARE_N; i++) {
        const acbb_study_compare_point *p = &c->pts[i];
        int b = (int)(i / (2 * ACBB_STUDY_NPTS)), k = (int)(i / 2 % ACBB_STUDY_NPTS);
        order = order && p->sweep == b && p->k == k && p->mode == (int)(i % 2);
        pairs = pairs && p->scene.thermal_expansion == (i % 2 == 0);
        if (i % 2) pairs = pairs && same_but_op(&c->pts[i - 1].scene, &p->scene)
                           && c->pts[i - 1].scene.thermal_expansion;
        double rpm = b == ACBB_STUDY_LOAD ? 12345.0 : acbb_study_speeds[k];
        double load = b == ACBB_STUDY_LOAD ? acbb_study_loads[k]
                      : b == ACBB_STUDY_S100 ? 100.0 : 1000.0;
        ops = ops && fabs(acbb_rads_to_rpm(p->scene.inner_speed) - rpm) <= 1e-9 * rpm
              && p->scene.axial_load == load && p->x == (b == ACBB_STUDY_LOAD ? load : rpm);
        rest = rest && same_but_op(&p->scene, base);
    }
    ok(ACBB_STUDY_COMPARE_N == 48, "compare: 48 points (3 sweeps x 8 x TE/WTE)");
    ok(order, "compare: sweep by sweep, k ascending, TE then WTE");
    ok(pairs, "compare: points 2k (TE) and 2k+1 (WTE) differ in thermal expansion only");
    ok(ops, "compare: load sweep at the scene's 12345 rpm over acbb_study_loads, speed "
            "sweeps over acbb_study_speeds at 100 and 1000 N");
    ok(rest, "compare: every other key is the scene's");
}

typedef struct {
    int seen[ACBB_STUDY_COMPARE_N];
    acbb_status status[ACBB_STUDY_COMPARE_N];
    int ran;
    double total_W[ACBB_STUDY_COMPARE_N];
    long iterations[ACBB_STUDY_COMPARE_N];
} compare_seen;

static void compare_done(void *ctx, const acbb_batch_result *r)
{
    compare_seen *s = ctx;
    s->seen[r->index]++;
    s->status[r->index] = r->status;
    s->ran += r->ran;
    s->total_W[r->index] = r->snap ? r->snap->losses.total : NAN;
    s->iterations[r->index] = r->snap ? r->snap->iteration : -1;
}

/* Point `i` driven here as a plain Sim: the batch must give the same run. */
static int same_as_sim(const acbb_study_compare *c, const compare_seen *s, size_t i)
{
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (acbb_sim_create(&c->pts[i].scene, NULL, &sim, &err) != ACBB_OK) return 0;
    acbb_run_ctl ctl = { 0 };
    acbb_status st = acbb_sim_drive(sim, &ctl);
    acbb_snapshot *snap = malloc(sizeof *snap);
    int same = snap != NULL;
    if (snap) acbb_sim_snapshot(sim, snap);
    same = same && st == s->status[i] && snap->losses.total == s->total_W[i]
           && snap->iteration == s->iterations[i];
    free(snap);
    acbb_sim_free(sim);
    return same;
}

static void test_compare(void)
{
    acbb_scene base = preset();
    base.inner_speed = acbb_rpm_to_rads(12345.0);
    base.axial_load = 777.0;
    base.thermal_expansion = 0;
    acbb_study_compare *c = malloc(sizeof *c);
    compare_seen *s = calloc(2, sizeof *s);
    if (!c || !s) {
        ok(0, "compare: out of memory");
        free(c);
        free(s);
        return;
    }
    acbb_study_compare_plan(&base, c);
    test_compare_plan(&base, c);

    atomic_int cancel;
    atomic_init(&cancel, 1);
    acbb_status st = acbb_study_compare_run(c, 2, &cancel, compare_done, &s[0], NULL);
    int once = 1;
    for (size_t i = 0; i < ACBB_STUDY_COMPARE_N; i++)
        once = once && s[0].seen[i] == 1 && s[0].status[i] == ACBB_CANCELLED;
    ok(st == ACBB_CANCELLED && once && s[0].ran == 0,
       "compare: cancelled first: ACBB_CANCELLED, every point reported once, none ran");

    acbb_batch_stats stats = { 0 };
    st = acbb_study_compare_run(c, 0, NULL, compare_done, &s[1], &stats);
    int all = 1;
    for (size_t i = 0; i < ACBB_STUDY_COMPARE_N; i++)
        all = all && s[1].seen[i] == 1 && s[1].status[i] == ACBB_OK;
    ok(st == ACBB_OK && all && stats.ran == ACBB_STUDY_COMPARE_N,
       "compare: every point runs once and converges on %s", PRESET);
    /* The transient (the scene's mode), not the steady solve: iterations > 1. */
    ok(s[1].iterations[0] > 1 && same_as_sim(c, &s[1], 0) && same_as_sim(c, &s[1], 47),
       "compare: the first and last points equal a Sim driven on their scene "
       "(%ld iterations)", s[1].iterations[0]);
    free(c);
    free(s);
}

/* Issue 25 item 6: "rises then falls" (checks 15b, 16c) reads a tail after
 * the low as level while it stays within REPORT_SAME (2 %) of the fall,
 * the swing from the peak to the low; beyond, a new rise. */
static void test_peak_tail(void)
{
    const double strict[] = { 1, 2, 3, 2, 1 }, rise[] = { 1, 2, 3, 4, 5 };
    const double small[] = { 1, 2, 3, 2, 1, 0, -1, -0.985, -0.99 };  /* tail 0.015 of 4 */
    const double big[] = { 1, 2, 3, 2, 1, 0, -1, -0.9 };             /* tail 0.1 of 4 */
    const double seed[] = { 41.7, 82.88, 94.87, 18.73, -140.4, -274.9, -335.4, -327.2 };
    acbb_study_shape sh;
    ok(acbb_study_peak_tail(strict, 0, 4, &sh) && sh.peak == 2 && sh.low == 4 && sh.tail == 0,
       "strict rise and fall: a peak, no tail");
    ok(!acbb_study_peak_tail(rise, 0, 4, &sh), "a plain rise: no peak");
    ok(acbb_study_peak_tail(small, 0, 8, &sh) && sh.low == 6 && fabs(sh.tail - 0.015) < 1e-12 &&
       sh.fall == 4, "a tail of 0.375 %% of the fall reads as level");
    ok(!acbb_study_peak_tail(big, 0, 7, &sh) && fabs(sh.tail / sh.fall - 0.025) < 1e-12,
       "a tail of 2.5 %% of the fall is a new rise");
    ok(acbb_study_peak_tail(seed, 0, 7, &sh) && fabs(sh.tail / sh.fall - 8.2 / 430.27) < 1e-12,
       "the seed's omega_so at 100 N (TE): tail 8.2 rad/s of a 430.3 rad/s fall (1.9 %%) is "
       "level, though 2.4 %% of the low");
    ok(acbb_study_peak(small, 0, 8) && !acbb_study_peak(big, 0, 7), "peak_shape is the same rule");
}


/* The default scene under a 300 N radial load (its balls differ: mirror
 * images), set up; NULL (and a failed check) if it does not. */
static acbb_sim *combined_sim(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    s.radial_load = 300.0;
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (acbb_sim_create(&s, NULL, &sim, &err) != ACBB_OK) ok(0, "a combined-load Sim (%s)", err.msg);
    return sim;
}

/* Issue 30, sixth round: a Sim's ball records past its balls are not
 * cleared (sim.c sim_alloc) because nothing reads them: a run with them
 * poisoned (NaN bytes) before every step is bit for bit a clean run, each
 * step's snapshot and the steady polish's end alike. */
static void poison(acbb_sim *sim)
{
    for (int j = sim->ms.n; j < ACBB_MAX_BALLS; j++) {
        memset(&sim->ms.ball[j], 0xff, sizeof sim->ms.ball[j]);
        memset(&sim->bl[j], 0xff, sizeof sim->bl[j]);
    }
}

static int poisoned_run_same(const acbb_scene *s)
{
    static acbb_snapshot a, b;
    acbb_sim *clean = NULL, *dirty = NULL;
    acbb_error err = { { 0 } };
    if (acbb_sim_create(s, NULL, &clean, &err) != ACBB_OK
        || acbb_sim_create(s, NULL, &dirty, &err) != ACBB_OK) {
        acbb_sim_free(clean);
        return 0;
    }
    int same = dirty->ms.n < ACBB_MAX_BALLS, steps = 0;
    for (acbb_status st = ACBB_OK; same && st == ACBB_OK && steps < 400; steps++) {
        poison(dirty);
        st = acbb_sim_step(dirty);
        same = acbb_sim_step(clean) == st;
        acbb_sim_snapshot(clean, &a);
        acbb_sim_snapshot(dirty, &b);
        same = same && a.state == b.state && a.n_balls == b.n_balls
               && memcmp(a.T, b.T, sizeof a.T[0] * (size_t)a.n_nodes) == 0
               && memcmp(&a.losses, &b.losses, sizeof a.losses) == 0
               && memcmp(a.balls, b.balls, sizeof a.balls[0] * (size_t)a.n_balls) == 0;
        if (a.state != ACBB_RUN_RUNNING) break;
    }
    same = same && a.state == ACBB_RUN_CONVERGED;
    acbb_sim_free(clean);
    acbb_sim_free(dirty);
    return same;
}

static void test_unused_balls(void)
{
    acbb_scene s = preset();
    int single = poisoned_run_same(&s);
    s.radial_load = 300.0;
    int combined = poisoned_run_same(&s);
    s.thermal_mode = ACBB_THERMAL_STEADY;
    int steady = poisoned_run_same(&s);
    ok(single && combined && steady, "ball records past the bearing's balls poisoned before "
       "every step: the same bits to steady state (pure thrust %d, combined %d, steady %d)",
       single, combined, steady);
}

/* Issue 30: a single bearing's step checkpoint (sim_plant.c) holds the
 * solved balls only and restores the others as their images: every ball
 * view (loads, angles, speeds, film, losses) comes back bit for bit, and
 * the checkpoint's other balls are never written. A radial load: 11 of 21
 * balls solved (mirror images). */
static void test_checkpoint(void)
{
    static acbb_snapshot before, after;
    acbb_sim *sim = combined_sim();
    if (!sim) return;
    for (int k = 0; k < 3; k++) acbb_sim_step(sim);
    acbb_plant p;
    acbb_simx_plant(sim, &p);
    int n = sim->ms.n, nd = acbb_mech_distinct(&sim->ms);
    for (int j = 0; j < ACBB_MAX_BALLS; j++) sim->keep->ms.ball[j].Qi = -1.0; /* untouched mark */
    acbb_sim_snapshot(sim, &before);
    p.save(p.ctx, ACBB_KEEP_LAST);
    int untouched = 1;
    for (int j = nd; j < n; j++) untouched = untouched && sim->keep->ms.ball[j].Qi == -1.0;
    acbb_sim_step(sim); /* moves every ball */
    int moved = sim->ms.ball[n - 1].Qi != before.balls[n - 1].Qi;
    p.restore(p.ctx, ACBB_KEEP_LAST);
    acbb_sim_snapshot(sim, &after);
    int same = after.n_balls == n && after.delta_x == before.delta_x
               && after.reaction_x == before.reaction_x
               && memcmp(&after.losses, &before.losses, sizeof before.losses) == 0
               && memcmp(after.balls, before.balls, sizeof before.balls[0] * (size_t)n) == 0;
    ok(nd < n && untouched && moved && same,
       "checkpoint: %d of %d balls kept, the other %d never written; after a step, every ball "
       "view and the losses restored bit for bit", nd, n, n - nd);
    acbb_sim_free(sim);
}

/* Issue 30: the study's per-step snapshot (acbb_simx_snapshot_step) makes
 * of each ball only the loads and the loss its hook reads, the same bits
 * as the whole snapshot's, and leaves the rest of every ball view alone.
 * A radial load, so the balls differ (mirror images). */
static void step_snapshot_case(acbb_sim *sim, const char *what)
{
    static acbb_snapshot step, whole;
    if (!sim) return;
    acbb_simx_snapshot_step(sim, &step); /* iteration 0: whole */
    int same = 1, kept = 1, steps = 0;
    for (; steps < 4 && acbb_sim_step(sim) == ACBB_OK; steps++) {
        for (int j = 0; j < step.n_balls; j++) step.balls[j].psi = -1.0 - j; /* stale */
        step.T[0] = -1.0;
        acbb_simx_snapshot_step(sim, &step);
        acbb_sim_snapshot(sim, &whole);
        same = same && step.n_balls == whole.n_balls && step.time == whole.time
               && acbb_study_min_loss(&step) == acbb_study_min_loss(&whole)
               && step.losses.total == whole.losses.total && step.delta_x == whole.delta_x
               && step.exp_inner == whole.exp_inner && step.exp_inner_cen == whole.exp_inner_cen
               && step.exp_outer == whole.exp_outer && step.exp_ball == whole.exp_ball
               && step.iteration == whole.iteration && step.state == whole.state;
        for (int j = 0; j < whole.n_balls; j++) {
            same = same && step.balls[j].Qi == whole.balls[j].Qi
                   && step.balls[j].Qo == whole.balls[j].Qo
                   && step.balls[j].loss == whole.balls[j].loss;
            kept = kept && step.balls[j].psi == -1.0 - j;
        }
        kept = kept && step.T[0] == -1.0;
    }
    ok(steps == 4 && same && whole.balls[1].Qi != whole.balls[3].Qi,
       "step snapshot (%s): every ball's Qi, Qo, loss and the smallest loss the whole "
       "snapshot's, bit for bit, over %d steps (balls differ)", what, steps);
    ok(kept, "step snapshot (%s): the rest is not made (a stale azimuth and temperature stay)",
       what);
    acbb_sim_free(sim);
}

/* Issue 30, sixth round: a perturbed study's hook (acbb_simx_snapshot_values)
 * makes step 0 as a later step, not whole: the same loads, losses,
 * expansions and smallest loss as the whole snapshot, the rest not made. */
static void test_values_snapshot(void)
{
    static acbb_snapshot vals, whole;
    acbb_sim *sim = combined_sim();
    if (!sim) return;
    for (int j = 0; j < ACBB_MAX_BALLS; j++) vals.balls[j].psi = -1.0 - j; /* stale */
    vals.T[0] = -1.0;
    acbb_simx_snapshot_values(sim, &vals);
    acbb_sim_snapshot(sim, &whole);
    int same = vals.iteration == 0 && whole.iteration == 0 && vals.n_balls == whole.n_balls
               && vals.time == whole.time && vals.state == whole.state
               && acbb_study_min_loss(&vals) == acbb_study_min_loss(&whole)
               && vals.losses.total == whole.losses.total && vals.delta_x == whole.delta_x
               && vals.exp_inner == whole.exp_inner && vals.exp_inner_cen == whole.exp_inner_cen
               && vals.exp_outer == whole.exp_outer && vals.exp_ball == whole.exp_ball;
    int kept = vals.T[0] == -1.0;
    for (int j = 0; j < whole.n_balls; j++) {
        same = same && vals.balls[j].Qi == whole.balls[j].Qi
               && vals.balls[j].Qo == whole.balls[j].Qo && vals.balls[j].loss == whole.balls[j].loss;
        kept = kept && vals.balls[j].psi == -1.0 - j;
    }
    ok(same && whole.balls[1].Qi != whole.balls[3].Qi,
       "values snapshot at step 0: every ball's Qi, Qo, loss and the smallest loss the whole "
       "snapshot's, bit for bit (balls differ)");
    ok(kept, "values snapshot at step 0: the rest is not made (a stale azimuth and temperature "
       "stay)");
    acbb_sim_free(sim);
}

/* The same for a DB pair (issue 30, fifth round): a set's step snapshot is
 * bearing 0's, made from its values, not the whole set snapshot. */
static void test_step_snapshot(void)
{
    step_snapshot_case(combined_sim(), "single bearing");
    acbb_scene s;
    acbb_scene_default(&s);
    s.radial_load = 300.0;
    s.set_arrangement = ACBB_SET_DB;
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (acbb_sim_create(&s, NULL, &sim, &err) != ACBB_OK) ok(0, "a DB pair's Sim (%s)", err.msg);
    step_snapshot_case(sim, "DB pair");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_table_shape();
    test_peak_tail();
    test_constructed();
    test_closed_form();
    test_be_vs_steady();
    test_whole();
    test_compare();
    test_step_snapshot();
    test_values_snapshot();
    test_checkpoint();
    test_unused_balls();
    return done_testing();
}
