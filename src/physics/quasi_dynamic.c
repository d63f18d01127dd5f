/* acbb — Level-2 quasi-dynamic kinematics, MODEL.md section 4.
 *
 * Unknowns per ball, scaled by omega_i: x = (omega_m, wx, wy, wz) / omega_i.
 * Equations (orbiting frame, free ball, no cage force):
 *   y' force:  F_i,y + F_o,y + F_drag = 0        (drag along +y')
 *   moments:   M_i + M_o = J omega_m (0, -wz, wy)
 * solved by GSL's hybridsj with a finite-difference Jacobian of fixed
 * absolute steps (GSL's own relative steps fail at wy ~ 0). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include "quasi_dynamic.h"
#include "broyden.h"

#define FD_STEP 1e-7
#define MIN_LOAD 1e-3      /* N: below this a contact cannot drive the ball */
#define RES_TOL 1e-10
/* Residual that ends a transient step's solve in a scene of many distinct
 * balls (acbb_qd_set_skip > 0 with acbb_qd_set_path): those steps already
 * keep a ball's speeds while its inputs move < 3e-3, a far larger error
 * than this; the steady polish solves every ball to RES_TOL again. The
 * combined-load run then ends within 1.4e-9 of RES_TOL throughout, its
 * steps and time to steady state the same; at 1e-3 the time moved one
 * step (BENCHMARKS.md, issue 30, sixth round). */
#define PATH_RES_TOL 1e-4
#define STALE_EVALS 4 /* a Broyden solve of more residuals: its Jacobian had gone stale */
#define PRED_INPUTS 7  /* loads, angles, inlet viscosities, inner-ring speed */

/* What Level 2 keeps of one ball from update to update. */
typedef struct {
    /* Last Jacobian (scaled unknowns and residuals) for the Broyden steps
     * of the next update; J_ok = 0: none yet. */
    double J[16];
    int J_ok;
    /* 1: the last Broyden solve was slow, the next one starts from the
     * analytic Jacobian (the kept one had gone stale) */
    int J_stale;
    /* Inputs of the last solve (acbb_ball_inputs); in_ok = 0: none. */
    double in[ACBB_BALL_INPUTS];
    int in_ok;
    double tol_used; /* the residual the last solve ended below */
    /* The last two roots and the inputs they were solved at (PRED_INPUTS
     * of them), newest first; nh: how many are kept. */
    double xh[2][4], uh[2][PRED_INPUTS];
    int nh;
} qd_ball;

struct acbb_qd {
    acbb_traction_contact ci, co;
    gsl_multiroot_fdfsolver *solver;
    double skip_tol;    /* 0: every update solves every ball */
    int path;           /* 1: transient steps (acbb_qd_set_path): predicted starts */
    int used;           /* b[used..] are all zero (no update reached them) */
    qd_ball b[ACBB_MAX_BALLS]; /* last: acbb_qd_renew clears all before it */
};

typedef struct {
    const acbb_scene *s;
    const acbb_traction_contact *ci, *co;
    double omega_i, J, D, Fscale;
    const acbb_mixture *mix;
    acbb_traction tri, tro;
    int evals;          /* residuals evaluated by eval (the Broyden steps) */
    double tol;         /* sum |f| that ends a solve (qd_tol) */
} qd_ctx;

/* The Level-2 residual f at scaled speeds x (plain arrays): 0 on a
 * non-finite value. */
static int residual(const double *x, qd_ctx *c, double *f)
{
    double wi = c->omega_i;
    double wm = wi * x[0];
    double wb[3] = { wi * x[1], wi * x[2], wi * x[3] };
    acbb_traction_eval(c->s, c->ci, wb, wi - wm, &c->tri);
    acbb_traction_eval(c->s, c->co, wb, -wm, &c->tro);
    double Fv = c->s->loss_drag ? acbb_drag_force(c->s, c->mix, wm) : 0.0;
    /* The gyroscopic moment omega_m x J omega_b (MODEL.md 4), off with its switch. */
    double gy = c->s->gyroscopic ? c->J : 0.0;
    double Mreq[3] = { 0.0, -gy * wm * wb[2], gy * wm * wb[1] };
    double Ms = c->Fscale * 0.5 * c->D;
    f[0] = (c->tri.F[1] + c->tro.F[1] + Fv) / c->Fscale;
    for (int d = 0; d < 3; d++) f[1 + d] = (c->tri.M[d] + c->tro.M[d] - Mreq[d]) / Ms;
    for (int d = 0; d < 4; d++)
        if (!isfinite(f[d])) return 0;
    return 1;
}

