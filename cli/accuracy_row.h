/* acbb CLI — the lines of `acbb bench accuracy`'s table (cli/accuracy.c),
 * apart so that a test can format rows without running a ladder.
 *
 * Columns (80 in all, as the header): setting 19, mark 2 (R, D, RD),
 * status 9, then right-aligned ms 7, work 6 and five errors of 7 each.
 * Every column after the first keeps at least one space before it, and a
 * row never grows past the header, whatever its numbers or status:
 * - ms and work carry one decimal below 1000, none from 1000 up, and in
 *   mantissa-exponent form ("1.2e6") once the whole number no longer fits
 *   (ms from 999999.5 ms, work from 99999.5 units);
 * - a status longer than 9 letters is cut to 8 and ends in '.'
 *   ("contact_lost" -> "contact.", "wall_limit" -> "wall_lim."), a
 *   trailing '_' dropped; the notes below the table name it whole;
 * - the errors come from acbb_accuracy_format_pct (at most 6 characters). */
#ifndef ACBB_CLI_ACCURACY_ROW_H
#define ACBB_CLI_ACCURACY_ROW_H

#include <stddef.h>
#include "acbb/tools/accuracy.h"

#define ACBB_CLI_ACC_STATUS_W 9 /* the status column's letters */

/* "model=static": the key without its "fidelity." section (every knob is
 * in [fidelity], the table header says so). */
void acbb_cli_acc_label(const acbb_accuracy_row *r, char *buf, size_t n);

/* "converged", "skipped" or the failure's status name, whole (notes, CSV). */
const char *acbb_cli_acc_status(const acbb_accuracy_row *r);

/* The header line and one row, without the newline (n >= 96 holds any). */
void acbb_cli_acc_header(char *buf, size_t n);
void acbb_cli_acc_row(const acbb_accuracy_row *r, char *buf, size_t n);

#endif
