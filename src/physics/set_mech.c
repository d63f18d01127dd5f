/* acbb — shaft equilibrium of a bearing set (MODEL.md section 14;
 * set_mech.h for the frames). Newton on the active shaft unknowns with a
 * forward-difference Jacobian kept between solves and Broyden updates
 * (broyden.h, as the ring equilibrium of one bearing): every residual is a
 * set of full ball solutions, so a finite-difference Jacobian per
 * iteration would cost n+1 of them. Unknowns in um and mrad, residuals in
 * N (moments over the pitch radius). */
#include <math.h>
#include <string.h>
#include "set_mech.h"
#include "broyden.h"
#include "acbb/tools/set.h"

#define UM 1e-6
#define MRAD 1e-3
#define LOADED_N 1e-6   /* as mechanics.c: an open contact carries less */

typedef struct {
    acbb_set_mech *sm;
    acbb_set_member *mb;
    double omega;
    int act[ACBB_SET_Q];          /* active unknowns, in order */
    int n;
    double R;                     /* moment arm for the residual scale, m */
    acbb_status st;
    acbb_set_mech_memo *memo;     /* NULL, or recording / replaying (replay) */
    int replay, ev;               /* evaluations so far */
} ctx_t;

void acbb_set_mech_init(acbb_set_mech *sm, const acbb_scene *s)
{
    memset(sm, 0, sizeof *sm);
    sm->n = acbb_set_layout(s, sm->orient, sm->x);
    if (sm->n > ACBB_MAX_SET) sm->n = ACBB_MAX_SET;
    sm->x_nose = s->set_load_offset;
    sm->spring = s->preload == ACBB_PRELOAD_FORCE;
    sm->Fp = s->preload_force;
    sm->across = s->set_mirrored;
    sm->Fa = s->axial_load;
    sm->Fr = s->radial_load;
    sm->M = s->moment_load;
    sm->tol = s->mech_tol;
}

static int side_count(const acbb_set_mech *sm, int s)
{
    int c = 0;
    for (int k = 0; k < sm->n; k++) c += sm->orient[k] == s;
    return c;
}

void acbb_set_mech_assemble(acbb_set_mech *sm, double (*dx1)(double F, void *ctx), void *ctx)
{
    int np = side_count(sm, 1), nm = side_count(sm, -1);
    for (int k = 0; k < sm->n; k++) {
        int nk = sm->orient[k] > 0 ? np : nm;
        /* A tandem set has no opposite side: its thrust alone loads it
         * (or, set against another set across the shaft, that preload). */
        if (nm == 0 || np == 0)
            sm->e[k] = sm->across && sm->Fp > 0.0 ? dx1(sm->Fp / sm->n, ctx) : 0.0;
        else
            sm->e[k] = dx1(sm->Fp / nk, ctx);
    }
}

static int floating(const acbb_set_mech *sm, int k)
{
    return sm->spring && sm->orient[k] < 0;
}

/* External thrust: a tandem set's spring pushes like a thrust. */
static double thrust(const acbb_set_mech *sm)
{
    return sm->spring && side_count(sm, -1) == 0 ? sm->Fa + sm->Fp : sm->Fa;
}

static void member_displacement(const acbb_set_mech *sm, int k, const double *q, double d[3])
{
    int s = sm->orient[k];
    d[0] = s * (q[0] + sm->u[k]) + sm->e[k] + (floating(sm, k) ? q[3] : 0.0);
    d[1] = q[1] - q[2] * sm->x[k];
    d[2] = s * q[2];
}

static int all_unloaded(const acbb_mech_state *st)
{
    for (int j = 0; j < st->n; j++)
        if (st->ball[j].Qi > LOADED_N) return 0;
    return 1;
}

/* Every member solved at shaft position q into sm's reactions. */
static int solve_members(ctx_t *c, const double *q)
{
    acbb_set_mech *sm = c->sm;
    for (int k = 0; k < sm->n; k++) {
        double d[3];
        member_displacement(sm, k, q, d);
        acbb_set_member *b = &c->mb[k];
        acbb_mech_prescribe(b->m, d[0], d[1], d[2]);
        sm->solves++;
        acbb_status rc = acbb_mech_solve(b->m, c->omega, b->e, b->st, NULL);
        if (rc != ACBB_OK) { c->st = rc; return 0; }
        sm->Fx[k] = b->st->Fx;
        sm->Fz[k] = b->st->Fz;
        sm->My[k] = b->st->My;
        sm->lost[k] = all_unloaded(b->st);
    }
    return 1;
}

