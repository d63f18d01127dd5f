/* acbb TUI — the bars around every screen: the title bar (the tabs, made
 * from the table of screens, and the scene's name) and the status line
 * (phase, iteration, timing, pace, progress to steady state). */
#include <stdio.h>
#include <string.h>
#include "screens.h"

/* Columns the tab row takes with every name spelled out. */
static int full_tabs_width(void)
{
    int w = 0;
    for (int i = 0; i < acbb_screen_count; i++) w += (int)strlen(acbb_screens[i]->name) + 4; /* "[n name]" */
    return w;
}

void acbb_draw_title(acbb_app *a)
{
    acbb_rect r = a->lay.title;
    acbb_role_on(a, ACBB_ROLE_TITLE);
    mvhline(r.y, r.x, ' ', r.w);
    int x = r.x;
    acbb_put(a, r.y, x, r.w, ACBB_ROLE_TITLE, " acbb ");
    x += 6;
    /* At 80 columns eight names leave no room for the scene's name (and its
     * unsaved-edit star), so then only the current tab keeps its name. */
    char name[PATH_MAX + 8];
    snprintf(name, sizeof name, "%s%s ", acbb_editor_name(&a->ed), a->ed.modified ? "*" : "");
    int compact = x + full_tabs_width() + (int)strlen(name) + 1 > r.x + r.w;
    for (int i = 0; i < acbb_screen_count; i++) {
        const acbb_screen *s = acbb_screens[i];
        char tab[24];
        if (compact && a->screen != i) snprintf(tab, sizeof tab, "%c", s->key);
        else snprintf(tab, sizeof tab, "%c %s", s->key, s->name);
        acbb_role rr = a->screen == i ? ACBB_ROLE_TAB : ACBB_ROLE_TITLE;
        /* Monochrome: brackets mark the current tab as well as bold. */
        acbb_put(a, r.y, x, r.x + r.w - x, rr, a->screen == i ? "[%s]" : " %s ", tab);
        x += (int)strlen(tab) + 2;
    }
    int room = r.x + r.w - x - 1;
    int len = (int)strlen(name);
    if (room > 4) {
        if (len > room) { /* keep the end of a long name, marked as cut */
            acbb_put(a, r.y, r.x + r.w - room, room, ACBB_ROLE_TITLE, "%s%s", a->term.g.ellipsis,
                     name + (len - room + 1));
        } else {
            acbb_put(a, r.y, r.x + r.w - len, len, ACBB_ROLE_TITLE, "%s", name);
        }
    }
    acbb_role_on(a, ACBB_ROLE_NORMAL);
}

static acbb_role phase_role(const acbb_app *a)
{
    switch (a->st.phase) {
    case ACBB_WORKER_RUNNING: return ACBB_ROLE_OK;
    case ACBB_WORKER_DONE:
        return a->st.snap.state == ACBB_RUN_CONVERGED ? ACBB_ROLE_OK : ACBB_ROLE_ERROR;
    case ACBB_WORKER_NO_SIM: return ACBB_ROLE_ERROR;
    default: return ACBB_ROLE_WARN;
    }
}

static void phase_text(const acbb_app *a, char *buf, size_t n)
{
    if (a->st.phase == ACBB_WORKER_DONE)
        snprintf(buf, n, "%s", acbb_run_status_name(&a->st.snap));
    else
        snprintf(buf, n, "%s", acbb_worker_phase_name(a->st.phase));
}

void acbb_draw_status(acbb_app *a)
{
    acbb_rect r = a->lay.status;
    const acbb_snapshot *s = &a->st.snap;
    char ph[32], wall[16], eta[16], pace[16], line[256];
    phase_text(a, ph, sizeof ph);
    acbb_fmt_duration(a->st.run_wall_s, wall, sizeof wall);
    acbb_fmt_duration(a->prog.eta_s, eta, sizeof eta);
    int p = acbb_worker_pace(a->worker); /* the atomic: current even while idle */
    if (p > 0) snprintf(pace, sizeof pace, "%d/s", p);
    else snprintf(pace, sizeof pace, "max");
    int x = r.x;
    acbb_put(a, r.y, x, r.w, phase_role(a), "%-9s", ph);
    x += 10;
    snprintf(line, sizeof line, "it %ld t %.0fs wall %s %.0f st/s pace %s res %.1e",
             s->iteration, s->time, wall, a->st.steps_per_s, pace, s->residual);
    acbb_put(a, r.y, x, r.x + r.w - x, ACBB_ROLE_NORMAL, "%s", line);
    x += (int)strlen(line) + 1;
    /* Progress to steady state on the log scale of the residual. */
    int room = r.x + r.w - x;
    if (room >= 14) {
        double f = a->st.phase == ACBB_WORKER_DONE && s->state == ACBB_RUN_CONVERGED ? 1.0
                                                                                      : a->prog.fraction;
        char tail[32];
        if (f >= 1.0) snprintf(tail, sizeof tail, "100%% done");
        else snprintf(tail, sizeof tail, "%3.0f%% eta %s", 100 * f, eta);
        int bw = room - (int)strlen(tail) - 1;
        if (bw > 10) bw = 10;
        if (bw >= 3) {
            acbb_bar(a, r.y, x, bw, f, ACBB_ROLE_BAR);
            x += bw + 1;
        }
        acbb_put(a, r.y, x, r.x + r.w - x, ACBB_ROLE_NORMAL, "%s", tail);
    }
}
