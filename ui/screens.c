/* acbb TUI — the table of screens (see screens.h). Adding a screen: write
 * screen_NAME.c exporting `const acbb_screen acbb_screen_NAME`, then add
 * its declaration and its row below (the row's place is its tab). */
#include <stdlib.h>
#include "screens.h"

extern const acbb_screen acbb_screen_run, acbb_screen_nodes, acbb_screen_balls,
    acbb_screen_charts, acbb_screen_edit, acbb_screen_compare, acbb_screen_plot,
    acbb_screen_accuracy, acbb_screen_sweep, acbb_screen_sensitivity;
extern const acbb_screen acbb_screen_set;
extern const acbb_screen acbb_screen_preload;
extern const acbb_screen acbb_screen_spindle;

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
    &acbb_screen_spindle,
    &acbb_screen_set,
};

const int acbb_screen_count = (int)(sizeof acbb_screens / sizeof acbb_screens[0]);
_Static_assert(sizeof acbb_screens / sizeof acbb_screens[0] <= ACBB_MAX_TABS, "app.h: ACBB_MAX_TABS");

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

void *acbb_screen_state(const acbb_app *a, const acbb_screen *s)
{
    return a->screen_state[acbb_screen_index(s)];
}

acbb_status acbb_screens_init(acbb_app *a, acbb_error *err)
{
    for (int i = 0; i < acbb_screen_count; i++) {
        const acbb_screen *s = acbb_screens[i];
        acbb_status rc = s->init ? s->init(a, &a->screen_state[i], err)
                         : s->state_size ? acbb_screen_state_new(&a->screen_state[i], s->state_size, NULL, err)
                                         : ACBB_OK;
        if (rc != ACBB_OK) return rc;
    }
    return ACBB_OK;
}

void acbb_screens_free(acbb_app *a)
{
    for (int i = 0; i < acbb_screen_count; i++) {
        if (acbb_screens[i]->free) acbb_screens[i]->free(a->screen_state[i]);
        else free(a->screen_state[i]);
        a->screen_state[i] = NULL;
    }
}

acbb_status acbb_screen_state_new(void **state, size_t size, acbb_status (*make)(void *p, acbb_error *err),
                                  acbb_error *err)
{
    void *p = calloc(1, size);
    if (!p) return acbb_error_set(err, ACBB_ENOMEM, "out of memory");
    acbb_status rc = make ? make(p, err) : ACBB_OK;
    if (rc != ACBB_OK) {
        free(p);
        return rc;
    }
    *state = p;
    return ACBB_OK;
}
