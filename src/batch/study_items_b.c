/* acbb — the seed study, items 10-18 of MODEL.md section 12: the loss
 * terms P_L, P_t, P_s, P_r, film thickness, sliding and spin, ball angular
 * velocities, and the sanity item (see study.h; thresholds in
 * study_priv.h). The (L2) items read the quasi-dynamic sweeps. */
#include <math.h>
#include <stdio.h>
#include "study_priv.h"

static double g_loss(int k, const acbb_snapshot *s) { return acbb_study_loss_list[k].get(s); }
static double g_shear(const acbb_snapshot *s) { return g_loss(LOSS_SHEAR, s); }
static double g_slip(const acbb_snapshot *s) { return g_loss(LOSS_SLIP, s); }
static double g_spin(const acbb_snapshot *s) { return g_loss(LOSS_SPIN, s); }
static double g_rolling(const acbb_snapshot *s) { return g_loss(LOSS_ROLLING, s); }
static double g_film_i(const acbb_snapshot *s) { return s->balls[0].film_i; }
static double g_film_o(const acbb_snapshot *s) { return s->balls[0].film_o; }
static double g_slide_i(const acbb_snapshot *s) { return s->balls[0].slide_i; }
static double g_slide_o(const acbb_snapshot *s) { return s->balls[0].slide_o; }
static double g_spin_i(const acbb_snapshot *s) { return fabs(s->balls[0].spin_i); }
static double g_spin_o(const acbb_snapshot *s) { return fabs(s->balls[0].spin_o); }
static double g_spin_o_signed(const acbb_snapshot *s) { return s->balls[0].spin_o; }
static double g_wx(const acbb_snapshot *s) { return fabs(s->balls[0].omega_x); }
static double g_wy(const acbb_snapshot *s) { return fabs(s->balls[0].omega_y); }
static double g_wz(const acbb_snapshot *s) { return s->balls[0].omega_z; }

/* Ball 0's orbital surface speed omega_m d_m / 2, m/s (micro-sliding scale). */
static double orbit_speed(const acbb_snapshot *s, const acbb_scene *sc)
{
    return fabs(s->balls[0].omega_m) * 0.5 * sc->pitch_diameter;
}

void acbb_study_item10(const acbb_study_runs *c, acbb_study_item *it)
{
    double lt[NL], lw[NL], pt[NL], pw[NL], ft[NL], fw[NL];
    if (!load_pair(c, it, "10", LV_L2, g_shear, "P_L", "W", lt, lw)) return;
    series(c, LV_L2, BLK_LOAD, TE, acbb_study_g_total, pt);
    series(c, LV_L2, BLK_LOAD, WTE, acbb_study_g_total, pw);
    for (int k = 0; k < NL; k++) {
        ft[k] = 100.0 * lt[k] / pt[k];
        fw[k] = 100.0 * lw[k] / pw[k];
    }
    val_series(it, "P_L_share_TE_pct", BLK_LOAD, ft, 0, NL - 1);
    tbuf t = TB(it);
    int n = 0;
    for (int k = 0; k < N_LIGHT; k++) n += ft[k] >= 100.0 * REPORT_SIGNIFICANT;
    tb_series(&t, "P_L/P_T % (TE)", BLK_LOAD, ft, 0, NL - 1, 3);
    tb(&t, "; significant (>= %.0f %%) at %d of %d light loads", 100.0 * REPORT_SIGNIFICANT, n,
       N_LIGHT);
    add_check(it, "10a", V(n == N_LIGHT), &t);
    t.n = 0;
    tb(&t, "at 1000 N: P_L/P_T = %.3g %% (TE), %.3g %% (WTE); need < 5 %%", ft[NL - 1],
       fw[NL - 1]);
    add_check(it, "10b", V(ft[NL - 1] < 5.0 && fw[NL - 1] < 5.0), &t);
    t.n = 0;
    tb(&t, "P_L W TE/WTE: 100 N %.4g/%.4g (need WTE > TE), 1000 N %.4g/%.4g (need TE > WTE)",
       lt[1], lw[1], lt[NL - 1], lw[NL - 1]);
    add_check(it, "10c", V(lw[1] > lt[1] && lt[NL - 1] > lw[NL - 1]), &t);
}

