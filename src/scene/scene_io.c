/* acbb — scene files: INI parsing, load and full save.
 *
 * Files are parsed with inih (Debian libinih, 200-byte line buffer). A small
 * reader wrapped around getc counts lines (inih's handler does not get the
 * line number in this build) and looks at each raw line before inih does:
 * - it refuses over-long lines instead of letting inih split them;
 * - it refuses text after a section header ("[operating] axial_load_N = 5",
 *   or a stray CR as line break), which inih would drop silently;
 * - it refuses NUL bytes (fgets/inih would cut the value there) and control
 *   characters other than tab (a line starting with \v or \f would be read
 *   as a continuation of the previous value);
 * - it strips leading blanks so that an indented line is never taken as a
 *   multi-line continuation of the previous value. */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <ini.h>

#include "acbb/tools/outfile.h"
#include "acbb/tools/physics_profile.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/scene_edit.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"

/* ---- opening ---- */

static const char *file_kind(mode_t m)
{
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

/* O_NONBLOCK so that opening a FIFO with no writer returns at once; fstat
 * on the open descriptor, so what is checked is what is read. */
FILE *acbb_sf_open_preset(const char *path, acbb_error *err)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        acbb_error_set(err, ACBB_EIO, "%s: cannot open: %s", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(errno));
        close(fd);
        return NULL;
    }
    if (!S_ISREG(st.st_mode)) {
        acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s, not a regular file (a preset must "
                       "be a file)", path, file_kind(st.st_mode));
        close(fd);
        return NULL;
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0) (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "r");
    if (!f) {
        acbb_error_set(err, ACBB_EIO, "%s: cannot open: %s", path, strerror(errno));
        close(fd);
    }
    return f;
}

/* ---- parsing ---- */

typedef struct {
    const char *path;
    FILE *file;
    acbb_sf_parsed *out;
    int line;                   /* line number of the line inih is handling */
    int err_line;               /* first error found by us, 0 = none */
    acbb_status err_code;
    acbb_error err;
} load_ctx;

