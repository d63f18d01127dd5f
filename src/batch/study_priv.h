/* acbb — the seed study's private helpers, shared by its check files
 * (study_items_*.c): evidence buffers, series over a sweep, shape tests.
 * Not installed; the public interface is include/acbb/tools/study.h. */
#ifndef ACBB_STUDY_PRIV_H
#define ACBB_STUDY_PRIV_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/tools/study.h"

/* Thresholds MODEL.md section 12 does not give (each check names its own). */
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

#define NL ACBB_STUDY_NPTS
#define N_LIGHT ACBB_STUDY_NLIGHT
#define BLK_LOAD ACBB_STUDY_LOAD
#define BLK_S100 ACBB_STUDY_S100
#define BLK_S1000 ACBB_STUDY_S1000
#define NBLK ACBB_STUDY_NSWEEPS
#define TE ACBB_STUDY_TE
#define WTE ACBB_STUDY_WTE
#define LV_BASE ACBB_STUDY_BASE
#define LV_L2 ACBB_STUDY_L2
#define k_loads acbb_study_loads
#define k_speeds acbb_study_speeds
/* Degrees per radian, as the report always computed it (the same rounding
 * keeps every printed number unchanged). */
#define DEG_PER_RAD (180.0 / 3.14159265358979323846)

typedef acbb_verdict verdict;
#define V_HELD ACBB_VERDICT_HELD
#define V_NOT_HELD ACBB_VERDICT_NOT_HELD
#define V_NOT_EVAL ACBB_VERDICT_NOT_EVALUATED

static inline verdict V(bool held) { return held ? V_HELD : V_NOT_HELD; }

static inline const acbb_study_point *P(const acbb_study_runs *r, int lv, int blk, int k, int m)
{
    return &r->sweep[lv][blk][2 * k + m];
}

/* ---- the study object and its run set (study.c) ---- */

struct acbb_study {
    acbb_scene base;
    acbb_study_runs runs;
    size_t n_items;
    acbb_study_item *items;
};

/* The run set of `base` (nothing runs yet); ACBB_ENOMEM. */
acbb_status acbb_study_plan_runs(acbb_study_runs *r, const acbb_scene *base);
void acbb_study_free_runs(acbb_study_runs *r);
/* End `hi` of input `in` planned from the base study's run set `b`: each
 * point's scene is b's with the end applied. The study's edits touch
 * other keys than the input's, so every scene is the one
 * acbb_study_plan_runs makes from the base scene with the end applied,
 * with one key edit a point instead of four or five (issue 30); the
 * cross-field rules run as there, once on the final scene. 1; 0 (nothing
 * planned) when a point of b was skipped (no base scene to start from) or
 * out of memory. */
int acbb_study_plan_end(acbb_study_runs *r, const acbb_study_runs *b, const acbb_sens_input *in,
                        int hi);
/* Run the listed points on one pool of `jobs` threads; `progress` (may be
 * NULL) after each finished point, under a lock. checks_only: for run sets
 * that only the check table reads (the robustness's perturbed studies):
 * no rating life (acbb_sim_opts.skip_life) and no state kept to start
 * others from. */
void acbb_study_run_list(acbb_study_point *const *pts, size_t n, int jobs, int checks_only,
                         const atomic_int *cancel, acbb_study_progress_fn progress, void *ctx);

/* The sign conditions from a run set (study_sens.c): the scene's value
 * into o (o->sign set), then one end at a time. */
void acbb_study_sign_base(const acbb_study_runs *r, acbb_study_robust *o);
void acbb_study_sign_end(const acbb_study_runs *r, const char *key, const char *value,
                         acbb_study_robust *o);

/* ---- evidence text ---- */

typedef struct {
    char s[ACBB_STUDY_TEXT];
    size_t n;
    char win[2];                 /* text-free mode: the last two characters (study_evidence.c) */
    acbb_study_item *it;         /* the item the text is for (its text_free mode) */
} tbuf;
#define TB(item) { .n = 0, .it = (item) }

/* Text-free mode (issue 30: a perturbed study's check table, whose texts
 * only a changed verdict prints), on while an item's text_free is set: tb
 * formats nothing for it (n still counts what it would write), add_check
 * keeps no text, add_val no value. A number printed non-finite, or "nan"
 * or "inf" in the text it would have made (numbers as "0"), sets the
 * item's text_suspect: its verdicts may differ from the text's (sanitize),
 * so it is made again with text. */
/* acbb_study_eval_row without the texts (and values): 1 when its
 * verdicts, item and checks, are the text's (none suspect), else 0 (make
 * it with text). */
int acbb_study_eval_verdicts(const acbb_study_row *row, const acbb_study_runs *runs,
                             acbb_study_item *out);

