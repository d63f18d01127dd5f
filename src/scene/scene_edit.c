/* acbb — saving into the user's own preset file, keeping it (scene.h,
 * acbb_scene_save_edits): the idea of `git config`'s writer (DESIGN.md).
 *
 * The old file is read once into memory and parsed by the same reader as
 * acbb_scene_load (scene_io.c), which notes the line of every key and the
 * last line of every section. The new file is the old one line by line:
 * a key line whose value changed gets the new value in place of the old
 * (the text before and after the value, an inline comment included, stays);
 * keys new to the file follow the last line of their section; sections new
 * to the file go at the end. "Changed" compares values, not spellings: the
 * formatted text of a value is exact (scene_schema.c, format_real), so equal
 * text means equal value. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "acbb/tools/outfile.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/scene_edit.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"

/* A preset is a few kB; anything far larger is not one. */
#define EDIT_FILE_MAX (4L << 20)

typedef struct {
    const acbb_scene *s;         /* the scene to save */
    const acbb_sf_parsed *p;     /* what the old file says */
    acbb_scene defaults;
    const char *eol;             /* "\n" or "\r\n", as the old file */
    FILE *f;
    int at_line_start;           /* the output ends with a line end (or is empty) */
} edit_ctx;

static int differs(const acbb_scene *a, const acbb_scene *b, size_t i)
{
    char va[64], vb[64];
    acbb_scene_field_format(a, i, va, sizeof va);
    acbb_scene_field_format(b, i, vb, sizeof vb);
    return strcmp(va, vb) != 0;
}

/* Field i is not in the file and its new value is not the default. */
static int is_new_key(const edit_ctx *c, size_t i)
{
    return !c->p->first_line[i] && differs(&c->defaults, c->s, i);
}

static int section_of(size_t i)
{
    return acbb_sf_section_index(acbb_sf_table[i].info.section);
}

static int section_has_new_keys(const edit_ctx *c, int k)
{
    for (size_t i = 0; i < acbb_sf_n; i++)
        if (section_of(i) == k && is_new_key(c, i)) return 1;
    return 0;
}

static void put_text(edit_ctx *c, const char *text, size_t n)
{
    if (n == 0) return;
    fwrite(text, 1, n, c->f);
    c->at_line_start = text[n - 1] == '\n';
}

static void end_line(edit_ctx *c)
{
    if (!c->at_line_start) put_text(c, c->eol, strlen(c->eol));
}

static void write_new_keys(edit_ctx *c, int k)
{
    end_line(c);
    for (size_t i = 0; i < acbb_sf_n; i++) {
        if (section_of(i) != k || !is_new_key(c, i)) continue;
        char val[64];
        acbb_scene_field_format(c->s, i, val, sizeof val);
        fprintf(c->f, "%s = %s%s", acbb_sf_table[i].info.key, val, c->eol);
    }
}

/* Where the value of key line `line` (n bytes) is, as inih reads it: after
 * the first '=' or ':', blanks skipped, up to an inline comment (';' after
 * a blank) or the line end, trailing blanks dropped. */
static void value_span(const char *line, size_t n, size_t *vs, size_t *ve)
{
    size_t v = 0;
    while (v < n && line[v] != '=' && line[v] != ':') v++;
    size_t e = v < n ? ++v : v;
    for (int was_space = 0; e < n && line[e] != '\n' && !(line[e] == ';' && was_space); e++)
        was_space = isspace((unsigned char)line[e]) != 0;
    while (e > v && isspace((unsigned char)line[e - 1])) e--;
    while (v < e && isspace((unsigned char)line[v])) v++;
    *vs = v;
    *ve = e;
}

/* ---- the [schedule] rows (schedule.h): kept as they are while the rows
 * are the same; else the new rows go where the first old row was (or after
 * the section header, or in a new section at the end) and the other old row
 * lines go. Comments in the section stay. ---- */

static int same_schedule(const acbb_scene *a, const acbb_scene *b)
{
    if (a->schedule_n != b->schedule_n) return 0;
    for (int i = 0; i < a->schedule_n; i++) {
        char ra[160], rb[160];
        acbb_schedule_format_row(a, i, ra, sizeof ra);
        acbb_schedule_format_row(b, i, rb, sizeof rb);
        if (strcmp(ra, rb) != 0) return 0;
    }
    return 1;
}

static void write_rows(edit_ctx *c)
{
    end_line(c);
    for (int i = 0; i < c->s->schedule_n; i++) {
        char row[160];
        acbb_schedule_format_row(c->s, i, row, sizeof row);
        fprintf(c->f, "row = %s%s", row, c->eol);
    }
}

/* Old line `no` is a row line (returns 1: handled) or ends the [schedule]
 * section of a file without rows (the new rows follow it). */
static int emit_schedule_line(edit_ctx *c, const char *line, size_t n, int no)
{
    const acbb_sf_parsed *p = c->p;
    int k = 0;
    while (k < p->scene.schedule_n && p->schedule_line[k] != no) k++;
    int changed = !same_schedule(&p->scene, c->s);
    if (k < p->scene.schedule_n) {
        if (!changed) put_text(c, line, n);
        else if (k == 0) write_rows(c);
        return 1;
    }
    if (no == p->schedule_end && p->scene.schedule_n == 0 && changed) {
        put_text(c, line, n);
        write_rows(c);
        return 1;
    }
    return 0;
}

/* Copy old line `no` (n bytes with its line end), its value replaced if the
 * key on it changed; then the section's new keys if the section ends here. */