void acbb_study_item11(const acbb_study_runs *c, acbb_study_item *it)
{
    double te[NL], wte[NL];
    if (!load_pair(c, it, "11", LV_BASE, g_slip, "P_t", "W", te, wte)) return;
    light_large(it, "11a", "11b", "P_t W", te, wte, "; WTE > TE at %d of %d",
                "; TE > WTE at %d of %d");
}

void acbb_study_item12(const acbb_study_runs *c, acbb_study_item *it)
{
    double te[NL], wte[NL];
    if (!load_pair(c, it, "12", LV_L2, g_spin, "P_s", "W", te, wte)) return;
    tbuf t = TB(it);
    tb(&t, "P_s W (TE/WTE): 50 N %.4g/%.4g, 100 N %.4g/%.4g; need P_s(50 N) < P_s(100 N)",
       te[0], wte[0], te[1], wte[1]);
    add_check(it, "12a", V(te[0] < te[1] && wte[0] < wte[1]), &t);
    t.n = 0;
    bool vt = valley_shape(te, 1, NL - 1), vw = valley_shape(wte, 1, NL - 1);
    tb_pairs(&t, "P_s W", BLK_LOAD, te, wte, 1, NL - 1, 4);
    tb(&t, "; falls then rises over 100-1000 N: TE %s, WTE %s", vt ? "yes" : "no",
       vw ? "yes" : "no");
    add_check(it, "12b", V(vt && vw), &t);
    t.n = 0;
    double r1 = te[1] / wte[1] - 1.0, r2 = te[NL - 1] / wte[NL - 1] - 1.0;
    tb(&t, "P_s(TE)/P_s(WTE) - 1: 100 N %+.2f %% (need within +-%.0f %%), 1000 N %+.2f %% "
       "(need >= +%.0f %%)", 100.0 * r1, 100.0 * REPORT_SAME, 100.0 * r2, 100.0 * REPORT_MARKED);
    add_check(it, "12c", V(fabs(r1) < REPORT_SAME && r2 >= REPORT_MARKED), &t);
}

void acbb_study_item13(const acbb_study_runs *c, acbb_study_item *it)
{
    bool ok = true;
    for (int b = 0; b < NBLK; b++) ok = need(it, "13", c, LV_BASE, b) && ok;
    if (!ok) return;
    double v[NBLK][2][NL];
    for (int b = 0; b < NBLK; b++)
        for (int m = 0; m < 2; m++) series(c, LV_BASE, b, m, g_rolling, v[b][m]);
    val_series(it, "P_r_TE_W", BLK_LOAD, v[BLK_LOAD][TE], 0, NL - 1);
    val_series(it, "P_r_WTE_W", BLK_LOAD, v[BLK_LOAD][WTE], 0, NL - 1);
    tbuf t = TB(it);
    bool a = incr(v[BLK_LOAD][TE], 0, NL - 1) && incr(v[BLK_LOAD][WTE], 0, NL - 1);
    tb_pairs(&t, "P_r W", BLK_LOAD, v[BLK_LOAD][TE], v[BLK_LOAD][WTE], 0, NL - 1, 4);
    tb(&t, "; increases with F_x: %s", a ? "yes" : "no");
    add_check(it, "13a", V(a), &t);
    t.n = 0;
    bool s = true;
    for (int b = BLK_S100; b <= BLK_S1000; b++)
        for (int m = 0; m < 2; m++) s = s && incr(v[b][m], 0, NL - 1);
    tb(&t, "P_r W TE at 2000/16000 rpm: 100 N %.4g/%.4g, 1000 N %.4g/%.4g; increases with speed "
       "at every step (100 N and 1000 N, TE and WTE): %s", v[BLK_S100][TE][0],
       v[BLK_S100][TE][NL - 1], v[BLK_S1000][TE][0], v[BLK_S1000][TE][NL - 1], s ? "yes" : "no");
    add_check(it, "13b", V(s), &t);
    t.n = 0;
    int n = 0, e = 0;
    tb(&t, "P_r(TE)/P_r(WTE) - 1 %%:");
    for (int k = 0; k < NL; k++) {
        double r = v[BLK_LOAD][TE][k] / v[BLK_LOAD][WTE][k] - 1.0;
        if (k < N_LIGHT) e += fabs(r) < REPORT_SAME;
        else n += r > 0.0;
        tb(&t, " %g N %+.2f%s", k_loads[k], 100.0 * r, k < NL - 1 ? "," : "");
    }
    tb(&t, "; TE > WTE at %d of %d large loads, within +-%.0f %% at %d of %d light loads", n,
       NL - N_LIGHT, 100.0 * REPORT_SAME, e, N_LIGHT);
    add_check(it, "13c", V(n == NL - N_LIGHT && e == N_LIGHT), &t);
}

