/* The FFI entry point (include/acbb/ffi.h) and the text loader.
 *
 * acbb_run_preset_json on the text of presets/7008C.ini, plain and with a
 * setting, returns the very document `acbb run PRESET [--set ...] --json`
 * prints (every line but wall_ms, byte for byte); runs on two threads at
 * once give the same document; bad input gives a {status, message} object
 * with the engine's exact message and status; acbb_scene_load_text reads
 * what acbb_scene_load reads. $1 = the acbb binary. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/ffi.h"
#include "acbb/tools/json.h"
#include "acbb/scene.h"
#include "acbb/tools/scene_schema.h"
#include "slurp.h"
#include "tap.h"

#define PRESET "presets/7008C.ini"

/* The document without its wall_ms line (the one run-dependent number). */
static void drop_wall(char *s)
{
    char *w = s ? strstr(s, "\n  \"wall_ms\": ") : NULL;
    if (!w) return;
    char *end = strchr(w + 1, '\n');
    memmove(w, end, strlen(end) + 1);
}

static int same_doc(char *got, char *want)
{
    drop_wall(got);
    drop_wall(want);
    return got && want && strlen(want) > 1000 && strcmp(got, want) == 0;
}

static char *preset_text(void)
{
    FILE *f = fopen(PRESET, "r");
    char *s = f ? slurp(f) : NULL;
    if (f) fclose(f);
    return s;
}

static void test_cli_equal(const char *acbb, const char *text)
{
    char cmd[1024];
    int st = 1;
    snprintf(cmd, sizeof cmd, "'%s' run " PRESET " --json 2>/dev/null", acbb);
    char *want = slurp_cmd(cmd), *got = acbb_run_preset_json(text, NULL, 0, &st);
    ok(st == 0 && got && strstr(got, "\"status\": \"converged\""), "7008C converges (status 0)");
    ok(same_doc(got, want), "7008C: the CLI's JSON, every line but wall_ms");
    acbb_string_free(got);
    free(want);

    const char *set[] = { "operating.axial_load_N=300", "operating.inner_speed_rpm=9000" };
    snprintf(cmd, sizeof cmd, "'%s' run " PRESET " --set %s --set %s --json 2>/dev/null", acbb,
             set[0], set[1]);
    want = slurp_cmd(cmd);
    got = acbb_run_preset_json(text, set, 2, &st);
    ok(st == 0 && same_doc(got, want), "7008C with two settings: the CLI's JSON with --set");
    ok(got && strstr(got, "\"operating.axial_load_N\": 300,"), "the setting is in the scene");
    acbb_string_free(got);
    free(want);
}

static void *run_thread(void *text)
{
    int st;
    char *doc = acbb_run_preset_json(text, NULL, 0, &st);
    drop_wall(doc);
    return doc;
}

static void test_threads(char *text)
{
    pthread_t t[2];
    char *doc[2] = { NULL, NULL };
    for (int i = 0; i < 2; i++) pthread_create(&t[i], NULL, run_thread, text);
    for (int i = 0; i < 2; i++) pthread_join(t[i], (void **)&doc[i]);
    ok(doc[0] && doc[1] && strcmp(doc[0], doc[1]) == 0,
       "two runs on two threads at once give the same document");
    acbb_string_free(doc[0]);
    acbb_string_free(doc[1]);
}

/* Bad input: exactly {schema_version, status, message} (issue 28 item 4:
 * schema_version as in every document), the engine's message. */
static void bad(const char *what, const char *text, const char *setting, int want_st,
                const char *msg)
{
    int st = 0;
    char want[1024];
    snprintf(want, sizeof want, "{\n  \"schema_version\": %d,\n  \"status\": \"bad_input\",\n"
             "  \"message\": \"%s\"\n}\n", ACBB_JSON_SCHEMA_VERSION, msg);
    char *got = acbb_run_preset_json(text, &setting, setting ? 1 : 0, &st);
    ok(st == want_st && got && strcmp(got, want) == 0, "%s: %s", what, msg);
    if (got && strcmp(got, want) != 0) printf("#   got: %s", got);
    acbb_string_free(got);
}

