/* acbb fuzzing — entry points into the CLI's readers of user files (issue
 * 20 item 10, issue 26): `acbb merge` inputs, a resumed sweep's file and
 * the `--baseline` JSON. Same
 * outcomes as fuzz_entry.h. Harness state (temporary files, one baseline
 * run) lives in fuzz_cli.c, never in the engine. */
#ifndef ACBB_FUZZ_CLI_H
#define ACBB_FUZZ_CLI_H

#include "fuzz_entry.h"

/* The input as one merge input file (then, when accepted, its output merged
 * again): exit 0 or 2 only; an accepted merge is canonical (its output is
 * accepted again, so every number is finite, and gives the same bytes). */
acbb_fuzz_outcome acbb_fuzz_merge(const uint8_t *data, size_t size, char *why, size_t n);

/* The input as an existing output of one fixed sweep (fuzz_cli.c), opened
 * as `acbb sweep` resumes it (lock, resume, header; no point run): exit 0
 * or 2 only; refused: the file untouched; accepted: the file ends with a
 * whole line and a second resume finds the same records and changes no
 * byte (what a writer left unfinished was cut, the header written). */
acbb_fuzz_outcome acbb_fuzz_resume(const uint8_t *data, size_t size, char *why, size_t n);

/* The input as the --baseline file of a quasi-static 7008C run: exit 0 or 2
 * only, no inf/nan in the text table or the JSON. */
acbb_fuzz_outcome acbb_fuzz_baseline(const uint8_t *data, size_t size, char *why, size_t n);

#endif
