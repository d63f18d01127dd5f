/* acbb CLI — `acbb report`: MODEL.md section 12 judged from runs of the
 * engine (see cli_report.h for the command line and exit statuses).
 *
 * House rule: physics over wished-for results. Every statement is turned
 * into numeric checks with the thresholds MODEL.md section 12 gives; where
 * it gives none (words such as "strongly", "slightly", "much smaller"),
 * this file fixes one, names it in the check's text and keeps it in one
 * place (the REPORT_* constants below). A check fails on the numbers, never
 * on a missing feature: the transient items use the stepper's per-step
 * snapshots, the (L2) items a quasi-dynamic copy of the scene.
 *
 * Run set (MODEL.md section 12 "Conditions"): load sweep 50..1000 N at
 * 15000 rpm and speed sweeps 2000..16000 rpm at 100 N and 1000 N, TE and
 * WTE; "room temperature" = the snapshot right after acbb_sim_new (step
 * 0) of the TE run, "final" = its converged snapshot. Per-ball numbers are
 * ball 0's (psi = 0; every ball is identical under pure thrust). */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "acbb/geometry.h"
#include "acbb/hertz.h"
#include "acbb/network.h"
#include "acbb/scene.h"
#include "acbb/sim.h"
#include "cli_report.h"

enum { EXIT_OK = 0, EXIT_BADINPUT = 2, EXIT_SOLVER = 3, EXIT_INTERNAL = 4 };

#define RPT_PI 3.14159265358979323846
#define DEG (180.0 / RPT_PI)

/* Thresholds MODEL.md section 12 does not give (named in the output). */
#define REPORT_RISE 1e-3         /* "rises above step 0": > 0.1 % */
#define REPORT_NEAR 0.10         /* "peak near": within 10 % of the run's time */
#define REPORT_SAME 0.02         /* "approximately equal": within 2 % */
#define REPORT_ABOVE 0.02        /* "final > step 0": by more than 2 % */
#define REPORT_MUCH_SMALLER 0.25 /* "much smaller": at most a quarter */
#define REPORT_STRONG 0.10       /* "strongly reduced": by 10 % or more */
#define REPORT_MAINLY 5.0        /* "depends mainly on speed": spread ratio */
#define REPORT_SIGNIFICANT 0.10  /* "P_L significant": >= 10 % of P_T */
#define REPORT_MARKED 0.05       /* "markedly": >= 5 % */
#define REPORT_SLIGHT 0.10       /* "slightly": a change of less than 10 % */
#define REPORT_MICRO 0.01        /* micro-sliding: < 1 % of the orbital speed */
#define REPORT_LEVEL 0.25        /* "levels off": later change < 25 % of early */
#define REPORT_FLAT 0.05         /* "approximately constant": spread < 5 % */

#define NL 8                     /* points per sweep */
static const double k_loads[NL] = { 50, 100, 150, 200, 400, 600, 800, 1000 };
static const double k_speeds[NL] = { 2000, 4000, 6000, 8000, 10000, 12000, 14000, 16000 };
#define N_LIGHT 4                /* loads[0..3] are "light", loads[4..7] "large" */
#define BASE_RPM 15000.0

enum { BLK_LOAD, BLK_S100, BLK_S1000, NBLK };
enum { TE = 0, WTE = 1 };
enum { LV_BASE = 0, LV_L2 = 1 };

/* ---- one run ---- */

typedef struct {
    double t, exp_in, exp_out, exp_ball, Qi, Qo, dx;
} traj_pt;

typedef struct {
    acbb_scene scene;
    char label[96];
    bool record;                 /* keep the per-step trajectory */
    bool skip;                   /* the scene edit failed: nothing to run */
    bool ok;                     /* reached thermal steady state */
    acbb_status status;
    char message[520];
    acbb_snapshot first, last;   /* step 0 and the final step */
    traj_pt *traj;
    size_t n_traj, cap_traj;
    bool oom;
    double min_loss;             /* smallest loss term seen at any step, W */
    double wall_ms;
} rpoint;

typedef struct {
    const char *preset;
    const char **sets;           /* the --set edits as typed */
    int n_sets;
    acbb_scene base;
    rpoint *pts;
    size_t n;
    rpoint *blk[2][NBLK];        /* 2 * NL points each: [2k + TE/WTE] */
    rpoint *zero;
    double wall_ms;
} report_ctx;

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e3 * (double)ts.tv_sec + 1e-6 * (double)ts.tv_nsec;
}

static void observe(rpoint *p, const acbb_snapshot *s)
{
    const acbb_losses *L = &s->losses;
    double m = fmin(fmin(fmin(L->P[ACBB_LOSS_SHEAR], L->P[ACBB_LOSS_SLIP]), fmin(L->P[ACBB_LOSS_SPIN], L->P[ACBB_LOSS_ROLLING])), L->P[ACBB_LOSS_DRAG]);
    for (int j = 0; j < s->n_balls; j++) m = fmin(m, s->balls[j].loss);
    p->min_loss = fmin(p->min_loss, m);
    if (!p->record) return;
    if (p->n_traj == p->cap_traj) {
        size_t cap = p->cap_traj ? 2 * p->cap_traj : 256;
        traj_pt *t = realloc(p->traj, cap * sizeof *t);
        if (!t) {
            p->oom = true;
            return;
        }
        p->traj = t;
        p->cap_traj = cap;
    }
    p->traj[p->n_traj++] = (traj_pt){ s->time, s->exp_inner + s->exp_inner_cen, s->exp_outer,
                                      s->exp_ball, s->balls[0].Qi, s->balls[0].Qo, s->delta_x };
}

static int observe_hook(void *ctx, const acbb_sim *sim)
{
    rpoint *p = ctx;
    acbb_sim_snapshot(sim, &p->last);
    if (p->last.iteration == 0) p->first = p->last;
    observe(p, &p->last);
    return 0;
}

/* Drive one Sim to the end of its run, as `acbb run` does. */
static void run_one(rpoint *p)
{
    double t0 = now_ms();
    acbb_sim *sim = NULL;
    acbb_error err = { { 0 } };
    if (p->skip) return;
    p->status = acbb_sim_new(&p->scene, &sim, &err);
    if (p->status != ACBB_OK) {
        snprintf(p->message, sizeof p->message, "%s",
                 err.msg[0] ? err.msg : acbb_status_name(p->status));
        p->wall_ms = now_ms() - t0;
        return;
    }
    acbb_run_ctl ctl = { .hook = observe_hook, .ctx = p };
    acbb_status st = acbb_sim_drive(sim, &ctl);
    acbb_sim_snapshot(sim, &p->last);
    p->ok = p->last.state == ACBB_RUN_CONVERGED && !p->oom;
    if (p->oom) {
        p->status = ACBB_ENOMEM;
        snprintf(p->message, sizeof p->message, "out of memory recording the transient");
    } else if (!p->ok) {
        p->status = st != ACBB_OK ? st : p->last.status;
        if (p->last.state == ACBB_RUN_RUNNING)
            snprintf(p->message, sizeof p->message, "the engine did not end the run");
        else
            snprintf(p->message, sizeof p->message, "%s", p->last.message);
    }
    acbb_sim_free(sim);
    p->wall_ms = now_ms() - t0;
}

/* Independent runs in parallel: each Sim is private to one thread and the
 * engine keeps no global mutable state, so results do not depend on the
 * number of threads. */
typedef struct {
    rpoint *pts;
    size_t n;
    atomic_size_t next;
} pool;

static void *pool_worker(void *arg)
{
    pool *pl = arg;
    for (;;) {
        size_t i = atomic_fetch_add(&pl->next, 1);
        if (i >= pl->n) return NULL;
        run_one(&pl->pts[i]);
    }
}

static void run_all(rpoint *pts, size_t n)
{
    pool pl = { .pts = pts, .n = n };
    atomic_init(&pl.next, 0);
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    size_t extra = cpus > 1 ? (size_t)cpus - 1 : 0;
    if (extra > 15) extra = 15;
    pthread_t tid[15];
    size_t started = 0;
    for (; started < extra; started++)
        if (pthread_create(&tid[started], NULL, pool_worker, &pl) != 0) break;
    pool_worker(&pl); /* the calling thread works too */
    for (size_t i = 0; i < started; i++) pthread_join(tid[i], NULL);
}

/* ---- building the run set ---- */

/* Edits go through acbb_scene_set with the text `--set` would use, so a
 * report point is bit-identical to `acbb run PRESET --set ...`. */
static acbb_status set_point(acbb_scene *s, double rpm, double load, int te, int l2,
                             acbb_error *err)
{
    char v[2][32];
    snprintf(v[0], sizeof v[0], "%g", rpm);
    snprintf(v[1], sizeof v[1], "%g", load);
    acbb_status st = acbb_scene_set(s, "operating.inner_speed_rpm", v[0], err);
    if (st == ACBB_OK) st = acbb_scene_set(s, "operating.axial_load_N", v[1], err);
    if (st == ACBB_OK)
        st = acbb_scene_set(s, "effects.thermal_expansion", te ? "on" : "off", err);
    if (st == ACBB_OK && l2) st = acbb_scene_set(s, "fidelity.model", "quasi-dynamic", err);
    return st;
}

static void init_point(rpoint *p, const acbb_scene *base, double rpm, double load, int te,
                       int l2, bool record)
{
    acbb_error err = { { 0 } };
    p->scene = *base;
    p->record = record;
    p->min_loss = INFINITY;
    acbb_status st = set_point(&p->scene, rpm, load, te, l2, &err);
    snprintf(p->label, sizeof p->label, "%g rpm, %g N, %s, %s", rpm, load, te ? "TE" : "WTE",
             acbb_model_level_name(p->scene.model));
    if (st != ACBB_OK) {
        p->status = st;
        p->skip = true;
        snprintf(p->message, sizeof p->message, "%s", err.msg);
    }
}

