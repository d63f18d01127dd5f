/* The rows of `acbb bench accuracy`'s table (cli/accuracy_row.c), formatted
 * from rows filled by hand: wall times from 0.1 ms to 10^6 ms and beyond,
 * work from 0.1 to 10^7 units, every status a row can show (converged,
 * diverged, contact_lost, wall_limit, skipped, not_converged). Each line:
 * - at most 80 columns (the header is exactly 80: SSH at 80x24);
 * - its columns where the header's are: the setting, mark and status left
 *   aligned at the header's starts, the numbers right aligned at its ends,
 *   so every column keeps a space before it (a 10 s wall time once ran
 *   into "converged", "contact_lost" shifted every later column);
 * - the numbers read back (sscanf) as given to the printed precision;
 * - a status wider than its column cut to 8 letters and '.', whole when
 *   it fits. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "accuracy_row.h"
#include "tap.h"

#define N_COLS 10 /* setting, mark, status, ms, work, five errors */

/* Where each whitespace-separated token of s starts and ends (one past). */
static int tokens(const char *s, int start[], int end[], int max)
{
    int n = 0;
    for (int i = 0; s[i] && n < max;) {
        while (s[i] == ' ') i++;
        if (!s[i]) break;
        start[n] = i;
        while (s[i] && s[i] != ' ') i++;
        end[n++] = i;
    }
    return n;
}

/* Half a unit of the last digit "123.4", "1234" or "1.2e6" prints. */
static double half_ulp(const char *tok)
{
    const char *dot = strchr(tok, '.'), *e = strchr(tok, 'e');
    int decimals = 0;
    if (dot) decimals = (int)((e ? e : tok + strlen(tok)) - dot - 1);
    return 0.5 * pow(10.0, (e ? atoi(e + 1) : 0) - decimals);
}

static int reads_as(const char *tok, double want)
{
    double got;
    char rest;
    if (sscanf(tok, "%lf%c", &got, &rest) != 1) return 0;
    return fabs(got - want) <= half_ulp(tok) * (1.0 + 1e-9);
}

static acbb_accuracy_row make(const char *key, const char *value, acbb_status st,
                              int skipped, double ms, double work)
{
    acbb_accuracy_row r;
    memset(&r, 0, sizeof r);
    snprintf(r.key, sizeof r.key, "%s", key);
    snprintf(r.value, sizeof r.value, "%s", value);
    r.is_reference = 1; /* mark "R": a token of its own */
    r.status = st;
    r.skipped = skipped;
    r.wall_ms = ms;
    r.work = work;
    r.e_loss = 0.0329;
    r.e_T = 0.0;
    r.e_Qi = 5e-9;
    r.e_alpha = 12.5; /* 1250 % */
    r.e_slide = 0.4615;
    return r;
}

/* Header columns: setting, status, ms ... slide% (the mark has no title). */
static int hs[N_COLS], he[N_COLS];

static void check_row(const acbb_accuracy_row *r, const char *shown_status)
{
    char line[160], what[96];
    int s[N_COLS + 1], e[N_COLS + 1];
    acbb_cli_acc_row(r, line, sizeof line);
    snprintf(what, sizeof what, "%s %g ms %g units", shown_status, r->wall_ms, r->work);
    if (!ok(strlen(line) <= 80, "%s: %zu <= 80 columns", what, strlen(line)))
        printf("#   '%s'\n", line);
    int n = tokens(line, s, e, N_COLS + 1);
    if (!ok(n == N_COLS, "%s: %d columns apart", what, N_COLS)) {
        printf("#   '%s' has %d\n", line, n);
        return;
    }
    int aligned = s[0] == hs[0] && s[1] == 20 && s[2] == hs[1];
    for (int k = 3; k < N_COLS; k++) aligned = aligned && e[k] == he[k - 1];
    if (!ok(aligned, "%s: columns where the header's are", what))
        printf("#   '%s'\n#   under the header's columns\n", line);
    char tok[3][32];
    for (int k = 0; k < 3; k++) {
        int k0 = k == 0 ? 2 : 2 + k; /* status, ms, work */
        snprintf(tok[k], sizeof tok[k], "%.*s", e[k0] - s[k0], line + s[k0]);
    }
    ok(strcmp(tok[0], shown_status) == 0, "%s: status shown as '%s' (got '%s')", what,
       shown_status, tok[0]);
    ok(reads_as(tok[1], r->wall_ms), "%s: ms '%s' reads back", what, tok[1]);
    ok(reads_as(tok[2], r->work), "%s: work '%s' reads back", what, tok[2]);
}

int main(void)
{
    char header[160];
    acbb_cli_acc_header(header, sizeof header);
    ok(strlen(header) == 80, "the header is 80 columns (%zu)", strlen(header));
    int hn = tokens(header, hs, he, N_COLS);
    ok(hn == N_COLS - 1 && strncmp(header + hs[1], "status", 6) == 0 &&
           strncmp(header + hs[2], "ms", 2) == 0,
       "the header names setting, status, ms, ... (%d titles)", hn);

    const double ms[] = { 0.1, 999.9, 1000, 10000, 123456, 999999, 1e6, 3.2e7 };
    const double work[] = { 0.1, 999.9, 20024.3, 99999, 123456, 1.1e6, 1e6, 1.23e7 };
    const struct { acbb_status st; int skipped; const char *shown; } sts[] = {
        { ACBB_OK, 0, "converged" }, { ACBB_DIVERGED, 0, "diverged" },
        { ACBB_CONTACT_LOST, 0, "contact." }, { ACBB_WALL_LIMIT, 0, "wall_lim." },
        { ACBB_OK, 1, "skipped" }, { ACBB_NOT_CONVERGED, 0, "not_conv." },
    };
    for (size_t i = 0; i < sizeof sts / sizeof sts[0]; i++)
        for (size_t j = 0; j < sizeof ms / sizeof ms[0]; j++) {
            acbb_accuracy_row r = make("fidelity.steady_tol_K_s", "1e-5", sts[i].st,
                                       sts[i].skipped, ms[j], work[j]);
            check_row(&r, sts[i].shown);
        }

    /* The notes and the CSV keep the status whole; the label drops "fidelity.". */
    acbb_accuracy_row r = make("fidelity.model", "dynamic", ACBB_CONTACT_LOST, 0, 1, 1);
    char label[96];
    acbb_cli_acc_label(&r, label, sizeof label);
    ok(strcmp(acbb_cli_acc_status(&r), "contact_lost") == 0, "the status whole for the notes");
    ok(strcmp(label, "model=dynamic") == 0, "label '%s'", label);
    /* An undefined time or cost prints "-", in its column. */
    r.wall_ms = NAN;
    r.work = NAN;
    char line[160];
    acbb_cli_acc_row(&r, line, sizeof line);
    int s[N_COLS], e[N_COLS];
    int n = tokens(line, s, e, N_COLS);
    ok(n == N_COLS && line[s[3]] == '-' && e[3] == he[2] && line[s[4]] == '-' && e[4] == he[3],
       "undefined ms and work print '-' in their columns: '%s'", line);
    return done_testing();
}
