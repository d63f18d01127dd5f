/* acbb TUI — terminal set-up and restore (see term.h). */
#include <errno.h>
#include <fcntl.h>
#include <langinfo.h>
#include <locale.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "term.h"
/* ncurses' terminfo header, by its full path: "term.h" above is ours. */
#include <ncursesw/term.h>

#define CLI_POINTER "use the CLI instead: `acbb run PRESET` (or `acbb help`)"

/* TERM=dumb, or a terminal without cursor addressing, cannot draw a
 * screen: refuse clearly and point at the CLI (before and after curses
 * starts, since a terminfo entry may exist but lack `cup`). */
static int no_cursor_addressing(void)
{
    const char *cup = tigetstr("cup");
    return cup == NULL || cup == (char *)-1;
}

/* The only global mutable state of the TUI (allowed by DESIGN.md):
 * the signal handler can reach nothing else, so it writes the flags below
 * and one byte into the self-pipe whose write end it finds here; and the
 * atexit backstop needs to know whether curses is still active. */
static volatile sig_atomic_t sig_pipe_wr = -1;
static volatile sig_atomic_t sig_winch, sig_interrupt, sig_fatal;
static volatile sig_atomic_t curses_active;

static void on_signal(int sig)
{
    int saved = errno;
    if (sig == SIGWINCH) sig_winch = 1;
    else if (sig == SIGINT) sig_interrupt = 1;
    else sig_fatal = sig;
    if (sig_pipe_wr >= 0) {
        char b = (char)sig;
        ssize_t r = write(sig_pipe_wr, &b, 1);
        (void)r; /* a full pipe already wakes the loop */
    }
    errno = saved;
}

/* Backstop for exit paths that skip acbb_term_close (e.g. exit() deep in a
 * library): never leave the user's terminal in cbreak/noecho mode. */
static void restore_backstop(void)
{
    if (curses_active) {
        curses_active = 0;
        endwin();
    }
}

void acbb_glyphs_init(acbb_glyphs *g, int utf8)
{
    static const char *const u8[9] = { " ", "\u258f", "\u258e", "\u258d", "\u258c",
                                       "\u258b", "\u258a", "\u2589", "\u2588" };
    static const char *const ascii[9] = { " ", " ", " ", " ", "#", "#", "#", "#", "#" };
    g->utf8 = utf8;
    for (int i = 0; i < 9; i++) g->eighths[i] = utf8 ? u8[i] : ascii[i];
    g->hline = utf8 ? "\u2500" : "-";
    g->ellipsis = utf8 ? "\u2026" : "~";
    g->deg = utf8 ? "\u00b0" : "deg";
}

static int install_signals(acbb_term *t)
{
    int fd[2];
    if (pipe(fd) != 0) return -1;
    for (int i = 0; i < 2; i++) {
        fcntl(fd[i], F_SETFL, fcntl(fd[i], F_GETFL) | O_NONBLOCK);
        fcntl(fd[i], F_SETFD, FD_CLOEXEC);
    }
    t->sig_rd = fd[0];
    t->sig_wr = fd[1];
    sig_pipe_wr = fd[1];
    /* Installed before curses starts, so curses keeps its hands off these
     * (it only installs handlers over SIG_DFL). No SA_RESTART: select()
     * returns EINTR and the loop looks at the pipe at once. */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGWINCH };
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) sigaction(sigs[i], &sa, NULL);
    return 0;
}

static void set_role(acbb_term *t, acbb_role r, short fg, short bg, attr_t colour_attr,
                     attr_t mono_attr)
{
    if (t->colour) {
        init_pair((short)(r + 1), fg, bg);
        t->attr[r] = COLOR_PAIR(r + 1) | colour_attr;
    } else {
        t->attr[r] = mono_attr;
    }
}

static void init_roles(acbb_term *t)
{
    const char *nc = getenv("NO_COLOR");
    t->colour = has_colors() && !(nc && nc[0]);
    if (t->colour) {
        start_color();
        use_default_colors();
    }
    set_role(t, ACBB_ROLE_NORMAL, -1, -1, A_NORMAL, A_NORMAL);
    set_role(t, ACBB_ROLE_TITLE, COLOR_WHITE, COLOR_BLUE, A_NORMAL, A_REVERSE);
    set_role(t, ACBB_ROLE_TAB, COLOR_BLACK, COLOR_CYAN, A_BOLD, A_BOLD);
    set_role(t, ACBB_ROLE_HEADER, COLOR_YELLOW, -1, A_BOLD, A_BOLD);
    set_role(t, ACBB_ROLE_OK, COLOR_GREEN, -1, A_BOLD, A_BOLD);
    set_role(t, ACBB_ROLE_WARN, COLOR_YELLOW, -1, A_BOLD, A_BOLD | A_UNDERLINE);
    set_role(t, ACBB_ROLE_ERROR, COLOR_WHITE, COLOR_RED, A_BOLD, A_REVERSE | A_BOLD);
    set_role(t, ACBB_ROLE_BAR, COLOR_CYAN, -1, A_NORMAL, A_NORMAL);
    set_role(t, ACBB_ROLE_BAR2, COLOR_MAGENTA, -1, A_NORMAL, A_NORMAL);
    set_role(t, ACBB_ROLE_SELECTED, COLOR_BLACK, COLOR_WHITE, A_NORMAL, A_REVERSE);
    set_role(t, ACBB_ROLE_DIM, -1, -1, A_DIM, A_DIM);
    set_role(t, ACBB_ROLE_SERIES1, COLOR_CYAN, -1, A_NORMAL, A_NORMAL);
    set_role(t, ACBB_ROLE_SERIES2, COLOR_MAGENTA, -1, A_NORMAL, A_BOLD);
}