/* residual for GSL's solvers (vectors of any stride). */
static int qd_f(const gsl_vector *x, void *p, gsl_vector *f)
{
    double xv[4], fv[4];
    for (int d = 0; d < 4; d++) xv[d] = gsl_vector_get(x, d);
    int ok = residual(xv, p, fv);
    for (int d = 0; d < 4; d++) gsl_vector_set(f, d, fv[d]);
    return ok ? GSL_SUCCESS : GSL_EBADFUNC;
}

/* Residual as qd_f and its Jacobian J (row-major, scaled unknowns) from
 * the analytic traction derivatives (acbb_traction_eval_jac) with the drag
 * (F_v ~ omega_m^2) and gyroscopic terms differentiated by hand; c holds
 * the tractions at x. 0 if the traction law has no analytic derivative or
 * a value is not finite. */
static int qd_fj(const double *x, qd_ctx *c, double f[4], double J[16])
{
    double wi = c->omega_i, wm = wi * x[0];
    double wb[3] = { wi * x[1], wi * x[2], wi * x[3] };
    double dFi[3][4], dMi[3][4], dFo[3][4], dMo[3][4];
    if (!acbb_traction_eval_jac(c->s, c->ci, wb, wi - wm, &c->tri, dFi, dMi)
        || !acbb_traction_eval_jac(c->s, c->co, wb, -wm, &c->tro, dFo, dMo))
        return 0;
    double Fv = c->s->loss_drag ? acbb_drag_force(c->s, c->mix, wm) : 0.0;
    double dFv = wm != 0.0 ? 2.0 * Fv / wm : 0.0;
    double gy = c->s->gyroscopic ? c->J : 0.0, Ms = c->Fscale * 0.5 * c->D;
    double Mreq[3] = { 0.0, -gy * wm * wb[2], gy * wm * wb[1] };
    /* d Mreq / d x: row d, column k (x = (omega_m, wx, wy, wz) / omega_i). */
    double dMr[3][4] = { { 0 }, { -gy * wi * wb[2], 0.0, 0.0, -gy * wm * wi },
                         { gy * wi * wb[1], 0.0, gy * wm * wi, 0.0 } };
    f[0] = (c->tri.F[1] + c->tro.F[1] + Fv) / c->Fscale;
    for (int d = 0; d < 3; d++) f[1 + d] = (c->tri.M[d] + c->tro.M[d] - Mreq[d]) / Ms;
    for (int r = 0; r < 4; r++) {
        const double *di = r ? dMi[r - 1] : dFi[1], *dd = r ? dMo[r - 1] : dFo[1];
        double sc = r ? Ms : c->Fscale;
        /* omega_m enters both race speeds with -1, the ball speeds as is. */
        J[4 * r] = -wi * (di[3] + dd[3]) + (r ? -dMr[r - 1][0] : wi * dFv);
        for (int k = 1; k < 4; k++)
            J[4 * r + k] = wi * (di[k - 1] + dd[k - 1]) - (r ? dMr[r - 1][k] : 0.0);
        for (int k = 0; k < 4; k++) J[4 * r + k] /= sc;
    }
    for (int k = 0; k < 16; k++)
        if (!isfinite(J[k]) || (k < 4 && !isfinite(f[k]))) return 0;
    return 1;
}

/* Newton with the analytic Jacobian from x (transient steps): 1 with x
 * the root, c's tractions there and J its Jacobian; 0 if the law has no
 * analytic derivative or a step halved 4 times does not lower sum |f|
 * (a full step that overshoots is damped rather than handed to the
 * hybrid solver's ~17 iterations of five evaluations: issue 30). */
static int newton_analytic(qd_ctx *c, double x[4], double J[16])
{
    double f[4], d[4] = { 0 }, x0[4] = { 0 }, prev = INFINITY;
    int halvings = 0;
    for (int it = 0; it < 16; it++) {
        if (!qd_fj(x, c, f, J)) return 0;
        double r = fabs(f[0]) + fabs(f[1]) + fabs(f[2]) + fabs(f[3]);
        if (r < c->tol) return 1;
        if (!(r < prev)) {
            if (++halvings > 4) return 0;
            for (int k = 0; k < 4; k++) x[k] = x0[k] + (d[k] *= 0.5);
            continue;
        }
        if (!acbb_newton_step(4, J, f, d)) return 0;
        memcpy(x0, x, sizeof x0);
        for (int k = 0; k < 4; k++) x[k] += d[k];
        prev = r;
        halvings = 0;
    }
    return 0;
}

