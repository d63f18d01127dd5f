/* acbb fuzzing — the entry points shared by the libFuzzer harnesses
 * (fuzz_preset.c, fuzz_set.c, built with clang -Dfuzz=true) and the plain
 * corpus replay in the default test suite (tests/test_fuzz_replay.c).
 *
 * Each feeds one input to the scene layer's public API and checks what
 * the issue "Nothing lost, nothing overwritten, nothing hangs" asks of it:
 * a rejected input gets a failure status and a non-empty message, an
 * accepted one gives a scene whose every value is finite and which passes
 * acbb_scene_validate. `why` gets the refusal's message, or for
 * ACBB_FUZZ_BROKEN the invariant that failed. */
#ifndef ACBB_FUZZ_ENTRY_H
#define ACBB_FUZZ_ENTRY_H

#include <stddef.h>
#include <stdint.h>

typedef enum {
    ACBB_FUZZ_ACCEPTED = 0,   /* a valid scene came out */
    ACBB_FUZZ_REJECTED = 1,   /* refused with a message */
    ACBB_FUZZ_BROKEN = -1     /* an invariant failed; `why` says which */
} acbb_fuzz_outcome;

/* The input as a preset file (written to a private temporary file, then
 * acbb_scene_load). */
acbb_fuzz_outcome acbb_fuzz_preset(const uint8_t *data, size_t size, char *why, size_t n);

/* The input as `--set` edits, one per line (at most 16): the batch through
 * acbb_scene_apply_edits, then each one alone through acbb_scene_set. */
acbb_fuzz_outcome acbb_fuzz_set(const uint8_t *data, size_t size, char *why, size_t n);

/* The input as `row = ` values of a [schedule], one row per line (at most
 * ACBB_SCHEDULE_MAX; more are not read): each through acbb_schedule_parse_row (an
 * accepted row is finite and prints back, acbb_schedule_format_row, to
 * text that reads as the very same doubles), then the accepted rows as
 * the 7008C scene's schedule through acbb_scene_validate (an accepted
 * schedule is a valid scene; a refused one names its row). */
acbb_fuzz_outcome acbb_fuzz_schedule(const uint8_t *data, size_t size, char *why, size_t n);

/* The temporary file acbb_fuzz_preset loads (a refusal names it). */
const char *acbb_fuzz_preset_path(void);

/* Remove the temporary file (call once at the end). */
void acbb_fuzz_cleanup(void);

#endif
