/* acbb TUI — the help screen: every key, in columns. The global keys are
 * listed here; each screen's own keys come from its descriptor, and the
 * list of screens from the table (screens.h), so the help cannot forget
 * a screen. */
#include <curses.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include "screens.h"

#define COL_W 40
#define WHAT_W (COL_W - 15) /* " %-12s %s" leaves this for the text */
#define HELP_MAX 240

static const acbb_help_line global_help[] = {
    { "Tab  S-Tab", "next / previous screen" },
    { "?  F1", "this help; PgDn PgUp space page it, any other key closes it" },
    { "/  n  N", "search (Edit, Nodes, help); next / previous match" },
    { "Esc", "clear the message (the next key does too); cancel a prompt" },
    { "Ctrl-L", "redraw the whole screen" },
    { "q  F10", "quit (asks during a run or if unsaved)" },
    { "Ctrl-C", "quit, like q" },
    { "mouse", "click a tab, a row or a key of the hint line; wheel scrolls (off: --no-mouse)" },
    { NULL, NULL },
};

static const acbb_help_line run_help[] = {
    { "r", "cold run of edited scene" },
    { "space  p", "pause / resume" },
    { "x", "stop the run" },
    { "R", "reset to ambient" },
    { "a", "apply edits warm (keep T)" },
    { "A", "apply edits, cold" },
    { "+ =  -", "pace faster / slower (simulated s per second, x200 to start)" },
    { "v", "presentation view: big digits, chart below" },
    { "m", "pin the result as what-if baseline: live values show their change" },
    { "M", "clear the baseline" },
    { "u", "undo the last edit" },
    { "w  W  o", "save / save as / open a preset" },
    { "b  B", "accuracy benchmark (B with the dynamic level)" },
    { "t", "TE vs WTE to steady state" },
    { "g", "export PNG+SVG (gnuplot) of the run" },
    { NULL, NULL },
};

/* What the screens' short names mean (issue 29 item 7: a_i was an angle
 * on one screen and a semi-axis on another, and no screen said). */
static const acbb_help_line glossary[] = {
    { "TE  WTE", "with / without thermal expansion" },
    { "IR  OR", "inner ring / outer ring" },
    { "Qi  Qo", "ball load on the inner / outer race, N" },
    { "alpha_i _o", "contact angle at the inner / outer race" },
    { "a_i  b_i", "contact ellipse semi-axes at the inner race (a_o b_o: outer)" },
    { "pi  po", "peak Hertz contact pressure, inner / outer" },
    { "P_L P_t P_s", "losses: lubricant shear, slip (traction), spin" },
    { "P_r  P_v", "losses: rolling hysteresis, drag in the oil-air" },
    { "rise", "temperature above ambient" },
    { "res", "residual: largest |dT/dt| in K/s; steady state below the tolerance" },
    { "C", "basic dynamic load rating" },
    { "L10r", "rating life 90 % of bearings reach, h" },
    { "Lnm", "modified life = a1 a_ISO L10r, h" },
    { "a_ISO", "life modification factor (lubrication, contamination), at most 50" },
    { "kappa", "viscosity ratio: the oil's at running temperature / the one needed" },
    { "s0", "static safety: static load rating / largest static load" },
    { "edge  EDGE", "margin of the contact ellipse to the shoulder; EDGE: over it" },
    { ">1e+09 h", "a life longer than the largest reported" },
    { "LONG", "the run needs over a minute more (steady estimate)" },
    { "&", "chart: two or more curves in one cell" },
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

static void add_row(help_rows *h, const char *keys, const char *what, int title)
{
    if (h->n == HELP_MAX) return;
    help_row *r = &h->r[h->n++];
    snprintf(r->keys, sizeof r->keys, "%s", keys);
    snprintf(r->what, sizeof r->what, "%s", what);
    r->title = title;
}

/* A key's text wrapped at spaces into WHAT_W columns: never cut. */
static void add(help_rows *h, const char *keys, const char *what)
{
    if (!what) {
        add_row(h, keys, "", 1);
        return;
    }
    const char *p = what;
    do {
        size_t n = strlen(p);
        if (n > WHAT_W) {
            n = WHAT_W;
            while (n > 0 && p[n] != ' ') n--;
            if (n == 0) n = WHAT_W;
        }
        char part[WHAT_W + 1];
        snprintf(part, sizeof part, "%.*s", (int)n, p);
        add_row(h, p == what ? keys : "", part, 0);
        p += n;
        while (*p == ' ') p++;
    } while (*p);
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
    add(h, "Glossary", NULL);
    add_lines(h, glossary);
}

void acbb_screen_help_draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    int ncol = b.w >= 2 * COL_W ? 2 : 1, per = b.h - 1;
    help_rows rows; /* about 16 kB: rebuilt per frame, cheap next to drawing */
    build(&rows);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "Keys (j/k scroll, / search, any other key closes)");
    for (int i = a->help_top; i < rows.n; i++) {
        int k = i - a->help_top, col = k / per, row = k % per;
        if (col >= ncol) break;
        int x = b.x + col * COL_W, y = b.y + 1 + row;
        const help_row *r = &rows.r[i];
        int hit = a->search[0] && a->search_help && i == a->help_hit;
        if (r->title)
            acbb_put(a, y, x, COL_W - 1, hit ? ACBB_ROLE_SELECTED : ACBB_ROLE_HEADER, "%s", r->keys);
        else
            acbb_put(a, y, x, COL_W - 1, hit ? ACBB_ROLE_SELECTED : ACBB_ROLE_NORMAL, " %-12s %s",
                     r->keys, r->what);
    }
}