static int qd_df(const gsl_vector *x, void *p, gsl_matrix *J)
{
    double f0[4], f1[4], xv[4];
    gsl_vector_view F0 = gsl_vector_view_array(f0, 4), F1 = gsl_vector_view_array(f1, 4);
    int rc = qd_f(x, p, &F0.vector);
    if (rc != GSL_SUCCESS) return rc;
    for (int j = 0; j < 4; j++) {
        for (int k = 0; k < 4; k++) xv[k] = gsl_vector_get(x, k);
        xv[j] += FD_STEP;
        gsl_vector_view X = gsl_vector_view_array(xv, 4);
        if ((rc = qd_f(&X.vector, p, &F1.vector)) != GSL_SUCCESS) return rc;
        for (int i = 0; i < 4; i++) gsl_matrix_set(J, i, j, (f1[i] - f0[i]) / FD_STEP);
    }
    return GSL_SUCCESS;
}

static int qd_fdf(const gsl_vector *x, void *p, gsl_vector *f, gsl_matrix *J)
{
    int rc = qd_f(x, p, f);
    return rc == GSL_SUCCESS ? qd_df(x, p, J) : rc;
}

acbb_status acbb_qd_new(int grid, acbb_qd **out)
{
    acbb_qd *q = calloc(1, sizeof *q);
    if (!q) return ACBB_ENOMEM;
    if (acbb_traction_contact_init(&q->ci, grid) != ACBB_OK
        || acbb_traction_contact_init(&q->co, grid) != ACBB_OK
        || !(q->solver = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, 4))) {
        acbb_qd_free(q);
        return ACBB_ENOMEM;
    }
    *out = q;
    return ACBB_OK;
}

/* As calloc leaves a new one, but of the balls only those an update
 * reached (the whole 26 kB cost as much as the allocations saved). */
acbb_status acbb_qd_renew(acbb_qd *q, int grid)
{
    acbb_traction_contact ci = q->ci, co = q->co;
    gsl_multiroot_fdfsolver *solver = q->solver;
    memset(q->b, 0, sizeof q->b[0] * (size_t)q->used);
    memset(q, 0, offsetof(acbb_qd, b));
    q->ci = ci;
    q->co = co;
    q->solver = solver;
    if (acbb_traction_contact_renew(&q->ci, grid) != ACBB_OK
        || acbb_traction_contact_renew(&q->co, grid) != ACBB_OK)
        return ACBB_ENOMEM;
    return ACBB_OK;
}

/* tc: src's scalars in the tables of `tables` (acbb_traction_prepare
 * writes the tables of every contact an update solves before
 * acbb_traction_eval reads them). */
static void contact_scalars(acbb_traction_contact *tc, const acbb_traction_contact *src,
                            const acbb_traction_contact *tables)
{
    acbb_traction_contact own = *tables;
    *tc = *src;
    tc->cap = own.cap;
    tc->P = own.P;
    tc->w = own.w;
    tc->p = own.p;
    tc->eta = own.eta;
    tc->tb = own.tb;
    tc->tlim = own.tlim;
}

acbb_qd *acbb_qd_save(const acbb_qd *q)
{
    size_t head = offsetof(acbb_qd, b), n = head + sizeof q->b[0] * (size_t)q->used;
    acbb_qd *t = malloc(n);
    if (!t) return NULL;
    memcpy(t, q, n);
    static const acbb_traction_contact no_tables = { 0 };
    t->solver = NULL; /* nor q's tables */
    contact_scalars(&t->ci, &q->ci, &no_tables);
    contact_scalars(&t->co, &q->co, &no_tables);
    return t;
}

void acbb_qd_restore(acbb_qd *q, const acbb_qd *saved)
{
    /* q's balls past saved's are cleared, as saved's were. */
    if (q->used > saved->used)
        memset(&q->b[saved->used], 0, sizeof q->b[0] * (size_t)(q->used - saved->used));
    memcpy(q->b, saved->b, sizeof q->b[0] * (size_t)saved->used);
    contact_scalars(&q->ci, &saved->ci, &q->ci);
    contact_scalars(&q->co, &saved->co, &q->co);
    q->skip_tol = saved->skip_tol;
    q->path = saved->path;
    q->used = saved->used;
}

