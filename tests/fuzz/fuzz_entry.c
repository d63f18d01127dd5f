/* acbb fuzzing — the shared entry points (fuzz_entry.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/scene.h"
#include "acbb/tools/schedule.h"
#include "acbb/tools/scene_schema.h"
#include "fuzz_entry.h"

/* One temporary file per process, rewritten for every input: the loader
 * reads only regular files (scene.h). Harness state, not engine state. */
static char tmp_path[4096];
static int tmp_fd = -1;

static int tmp_open(void)
{
    if (tmp_fd >= 0) return 0;
    const char *dir = getenv("TMPDIR");
    snprintf(tmp_path, sizeof tmp_path, "%s/acbb-fuzz-XXXXXX", dir && *dir ? dir : "/tmp");
    tmp_fd = mkstemp(tmp_path);
    return tmp_fd >= 0 ? 0 : -1;
}

const char *acbb_fuzz_preset_path(void) { return tmp_path; }

void acbb_fuzz_cleanup(void)
{
    if (tmp_fd < 0) return;
    close(tmp_fd);
    unlink(tmp_path);
    tmp_fd = -1;
}

static acbb_fuzz_outcome broken(char *why, size_t n, const char *fmt, const char *a,
                                const char *b)
{
    snprintf(why, n, fmt, a, b);
    return ACBB_FUZZ_BROKEN;
}

/* Every schema value of an accepted scene prints as a finite number (or a
 * name for on/off and choice keys), and the scene passes validation. */
static acbb_fuzz_outcome check_scene(const acbb_scene *s, char *why, size_t n)
{
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        const acbb_field_info *fi = acbb_scene_field(i);
        if (fi->type != ACBB_FIELD_REAL && fi->type != ACBB_FIELD_INT) continue;
        char buf[128], *end;
        acbb_scene_field_format(s, i, buf, sizeof buf);
        double v = strtod(buf, &end);
        if (end == buf || !isfinite(v))
            return broken(why, n, "accepted scene has %s = %s", fi->key, buf);
    }
    acbb_error err = { { 0 } };
    if (acbb_scene_validate(s, &err) != ACBB_OK)
        return broken(why, n, "accepted scene fails validation: %s%s", err.msg, "");
    return ACBB_FUZZ_ACCEPTED;
}

/* A refusal must say why, with a failure status. */
static acbb_fuzz_outcome check_refusal(acbb_status st, const acbb_error *err, const char *what,
                                       char *why, size_t n)
{
    if (st == ACBB_OK) return ACBB_FUZZ_ACCEPTED;
    if (err->msg[0] == '\0') return broken(why, n, "%s refused with an empty message%s", what, "");
    if (!memchr(err->msg, '\0', sizeof err->msg))
        return broken(why, n, "%s: message not terminated%s", what, "");
    if (st != ACBB_EINVAL && st != ACBB_EIO && st != ACBB_ILL_POSED)
        return broken(why, n, "%s refused with status %s", what, acbb_status_name(st));
    snprintf(why, n, "%s", err->msg);
    return ACBB_FUZZ_REJECTED;
}

acbb_fuzz_outcome acbb_fuzz_preset(const uint8_t *data, size_t size, char *why, size_t n)
{
    if (tmp_open() != 0 || ftruncate(tmp_fd, 0) != 0)
        return broken(why, n, "cannot write the temporary file %s%s", tmp_path, "");
    size_t done = 0;
    while (done < size) {
        ssize_t w = pwrite(tmp_fd, data + done, size - done, (off_t)done);
        if (w <= 0) return broken(why, n, "cannot write the temporary file %s%s", tmp_path, "");
        done += (size_t)w;
    }
    acbb_scene s;
    acbb_error err = { { 0 } };
    acbb_status st = acbb_scene_load(tmp_path, &s, &err);
    acbb_fuzz_outcome o = check_refusal(st, &err, "preset", why, n);
    return o == ACBB_FUZZ_ACCEPTED ? check_scene(&s, why, n) : o;
}

#define MAX_EDITS 16

