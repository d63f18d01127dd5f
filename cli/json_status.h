/* acbb CLI — with --json, bad input is a JSON document too (issue 21 item
 * 10): exit 2 prints {"schema_version": N, "status": "bad_input",
 * "message": "..."} on stdout, the message being the first error the
 * command reported (acbb_cli_say, say.h: it goes to stderr as it is
 * reported); "note:" and "warning:" lines are not errors.
 *
 * Exactly one document reaches stdout whatever the exit (issue 26 item
 * 8): with --json, stdout is held in memory until the command returns.
 * On exit 2 a command's own document (the failure record of `run`) is
 * passed on when it is the only thing printed and does not say
 * "converged"; anything else is replaced by the bad_input document.
 * On other exits what was printed passes unchanged. */
#ifndef ACBB_CLI_JSON_STATUS_H
#define ACBB_CLI_JSON_STATUS_H

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    int saved_out;         /* the real stdout while it is held; -1 none */
    int held;              /* what the command printed on stdout */
} acbb_cli_json_status;

/* If argv has --json: hold stdout (in memory) until the end. Otherwise,
 * or if it cannot be held, nothing changes. */
void acbb_cli_json_status_begin(acbb_cli_json_status *t, int argc, char **argv);
/* Put stdout back; pass on one document as above. Returns rc,
 * or 4 when stdout could not be written. */
int acbb_cli_json_status_end(acbb_cli_json_status *t, int rc);

#endif