static void test_bad(const char *text)
{
    bad("a setting out of range", text, "operating.axial_load_N=-5", ACBB_EINVAL,
        "operating.axial_load_N=-5: operating.axial_load_N = -5: must be >= 0 N");
    bad("an unknown key", text, "operating.axial_load=5", ACBB_EINVAL,
        "operating.axial_load=5: operating.axial_load: unknown key (did you mean "
        "operating.axial_load_N?)");
    bad("a bad value in the text", "[operating]\naxial_load_N = abc\n", NULL, ACBB_EINVAL,
        "<text>:2: operating.axial_load_N = abc: not a number");
    bad("empty text", "", NULL, ACBB_EINVAL, "<text>: empty preset (no keys)");
    bad("a comment only", "; only a comment\n", NULL, ACBB_EINVAL,
        "<text>: empty preset (no keys)");
}

static void test_load_text(const char *text)
{
    acbb_scene a, b;
    acbb_error err = { { 0 } };
    int same = acbb_scene_load(PRESET, &a, &err) == ACBB_OK &&
               acbb_scene_load_text(text, &b, &err) == ACBB_OK;
    for (size_t i = 0; same && i < acbb_scene_field_count(); i++) {
        char x[128], y[128];
        acbb_scene_field_format(&a, i, x, sizeof x);
        acbb_scene_field_format(&b, i, y, sizeof y);
        same = strcmp(x, y) == 0;
    }
    ok(same, "acbb_scene_load_text reads the preset text as acbb_scene_load reads the file");
    ok(acbb_scene_load_text("[operating]\naxial_load_N = 5\x01\n", &a, &err) == ACBB_EINVAL &&
       strstr(err.msg, "<text>:2: control character \\x01") == err.msg,
       "the text meets the file's line checks (%s)", err.msg);
}

/* Misuse of the JSON writer (too deep, a close at the top) is counted, not
 * an abort() in the caller's process; the writer stays usable. */
static void test_json_misuse(void)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f) {
        ok(0, "open_memstream");
        return;
    }
    acbb_json j;
    acbb_json_init(&j, f);
    acbb_json_close(&j, '}');
    for (int d = 0; d < ACBB_JSON_DEPTH + 2; d++) acbb_json_open(&j, NULL, '[', true);
    long after_open = j.misuse;
    while (j.depth > 0) acbb_json_close(&j, ']');
    fclose(f);
    ok(after_open == 1 + 3 && j.misuse == 4 && j.depth == 0,
       "JSON writer: 1 close at the top and 3 opens past depth %d counted (%ld), no abort",
       ACBB_JSON_DEPTH, j.misuse);
    size_t opens = 0, closes = 0;
    for (size_t i = 0; i < len; i++) opens += buf[i] == '[', closes += buf[i] == ']';
    ok(opens == (size_t)ACBB_JSON_DEPTH - 1 && closes == opens,
       "the text written stays balanced (%zu [ and %zu ])", opens, closes);
    free(buf);
}

/* acbb_run_preset_json_ctl (issue 28 items 2, 4): a flag set before the
 * call cancels the set-up (document "cancelled", status ACBB_CANCELLED);
 * a NUL byte inside the given length is refused as in a file. */
static void test_ctl(const char *text)
{
    acbb_atomic_int stop = 1;
    int st = 0;
    char *got = acbb_run_preset_json_ctl(text, strlen(text), NULL, 0, &stop, &st);
    ok(st == ACBB_CANCELLED && got && strstr(got, "\"status\": \"cancelled\""),
       "a set cancel flag: a cancelled document, ACBB_CANCELLED");
    acbb_string_free(got);
    static const char nul[] = "[operating]\naxial_load_N = 100\0 junk\n";
    got = acbb_run_preset_json_ctl(nul, sizeof nul - 1, NULL, 0, NULL, &st);
    ok(st == ACBB_EINVAL && got && strstr(got, "<text>:2: NUL byte in line 2"),
       "a NUL byte inside the text's length is refused (line 2)");
    acbb_string_free(got);
}

int main(int argc, char **argv)
{
    char *text = preset_text();
    if (argc < 2 || !text) {
        printf("Bail out! usage: test_api ACBB (from the source root)\n");
        return 1;
    }
    test_cli_equal(argv[1], text);
    test_threads(text);
    test_bad(text);
    test_load_text(text);
    test_json_misuse();
    test_ctl(text);
    free(text);
    printf("1..%d\n", tap_n);
    return tap_failed ? 1 : 0;
}
