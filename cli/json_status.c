/* acbb CLI — the bad_input JSON document (json_status.h).
 *
 * Exit 2 has dozens of sources (argument parsing, preset values, merge
 * inputs), each printing "acbb: ..." to stderr; catching the text once
 * here keeps every one of them a JSON document without touching them.
 * A thread tees the pipe so stderr stays live (progress, warnings). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/json.h"
#include "exit.h"
#include "json_status.h"

static void *tee_main(void *arg)
{
    acbb_cli_json_status *t = arg;
    char buf[1024];
    ssize_t n;
    while ((n = read(t->pipe_rd, buf, sizeof buf)) > 0) {
        for (ssize_t off = 0; off < n;) {
            ssize_t w = write(t->saved_fd, buf + off, (size_t)(n - off));
            if (w <= 0) break;
            off += w;
        }
        size_t room = sizeof t->start - 1 - t->len, take = (size_t)n < room ? (size_t)n : room;
        memcpy(t->start + t->len, buf, take);
        t->len += take;
    }
    return NULL;
}

void acbb_cli_json_status_begin(acbb_cli_json_status *t, int argc, char **argv)
{
    memset(t, 0, sizeof *t);
    bool json = false;
    for (int i = 1; i < argc; i++) json |= strcmp(argv[i], "--json") == 0;
    int p[2];
    if (!json || pipe(p) != 0) return;
    /* Progress lines follow the real stderr, not the pipe (progress.c reads
     * ACBB_PROGRESS first); an explicit setting wins. */
    if (isatty(STDERR_FILENO)) setenv("ACBB_PROGRESS", "1", 0);
    fflush(stderr);
    t->saved_fd = dup(STDERR_FILENO);
    if (t->saved_fd < 0 || dup2(p[1], STDERR_FILENO) < 0) {
        if (t->saved_fd >= 0) close(t->saved_fd);
        close(p[0]);
        close(p[1]);
        return;
    }
    close(p[1]);
    t->pipe_rd = p[0];
    if (pthread_create(&t->thread, NULL, tee_main, t) != 0) {
        dup2(t->saved_fd, STDERR_FILENO);
        close(t->saved_fd);
        close(p[0]);
        return;
    }
    t->active = true;
}

/* The message: the first line, without the "acbb: " every error starts with. */
static void first_line(char *s)
{
    s[strcspn(s, "\n")] = '\0';
    if (strncmp(s, "acbb: ", 6) == 0) memmove(s, s + 6, strlen(s + 6) + 1);
}

int acbb_cli_json_status_end(acbb_cli_json_status *t, int rc)
{
    if (!t->active) return rc;
    fflush(stderr);
    dup2(t->saved_fd, STDERR_FILENO); /* the pipe's last writer closes: EOF */
    pthread_join(t->thread, NULL);
    close(t->saved_fd);
    close(t->pipe_rd);
    t->active = false;
    if (rc != ACBB_EXIT_INPUT) return rc;
    t->start[t->len] = '\0';
    first_line(t->start);
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON_AddStringToObject(o, "status", "bad_input");
    cJSON_AddStringToObject(o, "message", t->start[0] ? t->start : "bad input");
    char *text = cJSON_PrintUnformatted(o);
    if (text) printf("%s\n", text);
    free(text);
    cJSON_Delete(o);
    fflush(stdout);
    return rc;
}
