/* The SKF model for the frictional moment (SKF general catalogue 6000,
 * 2003/2005, "The SKF model for calculating the frictional moment"), as
 * docs/losses_validation.md states its sources (header-only, for tests):
 *   M = M_rr + M_sl,  M_rr = phi_ish phi_rs G_rr (nu n)^0.6,
 *   M_sl = G_sl mu_sl,  mu_sl = phi_bl 0.15 + (1 - phi_bl) 0.05,
 *   phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64),
 *   phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))),
 *   phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m)          (N mm, mm, rpm, mm^2/s)
 * with the geometric constants of its tables (deep groove 60 series:
 * R1 4.1e-7, R2 1.7, S1 3.73e-3, S2 14.6, K_Z 3.1; single-row angular
 * contact 72 B / 73 B: R1 5.03e-7, R2 1.97, R3 1.90e-12, S1 1.30e-2,
 * S2 0.68, S3 1.91e-12, K_Z 4.4). Oil-air: K_rs = 6e-8; no seal and no
 * drag term. Nothing is fitted. */
#ifndef ACBB_TEST_SKF_MODEL_H
#define ACBB_TEST_SKF_MODEL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    int angular;
    double R1, R2, R3, S1, S2, S3, K_Z;
} skf_bearing;

static const skf_bearing k_dgbb60 = { 0, 4.1e-7, 1.7, 0, 3.73e-3, 14.6, 0, 3.1 };
static const skf_bearing k_acbb72b = { 1, 5.03e-7, 1.97, 1.90e-12, 1.30e-2, 0.68, 1.91e-12, 4.4 };

/* The SKF model's moment, N mm, of a bearing d x D mm at n rpm, nu mm^2/s,
 * loads Fr, Fa N; *Mrr its rolling part, *Msl its sliding part. */
static double skf_moment_parts(const skf_bearing *k, double d, double D, double n, double nu,
                               double Fr, double Fa, double *Mrr, double *Msl)
{
    double dm = 0.5 * (d + D), Grr, Gsl;
    if (!k->angular) {
        Grr = k->R1 * pow(dm, 1.96) * pow(Fr, 0.54);
        Gsl = k->S1 * pow(dm, -0.26) * pow(Fr, 5.0 / 3.0);
    } else {
        double Fg = k->R3 * pow(dm, 4) * n * n, Fgs = k->S3 * pow(dm, 4) * n * n;
        Grr = k->R1 * pow(dm, 1.97) * pow(Fr + Fg + k->R2 * Fa, 0.54);
        Gsl = k->S1 * pow(dm, 0.26) * (pow(Fr + Fgs, 4.0 / 3.0) + k->S2 * pow(Fa, 4.0 / 3.0));
    }
    double ish = 1.0 / (1.0 + 1.84e-9 * pow(n * dm, 1.28) * pow(nu, 0.64));
    double rs = exp(-6e-8 * nu * n * (d + D) * sqrt(k->K_Z / (2.0 * (D - d))));
    double bl = exp(-2.6e-8 * pow(n * nu, 1.4) * dm);
    *Mrr = ish * rs * Grr * pow(nu * n, 0.6);
    *Msl = Gsl * (bl * 0.15 + (1.0 - bl) * 0.05);
    return *Mrr + *Msl;
}

/* The rows of a markdown table of `path` whose header line starts with
 * `header`: each row's numeric cells after the first (the bearing's name),
 * up to `ncols` of them, into v[row][col] (cells that are not numbers: 0).
 * Returns the rows read (at most cap), -1 if the file cannot be read. */
#define SKF_DOC_COLS 16
static int skf_doc_table(const char *path, const char *header, double (*v)[SKF_DOC_COLS],
                         int ncols, int cap)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    char line[512];
    int n = 0, in = 0;
    while (fgets(line, sizeof line, f) && n < cap) {
        if (!in) {
            in = strncmp(line, header, strlen(header)) == 0;
            if (in && !fgets(line, sizeof line, f)) break;   /* the |---| line */
            continue;
        }
        if (line[0] != '|') break;   /* the blank line after the table */
        char *cell = strchr(line + 1, '|');
        for (int k = 0; k < ncols && k < SKF_DOC_COLS; k++) {
            v[n][k] = cell ? strtod(cell + 1, NULL) : 0.0;
            cell = cell ? strchr(cell + 1, '|') : NULL;
        }
        n++;
    }
    fclose(f);
    return n;
}

#endif
