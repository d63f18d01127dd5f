/* acbb — the JSON writer's primitives (acbb/tools/json.h).
 *
 * By hand, not cJSON (issue 21 item 10 asked for cJSON; kept, why): cJSON
 * 1.7's printer writes "%1.15g" whenever that reads back within one ulp, so
 * its numbers are not the doubles computed (measured: 34.1969004888535 for
 * 34.19690048885351); the contract is %.17g, exact. The writer also streams
 * into the caller's FILE (a run document is written as it is walked, no
 * tree), and the engine library does not link cJSON (only the CLI does:
 * meson.build), so libacbb.pc gains no dependency. The CLI's cJSON
 * documents write numbers through acbb_cli_json_number (cli/output.h) for
 * the same reason. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/json.h"
#include "c_locale.h"

void acbb_json_init(acbb_json *j, FILE *f)
{
    memset(j, 0, sizeof *j);
    j->f = f;
}

static void put_string(acbb_json *j, const char *s)
{
    fputc('"', j->f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        if (*p == '"' || *p == '\\') fprintf(j->f, "\\%c", *p);
        else if (*p == '\n') fputs("\\n", j->f);
        else if (*p == '\t') fputs("\\t", j->f);
        else if (*p < 0x20) fprintf(j->f, "\\u%04x", *p);
        else fputc(*p, j->f);
    }
    fputc('"', j->f);
}

/* Separator, newline and indent before an element, then its key. */
static void put_key(acbb_json *j, const char *key)
{
    int d = j->depth;
    if (d > 0) {
        if (!j->first[d]) fputc(',', j->f);
        if (j->inline_[d]) {
            if (!j->first[d]) fputc(' ', j->f);
        } else {
            fprintf(j->f, "\n%*s", 2 * d, "");
        }
        j->first[d] = false;
    }
    if (key) {
        put_string(j, key);
        fputs(": ", j->f);
    }
}

void acbb_json_open(acbb_json *j, const char *key, char bracket, bool one_line)
{
    /* Nesting is static in every writer: too deep is a bug, counted (a
     * library must not abort its caller's process). */
    if (j->depth + 1 >= ACBB_JSON_DEPTH) {
        j->misuse++;
        return;
    }
    put_key(j, key);
    fputc(bracket, j->f);
    j->depth++;
    j->first[j->depth] = true;
    j->inline_[j->depth] = one_line || j->inline_[j->depth - 1];
}

void acbb_json_close(acbb_json *j, char bracket)
{
    int d = j->depth;
    if (d <= 0) {
        j->misuse++;
        return;
    }
    if (!j->inline_[d] && !j->first[d]) fprintf(j->f, "\n%*s", 2 * (d - 1), "");
    fputc(bracket, j->f);
    j->depth--;
    if (j->depth == 0) fputc('\n', j->f);
}

void acbb_json_num(acbb_json *j, const char *key, double v)
{
    put_key(j, key);
    if (isfinite(v)) {
        {
            char t[32]; /* full precision: round-trips exactly; a point, never a comma */
            acbb_snprintf_c(t, sizeof t, "%.17g", v);
            fputs(t, j->f);
        }
    } else {
        j->nonfinite++;
        fputs("null", j->f);
    }
}

void acbb_json_long(acbb_json *j, const char *key, long v)
{
    put_key(j, key);
    fprintf(j->f, "%ld", v);
}

void acbb_json_str(acbb_json *j, const char *key, const char *s)
{
    put_key(j, key);
    put_string(j, s);
}

void acbb_json_bool(acbb_json *j, const char *key, bool b)
{
    put_key(j, key);
    fputs(b ? "true" : "false", j->f);
}

void acbb_json_null(acbb_json *j, const char *key)
{
    put_key(j, key);
    fputs("null", j->f);
}

void acbb_json_value_text(acbb_json *j, const char *key, const char *text)
{
    char *end = NULL;
    double v = acbb_strtod_c(text, &end);
    if (end != text && *end == '\0' && isfinite(v)) acbb_json_num(j, key, v);
    else acbb_json_str(j, key, text);
}
