/* acbb TUI — the preset editor screen and the preset browser.
 * The model (validation, undo, save) is editor.c; this file draws it and
 * maps keys onto it. */
#include <curses.h>
#include <glob.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include "screens.h"
#include "acbb/tools/preset_info.h"
#include "acbb/tools/scene_inactive.h"
#include "acbb/tools/scene_schema.h"

#define INFO_ROWS 4 /* help and range of the selected field (1 row when a refusal takes 3) */

static int list_rows(const acbb_app *a)
{
    int n = a->lay.body.h - 1 - INFO_ROWS;
    return n < 1 ? 1 : n;
}

static void keep_visible(acbb_app *a)
{
    acbb_editor *e = &a->ed;
    size_t rows = (size_t)list_rows(a);
    if (e->cursor < e->top) e->top = e->cursor;
    if (e->cursor >= e->top + rows) e->top = e->cursor - rows + 1;
}

/* Columns wide enough for every section and key name (issue 29 item 7:
 * "surroundings" pushed its row out of line); a range or list of choices
 * longer than the rest of the row ends in an ellipsis (the info rows
 * below give it whole). */
#define SECTION_W 12
#define KEY_W 26
#define VALUE_W 14

/* The row's mark: '*' changed since the save, '~' no effect in the scene
 * as set (issue 29 item 1: the info rows say why and what makes it act),
 * '!' both. */
static char row_mark(const acbb_app *a, int changed, const acbb_field_info *f)
{
    char key[96];
    snprintf(key, sizeof key, "%s.%s", f->section, f->key);
    int off = acbb_scene_key_inactive(&a->ed.scene, key, NULL);
    return off ? (changed ? '!' : '~') : changed ? '*' : ' ';
}

static void put_row(acbb_app *a, int y, acbb_role role, int changed, const acbb_field_info *f,
                    const char *val, const char *range)
{
    acbb_rect b = a->lay.body;
    int x = b.x + 1 + SECTION_W + 1 + KEY_W + 1 + VALUE_W + 1, room = b.x + b.w - x;
    acbb_put(a, y, b.x, b.w, role, "%c%-*s %-*s %-*s", row_mark(a, changed, f), SECTION_W, f->section,
             KEY_W, f->key, VALUE_W, val);
    if (room <= 0) return;
    if ((int)strlen(range) <= room) acbb_put(a, y, x, room, role, "%s", range);
    else acbb_put(a, y, x, room, role, "%.*s%s", room - 1, range, a->term.g.ellipsis);
}

static void draw(acbb_app *a)
{
    acbb_editor *e = &a->ed;
    acbb_rect b = a->lay.body;
    keep_visible(a);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "%s%s  Enter edit  </> cycle  / find  u undo  w save",
             e->path[0] ? e->path : "(built-in default)", e->modified ? " [modified]" : "");
    size_t n = acbb_scene_field_count();
    int rows = list_rows(a);
    for (int r = 0; r < rows; r++) {
        size_t i = e->top + (size_t)r;
        if (i >= n) break;
        const acbb_field_info *f = acbb_scene_field(i);
        char val[128], was[128], range[192];
        acbb_scene_field_format(&e->scene, i, val, sizeof val);
        acbb_scene_field_format(&e->saved, i, was, sizeof was);
        acbb_scene_field_range(i, range, sizeof range);
        acbb_role role = i == e->cursor ? ACBB_ROLE_SELECTED : ACBB_ROLE_NORMAL;
        if (i == e->cursor) {
            acbb_role_on(a, role);
            mvhline(b.y + 1 + r, b.x, ' ', b.w);
        }
        put_row(a, b.y + 1 + r, role, strcmp(val, was) != 0, f, val, range);
    }
    const acbb_field_info *f = acbb_scene_field(e->cursor);
    int y = b.y + 1 + rows;
    int help_rows = a->edit_error[0] ? 1 : INFO_ROWS;
    if (f) {
        char text[1024], range[192];
        acbb_scene_field_range(e->cursor, range, sizeof range);
        /* The whole range or list of choices: a row may have to cut it. */
        char key[96];
        acbb_inactive_effect in;
        snprintf(key, sizeof key, "%s.%s", f->section, f->key);
        if (acbb_scene_key_inactive(&e->scene, key, &in))
            snprintf(text, sizeof text, "%s: NO EFFECT here: %s. %s; allowed: %s", key, in.why,
                     f->help, range);
        else
            snprintf(text, sizeof text, "%s: %s; allowed: %s", key, f->help, range);
        acbb_put_wrap(a, y, b.x, b.w, help_rows, ACBB_ROLE_NORMAL, text);
    }
    if (a->edit_error[0]) {
        char text[600];
        snprintf(text, sizeof text, "refused: %s", a->edit_error);
        acbb_put_wrap(a, y + help_rows, b.x, b.w, INFO_ROWS - help_rows, ACBB_ROLE_ERROR, text);
    }
}

