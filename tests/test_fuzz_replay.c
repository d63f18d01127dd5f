/* The fuzz corpus replayed through the same entry points as the libFuzzer
 * harnesses (tests/fuzz/fuzz_entry.h), with the plain compiler: in the
 * default suite, so a fixed crash stays fixed without clang.
 *
 * Usage: test_fuzz_replay --preset DIR... --set DIR... --merge DIR... --resume DIR...
 *        --schedule DIR...
 * Every file of a --preset directory is loaded as a preset, of a --set
 * directory read as `--set` edits, of --merge merged, of --resume resumed
 * as a sweep's output (fuzz_cli.h), of a --schedule directory as the
 * values of [schedule] `row = ` lines, one per line; every entry of a directory is replayed
 * (counted against the directory listing, at least one). The entry points
 * check that a refusal has a message and an accepted scene no NaN/Inf (a
 * failure there is "broken"). Here, for every file: ok-* must be accepted,
 * bad-* refused, other names (presets, libFuzzer finds) either; and every
 * refusal must name what it refuses: a preset's the file (its message
 * starts with the path loaded), an edit's the key (the name after the
 * last dot of one of the input's keys, as a cross-field rule names the
 * other key of the pair by its full name; of a longer name its first 64
 * characters). The CLI's readers (merge, resume) print their refusals on
 * stderr, which the entry points silence: their refusal is not matched. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "fuzz/fuzz_cli.h"

typedef acbb_fuzz_outcome (*entry_fn)(const uint8_t *, size_t, char *, size_t);

static unsigned char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, len = 0;
    unsigned char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + len, 1, cap - len, f)) > 0;) {
        len += got;
        if (len == cap) {
            unsigned char *nb = realloc(buf, cap *= 2);
            if (!nb) free(buf);
            buf = nb;
        }
    }
    fclose(f);
    *n = len;
    return buf;
}

static int by_name(const struct dirent **a, const struct dirent **b)
{
    return strcmp((*a)->d_name, (*b)->d_name);
}

typedef struct {
    entry_fn fn;
    int preset; /* 1: --preset (a refusal names the file), 0: --set (the key), */
                /* 2: --schedule (the row: "schedule.row = ..." or "schedule row K"), */
                /* -1: a CLI reader (merge, resume) */
} entry;

/* Does a refusal of `data` as edits name one of its keys (by the name
 * after the last dot, blanks trimmed; an edit without a key names none
 * to look for)? */
static int names_a_key(const unsigned char *data, size_t n, const char *msg)
{
    char text[4096];
    size_t len = n < sizeof text - 1 ? n : sizeof text - 1;
    memcpy(text, data, len);
    text[len] = '\0'; /* the entry stops at a NUL too */
    for (char *line = text, *next; line; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        char *eq = strchr(line, '=');
        if (eq) *eq = '\0';
        char *name = strrchr(line, '.');
        name = name ? name + 1 : line;
        while (*name == ' ' || *name == '\t') name++;
        size_t k = strlen(name);
        while (k > 0 && (name[k - 1] == ' ' || name[k - 1] == '\t' || name[k - 1] == '\r')) k--;
        name[k < 64 ? k : 64] = '\0'; /* a longer name is quoted cut short */
        if (strstr(msg, name)) return 1;
    }
    return 0;
}

static int names_input(const entry *e, const unsigned char *data, size_t n, const char *msg)
{
    if (e->preset < 0) return 1;
    if (e->preset == 2) return strstr(msg, "schedule") != NULL;
    if (e->preset) {
        const char *path = acbb_fuzz_preset_path();
        return path[0] && strncmp(msg, path, strlen(path)) == 0;
    }
    return names_a_key(data, n, msg);
}

static void replay_one(const char *dir, const char *name, const entry *e)
{
    char path[4096], why[1024] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    size_t n = 0;
    unsigned char *data = slurp(path, &n);
    if (!ok(data != NULL, "%s: readable", path)) return;
    acbb_fuzz_outcome o = e->fn(data, n, why, sizeof why);
    int named = o == ACBB_FUZZ_REJECTED && why[0] && names_input(e, data, n, why);
    free(data);
    /* Keep the TAP line one line: the message may quote a CR or a long value. */
    for (char *c = why; *c; c++)
        if (*c == '\n' || *c == '\r') *c = ' ';
    why[120] = '\0';
    int want_ok = !strncmp(name, "ok-", 3), want_bad = !strncmp(name, "bad-", 4);
    if (o == ACBB_FUZZ_BROKEN) {
        ok(0, "%s: %s", path, why);
    } else if (o == ACBB_FUZZ_ACCEPTED) {
        ok(!want_bad, "%s: accepted, every value finite%s", path, want_bad ? " (want refused)" : "");
    } else {
        static const char *const what[] = { "key", "file", "row" };
        ok(!want_ok && named, "%s: refused%s, the message names the %s: %s", path,
           want_ok ? " (want accepted)" : "", e->preset < 0 ? "input" : what[e->preset], why);
    }
}

static void replay_dir(const char *dir, const entry *e)
{
    struct dirent **list;
    int n = scandir(dir, &list, NULL, by_name);
    int entries = 0, replayed = 0;
    for (int i = 0; i < n; i++) {
        const char *name = list[i]->d_name;
        if (strcmp(name, ".") && strcmp(name, "..")) {
            entries++;
            replay_one(dir, name, e);
            replayed++;
        }
        free(list[i]);
    }
    if (n >= 0) free(list);
    ok(n >= 0 && replayed > 0 && replayed == entries, "%s: all %d of %d entries replayed", dir,
       replayed, entries);
}

int main(int argc, char **argv)
{
    const entry as_preset = { acbb_fuzz_preset, 1 }, as_set = { acbb_fuzz_set, 0 };
    const entry as_merge = { acbb_fuzz_merge, -1 }, as_resume = { acbb_fuzz_resume, -1 };
    const entry as_schedule = { acbb_fuzz_schedule, 2 };
    const entry *e = &as_preset;
    int dirs = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--preset")) e = &as_preset;
        else if (!strcmp(argv[i], "--set")) e = &as_set;
        else if (!strcmp(argv[i], "--merge")) e = &as_merge;
        else if (!strcmp(argv[i], "--resume")) e = &as_resume;
        else if (!strcmp(argv[i], "--schedule")) e = &as_schedule;
        else replay_dir(argv[i], e), dirs++;
    }
    ok(dirs > 0, "%d corpus directories replayed", dirs);
    acbb_fuzz_cleanup();
    printf("1..%d\n", tap_n);
    return tap_failed != 0;
}