void acbb_study_tb(tbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void acbb_study_add_val(acbb_study_item *it, const char *key, double v);
acbb_study_check *acbb_study_add_check(acbb_study_item *it, const char *id, verdict v,
                                       const tbuf *text);
/* NOT EVALUATED (with the failed run's status) unless every point of the
 * sweep reached steady state. */
bool acbb_study_need(acbb_study_item *it, const char *id, const acbb_study_runs *r, int lv,
                     int blk);
#define tb acbb_study_tb
#define add_val acbb_study_add_val
#define add_check acbb_study_add_check
#define need acbb_study_need

/* ---- series over a sweep ---- */

typedef double (*getter)(const acbb_snapshot *);
double acbb_study_g_total(const acbb_snapshot *s);
double acbb_study_g_T5(const acbb_snapshot *s);

/* The five losses of the seed, in one place (name, getter), so a change of
 * acbb_losses touches only this list (study_evidence.c). */
typedef struct {
    const char *symbol;          /* "P_L" */
    getter get;
} acbb_study_loss;
enum { LOSS_SHEAR, LOSS_SLIP, LOSS_SPIN, LOSS_ROLLING, LOSS_DRAG, N_LOSSES };
extern const acbb_study_loss acbb_study_loss_list[N_LOSSES];
/* Smallest of the loss terms and every ball's share, W. */
double acbb_study_min_loss(const acbb_snapshot *s);

void acbb_study_series(const acbb_study_runs *r, int lv, int blk, int m, getter g, double *v);
bool acbb_study_incr(const double *v, int a, int z);
bool acbb_study_decr(const double *v, int a, int z);
/* "Rises then falls" (MODEL.md 12 items 15b, 16c): strict rises to an
 * interior maximum, strict falls from it to the lowest value after it; a
 * tail after that low is read as level, not as a new rise, while it stays
 * within REPORT_SAME (the report's "approximately equal") of the fall. A
 * signed series that crosses zero (omega_so) has no scale of its own near
 * zero, so the tail is measured against the fall, the swing the statement
 * is about. */
typedef struct {
    int peak, low;               /* indices of the maximum and the low after it */
    double fall, tail;           /* v[peak] - v[low]; largest v[k] - v[low] after the low */
} acbb_study_shape;
bool acbb_study_peak_tail(const double *v, int a, int z, acbb_study_shape *s);
bool acbb_study_peak(const double *v, int a, int z);
bool acbb_study_valley(const double *v, int a, int z);
double acbb_study_spread(const double *v, int a, int z);
const double *acbb_study_xs(int blk);
const char *acbb_study_xunit(int blk);
void acbb_study_tb_series(tbuf *t, const char *what, int blk, const double *v, int a, int z,
                          int prec);
void acbb_study_tb_pairs(tbuf *t, const char *what, int blk, const double *te,
                         const double *wte, int a, int z, int prec);
void acbb_study_val_series(acbb_study_item *it, const char *name, int blk, const double *v,
                           int a, int z);
/* "<what> peak X at x, low Y at x, tail +T = p % of the fall F (q % of |Y|)". */
void acbb_study_tb_shape(tbuf *t, const char *what, int blk, const double *v,
                         const acbb_study_shape *s);
/* The TE and WTE series of g over the load sweep of level lv, kept as the
 * values "<name>_TE_<unit>_50N"...; false (a NOT EVALUATED check `id`) if a
 * run of the sweep failed. */
bool acbb_study_load_pair(const acbb_study_runs *r, acbb_study_item *it, const char *id, int lv,
                          getter g, const char *name, const char *unit, double *te,
                          double *wte);
/* Checks `ida` (WTE > TE at every light load) and `idb` (TE > WTE at every
 * large load) over load-sweep series, "what TE/WTE: ..." and the counts. */
void acbb_study_light_large(acbb_study_item *it, const char *ida, const char *idb,
                            const char *what, const double *te, const double *wte,
                            const char *fmt_light, const char *fmt_large);
#define load_pair acbb_study_load_pair
#define light_large acbb_study_light_large
#define series acbb_study_series
#define incr acbb_study_incr
#define decr acbb_study_decr
#define peak_shape acbb_study_peak
#define valley_shape acbb_study_valley
#define spread acbb_study_spread
#define xs acbb_study_xs
#define xunit acbb_study_xunit
#define tb_series acbb_study_tb_series
#define tb_pairs acbb_study_tb_pairs
#define tb_shape acbb_study_tb_shape
#define val_series acbb_study_val_series

/* ---- the item functions (study_items_a.c: 1-9, study_items_b.c: 10-18) ---- */

void acbb_study_item1(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item2(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item3(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item4(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item5(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item6(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item7(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item8(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item9(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item10(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item11(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item12(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item13(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item14(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item15(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item16(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item17(const acbb_study_runs *r, acbb_study_item *it);
void acbb_study_item18(const acbb_study_runs *r, acbb_study_item *it);

#endif
