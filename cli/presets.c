/* acbb CLI — the preset search path and `acbb presets` (presets.h). */
#include <dirent.h>
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "exit.h"
#include "presets.h"
#include "acbb/tools/preset_info.h"
#include "say.h"

/* Set by meson (meson.build); the fallbacks keep a bare compile working. */
#ifndef ACBB_PRESET_DIR
#define ACBB_PRESET_DIR "/usr/local/share/acbb/presets"
#endif
#ifndef ACBB_BINDIR
#define ACBB_BINDIR "bin"
#endif
#ifndef ACBB_DATADIR
#define ACBB_DATADIR "share"
#endif

static bool is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* A FIFO, device or socket by that name: the loader names its kind (issue
 * 20 item 7), rather than "no such file". */
static bool is_special(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

static bool is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

static bool user_dir(char *buf, size_t n)
{
    const char *xdg = getenv("XDG_CONFIG_HOME");
    const char *home = getenv("HOME");
    /* The XDG spec ignores a relative XDG_CONFIG_HOME. */
    if (xdg && xdg[0] == '/')
        return (size_t)snprintf(buf, n, "%s/acbb/presets", xdg) < n;
    if (home && home[0])
        return (size_t)snprintf(buf, n, "%s/.config/acbb/presets", home) < n;
    return false;
}

/* PREFIX/DATADIR/acbb/presets for the prefix the running binary sits in
 * (PREFIX/BINDIR/acbb); false when it is not in a BINDIR (a build tree). */
static bool relocated_dir(char *buf, size_t n)
{
    char exe[CLI_PATH_MAX];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0) return false;
    exe[len] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash) return false;
    *slash = '\0';                          /* the binary's directory */
    size_t bl = strlen(ACBB_BINDIR), el = strlen(exe);
    if (ACBB_BINDIR[0] == '/' || el <= bl || exe[el - bl - 1] != '/' ||
        strcmp(exe + el - bl, ACBB_BINDIR) != 0)
        return false;
    exe[el - bl - 1] = '\0';                /* the prefix */
    return (size_t)snprintf(buf, n, "%s/%s/acbb/presets", exe, ACBB_DATADIR) < n;
}

static void add_dir(acbb_cli_preset_dir *dirs, size_t *n, const char *path, const char *role)
{
    for (size_t i = 0; i < *n; i++)
        if (strcmp(dirs[i].path, path) == 0) return;
    snprintf(dirs[*n].path, sizeof dirs[*n].path, "%s", path);
    dirs[*n].role = role;
    ++*n;
}

size_t acbb_cli_preset_dirs(acbb_cli_preset_dir dirs[CLI_MAX_PRESET_DIRS])
{
    size_t n = 0;
    char buf[CLI_PATH_MAX];
    if (user_dir(buf, sizeof buf)) add_dir(dirs, &n, buf, "user");
    add_dir(dirs, &n, "presets", "source tree");
    add_dir(dirs, &n, ACBB_PRESET_DIR, "installed");
    if (relocated_dir(buf, sizeof buf)) {
        /* The same directory reached another way adds nothing. */
        char *a = realpath(buf, NULL), *b = realpath(ACBB_PRESET_DIR, NULL);
        if (!a || !b || strcmp(a, b) != 0) add_dir(dirs, &n, buf, "installed");
        free(a);
        free(b);
    }
    return n;
}

static bool ends_with_ini(const char *s)
{
    size_t len = strlen(s);
    return len > 4 && strcmp(s + len - 4, ".ini") == 0;
}

int acbb_cli_resolve_preset(const char *arg, char *out, size_t n, bool report)
{
    /* "-": the preset is read from stdin (acbb_cli_load_scene). */
    if (strchr(arg, '/') || is_file(arg) || is_special(arg) || !arg[0] || !strcmp(arg, "-")) {
        snprintf(out, n, "%s", arg);
        return 0;
    }
    acbb_cli_preset_dir dirs[CLI_MAX_PRESET_DIRS];
    size_t nd = acbb_cli_preset_dirs(dirs);
    for (size_t i = 0; i < nd; i++) {
        for (int ext = 0; ext < 2; ext++) {
            if (ext && ends_with_ini(arg)) break;
            if ((size_t)snprintf(out, n, "%s/%s%s", dirs[i].path, arg, ext ? ".ini" : "") >= n)
                continue;
            if (is_file(out)) return 0;
        }
    }
    if (!report) return -1;
    acbb_cli_msg m;
    FILE *f = acbb_cli_msg_begin(&m);
    fprintf(f, "cannot open preset %s: no such file, and no %s%s in", arg, arg,
            ends_with_ini(arg) ? "" : "[.ini]");
    for (size_t i = 0; i < nd; i++) fprintf(f, "%s %s", i ? "," : "", dirs[i].path);
    fputs(" (see `acbb presets`)\n", f);
    acbb_cli_msg_say(&m);
    return -1;
}

