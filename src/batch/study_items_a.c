/* acbb — the seed study, items 1-9 of MODEL.md section 12: total loss and
 * its parts TE vs WTE, drag, expansions and contact loads over the
 * transient, contact angles, outer-ring temperature (see study.h).
 *
 * House rule: physics over wished-for results. Every statement becomes
 * numeric checks with the thresholds MODEL.md section 12 gives; where it
 * gives none ("strongly", "slightly", "much smaller") study_priv.h fixes one
 * (REPORT_*) and the check's text names it. "Room temperature" is the WTE
 * state (MODEL.md 12: step 0 of the TE run already carries the centrifugal
 * ring growth), "final" the TE run's converged snapshot; "step 0" (item 5's
 * transients) the TE run's start; per-ball numbers are ball 0's (psi = 0;
 * every ball is identical under pure thrust). */
#include <math.h>
#include <stdio.h>
#include "study_priv.h"

static double g_drag(const acbb_snapshot *s) { return acbb_study_loss_list[LOSS_DRAG].get(s); }
static double g_ai(const acbb_snapshot *s) { return s->balls[0].alpha_i * DEG_PER_RAD; }
static double g_ao(const acbb_snapshot *s) { return s->balls[0].alpha_o * DEG_PER_RAD; }
static double g_exp_in(const acbb_snapshot *s) { return 1e6 * (s->exp_inner + s->exp_inner_cen); }
static double g_exp_out(const acbb_snapshot *s) { return 1e6 * s->exp_outer; }
static double g_exp_ball(const acbb_snapshot *s) { return 1e6 * s->exp_ball; }

void acbb_study_item1(const acbb_study_runs *c, acbb_study_item *it)
{
    double te[NL], wte[NL];
    if (!load_pair(c, it, "1", LV_BASE, acbb_study_g_total, "P_T", "W", te, wte)) return;
    light_large(it, "1a", "1b", "P_T W", te, wte, "; WTE > TE at %d of %d light loads",
                "; WTE < TE at %d of %d large loads");
}

void acbb_study_item2(const acbb_study_runs *c, acbb_study_item *it)
{
    if (!need(it, "2", c, LV_BASE, BLK_LOAD)) return;
    const acbb_study_loss *L = acbb_study_loss_list;
    double share[NL], pct[NL];
    int top[NL];
    for (int k = 0; k < NL; k++) {
        const acbb_snapshot *a = &P(c, LV_BASE, BLK_LOAD, k, TE)->last;
        const acbb_snapshot *b = &P(c, LV_BASE, BLK_LOAD, k, WTE)->last;
        double d[N_LOSSES], gross = 0.0;
        top[k] = 0;
        for (int i = 0; i < N_LOSSES; i++) {
            d[i] = fabs(L[i].get(a) - L[i].get(b));
            gross += d[i];
            if (d[i] > d[top[k]]) top[k] = i;
        }
        /* Light loads: P_t + P_L; large loads: P_t + P_r. */
        double pair = d[LOSS_SLIP] + (k < N_LIGHT ? d[LOSS_SHEAR] : d[LOSS_ROLLING]);
        share[k] = gross > 0.0 ? pair / gross : NAN;
        pct[k] = 100.0 * share[k];
    }
    val_series(it, "share_pct", BLK_LOAD, pct, 0, NL - 1);
    for (int half = 0; half < 2; half++) {
        int a = half ? N_LIGHT : 0, z = half ? NL - 1 : N_LIGHT - 1, n = 0;
        tbuf t = TB(it);
        tb(&t, "share of %s in sum|dP_k| (dP_k = TE-WTE of each loss):",
           half ? "P_t+P_r" : "P_t+P_L");
        for (int k = a; k <= z; k++) {
            tb(&t, " %g N %.0f %% (largest %s)%s", k_loads[k], 100.0 * share[k], L[top[k]].symbol,
               k < z ? "," : "");
            n += share[k] > 0.5;
        }
        tb(&t, "; > 50 %% at %d of %d", n, z - a + 1);
        add_check(it, half ? "2b" : "2a", V(n == z - a + 1), &t);
    }
}