static int on_key(acbb_app *a, int ch)
{
    acbb_editor *e = &a->ed;
    size_t n = acbb_scene_field_count(), page = (size_t)list_rows(a);
    acbb_error err = { { 0 } };
    switch (ch) {
    case 'j': case KEY_DOWN: if (e->cursor + 1 < n) e->cursor++; return 1;
    case 'k': case KEY_UP: if (e->cursor > 0) e->cursor--; return 1;
    case KEY_NPAGE: e->cursor = e->cursor + page < n ? e->cursor + page : n - 1; return 1;
    case KEY_PPAGE: e->cursor = e->cursor > page ? e->cursor - page : 0; return 1;
    case KEY_HOME: e->cursor = 0; return 1;
    case KEY_END: e->cursor = n - 1; return 1;
    case '\n': case '\r': case KEY_ENTER: case 'e': {
        const acbb_field_info *f = acbb_scene_field(e->cursor);
        char val[128], label[160];
        acbb_scene_field_format(&e->scene, e->cursor, val, sizeof val);
        snprintf(label, sizeof label, "%s.%s%s%s%s = ", f->section, f->key, f->unit[0] ? " [" : "",
                 f->unit, f->unit[0] ? "]" : "");
        acbb_app_prompt(a, ACBB_PROMPT_VALUE, label, val);
        return 1;
    }
    case KEY_LEFT: case KEY_RIGHT: case 'h': case 'l': case '<': case '>':
        if (acbb_editor_cycle(e, e->cursor, ch == KEY_RIGHT || ch == 'l' || ch == '>' ? 1 : -1, &err) != ACBB_OK) {
            acbb_app_msg(a, ACBB_ROLE_WARN, "%s", err.msg);
        } else {
            a->edit_error[0] = '\0';
            acbb_screen_editor_edited(a, "edited (a: apply warm, A: apply cold)");
        }
        return 1;
    default:
        return 0;
    }
}

static int icontains(const char *hay, const char *needle)
{
    size_t len = strlen(needle);
    for (; *hay; hay++)
        if (strncasecmp(hay, needle, len) == 0) return 1;
    return 0;
}

/* `/`: the next field from the cursor on whose section.key holds the text
 * (any case); only if no key does, the next whose help does. */
static int search(acbb_app *a, const char *text, int dir)
{
    acbb_editor *e = &a->ed;
    size_t n = acbb_scene_field_count();
    for (int in_help = 0; in_help < 2; in_help++)
        for (size_t k = dir == 0 ? 0 : 1; k <= n; k++) {
            size_t i = dir < 0 ? (e->cursor + n * 2 - k) % n : (e->cursor + k) % n;
            const acbb_field_info *f = acbb_scene_field(i);
            char hay[512];
            snprintf(hay, sizeof hay, "%s.%s", f->section, f->key);
            if (icontains(in_help ? f->help : hay, text)) {
                e->cursor = i;
                keep_visible(a);
                return 1;
            }
        }
    return 0;
}

static void click(acbb_app *a, int row, int col)
{
    (void)col;
    size_t i = a->ed.top + (size_t)(row - 1);
    if (row >= 1 && row <= list_rows(a) && i < acbb_scene_field_count()) a->ed.cursor = i;
}