void acbb_study_item14(const acbb_study_runs *c, acbb_study_item *it)
{
    bool ok = true;
    for (int b = 0; b < NBLK; b++) ok = need(it, "14", c, LV_BASE, b) && ok;
    if (!ok) return;
    double worst = 0.0, h_te = 0.0, h_w = 0.0;
    int wb = 0, wk = 0, wc = 0;
    for (int b = 0; b < NBLK; b++)
        for (int k = 0; k < NL; k++)
            for (int cc = 0; cc < 2; cc++) {
                getter g = cc ? g_film_o : g_film_i;
                double a = g(&P(c, LV_BASE, b, k, TE)->last), w = g(&P(c, LV_BASE, b, k, WTE)->last);
                double r = w > 0.0 ? fabs(a - w) / w : 0.0;
                if (r >= worst) {
                    worst = r;
                    wb = b, wk = k, wc = cc;
                    h_te = a, h_w = w;
                }
            }
    add_val(it, "max_rel_dhc_pct", 100.0 * worst);
    tbuf t = TB(it);
    tb(&t, "max |h_c(TE)-h_c(WTE)|/h_c(WTE) over 24 pairs x 2 contacts = %.3g %% (%s contact, "
       "%g %s of the %s sweep: %.4g vs %.4g um); need < 5 %%", 100.0 * worst,
       wc ? "outer" : "inner", xs(wb)[wk], xunit(wb),
       wb == BLK_LOAD ? "load" : wb == BLK_S100 ? "100 N speed" : "1000 N speed", 1e6 * h_te,
       1e6 * h_w);
    add_check(it, "14a", V(worst < 0.05), &t);
}

