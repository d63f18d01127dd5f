/* acbb — one stable entry point for any language's FFI (Python ctypes,
 * cffi, Julia ccall, ...): preset text and "section.key=value" settings in,
 * the run's JSON out. Only C strings cross the boundary; no acbb struct
 * does, so the entry point stays stable while the structs grow.
 *
 * acbb_run_preset_json runs the scene to the end exactly as
 * `acbb run PRESET --set S1 --set S2 ... --json` does (the same loading and
 * checks, the fidelity preset applied, the same run loop, the other
 * branch solved for a scene with a [schedule] or a displacement preload,
 * acbb/branches.h) and returns the document that command prints, byte for
 * byte; only wall_ms, the run's wall time, differs between any two runs.
 *
 * - preset_text: the preset's content (INI text, NUL-terminated), not a
 *   path. Messages name it "<text>" ("<text>:3: ...").
 * - settings: n_settings strings "section.key=value" in preset units, as
 *   the CLI's --set takes them (NULL when n_settings is 0); checked and
 *   applied after the text, as a whole (acbb_scene_apply_edits).
 * - Returns a JSON object as a NUL-terminated string (ASCII, or UTF-8
 *   quoted from the input). It always has "status" and "message" strings:
 *   - the run started: the full run document (acbb/json.h,
 *     acbb_json_write_run); status "converged", or how the run failed
 *     ("not_converged", "runaway", ...) with the reason in message;
 *   - the scene could not be compiled: status, message, "iterations": 0
 *     and "scene" (acbb_json_write_failed);
 *   - bad input (text or a setting): {"status": "bad_input", "message":
 *     ...} with the engine's message, e.g. "operating.axial_load_N=-5:
 *     ..." for a setting (the CLI prefixes it with "--set ").
 *   No number in it is NaN or Inf: one would be written as null and
 *   *status set to ACBB_NONFINITE (an internal error, as the CLI's exit
 *   status reports it; the document stays the one the CLI prints).
 * - Ownership: the string is the caller's; free it with acbb_string_free
 *   (not free(): the caller's runtime may not share this allocator).
 *   NULL is returned only when memory runs out.
 * - *status (may be NULL): ACBB_OK when the run converged, else the
 *   acbb_status (status.h) that the "status" string names: ACBB_EINVAL for
 *   bad input, the run's final status for a failed run (ACBB_NONFINITE
 *   and ACBB_ENOMEM as said above).
 * - Thread-safety: reentrant; calls on different threads are independent
 *   (the engine keeps no global mutable state but GSL's process-wide error
 *   handler, which it turns off while a call works and gives back to the
 *   host when the last call ends; acbb/sim.h). A call blocks until its
 *   run ends (milliseconds to seconds; no cancel). Nothing is printed.
 * - Numbers are read and written with a decimal point whatever locale the
 *   host set (setlocale(LC_ALL, "") under de_DE included): the engine
 *   reads and prints them in the "C" locale on the calling thread only. */
#ifndef ACBB_FFI_H
#define ACBB_FFI_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

char *acbb_run_preset_json(const char *preset_text, const char *const *settings,
                           size_t n_settings, int *status);

/* Free a string returned by this API; NULL is allowed. */
void acbb_string_free(char *s);

#ifdef __cplusplus
}
#endif

#endif
