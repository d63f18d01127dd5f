/* acbb — scene files: INI load and full save.
 *
 * Files are parsed with inih (Debian libinih, 200-byte line buffer). A small
 * reader wrapped around fgets counts lines (inih's handler does not get the
 * line number in this build), refuses over-long lines instead of letting
 * inih split them, and strips leading blanks so that an indented line is
 * never taken as a multi-line continuation of the previous value. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ini.h>

#include "scene_internal.h"

/* ---- loading ---- */

typedef struct {
    const char *path;
    FILE *file;
    acbb_scene scene;
    int line;                   /* line number of the line inih is handling */
    int n_keys;
    int first_line[ACBB_SF_MAX];   /* where each key was set, 0 = not yet */
    int err_line;               /* first error found by us, 0 = none */
    acbb_status err_code;
    acbb_error err;
} load_ctx;

static void load_fail(load_ctx *c, acbb_status code, const char *msg)
{
    if (c->err_line) return;
    c->err_line = c->line;
    c->err_code = code;
    acbb_error_set(&c->err, code, "%s:%d: %s", c->path, c->line, msg);
}

/* fgets for inih that counts lines, stops on a line that does not fit the
 * buffer (inih would silently split it into two lines), and strips leading
 * blanks so no line is read as a continuation of the previous value. */
static char *read_line(char *str, int num, void *stream)
{
    load_ctx *c = stream;
    if (c->err_line || !fgets(str, num, c->file)) return NULL;
    c->line++;
    size_t len = strlen(str);
    if (len == 0 || str[len - 1] != '\n') {
        int ch = fgetc(c->file);
        if (ch != EOF) {
            char msg[96];
            snprintf(msg, sizeof msg, "line too long (at most %d characters)", num - 3);
            load_fail(c, ACBB_EINVAL, msg);
            return NULL;
        }
    }
    size_t skip = strspn(str, " \t");
    memmove(str, str + skip, strlen(str + skip) + 1);
    return str;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    load_ctx *c = user;
    if (c->err_line) return 1;
    acbb_error e;
    c->n_keys++;
    const acbb_sfield *f = acbb_sf_find(section, name);
    if (!f) {
        acbb_sf_unknown_key(section, name, &e);
        load_fail(c, ACBB_EINVAL, e.msg);
        return 0;
    }
    size_t i = (size_t)(f - acbb_sf_table);
    if (c->first_line[i]) {
        snprintf(e.msg, sizeof e.msg, "%s.%s: set twice (first at line %d)", section, name,
                 c->first_line[i]);
        load_fail(c, ACBB_EINVAL, e.msg);
        return 0;
    }
    c->first_line[i] = c->line;
    if (acbb_sf_apply(&c->scene, f, value, &e) != ACBB_OK) {
        load_fail(c, ACBB_EINVAL, e.msg);
        return 0;
    }
    return 1;
}

acbb_status acbb_scene_load(const char *path, acbb_scene *s, acbb_error *err)
{
    load_ctx *c = calloc(1, sizeof *c);
    if (!c) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    c->path = path;
    acbb_scene_default(&c->scene);
    c->file = fopen(path, "r");
    if (!c->file) {
        int e = errno;
        free(c);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot open: %s", path, strerror(e));
    }

    int ret = ini_parse_stream(read_line, c, on_key, c);
    int read_errno = ferror(c->file) ? errno : 0;
    bool read_error = ferror(c->file) != 0;
    fclose(c->file);

    acbb_status rc = ACBB_OK;
    if (read_error) {
        rc = acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(read_errno));
    } else if (ret < 0) {
        rc = acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    } else if (ret > 0 && (c->err_line == 0 || ret < c->err_line)) {
        rc = acbb_error_set(err, ACBB_EINVAL,
                            "%s:%d: malformed line (expected key = value or [section])", path, ret);
    } else if (c->err_line) {
        rc = acbb_error_set(err, c->err_code, "%s", c->err.msg);
    } else if (c->n_keys == 0) {
        rc = acbb_error_set(err, ACBB_EINVAL, "%s: empty preset (no keys)", path);
    } else {
        acbb_error e;
        rc = acbb_scene_validate(&c->scene, &e);
        if (rc != ACBB_OK)
            acbb_error_set(err, rc, "%s: %s", path, e.msg);
        else
            *s = c->scene;
    }
    free(c);
    return rc;
}

/* ---- saving ---- */

static int write_preset(FILE *f, const acbb_scene *s)
{
    const char *section = "";
    int bad = fprintf(f, "; acbb preset (bearing scene). Units are in the key names; decimal "
                         "point '.'.\n; Every key is listed; a key left out of a preset takes "
                         "its default (presets/7008C.ini).\n") < 0;
    for (size_t i = 0; i < acbb_sf_n && !bad; i++) {
        const acbb_field_info *in = &acbb_sf_table[i].info;
        char range[160], val[64];
        if (strcmp(section, in->section) != 0) {
            section = in->section;
            bad |= fprintf(f, "\n[%s]\n", section) < 0;
        }
        acbb_scene_field_range(i, range, sizeof range);
        acbb_scene_field_format(s, i, val, sizeof val);
        bad |= fprintf(f, "; %s [%s]\n%s = %s\n", in->help, range, in->key, val) < 0;
    }
    return bad ? -1 : 0;
}

/* Flush the rename to disk; best effort (the file itself is already safe). */
static void sync_parent_dir(const char *path)
{
    char *dir = strdup(path);
    if (!dir) return;
    char *slash = strrchr(dir, '/');
    const char *d = ".";
    if (slash) {
        slash[slash == dir ? 1 : 0] = '\0';
        d = dir;
    }
    int fd = open(d, O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        (void)fsync(fd);
        close(fd);
    }
    free(dir);
}

acbb_status acbb_scene_save(const char *path, const acbb_scene *s, acbb_error *err)
{
    acbb_error e;
    acbb_status rc = acbb_scene_validate(s, &e);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "%s: not saved: %s", path, e.msg);

    size_t n = strlen(path) + sizeof ".tmp.XXXXXX";
    char *tmp = malloc(n);
    if (!tmp) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    snprintf(tmp, n, "%s.tmp.XXXXXX", path);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        int en = errno;
        free(tmp);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot save (temporary file): %s", path,
                              strerror(en));
    }
    /* mkstemp makes the file 0600; keep the mode of the file we replace. */
    struct stat st;
    (void)fchmod(fd, stat(path, &st) == 0 ? (st.st_mode & 07777) : 0644);

    const char *step = "write";
    FILE *f = fdopen(fd, "w");
    bool ok = f != NULL;
    if (!ok) close(fd);
    if (ok) ok = write_preset(f, s) == 0 && fflush(f) == 0;
    if (ok && fsync(fileno(f)) != 0) ok = false, step = "fsync";
    int en = errno;
    if (f && fclose(f) != 0 && ok) ok = false, en = errno;
    if (ok && rename(tmp, path) != 0) ok = false, en = errno, step = "rename";
    if (!ok) {
        unlink(tmp);
        free(tmp);
        return acbb_error_set(err, ACBB_EIO, "%s: cannot save (%s): %s", path, step,
                              strerror(en));
    }
    free(tmp);
    sync_parent_dir(path);
    return ACBB_OK;
}
