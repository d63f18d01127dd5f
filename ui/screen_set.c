/* acbb TUI — a bearing set (MODEL.md 14): the set's preload now against
 * the assembly preload, its stiffness at the nose and the lift-off thrust,
 * one row per bearing (which way it carries thrust, its axial load, outer
 * and inner ring temperatures, loss, modified life Lnm and least static
 * safety s0 (MODEL.md 15), lifted off or edge loaded), and the preload
 * over time beside each bearing's outer-ring temperature; the spacing and
 * spacer lengths with the spacers' axial growth. [ and ] (or a
 * click on a row) choose the bearing the Run, Nodes and Balls screens show. */
#include <math.h>
#include <stdio.h>
#include "screens.h"
#include "acbb/tools/set.h"

#define TABLE_Y 3               /* body row of the first bearing row */

void acbb_set_choose(acbb_app *a, int k)
{
    int n = a->st.snap.n_bearings;
    if (n < 2) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "one bearing: set.arrangement = single");
        return;
    }
    a->bearing = ((k % n) + n) % n;
    acbb_worker_set_bearing(a->worker, a->bearing);
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "showing bearing %d of %d", a->bearing, n);
}

static void table(acbb_app *a, acbb_rect b)
{
    const acbb_set_view *v = &a->st.snap.set;
    acbb_put(a, b.y + TABLE_Y - 1, b.x, b.w, ACBB_ROLE_HEADER,
             "   #  thrust   axial N   outer C   inner C    loss W     Lnm h    s0");
    for (int k = 0; k < a->st.snap.n_bearings && k < ACBB_MAX_SET; k++) {
        const acbb_life *L = &a->st.set_life[k]; /* each bearing's own (worker.h) */
        acbb_put(a, b.y + TABLE_Y + k, b.x, b.w,
                 k == a->bearing ? ACBB_ROLE_SELECTED : ACBB_ROLE_NORMAL,
                 "%s %2d  %-6s %9.1f %9.2f %9.2f %9.2f %9.3g %5.3g  %s%s", k == a->bearing ? ">" : " ",
                 k, v->orientation[k] > 0 ? "+x" : "-x", v->axial_force[k], v->T_outer_ring[k],
                 v->T_inner_ring[k], v->loss_total[k], L->Lnmr_h, L->s0_min,
                 v->contact_lost[k] ? "LIFTED OFF " : "", L->edge_loaded ? "EDGE" : "");
    }
}

static void charts(acbb_app *a, acbb_rect r)
{
    static double x[ACBB_HISTORY_CAP], pre[ACBB_HISTORY_CAP], T[3][ACBB_HISTORY_CAP];
    size_t n = a->hist.n;
    int nb = a->st.snap.n_bearings < 3 ? a->st.snap.n_bearings : 3; /* a chart shows 3 series */
    for (size_t i = 0; i < n; i++) {
        const acbb_history_point *p = &a->hist.p[i];
        x[i] = p->time;
        pre[i] = p->set_preload;
        for (int k = 0; k < nb; k++) T[k][i] = p->T_outer_set[k];
    }
    static const char *const names[3] = { "bearing 0", "bearing 1", "bearing 2" };
    const double *sp[1] = { pre }, *st[3] = { T[0], T[1], T[2] };
    const char *pn[1] = { "preload" };
    acbb_rect left = { r.y, r.x, r.h, r.w / 2 }, right = { r.y, r.x + r.w / 2, r.h, r.w - r.w / 2 };
    acbb_chart_spec c1 = { .title = "Set preload", .yunit = "N", .xunit = "s", .x = x, .ys = sp,
                           .names = pn, .nser = 1, .n = n, .polish = acbb_app_polished(a),
                           .floor_y = a->st.snap.set.preload_assembly_N };
    acbb_chart_spec c2 = { .title = "Outer rings", .yunit = "C", .xunit = "s", .x = x, .ys = st,
                           .names = names, .nser = nb, .n = n, .polish = acbb_app_polished(a),
                           .floor_y = a->st.scene.ambient_C };
    acbb_chart_draw(a, left, &c1);
    acbb_chart_draw(a, right, &c2);
}

static void draw(acbb_app *a)
{
    const acbb_snapshot *s = &a->st.snap;
    acbb_rect b = a->lay.body;
    if (s->n_bearings < 2) {
        acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_NORMAL, "One bearing (set.arrangement = single): "
                 "edit [set] (e.g. arrangement = DB) or open presets/pair-DB-heated.ini");
        return;
    }
    const acbb_set_view *v = &s->set;
    /* Each line fits 80 columns (issue 29 item 7); [ ] is in the hint bar. */
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER,
             "%s x%d: preload %.1f N (assembly %.1f)  lift-off thrust %.0f N (%.1f N left)",
             acbb_set_arrangement_name(a->st.scene.set_arrangement), s->n_bearings, v->preload_N,
             v->preload_assembly_N, v->liftoff_thrust_N, v->liftoff_remainder_N);
    if (s->state == ACBB_RUN_CONVERGED)
        acbb_put(a, b.y + 1, b.x, b.w, ACBB_ROLE_NORMAL,
                 "stiffness at the nose: axial %.1f N/um  radial %.1f N/um  tilt %.1f N m/mrad",
                 v->stiffness_axial * 1e-6, v->stiffness_radial * 1e-6, v->stiffness_tilt * 1e-3);
    else /* computed once, at convergence (issue 29 item 4: never a misleading 0) */
        acbb_put(a, b.y + 1, b.x, b.w, ACBB_ROLE_NORMAL,
                 "stiffness at the nose: pending (computed at convergence)");
    table(a, b);
    /* the spacers (MODEL.md 14 L_s, L_h) and what their growth does now;
     * the row after the longest table (4 bearings) is free */
    double L_in, L_out;
    acbb_set_spacers(&a->st.scene, &L_in, &L_out);
    acbb_put(a, b.y + TABLE_Y + ACBB_MAX_SET, b.x, b.w, ACBB_ROLE_NORMAL,
             "spacers: pitch %.1f mm, inner %.1f mm, outer %.1f mm, growth %+.2f um (5: edit)", acbb_set_pitch(&a->st.scene) * 1e3, L_in * 1e3, L_out * 1e3,
             v->spacer_growth * 1e6);
    int top = TABLE_Y + ACBB_MAX_SET + 1;
    acbb_rect r = { b.y + top, b.x, b.h - top, b.w };
    if (r.h >= 6) charts(a, r);
}

static int on_key(acbb_app *a, int ch)
{
    if (ch == 'j' || ch == KEY_DOWN) acbb_set_choose(a, a->bearing + 1);
    else if (ch == 'k' || ch == KEY_UP) acbb_set_choose(a, a->bearing - 1);
    else return 0;
    return 1;
}

static void click(acbb_app *a, int row, int col)
{
    (void)col;
    int k = row - TABLE_Y;
    if (k >= 0 && k < a->st.snap.n_bearings) acbb_set_choose(a, k);
}

static const acbb_help_line help[] = {
    { "[ ]  j k", "choose the bearing the Run, Nodes and Balls screens show" },
    { "click", "a bearing's row chooses it" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_set = {
    .name = "Set", .key = 'S', .draw = draw, .on_key = on_key, .help = help, .click = click,
    .hint = "[ ] or j k choose the bearing the Run, Nodes and Balls screens show  ? help",
};
