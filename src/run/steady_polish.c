/* acbb — the steady polish's relaxation and stopping (steady_polish.h).
 *
 * Adaptive rather than MODEL.md section 9's fixed 0.5: a polish that
 * contracts keeps plain Picard (the path, and so every result, of the
 * presets that converged before stays bit for bit, and modes with a gain
 * near +1 are not slowed down), and halving on growth damps any gain
 * below -1, where a fixed 0.5 fails below -3, and on reversing moves that
 * shrink too slowly to converge within the cap (a gain near -1). */
#include <math.h>
#include "steady_polish.h"
#include "dynamic.h"

double acbb_polish_loss_rtol(const acbb_scene *s)
{
    return s->model == ACBB_MODEL_DYNAMIC ? fmax(s->mech_tol, ACBB_DYN_RTOL) : s->mech_tol;
}

double acbb_polish_resolution(double mech_tol, const double *T, int n)
{
    double lo = T[0], hi = T[0];
    for (int i = 1; i < n; i++) {
        lo = fmin(lo, T[i]);
        hi = fmax(hi, T[i]);
    }
    return fmax(mech_tol, ACBB_POLISH_REUSE_TOL) * (hi - lo);
}

double acbb_polish_turn(double *prev, const double *T, const double *Tn, double relax, int n)
{
    double dot = 0.0, pp = 0.0, mm = 0.0;
    for (int i = 0; i < n; i++) {
        double m = (Tn[i] - T[i]) / relax;
        dot += m * prev[i];
        pp += prev[i] * prev[i];
        mm += m * m;
        prev[i] = m;
    }
    return pp > 0.0 && mm > 0.0 ? dot / sqrt(pp * mm) : 0.0;
}

/* The tolerance of a polish at relaxation `relax` (steady_polish.h). */
static double tolerance(double relax, double resolution_K)
{
    return relax < 1.0 ? fmax(resolution_K, ACBB_POLISH_TOL_K) : ACBB_POLISH_TOL_K;
}

/* Converged: to the round-off tolerance when undamped, else to the map's
 * resolution (steady_polish.h). */
static int converged(const acbb_polish_result *r, double resolution_K)
{
    return r->residual < ACBB_POLISH_TOL_K || (r->relax < 1.0 && r->residual < resolution_K);
}

/* Whether the last residual, after `prev`, asks to halve the relaxation
 * (steady_polish.h): growth or a standstill (|rho| >= 1), or a reversing
 * move whose ratio rho < -1/3 (halving shrinks |rho|) would not reach the
 * tolerance within the cap at its rate. Growth below the noise band is
 * not judged. */
static int overshoots(const acbb_polish_result *r, double prev, double turn,
                      double resolution_K)
{
    if (r->residual <= ACBB_POLISH_NOISE_FACTOR * resolution_K) return 0;
    if (r->residual >= prev) return 1;
    double ratio = r->residual / prev;
    int left = ACBB_POLISH_ITERS - r->iterations;
    return turn < 0.0 && ratio > 1.0 / 3.0
           && r->residual * pow(ratio, left) >= tolerance(r->relax, resolution_K);
}

void acbb_relax_start(acbb_relax_ctl *c)
{
    c->relax = 1.0;
    c->prev = INFINITY;
    c->made_by = 1.0;
    c->judged = 0;
}

/* This residual judges the previous move's relaxation: halve only if that
 * move was made at the relaxation still in force, and not on the second
 * residual: the first step changes the map itself (sim.c: every ball
 * recomputed; a set: its joined network's resistances, lagged in the
 * transient, synced), so the first residual is not comparable. An equal
 * residual (a gain of -1, a two-state cycle) is no progress either. */
void acbb_relax_judge(acbb_relax_ctl *c, double w, double residual, double floor_K)
{
    c->judged++;
    if (c->judged > 2 && residual >= c->prev && residual > floor_K && c->made_by == c->relax)
        c->relax = fmax(0.5 * c->relax, ACBB_POLISH_RELAX_MIN);
    c->prev = residual;
    c->made_by = w;
}

int acbb_relax_reject(acbb_relax_ctl *c, acbb_status rc)
{
    if ((rc != ACBB_CONTACT_LOST && rc != ACBB_DIVERGED) || c->relax <= ACBB_POLISH_RELAX_MIN)
        return 0;
    c->relax = fmax(0.5 * c->relax, ACBB_POLISH_RELAX_MIN);
    return 1;
}

acbb_status acbb_polish_iterate(acbb_polish_step step, void *ctx, double resolution_K,
                                acbb_polish_result *out, acbb_error *err)
{
    acbb_polish_result r = { 0, 0.0, 1.0 };
    double prev = INFINITY, made_by = 1.0; /* relaxation of the move that led here */
    acbb_status rc;
    for (;;) {
        if (r.iterations == ACBB_POLISH_ITERS) {
            /* Stalled within the noise band: steady to the map's resolution. */
            if (r.residual < ACBB_POLISH_NOISE_FACTOR * resolution_K) {
                rc = ACBB_OK;
                break;
            }
            rc = acbb_error_set(err, ACBB_DIVERGED, "the steady iteration did not converge: "
                                "residual %.3g K after %d iterations (relaxation %g, tolerance "
                                "%.3g K)", r.residual, r.iterations, r.relax,
                                tolerance(r.relax, resolution_K));
            break;
        }
        double w = r.relax, turn = 0.0;
        if ((rc = step(ctx, w, &r.residual, &turn, err)) != ACBB_OK) break;
        r.iterations++;
        if (converged(&r, resolution_K)) break;
        /* This residual judges the previous move's relaxation: halve only
         * if that move was made at the relaxation still in force, and not
         * on the second residual: the first step changes the map itself
         * (sim.c: every ball recomputed; a set: its joined network's
         * resistances, lagged in the transient, synced), so the first
         * residual is not comparable. An equal residual (a gain of -1, a
         * two-state cycle) is no progress either, nor is a slow one. */
        if (r.iterations > 2 && made_by == r.relax && overshoots(&r, prev, turn, resolution_K))
            r.relax = fmax(0.5 * r.relax, ACBB_POLISH_RELAX_MIN);
        prev = r.residual;
        made_by = w;
    }
    if (out) *out = r;
    return rc;
}

acbb_status acbb_balance_check(double in, double out, acbb_error *err)
{
    if (fabs(in - out) <= fmax(ACBB_BALANCE_TOL * fabs(in), ACBB_BALANCE_FLOOR_W)) return ACBB_OK;
    return acbb_error_set(err, ACBB_UNBALANCED, "the network's heat balance does not close at "
                          "the steady state (%.6g W in, %.6g W out, tolerance %g of the heat in "
                          "or %g W); last state kept", in, out, ACBB_BALANCE_TOL,
                          ACBB_BALANCE_FLOOR_W);
}
