/* acbb — the seed study as data: the check table (one row per item of
 * MODEL.md section 12: number, statement, function), the seed's
 * conclusions mapped onto checks, and how check verdicts combine. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "study_priv.h"

/* Rows: {item, statement, (L2), function}. The statement is MODEL.md
 * section 12's, condensed; the function (study_items_a.c, _b.c) holds the
 * numeric checks. */
static const acbb_study_row k_rows[] = {
    { 1, 0, acbb_study_item1,
      "Total loss: P_T(WTE) > P_T(TE) at 50-200 N, P_T(WTE) < P_T(TE) at "
      "400-1000 N (15000 rpm)." },
    { 2, 0, acbb_study_item2,
      "The TE-WTE difference of P_T is dominated by P_t and P_L at light loads "
      "and by P_t and P_r at large loads (> 50 %)." },
    { 3, 0, acbb_study_item3,
      "P_v: TE and WTE differ by < 2 % at all loads and speeds; P_v depends "
      "mainly on speed." },
    { 4, 0, acbb_study_item4,
      "Expansions vs time: theta_i+theta_icen > theta_o early, theta_o larger at "
      "steady state (one crossover); theta_ba much smaller than both; steady "
      "expansions fall over 50-200 N and rise over 400-1000 N." },
    { 5, 0, acbb_study_item5,
      "Contact loads vs time rise above step 0, peak near the maximal "
      "theta_i+theta_icen-theta_o, then relax; final ~ step 0 at light loads, "
      "final > step 0 at large loads; delta_x first falls, then rises." },
    { 6, 0, acbb_study_item6,
      "Contact angles: room temperature > final at all loads; WTE light loads: "
      "alpha_o strongly reduced by centrifugal force, alpha_i > alpha_o, alpha_i "
      "falls and alpha_o rises with F_x; WTE large loads: both rise with F_x; "
      "TE: alpha_i falls with F_x." },
    { 7, 0, acbb_study_item7,
      "Outer-ring (node 5) steady temperature at 15000 rpm increases with F_x "
      "for F_x >= 200 N." },
    { 8, 0, acbb_study_item8,
      "Speed sweep 2000-16000 rpm: T5(WTE) > T5(TE) at 100 N; T5(WTE) < T5(TE) "
      "at 1000 N." },
    { 9, 0, acbb_study_item9,
      "Relative TE effect on P_T: < 5 % at 2000 rpm, 100 N; > 10 % at "
      "16000 rpm, 1000 N." },
    { 10, 1, acbb_study_item10,
      "P_L significant at light loads, < 5 % of P_T at 1000 N; P_L(WTE) > "
      "P_L(TE) at 100 N, P_L(TE) > P_L(WTE) at 1000 N." },
    { 11, 0, acbb_study_item11,
      "P_t: WTE > TE at light loads, TE > WTE at large loads (15000 rpm)." },
    { 12, 1, acbb_study_item12,
      "P_s(50 N) < P_s(100 N); P_s(F_x) first falls, then rises; TE raises P_s "
      "markedly at 1000 N, little at 100 N." },
    { 13, 0, acbb_study_item13,
      "P_r increases with F_x and with speed; P_r(TE) > P_r(WTE) at large "
      "loads, ~ equal at light loads." },
    { 14, 0, acbb_study_item14,
      "Film thickness: TE and WTE differ by < 5 %." },
    { 15, 1, acbb_study_item15,
      "100 N: inner sliding rises with speed, outer sliding rises then falls, "
      "sliding TE < WTE; 1000 N: micro-sliding, slightly larger with TE." },
    { 16, 1, acbb_study_item16,
      "Spin: omega_si rises with speed at 100 N and 1000 N; omega_so rises then "
      "falls at 100 N; spin at 100 N > at 1000 N; slightly lower with TE." },
    { 17, 1, acbb_study_item17,
      "Ball angular velocities vs F_x: |omega_x'| falls then levels off; "
      "omega_z' rises below 300 N then ~ constant; |omega_y'| < 1 % of "
      "|omega_x'| at 1000 N." },
    { 18, 0, acbb_study_item18,
      "Sanity: zero speed gives no loss and ambient temperatures; steady energy "
      "balance to 1e-6; static thrust solution matches the closed form to "
      "1e-4; all losses >= 0; BE with dt -> inf equals the steady solve." },
};