void acbb_study_item3(const acbb_study_runs *c, acbb_study_item *it)
{
    bool ok = true;
    for (int b = 0; b < NBLK; b++) ok = need(it, "3", c, LV_BASE, b) && ok;
    if (!ok) return;
    double worst = 0.0;
    int wb = 0, wk = 0;
    for (int b = 0; b < NBLK; b++)
        for (int k = 0; k < NL; k++) {
            double te = g_drag(&P(c, LV_BASE, b, k, TE)->last);
            double w = g_drag(&P(c, LV_BASE, b, k, WTE)->last);
            double r = w > 0.0 ? fabs(te - w) / w : 0.0;
            if (r >= worst) {
                worst = r;
                wb = b;
                wk = k;
            }
        }
    add_val(it, "max_rel_dPv_pct", 100.0 * worst);
    tbuf t = TB(it);
    tb(&t, "max |P_v(TE)-P_v(WTE)|/P_v(WTE) over the 24 TE/WTE pairs = %.3g %% (at %g %s, %s "
       "sweep); need < 2 %%", 100.0 * worst, xs(wb)[wk], xunit(wb),
       wb == BLK_LOAD ? "15000 rpm load" : wb == BLK_S100 ? "100 N speed" : "1000 N speed");
    add_check(it, "3a", V(worst < 0.02), &t);
    double vl[NL], v1[NL], v2[NL];
    series(c, LV_BASE, BLK_LOAD, TE, g_drag, vl);
    series(c, LV_BASE, BLK_S100, TE, g_drag, v1);
    series(c, LV_BASE, BLK_S1000, TE, g_drag, v2);
    double sl = spread(vl, 0, NL - 1), ss = fmin(spread(v1, 0, NL - 1), spread(v2, 0, NL - 1));
    add_val(it, "Pv_spread_load_pct", 100.0 * sl);
    add_val(it, "Pv_spread_speed_pct", 100.0 * ss);
    t.n = 0;
    tb(&t, "P_v (TE) spread (max-min)/max: over 50-1000 N at 15000 rpm %.3g %%, over "
       "2000-16000 rpm %.3g %% (smaller of 100 N, 1000 N); mainly speed if >= %.0fx: ",
       100.0 * sl, 100.0 * ss, REPORT_MAINLY);
    if (sl > 0.0) tb(&t, "%.3gx", ss / sl);
    else tb(&t, "%s", ss > 0.0 ? "unbounded (no spread over load)" : "no spread at all");
    /* No spread over speed either (P_v switched off): nothing to compare. */
    add_check(it, "3b", ss > 0.0 ? V(ss >= REPORT_MAINLY * sl) : V_NOT_EVAL, &t);
}

/* The transient items read the per-step record of the TE load sweep. */
static bool need_traj(acbb_study_item *it, const char *id, const acbb_study_runs *c)
{
    for (int k = 0; k < NL; k++) {
        const acbb_study_point *p = P(c, LV_BASE, BLK_LOAD, k, TE);
        if (p->n_traj > 0 && p->traj) continue;
        tbuf t = TB(it);
        tb(&t, "run %s: no transient recorded", p->label);
        add_check(it, id, V_NOT_EVAL, &t);
        return false;
    }
    return true;
}

/* A transient of the TE load sweep that ran away (rigid preload; study.c,
 * steady_branch) is read as it ran, up to its last good state: an info
 * check says which, and that its steady values elsewhere are the steady
 * solve's, another branch (MODEL.md 14). */
