/* acbb TUI — a screen is one row of a table.
 *
 * Each screen file exports one const acbb_screen descriptor; ui/screens.c
 * lists them in tab order. The title bar's tabs, the number keys, Tab and
 * Shift-Tab, the message-row hint, the `?` help screen and the dispatch of
 * screen-specific keys are all generated from that table, so a new screen
 * is one file plus one row in screens.c. */
#ifndef ACBB_UI_SCREENS_H
#define ACBB_UI_SCREENS_H

#include "app.h"

/* One line of the `?` screen: the keys, and what they do. */
typedef struct {
    const char *keys;
    const char *what;
} acbb_help_line;

typedef struct {
    const char *name;                    /* tab label, e.g. "Run" */
    int key;                             /* key that opens it, e.g. '1' */
    void (*draw)(acbb_app *a);           /* the body (a->lay.body and friends) */
    int (*on_key)(acbb_app *a, int ch);  /* its own keys first; 1 if used. NULL: none */
    void (*enter)(acbb_app *a);          /* on being switched to. NULL: nothing */
    const char *hint;                    /* message-row hint. NULL: the run keys */
    const acbb_help_line *help;          /* its `?` section, ended by { NULL, NULL }. NULL: none */
    /* `/` and n/N: find `text` from the current place on, forwards (dir 1)
     * or backwards (-1), wrapping; 1 if found. NULL: the screen has no search. */
    int (*search)(acbb_app *a, const char *text, int dir);
    /* A mouse click at body row `row` (0 = the body's first row). NULL: none. */
    void (*click)(acbb_app *a, int row, int col);
} acbb_screen;

/* The Run screen (the presentation view and baseline keys show it). */
extern const acbb_screen acbb_screen_run;

/* A bearing set: show bearing k (wrapping) on every screen (screen_set.c). */
void acbb_set_choose(acbb_app *a, int k);

/* The table, in tab order (screens.c). */
extern const acbb_screen *const acbb_screens[];
extern const int acbb_screen_count;

/* Index of a descriptor in the table (0 if it is not there). */
int acbb_screen_index(const acbb_screen *s);
/* Switch to screen i (wrapping, so i +- 1 cycles) and run its `enter`. */
void acbb_screen_show(acbb_app *a, int i);
/* The current screen's descriptor. */
const acbb_screen *acbb_screen_current(const acbb_app *a);

#endif
