/* acbb CLI — with --json, bad input is a JSON document too (issue 21 item
 * 10): exit 2 prints {"schema_version": N, "status": "bad_input",
 * "message": "..."} on stdout, the message being the first line the
 * command wrote to stderr (it still goes to stderr as it is written). */
#ifndef ACBB_CLI_JSON_STATUS_H
#define ACBB_CLI_JSON_STATUS_H

#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>

typedef struct {
    bool active;
    int saved_fd;          /* the real stderr */
    int pipe_rd;
    pthread_t thread;      /* copies the pipe to saved_fd, keeps the start */
    char start[2048];
    size_t len;
} acbb_cli_json_status;

/* If argv has --json: route stderr through a pipe whose reader copies
 * everything to the real stderr at once and keeps its start. Otherwise,
 * or if the pipe cannot be made, nothing changes. */
void acbb_cli_json_status_begin(acbb_cli_json_status *t, int argc, char **argv);
/* Put stderr back; for rc 2 print the bad_input document on stdout.
 * Returns rc. */
int acbb_cli_json_status_end(acbb_cli_json_status *t, int rc);

#endif