static void runaway_note(acbb_study_item *it, const char *id, const acbb_study_runs *c)
{
    tbuf t = TB(it);
    for (int k = 0; k < NL; k++) {
        const acbb_study_point *p = P(c, LV_BASE, BLK_LOAD, k, TE);
        if (p->runaway_t > 0.0) tb(&t, "%s%g N at t = %.0f s", t.n ? ", " : "", k_loads[k],
                                   p->runaway_t);
    }
    if (!t.n) return;
    tb(&t, ": the transient ran away there; \"final\" above is its last good state, while "
       "its steady values in the other items are the steady solve's (another branch, "
       "docs/physics.md section 14)");
    acbb_study_check *ch = add_check(it, id, V_NOT_EVAL, &t);
    if (ch) ch->info = 1;
}

/* Transient of the TE load-sweep point k: sign changes of
 * (theta_i + theta_icen) - theta_o, and the time of the first one. */
static int crossings(const acbb_study_point *p, double *t_first)
{
    int n = 0, last = 0;
    *t_first = NAN;
    for (size_t i = 0; i < p->n_traj; i++) {
        double d = p->traj[i].exp_in - p->traj[i].exp_out;
        int s = (d > 0.0) - (d < 0.0);
        if (s == 0) continue;
        if (last != 0 && s != last) {
            if (n == 0) *t_first = p->traj[i].t;
            n++;
        }
        last = s;
    }
    return n;
}

void acbb_study_item4(const acbb_study_runs *c, acbb_study_item *it)
{
    if (!need(it, "4", c, LV_BASE, BLK_LOAD) || !need_traj(it, "4", c)) return;
    int n_early = 0, n_final = 0, n_one = 0, n_ball = 0;
    tbuf ta = TB(it), tc = TB(it), td = TB(it);
    tb(&ta, "(theta_i+theta_icen) - theta_o um at step 0 / final:");
    tb(&tc, "sign changes of (theta_i+theta_icen) - theta_o over time (at t s):");
    tb(&td, "final theta_ba / min(theta_i+theta_icen, theta_o), need <= %.2f:",
       REPORT_MUCH_SMALLER);
    for (int k = 0; k < NL; k++) {
        const acbb_study_point *p = P(c, LV_BASE, BLK_LOAD, k, TE);
        const acbb_study_step *a = &p->traj[0], *z = &p->traj[p->n_traj - 1];
        double d0 = a->exp_in - a->exp_out, d1 = z->exp_in - z->exp_out, tx;
        int nx = crossings(p, &tx);
        double ratio = z->exp_ball / fmin(z->exp_in, z->exp_out);
        n_early += d0 > 0.0;
        n_final += d1 < 0.0;
        n_one += nx == 1;
        n_ball += ratio >= 0.0 && ratio <= REPORT_MUCH_SMALLER;
        const char *sep = k < NL - 1 ? "," : "";
        tb(&ta, " %g N %+.3f/%+.3f%s", k_loads[k], 1e6 * d0, 1e6 * d1, sep);
        if (nx > 0) tb(&tc, " %g N %d (%.0f)%s", k_loads[k], nx, tx, sep);
        else tb(&tc, " %g N 0%s", k_loads[k], sep);
        tb(&td, " %g N %.2f%s", k_loads[k], ratio, sep);
    }
    tb(&ta, "; early IR > OR at %d of %d, final OR > IR at %d of %d", n_early, NL, n_final, NL);
    add_check(it, "4a", V(n_early == NL && n_final == NL), &ta);
    tb(&tc, "; exactly one at %d of %d", n_one, NL);
    add_check(it, "4b", V(n_one == NL), &tc);
    tb(&td, "; held at %d of %d", n_ball, NL);
    add_check(it, "4c", V(n_ball == NL), &td);

    static const getter g[3] = { g_exp_in, g_exp_out, g_exp_ball };
    static const char *const nm[3] = { "theta_i+theta_icen", "theta_o", "theta_ba" };
    static const char *const key[3] = { "exp_inner_um", "exp_outer_um", "exp_ball_um" };
    tbuf t = TB(it);
    bool ok = true;
    tb(&t, "final expansions um (TE); need falling over 50-200 N, rising over 400-1000 N. ");
    for (int i = 0; i < 3; i++) {
        double v[NL];
        series(c, LV_BASE, BLK_LOAD, TE, g[i], v);
        val_series(it, key[i], BLK_LOAD, v, 0, NL - 1);
        bool fall = decr(v, 0, N_LIGHT - 1), rise = incr(v, N_LIGHT, NL - 1);
        ok = ok && fall && rise;
        tb_series(&t, nm[i], BLK_LOAD, v, 0, NL - 1, 3);
        tb(&t, " [%s, %s]%s", fall ? "falls" : "does not fall", rise ? "rises" : "does not rise",
           i < 2 ? "; " : "");
    }
    add_check(it, "4d", V(ok), &t);
    runaway_note(it, "4r", c);
}

