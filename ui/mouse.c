/* acbb TUI — the mouse, when the terminal reports it (htop, btop and
 * ranger habits): a click on a tab opens it, on a row selects it, on a
 * key of the hint row presses that key; the wheel scrolls. Off with
 * `acbb tui --no-mouse` (then the terminal keeps its own selection). */
#include <string.h>
#include "screens.h"

#define WHEEL_ROWS 3

/* The key named by a hint item's first word ("r run", "space pause"). */
static int hint_item_key(const char *item, size_t len)
{
    size_t w = 0;
    while (w < len && item[w] != ' ') w++;
    if (w == 1) return (unsigned char)item[0];
    if (w == 5 && strncmp(item, "space", 5) == 0) return ' ';
    if (w == 5 && strncmp(item, "Enter", 5) == 0) return '\n';
    if (w == 3 && item[1] == '/') return (unsigned char)item[2]; /* "+/-", "</>": the second */
    return 0;
}

/* Press the key of the hint item under column x (items are separated by
 * two spaces). */
static void click_hint(acbb_app *a, int x)
{
    const char *h = acbb_app_hint(a);
    size_t n = strlen(h);
    for (size_t i = 0; i < n;) {
        const char *end = strstr(h + i, "  ");
        size_t j = end ? (size_t)(end - h) : n;
        if ((size_t)x >= i && (size_t)x < j) {
            int k = hint_item_key(h + i, j - i);
            if (k) acbb_app_key(a, k);
            return;
        }
        i = j;
        while (i < n && h[i] == ' ') i++;
    }
}

/* One mouse report: button 0-2 pressed, 64/65 wheel up/down (xterm's
 * numbering); releases never get here. */
static void mouse_at(acbb_app *a, int button, int x, int y)
{
    if (button == 64 || button == 65) {
        int k = button == 64 ? KEY_UP : KEY_DOWN;
        for (int i = 0; i < WHEEL_ROWS; i++) acbb_app_key(a, k);
        return;
    }
    if (button != 0) return;
    if (a->mode == ACBB_MODE_HELP) { /* a click closes the help, like a key */
        a->mode = ACBB_MODE_NORMAL;
        return;
    }
    a->msg[0] = '\0'; /* a click is a key: the hints come back (app.c) */
    if (y == a->lay.title.y) {
        for (int i = 0; i < acbb_screen_count && i < ACBB_MAX_TABS; i++)
            if (x >= a->tab_x0[i] && x < a->tab_x1[i]) acbb_screen_show(a, i);
    } else if (y == a->lay.message.y && a->mode == ACBB_MODE_NORMAL) {
        click_hint(a, x);
    } else if (y >= a->lay.body.y && y < a->lay.body.y + a->lay.body.h) {
        const acbb_screen *s = acbb_screen_current(a);
        if (s->click && a->mode == ACBB_MODE_NORMAL) s->click(a, y - a->lay.body.y, x - a->lay.body.x);
    }
}

void acbb_app_mouse(acbb_app *a)
{
    MEVENT ev;
    if (getmouse(&ev) != OK) return;
    if (ev.bstate & (BUTTON4_PRESSED | BUTTON5_PRESSED))
        mouse_at(a, ev.bstate & BUTTON4_PRESSED ? 64 : 65, ev.x, ev.y);
    else if (ev.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED))
        mouse_at(a, 0, ev.x, ev.y);
}

/* A mouse report that curses did not decode, because the terminfo entry
 * names the other encoding (xterm-256color's kmous is SGR "\e[<", and a
 * terminal may still send X10 "\e[M" bytes, or the reverse): its bytes
 * arrive as keys, and a click's " " would pause the run. Both encodings
 * (xterm ctlseqs, "Mouse Tracking") are decoded here; returns the number
 * of keys used (0: not a mouse report). */
int acbb_mouse_decode(const int *k, int n, int *button, int *x, int *y, int *press)
{
    if (n < 3 || k[0] != 27 || k[1] != '[') return 0;
    if (k[2] == 'M') { /* X10: ESC [ M b x y, each + 32; b & 3 == 3 is a release */
        if (n < 6) return 0;
        int b = k[3] - 32;
        *button = b & ~(4 | 8 | 16 | 32);
        *press = (b & 3) != 3 || (b & 64);
        if ((b & 3) == 3 && !(b & 64)) *button = 3;
        *x = k[4] - 33;
        *y = k[5] - 33;
        return 6;
    }
    if (k[2] != '<') return 0;
    int v[3] = { 0, 0, 0 }, f = 0, i = 3; /* SGR: ESC [ < b ; x ; y M|m */
    for (; i < n && i < 24; i++) {
        if (k[i] >= '0' && k[i] <= '9') v[f] = v[f] * 10 + (k[i] - '0');
        else if (k[i] == ';' && f < 2) f++;
        else if ((k[i] == 'M' || k[i] == 'm') && f == 2) {
            *button = v[0] & ~(4 | 8 | 16 | 32);
            *press = k[i] == 'M';
            *x = v[1] - 1;
            *y = v[2] - 1;
            return i + 1;
        } else return 0;
    }
    return 0;
}

void acbb_app_mouse_raw(acbb_app *a, int button, int x, int y, int press)
{
    if (press && a->mouse) mouse_at(a, button, x, y);
}
