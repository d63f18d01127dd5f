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

    /* Its own state and background work, as htop's meter classes own
     * theirs: the loop calls these for every row of the table (app.c,
     * results.c), so a screen with a job is one file plus its row. NULL:
     * nothing to do. The state lives in acbb_screen_state(a, screen). */
    size_t state_size;                   /* without init: its state is this many zeroed bytes */
    acbb_status (*init)(acbb_app *a, void **state, acbb_error *err); /* before the loop */
    void (*free)(void *state);           /* after it: cancel, join, free (NULL state too). NULL: free() */
    int (*wake_fd)(const acbb_app *a);   /* its job's wake-up pipe, for select() */
    void (*wake)(acbb_app *a);           /* ... was readable: drain it */
    void (*poll)(acbb_app *a);           /* once per frame: take the job's published state */
    void (*drop)(acbb_app *a);           /* another preset was opened: cancel, hide the result */
    int (*running)(const acbb_app *a);   /* 1 while its job runs (as of the last frame) */
    const char *job_subject, *job_noun;  /* "The preload map" starts a sentence, "preload map" after "the" */
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
/* The state screen s made in its init (NULL: none). */
void *acbb_screen_state(const acbb_app *a, const acbb_screen *s);
/* For an init: *state = size zeroed bytes, then make(*state) (its job;
 * NULL: none); on failure nothing is kept. */
acbb_status acbb_screen_state_new(void **state, size_t size, acbb_status (*make)(void *p, acbb_error *err),
                                  acbb_error *err);
/* Every screen's init, in table order; stops at the first failure. */
acbb_status acbb_screens_init(acbb_app *a, acbb_error *err);
/* Every screen's free (also after a failed acbb_screens_init). */
void acbb_screens_free(acbb_app *a);

#endif