static void emit_line(edit_ctx *c, const char *line, size_t n, int no)
{
    if (emit_schedule_line(c, line, n, no)) return;
    size_t i = 0;
    while (i < acbb_sf_n && c->p->first_line[i] != no) i++;
    if (i < acbb_sf_n && differs(&c->p->scene, c->s, i)) {
        size_t vs, ve;
        char val[64];
        value_span(line, n, &vs, &ve);
        acbb_scene_field_format(c->s, i, val, sizeof val);
        put_text(c, line, vs);
        put_text(c, val, strlen(val));
        put_text(c, line + ve, n - ve);
    } else {
        put_text(c, line, n);
    }
    for (size_t k = 0; k < acbb_sf_section_count(); k++)
        if (c->p->section_end[k] == no && section_has_new_keys(c, (int)k))
            write_new_keys(c, (int)k);
}

static void emit_file(edit_ctx *c, const char *buf, size_t len)
{
    const char *nl = memchr(buf, '\n', len);
    c->eol = nl && nl > buf && nl[-1] == '\r' ? "\r\n" : "\n";
    c->at_line_start = 1;
    int no = 0;
    for (size_t pos = 0; pos < len;) {
        const char *end = memchr(buf + pos, '\n', len - pos);
        size_t next = end ? (size_t)(end - buf) + 1 : len;
        emit_line(c, buf + pos, next - pos, ++no);
        pos = next;
    }
    for (size_t k = 0; k < acbb_sf_section_count(); k++) {
        if (c->p->section_end[k] || !section_has_new_keys(c, (int)k)) continue;
        end_line(c);
        fprintf(c->f, "%s[%s]%s", c->eol, acbb_sf_section_name(k), c->eol);
        write_new_keys(c, (int)k);
    }
    if (!c->p->schedule_end && c->s->schedule_n > 0) {
        end_line(c);
        fprintf(c->f, "%s[schedule]%s", c->eol, c->eol);
        write_rows(c);
    }
}

/* The old file, whole, into *buf (malloc'd). */
static acbb_status slurp(const char *path, char **buf, size_t *len, acbb_error *err)
{
    FILE *in = acbb_sf_open_preset(path, err);
    if (!in) return ACBB_EIO;
    *buf = malloc((size_t)EDIT_FILE_MAX + 1);
    *len = *buf ? fread(*buf, 1, (size_t)EDIT_FILE_MAX + 1, in) : 0;
    acbb_status rc = ACBB_OK;
    if (!*buf)
        rc = acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    else if (ferror(in))
        rc = acbb_error_set(err, ACBB_EIO, "%s: cannot read: %s", path, strerror(errno));
    else if (*len > (size_t)EDIT_FILE_MAX)
        rc = acbb_error_set(err, ACBB_EINVAL, "%s: not saved: larger than %ld bytes, not a "
                            "preset", path, EDIT_FILE_MAX);
    fclose(in);
    if (rc != ACBB_OK) {
        free(*buf);
        *buf = NULL;
    }
    return rc;
}

/* Parse the old file (from memory: what is parsed is what is copied). */
static acbb_status parse_old(const char *path, char *buf, size_t len, acbb_sf_parsed *p,
                             acbb_error *err)
{
    FILE *mf = fmemopen(buf, len, "r");
    if (!mf) return acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    acbb_error e;
    acbb_status rc = acbb_sf_parse(mf, path, p, &e);
    fclose(mf);
    if (rc != ACBB_OK)
        acbb_error_set(err, rc, "%s: not saved: %s (the file is kept as it is; fix that line "
                       "or save under another name)", path, e.msg);
    return rc;
}

static acbb_status edit_file(const char *path, const char *to, const acbb_scene *s,
                             acbb_error *err)
{
    char *buf = NULL;
    size_t len = 0;
    acbb_status rc = slurp(path, &buf, &len, err);
    if (rc != ACBB_OK) return rc;
    edit_ctx *c = calloc(1, sizeof *c);
    acbb_sf_parsed *p = calloc(1, sizeof *p);
    if (!c || !p) rc = acbb_error_set(err, ACBB_ENOMEM, "%s: out of memory", path);
    if (rc == ACBB_OK) rc = parse_old(path, buf, len, p, err);
    acbb_out *o = NULL;
    if (rc == ACBB_OK) rc = acbb_out_open(to, &o, &c->f, err);
    if (rc == ACBB_OK) {
        c->s = s;
        c->p = p;
        /* A key's default is its profile's (physics_profile.h). */
        acbb_sf_profile_defaults(&c->defaults, s->profile);
        emit_file(c, buf, len);
        rc = acbb_out_commit(o, err);
    }
    free(p);
    free(c);
    free(buf);
    return rc;
}

acbb_status acbb_scene_save_edits(const char *path, const acbb_scene *s, acbb_error *err)
{
    return acbb_scene_save_edits_to(path, path, s, err);
}

acbb_status acbb_scene_save_edits_to(const char *path, const char *to, const acbb_scene *s,
                                     acbb_error *err)
{
    acbb_error e;
    acbb_status rc = acbb_scene_validate(s, &e);
    struct stat st;
    int found = rc == ACBB_OK && stat(path, &st) == 0, en = errno;
    if (rc != ACBB_OK)
        acbb_error_set(err, rc, "%s: not saved: %s", path, e.msg);
    else if (!found && en != ENOENT)
        rc = acbb_error_set(err, ACBB_EIO, "%s: cannot save: %s", path, strerror(en));
    else if (!found || !S_ISREG(st.st_mode) || st.st_size == 0)
        return acbb_scene_save(to, s, err);
    else
        rc = edit_file(path, to, s, err);
    if (rc != ACBB_OK) acbb_sf_escape_msg(err);
    return rc;
}
