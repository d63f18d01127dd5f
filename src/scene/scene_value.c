/* acbb — scene values: key lookup with suggestions, value parsing, and the
 * acbb_scene_set / set_value / apply_edits entry points. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "acbb/tools/physics_profile.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"
#include "c_locale.h"

/* ---- key lookup and suggestions ---- */

const acbb_sfield *acbb_sf_find(const char *section, const char *key)
{
    for (size_t i = 0; i < acbb_sf_n; i++)
        if (strcmp(acbb_sf_table[i].info.section, section) == 0 &&
            strcmp(acbb_sf_table[i].info.key, key) == 0)
            return &acbb_sf_table[i];
    return NULL;
}

static bool section_known(const char *section)
{
    for (size_t i = 0; i < acbb_sf_n; i++)
        if (strcmp(acbb_sf_table[i].info.section, section) == 0) return true;
    return false;
}

#define EDIT_MAX 128

/* Levenshtein distance (two-row dynamic programme); hand-written because no
 * library at hand offers it and the strings are short. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la >= EDIT_MAX || lb >= EDIT_MAX) return (size_t)-1;
    size_t prev[EDIT_MAX], cur[EDIT_MAX];
    for (size_t j = 0; j <= lb; j++) prev[j] = j;
    for (size_t i = 1; i <= la; i++) {
        cur[0] = i;
        for (size_t j = 1; j <= lb; j++) {
            size_t del = prev[j] + 1, ins = cur[j - 1] + 1;
            size_t sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            size_t m = del < ins ? del : ins;
            cur[j] = m < sub ? m : sub;
        }
        memcpy(prev, cur, (lb + 1) * sizeof prev[0]);
    }
    return prev[lb];
}

/* Nearest schema key to `name`: compared with "section.key" when
 * `dotted`, else with the bare key. NULL if nothing is reasonably close. */
static const acbb_sfield *nearest_field(const char *name, bool dotted)
{
    const acbb_sfield *best = NULL;
    size_t best_d = (size_t)-1;
    for (size_t i = 0; i < acbb_sf_n; i++) {
        char full[EDIT_MAX];
        snprintf(full, sizeof full, "%s.%s", acbb_sf_table[i].info.section, acbb_sf_table[i].info.key);
        size_t d = edit_distance(name, dotted ? full : acbb_sf_table[i].info.key);
        if (d < best_d) {
            best_d = d;
            best = &acbb_sf_table[i];
        }
    }
    return best_d <= 2 + strlen(name) / 4 ? best : NULL;
}

/* " (did you mean section.key?)" or "". */
static void suggestion(const char *name, bool dotted, char *buf, size_t n)
{
    const acbb_sfield *f = nearest_field(name, dotted);
    if (f)
        snprintf(buf, n, " (did you mean %s.%s?)", f->info.section, f->info.key);
    else
        buf[0] = '\0';
}

/* Message for a key that is not in the schema ("section.key: ..."). */
acbb_status acbb_sf_unknown_key(const char *section, const char *key, acbb_error *err)
{
    char name[2 * EDIT_MAX], hint[160];
    snprintf(name, sizeof name, "%s.%s", section, key);
    if (section[0] == '\0') {
        suggestion(key, false, hint, sizeof hint);
        return acbb_error_set(err, ACBB_EINVAL, "%s: key outside any [section]%s", key, hint);
    }
    suggestion(name, true, hint, sizeof hint);
    if (!section_known(section))
        return acbb_error_set(err, ACBB_EINVAL, "%s: unknown section [%s]%s", name, section,
                              hint);
    return acbb_error_set(err, ACBB_EINVAL, "%s: unknown key%s", name, hint);
}

/* ---- value parsing ---- */

static bool word_eq(const char *a, const char *b)
{
    return strcasecmp(a, b) == 0;
}

/* Copy `text` without surrounding blanks (inih trims, acbb_scene_set may
 * not); false if it does not fit. */
static bool trim_copy(const char *text, char *out, size_t n)
{
    while (isspace((unsigned char)*text)) text++;
    size_t len = strlen(text);
    while (len > 0 && isspace((unsigned char)text[len - 1])) len--;
    bool fits = len < n;
    if (!fits) len = n - 1;
    memcpy(out, text, len);
    out[len] = '\0';
    return fits;
}

