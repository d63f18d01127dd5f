/* acbb — the teaching header of a preset (preset_info.h). */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/preset_info.h"

/* Append text to a joined paragraph, one space between lines. */
static void join(char *dst, size_t cap, const char *text)
{
    size_t n = strlen(dst);
    if (n > 0 && n + 1 < cap) dst[n++] = ' ', dst[n] = '\0';
    snprintf(dst + n, cap - n, "%s", text);
}

/* The comment's text without its marker and surrounding blanks; NULL for
 * a line that is not a comment. */
static char *comment_text(char *line)
{
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (*p != ';' && *p != '#') return NULL;
    p++;
    while (*p == ' ' || *p == '\t') p++;
    size_t n = strlen(p);
    while (n > 0 && isspace((unsigned char)p[n - 1])) p[--n] = '\0';
    return p;
}

static int is_blank(const char *line)
{
    for (; *line; line++)
        if (!isspace((unsigned char)*line)) return 0;
    return 1;
}

acbb_status acbb_preset_info_read(const char *path, acbb_preset_info *out, acbb_error *err)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "r");
    if (!f) return acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(errno));
    char line[512];
    int in_look = 0, in_title = 0;
    while (fgets(line, sizeof line, f)) {
        char *t = comment_text(line);
        if (!t) {
            if (is_blank(line)) continue;
            break; /* the first key or section ends the header */
        }
        int keyword = strncmp(t, "Look at:", 8) == 0 || strncmp(t, "Expect:", 7) == 0;
        if (!out->title[0] && t[0]) {
            snprintf(out->title, sizeof out->title, "%s", t);
            in_title = 1;
        } else if (in_title && t[0] && !keyword) {
            /* The title is the whole first paragraph: cut after its first
             * line, pair-rigid-16k and pair-spring-16k read the same
             * (issue 29 item 7). */
            join(out->title, sizeof out->title, t);
        } else if (strncmp(t, "Look at:", 8) == 0) {
            in_look = 1;
            join(out->look_at, sizeof out->look_at, t + 8 + strspn(t + 8, " "));
        } else if (strncmp(t, "Expect:", 7) == 0) {
            in_look = 0;
            in_title = 0;
            sscanf(t + 7, " %31s", out->expect);
        } else if (in_look && t[0]) {
            join(out->look_at, sizeof out->look_at, t);
        } else {
            in_look = 0;
        }
        if (!t[0] || keyword) in_title = 0;
    }
    fclose(f);
    return ACBB_OK;
}