void acbb_study_item15(const acbb_study_runs *c, acbb_study_item *it)
{
    bool ok100 = need(it, "15a", c, LV_L2, BLK_S100);
    bool ok1000 = need(it, "15d", c, LV_L2, BLK_S1000);
    if (ok100) {
        double it_[NL], iw[NL], ot[NL], ow[NL];
        series(c, LV_L2, BLK_S100, TE, g_slide_i, it_);
        series(c, LV_L2, BLK_S100, WTE, g_slide_i, iw);
        series(c, LV_L2, BLK_S100, TE, g_slide_o, ot);
        series(c, LV_L2, BLK_S100, WTE, g_slide_o, ow);
        val_series(it, "slide_i_TE_mps_100N", BLK_S100, it_, 0, NL - 1);
        val_series(it, "slide_o_TE_mps_100N", BLK_S100, ot, 0, NL - 1);
        tbuf t = TB(it);
        bool a = incr(it_, 0, NL - 1) && incr(iw, 0, NL - 1);
        tb(&t, "100 N ");
        tb_pairs(&t, "inner sliding m/s", BLK_S100, it_, iw, 0, NL - 1, 3);
        tb(&t, "; increases with speed: %s", a ? "yes" : "no");
        add_check(it, "15a", V(a), &t);
        t.n = 0;
        bool p = peak_shape(ot, 0, NL - 1) && peak_shape(ow, 0, NL - 1);
        tb(&t, "100 N ");
        tb_pairs(&t, "outer sliding m/s", BLK_S100, ot, ow, 0, NL - 1, 3);
        tb(&t, "; rises then falls: %s", p ? "yes" : "no");
        add_check(it, "15b", V(p), &t);
        t.n = 0;
        int n = 0;
        for (int k = 0; k < NL; k++) n += it_[k] < iw[k] && ot[k] < ow[k];
        tb(&t, "100 N: sliding TE < WTE at both contacts at %d of %d speeds", n, NL);
        add_check(it, "15c", V(n == NL), &t);
    }
    if (ok1000) {
        double it_[NL], iw[NL], ot[NL], ow[NL], worst = 0.0;
        series(c, LV_L2, BLK_S1000, TE, g_slide_i, it_);
        series(c, LV_L2, BLK_S1000, WTE, g_slide_i, iw);
        series(c, LV_L2, BLK_S1000, TE, g_slide_o, ot);
        series(c, LV_L2, BLK_S1000, WTE, g_slide_o, ow);
        for (int k = 0; k < NL; k++) {
            const acbb_study_point *p = P(c, LV_L2, BLK_S1000, k, TE);
            double u = orbit_speed(&p->last, &p->scene);
            worst = fmax(worst, fmax(it_[k], ot[k]) / u);
        }
        add_val(it, "slide_over_orbit_max_pct_1000N", 100.0 * worst);
        tbuf t = TB(it);
        tb(&t, "1000 N: largest sliding speed / orbital speed omega_m d_m/2 = %.3g %% (TE); "
           "micro-scale if < %.0f %%", 100.0 * worst, 100.0 * REPORT_MICRO);
        if (ok100) {
            double m100 = 0.0;
            for (int k = 0; k < NL; k++) {
                const acbb_study_point *p = P(c, LV_L2, BLK_S100, k, TE);
                m100 = fmax(m100, fmax(p->last.balls[0].slide_i, p->last.balls[0].slide_o)
                                      / orbit_speed(&p->last, &p->scene));
            }
            tb(&t, " (100 N: %.3g %%)", 100.0 * m100);
        }
        add_check(it, "15d", V(worst < REPORT_MICRO), &t);
        t.n = 0;
        int n = 0;
        tb(&t, "1000 N sliding TE/WTE - 1 %% inner, outer:");
        for (int k = 0; k < NL; k++) {
            double ri = it_[k] / iw[k] - 1.0, ro = ot[k] / ow[k] - 1.0;
            n += ri > 0.0 && ri < REPORT_SLIGHT && ro > 0.0 && ro < REPORT_SLIGHT;
            tb(&t, " %g rpm %+.2f, %+.2f%s", k_speeds[k], 100.0 * ri, 100.0 * ro,
               k < NL - 1 ? ";" : "");
        }
        tb(&t, "; slightly larger with TE (0 to +%.0f %%) at %d of %d speeds",
           100.0 * REPORT_SLIGHT, n, NL);
        add_check(it, "15e", V(n == NL), &t);
    }
}