static acbb_status reason(char *why, size_t n, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static acbb_status reason(char *why, size_t n, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, n, fmt, ap);
    va_end(ap);
    return ACBB_EINVAL;
}

static acbb_status parse_number(const acbb_sfield *f, const char *t, double *out, char *why, size_t n)
{
    char *end;
    if (t[0] == '\0') return reason(why, n, "missing value");
    /* strtod also reads C99 hexadecimal ("0x10" = 16, "0x1p4"); a preset
     * holds decimal numbers only, so "0x10" is not silently sixteen. */
    const char *digits = t + (t[0] == '+' || t[0] == '-');
    if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'))
        return reason(why, n, "decimal numbers only (hexadecimal like 0x10 is not accepted)");
    double v = acbb_strtod_c(t, &end);
    if (end == t) return reason(why, n, "not a number");
    if (*end != '\0')
        return reason(why, n, "not a number (unexpected \"%s\" after %.*s)", end,
                      (int)(end - t), t);
    if (!isfinite(v)) return reason(why, n, "must be a finite number");
    if (f->info.type == ACBB_FIELD_INT && v != floor(v))
        return reason(why, n, "must be a whole number");
    acbb_sf_range_reason(f, v, why, n);
    if (why[0]) return ACBB_EINVAL;
    *out = v;
    return ACBB_OK;
}

static acbb_status parse_bool(const char *t, double *out, char *why, size_t n)
{
    static const char *const yes[] = {"on", "true", "yes", "1"}, *const no[] = {"off", "false", "no", "0"};
    for (size_t i = 0; i < 4; i++) {
        if (word_eq(t, yes[i]) || word_eq(t, no[i])) {
            *out = word_eq(t, yes[i]);
            return ACBB_OK;
        }
    }
    return reason(why, n, "must be on or off (or true/false, yes/no, 1/0)");
}

static acbb_status parse_enum(const acbb_sfield *f, const char *t, double *out, char *why, size_t n)
{
    size_t used = (size_t)snprintf(why, n, "must be one of: ");
    for (size_t c = 0; f->info.choices[c]; c++) {
        if (word_eq(t, f->info.choices[c])) {
            *out = (double)c;
            return ACBB_OK;
        }
        if (used < n)
            used += (size_t)snprintf(why + used, n - used, "%s%s", c ? ", " : "",
                                     f->info.choices[c]);
    }
    return ACBB_EINVAL;
}

/* Parse `text` (preset units) into field f of s. s is untouched on failure;
 * the message is "section.key = text: reason". */
acbb_status acbb_sf_apply(acbb_scene *s, const acbb_sfield *f, const char *text, acbb_error *err)
{
    char t[256], why[256];
    double v = 0.0;
    acbb_status rc;
    if (!trim_copy(text, t, sizeof t))
        return acbb_error_set(err, ACBB_EINVAL, "%s.%s: value too long", f->info.section,
                              f->info.key);
    switch (f->info.type) {
    case ACBB_FIELD_BOOL: rc = parse_bool(t, &v, why, sizeof why); break;
    case ACBB_FIELD_ENUM: rc = parse_enum(f, t, &v, why, sizeof why); break;
    default: rc = parse_number(f, t, &v, why, sizeof why); break;
    }
    if (rc != ACBB_OK)
        return acbb_error_set(err, rc, "%s.%s = %s: %s", f->info.section, f->info.key, t, why);
    acbb_sf_put(s, f, v);
    return ACBB_OK;
}

/* ---- acbb_scene_set ---- */

/* A key of the profile table set explicitly is the user's from now on; a
 * new physics.profile moves the keys not given (physics_profile.h). */
static void note_profile(acbb_scene *s, const acbb_sfield *f)
{
    int row = acbb_sf_profile_row(f);
    if (row >= 0) s->profile_given |= 1u << row;
    if (f == acbb_sf_find("physics", "profile")) acbb_profile_apply(s);
}