void acbb_qd_free(acbb_qd *q)
{
    if (!q) return;
    acbb_traction_contact_free(&q->ci);
    acbb_traction_contact_free(&q->co);
    if (q->solver) gsl_multiroot_fdfsolver_free(q->solver);
    free(q);
}

/* The residual a solve ends below: PATH_RES_TOL in a transient step that
 * skips balls, RES_TOL everywhere else. */
static double qd_tol(const acbb_qd *q)
{
    return q->path && q->skip_tol > 0.0 ? PATH_RES_TOL : RES_TOL;
}

/* Film and traction tables of one contact at the ball's current speeds. */
static acbb_status prepare(const acbb_scene *s, const acbb_quad *quad, const acbb_geometry *g,
                           const acbb_ball_state *b, int inner, double omega_i,
                           const acbb_oil_state *oil, acbb_traction_contact *tc)
{
    acbb_contact_in c;
    acbb_film film;
    acbb_mech_contact_input(g, b, inner, omega_i, &c);
    double u = fabs(c.u);
    double srr = u > 1e-6 ? fmin(acbb_slip_speed(&c, 0.0) / u, 2.0) : 0.0;
    acbb_film_compute(s, oil, u, c.Q, c.Rx, c.kappa, c.E_eff, c.pmax, srr, &film);
    return acbb_traction_prepare(s, quad, &c, &film, oil, tc);
}

/* Hybrid Newton from x0 to RES_TOL (accepting 1e3 x that on a stall). */
static acbb_status newton(acbb_qd *q, gsl_multiroot_function_fdf *F, const double *x0)
{
    double xv[4];
    memcpy(xv, x0, sizeof xv);
    gsl_vector_view v = gsl_vector_view_array(xv, 4);
    if (gsl_multiroot_fdfsolver_set(q->solver, F, &v.vector) != GSL_SUCCESS)
        return ACBB_DIVERGED;
    int status = gsl_multiroot_test_residual(q->solver->f, RES_TOL);
    for (int it = 0; status == GSL_CONTINUE && it < 100; it++) {
        if (gsl_multiroot_fdfsolver_iterate(q->solver) != GSL_SUCCESS) break;
        status = gsl_multiroot_test_residual(q->solver->f, RES_TOL);
    }
    if (status == GSL_SUCCESS
        || gsl_multiroot_test_residual(q->solver->f, 1e3 * RES_TOL) == GSL_SUCCESS)
        return ACBB_OK;
    return ACBB_DIVERGED;
}

/* Residual at x (scaled, as qd_f) for acbb_broyden; 0 on a non-finite value. */
static int eval(const double *x, void *p, double *f)
{
    ((qd_ctx *)p)->evals++;
    return residual(x, p, f);
}

/* Continuation in the slip regularisation: the traction field is nearly
 * discontinuous at zero slip (s_reg = 1 um/s, MODEL.md section 4); start from
 * a smooth 1 cm/s and tighten by sqrt(10), warm-starting each solve. With
 * boundary friction alone (no film) the stick/slip field can leave no root
 * a Newton method resolves at 1 um/s; the solution at the tightest
 * regularisation that converged is then kept if it is at most 0.1 mm/s
 * (the traction saturates within 0.1 mm/s of slip instead of 1 um/s). On
 * return the solver holds the accepted root and the tables its s_reg. */
static acbb_status continuation(acbb_qd *q, gsl_multiroot_function_fdf *F, const double *x0)
{
    double x[4], good = 0.0;
    memcpy(x, x0, sizeof x);
    for (double sr = 1e-2; sr >= 0.99e-6; sr *= 0.316227766) {
        q->ci.s_reg = q->co.s_reg = sr;
        if (newton(q, F, x) != ACBB_OK) break;
        for (int d = 0; d < 4; d++) x[d] = gsl_vector_get(q->solver->x, d);
        good = sr;
    }
    if (good <= 0.0 || good > 1.01e-4) return ACBB_DIVERGED;
    q->ci.s_reg = q->co.s_reg = good;
    return newton(q, F, x); /* leave the solver at the accepted root */
}

