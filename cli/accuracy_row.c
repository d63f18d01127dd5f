/* acbb CLI — the lines of `acbb bench accuracy`'s table (see accuracy_row.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "accuracy_row.h"

void acbb_cli_acc_label(const acbb_accuracy_row *r, char *buf, size_t n)
{
    const char *dot = strchr(r->key, '.');
    snprintf(buf, n, "%s=%s", dot ? dot + 1 : r->key, r->value);
}

const char *acbb_cli_acc_status(const acbb_accuracy_row *r)
{
    if (r->skipped) return "skipped";
    return r->status == ACBB_OK ? "converged" : acbb_status_name(r->status);
}

static const char *mark(const acbb_accuracy_row *r)
{
    if (r->is_reference && r->is_default) return "RD";
    if (r->is_reference) return "R";
    return r->is_default ? "D" : "";
}

/* The status in its column: cut to 8 letters and a '.' when longer. */
static void short_status(const char *s, char *buf, size_t n)
{
    size_t len = strlen(s);
    if (len <= ACBB_CLI_ACC_STATUS_W) {
        snprintf(buf, n, "%s", s);
        return;
    }
    len = ACBB_CLI_ACC_STATUS_W - 1;
    while (len > 1 && s[len - 1] == '_') len--;
    snprintf(buf, n, "%.*s.", (int)len, s);
}

/* A time or cost (>= 0) in at most w characters: one decimal below 1000,
 * the whole number while it fits, else "1.2e6" ("1e10" if even that is
 * too long); "-" when undefined. */
static void fit_number(double x, int w, char *buf, size_t n)
{
    if (!isfinite(x) || x < 0.0) {
        snprintf(buf, n, "-");
        return;
    }
    if (x < 999.95) {
        snprintf(buf, n, "%.1f", x);
        return;
    }
    if (snprintf(buf, n, "%.0f", x) <= w) return;
    int e = (int)floor(log10(x));
    double m = x / pow(10.0, e);
    if (m >= 9.95) { /* "%.1f" would print 10.0 */
        m /= 10.0;
        e++;
    }
    if (snprintf(buf, n, "%.1fe%d", m, e) > w) snprintf(buf, n, "%.0fe%d", m, e);
}

void acbb_cli_acc_header(char *buf, size_t n)
{
    snprintf(buf, n, "%-19s %-2s %-9s %6s%6s%7s%7s%7s%7s%7s", "setting", "", "status", "ms",
             "work", "loss%", "T%", "Qi%", "alpha%", "slide%");
}

void acbb_cli_acc_row(const acbb_accuracy_row *r, char *buf, size_t n)
{
    char label[96], st[16], ms[16], wu[16], e[5][16];
    acbb_cli_acc_label(r, label, sizeof label);
    short_status(acbb_cli_acc_status(r), st, sizeof st);
    fit_number(r->wall_ms, 6, ms, sizeof ms);
    fit_number(r->work, 5, wu, sizeof wu);
    const double errs[5] = { r->e_loss, r->e_T, r->e_Qi, r->e_alpha, r->e_slide };
    for (int k = 0; k < 5; k++) acbb_accuracy_format_pct(errs[k], e[k], sizeof e[k]);
    snprintf(buf, n, "%-19s %-2s %-9s %6s%6s%7s%7s%7s%7s%7s", label, mark(r), st, ms, wu, e[0],
             e[1], e[2], e[3], e[4]);
}
