/* acbb — Broyden's method for the small systems of the solvers (n <= 4):
 * the ring equilibrium (MODEL.md section 3) and the Level-2 ball speeds
 * (section 4). Between two thermal steps their roots move little, so a
 * Jacobian kept from the last solve and updated by rank-one corrections
 * replaces a finite-difference Jacobian (n + 1 evaluations) per iteration.
 * The callers fall back to their GSL hybrid solvers when it stalls. */
#ifndef ACBB_BROYDEN_H
#define ACBB_BROYDEN_H

#define ACBB_BROYDEN_MAX 4

/* Residual f(x) of an n-system; returns 0 if it could not be evaluated. */
typedef int (*acbb_broyden_fn)(const double *x, void *ctx, double *f);

/* From x with Jacobian J (row-major n x n, updated in place), iterate
 * until sum |f_i| < tol (GSL's residual test). Returns 1 on success: x is
 * the root, f its residual and the last evaluation was at x. Returns 0
 * after maxit steps, on a singular J, or as soon as a step halved
 * `halvings` times (0: the full step only) does not lower sum |f| (by 10 %
 * when halvings > 0) (then x and J are left at the last good point). */
int acbb_broyden(acbb_broyden_fn fn, void *ctx, int n, double *J, double *x, double *f,
                 double tol, int maxit, int halvings);

/* acbb_broyden with options: halvings as there; a step from a residual
 * sum below `noise` leaves J as it is (a residual with noise, the ring's:
 * sums of ball solves each converged to its tolerance; such a step's
 * change of f is mostly noise and would corrupt the Jacobian the next
 * solves start from); have_f: f holds f(x) already (not evaluated again;
 * the last evaluation may then have been elsewhere until the first step). */
typedef struct {
    int halvings;
    double noise;
    int have_f;
} acbb_broyden_opts;

int acbb_broyden_ex(acbb_broyden_fn fn, void *ctx, int n, double *J, double *x, double *f,
                    double tol, int maxit, const acbb_broyden_opts *o);

/* The Newton step: solve J d = -f (J row-major n x n, n <= 4) by Gaussian
 * elimination with partial pivoting; 0 if J is singular or d not finite. */
int acbb_newton_step(int n, const double *J, const double *f, double *d);

/* Forward-difference Jacobian at x with f = fn(x) given, steps
 * h_j = rel |x_j| (rel where x_j = 0). Returns 0 on a failed evaluation. */
int acbb_fd_jacobian(acbb_broyden_fn fn, void *ctx, int n, const double *x, const double *f,
                     double rel, double *J);

#endif
