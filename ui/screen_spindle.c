/* acbb TUI — the Spindle screen (issue 31): the shaft along x with its
 * front and rear sets, the temperature along the shaft and the housing,
 * the coolant, the nose drift and stiffness and each set's preload and
 * loads (rows laid out by spindle_draw.c), and below them the nose drift
 * over time, from the screen's own history of the snapshots it sees
 * (drift_hist.c). g writes the drift over time and the temperature along
 * the axis through gnuplot. Any other scene gets one line saying how to
 * open a spindle. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "drift_hist.h"
#include "export.h"
#include "screens.h"
#include "spindle_draw.h"

extern const acbb_screen acbb_screen_spindle;

typedef struct {
    acbb_drift_hist drift;
    unsigned long run;             /* the run the history belongs to */
    unsigned long pubs;            /* the last publication taken */
    acbb_axis_memo memo;           /* the chart's widen-only axes */
    acbb_spindle_page page;        /* scratch: this frame's rows */
} spindle_ui;

static spindle_ui *sp(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_spindle);
}

/* Every frame, shown or not: each new snapshot adds its nose drift. */
static void poll(acbb_app *a)
{
    spindle_ui *u = sp(a);
    if (a->st.run_id != u->run) {
        acbb_drift_clear(&u->drift);
        u->run = a->st.run_id;
    }
    if (a->st.publications == u->pubs || !a->st.has_snapshot) return;
    u->pubs = a->st.publications;
    const acbb_snapshot *s = &a->st.snap;
    if (s->spindle.n_sets > 0) acbb_drift_add(&u->drift, s->time, s->spindle.nose_drift_axial * 1e6);
}

/* Another preset was opened: its run starts a new history. */
static void drop(acbb_app *a)
{
    acbb_drift_clear(&sp(a)->drift);
}

static void draw(acbb_app *a)
{
    spindle_ui *u = sp(a);
    acbb_rect b = a->lay.body;
    if (acbb_spindle_page_fill(&a->st.scene, &a->st.snap.spindle, b.w, &u->page) != 0) {
        acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_NORMAL, "%s", acbb_spindle_none_text);
        return;
    }
    for (int r = 0; r < ACBB_SP_ROWS; r++)
        acbb_put(a, b.y + r, b.x, b.w, r == ACBB_SP_HEADER ? ACBB_ROLE_HEADER : ACBB_ROLE_NORMAL, "%s",
                 u->page.line[r]);
    const double *ys[1] = { u->drift.d };
    static const char *const names[1] = { "nose drift" };
    acbb_chart_spec c = { .title = "Nose drift (axial)", .yunit = "um", .xunit = "s", .x = u->drift.t,
                          .ys = ys, .names = names, .nser = 1, .n = u->drift.n,
                          .polish = acbb_app_polished(a), .floor_y = 0, .memo = &u->memo,
                          .memo_key = a->st.run_id };
    acbb_rect r = { b.y + ACBB_SP_ROWS, b.x, b.h - ACBB_SP_ROWS, b.w };
    acbb_chart_draw(a, r, &c);
}

/* "spindle_drift-2" of "dir/spindle_drift-2.png" (in place). */
static const char *stem(char *path)
{
    char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    if (dot) *dot = '\0';
    return slash ? slash + 1 : path;
}

/* g: dir/spindle_drift and dir/spindle_temperature (PNG and SVG). */
static void export_plots(acbb_app *a)
{
    const spindle_ui *u = sp(a);
    const acbb_spindle_view *v = &a->st.snap.spindle;
    if (v->n_sets == 0 || u->drift.n < 2) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s", v->n_sets == 0 ? "not a spindle: nothing to plot"
                                                             : "nothing to plot yet: r runs the scene, then g");
        return;
    }
    static double xs[ACBB_SPINDLE_MAX_CELLS], xh[ACBB_SPINDLE_MAX_CELLS];
    int ns = v->n_shaft < ACBB_SPINDLE_MAX_CELLS ? v->n_shaft : ACBB_SPINDLE_MAX_CELLS;
    int nh = v->n_housing < ACBB_SPINDLE_MAX_CELLS ? v->n_housing : ACBB_SPINDLE_MAX_CELLS;
    for (int i = 0; i < ns; i++) xs[i] = v->shaft_x[i] * 1e3;
    for (int i = 0; i < nh; i++) xh[i] = v->housing_x[i] * 1e3;
    char t1[PATH_MAX + 32], t2[PATH_MAX + 32], png[2][PATH_MAX + 32], svg[2][PATH_MAX + 32];
    snprintf(t1, sizeof t1, "%s: nose drift", acbb_editor_name(&a->ed));
    snprintf(t2, sizeof t2, "%s: temperature along the axis, t = %.0f s", acbb_editor_name(&a->ed),
             a->st.snap.time);
    acbb_plot_series d = { "nose drift (axial)", u->drift.t, u->drift.d, u->drift.n, 1, 1, 0 };
    acbb_plot_series T[2] = { { "shaft", xs, v->shaft_T_C, (size_t)ns, 1, 1, 1 },
                              { "housing", xh, v->housing_T_C, (size_t)nh, 2, 1, 1 } };
    acbb_plot_xy p1 = { t1, "time, s", "nose drift, um", &d, 1 };
    acbb_plot_xy p2 = { t2, "x from the nose, mm", "temperature, C", T, nh > 0 ? 2 : 1 };
    acbb_error err = { { 0 } };
    if (acbb_export_xy(a->plot_dir, "spindle_drift", &p1, 1000, 600, png[0], svg[0], sizeof png[0], &err) !=
            ACBB_OK ||
        acbb_export_xy(a->plot_dir, "spindle_temperature", &p2, 1000, 600, png[1], svg[1], sizeof png[1],
                       &err) != ACBB_OK)
        acbb_app_msg(a, ACBB_ROLE_ERROR, "plot export failed: %s", err.msg);
    else /* the names with their counter (-2, ...), without dir and extension: fits 80 columns */
        acbb_app_msg(a, ACBB_ROLE_OK, "wrote %s and %s (.png .svg) to %s/", stem(png[0]), stem(png[1]),
                     a->plot_dir);
}

static int on_key(acbb_app *a, int ch)
{
    if (ch != 'g') return 0;
    export_plots(a);
    return 1;
}

static const acbb_help_line help[] = {
    { "g", "write the nose drift over time and the temperature along the axis (PNG+SVG)" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_spindle = {
    .state_size = sizeof(spindle_ui),
    .name = "Spindle", .key = 'D', .draw = draw, .on_key = on_key, .help = help, .poll = poll,
    .drop = drop,
    .hint = "r run  space pause  x stop  g export drift+temperature  ? help  q quit",
};