static bool load_fail(load_ctx *c, acbb_status code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static bool load_fail(load_ctx *c, acbb_status code, const char *fmt, ...)
{
    if (c->err_line) return false;
    char msg[sizeof c->err.msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    c->err_line = c->line;
    c->err_code = code;
    acbb_error_set(&c->err, code, "%s:%d: %s", c->path, c->line, msg);
    return false;
}

/* A "[section]" line: nothing but blanks or a comment may follow the ']'
 * (inih ignores the rest of the line). Notes where a schema section is. */
static bool check_header(load_ctx *c, const char *p)
{
    const char *close = strchr(p, ']');
    if (!close) return true;   /* inih reports the malformed line */
    const char *rest = close + 1 + strspn(close + 1, " \t\r");
    if (*rest && *rest != '\n' && *rest != ';' && *rest != '#') {
        size_t n = strcspn(rest, "\n");
        while (n > 0 && rest[n - 1] == '\r') n--;
        return load_fail(c, ACBB_EINVAL, "text after the section header %.*s: \"%.*s\" (put "
                         "each key on a line of its own)", (int)(close + 1 - p), p, (int)n, rest);
    }
    char name[INI_MAX_LINE];
    snprintf(name, sizeof name, "%.*s", (int)(close - p - 1), p + 1);
    int k = acbb_sf_section_index(name);
    if (k >= 0) c->out->section_end[k] = c->line;
    if (strcmp(name, "schedule") == 0) c->out->schedule_end = c->line;
    return true;
}

/* Control characters: only tab, and CR right before the line end. */
static bool check_controls(load_ctx *c, const char *str)
{
    for (const char *q = str; *q; q++) {
        unsigned char u = (unsigned char)*q;
        bool line_end = u == '\n' || (u == '\r' && (q[1] == '\n' || q[1] == '\0'));
        if ((u < 0x20 && u != '\t' && !line_end) || u == 0x7f)
            return load_fail(c, ACBB_EINVAL, "control character \\x%02x in the line (a preset "
                             "is plain text; only spaces and tabs as blanks)", u);
    }
    return true;
}

/* One raw line for inih, checked as the file comment says. */
static char *read_line(char *str, int num, void *stream)
{
    load_ctx *c = stream;
    if (c->err_line) return NULL;
    size_t len = 0, max = (size_t)num - 1;
    bool nul = false;
    int ch;
    while (len < max && (ch = getc(c->file)) != EOF) {
        nul |= ch == '\0';
        str[len++] = (char)(ch ? ch : ' ');
        if (ch == '\n') break;
    }
    if (len == 0) return NULL;
    str[len] = '\0';
    c->line++;
    if (str[len - 1] != '\n' && (ch = getc(c->file)) != EOF) {
        load_fail(c, ACBB_EINVAL, "line too long (at most %d characters)", num - 3);
        return NULL;
    }
    if (nul) {
        load_fail(c, ACBB_EINVAL, "NUL byte in line %d (a preset is plain text)", c->line);
        return NULL;
    }
    const char *p = str;
    if (c->line == 1 && memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
    p += strspn(p, " \t");
    if ((*p == '[' && !check_header(c, p)) || !check_controls(c, str)) return NULL;
    size_t skip = strspn(str, " \t");
    memmove(str, str + skip, strlen(str + skip) + 1);
    return str;
}

/* A [schedule] line: only `row = t_s, speed_rpm, axial_N, radial_N`, each
 * row after the one before in time, at most ACBB_SCHEDULE_MAX (schedule.h). */
static int on_schedule_row(load_ctx *c, const char *name, const char *value)
{
    acbb_sf_parsed *o = c->out;
    acbb_scene *s = &o->scene;
    acbb_error e;
    if (strcmp(name, "row") != 0)
        return load_fail(c, ACBB_EINVAL, "schedule.%s: unknown key (the [schedule] section "
                         "holds only lines row = t_s, speed_rpm, axial_N, radial_N)", name);
    if (s->schedule_n >= ACBB_SCHEDULE_MAX)
        return load_fail(c, ACBB_EINVAL, "schedule.row: more than %d rows", ACBB_SCHEDULE_MAX);
    acbb_schedule_row r;
    if (acbb_schedule_parse_row(value, &r, &e) != ACBB_OK)
        return load_fail(c, ACBB_EINVAL, "%s", e.msg);
    int n = s->schedule_n;
    if (n == 0 && r.t != 0.0)
        return load_fail(c, ACBB_EINVAL, "schedule.row = %s: the first row is the start of the "
                         "run: its t_s must be 0", value);
    if (n > 0 && !(r.t > s->schedule[n - 1].t))
        return load_fail(c, ACBB_EINVAL, "schedule.row = %s: times must increase strictly (the "
                         "row before, line %d, is at a time >= this one)", value,
                         o->schedule_line[n - 1]);
    s->schedule[n] = r;
    s->schedule_n = n + 1;
    o->schedule_line[n] = c->line;
    o->schedule_end = c->line;
    return 1;
}

static int on_key(void *user, const char *section, const char *name, const char *value)
{
    load_ctx *c = user;
    if (c->err_line) return 1;
    acbb_error e;
    c->out->n_keys++;
    if (strcmp(section, "schedule") == 0) return on_schedule_row(c, name, value);
    const acbb_sfield *f = acbb_sf_find(section, name);
    if (!f) {
        acbb_sf_unknown_key(section, name, &e);
        return load_fail(c, ACBB_EINVAL, "%s", e.msg);
    }
    size_t i = (size_t)(f - acbb_sf_table);
    if (c->out->first_line[i])
        return load_fail(c, ACBB_EINVAL, "%s.%s: set twice (first at line %d)", section, name,
                         c->out->first_line[i]);
    c->out->first_line[i] = c->line;
    c->out->section_end[acbb_sf_section_index(section)] = c->line;
    if (acbb_sf_apply(&c->out->scene, f, value, &e) != ACBB_OK)
        return load_fail(c, ACBB_EINVAL, "%s", e.msg);
    return 1;
}

/* The keys of the profile table the file gives are the user's; the others
 * take physics.profile's values (physics_profile.h), wherever in the file
 * the profile key stands. */
static void given_by_profile(acbb_sf_parsed *out)
{
    out->scene.profile_given = 0;
    for (size_t k = 0; k < acbb_profile_row_count(); k++) {
        const acbb_sfield *f = acbb_sf_profile_field(k);
        if (f && out->first_line[f - acbb_sf_table]) out->scene.profile_given |= 1u << k;
    }
    acbb_profile_apply(&out->scene);
}

acbb_status acbb_sf_parse(FILE *f, const char *path, acbb_sf_parsed *out, acbb_error *err)
{
    load_ctx *c = calloc(1, sizeof *c);
    if (!c) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    memset(out, 0, sizeof *out);
    acbb_scene_default(&out->scene);
    c->path = path;
    c->file = f;
    c->out = out;
    int ret = ini_parse_stream(read_line, c, on_key, c);
    acbb_status rc = ACBB_OK;
    if (ferror(f))
        rc = acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(errno));
    else if (ret < 0)
        rc = acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    else if (ret > 0 && (c->err_line == 0 || ret < c->err_line))
        rc = acbb_error_set(err, ACBB_EINVAL,
                            "%s:%d: malformed line (expected key = value or [section])", path, ret);
    else if (c->err_line)
        rc = acbb_error_set(err, c->err_code, "%s", c->err.msg);
    if (rc == ACBB_OK) given_by_profile(out);
    free(c);
    return rc;
}

/* ---- loading ---- */

/* Parse the open preset `f`, named `name` in messages, into `s` and check
 * it: the one path of a file and of text (acbb_scene_load_text). */
static acbb_status load_stream(FILE *f, const char *name, acbb_scene *s, acbb_error *err)
{
    acbb_sf_parsed *p = calloc(1, sizeof *p);
    if (!p) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", name);
    acbb_status rc = acbb_sf_parse(f, name, p, err);
    if (rc == ACBB_OK && p->n_keys == 0) {
        rc = acbb_error_set(err, ACBB_EINVAL, "%s: empty preset (no keys)", name);
    } else if (rc == ACBB_OK) {
        acbb_error e, es;
        int row;
        rc = acbb_scene_validate(&p->scene, &e);
        /* A schedule row's rule: named with the row's line. */
        bool at_row = rc != ACBB_OK && acbb_sf_schedule_check(&p->scene, &row, &es) == rc
                      && row >= 0 && strcmp(es.msg, e.msg) == 0;
        if (at_row)
            acbb_error_set(err, rc, "%s:%d: %s", name, p->schedule_line[row], e.msg);
        else if (rc != ACBB_OK)
            acbb_error_set(err, rc, "%s: %s", name, e.msg);
        else
            *s = p->scene;
    }
    free(p);
    return rc;
}

acbb_status acbb_scene_load(const char *path, acbb_scene *s, acbb_error *err)
{
    acbb_status rc = ACBB_EIO;
    FILE *f = acbb_sf_open_preset(path, err);
    if (f) {
        rc = load_stream(f, path, s, err);
        fclose(f);
    }
    if (rc != ACBB_OK) acbb_sf_escape_msg(err);
    return rc;
}

/* The text is read through a memory stream, so it meets the very checks a
 * file does (issue 16: the FFI entry point takes preset text). */
acbb_status acbb_scene_load_text(const char *text, acbb_scene *s, acbb_error *err)
{
    return acbb_scene_load_text_n(text, text ? strlen(text) : 0, NULL, s, err);
}

/* The length is the caller's, so a NUL inside the text reaches the line
 * reader and is refused as in a file (issue 28 item 4), not cut there. */
acbb_status acbb_scene_load_text_n(const char *text, size_t len, const char *name,
                                   acbb_scene *s, acbb_error *err)
{
    if (!name) name = "<text>";
    acbb_status rc;
    FILE *f = text && len ? fmemopen((void *)text, len, "r") : NULL;
    if (!text || !len)
        rc = acbb_error_set(err, ACBB_EINVAL, "%s: empty preset (no keys)", name);
    else if (!f)
        rc = acbb_error_set(err, ACBB_ENOMEM, "%s: cannot read: %s", name, strerror(errno));
    else
        rc = load_stream(f, name, s, err);
    if (f) fclose(f);
    if (rc != ACBB_OK) acbb_sf_escape_msg(err);
    return rc;
}

/* ---- saving ---- */

int acbb_sf_write_preset(FILE *f, const acbb_scene *s)
{
    const char *section = "";
    int bad = fprintf(f, "; acbb preset (bearing scene). Units are in the key names; decimal "
                         "point '.'.\n; Every key is listed; a key left out of a preset takes "
                         "its default (presets/7008C.ini),\n; or physics.profile's value for "
                         "the keys the profile sets.\n") < 0;
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
    if (s->schedule_n > 0 && !bad)
        bad |= fprintf(f, "\n[schedule]\n; run-in rows: t_s, speed_rpm, axial_N, radial_N; "
                       "linear between rows, held after the last\n") < 0;
    for (int i = 0; i < s->schedule_n && !bad; i++) {
        char row[160];
        acbb_schedule_format_row(s, i, row, sizeof row);
        bad |= fprintf(f, "row = %s\n", row) < 0;
    }
    return bad ? -1 : 0;
}

acbb_status acbb_scene_write(FILE *f, const acbb_scene *s, acbb_error *err)
{
    acbb_error e;
    acbb_status rc = acbb_scene_validate(s, &e);
    if (rc != ACBB_OK) return acbb_error_set(err, rc, "not saved: %s", e.msg);
    if (acbb_sf_write_preset(f, s) != 0 || fflush(f) != 0)
        return acbb_error_set(err, ACBB_EIO, "cannot write: %s", strerror(errno));
    return ACBB_OK;
}

/* Through acbb_out (outfile.h): temp file beside the target, fsync, rename;
 * mode kept, symlinks followed, non-regular targets written directly. */
acbb_status acbb_scene_save(const char *path, const acbb_scene *s, acbb_error *err)
{
    acbb_error e;
    acbb_status rc = acbb_scene_validate(s, &e);
    if (rc != ACBB_OK) {
        acbb_error_set(err, rc, "%s: not saved: %s", path, e.msg);
    } else {
        acbb_out *o;
        FILE *f;
        rc = acbb_out_open(path, &o, &f, err);
        if (rc == ACBB_OK && acbb_sf_write_preset(f, s) != 0) {
            acbb_out_abort(o);
            rc = acbb_error_set(err, ACBB_EIO, "cannot write %s: %s", path, strerror(errno));
        } else if (rc == ACBB_OK) {
            rc = acbb_out_commit(o, err);
        }
    }
    if (rc != ACBB_OK) acbb_sf_escape_msg(err);
    return rc;
}
