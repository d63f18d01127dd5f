/* acbb — envelope (skyline) Cholesky of a symmetric positive definite
 * matrix, for the thermal network (thermal_network.c, issue 30 lever 3).
 * A network node couples to a few neighbours, so row i of its matrix is
 * zero left of some column first[i]; L = chol(A) keeps that envelope
 * (George & Liu, Computer Solution of Large Sparse Positive Definite
 * Systems, 1981, ch. 4), and the factor costs sum over rows of the
 * envelope's width squared instead of n^3 / 3. */
#ifndef ACBB_SKYLINE_H
#define ACBB_SKYLINE_H

/* Factor the n x n matrix A (row-major, row stride lda; the lower
 * triangle is read) in place into L (lower triangle; the upper one is
 * left alone). first[i] gives, on entry, a column left of which row i is
 * zero (0 when not known; entries left of it are not read) and receives
 * row i's envelope start (its first nonzero). Returns 0 if A is not
 * positive definite (a pivot <= 0 or not finite). */
int acbb_skyline_factor(double *A, int n, int lda, int *first);

/* Solve L L^T x = b with the factor and envelope from
 * acbb_skyline_factor; x may be b. */
void acbb_skyline_solve(const double *L, int n, int lda, const int *first, const double *b,
                        double *x);

#endif
