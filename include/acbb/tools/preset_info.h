/* acbb — what a preset says about itself, for the teaching library: its
 * header comment holds a title (the first paragraph), a "Look at:"
 * paragraph (what to watch, for `acbb presets` and the TUI) and an
 * "Expect: STATUS" line (the run's documented end: converged, runaway, ...;
 * tests/test_presets.sh holds every shipped preset to it).
 *
 * Ownership: a plain value the caller owns. */
#ifndef ACBB_PRESET_INFO_H
#define ACBB_PRESET_INFO_H

#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    char title[512];     /* the first paragraph joined into one line, "" if none */
    char look_at[1024];  /* the "Look at:" paragraph joined into one line, "" if none */
    char expect[32];     /* the status after "Expect:", "" if none */
} acbb_preset_info;

/* Read the leading comment block of a preset file (stops at the first
 * line that is not a comment or blank). ACBB_EIO if the file cannot be
 * read; a preset without the lines gives empty fields and ACBB_OK. */
acbb_status acbb_preset_info_read(const char *path, acbb_preset_info *out, acbb_error *err);

#ifdef __cplusplus
}
#endif

#endif