static size_t fill_level(rpoint *pts, rpoint *blk[NBLK], const acbb_scene *base, int l2)
{
    size_t i = 0;
    for (int b = 0; b < NBLK; b++) {
        blk[b] = &pts[i];
        for (int k = 0; k < NL; k++)
            for (int m = 0; m < 2; m++) {
                double rpm = b == BLK_LOAD ? BASE_RPM : k_speeds[k];
                double load = b == BLK_LOAD ? k_loads[k] : b == BLK_S100 ? 100.0 : 1000.0;
                init_point(&pts[i++], base, rpm, load, m == TE, l2,
                           !l2 && b == BLK_LOAD && m == TE);
            }
    }
    return i;
}

static int build_runs(report_ctx *c)
{
    bool l2_own = c->base.model != ACBB_MODEL_QUASI_DYNAMIC;
    c->n = (l2_own ? 2 : 1) * NBLK * 2 * NL + 1;
    c->pts = calloc(c->n, sizeof *c->pts);
    if (!c->pts) return EXIT_INTERNAL;
    size_t i = 0;
    /* The slow quasi-dynamic points first, so the pool ends evenly. */
    if (l2_own) i += fill_level(c->pts, c->blk[LV_L2], &c->base, 1);
    i += fill_level(c->pts + i, c->blk[LV_BASE], &c->base, 0);
    if (!l2_own)
        for (int b = 0; b < NBLK; b++) c->blk[LV_L2][b] = c->blk[LV_BASE][b];
    c->zero = &c->pts[i];
    init_point(c->zero, &c->base, 0.0, c->base.axial_load, 1, 0, false);
    return 0;
}

static void run_set(report_ctx *c)
{
    double t0 = now_ms();
    run_all(c->pts, c->n);
    c->wall_ms = now_ms() - t0;
}

static rpoint *P(const report_ctx *c, int lv, int blk, int k, int m)
{
    return &c->blk[lv][blk][2 * k + m];
}

/* ---- results ---- */

typedef enum { V_HELD, V_NOT_HELD, V_NOT_EVAL } verdict;
static const char *const k_vname[] = { "HELD", "NOT HELD", "NOT EVALUATED" };
static const char *const k_vmark[] = { "ok", "NO", "n/e" };

#define MAX_CHECKS 8
#define MAX_VALS 200
#define TEXT_CAP 1400

typedef struct {
    char id[8];
    verdict v;
    bool info;                   /* reported, but not part of the item verdict */
    char text[TEXT_CAP];
} check;

typedef struct {
    char key[48];
    double v;
} kv;

typedef struct {
    int num;
    const char *statement;
    bool l2;
    check ch[MAX_CHECKS];
    int nch;
    kv val[MAX_VALS];
    int nval;
    verdict v;
} item_res;

typedef struct {
    char s[TEXT_CAP];
    size_t n;
} tbuf;

static void tb(tbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void tb(tbuf *b, const char *fmt, ...)
{
    if (b->n >= sizeof b->s - 1) return;
    va_list ap;
    va_start(ap, fmt);
    int w = vsnprintf(b->s + b->n, sizeof b->s - b->n, fmt, ap);
    va_end(ap);
    if (w > 0) b->n += (size_t)w;
    if (b->n > sizeof b->s - 1) b->n = sizeof b->s - 1;
}

static void add_val(item_res *it, const char *key, double v)
{
    if (it->nval >= MAX_VALS) return;
    snprintf(it->val[it->nval].key, sizeof it->val[0].key, "%s", key);
    it->val[it->nval++].v = v;
}

static check *add_check(item_res *it, const char *id, verdict v, const tbuf *text)
{
    if (it->nch >= MAX_CHECKS) return NULL;
    check *c = &it->ch[it->nch++];
    snprintf(c->id, sizeof c->id, "%s", id);
    c->v = v;
    c->info = false;
    memcpy(c->text, text->s, sizeof c->text);
    return c;
}

static verdict V(bool held) { return held ? V_HELD : V_NOT_HELD; }

/* NOT EVALUATED with the failed run's status if any point of the block did
 * not reach steady state. */
static bool need(item_res *it, const char *id, const report_ctx *c, int lv, int blk)
{
    for (int i = 0; i < 2 * NL; i++) {
        const rpoint *p = &c->blk[lv][blk][i];
        if (p->ok) continue;
        tbuf t = { .n = 0 };
        tb(&t, "run %s failed (%s): %s", p->label, acbb_status_name(p->status), p->message);
        add_check(it, id, V_NOT_EVAL, &t);
        return false;
    }
    return true;
}

/* ---- series and shapes ---- */

typedef double (*getter)(const acbb_snapshot *);

static double g_total(const acbb_snapshot *s) { return s->losses.total; }
static double g_shear(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_SHEAR]; }
static double g_slip(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_SLIP]; }
static double g_spin(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_SPIN]; }
static double g_rolling(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_ROLLING]; }
static double g_drag(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_DRAG]; }
static double g_T5(const acbb_snapshot *s) { return s->T_outer_ring; }
static double g_ai(const acbb_snapshot *s) { return s->balls[0].alpha_i * DEG; }
static double g_ao(const acbb_snapshot *s) { return s->balls[0].alpha_o * DEG; }
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
static double g_exp_in(const acbb_snapshot *s) { return 1e6 * (s->exp_inner + s->exp_inner_cen); }
static double g_exp_out(const acbb_snapshot *s) { return 1e6 * s->exp_outer; }
static double g_exp_ball(const acbb_snapshot *s) { return 1e6 * s->exp_ball; }
/* Ball 0's orbital surface speed omega_m d_m / 2, m/s (micro-sliding scale). */
static double orbit_speed(const acbb_snapshot *s, const acbb_scene *sc)
{
    return fabs(s->balls[0].omega_m) * 0.5 * sc->pitch_diameter;
}

static void series(const report_ctx *c, int lv, int blk, int m, getter g, double *v)
{
    for (int k = 0; k < NL; k++) v[k] = g(&P(c, lv, blk, k, m)->last);
}

static bool incr(const double *v, int a, int z)
{
    for (int k = a; k < z; k++)
        if (!(v[k + 1] > v[k])) return false;
    return true;
}

static bool decr(const double *v, int a, int z)
{
    for (int k = a; k < z; k++)
        if (!(v[k + 1] < v[k])) return false;
    return true;
}

/* Rises to an interior maximum, then falls (strictly on both sides). */
static bool peak_shape(const double *v, int a, int z)
{
    int i = a;
    for (int k = a; k <= z; k++)
        if (v[k] > v[i]) i = k;
    return i > a && i < z && incr(v, a, i) && decr(v, i, z);
}

/* Falls to an interior minimum, then rises. */
static bool valley_shape(const double *v, int a, int z)
{
    int i = a;
    for (int k = a; k <= z; k++)
        if (v[k] < v[i]) i = k;
    return i > a && i < z && decr(v, a, i) && incr(v, i, z);
}

static double spread(const double *v, int a, int z)
{
    double lo = v[a], hi = v[a];
    for (int k = a; k <= z; k++) {
        lo = fmin(lo, v[k]);
        hi = fmax(hi, v[k]);
    }
    return hi > 0.0 ? (hi - lo) / hi : 0.0;
}

static const double *xs(int blk) { return blk == BLK_LOAD ? k_loads : k_speeds; }
static const char *xunit(int blk) { return blk == BLK_LOAD ? "N" : "rpm"; }

/* "what: 50 N 1.23, 100 N 1.45, ..." */
static void tb_series(tbuf *t, const char *what, int blk, const double *v, int a, int z,
                      int prec)
{
    tb(t, "%s:", what);
    for (int k = a; k <= z; k++)
        tb(t, " %g %s %.*g%s", xs(blk)[k], xunit(blk), prec, v[k], k < z ? "," : "");
}

/* "what TE/WTE: 50 N 1.23/1.24, ..." */
static void tb_pairs(tbuf *t, const char *what, int blk, const double *te, const double *wte,
                     int a, int z, int prec)
{
    tb(t, "%s TE/WTE:", what);
    for (int k = a; k <= z; k++)
        tb(t, " %g %s %.*g/%.*g%s", xs(blk)[k], xunit(blk), prec, te[k], prec, wte[k],
           k < z ? "," : "");
}

static void val_series(item_res *it, const char *name, int blk, const double *v, int a, int z)
{
    char key[48];
    for (int k = a; k <= z; k++) {
        snprintf(key, sizeof key, "%s_%g%s", name, xs(blk)[k], blk == BLK_LOAD ? "N" : "rpm");
        add_val(it, key, v[k]);
    }
}

/* ---- the static thrust relation (MODEL.md section 3, "Initial guesses")
 * solved independently of the mechanics module: bisection on alpha of
 * Z K_n(alpha) [A0 (cos alpha0 / cos alpha - 1)]^1.5 sin alpha = F_x, with
 * the Hertz constants at the operating angle as the engine uses them. */

static double kn_at(const acbb_geometry *g, acbb_hertz_mode mode, double alpha)
{
    double Rx, Ry;
    acbb_hertz_const hi, ho;
    acbb_contact_radii(g->D, g->dm, alpha, g->f_i, 1, &Rx, &Ry);
    if (acbb_hertz_const_compute(Rx, Ry, g->E_eff, mode, &hi) != ACBB_OK) return NAN;
    acbb_contact_radii(g->D, g->dm, alpha, g->f_o, 0, &Rx, &Ry);
    if (acbb_hertz_const_compute(Rx, Ry, g->E_eff, mode, &ho) != ACBB_OK) return NAN;
    return pow(pow(hi.Kc, -2.0 / 3.0) + pow(ho.Kc, -2.0 / 3.0), -1.5);
}

