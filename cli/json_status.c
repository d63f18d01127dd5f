#define _GNU_SOURCE /* memfd_create (Linux) */
/* acbb CLI — the bad_input JSON document (json_status.h).
 *
 * Exit 2 has dozens of sources (argument parsing, preset values, merge
 * inputs), each reporting through acbb_cli_say (say.h), which keeps the
 * first error for the document here: one reporter, no stderr capture. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <string.h>
#include <unistd.h>
#include "acbb/tools/json.h"
#include "exit.h"
#include "json_status.h"
#include "say.h"
#include "say.h"

/* stdout into an anonymous in-memory file until the end. */
static void hold_stdout(acbb_cli_json_status *t)
{
    int fd = memfd_create("acbb-stdout", MFD_CLOEXEC);
    if (fd < 0) return;
    fflush(stdout);
    t->saved_out = dup(STDOUT_FILENO);
    if (t->saved_out < 0 || dup2(fd, STDOUT_FILENO) < 0) {
        if (t->saved_out >= 0) close(t->saved_out);
        t->saved_out = -1;
        close(fd);
        return;
    }
    t->held = fd;
}

void acbb_cli_json_status_begin(acbb_cli_json_status *t, int argc, char **argv)
{
    memset(t, 0, sizeof *t);
    t->saved_out = t->held = -1;
    bool json = false;
    for (int i = 1; i < argc; i++) json |= strcmp(argv[i], "--json") == 0;
    if (json) hold_stdout(t);
}

/* What the command printed on stdout, NUL-terminated (malloc'd), or NULL. */
static char *held_text(int fd, size_t *len)
{
    off_t n = lseek(fd, 0, SEEK_END);
    char *buf = n >= 0 ? malloc((size_t)n + 1) : NULL;
    *len = 0;
    if (!buf || lseek(fd, 0, SEEK_SET) != 0) {
        free(buf);
        return NULL;
    }
    while (*len < (size_t)n) {
        ssize_t r = read(fd, buf + *len, (size_t)n - *len);
        if (r <= 0) break;
        *len += (size_t)r;
    }
    buf[*len] = '\0';
    return buf;
}

/* True when `text` is one JSON object alone whose status is not
 * "converged" (a failure record the command wrote itself). */
static bool own_failure(const char *text)
{
    const char *end = NULL;
    cJSON *o = cJSON_ParseWithOpts(text, &end, false);
    bool one = o && cJSON_IsObject(o) && end && end[strspn(end, " \t\r\n")] == '\0';
    const cJSON *st = one ? cJSON_GetObjectItemCaseSensitive(o, "status") : NULL;
    one = one && cJSON_IsString(st) && strcmp(st->valuestring, "converged") != 0;
    cJSON_Delete(o);
    return one;
}

static int write_all(int fd, const char *p, size_t n)
{
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w <= 0) return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

static char *bad_input_doc(const char *message)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddStringToObject(o, "status", "bad_input");
    cJSON_AddStringToObject(o, "message", message);
    char *text = cJSON_PrintUnformatted(o);
    cJSON_Delete(o);
    return text;
}

/* Put stdout back and pass on the one document. */
static int release_stdout(acbb_cli_json_status *t, int rc, const char *message)
{
    size_t len = 0;
    fflush(stdout);
    char *text = held_text(t->held, &len), *doc = NULL;
    dup2(t->saved_out, STDOUT_FILENO);
    close(t->saved_out);
    close(t->held);
    if (rc == ACBB_EXIT_INPUT && !(text && own_failure(text))) {
        free(text);
        doc = bad_input_doc(message);
        text = NULL;
    }
    int bad = text ? write_all(STDOUT_FILENO, text, len) != 0
                   : !doc || write_all(STDOUT_FILENO, doc, strlen(doc)) != 0 ||
                     write_all(STDOUT_FILENO, "\n", 1) != 0;
    free(text);
    free(doc);
    if (bad && rc < ACBB_EXIT_INTERNAL) {
        acbb_cli_say("cannot write to stdout\n");
        rc = ACBB_EXIT_INTERNAL;
    }
    return rc;
}

int acbb_cli_json_status_end(acbb_cli_json_status *t, int rc)
{
    if (t->held < 0) return rc; /* no --json, or stdout could not be held */
    /* The first error the command reported (say.h), not a note or warning
     * (issue 26 item 8). */
    const char *said = acbb_cli_said_error();
    return release_stdout(t, rc, said ? said : "bad input");
}
