/* acbb TUI — the help screen: every key, in columns. The global keys are
 * listed here; each screen's own keys come from its descriptor, and the
 * list of screens from the table (screens.h), so the help cannot forget
 * a screen. */
#include <curses.h>
#include <stdio.h>
#include <string.h>
#include "screens.h"

#define COL_W 40
#define WHAT_W (COL_W - 15) /* " %-12s %s" leaves this for the text */
#define HELP_MAX 160

static const acbb_help_line global_help[] = {
    { "Tab  S-Tab", "next / previous screen" },
    { "?", "this help" },
    { "q  Ctrl-C", "quit (asks if unsaved)" },
    { NULL, NULL },
};

static const acbb_help_line run_help[] = {
    { "r", "cold run of edited scene" },
    { "space", "pause / resume" },
    { "x", "stop the run" },
    { "R", "reset to ambient" },
    { "a", "apply edits warm (keep T)" },
    { "A", "apply edits, cold" },
    { "+  -", "pace faster / slower" },
    { "t", "TE vs WTE to steady state" },
    { "g", "export PNG+SVG (gnuplot)" },
    { NULL, NULL },
};

/* One row of the help: a section title (what == NULL) or keys + text. */
typedef struct {
    char keys[64];
    char what[WHAT_W + 8];
    int title;
} help_row;

typedef struct {
    help_row r[HELP_MAX];
    int n;
} help_rows;

static void add(help_rows *h, const char *keys, const char *what)
{
    if (h->n == HELP_MAX) return;
    help_row *r = &h->r[h->n++];
    snprintf(r->keys, sizeof r->keys, "%s", keys);
    snprintf(r->what, sizeof r->what, "%s", what ? what : "");
    r->title = what == NULL;
}

static void add_lines(help_rows *h, const acbb_help_line *l)
{
    for (; l && l->keys; l++) add(h, l->keys, l->what);
}

/* "1 .. 8" and the screens' names, wrapped to the text column. */
static void add_screen_keys(help_rows *h)
{
    char keys[16], line[WHAT_W + 1] = "";
    snprintf(keys, sizeof keys, "%c .. %c", acbb_screens[0]->key,
             acbb_screens[acbb_screen_count - 1]->key);
    for (int i = 0; i < acbb_screen_count; i++) {
        const char *name = acbb_screens[i]->name;
        size_t k = strlen(name);
        if (line[0] && strlen(line) + 1 + k > WHAT_W) {
            add(h, keys, line);
            keys[0] = line[0] = '\0';
        }
        if (line[0]) strcat(line, " ");
        strncat(line, name, WHAT_W - strlen(line));
    }
    if (line[0]) add(h, keys, line);
}

static void build(help_rows *h)
{
    h->n = 0;
    add(h, "Screens", NULL);
    add_screen_keys(h);
    add_lines(h, global_help);
    add(h, "Run (every screen)", NULL);
    add_lines(h, run_help);
    for (int i = 0; i < acbb_screen_count; i++) {
        const acbb_screen *s = acbb_screens[i];
        if (!s->help || !s->help[0].keys) continue;
        char title[64];
        snprintf(title, sizeof title, "%s (screen %c)", s->name, s->key);
        add(h, title, NULL);
        add_lines(h, s->help);
    }
}

void acbb_screen_help_draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    int ncol = b.w >= 2 * COL_W ? 2 : 1, per = b.h - 1;
    help_rows rows; /* about 16 kB: rebuilt per frame, cheap next to drawing */
    build(&rows);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "Keys (j/k scroll, any other key closes)");
    for (int i = a->help_top; i < rows.n; i++) {
        int k = i - a->help_top, col = k / per, row = k % per;
        if (col >= ncol) break;
        int x = b.x + col * COL_W, y = b.y + 1 + row;
        const help_row *r = &rows.r[i];
        if (r->title)
            acbb_put(a, y, x, COL_W - 1, ACBB_ROLE_HEADER, "%s", r->keys);
        else
            acbb_put(a, y, x, COL_W - 1, ACBB_ROLE_NORMAL, " %-12s %s", r->keys, r->what);
    }
}

int acbb_screen_help_key(acbb_app *a, int ch)
{
    int per = a->lay.body.h - 1;
    int ncol = a->lay.body.w >= 2 * COL_W ? 2 : 1;
    help_rows rows;
    build(&rows);
    int max_top = rows.n - per * ncol;
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
