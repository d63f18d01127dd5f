/* acbb TUI — the terminal: set-up and restore, signals, glyphs, colours.
 *
 * Glyph tables follow htop's CRT.c: UTF-8 glyphs when nl_langinfo(CODESET)
 * says UTF-8, ASCII otherwise. Colours follow NO_COLOR (https://no-color.org)
 * and has_colors(); the monochrome scheme uses only bold/reverse/underline,
 * so every role stays distinguishable on a black-and-white projector. */
#ifndef ACBB_UI_TERM_H
#define ACBB_UI_TERM_H

#include <curses.h>
#include "acbb/status.h"

typedef enum {
    ACBB_ROLE_NORMAL, ACBB_ROLE_TITLE, ACBB_ROLE_TAB, ACBB_ROLE_HEADER, ACBB_ROLE_OK,
    ACBB_ROLE_WARN, ACBB_ROLE_ERROR, ACBB_ROLE_BAR, ACBB_ROLE_BAR2, ACBB_ROLE_SELECTED,
    ACBB_ROLE_DIM, ACBB_ROLE_SERIES1, ACBB_ROLE_SERIES2, ACBB_ROLE_COUNT
} acbb_role;

typedef struct {
    int utf8;
    const char *eighths[9];   /* horizontal bar cells, 0/8 .. 8/8 filled */
    const char *hline;        /* rule */
    const char *ellipsis;
    const char *deg;          /* degree sign */
} acbb_glyphs;

typedef struct {
    int colour;               /* colours in use */
    acbb_glyphs g;
    attr_t attr[ACBB_ROLE_COUNT];
    int sig_rd, sig_wr;       /* self-pipe written by the signal handler */
    SCREEN *scr;
} acbb_term;

/* Signals seen since the last acbb_term_signals call. */
typedef struct {
    int winch;                /* the terminal was resized */
    int interrupt;            /* SIGINT: the user asks to quit */
    int fatal;                /* SIGTERM / SIGHUP / SIGQUIT number: quit now, 0 if none */
} acbb_term_events;

/* Glyphs for a UTF-8 (1) or ASCII (0) terminal. Pure. */
void acbb_glyphs_init(acbb_glyphs *g, int utf8);

/* Locale (LC_CTYPE only), signal handlers and self-pipe, curses in
 * cbreak/noecho/keypad mode, colours or monochrome. On failure nothing is
 * left changed and err says why. */
acbb_status acbb_term_open(acbb_term *t, acbb_error *err);
/* Ask for mouse reports (press, wheel); 0 if the terminal has none. */
int acbb_term_mouse(acbb_term *t);
/* Restore the terminal (idempotent). */
void acbb_term_close(acbb_term *t);
/* Drain the self-pipe and report the signals that arrived. */
void acbb_term_signals(acbb_term *t, acbb_term_events *ev);
/* Follow a SIGWINCH: read the new size from the tty and resize curses. */
void acbb_term_resize(acbb_term *t);

#endif