static int icontains(const char *hay, const char *needle)
{
    size_t n = strlen(needle);
    for (; *hay; hay++)
        if (strncasecmp(hay, needle, n) == 0) return 1;
    return 0;
}

static int max_top(const acbb_app *a, int n)
{
    int per = a->lay.body.h - 1, ncol = a->lay.body.w >= 2 * COL_W ? 2 : 1;
    int m = n - per * ncol;
    return m < 0 ? 0 : m;
}

int acbb_screen_help_search(acbb_app *a, const char *text, int dir)
{
    help_rows rows;
    build(&rows);
    int from = a->help_hit >= 0 && a->help_hit < rows.n ? a->help_hit : 0;
    for (int k = dir == 0 ? 0 : 1; k <= rows.n; k++) {
        int i = ((from + (dir < 0 ? -k : k)) % rows.n + rows.n) % rows.n;
        if (icontains(rows.r[i].keys, text) || icontains(rows.r[i].what, text)) {
            a->help_hit = i;
            int shown = (a->lay.body.h - 1) * (a->lay.body.w >= 2 * COL_W ? 2 : 1);
            /* Keep the hit on screen. */
            if (i < a->help_top || i >= a->help_top + shown)
                a->help_top = i < max_top(a, rows.n) ? i : max_top(a, rows.n);
            return 1;
        }
    }
    return 0;
}

int acbb_screen_help_key(acbb_app *a, int ch)
{
    help_rows rows;
    build(&rows);
    int top_max = max_top(a, rows.n);
    if (acbb_app_search_key(a, ch, 1)) return 1;
    if (ch == 'j' || ch == KEY_DOWN) {
        if (a->help_top < top_max) a->help_top++;
        return 1;
    }
    if (ch == 'k' || ch == KEY_UP) {
        if (a->help_top > 0) a->help_top--;
        return 1;
    }
    /* Paging keys page, as in less(1); only other keys close the help. */
    int page = a->lay.body.h - 1 > 1 ? a->lay.body.h - 1 : 1;
    if (ch == KEY_NPAGE || ch == ' ' || ch == KEY_END || ch == 'G') {
        a->help_top = ch == KEY_END || ch == 'G' || a->help_top + page > top_max ? top_max : a->help_top + page;
        return 1;
    }
    if (ch == KEY_PPAGE || ch == 'b' || ch == KEY_HOME || ch == 'g') {
        a->help_top = ch == KEY_HOME || ch == 'g' || a->help_top < page ? 0 : a->help_top - page;
        return 1;
    }
    a->mode = ACBB_MODE_NORMAL;
    return 1;
}
