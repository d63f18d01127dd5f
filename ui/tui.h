/* acbb — the ncurses workbench, entry point for the acbb executable. */
#ifndef ACBB_TUI_H
#define ACBB_TUI_H

#include <stdbool.h>
#include <stddef.h>

/* `acbb` alone and `acbb tui [options] [PRESET]`: the options as the CLI's
 * one parser (cli/args.c, the `tui` row of the command table) read them.
 * Strings point into argv; NULL when absent. */
typedef struct {
    const char *preset;      /* resolved path, or as typed (the TUI reports it) */
    const char *pace;        /* --pace N */
    const char *plot_dir;    /* --plot-dir DIR */
    bool no_mouse, exit_after_steady;
    /* Whether `path` is an installed preset, shared by every user (its
     * directory into dir): the TUI's save in place refuses it, as
     * `acbb edit` does (issue 26 item 6). NULL: no preset is installed. */
    bool (*installed)(const char *path, char *dir, size_t n);
} acbb_tui_args;

/* Returns the exit status (cli/exit.h). */
int acbb_tui_main(const acbb_tui_args *args);

#endif
