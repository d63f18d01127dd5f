/* acbb — what the parts of the scene layer share (private to src/scene*.c).
 *
 * scene_schema.c  the schema table, defaults, field access, formatting,
 *                 ranges (acbb_scene_field*, `acbb keys`)
 * scene_value.c   key lookup, suggestions, value parsing, acbb_scene_set*
 * scene_rules.c   cross-field validation (acbb_scene_validate)
 * scene_io.c      INI parsing, load and full save
 * scene_edit.c    saving into an existing file, keeping the user's lines
 * physics_profile.c the profiles' table (which keys physics.profile sets)
 * scene_schema_spindle.h the spindle's rows of the table ([shaft] ...)
 * scene_rules_spindle.c the spindle's cross-field rules and unused keys
 *
 * ONE table (acbb_sf_table) describes every preset key: section, key (unit
 * in the name), type, unit, where the value lives in acbb_scene, the factor
 * to SI, the default and the allowed range in preset units, enum choices
 * and a help line. Defaults, parsing, range checks, saving, acbb_scene_set
 * and the TUI editor all read that table, so a key cannot be parsed one way
 * and saved another. */
#ifndef ACBB_SCENE_INTERNAL_H
#define ACBB_SCENE_INTERNAL_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/scene.h"
#include "acbb/tools/scene_inactive.h"
#include "acbb/tools/scene_schema.h"

/* Range ends: closed (inclusive) or open (exclusive, "must be > 0"). */
enum { CC, OC, CO, OO };

typedef struct {
    acbb_field_info info;   /* public part, handed out by acbb_scene_field */
    size_t off;             /* offsetof the member in acbb_scene */
    double scale;           /* value_SI = value_preset * scale */
    double def;             /* default in preset units (enum: index, bool: 0/1) */
    int ends;               /* CC, OC, CO or OO */
} acbb_sfield;

/* The schema, and how many rows it has (at most ACBB_SF_MAX). */
#define ACBB_SF_MAX 256
extern const acbb_sfield acbb_sf_table[];
extern const size_t acbb_sf_n;

/* Raw access through the table (memcpy: no type punning). */
double acbb_sf_get_real(const acbb_scene *s, const acbb_sfield *f);
int acbb_sf_get_int(const acbb_scene *s, const acbb_sfield *f);
/* Store a value given in preset units (enum: index, bool: 0/1). */
void acbb_sf_put(acbb_scene *s, const acbb_sfield *f, double v);
size_t acbb_sf_n_choices(const acbb_sfield *f);

/* Why v (preset units) is out of f's range; "" if it is inside. */
void acbb_sf_range_reason(const acbb_sfield *f, double v, char *buf, size_t n);
/* 1 when v (SI units) is outside f's range: the scene rules' test of every
 * field, without the reason's text or a scaled copy of the row. */
int acbb_sf_out_of_range_si(const acbb_sfield *f, double v);

/* The row of section.key, or NULL. */
const acbb_sfield *acbb_sf_find(const char *section, const char *key);
/* Message for a key that is not in the schema ("section.key: ..."). */
acbb_status acbb_sf_unknown_key(const char *section, const char *key, acbb_error *err);
/* Parse `text` (preset units) into field f of s; s untouched on failure. */
acbb_status acbb_sf_apply(acbb_scene *s, const acbb_sfield *f, const char *text, acbb_error *err);

/* Distinct schema sections, in table order ("bearing", "materials", ...). */
#define ACBB_SF_SECTIONS_MAX 20
size_t acbb_sf_section_count(void);
const char *acbb_sf_section_name(size_t k);
/* Index of a schema section, or -1. */
int acbb_sf_section_index(const char *name);

/* Rewrite err->msg with control characters (and UTF-8 C1 controls) shown as
 * \xNN, so that file or command-line text quoted in a message cannot drive
 * the terminal. Safe with err == NULL. */
void acbb_sf_escape_msg(acbb_error *err);

/* What a preset file says, before the cross-field rules. */
typedef struct {
    acbb_scene scene;              /* defaults, then every key of the file */
    int n_keys;
    int first_line[ACBB_SF_MAX];   /* line of each key, 0 = not in the file */
    int section_end[ACBB_SF_SECTIONS_MAX]; /* last line (header or key) of the
                                      section's last occurrence, 0 = absent */
    int schedule_line[ACBB_SCHEDULE_MAX]; /* line of each [schedule] row */
    int schedule_end;              /* last line of the last [schedule], 0 = absent */
} acbb_sf_parsed;

/* Open a preset for reading: refuses (ACBB_EIO, with the reason) anything
 * but a regular file, without blocking on a FIFO. */
FILE *acbb_sf_open_preset(const char *path, acbb_error *err);

/* Parse an open preset stream (`path` names it in messages): syntax, keys
 * and each key's own range, not the cross-field rules, not emptiness. */
acbb_status acbb_sf_parse(FILE *f, const char *path, acbb_sf_parsed *out, acbb_error *err);

/* acbb_schedule_validate (schedule.c), also saying which row failed (0-based;
 * -1: none), so that a file's message can name the row's line. */
acbb_status acbb_sf_schedule_check(const acbb_scene *s, int *row, acbb_error *err);

/* `schedule.rows = t_s, speed_rpm, axial_N, radial_N; ...` (every row at
 * once, ';' between rows; "" = no schedule) as acbb_scene_set* take it;
 * cross_check: the scene's rules too. `s` unchanged on failure. */
acbb_status acbb_sf_schedule_set(acbb_scene *s, const char *key, const char *value,
                                 int cross_check, acbb_error *err);

/* physics_profile.c: the profile table's row of field f, or -1; a default
 * scene with profile p's values in its table's keys (what "the default" of
 * a key means under p, for saving into a user's file), physics.profile
 * itself at its own default, seed. */
int acbb_sf_profile_row(const acbb_sfield *f);
const acbb_sfield *acbb_sf_profile_field(size_t k);   /* row k's field, NULL past the end */
void acbb_sf_profile_defaults(acbb_scene *d, acbb_physics_profile p);
/* section.key is not a key of the profile table, or its value is not the
 * one s->profile gives it (the user's own choice, not the profile's). */
bool acbb_sf_profile_own(const acbb_scene *s, const char *section, const char *key);

/* scene_rules.c: section.key's current value in preset units, for
 * messages (buf >= 40 bytes). */
const char *acbb_sf_show(const acbb_scene *s, const char *section, const char *key, char *buf);

/* scene_rules_spindle.c: the spindle's cross-field rules (nothing to check
 * when shaft.segments = 0), and its keys that do nothing in scene s
 * (d: the defaults), appended by acbb_scene_inactive_effects. */
acbb_status acbb_sf_spindle_rules(const acbb_scene *s, acbb_error *err);
size_t acbb_sf_spindle_inactive(const acbb_scene *s, const acbb_scene *d,
                                acbb_inactive_effect *out, size_t cap);

/* The whole preset, every key with its help and range (acbb_scene_save). */
int acbb_sf_write_preset(FILE *f, const acbb_scene *s);

#endif
