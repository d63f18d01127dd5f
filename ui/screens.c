/* acbb TUI — the table of screens (see screens.h). Adding a screen: write
 * screen_NAME.c exporting `const acbb_screen acbb_screen_NAME`, then add
 * its declaration and its row below (the row's place is its tab). */
#include "screens.h"

extern const acbb_screen acbb_screen_run, acbb_screen_nodes, acbb_screen_balls,
    acbb_screen_charts, acbb_screen_edit, acbb_screen_compare, acbb_screen_plot,
    acbb_screen_accuracy, acbb_screen_sweep, acbb_screen_sensitivity;
extern const acbb_screen acbb_screen_set;
extern const acbb_screen acbb_screen_preload;

const acbb_screen *const acbb_screens[] = {
    &acbb_screen_run,
    &acbb_screen_nodes,
    &acbb_screen_balls,
    &acbb_screen_charts,
    &acbb_screen_edit,
    &acbb_screen_compare,
    &acbb_screen_plot,
    &acbb_screen_accuracy,
    &acbb_screen_sweep,
    &acbb_screen_sensitivity,
    &acbb_screen_preload,
    &acbb_screen_set,
};

const int acbb_screen_count = (int)(sizeof acbb_screens / sizeof acbb_screens[0]);

int acbb_screen_index(const acbb_screen *s)
{
    for (int i = 0; i < acbb_screen_count; i++)
        if (acbb_screens[i] == s) return i;
    return 0;
}

void acbb_screen_show(acbb_app *a, int i)
{
    a->screen = ((i % acbb_screen_count) + acbb_screen_count) % acbb_screen_count;
    const acbb_screen *s = acbb_screens[a->screen];
    if (s->enter) s->enter(a);
}

const acbb_screen *acbb_screen_current(const acbb_app *a)
{
    return acbb_screens[a->screen];
}
