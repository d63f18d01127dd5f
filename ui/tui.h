/* acbb — the ncurses workbench, entry point for the acbb executable. */
#ifndef ACBB_TUI_H
#define ACBB_TUI_H
/* `acbb` with no arguments and `acbb tui [PRESET]` land here; argv[0] is
 * "tui" (or the program name when started bare). Returns the exit code. */
int acbb_tui_main(int argc, char **argv);
#endif
