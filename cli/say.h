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

#include <stddef.h>
#include <stdio.h>

void acbb_cli_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* A message composed in pieces (a list printed by a function that takes
 * a FILE *, a hint only some cases add): write the whole of it, "\n"
 * ended, on the stream acbb_cli_msg_begin returns, then acbb_cli_msg_say
 * says it as one message. Nothing in cli/ writes to stderr but this file
 * and the progress line (progress.h): tests/test_json_message.sh checks. */
typedef struct {
    FILE *f;
    char *text;
    size_t len;
} acbb_cli_msg;

FILE *acbb_cli_msg_begin(acbb_cli_msg *m);
void acbb_cli_msg_say(acbb_cli_msg *m);

/* The first error reported (its first line, without "acbb: "), or NULL. */
const char *acbb_cli_said_error(void);

#endif
