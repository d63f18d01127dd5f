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
    char name[PATH_MAX + 40], which[32] = "";
    /* A set: which bearing the Run, Nodes, Balls and Charts screens show,
     * on every screen (issue 29 item 4); kept when a long name is cut. */
    if (a->st.snap.n_bearings > 1)
        snprintf(which, sizeof which, " bearing %d/%d", a->bearing, a->st.snap.n_bearings);
    snprintf(name, sizeof name, "%s%s%s ", acbb_editor_name(&a->ed), a->ed.modified ? "*" : "", which);
    int compact = x + full_tabs_width() + (int)strlen(name) + 1 > r.x + r.w;
    for (int i = 0; i < acbb_screen_count; i++) {
        const acbb_screen *s = acbb_screens[i];
        char tab[24];
        if (compact && a->screen != i) snprintf(tab, sizeof tab, "%c", s->key);
        else snprintf(tab, sizeof tab, "%c %s", s->key, s->name);
        acbb_role rr = a->screen == i ? ACBB_ROLE_TAB : ACBB_ROLE_TITLE;
        /* Monochrome: brackets mark the current tab as well as bold. */
        acbb_put(a, r.y, x, r.x + r.w - x, rr, a->screen == i ? "[%s]" : " %s ", tab);
        if (i < ACBB_MAX_TABS) { /* where a mouse click opens this tab */
            a->tab_x0[i] = x;
            a->tab_x1[i] = x + (int)strlen(tab) + 2;
        }
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

/* The pace as the user thinks of it: simulated seconds per wall second. */
void acbb_fmt_pace(int pace, char *buf, size_t n)
{
    if (pace > 0) snprintf(buf, n, "x%d", pace);
    else snprintf(buf, n, "max");
}

/* The progress tail: an ETA only while the run is stepping; "100% done"
 * only once it converged (issue: ETA kept by a stopped run, 100% while
 * still running). */
static void progress_tail(const acbb_app *a, double *f, char *tail, size_t n)
{
    const acbb_snapshot *s = &a->st.snap;
    char eta[16];
    acbb_fmt_duration(a->prog.eta_s, eta, sizeof eta);
    *f = a->prog.fraction;
    switch (a->st.phase) {
    case ACBB_WORKER_RUNNING:
        if (a->prog.valid && a->prog.eta_s == 0.0) snprintf(tail, n, "%2.0f%% finishing", 100 * *f);
        else if (acbb_progress_long(&a->prog)) /* issue 20 item 8: say it is long, once sure (29.6) */
            snprintf(tail, n, "%2.0f%% eta %s LONG", 100 * *f, eta);
        else snprintf(tail, n, "%2.0f%% eta %s", 100 * *f, eta);
        break;
    case ACBB_WORKER_DONE:
        if (s->state == ACBB_RUN_CONVERGED) {
            *f = 1.0;
            snprintf(tail, n, "100%% done");
        } else snprintf(tail, n, "%2.0f%% failed", 100 * *f);
        break;
    case ACBB_WORKER_PAUSED: snprintf(tail, n, "%2.0f%% paused", 100 * *f); break;
    case ACBB_WORKER_STOPPED: snprintf(tail, n, "%2.0f%% stopped", 100 * *f); break;
    default: *f = 0.0; snprintf(tail, n, "not started"); break;
    }
}

void acbb_draw_status(acbb_app *a)
{
    acbb_rect r = a->lay.status;
    const acbb_snapshot *s = &a->st.snap;
    char ph[32], wall[16], pace[16], line[256], rate[32] = "", tail[48];
    phase_text(a, ph, sizeof ph);
    acbb_fmt_duration(a->st.run_wall_s, wall, sizeof wall);
    acbb_fmt_pace(acbb_worker_pace(a->worker), pace, sizeof pace); /* the atomic: current even while idle */
    int x = r.x;
    acbb_put(a, r.y, x, r.w, phase_role(a), "%-9s", ph);
    x += 10;
    /* The step rate only where there is room: at 80 columns the progress
     * bar and its ETA come first. */
    if (r.w >= 100) snprintf(rate, sizeof rate, " %.0f st/s", a->st.steps_per_s);
    snprintf(line, sizeof line, "it %ld t %.0fs wall %s%s %s res %.1e", s->iteration, s->time, wall,
             rate, pace, s->residual);
    double f;
    progress_tail(a, &f, tail, sizeof tail);
    int room = r.x + r.w - x - (int)strlen(line) - 1;
    int bw = room - (int)strlen(tail) - 1;
    if (bw > 10) bw = 10;
    acbb_put(a, r.y, x, r.x + r.w - x, ACBB_ROLE_NORMAL, "%s", line);
    x += (int)strlen(line) + 1;
    if (bw >= 3) {
        acbb_bar(a, r.y, x, bw, f, ACBB_ROLE_BAR);
        x += bw + 1;
    }
    acbb_put(a, r.y, x, r.x + r.w - x, ACBB_ROLE_NORMAL, "%s", tail);
}