/* Index of the largest value of f over the trajectory. */
static size_t argmax_traj(const acbb_study_point *p, int what)
{
    size_t best = 0;
    for (size_t i = 0; i < p->n_traj; i++) {
        const acbb_study_step *a = &p->traj[i], *b = &p->traj[best];
        double va = what == 0 ? a->Qi : what == 1 ? a->Qo : a->exp_in - a->exp_out;
        double vb = what == 0 ? b->Qi : what == 1 ? b->Qo : b->exp_in - b->exp_out;
        if (va > vb) best = i;
    }
    return best;
}

void acbb_study_item5(const acbb_study_runs *c, acbb_study_item *it)
{
    if (!need(it, "5", c, LV_BASE, BLK_LOAD) || !need_traj(it, "5", c)) return;
    tbuf tr = TB(it), tp = TB(it), tl = TB(it), tg = TB(it), tx = TB(it);
    int n_rise = 0, n_peak = 0, n_light = 0, n_large = 0, n_dx = 0;
    tb(&tr, "peak rise of Qi/Qo over step 0 (need > %.1f %%):", 100.0 * REPORT_RISE);
    tb(&tp, "time of Qi peak / of max (theta_i+theta_icen-theta_o) / end of run s, final Qi "
       "below peak (need peaks within %.0f %% of the run time, then relaxing):",
       100.0 * REPORT_NEAR);
    /* The seed's Fig. 11c compares the final TE loads with the "initial
     * (WTE)" state; the TE step 0 already holds the centrifugal ring
     * growth, so the reference is the WTE run's final state. */
    tb(&tl, "final TE / WTE Qi, Qo - 1 at light loads (need within +-%.0f %%):",
       100.0 * REPORT_SAME);
    tb(&tg, "final TE / WTE Qi, Qo - 1 at large loads (need > +%.0f %%):", 100.0 * REPORT_ABOVE);
    tb(&tx, "delta_x um: step 0 / min (at t s) / final (need a fall, then a rise):");
    for (int k = 0; k < NL; k++) {
        const acbb_study_point *p = P(c, LV_BASE, BLK_LOAD, k, TE);
        const acbb_study_step *a = &p->traj[0], *z = &p->traj[p->n_traj - 1];
        const char *sep = k < NL - 1 ? "," : "";
        size_t ii = argmax_traj(p, 0), io = argmax_traj(p, 1), id = argmax_traj(p, 2);
        double ri = p->traj[ii].Qi / a->Qi - 1.0, ro = p->traj[io].Qo / a->Qo - 1.0;
        bool rise = ri > REPORT_RISE && ro > REPORT_RISE;
        n_rise += rise;
        tb(&tr, " %g N %+.2f/%+.2f %%%s", k_loads[k], 100.0 * ri, 100.0 * ro, sep);
        double tq = p->traj[ii].t, td = p->traj[id].t;
        bool relax = z->Qi < p->traj[ii].Qi * (1.0 - REPORT_RISE);
        bool near = rise && fabs(tq - td) <= REPORT_NEAR * z->t && relax;
        n_peak += near;
        tb(&tp, " %g N %.0f/%.0f/%.0f %s%s", k_loads[k], tq, td, z->t, relax ? "yes" : "no", sep);
        const acbb_snapshot *w = &P(c, LV_BASE, BLK_LOAD, k, WTE)->last;
        double fi = z->Qi / w->balls[0].Qi - 1.0, fo = z->Qo / w->balls[0].Qo - 1.0;
        if (k < N_LIGHT) {
            n_light += fabs(fi) < REPORT_SAME && fabs(fo) < REPORT_SAME;
            tb(&tl, " %g N %+.2f/%+.2f %%%s", k_loads[k], 100.0 * fi, 100.0 * fo,
               k < N_LIGHT - 1 ? "," : "");
        } else {
            n_large += fi > REPORT_ABOVE && fo > REPORT_ABOVE;
            tb(&tg, " %g N %+.2f/%+.2f %%%s", k_loads[k], 100.0 * fi, 100.0 * fo, sep);
        }
        size_t im = 0;
        for (size_t i = 0; i < p->n_traj; i++)
            if (p->traj[i].dx < p->traj[im].dx) im = i;
        const double tol = 1e-9; /* m: a nanometre */
        bool dx_ok = p->traj[im].dx < a->dx - tol && z->dx > p->traj[im].dx + tol;
        n_dx += dx_ok;
        tb(&tx, " %g N %.3f/%.3f (%.0f)/%.3f%s", k_loads[k], 1e6 * a->dx, 1e6 * p->traj[im].dx,
           p->traj[im].t, 1e6 * z->dx, sep);
        char key[48];
        snprintf(key, sizeof key, "Qi_step0_%gN", k_loads[k]);
        add_val(it, key, a->Qi);
        snprintf(key, sizeof key, "Qi_peak_%gN", k_loads[k]);
        add_val(it, key, p->traj[ii].Qi);
        snprintf(key, sizeof key, "Qi_final_%gN", k_loads[k]);
        add_val(it, key, z->Qi);
        snprintf(key, sizeof key, "Qo_step0_%gN", k_loads[k]);
        add_val(it, key, a->Qo);
        snprintf(key, sizeof key, "Qo_final_%gN", k_loads[k]);
        add_val(it, key, z->Qo);
    }
    tb(&tr, "; at %d of %d", n_rise, NL);
    add_check(it, "5a", V(n_rise == NL), &tr);
    tb(&tp, "; held at %d of %d", n_peak, NL);
    add_check(it, "5b", V(n_peak == NL), &tp);
    tb(&tl, "; held at %d of %d", n_light, N_LIGHT);
    add_check(it, "5c", V(n_light == N_LIGHT), &tl);
    tb(&tg, "; held at %d of %d", n_large, NL - N_LIGHT);
    add_check(it, "5d", V(n_large == NL - N_LIGHT), &tg);
    tb(&tx, "; held at %d of %d", n_dx, NL);
    add_check(it, "5e", V(n_dx == NL), &tx);
    runaway_note(it, "5r", c);
}