static const acbb_help_line help[] = {
    { "/  n  N", "find a key (e.g. /axial), next / previous" },
    { "j k arrows", "move (PgUp PgDn Home End)" },
    { "Enter  e", "type a value, Esc cancels" },
    { "< >  h l", "cycle on/off and choices" },
    { "u", "undo the last edit" },
    { "w  W", "save / save as (atomic)" },
    { "o", "open a preset" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_edit = {
    .name = "Edit", .key = '5', .draw = draw, .on_key = on_key, .help = help, .search = search,
    .click = click,
    .hint = "Enter edit  </> cycle  / find  u undo  w save  o open  a apply  ? help",
};

void acbb_screen_editor_edited(acbb_app *a, const char *hint)
{
    acbb_inactive_effect in[8];
    size_t n = acbb_scene_inactive_effects(&a->ed.scene, in, 8);
    if (n == 0)
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "%s", hint);
    else
        acbb_app_msg(a, ACBB_ROLE_WARN, "edited; note: %s has no effect here: %s", in[0].key,
                     in[0].why);
}

/* ---- preset browser ---- */

void acbb_screen_browse_begin(acbb_app *a)
{
    glob_t g;
    a->browse.n = 0;
    a->browse.sel = 0;
    if (glob("presets/*.ini", 0, NULL, &g) == 0) {
        for (size_t i = 0; i < g.gl_pathc && a->browse.n < ACBB_BROWSE_MAX - 1; i++)
            snprintf(a->browse.names[a->browse.n++], sizeof a->browse.names[0], "%s", g.gl_pathv[i]);
        globfree(&g);
    }
    snprintf(a->browse.names[a->browse.n++], sizeof a->browse.names[0], "(type a path...)");
    a->mode = ACBB_MODE_BROWSE;
}

/* The teaching header of the selected preset (preset_info.h): its title,
 * what to look at, and how its run ends. */
static void browse_info(acbb_app *a, int y, int x, int w, int rows)
{
    acbb_preset_info info;
    if (rows < 2 || a->browse.sel >= a->browse.n - 1) return;
    if (acbb_preset_info_read(a->browse.names[a->browse.sel], &info, NULL) != ACBB_OK) return;
    int used = acbb_put_wrap(a, y, x, w, rows, ACBB_ROLE_HEADER, info.title);
    if (info.look_at[0] && used < rows) {
        char text[1100];
        snprintf(text, sizeof text, "Look at: %s", info.look_at);
        used += acbb_put_wrap(a, y + used, x, w, rows - used, ACBB_ROLE_NORMAL, text);
    }
    if (info.expect[0] && used < rows)
        acbb_put(a, y + used, x, w, ACBB_ROLE_NORMAL, "Expect: %s", info.expect);
}

void acbb_screen_browse_draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    int w = b.w > 78 ? 78 : b.w, x = b.x + (b.w - w) / 2;
    int list = a->browse.n + 2 < b.h / 2 ? a->browse.n + 2 : b.h / 2;
    for (int r = 0; r < b.h; r++) { /* the overlay covers the whole body */
        acbb_role_on(a, ACBB_ROLE_NORMAL);
        mvhline(b.y + r, b.x, ' ', b.w);
    }
    acbb_put(a, b.y, x, w, ACBB_ROLE_TITLE, " Open a preset: Enter open, p type a path, Esc cancel ");
    int first = a->browse.sel >= list - 1 ? a->browse.sel - (list - 2) : 0;
    for (int i = first; i < a->browse.n && i - first + 1 < list; i++)
        acbb_put(a, b.y + 1 + i - first, x + 2, w - 2,
                 i == a->browse.sel ? ACBB_ROLE_SELECTED : ACBB_ROLE_NORMAL, "%s",
                 a->browse.names[i]);
    acbb_hrule(a, b.y + list, x, w);
    browse_info(a, b.y + list + 1, x + 1, w - 2, b.h - list - 1);
}

int acbb_screen_browse_key(acbb_app *a, int ch)
{
    switch (ch) {
    case 'j': case KEY_DOWN: if (a->browse.sel + 1 < a->browse.n) a->browse.sel++; return 1;
    case 'k': case KEY_UP: if (a->browse.sel > 0) a->browse.sel--; return 1;
    case 27: a->mode = ACBB_MODE_NORMAL; return 1;
    case 'p': case '/':
        a->mode = ACBB_MODE_NORMAL;
        acbb_app_prompt(a, ACBB_PROMPT_OPEN, "open preset: ", "");
        return 1;
    case '\n': case '\r': case KEY_ENTER:
        a->mode = ACBB_MODE_NORMAL;
        if (a->browse.sel == a->browse.n - 1)
            acbb_app_prompt(a, ACBB_PROMPT_OPEN, "open preset: ", "");
        else
            acbb_app_open(a, a->browse.names[a->browse.sel]);
        return 1;
    default:
        return 1; /* the browser is modal */
    }
}