void acbb_study_item16(const acbb_study_runs *c, acbb_study_item *it)
{
    bool ok100 = need(it, "16", c, LV_L2, BLK_S100);
    bool ok1000 = need(it, "16", c, LV_L2, BLK_S1000);
    if (!ok100 || !ok1000) return;
    double si[2][2][NL], so[2][2][NL]; /* [100 N / 1000 N][TE/WTE] */
    for (int h = 0; h < 2; h++)
        for (int m = 0; m < 2; m++) {
            series(c, LV_L2, h ? BLK_S1000 : BLK_S100, m, g_spin_i, si[h][m]);
            series(c, LV_L2, h ? BLK_S1000 : BLK_S100, m, g_spin_o, so[h][m]);
        }
    val_series(it, "spin_i_TE_radps_100N", BLK_S100, si[0][TE], 0, NL - 1);
    val_series(it, "spin_o_TE_radps_100N", BLK_S100, so[0][TE], 0, NL - 1);
    val_series(it, "spin_i_TE_radps_1000N", BLK_S1000, si[1][TE], 0, NL - 1);
    val_series(it, "spin_o_TE_radps_1000N", BLK_S1000, so[1][TE], 0, NL - 1);
    for (int h = 0; h < 2; h++) {
        tbuf t = TB(it);
        bool a = incr(si[h][TE], 0, NL - 1) && incr(si[h][WTE], 0, NL - 1);
        tb(&t, "%s ", h ? "1000 N" : "100 N");
        tb_pairs(&t, "|omega_si| rad/s", BLK_S100, si[h][TE], si[h][WTE], 0, NL - 1, 4);
        tb(&t, "; increases with speed: %s", a ? "yes" : "no");
        add_check(it, h ? "16b" : "16a", V(a), &t);
    }
    /* omega_so as MODEL.md section 4 defines it: signed (it changes sign). */
    double sso[2][NL];
    series(c, LV_L2, BLK_S100, TE, g_spin_o_signed, sso[TE]);
    series(c, LV_L2, BLK_S100, WTE, g_spin_o_signed, sso[WTE]);
    tbuf t = TB(it);
    acbb_study_shape sh[2];
    bool pt = acbb_study_peak_tail(sso[TE], 0, NL - 1, &sh[TE]);
    bool p = acbb_study_peak_tail(sso[WTE], 0, NL - 1, &sh[WTE]) && pt;
    tb(&t, "100 N ");
    tb_pairs(&t, "omega_so (signed) rad/s", BLK_S100, sso[TE], sso[WTE], 0, NL - 1, 4);
    for (int m = 0; m < 2; m++) tb_shape(&t, m ? "; WTE" : "; TE", BLK_S100, sso[m], &sh[m]);
    tb(&t, "; a tail after the low within %.0f %% of the fall (the report's \"approximately "
       "equal\") counts as level; rises then falls: %s", 100.0 * REPORT_SAME, p ? "yes" : "no");
    add_check(it, "16c", V(p), &t);
    t.n = 0;
    int n = 0;
    for (int k = 0; k < NL; k++) n += si[0][TE][k] > si[1][TE][k] && so[0][TE][k] > so[1][TE][k];
    tb(&t, "|omega_si|, |omega_so| at 100 N > at 1000 N (TE) at %d of %d speeds; at 16000 rpm: "
       "%.4g vs %.4g, %.4g vs %.4g rad/s", n, NL, si[0][TE][NL - 1], si[1][TE][NL - 1],
       so[0][TE][NL - 1], so[1][TE][NL - 1]);
    add_check(it, "16d", V(n == NL), &t);
    t.n = 0;
    n = 0;
    int tot = 0;
    double lo = INFINITY, hi = -INFINITY;
    for (int h = 0; h < 2; h++)
        for (int k = 0; k < NL; k++)
            for (int cc = 0; cc < 2; cc++) {
                const double *te = cc ? so[h][TE] : si[h][TE], *w = cc ? so[h][WTE] : si[h][WTE];
                if (w[k] <= 0.0) continue;
                double r = 1.0 - te[k] / w[k];
                lo = fmin(lo, r);
                hi = fmax(hi, r);
                n += r > 0.0 && r < REPORT_SLIGHT;
                tot++;
            }
    tb(&t, "1 - |spin(TE)|/|spin(WTE)| ranges %+.2f %% .. %+.2f %% over both loads, speeds and "
       "contacts; slightly lower with TE (0 to %.0f %%) at %d of %d", 100.0 * lo, 100.0 * hi,
       100.0 * REPORT_SLIGHT, n, tot);
    add_check(it, "16e", V(tot > 0 && n == tot), &t);
    t.n = 0;
    double d0 = so[1][TE][1] - so[1][TE][0], dz = so[1][TE][NL - 1] - so[1][TE][NL - 2];
    bool r = incr(so[1][TE], 0, NL - 1), slow = dz < d0;
    tb(&t, "seed conclusion (7), not in docs/physics.md: 1000 N |omega_so| (TE) increases with speed: "
       "%s; its rise slows at high speed (last step %+.4g < first step %+.4g rad/s): %s",
       r ? "yes" : "no", dz, d0, slow ? "yes" : "no");
    acbb_study_check *ch = add_check(it, "16f", V(r && slow), &t);
    if (ch) ch->info = 1;
}

