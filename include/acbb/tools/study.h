/* acbb — the seed study: MODEL.md section 12 (the seed's qualitative
 * acceptance statements, items 1-18) and the seed's conclusions (seed
 * section 5), judged from runs of the engine.
 *
 * The study is data: a table of rows {item number, statement, function
 * over the run results}. Each function turns its statement into numeric
 * checks (a verdict and the evidence: a short sentence with the numbers
 * that decide it, plus named values); the item's verdict combines them.
 * The engine prints nothing: clients format the plain structs below.
 *
 * Run set (MODEL.md section 12 "Conditions"): load sweep 50..1000 N at
 * 15000 rpm and speed sweeps 2000..16000 rpm at 100 N and 1000 N, each with
 * (TE) and without (WTE) thermal expansion, at the scene's fidelity level;
 * the same again at quasi-dynamic for the (L2) items (shared when the scene
 * is quasi-dynamic already); one zero-speed run at the scene's load; four
 * zero-speed WTE runs at the light loads (the static angle of item 6).
 * Speed and load of the sweeps override the scene's; every other key is the
 * scene's. Runs are driven by acbb_sim_drive; a run hook records what the
 * checks need from each step's snapshot. Only the public sim API is used:
 * recomputations of the physics (closed forms, network solves) live in
 * tests (tests/test_study.c).
 *
 * Ownership: acbb_study_plan allocates a study that acbb_study_free
 * releases; everything the accessors return is owned by the study. */
#ifndef ACBB_STUDY_H
#define ACBB_STUDY_H

#include "acbb/cancel_flag.h"
#include <stddef.h>
#include "acbb/batch.h"
#include "acbb/scene.h"
#include "acbb/tools/sensitivity.h"
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    ACBB_VERDICT_HELD,
    ACBB_VERDICT_NOT_HELD,
    ACBB_VERDICT_NOT_EVALUATED
} acbb_verdict;

/* "HELD", "NOT HELD", "NOT EVALUATED". */
const char *acbb_verdict_name(acbb_verdict v);

/* ---- run results (what the checks read; plain data a test can build) ---- */

/* What the transient items need from each step of a recorded run. */
typedef struct {
    double t;                    /* simulated time, s */
    double exp_in;               /* theta_i + theta_icen, m */
    double exp_out, exp_ball;    /* theta_o, theta_ba, m */
    double Qi, Qo;               /* ball 0's contact loads, N */
    double dx;                   /* delta_x, m */
} acbb_study_step;

typedef struct {
    acbb_scene scene;            /* the scene this point ran */
    char label[96];              /* "15000 rpm, 100 N, TE, quasi-dynamic" */
    int record;                  /* keep the per-step trajectory */
    int skip;                    /* the scene edit failed: nothing to run */
    int ok;                      /* reached thermal steady state */
    acbb_status status;
    char message[520];
    acbb_snapshot first, last;   /* step 0 and the final step */
    acbb_study_step *traj;       /* owned by the study (malloc) */
    size_t n_traj, cap_traj;
    int oom;
    double min_loss;             /* smallest loss term seen at any step, W */
    double wall_ms;
    double runaway_t;            /* > 0: its transient ran away then (s); its steady values
                                  * are the steady solve's (MODEL.md 14, two branches) */
    /* A steady point's converged state (batch.h), kept by a study whose
     * points start none from another's; the robustness's perturbed
     * studies start each steady point from the base study's (issue 30). */
    acbb_warm *warm;             /* owned (acbb_study_free_runs frees it) */
    const acbb_warm *warm_from;  /* not owned: NULL, or the base point's */
} acbb_study_point;

#define ACBB_STUDY_NPTS 8        /* points per sweep */
#define ACBB_STUDY_NLIGHT 4      /* loads[0..3] are "light", [4..7] "large" */
enum { ACBB_STUDY_LOAD, ACBB_STUDY_S100, ACBB_STUDY_S1000, ACBB_STUDY_NSWEEPS };
enum { ACBB_STUDY_TE = 0, ACBB_STUDY_WTE = 1 };
enum { ACBB_STUDY_BASE = 0, ACBB_STUDY_L2 = 1 };

/* The sweep abscissae: loads in N, speeds in rpm. */
extern const double acbb_study_loads[ACBB_STUDY_NPTS];
extern const double acbb_study_speeds[ACBB_STUDY_NPTS];

/* The run set. sweep[level][sweep] points at 2 * NPTS points laid out
 * [2k + TE/WTE]; the L2 sweeps alias the base ones when the scene is
 * quasi-dynamic. */