/* The reactions of evaluation i from the memo, and after its last one the
 * members' states; 0 when q is not the recorded position. */
static int replay(ctx_t *c, int i, const double *q)
{
    acbb_set_mech *sm = c->sm;
    acbb_set_mech_memo *m = c->memo;
    if (memcmp(m->q[i], q, sizeof m->q[i])) return 0;
    for (int k = 0; k < sm->n; k++) {
        sm->Fx[k] = m->Fx[i][k];
        sm->Fz[k] = m->Fz[i][k];
        sm->My[k] = m->My[i][k];
        sm->lost[k] = m->lost[i][k];
    }
    if (i == m->n_ev - 1)
        for (int k = 0; k < sm->n; k++) acbb_mech_state_copy(c->mb[k].st, m->ms[k]);
    return 1;
}

static void record(ctx_t *c, int i, const double *q)
{
    acbb_set_mech *sm = c->sm;
    acbb_set_mech_memo *m = c->memo;
    memcpy(m->q[i], q, sizeof m->q[i]);
    for (int k = 0; k < sm->n; k++) {
        m->Fx[i][k] = sm->Fx[k];
        m->Fz[i][k] = sm->Fz[k];
        m->My[i][k] = sm->My[k];
        m->lost[i][k] = sm->lost[k];
    }
    if (i < m->n_ev - 1) return;
    for (int k = 0; k < sm->n; k++) acbb_mech_state_copy(m->ms[k], c->mb[k].st);
    m->state = 2;
}

/* The members at q: solved, or the memo's first evaluations replayed or
 * recorded. */
static int members_at(ctx_t *c, const double *q)
{
    int i = c->ev++;
    if (!c->memo || i >= c->memo->n_ev) return solve_members(c, q);
    if (c->replay && replay(c, i, q)) return 1;
    if (c->replay) { /* not the recorded path (the members still at their
                        start before its last evaluation): solved from here on */
        c->memo = NULL;
        return solve_members(c, q);
    }
    if (!solve_members(c, q)) return 0;
    record(c, i, q);
    return 1;
}

/* Every member at shaft position q; the residuals of all four equations. */
static int evaluate(ctx_t *c, const double *q, double r[ACBB_SET_Q])
{
    acbb_set_mech *sm = c->sm;
    double Fx = 0.0, Fz = 0.0, My = 0.0, Ff = 0.0;
    if (!members_at(c, q)) return 0;
    for (int k = 0; k < sm->n; k++) {
        Fx += sm->orient[k] * sm->Fx[k];
        Fz += sm->Fz[k];
        My += sm->orient[k] * sm->My[k] - sm->x[k] * sm->Fz[k];
        if (floating(sm, k)) Ff += sm->Fx[k];
    }
    r[0] = thrust(sm) - Fx;
    r[1] = sm->Fr - Fz;
    r[2] = (sm->M - sm->x_nose * sm->Fr - My) / c->R;
    r[3] = sm->Fp - Ff;
    return 1;
}

static void unpack(const ctx_t *c, const double *x, double *q)
{
    static const double unit[ACBB_SET_Q] = { UM, UM, MRAD, UM };
    memcpy(q, c->sm->q, sizeof c->sm->q);
    for (int i = 0; i < c->n; i++) q[c->act[i]] = x[i] * unit[c->act[i]];
}

static int residual(const double *x, void *p, double *f)
{
    ctx_t *c = p;
    double q[ACBB_SET_Q], r[ACBB_SET_Q];
    unpack(c, x, q);
    if (!evaluate(c, q, r)) return 0;
    for (int i = 0; i < c->n; i++) f[i] = r[c->act[i]];
    return 1;
}

static void activate(ctx_t *c)
{
    const acbb_set_mech *sm = c->sm;
    int tandem = side_count(sm, -1) == 0 || side_count(sm, 1) == 0;
    int spring = sm->spring && !tandem;
    int on[ACBB_SET_Q] = { 1, 0, 0, spring };
    /* Radial and tilt stay 0 by symmetry without radial load or moment
     * (their solution is continuous in both: it is 0 at 0). */
    on[1] = on[2] = sm->Fr != 0.0 || sm->M != 0.0;
    c->n = 0;
    for (int i = 0; i < ACBB_SET_Q; i++)
        if (on[i] && !sm->hold[i]) c->act[c->n++] = i;
}