/* 6b: "alpha_o strongly reduced by centrifugal force" measured against the
 * static angle, the engine's own zero-speed WTE run at the same load (its
 * match with the closed form of MODEL.md section 3 is tested in
 * tests/test_study.c). */
static void item6_static(const acbb_study_runs *c, const double *wi, const double *wo,
                         acbb_study_item *it)
{
    tbuf t = TB(it);
    int n = 0;
    for (int k = 0; k < N_LIGHT; k++) {
        const acbb_study_point *p = &c->statics[k];
        if (p->ok) continue;
        tb(&t, "run %s failed (%s): %s", p->label, acbb_status_name(p->status), p->message);
        add_check(it, "6b", V_NOT_EVAL, &t);
        return;
    }
    tb(&t, "WTE light loads, alpha_o vs the static angle (the engine at 0 rpm) and alpha_i, "
       "deg; need alpha_o >= %.0f %% below static and alpha_i > alpha_o:", 100.0 * REPORT_STRONG);
    for (int k = 0; k < N_LIGHT; k++) {
        double as = g_ao(&c->statics[k].last);
        bool ok = wo[k] <= (1.0 - REPORT_STRONG) * as && wi[k] > wo[k];
        n += ok;
        tb(&t, " %g N static %.3f, alpha_o %.3f (%+.1f %%), alpha_i %.3f%s", k_loads[k], as,
           wo[k], 100.0 * (wo[k] / as - 1.0), wi[k], k < N_LIGHT - 1 ? ";" : "");
    }
    tb(&t, "; held at %d of %d", n, N_LIGHT);
    add_check(it, "6b", V(n == N_LIGHT), &t);
}