typedef struct {
    acbb_model_level model;      /* the scene's level */
    acbb_study_point *all;
    size_t n;
    acbb_study_point *sweep[2][ACBB_STUDY_NSWEEPS];
    acbb_study_point *zero;      /* 0 rpm at the scene's load */
    acbb_study_point *statics;   /* 0 rpm, WTE, at the NLIGHT light loads */
    double wall_ms;
} acbb_study_runs;

/* ---- results ---- */

#define ACBB_STUDY_MAX_CHECKS 8
#define ACBB_STUDY_MAX_VALUES 200
#define ACBB_STUDY_TEXT 1400

typedef struct {
    char id[8];                  /* "5b" */
    acbb_verdict verdict;
    int info;                    /* reported, not part of the item verdict */
    char text[ACBB_STUDY_TEXT];  /* the numbers that decide it */
} acbb_study_check;

typedef struct {
    char key[48];                /* "P_T_TE_W_50N" */
    double v;
} acbb_study_value;

typedef struct {
    int num;                     /* MODEL.md section 12 item number */
    const char *statement;
    int l2;                      /* judged at quasi-dynamic */
    acbb_verdict verdict;
    int n_checks;
    acbb_study_check checks[ACBB_STUDY_MAX_CHECKS];
    int n_values;
    acbb_study_value values[ACBB_STUDY_MAX_VALUES];
    /* Internal to the check table's evaluation, 0 in every result: the
     * text-free mode (a perturbed study's rows: no text or value made) and
     * whether a text it did not make could have changed a verdict. */
    int text_free, text_suspect;
} acbb_study_item;

/* One row of the check table. fn appends checks and values to `out`
 * (num, statement and l2 already set); the item's verdict is then NOT HELD
 * if a non-info check fails, HELD if all hold, else NOT EVALUATED. */
typedef void (*acbb_study_fn)(const acbb_study_runs *runs, acbb_study_item *out);
typedef struct {
    int num;
    int l2;
    acbb_study_fn fn;
    const char *statement;       /* MODEL.md section 12, condensed */
} acbb_study_row;

const acbb_study_row *acbb_study_table(size_t *n);

/* Evaluate one row over run results (clears `out` first). Non-finite
 * numbers never reach the evidence: a check whose deciding number is
 * undefined (a zero denominator) is NOT EVALUATED and says so. */
void acbb_study_eval_row(const acbb_study_row *row, const acbb_study_runs *runs,
                         acbb_study_item *out);

/* Seed section 5's conclusions, each mapped onto checks of the table. */
#define ACBB_STUDY_CONCL_CHECKS 3
typedef struct {
    const char *text;
    const char *checks[ACBB_STUDY_CONCL_CHECKS]; /* ids, NULL-terminated if fewer */
} acbb_study_conclusion;

const acbb_study_conclusion *acbb_study_conclusions(size_t *n);

/* ---- the study ---- */

typedef struct acbb_study acbb_study;

/* Plan the run set from `base` (copied). Nothing runs yet. Errors: ENOMEM;
 * a scene edit that fails marks its point (skip, status, message). */
acbb_status acbb_study_plan(const acbb_scene *base, acbb_study **out, acbb_error *err);

/* Run every point on the batch runner with `jobs` workers (0:
 * acbb_batch_cpus(); batch.h), then evaluate the table. Points only read
 * at their steady state take the steady solve; the recorded TE load sweep
 * (items 4, 5) runs the scene's transient. `cancel` (may be NULL), when set, stops the runs:
 * unfinished points end ACBB_CANCELLED and the items that need them are
 * NOT EVALUATED. Returns ACBB_OK when every run reached steady state, else
 * the status of the first failed run (the results are complete either
 * way), or ACBB_CANCELLED. */
acbb_status acbb_study_run(acbb_study *s, int jobs, const acbb_atomic_int *cancel);

/* Re-evaluate the table over the current run results (after a caller
 * changed them through acbb_study_results: tests build results this way). */
void acbb_study_evaluate(acbb_study *s);

acbb_study_runs *acbb_study_results(acbb_study *s);
size_t acbb_study_n_failed(const acbb_study *s);

size_t acbb_study_n_items(const acbb_study *s);
const acbb_study_item *acbb_study_item_at(const acbb_study *s, size_t i);
/* The check `id` ("5a") or NULL. */
const acbb_study_check *acbb_study_find_check(const acbb_study *s, const char *id);
acbb_verdict acbb_study_conclusion_verdict(const acbb_study *s, size_t i);
/* 1 if item i has a check that conclusion k maps onto. */
int acbb_study_item_in_conclusion(const acbb_study *s, size_t i, size_t k);
/* counts[v] = items with verdict v. */
void acbb_study_counts(const acbb_study *s, int counts[3]);

