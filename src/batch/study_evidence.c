/* acbb — the seed study's evidence helpers: the sentence and named values
 * each check leaves, series of a snapshot quantity over a sweep, and the
 * shapes MODEL.md section 12 speaks of (rises, falls, peaks, spread). */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "study_priv.h"

/* One character of the text-free mode's shadow text: a "nan" or "inf"
 * ending here could be a token sanitize() (study_checks.c) would catch. */
static void shadow(tbuf *b, char c)
{
    if ((b->win[0] == 'n' && b->win[1] == 'a' && c == 'n')
        || (b->win[0] == 'i' && b->win[1] == 'n' && c == 'f'))
        b->it->text_suspect = 1;
    b->win[0] = b->win[1];
    b->win[1] = c;
    if (b->n < sizeof b->s - 1) b->n++;
}

static const char *skip_digits(const char *p, va_list *ap)
{
    if (*p == '*') {
        (void)va_arg(*ap, int);
        return p + 1;
    }
    while (*p >= '0' && *p <= '9') p++;
    return p;
}

/* An integer argument of length modifier `len` ('l', 'L' for ll, 'z', 'j',
 * 't' or 0) taken off the list. */
static void skip_int(char len, va_list *ap)
{
    if (len == 'l') (void)va_arg(*ap, long);
    else if (len == 'L') (void)va_arg(*ap, long long);
    else if (len == 'z') (void)va_arg(*ap, size_t);
    else if (len == 'j') (void)va_arg(*ap, intmax_t);
    else if (len == 't') (void)va_arg(*ap, ptrdiff_t);
    else (void)va_arg(*ap, int);
}

/* One conversion at p (after its '%'); the character after it, or NULL
 * for one this mode does not know (the evaluation is then suspect). */
static const char *shadow_conv(tbuf *b, const char *p, va_list *ap)
{
    while (*p && strchr("-+ #0", *p)) p++;
    p = skip_digits(p, ap);
    if (*p == '.') p = skip_digits(p + 1, ap);
    char len = 0;
    for (; *p && strchr("hlLzjt", *p); p++)
        len = *p == 'l' && len == 'l' ? 'L' : *p == 'h' ? len : *p;
    if (*p && strchr("fFeEgGaA", *p)) {
        double x = len == 'L' ? (double)va_arg(*ap, long double) : va_arg(*ap, double);
        if (!isfinite(x)) b->it->text_suspect = 1;
        shadow(b, '0');
    } else if (*p && strchr("diouxX", *p)) {
        skip_int(len, ap);
        shadow(b, '0');
    } else if (*p == 'c') {
        shadow(b, (char)va_arg(*ap, int));
    } else if (*p == 's') {
        const char *s = va_arg(*ap, const char *);
        for (s = s ? s : "(null)"; *s; s++) shadow(b, *s); /* as glibc prints NULL */
    } else if (*p == '%') {
        shadow(b, '%');
    } else {
        return NULL;
    }
    return p + 1;
}

/* tb in the text-free mode: the shadow text is scanned, not written. */
static void shadow_text(tbuf *b, const char *fmt, va_list ap)
{
    va_list a;
    va_copy(a, ap);
    for (const char *p = fmt; p && *p;) {
        if (*p != '%') shadow(b, *p++);
        else if (!(p = shadow_conv(b, p + 1, &a))) b->it->text_suspect = 1;
    }
    va_end(a);
}

void acbb_study_tb(tbuf *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (b->it && b->it->text_free) {
        shadow_text(b, fmt, ap);
        va_end(ap);
        return;
    }
    if (b->n >= sizeof b->s - 1) {
        va_end(ap);
        return;
    }
    int w = vsnprintf(b->s + b->n, sizeof b->s - b->n, fmt, ap);
    va_end(ap);
    if (w > 0) b->n += (size_t)w;
    if (b->n > sizeof b->s - 1) b->n = sizeof b->s - 1;
}

void acbb_study_add_val(acbb_study_item *it, const char *key, double v)
{
    if (it->text_free || it->n_values >= ACBB_STUDY_MAX_VALUES) return;
    snprintf(it->values[it->n_values].key, sizeof it->values[0].key, "%s", key);
    it->values[it->n_values++].v = v;
}