acbb_status acbb_term_open(acbb_term *t, acbb_error *err)
{
    memset(t, 0, sizeof *t);
    t->sig_rd = t->sig_wr = -1;
    /* LC_CTYPE only: LC_NUMERIC stays "C" so numbers keep a decimal point
     * (DESIGN.md "Practical notes"). */
    setlocale(LC_CTYPE, "");
    const char *cs = nl_langinfo(CODESET);
    const char *force = getenv("ACBB_ASCII");
    acbb_glyphs_init(&t->g, cs && strcmp(cs, "UTF-8") == 0 && !(force && force[0]));
    const char *term = getenv("TERM");
    if (!term || !term[0] || strcmp(term, "dumb") == 0)
        return acbb_error_set(err, ACBB_EIO, "TERM=%s cannot address the cursor, so the TUI cannot draw; %s",
                              term && term[0] ? term : "(unset)", CLI_POINTER);
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO))
        return acbb_error_set(err, ACBB_EIO, "the TUI needs a terminal (use `acbb run` for batch work)");
    if (install_signals(t) != 0)
        return acbb_error_set(err, ACBB_EIO, "cannot create the signal pipe: %s", strerror(errno));
    /* newterm, not initscr: initscr exits the process on a bad $TERM. */
    t->scr = newterm(NULL, stdout, stdin);
    if (!t->scr) {
        acbb_term_close(t);
        return acbb_error_set(err, ACBB_EIO, "cannot start curses for TERM=%s; %s", term, CLI_POINTER);
    }
    if (no_cursor_addressing()) {
        acbb_term_close(t);
        return acbb_error_set(err, ACBB_EIO, "TERM=%s has no cursor addressing, so the TUI cannot draw; %s",
                              term, CLI_POINTER);
    }
    curses_active = 1;
    atexit(restore_backstop);
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    nodelay(stdscr, TRUE);
    set_escdelay(25);
    curs_set(0);
    init_roles(t);
    return ACBB_OK;
}

int acbb_term_mouse(acbb_term *t)
{
    (void)t;
    mmask_t want = BUTTON1_PRESSED | BUTTON4_PRESSED | BUTTON5_PRESSED, got;
    got = mousemask(want, NULL);
    mouseinterval(0); /* presses at once, no click detection delay */
    return got != 0;
}

void acbb_term_close(acbb_term *t)
{
    if (t->scr) {
        if (curses_active) {
            curses_active = 0;
            endwin();
        }
        delscreen(t->scr);
        t->scr = NULL;
    }
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    int sigs[] = { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGWINCH };
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) sigaction(sigs[i], &sa, NULL);
    sig_pipe_wr = -1;
    if (t->sig_rd >= 0) close(t->sig_rd);
    if (t->sig_wr >= 0) close(t->sig_wr);
    t->sig_rd = t->sig_wr = -1;
}

void acbb_term_signals(acbb_term *t, acbb_term_events *ev)
{
    /* Flags first, then the bytes: a signal landing between reading and
     * clearing a flag still left its number in the pipe. */
    ev->winch = sig_winch;
    sig_winch = 0;
    ev->interrupt = sig_interrupt;
    sig_interrupt = 0;
    ev->fatal = sig_fatal;
    unsigned char buf[64];
    ssize_t n;
    while (t->sig_rd >= 0 && (n = read(t->sig_rd, buf, sizeof buf)) > 0)
        for (ssize_t i = 0; i < n; i++) {
            if (buf[i] == SIGWINCH) ev->winch = 1;
            else if (buf[i] == SIGINT) ev->interrupt = 1;
            else ev->fatal = buf[i];
        }
}

void acbb_term_resize(acbb_term *t)
{
    struct winsize ws;
    (void)t;
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_row > 0 && ws.ws_col > 0)
        resizeterm(ws.ws_row, ws.ws_col);
}