bool acbb_cli_preset_installed(const char *path, char *dir, size_t n)
{
    char *file = realpath(path, NULL);
    char *slash = file ? strrchr(file, '/') : NULL;
    bool found = false;
    if (slash) *slash = '\0';
    acbb_cli_preset_dir dirs[CLI_MAX_PRESET_DIRS];
    size_t nd = slash ? acbb_cli_preset_dirs(dirs) : 0;
    for (size_t i = 0; i < nd && !found; i++) {
        char *d = strcmp(dirs[i].role, "installed") == 0 ? realpath(dirs[i].path, NULL) : NULL;
        found = d && strcmp(d, file) == 0;
        if (found) snprintf(dir, n, "%s", dirs[i].path);
        free(d);
    }
    free(file);
    return found;
}

const char *acbb_cli_study_preset_name(const char *arg)
{
    return strcmp(arg, "seed") == 0 ? "7008C" : arg;
}

/* ---- acbb presets ---- */

static int cmp_str(const void *x, const void *y)
{
    return strcmp(*(char *const *)x, *(char *const *)y);
}

/* Text from a file, with control characters shown as \xNN so a preset
 * cannot drive the terminal. */
static void put_safe(const char *t, size_t max)
{
    for (size_t i = 0; t[i] && i < max; i++) {
        unsigned char c = (unsigned char)t[i];
        if (c < 0x20 || c == 0x7f) printf("\\x%02x", c);
        else putchar(c);
    }
}

/* The "Look at:" paragraph wrapped at 78 columns under the preset. */
static void put_wrapped(const char *label, const char *text)
{
    const int indent = 6, width = 78;
    printf("%*s%s", indent, "", label);
    int col = indent + (int)strlen(label);
    const char *p = text;
    while (*p) {
        size_t w = strcspn(p, " ");
        if (col + 1 + (int)w > width && col > indent + (int)strlen(label)) {
            printf("\n%*s", indent + 2, "");
            col = indent + 2;
        } else if (p != text) {
            putchar(' ');
            col++;
        }
        put_safe(p, w);
        col += (int)w;
        p += w;
        p += strspn(p, " ");
    }
    putchar('\n');
}

/* The *.ini names in `dir`, sorted; NULL with *n = 0 when none. */
static char **ini_names(const char *dir, size_t *n)
{
    *n = 0;
    DIR *d = opendir(dir);
    if (!d) return NULL;
    char **names = NULL;
    size_t cap = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (!ends_with_ini(e->d_name)) continue;
        if (*n == cap) {
            cap = cap ? 2 * cap : 16;
            char **grown = realloc(names, cap * sizeof *names);
            if (!grown) break;
            names = grown;
        }
        if (!(names[*n] = strdup(e->d_name))) break;
        ++*n;
    }
    closedir(d);
    if (*n) qsort(names, *n, sizeof *names, cmp_str);
    return names;
}

/* The directory's presets, each marked when an earlier directory of the
 * search path (dirs[0..before)) already has one of that name. */
static void list_dir(const char *dir, const acbb_cli_preset_dir *dirs, size_t before)
{
    size_t n;
    char **names = ini_names(dir, &n);
    for (size_t i = 0; i < n; i++) {
        char path[CLI_PATH_MAX + 256], other[CLI_PATH_MAX + 256];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        acbb_preset_info info;
        if (acbb_preset_info_read(path, &info, NULL) != ACBB_OK || !info.title[0])
            snprintf(info.title, sizeof info.title, "(no description)");
        const char *shadow = NULL;
        for (size_t k = 0; k < before && !shadow; k++) {
            snprintf(other, sizeof other, "%s/%s", dirs[k].path, names[i]);
            if (is_file(other)) shadow = dirs[k].path;
        }
        printf("  %s", names[i]);
        if (shadow) {
            printf("  (shadowed by %s)\n", shadow);
        } else {
            putchar('\n');
            put_wrapped("", info.title);
            if (info.look_at[0]) put_wrapped("look at: ", info.look_at);
            if (info.expect[0]) printf("      expect: %s\n", info.expect);
        }
        free(names[i]);
    }
    if (n == 0) puts("  (no presets)");
    free(names);
}

int acbb_cli_cmd_presets(const acbb_cli_args *a)
{
    if (a->n_pos) {
        if (!is_dir(a->pos[0])) {
            acbb_cli_say("presets: cannot open %s: %s\n", a->pos[0],
                    strerror(errno ? errno : ENOENT));
            return ACBB_EXIT_INPUT;
        }
        printf("%s/\n", a->pos[0]);
        list_dir(a->pos[0], NULL, 0);
    } else {
        acbb_cli_preset_dir dirs[CLI_MAX_PRESET_DIRS];
        size_t nd = acbb_cli_preset_dirs(dirs);
        puts("preset search path, first match wins (a PRESET naming a file is used as is):");
        for (size_t i = 0; i < nd; i++) {
            bool there = is_dir(dirs[i].path);
            printf("\n%s/  (%s%s)\n", dirs[i].path, dirs[i].role, there ? "" : ", not present");
            if (there) list_dir(dirs[i].path, dirs, i);
        }
    }
    if (fflush(stdout) != 0 || ferror(stdout)) {
        acbb_cli_say("cannot write to stdout\n");
        return ACBB_EXIT_INTERNAL;
    }
    return 0;
}