acbb_study_check *acbb_study_add_check(acbb_study_item *it, const char *id, verdict v,
                                       const tbuf *text)
{
    if (it->n_checks >= ACBB_STUDY_MAX_CHECKS) return NULL;
    acbb_study_check *c = &it->checks[it->n_checks++];
    snprintf(c->id, sizeof c->id, "%s", id);
    c->verdict = v;
    c->info = 0;
    if (it->text_free) c->text[0] = '\0';
    else memcpy(c->text, text->s, sizeof c->text);
    return c;
}

bool acbb_study_need(acbb_study_item *it, const char *id, const acbb_study_runs *r, int lv,
                     int blk)
{
    for (int i = 0; i < 2 * NL; i++) {
        const acbb_study_point *p = &r->sweep[lv][blk][i];
        if (p->ok) continue;
        tbuf t = TB(it);
        tb(&t, "run %s failed (%s): %s", p->label, acbb_status_name(p->status), p->message);
        add_check(it, id, V_NOT_EVAL, &t);
        return false;
    }
    return true;
}

/* ---- the seed's five losses (MODEL.md 12 speaks of these), listed once ---- */

static double g_shear(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_SHEAR]; }
static double g_slip(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_SLIP]; }
static double g_spin(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_SPIN]; }
static double g_rolling(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_ROLLING]; }
static double g_drag(const acbb_snapshot *s) { return s->losses.P[ACBB_LOSS_DRAG]; }

const acbb_study_loss acbb_study_loss_list[N_LOSSES] = {
    [LOSS_SHEAR] = { "P_L", g_shear },     [LOSS_SLIP] = { "P_t", g_slip },
    [LOSS_SPIN] = { "P_s", g_spin },       [LOSS_ROLLING] = { "P_r", g_rolling },
    [LOSS_DRAG] = { "P_v", g_drag },
};

double acbb_study_min_loss(const acbb_snapshot *s)
{
    double m = INFINITY;
    for (int i = 0; i < N_LOSSES; i++) m = fmin(m, acbb_study_loss_list[i].get(s));
    for (int j = 0; j < s->n_balls; j++) m = fmin(m, s->balls[j].loss);
    return m;
}

double acbb_study_g_total(const acbb_snapshot *s) { return s->losses.total; }
double acbb_study_g_T5(const acbb_snapshot *s) { return s->T_outer_ring; }

/* ---- series and shapes ---- */

void acbb_study_series(const acbb_study_runs *r, int lv, int blk, int m, getter g, double *v)
{
    for (int k = 0; k < NL; k++) v[k] = g(&P(r, lv, blk, k, m)->last);
}

bool acbb_study_incr(const double *v, int a, int z)
{
    for (int k = a; k < z; k++)
        if (!(v[k + 1] > v[k])) return false;
    return true;
}

bool acbb_study_decr(const double *v, int a, int z)
{
    for (int k = a; k < z; k++)
        if (!(v[k + 1] < v[k])) return false;
    return true;
}

bool acbb_study_peak_tail(const double *v, int a, int z, acbb_study_shape *out)
{
    acbb_study_shape s = { a, a, 0.0, 0.0 };
    for (int k = a; k <= z; k++)
        if (v[k] > v[s.peak]) s.peak = k;
    s.low = s.peak;
    for (int k = s.peak; k <= z; k++)
        if (v[k] < v[s.low]) s.low = k;
    s.fall = v[s.peak] - v[s.low];
    for (int k = s.low; k <= z; k++) s.tail = fmax(s.tail, v[k] - v[s.low]);
    if (out) *out = s;
    return s.peak > a && s.low > s.peak && incr(v, a, s.peak) && decr(v, s.peak, s.low) &&
           s.tail <= REPORT_SAME * s.fall;
}

bool acbb_study_peak(const double *v, int a, int z) { return acbb_study_peak_tail(v, a, z, NULL); }

/* Falls to an interior minimum, then rises. */
bool acbb_study_valley(const double *v, int a, int z)
{
    int i = a;
    for (int k = a; k <= z; k++)
        if (v[k] < v[i]) i = k;
    return i > a && i < z && decr(v, a, i) && incr(v, i, z);
}

