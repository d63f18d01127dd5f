/* acbb CLI — the one output guard every command passes before anything
 * runs (issue 20 item 5, issue 26 items 1, 3, 11). An output is refused
 * (exit 2, the message naming both paths) when it
 *   - is an input of the command (the preset, --baseline, a merge input):
 *     by path, by inode, through symlinks, a dangling one included (its
 *     target is what the writer would create);
 *   - is another output of the same command (two formats, one file);
 *   - cannot be written: no directory, not writable, a directory, a block
 *     device or socket, a FIFO with no reader (said at once: the guard
 *     opens it and keeps it open, so the command's own open finds the
 *     reader still there);
 *   - has a name longer than the file system takes (NAME_MAX for a
 *     component, less the atomic writer's temporary suffix; PATH_MAX).
 * "-" is standard output; two formats on it are refused too. A FIFO or
 * character device with a reader is written as a stream (outfile.h). */
#ifndef ACBB_CLI_OUT_GUARD_H
#define ACBB_CLI_OUT_GUARD_H

#include <stdbool.h>
#include <stddef.h>
#include "args.h"

typedef struct {
    const char *path;
    const char *what;   /* "--csv", "OUT", "the preset", ... */
} acbb_cli_named_path;

/* The inputs and outputs given, checked as above: 0, or 2 (message
 * printed, prefixed by `cmd`). `json` counts as a format on stdout. */
int acbb_cli_guard_paths(const char *cmd, const acbb_cli_named_path *in, size_t n_in,
                         const acbb_cli_named_path *out, size_t n_out, bool json);

/* The inputs and outputs of the parsed command `a` (study's preset
 * resolved here, as the command will), checked by acbb_cli_guard_paths. */
int acbb_cli_out_guard(const acbb_cli_args *a);

#endif
