/* acbb TUI — accuracy chart model and number formats (see acc_chart.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acc_chart.h"

double acbb_acc_error_pct(const acbb_accuracy_row *r)
{
    if (r->skipped || r->status != ACBB_OK) return NAN;
    if (!isfinite(r->e_loss) || !isfinite(r->e_T)) return NAN;
    return 100.0 * fmax(r->e_loss, r->e_T);
}

size_t acbb_acc_chart_build(const acbb_accuracy_row *rows, size_t n, acbb_acc_chart *c)
{
    double tol_pct = 100.0 * ACBB_ACCURACY_FRONTIER_TOL;
    double tlo = INFINITY, thi = -INFINITY, elo = INFINITY, ehi = -INFINITY;
    memset(c, 0, sizeof *c);
    if (n > ACBB_BENCH_MAX_ROWS) n = ACBB_BENCH_MAX_ROWS;
    for (size_t i = 0; i < n; i++) {
        double e = acbb_acc_error_pct(&rows[i]), ms = rows[i].wall_ms;
        if (!isfinite(e) || !(ms > 0) || !isfinite(ms)) continue;
        acbb_acc_point *p = &c->p[c->n++];
        p->x = log10(ms);
        p->zero = e == 0.0;
        p->y = p->zero ? 0.0 : log10(e); /* zeros are placed once ymin is known */
        p->knob = rows[i].knob;
        p->row = i;
        tlo = fmin(tlo, p->x);
        thi = fmax(thi, p->x);
        if (!p->zero) {
            elo = fmin(elo, p->y);
            ehi = fmax(ehi, p->y);
        }
    }
    if (c->n == 0) tlo = thi = 0.0;
    c->xmin = floor(tlo);
    c->xmax = ceil(thi);
    if (c->xmax <= c->xmin) c->xmax = c->xmin + 1.0;
    /* The tolerance decade is always inside; one spare decade below the
     * smallest error holds the zeros. */
    double ltol = log10(tol_pct);
    if (!isfinite(elo)) elo = ehi = ltol;
    c->ymax = fmax(ceil(ehi), ceil(ltol) + 1.0);
    c->ymin = fmin(floor(elo), floor(ltol)) - 1.0;
    for (size_t k = 0; k < c->n; k++)
        if (c->p[k].zero) c->p[k].y = c->ymin;
    return c->n;
}

char acbb_acc_knob_letter(acbb_accuracy_knob k)
{
    static const char letters[ACBB_KNOB_COUNT] = { 'M', 'G', 'H', 'E', 'S', 'T', 'N' };
    return (unsigned)k < ACBB_KNOB_COUNT ? letters[k] : '?';
}

void acbb_acc_fmt_pct(double e, char *buf, size_t n)
{
    acbb_accuracy_format_pct(e, buf, n); /* the CLI's formatter: same digits */
}

void acbb_acc_fmt_pct_decade(int d, char *buf, size_t n)
{
    static const char *const fixed[] = { "0.01%", "0.1%", "1%", "10%", "100%", "1000%" };
    if (d >= -2 && d <= 3) snprintf(buf, n, "%s", fixed[d + 2]);
    else snprintf(buf, n, "1e%+03d%%", d);
}

void acbb_acc_fmt_ms_decade(int d, char *buf, size_t n)
{
    static const char *const fixed[] = { "1ms", "10ms", "100ms", "1s", "10s", "100s", "1000s" };
    if (d >= 0 && d <= 6) snprintf(buf, n, "%s", fixed[d]);
    else snprintf(buf, n, "1e%+03dms", d);
}

void acbb_acc_setting_label(const acbb_accuracy_row *r, char *buf, size_t n)
{
    const char *dot = strchr(r->key, '.');
    snprintf(buf, n, "%s=%s", dot ? dot + 1 : r->key, r->value);
}
