/* acbb — one stable entry point for any language's FFI (Python ctypes,
 * cffi, Julia ccall, ...): preset text and "section.key=value" settings in,
 * the run's JSON out. Only C strings cross the boundary; no acbb struct
 * does, so the entry point stays stable while the structs grow.
 *
 * acbb_run_preset_json runs the scene to the end exactly as
 * `acbb run PRESET --set S1 --set S2 ... --json` does (the same loading and
 * checks, the fidelity preset applied, the same run loop, the other branch
 * solved for a scene that wants it, acbb/tools/branches.h) and returns the
 * document that command prints, byte for byte (test `python` compares
 * every preset's); only wall_ms, the run's wall time, differs between any
 * two runs.
 *
 * - preset_text: the preset's content (INI text, NUL-terminated), not a
 *   path. Messages name it "<text>" ("<text>:3: ...").
 * - settings: n_settings strings "section.key=value" in preset units, as
 *   the CLI's --set takes them (NULL when n_settings is 0); checked and
 *   applied after the text, as a whole (acbb_scene_apply_edits).
 * - Returns a JSON object as a NUL-terminated string (ASCII, or UTF-8
 *   quoted from the input). It always has "schema_version" first, then
 *   "status" and "message" strings (docs/schema/acbb.schema.json):
 *   - the run started: the full run document (acbb/tools/json.h,
 *     acbb_json_write_run); status "converged", or how the run failed
 *     ("not_converged", "runaway", ...) with the reason in message;
 *   - the scene could not be compiled: status, message, "iterations": 0
 *     and "scene" (acbb_json_write_failed);
 *   - bad input (text or a setting): {"schema_version": N, "status":
 *     "bad_input", "message": ...} with the engine's message, e.g.
 *     "operating.axial_load_N=-5: ..." for a setting (the CLI prefixes it with "--set "); a scene
 *     the rules find ill-posed as it loads is bad_input too, as the CLI
 *     names it, with *status ACBB_ILL_POSED.
 *   No number in it is NaN or Inf: one would be written as null and
 *   *status set to ACBB_NONFINITE (an internal error, as the CLI's exit
 *   status reports it; the document stays the one the CLI prints).
 * - Ownership: the string is the caller's; free it with acbb_string_free
 *   (not free(): the caller's runtime may not share this allocator).
 *   NULL is returned only when memory runs out.
 * - *status (may be NULL): ACBB_OK when the run converged, else the
 *   acbb_status (status.h) that the "status" string names: ACBB_EINVAL for
 *   bad input (ACBB_ILL_POSED for an ill-posed one), the run's final
 *   status for a failed run (ACBB_NONFINITE and ACBB_ENOMEM as said
 *   above).
 * - Thread-safety: reentrant; calls on different threads are independent
 *   (the engine keeps no global mutable state but GSL's process-wide error
 *   handler, which it turns off while a call works and gives back to the
 *   host when the last call ends; acbb/sim.h). A call blocks until its
 *   run ends (milliseconds to seconds) or acbb_run_preset_json_ctl's
 *   cancel flag is set. Nothing is printed.
 * - Numbers are read and written with a decimal point whatever locale the
 *   host set (setlocale(LC_ALL, "") under de_DE included): the engine
 *   reads and prints them in the "C" locale on the calling thread only. */
#ifndef ACBB_FFI_H
#define ACBB_FFI_H

#include <stddef.h>
#include "acbb/cancel_flag.h"

#ifdef __cplusplus
extern "C" {
#endif

char *acbb_run_preset_json(const char *preset_text, const char *const *settings,
                           size_t n_settings, int *status);

/* acbb_run_preset_json with two controls (issue 28 items 2 and 4):
 * - the text is text_len bytes (no terminator needed), so a NUL byte in
 *   it is refused as `acbb run` refuses it in a file ("<text>:2: NUL byte
 *   in line 2 (a preset is plain text)", bad_input), not taken as the end;
 * - cancel (may be NULL): the caller sets it (nonzero, from any thread or
 *   a signal handler) to stop the run, as Ctrl-C stops `acbb run`: the
 *   call returns soon after with the document that command prints then,
 *   status "cancelled" and the last good state (a set-up that was cut:
 *   "cancelled", iterations 0 and the scene), and *status ACBB_CANCELLED.
 *   The flag is only read; the caller owns it and clears it for reuse.
 * acbb_run_preset_json(t, ...) is acbb_run_preset_json_ctl(t, strlen(t),
 * ..., NULL, ...). */
char *acbb_run_preset_json_ctl(const char *preset_text, size_t text_len,
                               const char *const *settings, size_t n_settings,
                               const acbb_atomic_int *cancel, int *status);

/* Free a string returned by this API; NULL is allowed. */
void acbb_string_free(char *s);

#ifdef __cplusplus
}
#endif

#endif