static double thrust_of(const acbb_geometry *g, acbb_hertz_mode mode, double alpha)
{
    double dn = g->A0 * (cos(g->alpha0) / cos(alpha) - 1.0);
    return g->Z * kn_at(g, mode, alpha) * pow(fmax(dn, 0.0), 1.5) * sin(alpha);
}

/* Static contact angle (rad) and load (N) under thrust F; NAN if none. */
static double static_angle(const acbb_scene *s, double F, double *Q)
{
    acbb_geometry g;
    acbb_geometry_init(s, &g);
    double lo = g.alpha0, hi = 89.0 / DEG;
    if (!(thrust_of(&g, s->hertz, hi) > F) || F <= 0.0) return NAN;
    for (int it = 0; it < 200 && hi - lo > 1e-15; it++) {
        double mid = 0.5 * (lo + hi), f = thrust_of(&g, s->hertz, mid);
        if (!isfinite(f)) return NAN;
        if (f < F) lo = mid;
        else hi = mid;
    }
    double a = 0.5 * (lo + hi);
    if (Q) *Q = F / (g.Z * sin(a));
    return a;
}

/* ---- items (MODEL.md section 12) ---- */

static void item1(const report_ctx *c, item_res *it)
{
    if (!need(it, "1", c, LV_BASE, BLK_LOAD)) return;
    double te[NL], wte[NL];
    series(c, LV_BASE, BLK_LOAD, TE, g_total, te);
    series(c, LV_BASE, BLK_LOAD, WTE, g_total, wte);
    val_series(it, "P_T_TE_W", BLK_LOAD, te, 0, NL - 1);
    val_series(it, "P_T_WTE_W", BLK_LOAD, wte, 0, NL - 1);
    int n1 = 0, n2 = 0;
    for (int k = 0; k < N_LIGHT; k++) n1 += wte[k] > te[k];
    for (int k = N_LIGHT; k < NL; k++) n2 += wte[k] < te[k];
    tbuf t = { .n = 0 };
    tb_pairs(&t, "P_T W", BLK_LOAD, te, wte, 0, N_LIGHT - 1, 4);
    tb(&t, "; WTE > TE at %d of %d light loads", n1, N_LIGHT);
    add_check(it, "1a", V(n1 == N_LIGHT), &t);
    t.n = 0;
    tb_pairs(&t, "P_T W", BLK_LOAD, te, wte, N_LIGHT, NL - 1, 4);
    tb(&t, "; WTE < TE at %d of %d large loads", n2, NL - N_LIGHT);
    add_check(it, "1b", V(n2 == NL - N_LIGHT), &t);
}

static void item2(const report_ctx *c, item_res *it)
{
    if (!need(it, "2", c, LV_BASE, BLK_LOAD)) return;
    static const getter g[5] = { g_shear, g_slip, g_spin, g_rolling, g_drag };
    static const char *const nm[5] = { "P_L", "P_t", "P_s", "P_r", "P_v" };
    double share[NL], pct[NL];
    int top[NL];
    for (int k = 0; k < NL; k++) {
        const acbb_snapshot *a = &P(c, LV_BASE, BLK_LOAD, k, TE)->last;
        const acbb_snapshot *b = &P(c, LV_BASE, BLK_LOAD, k, WTE)->last;
        double d[5], gross = 0.0;
        top[k] = 0;
        for (int i = 0; i < 5; i++) {
            d[i] = fabs(g[i](a) - g[i](b));
            gross += d[i];
            if (d[i] > d[top[k]]) top[k] = i;
        }
        /* Light loads: P_t + P_L; large loads: P_t + P_r. */
        double pair = d[1] + (k < N_LIGHT ? d[0] : d[3]);
        share[k] = gross > 0.0 ? pair / gross : NAN;
        pct[k] = 100.0 * share[k];
    }
    val_series(it, "share_pct", BLK_LOAD, pct, 0, NL - 1);
    for (int half = 0; half < 2; half++) {
        int a = half ? N_LIGHT : 0, z = half ? NL - 1 : N_LIGHT - 1, n = 0;
        tbuf t = { .n = 0 };
        tb(&t, "share of %s in sum|dP_k| (dP_k = TE-WTE of each loss):",
           half ? "P_t+P_r" : "P_t+P_L");
        for (int k = a; k <= z; k++) {
            tb(&t, " %g N %.0f %% (largest %s)%s", k_loads[k], 100.0 * share[k], nm[top[k]],
               k < z ? "," : "");
            n += share[k] > 0.5;
        }
        tb(&t, "; > 50 %% at %d of %d", n, z - a + 1);
        add_check(it, half ? "2b" : "2a", V(n == z - a + 1), &t);
    }
}

static void item3(const report_ctx *c, item_res *it)
{
    bool ok = true;
    for (int b = 0; b < NBLK; b++) ok = need(it, "3", c, LV_BASE, b) && ok;
    if (!ok) return;
    double worst = 0.0;
    int wb = 0, wk = 0;
    for (int b = 0; b < NBLK; b++)
        for (int k = 0; k < NL; k++) {
            double te = P(c, LV_BASE, b, k, TE)->last.losses.P[ACBB_LOSS_DRAG];
            double w = P(c, LV_BASE, b, k, WTE)->last.losses.P[ACBB_LOSS_DRAG];
            double r = w > 0.0 ? fabs(te - w) / w : 0.0;
            if (r >= worst) {
                worst = r;
                wb = b;
                wk = k;
            }
        }
    add_val(it, "max_rel_dPv_pct", 100.0 * worst);
    tbuf t = { .n = 0 };
    tb(&t, "max |P_v(TE)-P_v(WTE)|/P_v(WTE) over the 24 TE/WTE pairs = %.3g %% (at %g %s, %s "
       "sweep); need < 2 %%", 100.0 * worst, xs(wb)[wk], xunit(wb),
       wb == BLK_LOAD ? "15000 rpm load" : wb == BLK_S100 ? "100 N speed" : "1000 N speed");
    add_check(it, "3a", V(worst < 0.02), &t);
    double vl[NL], v1[NL], v2[NL];
    series(c, LV_BASE, BLK_LOAD, TE, g_drag, vl);
    series(c, LV_BASE, BLK_S100, TE, g_drag, v1);
    series(c, LV_BASE, BLK_S1000, TE, g_drag, v2);
    double sl = spread(vl, 0, NL - 1), ss = fmin(spread(v1, 0, NL - 1), spread(v2, 0, NL - 1));
    add_val(it, "Pv_spread_load_pct", 100.0 * sl);
    add_val(it, "Pv_spread_speed_pct", 100.0 * ss);
    t.n = 0;
    tb(&t, "P_v (TE) spread (max-min)/max: over 50-1000 N at 15000 rpm %.3g %%, over "
       "2000-16000 rpm %.3g %% (smaller of 100 N, 1000 N); mainly speed if >= %.0fx: %.3gx",
       100.0 * sl, 100.0 * ss, REPORT_MAINLY, sl > 0.0 ? ss / sl : INFINITY);
    add_check(it, "3b", V(ss >= REPORT_MAINLY * sl), &t);
}

/* Transient of the TE load-sweep point k: sign changes of
 * (theta_i + theta_icen) - theta_o, and the time of the first one. */
static int crossings(const rpoint *p, double *t_first)
{
    int n = 0, last = 0;
    *t_first = NAN;
    for (size_t i = 0; i < p->n_traj; i++) {
        double d = p->traj[i].exp_in - p->traj[i].exp_out;
        int s = (d > 0.0) - (d < 0.0);
        if (s == 0) continue;
        if (last != 0 && s != last) {
            if (n == 0) *t_first = p->traj[i].t;
            n++;
        }
        last = s;
    }
    return n;
}

static void item4(const report_ctx *c, item_res *it)
{
    if (!need(it, "4", c, LV_BASE, BLK_LOAD)) return;
    int n_early = 0, n_final = 0, n_one = 0, n_ball = 0;
    tbuf ta = { .n = 0 }, tc = { .n = 0 }, td = { .n = 0 };
    tb(&ta, "(theta_i+theta_icen) - theta_o um at step 0 / final:");
    tb(&tc, "sign changes of (theta_i+theta_icen) - theta_o over time (at t s):");
    tb(&td, "final theta_ba / min(theta_i+theta_icen, theta_o), need <= %.2f:",
       REPORT_MUCH_SMALLER);
    for (int k = 0; k < NL; k++) {
        const rpoint *p = P(c, LV_BASE, BLK_LOAD, k, TE);
        const traj_pt *a = &p->traj[0], *z = &p->traj[p->n_traj - 1];
        double d0 = a->exp_in - a->exp_out, d1 = z->exp_in - z->exp_out, tx;
        int nx = crossings(p, &tx);
        double ratio = z->exp_ball / fmin(z->exp_in, z->exp_out);
        n_early += d0 > 0.0;
        n_final += d1 < 0.0;
        n_one += nx == 1;
        n_ball += ratio >= 0.0 && ratio <= REPORT_MUCH_SMALLER;
        const char *sep = k < NL - 1 ? "," : "";
        tb(&ta, " %g N %+.3f/%+.3f%s", k_loads[k], 1e6 * d0, 1e6 * d1, sep);
        if (nx > 0) tb(&tc, " %g N %d (%.0f)%s", k_loads[k], nx, tx, sep);
        else tb(&tc, " %g N 0%s", k_loads[k], sep);
        tb(&td, " %g N %.2f%s", k_loads[k], ratio, sep);
    }
    tb(&ta, "; early IR > OR at %d of %d, final OR > IR at %d of %d", n_early, NL, n_final, NL);
    add_check(it, "4a", V(n_early == NL && n_final == NL), &ta);
    tb(&tc, "; exactly one at %d of %d", n_one, NL);
    add_check(it, "4b", V(n_one == NL), &tc);
    tb(&td, "; held at %d of %d", n_ball, NL);
    add_check(it, "4c", V(n_ball == NL), &td);

    static const getter g[3] = { g_exp_in, g_exp_out, g_exp_ball };
    static const char *const nm[3] = { "theta_i+theta_icen", "theta_o", "theta_ba" };
    static const char *const key[3] = { "exp_inner_um", "exp_outer_um", "exp_ball_um" };
    tbuf t = { .n = 0 };
    bool ok = true;
    tb(&t, "final expansions um (TE); need falling over 50-200 N, rising over 400-1000 N. ");
    for (int i = 0; i < 3; i++) {
        double v[NL];
        series(c, LV_BASE, BLK_LOAD, TE, g[i], v);
        val_series(it, key[i], BLK_LOAD, v, 0, NL - 1);
        bool fall = decr(v, 0, N_LIGHT - 1), rise = incr(v, N_LIGHT, NL - 1);
        ok = ok && fall && rise;
        tb_series(&t, nm[i], BLK_LOAD, v, 0, NL - 1, 3);
        tb(&t, " [%s, %s]%s", fall ? "falls" : "does not fall", rise ? "rises" : "does not rise",
           i < 2 ? "; " : "");
    }
    add_check(it, "4d", V(ok), &t);
}

