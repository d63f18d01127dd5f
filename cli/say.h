/* acbb CLI — the one reporter of the CLI's messages (issue 27 item 5).
 *
 * acbb_cli_say(fmt, ...) writes "acbb: <message>" to stderr, as every
 * message of the CLI reads, and keeps the first one that is an error (not
 * "note: ..." nor "warning: ...") for the JSON error document that --json
 * prints on exit 2 (json_status.h). So an error reaches stderr and the
 * document through one call, and no thread reads stderr back. fmt ends
 * with its own "\n", as fprintf's did. Thread-safe (a sweep's workers
 * may report). */
#ifndef ACBB_CLI_SAY_H
#define ACBB_CLI_SAY_H

void acbb_cli_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The first error reported (its first line, without "acbb: "), or NULL. */
const char *acbb_cli_said_error(void);

#endif
