/* acbb CLI — where presets are found, and `acbb presets`.
 *
 * A PRESET argument that names an existing file, or contains a '/', is
 * used as it is. Any other name ("7008C" or "7008C.ini") is looked up, as
 * NAME and NAME.ini, in the search path, first match wins:
 *   1. the user's own:  $XDG_CONFIG_HOME/acbb/presets
 *                       (XDG_CONFIG_HOME unset or empty: ~/.config)
 *   2. the source tree: ./presets
 *   3. the installation: DATADIR/acbb/presets (fixed at build time by
 *      meson, ACBB_PRESET_DIR), and the same place relative to the running
 *      binary (BINDIR/../DATADIR/acbb/presets) when it was installed under
 *      another root (DESTDIR, a moved prefix). */
#ifndef ACBB_CLI_PRESETS_H
#define ACBB_CLI_PRESETS_H

#include <stdbool.h>
#include <stddef.h>
#include "args.h"

#define CLI_MAX_PRESET_DIRS 4

typedef struct {
    char path[CLI_PATH_MAX];
    const char *role;          /* "user", "source tree", "installed" */
} acbb_cli_preset_dir;

/* The search path in order; returns the number of directories. */
size_t acbb_cli_preset_dirs(acbb_cli_preset_dir dirs[CLI_MAX_PRESET_DIRS]);

/* The file `arg` stands for, into out[n]: 0, or -1 (with `report`, a
 * message on stderr naming every directory searched). */
int acbb_cli_resolve_preset(const char *arg, char *out, size_t n, bool report);

/* True when the file `path` lies in an installed preset directory (role
 * "installed": shared by every user); dir[n] gets that directory. */
bool acbb_cli_preset_installed(const char *path, char *dir, size_t n);

/* The preset `acbb study NAME` means: `seed` is the seed's case, 7008C. */
const char *acbb_cli_study_preset_name(const char *arg);

/* `acbb presets [DIR]`: the search path and every preset in it (or in DIR
 * alone) with its first comment line. */
int acbb_cli_cmd_presets(const acbb_cli_args *a);

#endif
