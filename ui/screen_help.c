/* acbb TUI — the help screen: every key, in columns. */
#include <curses.h>
#include "app.h"

static const char *const help[][2] = {
    { "Screens", NULL },
    { "1 .. 8", "run nodes balls charts" },
    { "", "edit TE/WTE plot accuracy" },
    { "Tab", "next screen" },
    { "?", "this help" },
    { "q  Ctrl-C", "quit (asks if unsaved)" },
    { "Run", NULL },
    { "r", "cold run of edited scene" },
    { "space", "pause / resume" },
    { "x", "stop the run" },
    { "R", "reset to ambient" },
    { "a", "apply edits warm (keep T)" },
    { "A", "apply edits, cold" },
    { "+  -", "pace faster / slower" },
    { "t", "TE vs WTE to steady state" },
    { "Editor (screen 5)", NULL },
    { "j k arrows", "move (PgUp PgDn Home End)" },
    { "Enter  e", "type a value, Esc cancels" },
    { "< >  h l", "cycle on/off and choices" },
    { "u", "undo the last edit" },
    { "w  W", "save / save as (atomic)" },
    { "o", "open a preset" },
    { "Views", NULL },
    { "j k PgUp/Dn", "scroll nodes and balls" },
    { "i", "charts: x = time / iter" },
    { "g", "export PNG+SVG (gnuplot)" },
    { "< >  Enter", "plot kind / refresh plot" },
    { "Accuracy (screen 8)", NULL },
    { "b", "benchmark the edited scene" },
    { "B", "same, with the dynamic level" },
    { "x  Esc", "cancel the benchmark" },
    { "j k PgUp/Dn", "scroll the table" },
    { "g", "export its plot (gnuplot)" },
};

#define HELP_N (int)(sizeof help / sizeof help[0])
#define COL_W 40

void acbb_screen_help_draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    int ncol = b.w >= 2 * COL_W ? 2 : 1, per = b.h - 1;
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "Keys (j/k scroll, any other key closes)");
    for (int i = a->help_top; i < HELP_N; i++) {
        int k = i - a->help_top, col = k / per, row = k % per;
        if (col >= ncol) break;
        int x = b.x + col * COL_W, y = b.y + 1 + row;
        if (!help[i][1])
            acbb_put(a, y, x, COL_W - 1, ACBB_ROLE_HEADER, "%s", help[i][0]);
        else
            acbb_put(a, y, x, COL_W - 1, ACBB_ROLE_NORMAL, " %-12s %s", help[i][0], help[i][1]);
    }
}

int acbb_screen_help_key(acbb_app *a, int ch)
{
    int per = a->lay.body.h - 1;
    int ncol = a->lay.body.w >= 2 * COL_W ? 2 : 1;
    int max_top = HELP_N - per * ncol;
    if (ch == 'j' || ch == KEY_DOWN) {
        if (a->help_top < max_top) a->help_top++;
        return 1;
    }
    if (ch == 'k' || ch == KEY_UP) {
        if (a->help_top > 0) a->help_top--;
        return 1;
    }
    a->mode = ACBB_MODE_NORMAL;
    return 1;
}