static acbb_status set_one_raw(acbb_scene *s, const char *dotted_key, const char *value,
                               int cross_check, acbb_error *err)
{
    char section[EDIT_MAX], hint[160];
    const char *dot = strchr(dotted_key, '.');
    if (!dot) {
        suggestion(dotted_key, false, hint, sizeof hint);
        return acbb_error_set(err, ACBB_EINVAL, "%s: expected section.key%s", dotted_key, hint);
    }
    size_t len = (size_t)(dot - dotted_key);
    if (len >= sizeof section) len = sizeof section - 1;
    memcpy(section, dotted_key, len);
    section[len] = '\0';
    if (strcmp(section, "schedule") == 0)   /* schedule.rows (schedule.c) */
        return acbb_sf_schedule_set(s, dot + 1, value, cross_check, err);
    const acbb_sfield *f = acbb_sf_find(section, dot + 1);
    if (!f) return acbb_sf_unknown_key(section, dot + 1, err);

    acbb_scene trial = *s;
    acbb_status rc = acbb_sf_apply(&trial, f, value, err);
    if (rc == ACBB_OK) note_profile(&trial, f);
    if (rc == ACBB_OK && cross_check) rc = acbb_scene_validate(&trial, err);
    if (rc == ACBB_OK) *s = trial;
    return rc;
}

/* Every message quotes the caller's text: shown escaped. */
static acbb_status set_one(acbb_scene *s, const char *dotted_key, const char *value,
                           int cross_check, acbb_error *err)
{
    acbb_status rc = set_one_raw(s, dotted_key, value, cross_check, err);
    if (rc != ACBB_OK) acbb_sf_escape_msg(err);
    return rc;
}

acbb_status acbb_scene_set(acbb_scene *s, const char *dotted_key, const char *value,
                           acbb_error *err)
{
    return set_one(s, dotted_key, value, 1, err);
}

acbb_status acbb_scene_set_value(acbb_scene *s, const char *dotted_key, const char *value,
                                 acbb_error *err)
{
    return set_one(s, dotted_key, value, 0, err);
}

acbb_status acbb_scene_apply_edits(acbb_scene *s, const char *const *edits, size_t n,
                                   acbb_error *err)
{
    acbb_scene trial = *s;
    for (size_t i = 0; i < n; i++) {
        const char *text = edits[i], *eq = strchr(text, '=');
        char key[EDIT_MAX];
        if (!eq || eq == text || (size_t)(eq - text) >= sizeof key) {
            acbb_error_set(err, ACBB_EINVAL, "%s: expected section.key=value", text);
            acbb_sf_escape_msg(err);
            return ACBB_EINVAL;
        }
        memcpy(key, text, (size_t)(eq - text));
        key[eq - text] = '\0';
        acbb_error e = { "" };
        acbb_status rc = set_one(&trial, key, eq + 1, 0, &e);
        if (rc != ACBB_OK) {
            acbb_error_set(err, rc, "%s: %s", text, e.msg);
            acbb_sf_escape_msg(err);
            return rc;
        }
    }
    /* Cross-field rules once, on the scene as a whole. */
    acbb_status rc = acbb_scene_validate(&trial, err);
    if (rc == ACBB_OK) *s = trial;
    return rc;
}

void acbb_sf_escape_msg(acbb_error *err)
{
    if (!err) return;
    char in[sizeof err->msg];
    memcpy(in, err->msg, sizeof in);
    in[sizeof in - 1] = '\0';
    size_t o = 0, cap = sizeof err->msg;
    for (const unsigned char *p = (const unsigned char *)in; *p; p++) {
        /* C0 controls, DEL, and C1 controls as UTF-8 (0xc2 0x80..0x9f). */
        bool c1 = p[0] == 0xc2 && p[1] >= 0x80 && p[1] <= 0x9f;
        if (*p < 0x20 || *p == 0x7f || c1) {
            size_t len = c1 ? 8 : 4;
            if (o + len >= cap) break;
            if (c1) snprintf(err->msg + o, cap - o, "\\xc2\\x%02x", p[1]);
            else snprintf(err->msg + o, cap - o, "\\x%02x", *p);
            p += c1;
            o += len;
        } else {
            if (o + 1 >= cap) break;
            err->msg[o++] = (char)*p;
        }
    }
    err->msg[o] = '\0';
}