void acbb_study_item6(const acbb_study_runs *c, acbb_study_item *it)
{
    if (!need(it, "6", c, LV_BASE, BLK_LOAD)) return;
    double ai[NL], ao[NL], wi[NL], wo[NL];
    series(c, LV_BASE, BLK_LOAD, TE, g_ai, ai);
    series(c, LV_BASE, BLK_LOAD, TE, g_ao, ao);
    series(c, LV_BASE, BLK_LOAD, WTE, g_ai, wi);
    series(c, LV_BASE, BLK_LOAD, WTE, g_ao, wo);
    val_series(it, "alpha_i_TE_deg", BLK_LOAD, ai, 0, NL - 1);
    val_series(it, "alpha_o_TE_deg", BLK_LOAD, ao, 0, NL - 1);
    val_series(it, "alpha_i_WTE_deg", BLK_LOAD, wi, 0, NL - 1);
    val_series(it, "alpha_o_WTE_deg", BLK_LOAD, wo, 0, NL - 1);

    tbuf t = TB(it);
    int n = 0;
    /* MODEL.md 12: "room temperature" is the WTE state, not step 0 of the TE
     * run (which already carries the centrifugal ring growth). */
    tb(&t, "alpha_i, alpha_o deg, room temperature (WTE) -> final (TE):");
    for (int k = 0; k < NL; k++) {
        n += wi[k] > ai[k] && wo[k] > ao[k];
        tb(&t, " %g N %.3f->%.3f, %.3f->%.3f%s", k_loads[k], wi[k], ai[k], wo[k], ao[k],
           k < NL - 1 ? ";" : "");
    }
    tb(&t, "; both fall at %d of %d", n, NL);
    add_check(it, "6a", V(n == NL), &t);

    item6_static(c, wi, wo, it);

    t.n = 0;
    bool fi = decr(wi, 0, N_LIGHT - 1), ro = incr(wo, 0, N_LIGHT - 1);
    tb(&t, "WTE 50-200 N: ");
    tb_series(&t, "alpha_i deg", BLK_LOAD, wi, 0, N_LIGHT - 1, 5);
    tb(&t, " [%s]; ", fi ? "decreases" : "does not decrease");
    tb_series(&t, "alpha_o deg", BLK_LOAD, wo, 0, N_LIGHT - 1, 5);
    tb(&t, " [%s]", ro ? "increases" : "does not increase");
    add_check(it, "6c", V(fi && ro), &t);

    t.n = 0;
    bool ri = incr(wi, N_LIGHT, NL - 1), r2 = incr(wo, N_LIGHT, NL - 1);
    tb(&t, "WTE 400-1000 N: ");
    tb_series(&t, "alpha_i deg", BLK_LOAD, wi, N_LIGHT, NL - 1, 5);
    tb(&t, " [%s]; ", ri ? "increases" : "does not increase");
    tb_series(&t, "alpha_o deg", BLK_LOAD, wo, N_LIGHT, NL - 1, 5);
    tb(&t, " [%s]", r2 ? "increases" : "does not increase");
    add_check(it, "6d", V(ri && r2), &t);

    t.n = 0;
    bool d = decr(ai, 0, NL - 1);
    tb(&t, "TE final ");
    tb_series(&t, "alpha_i deg", BLK_LOAD, ai, 0, NL - 1, 5);
    tb(&t, " [%s with F_x over 50-1000 N]", d ? "decreases" : "does not decrease");
    add_check(it, "6e", V(d), &t);
}