/* Index of the largest value of f over the trajectory. */
static size_t argmax_traj(const rpoint *p, int what)
{
    size_t best = 0;
    for (size_t i = 0; i < p->n_traj; i++) {
        const traj_pt *a = &p->traj[i], *b = &p->traj[best];
        double va = what == 0 ? a->Qi : what == 1 ? a->Qo : a->exp_in - a->exp_out;
        double vb = what == 0 ? b->Qi : what == 1 ? b->Qo : b->exp_in - b->exp_out;
        if (va > vb) best = i;
    }
    return best;
}

static void item5(const report_ctx *c, item_res *it)
{
    if (!need(it, "5", c, LV_BASE, BLK_LOAD)) return;
    tbuf tr = { .n = 0 }, tp = { .n = 0 }, tl = { .n = 0 }, tg = { .n = 0 }, tx = { .n = 0 };
    int n_rise = 0, n_peak = 0, n_light = 0, n_large = 0, n_dx = 0;
    tb(&tr, "peak rise of Qi/Qo over step 0 (need > %.1f %%):", 100.0 * REPORT_RISE);
    tb(&tp, "time of Qi peak / of max (theta_i+theta_icen-theta_o) / end of run s, final Qi "
       "below peak (need peaks within %.0f %% of the run time, then relaxing):",
       100.0 * REPORT_NEAR);
    tb(&tl, "final/step-0 Qi, Qo - 1 at light loads (need within +-%.0f %%):",
       100.0 * REPORT_SAME);
    tb(&tg, "final/step-0 Qi, Qo - 1 at large loads (need > +%.0f %%):", 100.0 * REPORT_ABOVE);
    tb(&tx, "delta_x um: step 0 / min (at t s) / final (need a fall, then a rise):");
    for (int k = 0; k < NL; k++) {
        const rpoint *p = P(c, LV_BASE, BLK_LOAD, k, TE);
        const traj_pt *a = &p->traj[0], *z = &p->traj[p->n_traj - 1];
        const char *sep = k < NL - 1 ? "," : "";
        size_t ii = argmax_traj(p, 0), io = argmax_traj(p, 1), id = argmax_traj(p, 2);
        double ri = p->traj[ii].Qi / a->Qi - 1.0, ro = p->traj[io].Qo / a->Qo - 1.0;
        bool rise = ri > REPORT_RISE && ro > REPORT_RISE;
        n_rise += rise;
        tb(&tr, " %g N %+.2f/%+.2f %%%s", k_loads[k], 100.0 * ri, 100.0 * ro, sep);
        double tq = p->traj[ii].t, td = p->traj[id].t;
        bool relax = z->Qi < p->traj[ii].Qi * (1.0 - REPORT_RISE);
        bool near = rise && fabs(tq - td) <= REPORT_NEAR * z->t && relax;
        n_peak += near;
        tb(&tp, " %g N %.0f/%.0f/%.0f %s%s", k_loads[k], tq, td, z->t, relax ? "yes" : "no", sep);
        double fi = z->Qi / a->Qi - 1.0, fo = z->Qo / a->Qo - 1.0;
        if (k < N_LIGHT) {
            n_light += fabs(fi) < REPORT_SAME && fabs(fo) < REPORT_SAME;
            tb(&tl, " %g N %+.2f/%+.2f %%%s", k_loads[k], 100.0 * fi, 100.0 * fo,
               k < N_LIGHT - 1 ? "," : "");
        } else {
            n_large += fi > REPORT_ABOVE && fo > REPORT_ABOVE;
            tb(&tg, " %g N %+.2f/%+.2f %%%s", k_loads[k], 100.0 * fi, 100.0 * fo, sep);
        }
        size_t im = 0;
        for (size_t i = 0; i < p->n_traj; i++)
            if (p->traj[i].dx < p->traj[im].dx) im = i;
        const double tol = 1e-9; /* m: a nanometre */
        bool dx_ok = p->traj[im].dx < a->dx - tol && z->dx > p->traj[im].dx + tol;
        n_dx += dx_ok;
        tb(&tx, " %g N %.3f/%.3f (%.0f)/%.3f%s", k_loads[k], 1e6 * a->dx, 1e6 * p->traj[im].dx,
           p->traj[im].t, 1e6 * z->dx, sep);
        char key[48];
        snprintf(key, sizeof key, "Qi_step0_%gN", k_loads[k]);
        add_val(it, key, a->Qi);
        snprintf(key, sizeof key, "Qi_peak_%gN", k_loads[k]);
        add_val(it, key, p->traj[ii].Qi);
        snprintf(key, sizeof key, "Qi_final_%gN", k_loads[k]);
        add_val(it, key, z->Qi);
        snprintf(key, sizeof key, "Qo_step0_%gN", k_loads[k]);
        add_val(it, key, a->Qo);
        snprintf(key, sizeof key, "Qo_final_%gN", k_loads[k]);
        add_val(it, key, z->Qo);
    }
    tb(&tr, "; at %d of %d", n_rise, NL);
    add_check(it, "5a", V(n_rise == NL), &tr);
    tb(&tp, "; held at %d of %d", n_peak, NL);
    add_check(it, "5b", V(n_peak == NL), &tp);
    tb(&tl, "; held at %d of %d", n_light, N_LIGHT);
    add_check(it, "5c", V(n_light == N_LIGHT), &tl);
    tb(&tg, "; held at %d of %d", n_large, NL - N_LIGHT);
    add_check(it, "5d", V(n_large == NL - N_LIGHT), &tg);
    tb(&tx, "; held at %d of %d", n_dx, NL);
    add_check(it, "5e", V(n_dx == NL), &tx);
}

static void item6(const report_ctx *c, item_res *it)
{
    if (!need(it, "6", c, LV_BASE, BLK_LOAD)) return;
    double ai0[NL], ao0[NL], ai[NL], ao[NL], wi[NL], wo[NL];
    for (int k = 0; k < NL; k++) {
        ai0[k] = g_ai(&P(c, LV_BASE, BLK_LOAD, k, TE)->first);
        ao0[k] = g_ao(&P(c, LV_BASE, BLK_LOAD, k, TE)->first);
    }
    series(c, LV_BASE, BLK_LOAD, TE, g_ai, ai);
    series(c, LV_BASE, BLK_LOAD, TE, g_ao, ao);
    series(c, LV_BASE, BLK_LOAD, WTE, g_ai, wi);
    series(c, LV_BASE, BLK_LOAD, WTE, g_ao, wo);
    val_series(it, "alpha_i_TE_deg", BLK_LOAD, ai, 0, NL - 1);
    val_series(it, "alpha_o_TE_deg", BLK_LOAD, ao, 0, NL - 1);
    val_series(it, "alpha_i_WTE_deg", BLK_LOAD, wi, 0, NL - 1);
    val_series(it, "alpha_o_WTE_deg", BLK_LOAD, wo, 0, NL - 1);

    tbuf t = { .n = 0 };
    int n = 0;
    tb(&t, "alpha_i, alpha_o deg (TE) step 0 -> final:");
    for (int k = 0; k < NL; k++) {
        n += ai0[k] > ai[k] && ao0[k] > ao[k];
        tb(&t, " %g N %.3f->%.3f, %.3f->%.3f%s", k_loads[k], ai0[k], ai[k], ao0[k], ao[k],
           k < NL - 1 ? ";" : "");
    }
    tb(&t, "; both fall at %d of %d", n, NL);
    add_check(it, "6a", V(n == NL), &t);

    t.n = 0;
    n = 0;
    tb(&t, "WTE light loads, alpha_o vs the static angle (closed form, 0 rpm) and alpha_i, "
       "deg; need alpha_o >= %.0f %% below static and alpha_i > alpha_o:", 100.0 * REPORT_STRONG);
    for (int k = 0; k < N_LIGHT; k++) {
        double as = static_angle(&P(c, LV_BASE, BLK_LOAD, k, WTE)->scene, k_loads[k], NULL) * DEG;
        bool ok = wo[k] <= (1.0 - REPORT_STRONG) * as && wi[k] > wo[k];
        n += ok;
        tb(&t, " %g N static %.3f, alpha_o %.3f (%+.1f %%), alpha_i %.3f%s", k_loads[k], as, wo[k],
           100.0 * (wo[k] / as - 1.0), wi[k], k < N_LIGHT - 1 ? ";" : "");
    }
    tb(&t, "; held at %d of %d", n, N_LIGHT);
    add_check(it, "6b", V(n == N_LIGHT), &t);

    t.n = 0;
    bool fi = decr(wi, 0, N_LIGHT - 1), ro = incr(wo, 0, N_LIGHT - 1);
    tb(&t, "WTE 50-200 N: ");
    tb_series(&t, "alpha_i deg", BLK_LOAD, wi, 0, N_LIGHT - 1, 5);
    tb(&t, " [%s]; ", fi ? "decreases" : "does not decrease");
    tb_series(&t, "alpha_o deg", BLK_LOAD, wo, 0, N_LIGHT - 1, 5);
    tb(&t, " [%s]", ro ? "increases" : "does not increase");
    add_check(it, "6c", V(fi && ro), &t);

    t.n = 0;
    bool ri = incr(wi, N_LIGHT, NL - 1), r2 = incr(wo, N_LIGHT, NL - 1);
    tb(&t, "WTE 400-1000 N: ");
    tb_series(&t, "alpha_i deg", BLK_LOAD, wi, N_LIGHT, NL - 1, 5);
    tb(&t, " [%s]; ", ri ? "increases" : "does not increase");
    tb_series(&t, "alpha_o deg", BLK_LOAD, wo, N_LIGHT, NL - 1, 5);
    tb(&t, " [%s]", r2 ? "increases" : "does not increase");
    add_check(it, "6d", V(ri && r2), &t);

    t.n = 0;
    bool d = decr(ai, 0, NL - 1);
    tb(&t, "TE final ");
    tb_series(&t, "alpha_i deg", BLK_LOAD, ai, 0, NL - 1, 5);
    tb(&t, " [%s with F_x over 50-1000 N]", d ? "decreases" : "does not decrease");
    add_check(it, "6e", V(d), &t);
}