void acbb_study_item17(const acbb_study_runs *c, acbb_study_item *it)
{
    if (!need(it, "17", c, LV_L2, BLK_LOAD)) return;
    double wx[2][NL], wy[2][NL], wz[2][NL];
    for (int m = 0; m < 2; m++) {
        series(c, LV_L2, BLK_LOAD, m, g_wx, wx[m]);
        series(c, LV_L2, BLK_LOAD, m, g_wy, wy[m]);
        series(c, LV_L2, BLK_LOAD, m, g_wz, wz[m]);
    }
    val_series(it, "abs_omega_x_TE_radps", BLK_LOAD, wx[TE], 0, NL - 1);
    val_series(it, "omega_z_TE_radps", BLK_LOAD, wz[TE], 0, NL - 1);
    val_series(it, "abs_omega_y_TE_radps", BLK_LOAD, wy[TE], 0, NL - 1);
    tbuf t = TB(it);
    bool a = true;
    for (int m = 0; m < 2; m++) {
        double early = wx[m][0] - wx[m][N_LIGHT], late = fabs(wx[m][N_LIGHT] - wx[m][NL - 1]);
        a = a && decr(wx[m], 0, N_LIGHT) && late < REPORT_LEVEL * early;
    }
    tb_pairs(&t, "|omega_x'| rad/s", BLK_LOAD, wx[TE], wx[WTE], 0, NL - 1, 5);
    tb(&t, "; falls over 50-400 N and changes over 400-1000 N by < %.0f %% of that fall: %s",
       100.0 * REPORT_LEVEL, a ? "yes" : "no");
    add_check(it, "17a", V(a), &t);
    t.n = 0;
    bool b = true;
    for (int m = 0; m < 2; m++)
        b = b && incr(wz[m], 0, N_LIGHT - 1) && spread(wz[m], N_LIGHT, NL - 1) < REPORT_FLAT;
    tb_pairs(&t, "omega_z' rad/s", BLK_LOAD, wz[TE], wz[WTE], 0, NL - 1, 5);
    tb(&t, "; rises over 50-200 N and spread over 400-1000 N < %.0f %%: %s",
       100.0 * REPORT_FLAT, b ? "yes" : "no");
    add_check(it, "17b", V(b), &t);
    t.n = 0;
    double rt = wy[TE][NL - 1] / wx[TE][NL - 1], rw = wy[WTE][NL - 1] / wx[WTE][NL - 1];
    tb(&t, "at 1000 N |omega_y'|/|omega_x'| = %.3g %% (TE), %.3g %% (WTE); need < 1 %%",
       100.0 * rt, 100.0 * rw);
    add_check(it, "17c", V(rt < 0.01 && rw < 0.01), &t);
}

/* BE with a huge step against the direct steady solve on the network of
 * the TE 1000 N point, with its final resistances and heat sources. */