void acbb_study_free(acbb_study *s);

/* ---- robustness over the plausible ranges (sensitivity.h) ----
 *
 * MODEL.md 13: several verdicts rest on sub-micron balances, so each is
 * reported with the single plausible changes that would turn it. For every
 * uncertain input (acbb_sens_inputs: the schema's plausible ranges, `acbb
 * keys`) and each end of its range, the study's own run set is run on the
 * scene with that one change and the whole check table is evaluated there;
 * an item is "turned" by an end where its verdict differs from the
 * verdict at the scene's values. Physics is not changed: this only says how
 * close each verdict is to the uncertain inputs. Item 18 (sanity) is
 * model-independent and is not varied.
 *
 * Sharing (no run is repeated): every perturbed point runs in ONE batch; an
 * end equal to the scene's value is the scene itself (no runs); a point on
 * which the input provably has no effect is taken from the base study
 * instead of run again (study_robust.c lists these cases, each tested
 * bit-for-bit in tests/test_study_sens.c: the expansion coefficients in a
 * WTE run, a surroundings film coefficient on a fixed face, phi_p in the
 * 46-node network); the zero-speed run only serves item 18. */

/* The sign statements of MODEL.md 12 (the sign of a TE - WTE difference, or
 * a threshold on its relative size, at one load and speed of the study's
 * sweeps): the difference itself per input end, read from the same runs. */
typedef struct {
    int item;                    /* MODEL.md 12 item */
    const char *what;            /* "P_T(TE) - P_T(WTE) > 0 at 1000 N" */
    double load_N;
    const char *metric;          /* sensitivity.h metric, taken TE - WTE */
    int want;                    /* +1: y > thr, -1: y < thr, +2: |y| > thr, -2: |y| < thr */
    double speed_rpm;            /* operating speed of the condition */
    int rel;                     /* y = (TE - WTE) / |WTE| instead of TE - WTE */
    double thr;                  /* the threshold (0 for a sign) */
} acbb_study_sign;

const acbb_study_sign *acbb_study_signs(size_t *n);

typedef struct {
    char key[64];                /* "surroundings.shaft_bore" */
    char value[64];              /* the end of its range: "convective" */
    double y;                    /* the difference there */
} acbb_study_turn;

typedef struct {
    const acbb_study_sign *sign;
    int ok;                      /* the scene's run gave a value */
    double y;                    /* the difference at the scene's values */
    int holds;                   /* the condition holds at y */
    size_t n_inputs, failed;     /* inputs varied; ends without a value */
    size_t n_turns;
    acbb_study_turn turns[2 * ACBB_SENS_MAX];
} acbb_study_robust;

/* One end that turns an item (or leaves it NOT EVALUATED: a run failed),
 * or only some of its checks (turns_item 0: the item's verdict stays). */
typedef struct {
    char key[64], value[64];     /* the input and the end: "surroundings.cap", "convective" */
    int turns_item;              /* the item's verdict differs from the scene's */
    acbb_verdict verdict;        /* the item's verdict with that one change */
    int n_checks;                /* its checks whose verdict differs from the scene's */
    acbb_study_check checks[ACBB_STUDY_MAX_CHECKS]; /* as evaluated there (the numbers) */
} acbb_study_flip;

typedef struct {
    int num;                     /* MODEL.md 12 item */
    acbb_verdict verdict;        /* at the scene's values */
    int varied;                  /* 0: item 18, not varied */
    size_t n_turns;              /* flips with turns_item */
    size_t n_flips;              /* ends that change any check's verdict */
    acbb_study_flip *flips;      /* owned by the result; item turns first */
} acbb_study_item_rob;

/* Called from the batch's workers, one at a time, after each run. */
typedef void (*acbb_study_progress_fn)(void *ctx, size_t done, size_t total);

typedef struct {
    const char *const *keys;     /* only these inputs ("section.key"); NULL: all */
    size_t n_keys;
    int jobs;                    /* workers (0: acbb_batch_cpus()) */
    const acbb_atomic_int *cancel;    /* set: stop (ACBB_CANCELLED) */
    const acbb_study_row *rows;  /* the check table (NULL: acbb_study_table) */
    size_t n_rows;
    acbb_study_progress_fn progress; /* may be NULL */
    void *ctx;
} acbb_study_rob_opts;