static void item7(const report_ctx *c, item_res *it)
{
    if (!need(it, "7", c, LV_BASE, BLK_LOAD)) return;
    double te[NL], wte[NL];
    series(c, LV_BASE, BLK_LOAD, TE, g_T5, te);
    series(c, LV_BASE, BLK_LOAD, WTE, g_T5, wte);
    val_series(it, "T5_TE_C", BLK_LOAD, te, 0, NL - 1);
    val_series(it, "T5_WTE_C", BLK_LOAD, wte, 0, NL - 1);
    bool a = incr(te, 3, NL - 1), b = incr(wte, 3, NL - 1);
    tbuf t = { .n = 0 };
    tb_pairs(&t, "T5 C", BLK_LOAD, te, wte, 0, NL - 1, 5);
    tb(&t, "; over 200-1000 N: TE %s, WTE %s", a ? "increases" : "does not increase",
       b ? "increases" : "does not increase");
    add_check(it, "7a", V(a && b), &t);
}

static void item8(const report_ctx *c, item_res *it)
{
    for (int half = 0; half < 2; half++) {
        int blk = half ? BLK_S1000 : BLK_S100;
        const char *id = half ? "8b" : "8a";
        if (!need(it, id, c, LV_BASE, blk)) continue;
        double te[NL], wte[NL], d[NL];
        series(c, LV_BASE, blk, TE, g_T5, te);
        series(c, LV_BASE, blk, WTE, g_T5, wte);
        int n = 0;
        for (int k = 0; k < NL; k++) {
            d[k] = 1e3 * (wte[k] - te[k]);
            n += half ? d[k] < 0.0 : d[k] > 0.0;
        }
        val_series(it, half ? "T5_WTE_minus_TE_mK_1000N" : "T5_WTE_minus_TE_mK_100N", blk, d, 0,
                   NL - 1);
        tbuf t = { .n = 0 };
        tb(&t, "at %s: T5(WTE)-T5(TE) mK:", half ? "1000 N" : "100 N");
        for (int k = 0; k < NL; k++)
            tb(&t, " %g rpm %+.2f%s", k_speeds[k], d[k], k < NL - 1 ? "," : "");
        tb(&t, " (T5 TE at 16000 rpm %.3f C); need %s at every speed: %d of %d", te[NL - 1],
           half ? "< 0" : "> 0", n, NL);
        add_check(it, id, V(n == NL), &t);
    }
}

static void item9(const report_ctx *c, item_res *it)
{
    for (int half = 0; half < 2; half++) {
        int blk = half ? BLK_S1000 : BLK_S100, k = half ? NL - 1 : 0;
        const char *id = half ? "9b" : "9a";
        if (!need(it, id, c, LV_BASE, blk)) continue;
        double te = P(c, LV_BASE, blk, k, TE)->last.losses.total;
        double w = P(c, LV_BASE, blk, k, WTE)->last.losses.total;
        double r = fabs(te - w) / w;
        add_val(it, half ? "rel_dPT_pct_16000rpm_1000N" : "rel_dPT_pct_2000rpm_100N", 100.0 * r);
        tbuf t = { .n = 0 };
        tb(&t, "%g rpm, %s: P_T TE %.4g W, WTE %.4g W, |dP_T|/P_T(WTE) = %.3g %%; need %s",
           k_speeds[k], half ? "1000 N" : "100 N", te, w, 100.0 * r, half ? "> 10 %" : "< 5 %");
        add_check(it, id, V(half ? r > 0.10 : r < 0.05), &t);
    }
}

