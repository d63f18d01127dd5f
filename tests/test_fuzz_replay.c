/* The fuzz corpus replayed through the same entry points as the libFuzzer
 * harnesses (tests/fuzz/fuzz_entry.h), with the plain compiler: in the
 * default suite, so a fixed crash stays fixed without clang.
 *
 * Usage: test_fuzz_replay --preset DIR... --set DIR...
 * Every file of a --preset directory is loaded as a preset, of a --set
 * directory read as `--set` edits. A file named ok-* must be accepted,
 * bad-* refused; the entry points themselves check that a refusal has a
 * message and an accepted scene has no NaN/Inf (a failure there is
 * "broken"). Other names (presets, libFuzzer finds) may go either way. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include "tap.h"
#include "fuzz/fuzz_entry.h"

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

static void replay_one(const char *dir, const char *name, entry_fn fn)
{
    char path[4096], why[1024] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    size_t n = 0;
    unsigned char *data = slurp(path, &n);
    if (!ok(data != NULL, "%s: readable", path)) return;
    acbb_fuzz_outcome o = fn(data, n, why, sizeof why);
    free(data);
    /* Keep the TAP line one line: the message may quote a CR or a long value. */
    for (char *c = why; *c; c++)
        if (*c == '\n' || *c == '\r') *c = ' ';
    why[120] = '\0';
    if (o == ACBB_FUZZ_BROKEN) {
        ok(0, "%s: %s", path, why);
    } else if (!strncmp(name, "ok-", 3)) {
        ok(o == ACBB_FUZZ_ACCEPTED, "%s: accepted, every value finite%s%s", path,
           o ? ": refused: " : "", o ? why : "");
    } else if (!strncmp(name, "bad-", 4)) {
        ok(o == ACBB_FUZZ_REJECTED, "%s: refused with a message: %s", path,
           o ? why : "(accepted)");
    } else {
        ok(1, "%s: %s", path, o ? why : "accepted, every value finite");
    }
}

static void replay_dir(const char *dir, entry_fn fn)
{
    struct dirent **list;
    int n = scandir(dir, &list, NULL, by_name);
    if (!ok(n > 2, "%s: a corpus directory with files", dir)) return;
    for (int i = 0; i < n; i++) {
        if (list[i]->d_name[0] != '.') replay_one(dir, list[i]->d_name, fn);
        free(list[i]);
    }
    free(list);
}

int main(int argc, char **argv)
{
    entry_fn fn = acbb_fuzz_preset;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--preset")) fn = acbb_fuzz_preset;
        else if (!strcmp(argv[i], "--set")) fn = acbb_fuzz_set;
        else replay_dir(argv[i], fn);
    }
    acbb_fuzz_cleanup();
    printf("1..%d\n", tap_n);
    return tap_failed != 0;
}