/* Broyden for ball j from x0 with its kept Jacobian: 1 with x the root
 * and J kept. In a transient's steps, after a slow
 * solve of its own (more than STALE_EVALS residuals) ball j's next one
 * starts from the analytic Jacobian at x0 (with its residual: about 2.5
 * evaluations) instead of the kept one, which Broyden's rank-one updates
 * had let go stale (issue 30: 5.4 residuals a solve in the combined-load
 * run). A steady solve's iterates are no path: they keep Broyden's. */
static int broyden_from(acbb_qd *q, qd_ctx *c, int j, const double *x0, double x[4])
{
    double J[16], f[4], xa[4];
    memcpy(J, q->b[j].J, sizeof J);
    memcpy(xa, x0, sizeof xa);
    acbb_broyden_opts o = { 0 };
    double Ja[16];
    if (q->path && q->b[j].J_stale && (o.have_f = qd_fj(xa, c, f, Ja)))
        memcpy(J, Ja, sizeof J);
    int before = c->evals;
    if (!acbb_broyden_ex(eval, c, 4, J, xa, f, c->tol, 8, &o)) return 0;
    q->b[j].J_stale = q->path && c->evals - before > STALE_EVALS;
    memcpy(q->b[j].J, J, sizeof J);
    q->b[j].J_ok = 1;
    memcpy(x, xa, sizeof xa);
    return 1;
}

/* Level 2 of ball j: Broyden from its last Jacobian if there is one (two
 * or three traction evaluations between thermal steps instead of five per
 * hybrid iteration); a ball without one (the set-up's first pass) starts
 * Newton with the analytic Jacobian from the root xn of its neighbour if
 * given (neighbours in azimuth carry similar loads, MODEL.md section 4;
 * the root is the same to RES_TOL; Broyden with the neighbour's Jacobian
 * failed for 9 of the combined-load run's 10 such balls after 4 to 9
 * residuals, issue 30); else or if that stalls the hybrid Newton, with
 * continuation as the last resort. On success c holds the tractions at the root. The
 * Jacobian is kept only from a solve at the nominal s_reg. */
static acbb_status solve_speeds(acbb_qd *q, qd_ctx *c, int j, double x[4], const double *xn)
{
    double J[16], f[4], xa[4];
    int own = q->b[j].J_ok;
    if (own && broyden_from(q, c, j, x, x))
        return ACBB_OK;
    int from_nb = !own && xn;
    /* Transient steps (skip_tol > 0, non-symmetric scenes), starts from a
     * neighbour and a failed Broyden solve from the ball's own Jacobian
     * (the set-up's second pass, after the first equilibrium moved every
     * load: issue 30): Newton with the analytic Jacobian before the hybrid
     * solver (3-4 steps of about three evaluations each against ~30
     * evaluations; as the first choice it cost more than Broyden's ~5.7,
     * BENCHMARKS.md round 3). */
    memcpy(xa, from_nb ? xn : x, sizeof xa);
    if ((q->skip_tol > 0.0 || from_nb || own) && newton_analytic(c, xa, J)) {
        memcpy(q->b[j].J, J, sizeof J);
        q->b[j].J_ok = 1;
        memcpy(x, xa, sizeof xa);
        return ACBB_OK;
    }
    q->b[j].J_ok = 0;
    gsl_multiroot_function_fdf F = { qd_f, qd_df, qd_fdf, 4, c };
    if (newton(q, &F, x) == ACBB_OK) {
        gsl_matrix_view JM = gsl_matrix_view_array(q->b[j].J, 4, 4);
        q->b[j].J_ok = qd_df(q->solver->x, c, &JM.matrix) == GSL_SUCCESS;
    } else if (continuation(q, &F, x) != ACBB_OK)
        return ACBB_DIVERGED;
    for (int d = 0; d < 4; d++) x[d] = gsl_vector_get(q->solver->x, d);
    return eval(x, c, f) ? ACBB_OK : ACBB_DIVERGED; /* tractions at the accepted root */
}