static void item10(const report_ctx *c, item_res *it)
{
    if (!need(it, "10", c, LV_L2, BLK_LOAD)) return;
    double lt[NL], lw[NL], pt[NL], pw[NL], ft[NL], fw[NL];
    series(c, LV_L2, BLK_LOAD, TE, g_shear, lt);
    series(c, LV_L2, BLK_LOAD, WTE, g_shear, lw);
    series(c, LV_L2, BLK_LOAD, TE, g_total, pt);
    series(c, LV_L2, BLK_LOAD, WTE, g_total, pw);
    for (int k = 0; k < NL; k++) {
        ft[k] = 100.0 * lt[k] / pt[k];
        fw[k] = 100.0 * lw[k] / pw[k];
    }
    val_series(it, "P_L_TE_W", BLK_LOAD, lt, 0, NL - 1);
    val_series(it, "P_L_WTE_W", BLK_LOAD, lw, 0, NL - 1);
    val_series(it, "P_L_share_TE_pct", BLK_LOAD, ft, 0, NL - 1);
    tbuf t = { .n = 0 };
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

static void item11(const report_ctx *c, item_res *it)
{
    if (!need(it, "11", c, LV_BASE, BLK_LOAD)) return;
    double te[NL], wte[NL];
    series(c, LV_BASE, BLK_LOAD, TE, g_slip, te);
    series(c, LV_BASE, BLK_LOAD, WTE, g_slip, wte);
    val_series(it, "P_t_TE_W", BLK_LOAD, te, 0, NL - 1);
    val_series(it, "P_t_WTE_W", BLK_LOAD, wte, 0, NL - 1);
    int n1 = 0, n2 = 0;
    for (int k = 0; k < N_LIGHT; k++) n1 += wte[k] > te[k];
    for (int k = N_LIGHT; k < NL; k++) n2 += te[k] > wte[k];
    tbuf t = { .n = 0 };
    tb_pairs(&t, "P_t W", BLK_LOAD, te, wte, 0, N_LIGHT - 1, 4);
    tb(&t, "; WTE > TE at %d of %d", n1, N_LIGHT);
    add_check(it, "11a", V(n1 == N_LIGHT), &t);
    t.n = 0;
    tb_pairs(&t, "P_t W", BLK_LOAD, te, wte, N_LIGHT, NL - 1, 4);
    tb(&t, "; TE > WTE at %d of %d", n2, NL - N_LIGHT);
    add_check(it, "11b", V(n2 == NL - N_LIGHT), &t);
}

static void item12(const report_ctx *c, item_res *it)
{
    if (!need(it, "12", c, LV_L2, BLK_LOAD)) return;
    double te[NL], wte[NL];
    series(c, LV_L2, BLK_LOAD, TE, g_spin, te);
    series(c, LV_L2, BLK_LOAD, WTE, g_spin, wte);
    val_series(it, "P_s_TE_W", BLK_LOAD, te, 0, NL - 1);
    val_series(it, "P_s_WTE_W", BLK_LOAD, wte, 0, NL - 1);
    tbuf t = { .n = 0 };
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

static void item13(const report_ctx *c, item_res *it)
{
    bool ok = true;
    for (int b = 0; b < NBLK; b++) ok = need(it, "13", c, LV_BASE, b) && ok;
    if (!ok) return;
    double v[NBLK][2][NL];
    for (int b = 0; b < NBLK; b++)
        for (int m = 0; m < 2; m++) series(c, LV_BASE, b, m, g_rolling, v[b][m]);
    val_series(it, "P_r_TE_W", BLK_LOAD, v[BLK_LOAD][TE], 0, NL - 1);
    val_series(it, "P_r_WTE_W", BLK_LOAD, v[BLK_LOAD][WTE], 0, NL - 1);
    tbuf t = { .n = 0 };
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

static void item14(const report_ctx *c, item_res *it)
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
    tbuf t = { .n = 0 };
    tb(&t, "max |h_c(TE)-h_c(WTE)|/h_c(WTE) over 24 pairs x 2 contacts = %.3g %% (%s contact, "
       "%g %s of the %s sweep: %.4g vs %.4g um); need < 5 %%", 100.0 * worst,
       wc ? "outer" : "inner", xs(wb)[wk], xunit(wb),
       wb == BLK_LOAD ? "load" : wb == BLK_S100 ? "100 N speed" : "1000 N speed", 1e6 * h_te,
       1e6 * h_w);
    add_check(it, "14a", V(worst < 0.05), &t);
}

static void item15(const report_ctx *c, item_res *it)
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
        tbuf t = { .n = 0 };
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
            const rpoint *p = P(c, LV_L2, BLK_S1000, k, TE);
            double u = orbit_speed(&p->last, &p->scene);
            worst = fmax(worst, fmax(it_[k], ot[k]) / u);
        }
        add_val(it, "slide_over_orbit_max_pct_1000N", 100.0 * worst);
        tbuf t = { .n = 0 };
        tb(&t, "1000 N: largest sliding speed / orbital speed omega_m d_m/2 = %.3g %% (TE); "
           "micro-scale if < %.0f %%", 100.0 * worst, 100.0 * REPORT_MICRO);
        if (ok100) {
            double m100 = 0.0;
            for (int k = 0; k < NL; k++) {
                const rpoint *p = P(c, LV_L2, BLK_S100, k, TE);
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

static void item16(const report_ctx *c, item_res *it)
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
        tbuf t = { .n = 0 };
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
    tbuf t = { .n = 0 };
    bool p = peak_shape(sso[TE], 0, NL - 1) && peak_shape(sso[WTE], 0, NL - 1);
    tb(&t, "100 N ");
    tb_pairs(&t, "omega_so (signed) rad/s", BLK_S100, sso[TE], sso[WTE], 0, NL - 1, 4);
    tb(&t, "; rises then falls: %s", p ? "yes" : "no");
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
    tb(&t, "seed conclusion (7), not in MODEL.md: 1000 N |omega_so| (TE) increases with speed: "
       "%s; its rise slows at high speed (last step %+.4g < first step %+.4g rad/s): %s",
       r ? "yes" : "no", dz, d0, slow ? "yes" : "no");
    check *ch = add_check(it, "16f", V(r && slow), &t);
    if (ch) ch->info = true;
}

static void item17(const report_ctx *c, item_res *it)
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
    tbuf t = { .n = 0 };
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
static acbb_status be_vs_steady(const rpoint *p, double *diff, double *rise, double *vs_run)
{
    const acbb_scene *s = &p->scene;
    const acbb_snapshot *f = &p->last;
    acbb_network nw;
    acbb_error err;
    acbb_status st = acbb_network_build(s, &nw, &err);
    if (st != ACBB_OK) return st;
    acbb_net_inputs in = { .a_i = f->balls[0].a_i, .b_i = f->balls[0].b_i,
                           .a_o = f->balls[0].a_o, .b_o = f->balls[0].b_o,
                           .omega_i = s->inner_speed, .omega_m = f->balls[0].omega_m,
                           .T_cavity_C = f->T_cavity };
    acbb_heat_sources h = { f->losses.inner, f->losses.outer, f->losses.P[ACBB_LOSS_SPIN], f->losses.P[ACBB_LOSS_DRAG], f->losses.P[ACBB_LOSS_CAGE] };
    double q[ACBB_MAX_NODES], Tbe[ACBB_MAX_NODES], Tss[ACBB_MAX_NODES];
    st = acbb_network_update(&nw, s, &in);
    if (st == ACBB_OK) {
        acbb_network_heat(&nw, s, &h, q);
        for (int i = 0; i < nw.n; i++) Tbe[i] = s->ambient_C;
        st = acbb_tnet_step(nw.net, q, 1e12, Tbe);
    }
    if (st == ACBB_OK) st = acbb_tnet_steady(nw.net, q, Tss);
    if (st == ACBB_OK) {
        *diff = *rise = *vs_run = 0.0;
        for (int i = 0; i < nw.n && i < f->n_nodes; i++) {
            *diff = fmax(*diff, fabs(Tbe[i] - Tss[i]));
            *rise = fmax(*rise, Tss[i] - s->ambient_C);
            *vs_run = fmax(*vs_run, fabs(Tss[i] - f->T[i]));
        }
    }
    acbb_network_free(&nw);
    return st;
}

static void item18(const report_ctx *c, item_res *it)
{
    const rpoint *z = c->zero;
    tbuf t = { .n = 0 };
    if (!z->ok) {
        tb(&t, "zero-speed run failed (%s): %s", acbb_status_name(z->status), z->message);
        add_check(it, "18a", V_NOT_EVAL, &t);
    } else {
        double dT = 0.0;
        for (int i = 0; i < z->last.n_nodes; i++)
            dT = fmax(dT, fabs(z->last.T[i] - z->scene.ambient_C));
        double L = z->last.losses.total;
        add_val(it, "zero_speed_total_loss_W", L);
        add_val(it, "zero_speed_max_dT_K", dT);
        tb(&t, "0 rpm, %g N: total loss %.3g W, max |T - T_amb| %.3g K over %d nodes; need 0 "
           "(<= 1e-12 W, 1e-9 K)", z->scene.axial_load, L, dT, z->last.n_nodes);
        add_check(it, "18a", V(L <= 1e-12 && dT <= 1e-9), &t);
    }

    t.n = 0;
    double worst = 0.0, worst_abs = 0.0, min_loss = INFINITY;
    size_t n_ok = 0;
    const char *wl = "";
    for (size_t i = 0; i < c->n; i++) {
        const rpoint *p = &c->pts[i];
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
    if (!z->ok) {
        tb(&t, "zero-speed run failed");
        add_check(it, "18c", V_NOT_EVAL, &t);
    } else if (z->scene.radial_load != 0.0 || z->scene.moment_load != 0.0
               || z->scene.preload != ACBB_PRELOAD_FORCE) {
        tb(&t, "the closed-form static relation is for pure thrust under force control; the "
           "preset has a radial or moment load or a displacement preload");
        add_check(it, "18c", V_NOT_EVAL, &t);
    } else {
        double Q, a = static_angle(&z->scene, z->scene.axial_load, &Q);
        double ea = fabs(z->last.balls[0].alpha_i - a) / a, eq = fabs(z->last.balls[0].Qi - Q) / Q;
        add_val(it, "static_alpha_closed_deg", a * DEG);
        add_val(it, "static_alpha_engine_deg", z->last.balls[0].alpha_i * DEG);
        add_val(it, "static_Q_closed_N", Q);
        add_val(it, "static_Q_engine_N", z->last.balls[0].Qi);
        tb(&t, "0 rpm, %g N: engine alpha %.6f deg, Q %.6g N; closed form (bisection, K_n at the "
           "operating angle) %.6f deg, %.6g N; rel. errors %.2g, %.2g; need <= 1e-4",
           z->scene.axial_load, z->last.balls[0].alpha_i * DEG, z->last.balls[0].Qi, a * DEG, Q,
           ea, eq);
        add_check(it, "18c", isfinite(a) ? V(ea <= 1e-4 && eq <= 1e-4) : V_NOT_EVAL, &t);
    }

    t.n = 0;
    add_val(it, "min_loss_term_W", min_loss);
    tb(&t, "smallest loss term (any of the five, or any ball's share) at any step of any run: "
       "%.3g W; need >= 0", min_loss);
    add_check(it, "18d", V(min_loss >= 0.0), &t);

    t.n = 0;
    const rpoint *p = P(c, LV_BASE, BLK_LOAD, NL - 1, TE);
    double diff = 0, rise = 0, vs_run = 0;
    acbb_status st = p->ok ? be_vs_steady(p, &diff, &rise, &vs_run) : p->status;
    if (st != ACBB_OK) {
        tb(&t, "%s: %s", p->label, acbb_status_name(st));
        add_check(it, "18e", V_NOT_EVAL, &t);
    } else {
        add_val(it, "be_vs_steady_max_dK", diff);
        tb(&t, "%s network: backward Euler with dt = 1e12 s from ambient vs the direct steady "
           "solve: max |dT| %.3g K for a %.3g K rise (need <= 1e-6 of it); the run's final "
           "temperatures differ from that steady solve by %.3g K", p->label, diff, rise, vs_run);
        add_check(it, "18e", V(diff <= 1e-6 * rise), &t);
    }
}

typedef void (*item_fn)(const report_ctx *, item_res *);

static const struct {
    item_fn fn;
    bool l2;
    const char *statement;
} k_items[18] = {
    { item1, false, "Total loss: P_T(WTE) > P_T(TE) at 50-200 N, P_T(WTE) < P_T(TE) at "
                    "400-1000 N (15000 rpm)." },
    { item2, false, "The TE-WTE difference of P_T is dominated by P_t and P_L at light loads "
                    "and by P_t and P_r at large loads (> 50 %)." },
    { item3, false, "P_v: TE and WTE differ by < 2 % at all loads and speeds; P_v depends "
                    "mainly on speed." },
    { item4, false, "Expansions vs time: theta_i+theta_icen > theta_o early, theta_o larger at "
                    "steady state (one crossover); theta_ba much smaller than both; steady "
                    "expansions fall over 50-200 N and rise over 400-1000 N." },
    { item5, false, "Contact loads vs time rise above step 0, peak near the maximal "
                    "theta_i+theta_icen-theta_o, then relax; final ~ step 0 at light loads, "
                    "final > step 0 at large loads; delta_x first falls, then rises." },
    { item6, false, "Contact angles: room temperature > final at all loads; WTE light loads: "
                    "alpha_o strongly reduced by centrifugal force, alpha_i > alpha_o, alpha_i "
                    "falls and alpha_o rises with F_x; WTE large loads: both rise with F_x; "
                    "TE: alpha_i falls with F_x." },
    { item7, false, "Outer-ring (node 5) steady temperature at 15000 rpm increases with F_x "
                    "for F_x >= 200 N." },
    { item8, false, "Speed sweep 2000-16000 rpm: T5(WTE) > T5(TE) at 100 N; T5(WTE) < T5(TE) "
                    "at 1000 N." },
    { item9, false, "Relative TE effect on P_T: < 5 % at 2000 rpm, 100 N; > 10 % at "
                    "16000 rpm, 1000 N." },
    { item10, true, "P_L significant at light loads, < 5 % of P_T at 1000 N; P_L(WTE) > "
                    "P_L(TE) at 100 N, P_L(TE) > P_L(WTE) at 1000 N." },
    { item11, false, "P_t: WTE > TE at light loads, TE > WTE at large loads (15000 rpm)." },
    { item12, true, "P_s(50 N) < P_s(100 N); P_s(F_x) first falls, then rises; TE raises P_s "
                    "markedly at 1000 N, little at 100 N." },
    { item13, false, "P_r increases with F_x and with speed; P_r(TE) > P_r(WTE) at large "
                     "loads, ~ equal at light loads." },
    { item14, false, "Film thickness: TE and WTE differ by < 5 %." },
    { item15, true, "100 N: inner sliding rises with speed, outer sliding rises then falls, "
                    "sliding TE < WTE; 1000 N: micro-sliding, slightly larger with TE." },
    { item16, true, "Spin: omega_si rises with speed at 100 N and 1000 N; omega_so rises then "
                    "falls at 100 N; spin at 100 N > at 1000 N; slightly lower with TE." },
    { item17, true, "Ball angular velocities vs F_x: |omega_x'| falls then levels off; "
                    "omega_z' rises below 300 N then ~ constant; |omega_y'| < 1 % of "
                    "|omega_x'| at 1000 N." },
    { item18, false, "Sanity: zero speed gives no loss and ambient temperatures; steady energy "
                     "balance to 1e-6; static thrust solution matches the closed form to "
                     "1e-4; all losses >= 0; BE with dt -> inf equals the steady solve." },
};

/* Seed section 5 lists seven conclusions; each maps onto checks above. */
static const struct {
    const char *text;
    const char *checks[3];
} k_conclusions[] = {
    { "During the temperature rise thermal deformations squeeze the balls and raise the "
      "inner and outer contact loads significantly.", { "5a", NULL } },
    { "Thermal expansion affects the power loss significantly at high speed and large load, "
      "little at low speed and light load.", { "9a", "9b", NULL } },
    { "The WTE-TE difference of total loss comes mainly from P_t and P_L at light loads, from "
      "P_t and P_r at large loads.", { "2a", "2b", NULL } },
    { "Light loads: inner-ring macro-sliding grows with speed; outer-ring sliding first rises, "
      "then falls.", { "15a", "15b", NULL } },
    { "Large loads: micro-sliding is slightly larger with thermal expansion.", { "15d", "15e",
      NULL } },
    { "Light loads: omega_si grows with speed; omega_so first rises, then falls.",
      { "16a", "16c", NULL } },
    { "Large loads: omega_si rises slowly with speed; the rise of omega_so slows at high "
      "speed.", { "16b", "16f", NULL } },
};
#define N_CONCL (sizeof k_conclusions / sizeof k_conclusions[0])

static const check *find_check(const item_res *items, const char *id)
{
    for (int i = 0; i < 18; i++)
        for (int k = 0; k < items[i].nch; k++)
            if (strcmp(items[i].ch[k].id, id) == 0) return &items[i].ch[k];
    return NULL;
}

/* NOT HELD if any check fails; HELD if all hold; otherwise NOT EVALUATED. */
static verdict combine(const verdict *v, int n)
{
    bool ne = n == 0;
    for (int i = 0; i < n; i++) {
        if (v[i] == V_NOT_HELD) return V_NOT_HELD;
        ne = ne || v[i] == V_NOT_EVAL;
    }
    return ne ? V_NOT_EVAL : V_HELD;
}

static verdict conclusion_verdict(const item_res *items, size_t i)
{
    verdict v[3];
    int n = 0;
    for (int k = 0; k < 3 && k_conclusions[i].checks[k]; k++) {
        const check *c = find_check(items, k_conclusions[i].checks[k]);
        v[n++] = c ? c->v : V_NOT_EVAL;
    }
    return combine(v, n);
}

static bool item_in_conclusion(const item_res *it, size_t i)
{
    for (int k = 0; k < 3 && k_conclusions[i].checks[k]; k++)
        for (int j = 0; j < it->nch; j++)
            if (strcmp(it->ch[j].id, k_conclusions[i].checks[k]) == 0) return true;
    return false;
}

static void evaluate_all(const report_ctx *c, item_res *items)
{
    for (int i = 0; i < 18; i++) {
        item_res *it = &items[i];
        it->num = i + 1;
        it->statement = k_items[i].statement;
        it->l2 = k_items[i].l2;
        k_items[i].fn(c, it);
        verdict v[MAX_CHECKS];
        int n = 0;
        for (int k = 0; k < it->nch; k++)
            if (!it->ch[k].info) v[n++] = it->ch[k].v;
        it->v = combine(v, n);
    }
}

/* ---- text output (80 columns) ---- */

static void wrap(FILE *f, const char *head, int indent, const char *text)
{
    int col = fprintf(f, "%s", head);
    const char *w = text;
    bool first = true;
    while (*w) {
        while (*w == ' ') w++;
        if (!*w) break;
        int len = (int)strcspn(w, " ");
        if (!first && col + 1 + len > 80) {
            fprintf(f, "\n%*s", indent, "");
            col = indent;
            first = true;
        }
        col += fprintf(f, "%s%.*s", first ? "" : " ", len, w);
        first = false;
        w += len;
    }
    fputc('\n', f);
}

static const char *level_name(const report_ctx *c, bool l2)
{
    return l2 ? "quasi-dynamic" : acbb_model_level_name(c->base.model);
}

static size_t n_failed(const report_ctx *c)
{
    size_t n = 0;
    for (size_t i = 0; i < c->n; i++) n += !c->pts[i].ok;
    return n;
}

static void counts(const item_res *items, int *nv)
{
    nv[0] = nv[1] = nv[2] = 0;
    for (int i = 0; i < 18; i++) nv[items[i].v]++;
}

static void print_text(FILE *f, const report_ctx *c, const item_res *items)
{
    char line[4600];
    snprintf(line, sizeof line, "acbb report: %s - the seed's acceptance statements "
             "(MODEL.md section 12)", c->preset);
    wrap(f, "", 0, line);
    snprintf(line, sizeof line, "Runs: %zu (%s; items marked (L2) at quasi-dynamic), %zu failed, "
             "%.1f s wall. Load sweep 50-1000 N at 15000 rpm; speed sweeps 2000-16000 rpm at "
             "100 N and 1000 N; TE and WTE; one zero-speed run. Checks: ok = held, NO = not "
             "held, n/e = not evaluated, info = not part of the verdict.",
             c->n, acbb_model_level_name(c->base.model), n_failed(c), 1e-3 * c->wall_ms);
    wrap(f, "", 0, line);
    fputc('\n', f);
    fprintf(f, "%-4s %-14s %s\n", "item", "verdict", "statement / checks");
    for (int i = 0; i < 18; i++) {
        const item_res *it = &items[i];
        char head[32], st[600];
        snprintf(head, sizeof head, "%3d  %-14s ", it->num, k_vname[it->v]);
        snprintf(st, sizeof st, "%s%s", it->l2 ? "(L2) " : "", it->statement);
        wrap(f, head, 20, st);
        for (int k = 0; k < it->nch; k++) {
            const check *ch = &it->ch[k];
            snprintf(head, sizeof head, "%5s%-4s %-5s", "", ch->id, ch->info ? "info" : k_vmark[ch->v]);
            wrap(f, head, 15, ch->text);
        }
    }
    fputc('\n', f);
    wrap(f, "", 0, "Seed conclusions (seed section 5 lists seven), each judged from the checks "
                   "it maps onto:");
    for (size_t i = 0; i < N_CONCL; i++) {
        char head[32], txt[600];
        snprintf(head, sizeof head, "(%zu)  %-14s ", i + 1, k_vname[conclusion_verdict(items, i)]);
        int n = snprintf(txt, sizeof txt, "%s [checks", k_conclusions[i].text);
        for (int k = 0; k < 3 && k_conclusions[i].checks[k] && n > 0 && (size_t)n < sizeof txt; k++)
            n += snprintf(txt + n, sizeof txt - (size_t)n, " %s", k_conclusions[i].checks[k]);
        if (n > 0 && (size_t)n < sizeof txt) snprintf(txt + n, sizeof txt - (size_t)n, "]");
        wrap(f, head, 20, txt);
    }
    int nv[3];
    counts(items, nv);
    fprintf(f, "\n%d held, %d not held, %d not evaluated\n", nv[0], nv[1], nv[2]);
}

/* ---- JSON ---- */

static void json_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\') fprintf(f, "\\%c", ch);
        else if (ch < 0x20) fprintf(f, "\\u%04x", ch);
        else fputc(ch, f);
    }
    fputc('"', f);
}

static void json_num(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, "%.10g", v);
    else fputs("null", f);
}