/* Each edit alone: split at the first '=' as `acbb_scene_set KEY VALUE`. */
static acbb_fuzz_outcome set_one(const char *edit, char *why, size_t n)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", edit);
    char *eq = strchr(buf, '=');
    const char *value = "";
    if (eq) {
        *eq = '\0';
        value = eq + 1;
    }
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_error err = { { 0 } };
    acbb_fuzz_outcome o = check_refusal(acbb_scene_set(&s, buf, value, &err), &err,
                                        "acbb_scene_set", why, n);
    return o == ACBB_FUZZ_ACCEPTED ? check_scene(&s, why, n) : o;
}

acbb_fuzz_outcome acbb_fuzz_set(const uint8_t *data, size_t size, char *why, size_t n)
{
    char *text = malloc(size + 1);
    if (!text) return ACBB_FUZZ_REJECTED;
    memcpy(text, data, size);
    text[size] = '\0';
    const char *edits[MAX_EDITS];
    size_t k = 0;
    for (char *line = text, *next; line && k < MAX_EDITS; line = next) {
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        edits[k++] = line;
    }
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_error err = { { 0 } };
    acbb_fuzz_outcome o = check_refusal(acbb_scene_apply_edits(&s, edits, k, &err), &err,
                                        "--set batch", why, n);
    if (o == ACBB_FUZZ_ACCEPTED) o = check_scene(&s, why, n);
    for (size_t i = 0; i < k && o != ACBB_FUZZ_BROKEN; i++) {
        char one_why[1024];
        if (set_one(edits[i], one_why, sizeof one_why) == ACBB_FUZZ_BROKEN) {
            snprintf(why, n, "edit %zu alone: %s", i + 1, one_why);
            o = ACBB_FUZZ_BROKEN;
        }
    }
    free(text);
    return o;
}

/* One row's text: refused with a message, or finite and exact in print. */
static acbb_fuzz_outcome schedule_row(const char *text, acbb_scene *s, char *why, size_t n)
{
    acbb_schedule_row r;
    acbb_error err = { { 0 } };
    acbb_fuzz_outcome o = check_refusal(acbb_schedule_parse_row(text, &r, &err), &err,
                                        "schedule row", why, n);
    if (o != ACBB_FUZZ_ACCEPTED) return o;
    if (!isfinite(r.t) || !isfinite(r.inner_speed) || !isfinite(r.axial_load) ||
        !isfinite(r.radial_load))
        return broken(why, n, "accepted row \"%s\" has a non-finite value%s", text, "");
    if (s->schedule_n >= ACBB_SCHEDULE_MAX) return ACBB_FUZZ_ACCEPTED;
    s->schedule[s->schedule_n++] = r;
    char back[256];
    acbb_schedule_row again;
    acbb_schedule_format_row(s, s->schedule_n - 1, back, sizeof back);
    /* == (not the bits): -0 prints as 0, the same value */
    if (acbb_schedule_parse_row(back, &again, &err) != ACBB_OK || again.t != r.t ||
        again.inner_speed != r.inner_speed || again.axial_load != r.axial_load ||
        again.radial_load != r.radial_load)
        return broken(why, n, "row \"%s\" prints as \"%s\", which reads back otherwise", text,
                      back);
    return ACBB_FUZZ_ACCEPTED;
}

acbb_fuzz_outcome acbb_fuzz_schedule(const uint8_t *data, size_t size, char *why, size_t n)
{
    char *text = malloc(size + 1);
    if (!text) return ACBB_FUZZ_REJECTED;
    memcpy(text, data, size);
    text[size] = '\0';
    acbb_scene s;
    acbb_scene_default(&s);
    s.schedule_n = 0;
    acbb_fuzz_outcome o = ACBB_FUZZ_ACCEPTED;
    int lines = 0;
    for (char *line = text, *next; line && o == ACBB_FUZZ_ACCEPTED
                                   && lines < ACBB_SCHEDULE_MAX; line = next, lines++) {
        next = strchr(line, '\n');
        if (next) *next++ = '\0';
        if (!*line && !next && lines > 0) break; /* the text's last newline */
        o = schedule_row(line, &s, why, n);
    }
    free(text);
    if (o != ACBB_FUZZ_ACCEPTED) return o;
    acbb_error err = { { 0 } };
    o = check_refusal(acbb_scene_validate(&s, &err), &err, "schedule", why, n);
    return o == ACBB_FUZZ_ACCEPTED ? check_scene(&s, why, n) : o;
}