static acbb_status solve_ball(acbb_qd *q, const acbb_scene *s, const acbb_quad *quad,
                              const acbb_geometry *g, double omega_i,
                              const acbb_oil_state *oil_i, const acbb_oil_state *oil_o,
                              const acbb_mixture *mix, acbb_ball_state *b, int j,
                              const acbb_ball_state *bn, const double *x0)
{
    acbb_status rc = prepare(s, quad, g, b, 1, omega_i, oil_i, &q->ci);
    if (rc == ACBB_OK) rc = prepare(s, quad, g, b, 0, omega_i, oil_o, &q->co);
    if (rc != ACBB_OK) return rc;
    qd_ctx c = { .s = s, .ci = &q->ci, .co = &q->co, .omega_i = omega_i, .J = g->J,
                 .D = g->D, .mix = mix, .tol = qd_tol(q) };
    c.Fscale = fmax(s->mu_bd * (b->Qi + b->Qo), 1e-6);
    double x[4] = { b->kin.omega_m / omega_i, b->kin.wx / omega_i, b->kin.wy / omega_i,
                    b->kin.wz / omega_i };
    if (x0) memcpy(x, x0, sizeof x);
    double xn[4];
    for (int d = 0; bn && d < 4; d++) xn[d] = bn->qd_w[d] / omega_i;
    if (solve_speeds(q, &c, j, x, bn ? xn : NULL) != ACBB_OK)
        return ACBB_DIVERGED;
    for (int d = 0; d < 4; d++) b->qd_w[d] = omega_i * x[d];
    memcpy(b->tr_i, c.tri.F, sizeof b->tr_i);
    memcpy(b->tr_o, c.tro.F, sizeof b->tr_o);
    b->tr_Qi = b->Qi;
    b->tr_Qo = b->Qo;
    b->traction_valid = 1;
    acbb_kinematics_from_omega(b->alpha_i, b->alpha_o, g->D, g->dm, omega_i, b->qd_w[0],
                               b->qd_w[1], b->qd_w[2], b->qd_w[3], &b->kin);
    return ACBB_OK;
}

/* The start of ball j's solve at inputs u: its last root moved on along
 * the secant of its last two, by the projection of the inputs' move on
 * the last one (the transient's inputs drift one way, so each solve
 * starts closer than the last root: fewer Broyden residuals; the root
 * is the same to RES_TOL, issue 30). 0: no history or the inputs turned. */
static int predict(const acbb_qd *q, int j, const double u[PRED_INPUTS], double x[4])
{
    const qd_ball *h = &q->b[j];
    if (h->nh < 2 || !h->J_ok) return 0;
    const double *u0 = h->uh[0], *u1 = h->uh[1];
    double num = 0.0, den = 0.0;
    for (int k = 0; k < PRED_INPUTS; k++) {
        /* Angles (2, 3) in radians, the others relative. */
        double sc = k == 2 || k == 3 ? 1.0 : fmax(fabs(u0[k]), 1e-300);
        double a = (u[k] - u0[k]) / sc, b = (u0[k] - u1[k]) / sc;
        num += a * b;
        den += b * b;
    }
    double t = den > 0.0 ? num / den : 0.0; /* 0: the inputs did not move */
    if (!(t > 0.0 && t < 4.0)) return 0;
    for (int d = 0; d < 4; d++) x[d] = h->xh[0][d] + t * (h->xh[0][d] - h->xh[1][d]);
    return 1;
}

/* Ball j's root x at inputs u into its history. */
static void remember(acbb_qd *q, int j, const double u[PRED_INPUTS], const double *w, double wi)
{
    qd_ball *h = &q->b[j];
    memcpy(h->xh[1], h->xh[0], sizeof h->xh[0]);
    memcpy(h->uh[1], h->uh[0], sizeof h->uh[0]);
    for (int d = 0; d < 4; d++) h->xh[0][d] = w[d] / wi;
    memcpy(h->uh[0], u, sizeof h->uh[0]);
    h->nh = h->nh < 2 ? h->nh + 1 : 2;
}

/* Weights of the transient-step skip (acbb_ball_moved, inputs in the order
 * of acbb_ball_inputs): the inlet viscosities count 0.3. They are common to
 * every ball and drift on as the oil warms, so at weight 1 each such drift
 * re-solved all balls at once; the steady polish still solves every ball,
 * so the steady state is the same to 6e-7 and only the transient path
 * moves (BENCHMARKS.md, round 4: within the balanced preset's stated path
 * error, MODEL.md section 9). */
static const double skip_weights[ACBB_BALL_INPUTS] = { 1, 1, 1, 1, 0.3, 0.3, 1, 1, 1, 1 };

void acbb_qd_set_skip(acbb_qd *q, double tol)
{
    q->skip_tol = tol > 0.0 ? tol : 0.0;
}

void acbb_qd_set_path(acbb_qd *q, int transient) { q->path = transient; }