static void print_json(FILE *f, const report_ctx *c, const item_res *items)
{
    fputs("[\n", f);
    for (int i = 0; i < 18; i++) {
        const item_res *it = &items[i];
        fprintf(f, "  {\"item\": %d, \"statement\": ", it->num);
        json_str(f, it->statement);
        fputs(", \"verdict\": ", f);
        json_str(f, k_vname[it->v]);
        fputs(", \"level\": ", f);
        json_str(f, level_name(c, it->l2));
        fputs(", \"seed_conclusions\": [", f);
        bool first = true;
        for (size_t k = 0; k < N_CONCL; k++)
            if (item_in_conclusion(it, k)) {
                fprintf(f, "%s%zu", first ? "" : ", ", k + 1);
                first = false;
            }
        fputs("],\n   \"evidence\": {\"checks\": [", f);
        for (int k = 0; k < it->nch; k++) {
            fprintf(f, "%s\n     {\"id\": ", k ? "," : "");
            json_str(f, it->ch[k].id);
            fputs(", \"verdict\": ", f);
            json_str(f, k_vname[it->ch[k].v]);
            fprintf(f, ", \"info\": %s, \"text\": ", it->ch[k].info ? "true" : "false");
            json_str(f, it->ch[k].text);
            fputc('}', f);
        }
        fputs("],\n    \"values\": {", f);
        for (int k = 0; k < it->nval; k++) {
            fputs(k ? ", " : "", f);
            json_str(f, it->val[k].key);
            fputs(": ", f);
            json_num(f, it->val[k].v);
        }
        fprintf(f, "}}}%s\n", i < 17 ? "," : "");
    }
    fputs("]\n", f);
}

