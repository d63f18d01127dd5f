/* acbb TUI — the plot screen: a gnuplot `dumb` preview of one plot kind,
 * and the one-key export of PNG+SVG files. gnuplot runs only on request
 * (entering the screen, Enter, a kind change, g), never per frame. */
#include <curses.h>
#include <stdio.h>
#include <string.h>
#include "screens.h"
#include "export.h"

#define N_KINDS 5
#define PREVIEW_MAX 65536 /* bytes of gnuplot dumb text */

extern const acbb_screen acbb_screen_plot;

/* This screen's own state (screens.h init). */
typedef struct {
    int kind;                      /* preview kind (acbb_plot_kind) */
    int ok;                        /* the preview is a plot, not an error */
    char text[PREVIEW_MAX];   /* gnuplot dumb text */
} plot_ui;

static plot_ui *pl(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_plot);
}

static void title_of(const acbb_app *a, char *buf, size_t n)
{
    snprintf(buf, n, "acbb %s, iteration %ld", acbb_editor_name(&a->ed), a->st.snap.iteration);
}

static void refresh_preview(acbb_app *a)
{
    acbb_error err = { { 0 } };
    char title[PATH_MAX + 64];
    title_of(a, title, sizeof title);
    acbb_plot_data d = { .history = &a->hist, .snapshot = &a->st.snap, .title = title };
    int cols = a->lay.body.w, rows = a->lay.body.h - 1;
    acbb_status rc = acbb_plot_dumb((acbb_plot_kind)pl(a)->kind, cols, rows, &d, pl(a)->text,
                                    PREVIEW_MAX, &err);
    pl(a)->ok = rc == ACBB_OK;
    if (!pl(a)->ok) {
        snprintf(pl(a)->text, PREVIEW_MAX, "%s", err.msg);
        acbb_app_msg(a, ACBB_ROLE_ERROR, "preview failed: %s", err.msg);
    }
}

static void draw(acbb_app *a)
{
    acbb_rect b = a->lay.body;
    if (!pl(a)->text[0]) refresh_preview(a);
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "gnuplot preview: %s   < > kind  Enter refresh  g export to %s",
             acbb_plot_kind_name((acbb_plot_kind)pl(a)->kind), a->plot_dir);
    const char *p = pl(a)->text;
    for (int r = 0; r < b.h - 1 && *p; r++) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        char line[1024];
        if (len >= sizeof line) len = sizeof line - 1;
        memcpy(line, p, len);
        line[len] = '\0';
        /* gnuplot's dumb terminal may emit a form feed first. */
        for (char *c = line; *c; c++)
            if (*c == '\f' || *c == '\r') *c = ' ';
        acbb_put(a, b.y + 1 + r, b.x, b.w, pl(a)->ok ? ACBB_ROLE_NORMAL : ACBB_ROLE_ERROR,
                 "%s", line);
        p = nl ? nl + 1 : p + len;
    }
}

static int on_key(acbb_app *a, int ch)
{
    switch (ch) {
    case KEY_LEFT: case 'h': case '<': pl(a)->kind = (pl(a)->kind + N_KINDS - 1) % N_KINDS; break;
    case KEY_RIGHT: case 'l': case '>': pl(a)->kind = (pl(a)->kind + 1) % N_KINDS; break;
    case '\n': case '\r': case KEY_ENTER: break;
    default: return 0;
    }
    refresh_preview(a);
    return 1;
}

/* A fresh preview on every entry. */
static void enter(acbb_app *a)
{
    pl(a)->text[0] = '\0';
}

static const acbb_help_line help[] = {
    { "< >  h l", "plot kind" },
    { "Enter", "refresh the preview" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_plot = {
    .state_size = sizeof(plot_ui),
    .name = "Plot", .key = '7', .draw = draw, .on_key = on_key, .enter = enter, .help = help,
    .hint = "</> kind  Enter refresh  g export PNG+SVG  ? help  q quit",
};

void acbb_screen_plot_export(acbb_app *a)
{
    acbb_error err = { { 0 } };
    char title[PATH_MAX + 64];
    int written = 0;
    title_of(a, title, sizeof title);
    /* Say so before gnuplot runs: the export takes a moment. */
    acbb_app_msg(a, ACBB_ROLE_WARN, "exporting plots to %s ...", a->plot_dir);
    acbb_draw_title(a);
    move(a->lay.message.y, 0);
    clrtoeol();
    acbb_put(a, a->lay.message.y, 0, a->lay.message.w, ACBB_ROLE_WARN, "%s", a->msg);
    wnoutrefresh(stdscr);
    doupdate();
    if (a->hist.n < 2 || a->st.phase == ACBB_WORKER_IDLE || a->st.phase == ACBB_WORKER_NO_SIM) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "nothing to plot yet: r runs the scene, then g exports it");
        return;
    }
    char sfx[16];
    if (acbb_export_plots(a->plot_dir, &a->hist, &a->st.snap, title, sfx, sizeof sfx, &written, &err) !=
        ACBB_OK)
        acbb_app_msg(a, ACBB_ROLE_ERROR, "plot export failed: %s", err.msg);
    else if (!sfx[0])
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %d plots (PNG+SVG) to %s/", written, a->plot_dir);
    else
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %d plots (PNG+SVG) to %s/ named *%s (earlier kept)", written,
                     a->plot_dir, sfx);
}