double acbb_study_spread(const double *v, int a, int z)
{
    double lo = v[a], hi = v[a];
    for (int k = a; k <= z; k++) {
        lo = fmin(lo, v[k]);
        hi = fmax(hi, v[k]);
    }
    return hi > 0.0 ? (hi - lo) / hi : 0.0;
}

const double *acbb_study_xs(int blk) { return blk == BLK_LOAD ? k_loads : k_speeds; }
const char *acbb_study_xunit(int blk) { return blk == BLK_LOAD ? "N" : "rpm"; }

/* "what: 50 N 1.23, 100 N 1.45, ..." */
void acbb_study_tb_series(tbuf *t, const char *what, int blk, const double *v, int a, int z,
                          int prec)
{
    tb(t, "%s:", what);
    for (int k = a; k <= z; k++)
        tb(t, " %g %s %.*g%s", xs(blk)[k], xunit(blk), prec, v[k], k < z ? "," : "");
}

/* "what TE/WTE: 50 N 1.23/1.24, ..." */
void acbb_study_tb_pairs(tbuf *t, const char *what, int blk, const double *te,
                         const double *wte, int a, int z, int prec)
{
    tb(t, "%s TE/WTE:", what);
    for (int k = a; k <= z; k++)
        tb(t, " %g %s %.*g/%.*g%s", xs(blk)[k], xunit(blk), prec, te[k], prec, wte[k],
           k < z ? "," : "");
}

void acbb_study_tb_shape(tbuf *t, const char *what, int blk, const double *v,
                         const acbb_study_shape *s)
{
    double lo = v[s->low], of_low = lo != 0.0 ? 100.0 * s->tail / fabs(lo) : 0.0;
    tb(t, "%s peak %.4g at %g %s, low %.4g at %g %s, tail %+.3g = %.3g %% of the fall %.4g "
       "(%.3g %% of |low|)", what, v[s->peak], xs(blk)[s->peak], xunit(blk), lo, xs(blk)[s->low],
       xunit(blk), s->tail, s->fall > 0.0 ? 100.0 * s->tail / s->fall : 0.0, s->fall, of_low);
}

void acbb_study_val_series(acbb_study_item *it, const char *name, int blk, const double *v,
                           int a, int z)
{
    char key[48];
    for (int k = a; !it->text_free && k <= z; k++) {
        snprintf(key, sizeof key, "%s_%g%s", name, xs(blk)[k], blk == BLK_LOAD ? "N" : "rpm");
        add_val(it, key, v[k]);
    }
}

bool acbb_study_load_pair(const acbb_study_runs *r, acbb_study_item *it, const char *id, int lv,
                          getter g, const char *name, const char *unit, double *te,
                          double *wte)
{
    char key[40];
    if (!need(it, id, r, lv, BLK_LOAD)) return false;
    series(r, lv, BLK_LOAD, TE, g, te);
    series(r, lv, BLK_LOAD, WTE, g, wte);
    snprintf(key, sizeof key, "%s_TE_%s", name, unit);
    val_series(it, key, BLK_LOAD, te, 0, NL - 1);
    snprintf(key, sizeof key, "%s_WTE_%s", name, unit);
    val_series(it, key, BLK_LOAD, wte, 0, NL - 1);
    return true;
}

void acbb_study_light_large(acbb_study_item *it, const char *ida, const char *idb,
                            const char *what, const double *te, const double *wte,
                            const char *fmt_light, const char *fmt_large)
{
    int n1 = 0, n2 = 0;
    for (int k = 0; k < N_LIGHT; k++) n1 += wte[k] > te[k];
    for (int k = N_LIGHT; k < NL; k++) n2 += te[k] > wte[k];
    tbuf t = TB(it);
    tb_pairs(&t, what, BLK_LOAD, te, wte, 0, N_LIGHT - 1, 4);
    tb(&t, fmt_light, n1, N_LIGHT);
    add_check(it, ida, V(n1 == N_LIGHT), &t);
    t.n = 0;
    tb_pairs(&t, what, BLK_LOAD, te, wte, N_LIGHT, NL - 1, 4);
    tb(&t, fmt_large, n2, NL - N_LIGHT);
    add_check(it, idb, V(n2 == NL - N_LIGHT), &t);
}
