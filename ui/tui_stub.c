/* stub until the TUI lands */
#include "tui.h"
int acbb_tui_main(int argc, char **argv) { (void)argc; (void)argv; return 2; }