/* Seed section 5 lists seven conclusions; each maps onto checks above. */
static const acbb_study_conclusion k_conclusions[] = {
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

#define N_ROWS (sizeof k_rows / sizeof k_rows[0])
#define N_CONCL (sizeof k_conclusions / sizeof k_conclusions[0])

const acbb_study_row *acbb_study_table(size_t *n)
{
    *n = N_ROWS;
    return k_rows;
}

const acbb_study_conclusion *acbb_study_conclusions(size_t *n)
{
    *n = N_CONCL;
    return k_conclusions;
}

const char *acbb_verdict_name(acbb_verdict v)
{
    static const char *const name[] = { "HELD", "NOT HELD", "NOT EVALUATED" };
    return (unsigned)v < 3 ? name[v] : "NOT EVALUATED";
}

/* NOT HELD if any check fails; HELD if all hold; otherwise NOT EVALUATED. */
static acbb_verdict combine(const acbb_verdict *v, int n)
{
    bool ne = n == 0;
    for (int i = 0; i < n; i++) {
        if (v[i] == V_NOT_HELD) return V_NOT_HELD;
        ne = ne || v[i] == V_NOT_EVAL;
    }
    return ne ? V_NOT_EVAL : V_HELD;
}

/* printf's spelling of a non-finite number ("nan", "-nan", "inf", "-inf")
 * as a whole token at s, or 0. */
static size_t nonfinite_token(const char *text, const char *s)
{
    static const char *const tok[] = { "-nan", "-inf", "nan", "inf" };
    if (s > text && (s[-1] == '_' || s[-1] == '-' || (s[-1] >= 'a' && s[-1] <= 'z')))
        return 0;
    for (size_t i = 0; i < 4; i++) {
        size_t n = strlen(tok[i]);
        char after = s[n];
        if (strncmp(s, tok[i], n) == 0 && !(after == '_' || (after >= 'a' && after <= 'z')))
            return n;
    }
    return 0;
}

/* No NaN/Inf reaches the evidence: a check that printed one (a ratio with
 * a zero denominator, a run with nothing to measure) is NOT EVALUATED, the
 * number reads "n/a" and the text says why. */
static void sanitize(acbb_study_check *c)
{
    char out[ACBB_STUDY_TEXT];
    size_t o = 0;
    bool bad = false;
    for (const char *s = c->text; *s && o + 4 < sizeof out;) {
        size_t n = nonfinite_token(c->text, s);
        if (n) {
            memcpy(out + o, "n/a", 3);
            o += 3;
            s += n;
            bad = true;
        } else {
            out[o++] = *s++;
        }
    }
    if (!bad) return;
    static const char why[] = " [not evaluable: a deciding number is undefined]";
    size_t room = sizeof out - 1 - o, w = sizeof why - 1 < room ? sizeof why - 1 : room;
    memcpy(out + o, why, w);
    out[o + w] = '\0';
    memcpy(c->text, out, sizeof c->text);
    c->verdict = V_NOT_EVAL;
}

/* text 0: the text-free mode (study_priv.h); the record's header only is
 * cleared (no text or value is written or read). */
static void eval_row(const acbb_study_row *row, const acbb_study_runs *runs,
                     acbb_study_item *out, int text)
{
    if (text) {
        memset(out, 0, sizeof *out);
    } else {
        out->n_checks = out->n_values = 0;
        out->verdict = V_NOT_EVAL;
        out->text_free = 1;
        out->text_suspect = 0;
    }
    out->num = row->num;
    out->statement = row->statement;
    out->l2 = row->l2;
    row->fn(runs, out);
    acbb_verdict v[ACBB_STUDY_MAX_CHECKS];
    int n = 0;
    for (int k = 0; k < out->n_checks; k++) {
        if (text) sanitize(&out->checks[k]);
        if (!out->checks[k].info) v[n++] = out->checks[k].verdict;
    }
    out->verdict = combine(v, n);
}

void acbb_study_eval_row(const acbb_study_row *row, const acbb_study_runs *runs,
                         acbb_study_item *out)
{
    eval_row(row, runs, out, 1);
}

int acbb_study_eval_verdicts(const acbb_study_row *row, const acbb_study_runs *runs,
                             acbb_study_item *out)
{
    eval_row(row, runs, out, 0);
    int sure = !out->text_suspect;
    out->text_free = out->text_suspect = 0;
    return sure;
}

acbb_verdict acbb_study_conclusion_verdict(const acbb_study *s, size_t i)
{
    acbb_verdict v[ACBB_STUDY_CONCL_CHECKS];
    int n = 0;
    if (i >= N_CONCL) return V_NOT_EVAL;
    for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && k_conclusions[i].checks[k]; k++) {
        const acbb_study_check *c = acbb_study_find_check(s, k_conclusions[i].checks[k]);
        v[n++] = c ? c->verdict : V_NOT_EVAL;
    }
    return combine(v, n);
}

int acbb_study_item_in_conclusion(const acbb_study *s, size_t i, size_t k)
{
    const acbb_study_item *it = acbb_study_item_at(s, i);
    if (!it || k >= N_CONCL) return 0;
    for (int j = 0; j < ACBB_STUDY_CONCL_CHECKS && k_conclusions[k].checks[j]; j++)
        for (int m = 0; m < it->n_checks; m++)
            if (strcmp(it->checks[m].id, k_conclusions[k].checks[j]) == 0) return 1;
    return 0;
}
