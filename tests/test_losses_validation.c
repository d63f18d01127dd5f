/* The extended losses (MODEL.md 16) against a published friction model:
 * the SKF model for the frictional moment (SKF general catalogue 6000,
 * 2003/2005, "The SKF model for calculating the frictional moment"):
 *   M = M_rr + M_sl,  M_rr = phi_ish phi_rs G_rr (nu n)^0.6,
 *   M_sl = G_sl mu_sl,  mu_sl = phi_bl 0.15 + (1 - phi_bl) 0.05,
 *   phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64),
 *   phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))),
 *   phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m)           (N mm, mm, rpm, mm^2/s)
 * with the geometric constants of its tables (deep groove 60 series:
 * R1 4.1e-7, R2 1.7, S1 3.73e-3, S2 14.6; single-row angular contact
 * 72 B / 73 B: R1 5.03e-7, R2 1.97, R3 1.90e-12, S1 1.30e-2, S2 0.68,
 * S3 1.91e-12 -- the same values in two independent public implementations
 * of the SKF model (docs/losses_validation.md; the catalogue page itself
 * not reached), and the 7008C is a 70 C bearing outside that table).
 * Nothing is fitted.
 *
 * Each point runs acbb isothermal at 40 C (effects.heating = off, ambient
 * 40 C, nu40 = 30 mm^2/s, oil-air) with the seed set and with the
 * extended set, and converts the total loss to a moment P / omega_i.
 * `test_losses_validation --md` prints docs/losses_validation.md's table;
 * as a test it recomputes the table and checks every ratio against the
 * committed document (0.5 %): the comparison stays where it is. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "acbb/tools/designation.h"
#include "acbb/sim.h"
#include "skf_model.h"

#define DOC "docs/losses_validation.md"
#define RPM (2.0 * M_PI / 60.0)

/* The SKF model's moment, N mm (skf_model.h). */
static double skf_moment(const skf_bearing *k, double d, double D, double n, double nu,
                         double Fr, double Fa, double *Mrr)
{
    double Msl;
    return skf_moment_parts(k, d, D, n, nu, Fr, Fa, Mrr, &Msl);
}

/* acbb's frictional moment, N mm, of scene s with the given loss set;
 * *roll: the rolling part (P_r + P_e) as a moment. */
static double acbb_moment(acbb_scene s, int extended, int *good, double *roll)
{
    s.loss_ehl_rolling = s.loss_churning = extended;
    acbb_sim *sim = NULL;
    acbb_error err = { "" };
    acbb_snapshot snap;
    *good = acbb_sim_create(&s, NULL, &sim, &err) == ACBB_OK && acbb_sim_run(sim) == ACBB_OK;
    if (sim) acbb_sim_snapshot(sim, &snap);
    acbb_sim_free(sim);
    *roll = *good ? (snap.losses.P[ACBB_LOSS_ROLLING] + snap.losses.P[ACBB_LOSS_EHL_ROLLING])
                        / s.inner_speed * 1e3 : NAN;
    return *good ? snap.losses.total / s.inner_speed * 1e3 : NAN;
}

typedef struct {
    const char *name;
    double n, Fr, Fa;
    double seed, ext, skf, roll, skf_rr;
} row;

static void base(acbb_scene *s, const char *name)
{
    acbb_designation d;
    acbb_error err = { "" };
    if (strcmp(name, "7008C") == 0) acbb_scene_default(s);
    else if (acbb_designation_parse(name, &d, &err) == ACBB_OK)
        acbb_designation_scene(&d, s, NULL, 0);
    s->heating = false;
    s->ambient_C = 40.0;
    s->oil_nu40 = 30e-6;
    s->lub_method = ACBB_LUB_OIL_AIR;
}