/* 18a: zero speed gives no loss and ambient temperatures. */
static void item18_zero(const acbb_study_runs *c, acbb_study_item *it)
{
    const acbb_study_point *z = c->zero;
    tbuf t = TB(it);
    if (!z->ok) {
        tb(&t, "zero-speed run failed (%s): %s", acbb_status_name(z->status), z->message);
        add_check(it, "18a", V_NOT_EVAL, &t);
        return;
    }
    double dT = 0.0;
    for (int i = 0; i < z->last.n_nodes; i++)
        dT = fmax(dT, fabs(z->last.T[i] - z->scene.ambient_C));
    double L = acbb_study_g_total(&z->last);
    add_val(it, "zero_speed_total_loss_W", L);
    add_val(it, "zero_speed_max_dT_K", dT);
    tb(&t, "0 rpm, %g N: total loss %.3g W, max |T - T_amb| %.3g K over %d nodes; need 0 "
       "(<= 1e-12 W, 1e-9 K)", z->scene.axial_load, L, dT, z->last.n_nodes);
    add_check(it, "18a", V(L <= 1e-12 && dT <= 1e-9), &t);
}

/* 18b: the steady energy balance the engine publishes (heat_in, heat_out of
 * the snapshot); 18d: no loss term below zero at any step of any run. */
static void item18_balance(const acbb_study_runs *c, acbb_study_item *it)
{
    tbuf t = TB(it);
    double worst = 0.0, worst_abs = 0.0, min_loss = INFINITY;
    size_t n_ok = 0;
    const char *wl = "";
    for (size_t i = 0; i < c->n; i++) {
        const acbb_study_point *p = &c->all[i];
        min_loss = fmin(min_loss, p->min_loss);
        if (!p->ok) continue;
        n_ok++;
        double in = p->last.heat_in, d = fabs(in - p->last.heat_out);
        if (in > 0.0 && d / in >= worst) {
            worst = d / in;
            wl = p->label;
        }
        if (in <= 0.0) worst_abs = fmax(worst_abs, d);
    }
    add_val(it, "energy_balance_worst_rel", worst);
    tb(&t, "energy balance at steady state over %zu converged runs: worst |in-out|/in = %.3g "
       "(%s), worst |in-out| with no heat %.3g W; need <= 1e-6 (1e-9 W)", n_ok, worst, wl,
       worst_abs);
    add_check(it, "18b", n_ok ? V(worst <= 1e-6 && worst_abs <= 1e-9) : V_NOT_EVAL, &t);

    t.n = 0;
    add_val(it, "min_loss_term_W", min_loss);
    tb(&t, "smallest loss term (any of the five, or any ball's share) at any step of any run: "
       "%.3g W; need >= 0", min_loss);
    add_check(it, "18d", isfinite(min_loss) ? V(min_loss >= 0.0) : V_NOT_EVAL, &t);
}

void acbb_study_item18(const acbb_study_runs *c, acbb_study_item *it)
{
    item18_zero(c, it);
    item18_balance(c, it);
    /* The other two sanity statements need the physics recomputed below the
     * sim API; they are tests, not study checks (the study reads snapshots
     * only). Reported so the reader knows where they are judged. */
    tbuf t = TB(it);
    tb(&t, "the static thrust solution vs the closed-form relation of docs/physics.md section 3 "
       "(bisection, K_n at the operating angle), to 1e-4: judged by tests/test_study.c, "
       "not from the study's runs");
    acbb_study_check *ch = add_check(it, "18c", V_NOT_EVAL, &t);
    if (ch) ch->info = 1;
    t.n = 0;
    tb(&t, "backward Euler with dt -> infinity vs the direct steady solve of the thermal "
       "network: judged by tests/test_study.c, not from the study's runs");
    ch = add_check(it, "18e", V_NOT_EVAL, &t);
    if (ch) ch->info = 1;
}
