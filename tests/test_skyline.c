/* The envelope Cholesky of the thermal network (src/physics/skyline.h,
 * issue 30 lever 3): on a hand-factored 3x3, on network-like sparse
 * M-matrices against GSL's dense Cholesky (the factor it replaced), and
 * the refusal of a matrix that is not positive definite. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>
#include "tap.h"
#include "skyline.h"

#define N 40

/* A = [4 2 0; 2 5 3; 0 3 10]: L = [2 0 0; 1 2 0; 0 1.5 sqrt(7.75)];
 * row 2's envelope starts at column 1 (A[2][0] = 0). */
static void test_hand(void)
{
    double A[9] = { 4, 2, 0, 2, 5, 3, 0, 3, 10 };
    int first[3] = { 0, 0, 0 };
    ok(acbb_skyline_factor(A, 3, 3, first), "3x3: positive definite");
    ok(A[0] == 2 && A[3] == 1 && A[4] == 2 && A[7] == 1.5 && fabs(A[8] - sqrt(7.75)) < 1e-15
       && first[0] == 0 && first[1] == 0 && first[2] == 1,
       "3x3: L = [2; 1 2; 0 1.5 %.15g], envelope starts 0 0 %d", A[8], first[2]);
    double b[3] = { 6, 10, 13 }, x[3]; /* A [1 1 1] */
    acbb_skyline_solve(A, 3, 3, first, b, x);
    ok(fabs(x[0] - 1) < 1e-14 && fabs(x[1] - 1) < 1e-14 && fabs(x[2] - 1) < 1e-14,
       "3x3: solves A x = A [1 1 1] (%.17g %.17g %.17g)", x[0], x[1], x[2]);
}

/* A conductance matrix: a chain plus random couplings, some nodes
 * grounded (diagonal excess) or with capacity: symmetric, positive
 * definite, sparse. */
static void network(double *A, unsigned *seed)
{
    memset(A, 0, sizeof(double) * N * N);
    for (int e = 0; e < 3 * N; e++) {
        int a = e < N - 1 ? e : rand_r(seed) % N, b = e < N - 1 ? e + 1 : rand_r(seed) % N;
        if (a == b) continue;
        double g = 0.01 + (rand_r(seed) % 1000) / 10.0;
        A[a * N + a] += g;
        A[b * N + b] += g;
        A[a * N + b] -= g;
        A[b * N + a] -= g;
    }
    for (int i = 0; i < N; i += 7) A[i * N + i] += 0.5; /* to ground */
}

static void test_against_gsl(void)
{
    unsigned seed = 30;
    double worst = 0.0;
    for (int t = 0; t < 20; t++) {
        static double A[N * N], B[N * N];
        network(A, &seed);
        memcpy(B, A, sizeof A);
        int first[N] = { 0 };
        double b[N], x[N], y[N];
        for (int i = 0; i < N; i++) b[i] = (rand_r(&seed) % 200) - 100.0;
        int okf = acbb_skyline_factor(A, N, N, first);
        acbb_skyline_solve(A, N, N, first, b, x);
        gsl_matrix_view G = gsl_matrix_view_array(B, N, N);
        gsl_vector_view bv = gsl_vector_view_array(b, N), yv = gsl_vector_view_array(y, N);
        gsl_linalg_cholesky_decomp1(&G.matrix);
        gsl_linalg_cholesky_solve(&G.matrix, &bv.vector, &yv.vector);
        double scale = 0.0;
        for (int i = 0; i < N; i++) scale = fmax(scale, fabs(y[i]));
        for (int i = 0; i < N && okf; i++) worst = fmax(worst, fabs(x[i] - y[i]) / scale);
        if (!okf) worst = INFINITY;
    }
    ok(worst < 1e-12, "20 network matrices 40x40: the solution agrees with GSL's dense "
       "Cholesky to %.2g of its largest entry", worst);
}

static void test_not_definite(void)
{
    double A[4] = { 1, 2, 2, 1 }; /* eigenvalues 3, -1 */
    int first[2] = { 0, 0 };
    ok(!acbb_skyline_factor(A, 2, 2, first), "[1 2; 2 1] is refused (not positive definite)");
    double Z[4] = { 1, 0, 0, 0 };
    first[0] = first[1] = 0;
    ok(!acbb_skyline_factor(Z, 2, 2, first), "a zero pivot is refused");
}

/* first[] on entry bounds each row's envelope from the left (the thermal
 * network passes its rows' first couplings, issue 30): what lies left of
 * it is not read, and the factor and envelope are the bits of a factor
 * that scans every row from column 0. */
static void test_envelope_bound(void)
{
    unsigned seed = 31;
    static double A[N * N], B[N * N];
    network(A, &seed);
    memcpy(B, A, sizeof A);
    int fa[N] = { 0 }, fb[N];
    for (int i = 0; i < N; i++) { /* the structural first, garbage left of it */
        fb[i] = i;
        for (int k = 0; k < i; k++)
            if (B[i * N + k] != 0.0 && k < fb[i]) fb[i] = k;
        for (int k = 0; k < fb[i]; k++) B[i * N + k] = NAN;
    }
    int oka = acbb_skyline_factor(A, N, N, fa), okb = acbb_skyline_factor(B, N, N, fb);
    int same = oka && okb && !memcmp(fa, fb, sizeof fa);
    for (int i = 0; i < N && same; i++)
        same = !memcmp(A + i * N + fa[i], B + i * N + fb[i], sizeof(double) * (size_t)(i - fa[i] + 1));
    ok(same, "40x40 network: first[] given as each row's first coupling, NaN left of it: the "
       "factor and envelope of the scan from column 0, bit for bit");
}

int main(void)
{
    test_hand();
    test_against_gsl();
    test_not_definite();
    test_envelope_bound();
    return done_testing();
}
