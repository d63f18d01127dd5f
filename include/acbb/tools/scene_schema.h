/* acbb — the preset's key table as editors and help show it
 * (src/scene/scene_schema.c): each key's section, name, unit, type, range,
 * choices, help and plausible range, a scene's value of it as text, and
 * the names of a model level. For the TUI editor, `acbb keys`, the sweeps
 * and the sensitivity analysis; a program sets a key by name with
 * acbb_scene_set (scene.h) and needs none of this. */
#ifndef ACBB_TOOLS_SCENE_SCHEMA_H
#define ACBB_TOOLS_SCENE_SCHEMA_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { ACBB_FIELD_REAL, ACBB_FIELD_INT, ACBB_FIELD_BOOL,
               ACBB_FIELD_ENUM } acbb_field_type;

typedef struct {
    const char *section;     /* "bearing" */
    const char *key;         /* "ball_diameter_mm" (unit in the name) */
    acbb_field_type type;
    const char *unit;        /* "mm", "rpm", "" */
    double min, max;         /* allowed range in preset units; an end is
                                included unless min_open / max_open */
    const char *const *choices; /* NULL-terminated, for ENUM */
    const char *help;        /* one line */
    bool min_open, max_open; /* true: that end is excluded (x > min, x < max) */
    /* Plausible range of an uncertain input (MODEL.md ASSUMED / UNSURE items
     * and the surroundings), separate from the validation range above and
     * inside it: what `acbb sensitivity` varies. plaus_src NULL: the key is
     * not an uncertain input. REAL: preset units; ENUM: two choice indices
     * (a two-level factor, e.g. fixed vs convective). plaus_src cites where
     * the range comes from ("MODEL.md 5 ASSUMED 0.08-0.13"). */
    double plaus_lo, plaus_hi;
    const char *plaus_src;
} acbb_field_info;

size_t acbb_scene_field_count(void);
const acbb_field_info *acbb_scene_field(size_t i);
/* Current value of field i, formatted in preset units (buf >= 64 bytes). */
void acbb_scene_field_format(const acbb_scene *s, size_t i, char *buf, size_t n);
/* Allowed values of field i as text (buf >= 160 bytes), e.g.
 * "0 < x <= 100 mm", "on | off", "static | quasi-static | ...". Says which
 * range ends are exclusive, which acbb_field_info cannot. */
void acbb_scene_field_range(size_t i, char *buf, size_t n);

/* The same as an interval, as the check applies it (for `acbb keys`):
 * "(0, 100] mm", "[3, 64]", "on | off", "static | quasi-static | ...". */
void acbb_scene_field_interval(size_t i, char *buf, size_t n);

/* Field i's plausible range as text (buf >= 160 bytes), e.g.
 * "[0.08, 0.13]; MODEL.md 5 ASSUMED 0.08-0.13" or "fixed | convective;
 * ..."; "" when the key is not an uncertain input. */
void acbb_scene_field_plausible(size_t i, char *buf, size_t n);

/* Whether field i is no input of scene s: a spindle key of a scene
 * without a spindle, or of a part its spindle does not have (the motor's
 * losses without a motor, the coolant's keys without a flow, the spring's
 * force under another rear support, ...; src/scene/scene_rules_spindle.c).
 * The sensitivity analysis varies only the inputs a scene has. */
bool acbb_scene_field_unused(const acbb_scene *s, size_t i);

const char *acbb_model_level_name(acbb_model_level m);

#ifdef __cplusplus
}
#endif

#endif
