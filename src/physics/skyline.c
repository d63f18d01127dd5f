/* acbb — envelope Cholesky (skyline.h). Row-oriented ("bordering") form:
 * row i of L from the rows above it, each inner product over the
 * columns both rows have inside their envelopes. */
#include <math.h>
#include "skyline.h"

int acbb_skyline_factor(double *A, int n, int lda, int *first)
{
    for (int i = 0; i < n; i++) {
        double *Li = A + (long)i * lda;
        int f = first[i] < i ? first[i] : i;
        while (f < i && Li[f] == 0.0) f++;
        first[i] = f;
        for (int j = f; j < i; j++) {
            const double *Lj = A + (long)j * lda;
            int k0 = f > first[j] ? f : first[j];
            double s = Li[j];
            for (int k = k0; k < j; k++) s -= Li[k] * Lj[k];
            Li[j] = s / Lj[j];
        }
        double d = Li[i];
        for (int k = f; k < i; k++) d -= Li[k] * Li[k];
        if (!(d > 0.0) || !isfinite(d)) return 0;
        Li[i] = sqrt(d);
    }
    return 1;
}

void acbb_skyline_solve(const double *L, int n, int lda, const int *first, const double *b,
                        double *x)
{
    for (int i = 0; i < n; i++) { /* L y = b */
        const double *Li = L + (long)i * lda;
        double s = b[i];
        for (int k = first[i]; k < i; k++) s -= Li[k] * x[k];
        x[i] = s / Li[i];
    }
    for (int i = n - 1; i >= 0; i--) { /* L^T x = y, column i of L^T is row i of L */
        const double *Li = L + (long)i * lda;
        x[i] /= Li[i];
        for (int k = first[i]; k < i; k++) x[k] -= Li[k] * x[i];
    }
}