acbb_status acbb_qd_update(acbb_qd *q, const acbb_scene *s, const acbb_quad *quad,
                           const acbb_geometry *g, double omega_i,
                           const acbb_oil_state *oil_i, const acbb_oil_state *oil_o,
                           const acbb_mixture *mix, acbb_mech_state *st, double *change,
                           acbb_error *err)
{
    *change = 0.0;
    if (omega_i <= 0.0) return ACBB_OK;
    int nb = acbb_mech_distinct(st), jn = -1; /* last ball solved here with a Jacobian */
    if (nb > q->used) q->used = nb;
    for (int j = 0; j < nb; j++) {
        acbb_ball_state *b = &st->ball[j];
        if (b->Qi < MIN_LOAD || b->Qo < MIN_LOAD) {
            b->traction_valid = 0;
            q->b[j].J_ok = q->b[j].in_ok = q->b[j].nh = 0;
            continue;
        }
        /* Inside a transient step a ball whose inputs barely moved keeps
         * its speeds and tractions (the tractions scale with the load in
         * the ring equilibrium); so does the steady polish's (1e-9) if
         * its last solve was as tight as the polish's. */
        double in[ACBB_BALL_INPUTS];
        acbb_ball_inputs(b, oil_i->eta0, oil_o->eta0, omega_i, in);
        if (q->skip_tol > 0.0 && q->b[j].in_ok && b->traction_valid
            && q->b[j].tol_used <= qd_tol(q)
            && acbb_ball_moved(q->b[j].in, in, skip_weights) < q->skip_tol)
            continue;
        double wm0 = b->kin.omega_m, u[PRED_INPUTS], x0[4];
        memcpy(u, in, sizeof u[0] * 6);
        u[6] = omega_i;
        int pr = q->path && predict(q, j, u, x0);
        acbb_status rc = solve_ball(q, s, quad, g, omega_i, oil_i, oil_o, mix, b, j,
                                    jn >= 0 ? &st->ball[jn] : NULL, pr ? x0 : NULL);
        q->b[j].in_ok = rc == ACBB_OK;
        q->b[j].tol_used = qd_tol(q);
        if (rc == ACBB_OK) remember(q, j, u, b->qd_w, omega_i);
        else q->b[j].nh = 0;
        if (rc == ACBB_OK && q->b[j].J_ok) jn = j;
        /* Recorded after the solve: its speeds are the reference. */
        acbb_ball_inputs(b, oil_i->eta0, oil_o->eta0, omega_i, q->b[j].in);
        if (rc != ACBB_OK)
            return acbb_error_set(err, rc, "quasi-dynamic kinematics of ball %d did not converge "
                                  "(Qi %.3g N, Qo %.3g N)", j + 1, b->Qi, b->Qo);
        *change = fmax(*change, fabs(b->kin.omega_m - wm0) / fmax(fabs(wm0), 1e-12));
    }
    acbb_mech_spread(st);
    return ACBB_OK;
}

void acbb_qd_keep(const acbb_mech_state *st, acbb_qd_kept *k)
{
    for (int j = 0; j < acbb_mech_distinct(st); j++) {
        const acbb_ball_state *b = &st->ball[j];
        k[j].valid = b->traction_valid && b->tr_Qi > 0.0 && b->tr_Qo > 0.0;
        if (!k[j].valid) continue;
        memcpy(k[j].w, b->qd_w, sizeof k[j].w);
        for (int d = 0; d < 3; d++) {
            k[j].ti[d] = b->tr_i[d] / b->tr_Qi;
            k[j].to[d] = b->tr_o[d] / b->tr_Qo;
        }
    }
}

void acbb_qd_relax(acbb_mech_state *st, const acbb_qd_kept *k, double w)
{
    for (int j = 0; j < acbb_mech_distinct(st); j++) {
        acbb_ball_state *b = &st->ball[j];
        if (!k[j].valid || !b->traction_valid) continue;
        for (int d = 0; d < 4; d++) b->qd_w[d] = k[j].w[d] + w * (b->qd_w[d] - k[j].w[d]);
        for (int d = 0; d < 3; d++) {
            b->tr_i[d] = b->tr_Qi * (k[j].ti[d] + w * (b->tr_i[d] / b->tr_Qi - k[j].ti[d]));
            b->tr_o[d] = b->tr_Qo * (k[j].to[d] + w * (b->tr_o[d] / b->tr_Qo - k[j].to[d]));
        }
    }
    acbb_mech_spread(st);
}
