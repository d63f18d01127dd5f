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

void acbb_app_mouse(acbb_app *a)
{
    MEVENT ev;
    if (getmouse(&ev) != OK) return;
    if (ev.bstate & (BUTTON4_PRESSED | BUTTON5_PRESSED)) {
        int k = ev.bstate & BUTTON4_PRESSED ? KEY_UP : KEY_DOWN;
        for (int i = 0; i < WHEEL_ROWS; i++) acbb_app_key(a, k);
        return;
    }
    if (!(ev.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED))) return;
    if (a->mode == ACBB_MODE_HELP) { /* a click closes the help, like a key */
        a->mode = ACBB_MODE_NORMAL;
        return;
    }
    if (ev.y == a->lay.title.y) {
        for (int i = 0; i < acbb_screen_count && i < ACBB_MAX_TABS; i++)
            if (ev.x >= a->tab_x0[i] && ev.x < a->tab_x1[i]) acbb_screen_show(a, i);
    } else if (ev.y == a->lay.message.y && !a->msg[0] && a->mode == ACBB_MODE_NORMAL) {
        click_hint(a, ev.x);
    } else if (ev.y >= a->lay.body.y && ev.y < a->lay.body.y + a->lay.body.h) {
        const acbb_screen *s = acbb_screen_current(a);
        if (s->click && a->mode == ACBB_MODE_NORMAL) s->click(a, ev.y - a->lay.body.y, ev.x - a->lay.body.x);
    }
}