/* ---- Markdown ---- */

static void md_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '|' || *s == '*' || *s == '_') fputc('\\', f);
        fputc(*s, f);
    }
}

static void print_md(FILE *f, const report_ctx *c, const item_res *items)
{
    int nv[3];
    counts(items, nv);
    fputs("# Seed report: the acceptance statements of MODEL.md section 12\n\n", f);
    fprintf(f, "Generated by `acbb report %s", c->preset);
    for (int i = 0; i < c->n_sets; i++) fprintf(f, " --set %s", c->sets[i]);
    fputs("` (src/cli_report.c). Physics over wished-for results: every statement is judged "
          "from runs of the engine, HELD, NOT HELD or NOT EVALUATED, with the numbers that "
          "decide it.\n\n", f);
    fprintf(f, "Runs: %zu at %s (the preset's level), items marked (L2) at quasi-dynamic; %zu "
            "failed. Load sweep 50, 100, 150, 200, 400, 600, 800, 1000 N at 15000 rpm; speed "
            "sweeps 2000-16000 rpm (step 2000) at 100 N and 1000 N; each with (TE) and without "
            "(WTE) thermal expansion; one zero-speed run. \"Room temperature\" is step 0 of the "
            "TE run, \"final\" its converged state; per-ball numbers are ball 0's.\n\n", c->n,
            acbb_model_level_name(c->base.model), n_failed(c));
    fprintf(f, "**%d held, %d not held, %d not evaluated** (of 18).\n\n", nv[0], nv[1], nv[2]);
    fputs("| # | verdict | level | statement |\n|---|---|---|---|\n", f);
    for (int i = 0; i < 18; i++) {
        fprintf(f, "| %d | %s | %s | ", items[i].num, k_vname[items[i].v],
                level_name(c, items[i].l2));
        md_text(f, items[i].statement);
        fputs(" |\n", f);
    }
    fputs("\n## Seed conclusions (seed section 5)\n\n| # | verdict | conclusion | checks |\n"
          "|---|---|---|---|\n", f);
    for (size_t i = 0; i < N_CONCL; i++) {
        fprintf(f, "| (%zu) | %s | ", i + 1, k_vname[conclusion_verdict(items, i)]);
        md_text(f, k_conclusions[i].text);
        fputs(" |", f);
        for (int k = 0; k < 3 && k_conclusions[i].checks[k]; k++)
            fprintf(f, " %s", k_conclusions[i].checks[k]);
        fputs(" |\n", f);
    }
    fputs("\n## Evidence\n", f);
    for (int i = 0; i < 18; i++) {
        const item_res *it = &items[i];
        fprintf(f, "\n### %d. %s (%s)\n\n", it->num, k_vname[it->v], level_name(c, it->l2));
        md_text(f, it->statement);
        fputs("\n\n", f);
        for (int k = 0; k < it->nch; k++) {
            fprintf(f, "- **%s %s**: ", it->ch[k].id,
                    it->ch[k].info ? "info" : k_vname[it->ch[k].v]);
            md_text(f, it->ch[k].text);
            fputc('\n', f);
        }
    }
    fputs("\nThresholds MODEL.md does not give are fixed in src/cli_report.c (REPORT_*) and "
          "named in each check.\n", f);
}

/* The Markdown goes to a temporary file next to FILE, created before the
 * runs so a bad path fails fast, and renamed over FILE when complete. */
typedef struct {
    const char *path;
    char tmp[4096];
    FILE *f;
} md_file;

static int md_open(md_file *m, const char *path)
{
    m->path = path;
    int n = snprintf(m->tmp, sizeof m->tmp, "%s.tmpXXXXXX", path);
    if (n < 0 || (size_t)n >= sizeof m->tmp) {
        fprintf(stderr, "acbb: report: --md %s: path too long\n", path);
        return EXIT_BADINPUT;
    }
    int fd = mkstemp(m->tmp);
    if (fd < 0 || !(m->f = fdopen(fd, "w"))) {
        fprintf(stderr, "acbb: report: --md %s: %s\n", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(m->tmp);
        }
        return EXIT_BADINPUT;
    }
    return 0;
}

static int md_close(md_file *m, bool keep)
{
    bool ok = fflush(m->f) == 0 && !ferror(m->f) && fsync(fileno(m->f)) == 0;
    ok = fclose(m->f) == 0 && ok;
    if (keep && ok && rename(m->tmp, m->path) == 0) return 0;
    if (keep) fprintf(stderr, "acbb: report: --md %s: %s\n", m->path, strerror(errno));
    unlink(m->tmp);
    return keep ? EXIT_INTERNAL : 0;
}

/* ---- arguments and entry ---- */

static const char k_usage[] =
    "usage: acbb report PRESET [--set section.key=value]... [--json] [--md FILE]\n";

typedef struct {
    const char *preset, *md;
    const char **sets;
    int n_sets;
    bool json;
} rargs;

static int usage(const char *fmt, const char *what)
{
    fputs("acbb: report: ", stderr);
    fprintf(stderr, fmt, what);
    fputc('\n', stderr);
    fputs(k_usage, stderr);
    return EXIT_BADINPUT;
}

/* By hand, as in src/cli.c: four options, no user text reaches a shell. */
static int parse(rargs *a, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i], *v = NULL;
        bool is_set = strncmp(s, "--set", 5) == 0 && (s[5] == '\0' || s[5] == '=');
        bool is_md = strncmp(s, "--md", 4) == 0 && (s[4] == '\0' || s[4] == '=');
        if (is_set || is_md) {
            const char *eq = s + (is_set ? 5 : 4);
            if (*eq == '=') v = eq + 1;
            else if (i + 1 < argc) v = argv[++i];
            else return usage("%s needs a value", s);
            if (is_set) a->sets[a->n_sets++] = v;
            else a->md = v;
        } else if (strcmp(s, "--json") == 0) {
            a->json = true;
        } else if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            fputs(k_usage, stdout);
            return -1;
        } else if (s[0] == '-' && s[1] != '\0') {
            return usage("unknown option %s", s);
        } else if (!a->preset) {
            a->preset = s;
        } else {
            return usage("unexpected argument %s", s);
        }
    }
    if (!a->preset) return usage("%s", "missing PRESET");
    return 0;
}

static int load_base(const rargs *a, acbb_scene *s)
{
    acbb_error err = { { 0 } };
    acbb_status st = acbb_scene_load(a->preset, s, &err);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: report: %s\n", err.msg[0] ? err.msg : acbb_status_name(st));
        return EXIT_BADINPUT;
    }
    st = acbb_scene_apply_edits(s, a->sets, (size_t)a->n_sets, &err);
    if (st != ACBB_OK) {
        fprintf(stderr, "acbb: report: %s\n", err.msg[0] ? err.msg : acbb_status_name(st));
        return EXIT_BADINPUT;
    }
    return 0;
}

static void free_ctx(report_ctx *c)
{
    for (size_t i = 0; c->pts && i < c->n; i++) free(c->pts[i].traj);
    free(c->pts);
}

int acbb_cli_report(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[0], "report") != 0 && strcmp(argv[1], "report") == 0) {
        argc--;
        argv++;
    }
    rargs a = { 0 };
    a.sets = calloc((size_t)(argc > 0 ? argc : 1), sizeof *a.sets);
    if (!a.sets) return EXIT_INTERNAL;
    int rc = parse(&a, argc, argv);
    report_ctx c = { 0 };
    md_file md = { 0 };
    item_res *items = NULL;
    if (rc) goto out;
    c.preset = a.preset;
    c.sets = a.sets;
    c.n_sets = a.n_sets;
    if ((rc = load_base(&a, &c.base))) goto out;
    if (a.md && (rc = md_open(&md, a.md))) goto out;
    items = calloc(18, sizeof *items);
    if (!items || build_runs(&c)) {
        fputs("acbb: report: out of memory\n", stderr);
        rc = EXIT_INTERNAL;
        goto out;
    }
    run_set(&c);
    evaluate_all(&c, items);
    if (a.json) print_json(stdout, &c, items);
    else print_text(stdout, &c, items);
    if (a.md) print_md(md.f, &c, items);
    rc = n_failed(&c) ? EXIT_SOLVER : EXIT_OK;
    if (fflush(stdout) != 0 || ferror(stdout)) rc = EXIT_INTERNAL;
out:
    if (md.f) {
        int mrc = md_close(&md, rc == EXIT_OK || rc == EXIT_SOLVER);
        if (mrc) rc = mrc;
    }
    free(items);
    free_ctx(&c);
    free(a.sets);
    return rc < 0 ? EXIT_OK : rc;
}