typedef struct {
    size_t n_inputs, n_ends;     /* inputs varied; ends with a scene of their own */
    size_t n_same;               /* ends equal to the scene's value (nothing to run) */
    size_t n_runs, n_shared;     /* Sims run; points taken from the base study */
    size_t n_failed;             /* perturbed runs that did not reach steady state */
    size_t n_items;
    acbb_study_item_rob *items;  /* one per row, in table order */
    size_t n_signs;
    acbb_study_robust *signs;    /* one per acbb_study_signs row */
    double wall_ms;
} acbb_study_rob;

/* Robustness of `base`'s verdicts; `base` must have run (acbb_study_run:
 * its runs are the reference and are not repeated). Errors: ACBB_EINVAL
 * (an unknown key in o->keys, a scene edit), ACBB_ENOMEM, ACBB_CANCELLED;
 * `out` is then empty. Free with acbb_study_rob_free. */
acbb_status acbb_study_robustness(const acbb_study *base, const acbb_study_rob_opts *o,
                                  acbb_study_rob *out, acbb_error *err);
void acbb_study_rob_free(acbb_study_rob *r);
/* acbb_study_robustness's first check on its own: every o->keys is an
 * uncertain input of scene `s`; ACBB_OK, or ACBB_EINVAL with the same
 * message. A caller refuses bad keys with it before running the study
 * (issue 28 item 13: `report --inputs BAD` ran the whole study first). */
acbb_status acbb_study_rob_check_keys(const acbb_scene *s, const acbb_study_rob_opts *o,
                                      acbb_error *err);

/* The scene `s` was planned from. */
const acbb_scene *acbb_study_scene(const acbb_study *s);

/* ---- the TE/WTE comparison table (`acbb study PRESET`) ----
 *
 * The study's three sweeps on the scene as given, each point with (TE) and
 * without (WTE) thermal expansion, otherwise equal: the load sweep
 * (acbb_study_loads) at the scene's own speed (the check study's is 15000
 * rpm), the speed sweeps (acbb_study_speeds) at 100 N and 1000 N. Every
 * other key is the scene's, its fidelity included; each point runs as its
 * scene says (by default the transient from ambient, whose iteration count
 * a table can publish). The plan is plain data owned by the caller. */

#define ACBB_STUDY_COMPARE_N (ACBB_STUDY_NSWEEPS * ACBB_STUDY_NPTS * 2)

typedef struct {
    acbb_scene scene;            /* the scene with speed, load and TE set */
    int sweep;                   /* ACBB_STUDY_LOAD, _S100 or _S1000 */
    int k;                       /* its index in the sweep, 0..NPTS-1 */
    int mode;                    /* ACBB_STUDY_TE or ACBB_STUDY_WTE */
    double x;                    /* the abscissa: load in N (load sweep), else rpm */
} acbb_study_compare_point;

/* Pairs [first, first + count) of the points: pair k is points 2k (TE) and
 * 2k+1 (WTE). */
typedef struct {
    int sweep;                   /* ACBB_STUDY_LOAD, _S100 or _S1000 */
    const char *name;            /* "load", "speed_100N", "speed_1000N" (static) */
    char title[64];              /* "load sweep at 15000 rpm", "speed sweep at 100 N" */
    size_t first, count;
} acbb_study_compare_block;

/* Points in table order: sweep by sweep, k ascending, TE then WTE. */
typedef struct {
    acbb_study_compare_point pts[ACBB_STUDY_COMPARE_N];
    acbb_study_compare_block blocks[ACBB_STUDY_NSWEEPS];
} acbb_study_compare;

/* Fill `out` from `base` (copied into every point). Nothing runs. */
void acbb_study_compare_plan(const acbb_scene *base, acbb_study_compare *out);

/* Run every point of `c` on the batch runner (batch.h: `jobs` 0 is
 * acbb_batch_cpus(); `cancel` may be NULL). `done` (may be NULL) gets
 * each point's result, index = its place in c->pts; `stats` may be NULL.
 * Returns acbb_batch_run's status (ACBB_CANCELLED when a cancel stopped
 * the batch; failed points are results, not errors). */
acbb_status acbb_study_compare_run(const acbb_study_compare *c, int jobs,
                                   const acbb_atomic_int *cancel, acbb_batch_done_fn done,
                                   void *ctx, acbb_batch_stats *stats);

#ifdef __cplusplus
}
#endif

#endif