static int compute(row *r, int cap)
{
    static const double n6008[] = { 1000, 3000, 6000, 10000 }, F6008[] = { 200, 500, 1000 };
    static const double n7008[] = { 2000, 5000, 10000, 15000 }, F7008[] = { 300, 1000 };
    int k = 0, good = 1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4 && k < cap; j++, k++)
            r[k] = (row){ "6008", n6008[j], F6008[i], 0, 0, 0, 0, 0, 0 };
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 4 && k < cap; j++, k++)
            r[k] = (row){ "7008C", n7008[j], 0, F7008[i], 0, 0, 0, 0, 0 };
    for (int i = 0; i < k; i++) {
        acbb_scene s;
        base(&s, r[i].name);
        s.inner_speed = r[i].n * RPM;
        s.radial_load = r[i].Fr;
        s.axial_load = r[i].Fa;
        int g1, g2;
        double roll0;
        r[i].seed = acbb_moment(s, 0, &g1, &roll0);
        r[i].ext = acbb_moment(s, 1, &g2, &r[i].roll);
        const skf_bearing *kb = strcmp(r[i].name, "6008") == 0 ? &k_dgbb60 : &k_acbb72b;
        r[i].skf = skf_moment(kb, s.bore * 1e3, s.outer_diameter * 1e3, r[i].n, 30.0, r[i].Fr,
                              r[i].Fa, &r[i].skf_rr);
        if (!(g1 && g2))
            printf("# %s %.0f rpm Fr %.0f Fa %.0f: %s set did not converge\n", r[i].name,
                   r[i].n, r[i].Fr, r[i].Fa, g1 ? "extended" : "seed");
        good &= g1 && g2;
    }
    return good ? k : -1;
}

static void print_md(const row *r, int n)
{
    printf("| bearing | n rpm | Fr N | Fa N | acbb seed set N mm | acbb extended N mm "
           "| SKF model N mm | seed / SKF | extended / SKF | acbb P_r + P_e N mm "
           "| SKF M_rr N mm | (P_r + P_e) / M_rr |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < n; i++)
        printf("| %s | %.0f | %.0f | %.0f | %.3f | %.3f | %.3f | %.4f | %.4f | %.3f | %.3f "
               "| %.4f |\n", r[i].name, r[i].n, r[i].Fr, r[i].Fa, r[i].seed, r[i].ext, r[i].skf,
               r[i].seed / r[i].skf, r[i].ext / r[i].skf, r[i].roll, r[i].skf_rr,
               r[i].roll / r[i].skf_rr);
}

/* The ratios of the committed table, in row order. */
static int doc_ratios(double *seed, double *ext, int cap)
{
    static double v[32][SKF_DOC_COLS];
    int n = skf_doc_table(DOC, "| bearing | n rpm | Fr N | Fa N | acbb seed set", v, 8,
                          cap < 32 ? cap : 32);
    for (int i = 0; i < n; i++) {
        seed[i] = v[i][6];
        ext[i] = v[i][7];
    }
    return n;
}

int main(int argc, char **argv)
{
    row r[32];
    int n = compute(r, 32);
    if (argc > 1 && strcmp(argv[1], "--md") == 0) {
        if (n < 0) return 1;
        print_md(r, n);
        return 0;
    }
    ok(n == 20, "20 points computed, every run converged");
    double ds[32], de[32];
    int m = doc_ratios(ds, de, 32);
    ok(m == n, "%s lists the same %d points (%d)", DOC, n, m);
    for (int i = 0; i < n && i < m; i++) {
        double rs = r[i].seed / r[i].skf, re = r[i].ext / r[i].skf;
        ok(fabs(rs / ds[i] - 1) < 5e-3 && fabs(re / de[i] - 1) < 5e-3,
           "%s %.0f rpm Fr %.0f Fa %.0f: seed/SKF %.3f (doc %.3f), extended/SKF %.3f (doc %.3f)",
           r[i].name, r[i].n, r[i].Fr, r[i].Fa, rs, ds[i], re, de[i]);
    }
    /* the physics the issue asks for: the extended set adds a speed-driven
     * part, so its moment grows with speed where the seed set's barely does */
    ok(r[3].ext / r[0].ext > r[3].seed / r[0].seed, "6008 200 N: extended moment grows faster "
       "with speed (x%.2f) than the seed set's (x%.2f)", r[3].ext / r[0].ext, r[3].seed / r[0].seed);
    return done_testing();
}