void acbb_study_item7(const acbb_study_runs *c, acbb_study_item *it)
{
    double te[NL], wte[NL];
    if (!load_pair(c, it, "7", LV_BASE, acbb_study_g_T5, "T5", "C", te, wte)) return;
    bool a = incr(te, 3, NL - 1), b = incr(wte, 3, NL - 1);
    tbuf t = TB(it);
    tb_pairs(&t, "T5 C", BLK_LOAD, te, wte, 0, NL - 1, 5);
    tb(&t, "; over 200-1000 N: TE %s, WTE %s", a ? "increases" : "does not increase",
       b ? "increases" : "does not increase");
    add_check(it, "7a", V(a && b), &t);
}

void acbb_study_item8(const acbb_study_runs *c, acbb_study_item *it)
{
    for (int half = 0; half < 2; half++) {
        int blk = half ? BLK_S1000 : BLK_S100;
        const char *id = half ? "8b" : "8a";
        if (!need(it, id, c, LV_BASE, blk)) continue;
        double te[NL], wte[NL], d[NL];
        series(c, LV_BASE, blk, TE, acbb_study_g_T5, te);
        series(c, LV_BASE, blk, WTE, acbb_study_g_T5, wte);
        int n = 0;
        for (int k = 0; k < NL; k++) {
            d[k] = 1e3 * (wte[k] - te[k]);
            n += half ? d[k] < 0.0 : d[k] > 0.0;
        }
        val_series(it, half ? "T5_WTE_minus_TE_mK_1000N" : "T5_WTE_minus_TE_mK_100N", blk, d, 0,
                   NL - 1);
        tbuf t = TB(it);
        tb(&t, "at %s: T5(WTE)-T5(TE) mK:", half ? "1000 N" : "100 N");
        for (int k = 0; k < NL; k++)
            tb(&t, " %g rpm %+.2f%s", k_speeds[k], d[k], k < NL - 1 ? "," : "");
        tb(&t, " (T5 TE at 16000 rpm %.3f C); need %s at every speed: %d of %d", te[NL - 1],
           half ? "< 0" : "> 0", n, NL);
        add_check(it, id, V(n == NL), &t);
    }
}

void acbb_study_item9(const acbb_study_runs *c, acbb_study_item *it)
{
    for (int half = 0; half < 2; half++) {
        int blk = half ? BLK_S1000 : BLK_S100, k = half ? NL - 1 : 0;
        const char *id = half ? "9b" : "9a";
        if (!need(it, id, c, LV_BASE, blk)) continue;
        double te = acbb_study_g_total(&P(c, LV_BASE, blk, k, TE)->last);
        double w = acbb_study_g_total(&P(c, LV_BASE, blk, k, WTE)->last);
        double r = fabs(te - w) / w;
        add_val(it, half ? "rel_dPT_pct_16000rpm_1000N" : "rel_dPT_pct_2000rpm_100N", 100.0 * r);
        tbuf t = TB(it);
        tb(&t, "%g rpm, %s: P_T TE %.4g W, WTE %.4g W, |dP_T|/P_T(WTE) = %.3g %%; need %s",
           k_speeds[k], half ? "1000 N" : "100 N", te, w, 100.0 * r, half ? "> 10 %" : "< 5 %");
        add_check(it, id, V(half ? r > 0.10 : r < 0.05), &t);
    }
}

