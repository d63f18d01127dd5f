/* acbb — what the parts of the scene layer share (private to src/scene*.c).
 *
 * scene_schema.c  the schema table, defaults, field access, formatting,
 *                 ranges (acbb_scene_field*, `acbb keys`)
 * scene_value.c   key lookup, suggestions, value parsing, acbb_scene_set*
 * scene_rules.c   cross-field validation (acbb_scene_validate)
 * scene_io.c      INI load and full save
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
#define ACBB_SF_MAX 160
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

/* The row of section.key, or NULL. */
const acbb_sfield *acbb_sf_find(const char *section, const char *key);
/* Message for a key that is not in the schema ("section.key: ..."). */
acbb_status acbb_sf_unknown_key(const char *section, const char *key, acbb_error *err);
/* Parse `text` (preset units) into field f of s; s untouched on failure. */
acbb_status acbb_sf_apply(acbb_scene *s, const acbb_sfield *f, const char *text, acbb_error *err);

#endif
