/* acbb — which inputs of a scene do nothing (src/scene/scene_rules.c):
 * effect switches that are on but inactive at the scene's model level or
 * under another switch, and keys of parts its network does not have. The
 * CLI warns, the TUI marks them in its editor, the run JSON lists them. */
#ifndef ACBB_TOOLS_SCENE_INACTIVE_H
#define ACBB_TOOLS_SCENE_INACTIVE_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Effect switches that are on but do nothing in this scene (at its model
 * level, or because another switch overrides them), and set inputs the
 * scene's network does not have: the name (the [effects] key, or the part),
 * the key as the user would write it, and why; static strings; at most `cap`
 * of them; returns how many. A client says so instead of ignoring the input
 * silently. */
typedef struct {
    const char *effect;
    const char *why;
    const char *key;       /* "effects.centrifugal = on", "surroundings.cap_*" */
} acbb_inactive_effect;
size_t acbb_scene_inactive_effects(const acbb_scene *s, acbb_inactive_effect *out, size_t cap);

/* Whether the preset key "section.key" ("mounting.preload_N") has no effect
 * in scene s: true with the row that says why (and which key makes it act)
 * in *out (may be NULL). For a what-if line or an editor mark. */
bool acbb_scene_key_inactive(const acbb_scene *s, const char *key, acbb_inactive_effect *out);

#ifdef __cplusplus
}
#endif

#endif
