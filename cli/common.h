/* acbb CLI — what every command shares: loading the scene with its --set
 * edits, checking stdout, and output files written through the engine's
 * atomic writer (include/acbb/tools/outfile.h). */
#ifndef ACBB_CLI_COMMON_H
#define ACBB_CLI_COMMON_H

#include "acbb/tools/outfile.h"
#include "acbb/scene.h"
#include "args.h"
#include "output.h"

/* The engine's message, or the status name when it left none. */
const char *acbb_cli_err_text(const acbb_error *err, acbb_status st);
/* "--set " when msg names one of the --set edits (engine messages start with
 * the edit text), else "". */
const char *acbb_cli_set_prefix(const char *msg, const char *const *sets, size_t n);

/* a->preset with a->sets applied: 0, or the exit status (message printed). */
int acbb_cli_load_scene(const acbb_cli_args *a, acbb_scene *sc);

/* 0, or 4 (message printed) when `nonfinite` values were met or stdout
 * could not be written. */
int acbb_cli_stdout_check(long nonfinite);

/* A batch with runs that failed: 0 when `failed` is 0, else exit 3 after
 * one line on stderr, "CMD: F of T runs failed (first: FIRST); KEPT", so
 * a nonzero exit always says why. FIRST names the first failed run and
 * its status ("TE at n rpm 14000: not_converged: ..."). */
int acbb_cli_runs_failed(const char *cmd, size_t failed, size_t total, const char *first,
                         const char *kept);

/* "CMD: out of memory" on stderr; exit 4. */
int acbb_cli_no_memory(const char *cmd);

/* The same for a study's runs (acbb/tools/study.h). */
struct acbb_study;
int acbb_cli_study_failed(const char *cmd, struct acbb_study *st, const char *kept);

/* An output file: writers go to `out.f`; close commits it in place. */
typedef struct {
    const char *path;
    acbb_out *handle;
    acbb_cli_out out;
} acbb_cli_file;

/* 0, or 2 (message printed) when the file cannot be created. */
int acbb_cli_file_open(acbb_cli_file *c, const char *path);
/* Commit: 0; 2 when it could not be written; 4 when non-finite values
 * were met (the file is still written, with empty fields). */
int acbb_cli_file_close(acbb_cli_file *c);

#endif