static int active_mask(const ctx_t *c)
{
    int m = 0;
    for (int a = 0; a < c->n; a++) m |= 1 << c->act[a];
    return m;
}

void acbb_set_mech_loads(const acbb_set_mech *sm, double L[3])
{
    double Fx = 0.0, Fz = 0.0, My = 0.0;
    for (int k = 0; k < sm->n; k++) {
        Fx += sm->orient[k] * sm->Fx[k];
        Fz += sm->Fz[k];
        My += sm->orient[k] * sm->My[k] - sm->x[k] * sm->Fz[k];
    }
    L[0] = Fx - (thrust(sm) - sm->Fa);
    L[1] = Fz;
    L[2] = My;
}

/* A solve that starts without a Jacobian replays sm->memo's evaluations
 * when they were recorded for the same unknowns and members, else
 * records its own. */
static void memo_start(ctx_t *c)
{
    acbb_set_mech_memo *m = c->sm->memo;
    if (!m || c->sm->J_ok || c->n == 0) return;
    c->memo = m;
    c->replay = m->state == 2 && m->mask == active_mask(c) && m->n_ev == c->n + 1;
    if (c->replay) return;
    m->state = 1;
    m->n_ev = c->n + 1;
    m->mask = active_mask(c);
}

acbb_status acbb_set_mech_solve(acbb_set_mech *sm, acbb_set_member *mb, double omega,
                                acbb_error *err)
{
    static const double unit[ACBB_SET_Q] = { UM, UM, MRAD, UM };
    ctx_t c = { .sm = sm, .mb = mb, .omega = omega, .st = ACBB_OK };
    c.R = 0.5 * acbb_mech_geometry(mb[0].m)->dm;
    activate(&c);
    /* Inactive unknowns are 0 (a probe with other loads may have left
     * them), held ones stay where the caller put them. */
    for (int i = 1; i < ACBB_SET_Q; i++) {
        int on = sm->hold[i];
        for (int a = 0; a < c.n; a++) on |= c.act[a] == i;
        if (!on) sm->q[i] = 0.0;
    }
    if (c.n != sm->J_n || active_mask(&c) != sm->J_mask) sm->J_ok = 0;
    sm->J_n = c.n;
    sm->J_mask = active_mask(&c);
    memo_start(&c);
    double x[ACBB_SET_Q], f[ACBB_SET_Q];
    if (c.n == 0) { /* every unknown held: the members at q, nothing to solve */
        double r[ACBB_SET_Q];
        if (evaluate(&c, sm->q, r)) return ACBB_OK;
        return acbb_error_set(err, c.st, "bearing set: a bearing's balls at the held shaft "
                              "position: %s", acbb_status_name(c.st));
    }
    double scale = fabs(thrust(sm)) + fabs(sm->Fr) + fabs(sm->M) / c.R + sm->Fp + 1.0;
    double tol = fmax(sm->tol, 1e-12) * 10.0 * scale;
    for (int i = 0; i < c.n; i++) x[i] = sm->q[c.act[i]] / unit[c.act[i]];
    for (int attempt = 0; attempt < 4; attempt++) {
        if (!residual(x, &c, f)) break;
        double sum = 0.0;
        for (int i = 0; i < c.n; i++) sum += fabs(f[i]);
        if (sum < tol) {
            unpack(&c, x, sm->q);
            return ACBB_OK;
        }
        if (!sm->J_ok || attempt > 0) {
            if (!acbb_fd_jacobian(residual, &c, c.n, x, f, 1e-4, sm->J)) break;
            sm->J_ok = 1;
        }
        if (acbb_broyden(residual, &c, c.n, sm->J, x, f, tol, 30, 8)) {
            unpack(&c, x, sm->q); /* its last evaluation was at the root */
            return ACBB_OK;
        }
    }
    sm->J_ok = 0;
    acbb_status st = c.st != ACBB_OK ? c.st : ACBB_DIVERGED;
    return acbb_error_set(err, st, "bearing set: shaft equilibrium %s at %.0f rpm",
                          st == ACBB_DIVERGED ? "did not converge" : acbb_status_name(st),
                          omega * 30.0 / M_PI);
}

double acbb_set_mech_preload(const acbb_set_mech *sm)
{
    double F = 0.0;
    for (int k = 0; k < sm->n; k++)
        if (sm->orient[k] > 0) F += sm->Fx[k];
    return F;
}
