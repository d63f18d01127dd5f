/* acbb TUI — the overview screen: key temperatures, the losses, mechanics,
 * what the run is doing, and the temperature chart. With a baseline pinned
 * (m) every live value also shows its change against it; v swaps the
 * panels for the presentation view (bigview.c). */
#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "acbb/tools/schedule.h"
#include "acbb/units.h"
#include "acbb/life.h"
#include "acbb/tools/scene_inactive.h"
#include "screens.h"

/* The network node that the snapshot's T_outer_ring reads: the one whose
 * temperature it copies and whose name says outer ring (node 5 of the
 * 46-node network, node 2 of the 7-node one). -1 if not identifiable. */
/* This screen's own state (screens.h state_size). */
typedef struct {
    int bigview;                   /* the presentation view (v) */
    int has_base;                  /* a baseline is pinned (m) */
    acbb_snapshot base;            /* ... this result */
} run_ui;

static run_ui *rn(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_run);
}

static int outer_ring_node(const acbb_snapshot *s)
{
    if (!s->node_names) return -1;
    for (int i = 0; i < s->n_nodes; i++) {
        char low[64];
        snprintf(low, sizeof low, "%s", s->node_names[i]);
        for (char *c = low; *c; c++) *c = (char)tolower((unsigned char)*c);
        if (s->T[i] == s->T_outer_ring && (strstr(low, "outer ring") || strstr(low, "(sensor)")))
            return i;
    }
    return -1;
}

void acbb_run_outer_label(const acbb_snapshot *s, char *buf, size_t n)
{
    int k = outer_ring_node(s);
    if (k >= 0) snprintf(buf, n, "Outer ring (%d)", k);
    else snprintf(buf, n, "Outer ring");
}

void acbb_fmt_delta(double v, double base, double ref, char *buf, size_t n)
{
    if (fabs(ref) > 1e-12) snprintf(buf, n, "%+.2f %+5.1f%%", v - base, 100 * (v - base) / fabs(ref));
    else snprintf(buf, n, "%+.2f    --", v - base);
}

static void temps_panel(acbb_app *a, acbb_rect r)
{
    const acbb_snapshot *s = &a->st.snap, *b = &rn(a)->base;
    double amb = a->st.scene.ambient_C;
    char outer[32];
    acbb_run_outer_label(s, outer, sizeof outer);
    const struct { const char *name; double T, B; } rows[] = {
        { outer, s->T_outer_ring, b->T_outer_ring }, { "Inner ring", s->T_inner_ring, b->T_inner_ring },
        { "Ball", s->T_ball, b->T_ball }, { "Housing", s->T_housing, b->T_housing },
        { "Shaft", s->T_shaft, b->T_shaft }, { "Oil-air", s->T_cavity, b->T_cavity },
    };
    if (rn(a)->has_base)
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Temperature     C  vs base  %%rise");
    else
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Temperature        C   rise(%.0f)", amb);
    double hi = 1.0;
    for (size_t i = 0; i < 6; i++) hi = fmax(hi, rows[i].T - amb);
    for (size_t i = 0; i < 6 && (int)i + 1 < r.h; i++) {
        int y = r.y + 1 + (int)i;
        if (rn(a)->has_base) {
            char d[48];
            acbb_fmt_delta(rows[i].T, rows[i].B, rows[i].B - amb, d, sizeof d);
            acbb_put(a, y, r.x, r.w, ACBB_ROLE_NORMAL, "%-14s %6.2f %s", rows[i].name, rows[i].T, d);
            continue;
        }
        acbb_put(a, y, r.x, r.w, ACBB_ROLE_NORMAL, "%-15s %7.2f %+7.2f", rows[i].name, rows[i].T,
                 rows[i].T - amb);
        acbb_bar(a, y, r.x + 32, r.w - 33, (rows[i].T - amb) / hi, ACBB_ROLE_BAR2);
    }
}

/* A loss's name in at most 8 columns, so name and symbol fit the panel's
 * 13 (the JSON names run to 11: ehl_rolling). */
static const char *loss_label(acbb_loss_kind k)
{
    return k == ACBB_LOSS_EHL_ROLLING ? "EHL roll" : acbb_loss_name(k);
}

static bool loss_shown(const acbb_app *a, int k)
{
    return acbb_loss_enabled(&a->ed.scene, (acbb_loss_kind)k) || a->st.snap.losses.P[k] != 0.0;
}

/* The rows of the loss table that the scene switches on (or that carry a
 * value, for a run started before an edit), then the total; when the rows
 * leave no room for the total (the extended set at 24 lines), the header
 * carries it. */
static void losses_panel(acbb_app *a, acbb_rect r)
{
    const acbb_losses *l = &a->st.snap.losses, *lb = &rn(a)->base.losses;
    int n = 0;
    for (int k = 0; k < ACBB_LOSS_KINDS; k++) n += loss_shown(a, k);
    bool head_total = n + 1 >= r.h;
    if (head_total)
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Power loss  total %7.2f W", l->total);
    else
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER,
                 rn(a)->has_base ? "Power loss      W  vs base     %%" : "Power loss        W      %%");
    double tot = l->total > 0 ? l->total : 1.0;
    int row = 1;
    for (int k = 0; k <= ACBB_LOSS_KINDS - head_total && row < r.h; k++, row++) {
        int total = k == ACBB_LOSS_KINDS;
        double v = total ? l->total : l->P[k], vb = total ? lb->total : lb->P[k];
        char name[16];
        if (!total) {
            if (!loss_shown(a, k)) { row--; continue; }
            snprintf(name, sizeof name, "%s %s", loss_label((acbb_loss_kind)k),
                     acbb_loss_symbol((acbb_loss_kind)k));
        } else snprintf(name, sizeof name, "Total");
        acbb_role role = total ? ACBB_ROLE_HEADER : ACBB_ROLE_NORMAL;
        if (rn(a)->has_base) {
            char d[48];
            acbb_fmt_delta(v, vb, vb, d, sizeof d);
            acbb_put(a, r.y + row, r.x, r.w, role, "%-13s%6.2f %s", name, v, d);
            continue;
        }
        acbb_put(a, r.y + row, r.x, r.w, role, "%-13s%7.2f %6.1f", name, v, 100 * v / tot);
        if (!total) acbb_bar(a, r.y + row, r.x + 28, r.w - 29, v / tot, ACBB_ROLE_BAR);
    }
}

/* Min and max of a ball quantity over the balls (one ball under pure axial load). */
static void span(const acbb_snapshot *s, size_t off, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < s->n_balls; i++) {
        double v;
        memcpy(&v, (const char *)&s->balls[i] + off, sizeof v);
        *lo = fmin(*lo, v);
        *hi = fmax(*hi, v);
    }
    if (s->n_balls == 0) *lo = *hi = 0.0;
}

/* "Qi 412.3 N" with its range, or its change against the baseline. */
static void ball_item(acbb_app *a, char *buf, size_t n, const char *name, size_t off, double scale,
                      const char *unit)
{
    double lo, hi, blo, bhi;
    span(&a->st.snap, off, &lo, &hi);
    if (!rn(a)->has_base) {
        if (hi - lo > 1e-9 * fabs(hi)) snprintf(buf, n, "%s %.2f..%.2f%s", name, lo * scale, hi * scale, unit);
        else snprintf(buf, n, "%s %.2f%s", name, hi * scale, unit);
        return;
    }
    char d[48];
    span(&rn(a)->base, off, &blo, &bhi);
    acbb_fmt_delta(hi * scale, bhi * scale, bhi * scale, d, sizeof d);
    snprintf(buf, n, "%s max %.2f%s %s", name, hi * scale, unit, d);
}

static void mech_panel(acbb_app *a, acbb_rect r)
{
    const acbb_snapshot *s = &a->st.snap;
    const double R2D = 1.0 / ACBB_DEG /* deg per rad */, UM = 1e6;
    char item[6][288];
    ball_item(a, item[0], sizeof item[0], "Qi", offsetof(acbb_ball_view, Qi), 1, " N");
    ball_item(a, item[1], sizeof item[1], "Qo", offsetof(acbb_ball_view, Qo), 1, " N");
    /* alpha, not a: a_i is the contact ellipse's semi-axis on the Balls screen. */
    ball_item(a, item[2], sizeof item[2], "alpha_i", offsetof(acbb_ball_view, alpha_i), R2D, a->term.g.deg);
    ball_item(a, item[3], sizeof item[3], "alpha_o", offsetof(acbb_ball_view, alpha_o), R2D, a->term.g.deg);
    snprintf(item[4], sizeof item[4], "growth um: ball %.2f IR %.2f OR %.2f", s->exp_ball * UM,
             (s->exp_inner + s->exp_inner_cen) * UM, s->exp_outer * UM);
    snprintf(item[5], sizeof item[5], "Fx %.0f N dx %.2f um heat %.2f/%.2f W", s->reaction_x,
             s->delta_x * UM, s->heat_in, s->heat_out);
    char which[40] = ""; /* a set: the bearing shown (Set screen, [ ]) */
    if (s->n_bearings > 1) snprintf(which, sizeof which, ", bearing %d of %d", a->bearing, s->n_bearings);
    acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "Mechanics (%d balls%s%s)", s->n_balls,
             rn(a)->has_base ? ", change vs base" : ", min..max", which);
    /* A tall panel (wide layout) gets one item per row, a short one pairs. */
    int per_row = r.h - 1 >= 6 ? 1 : 2, half = r.w / 2;
    for (int k = 0, row = 1; k < 6 && row < r.h; k += per_row, row++) {
        acbb_put(a, r.y + row, r.x, per_row == 1 ? r.w : half - 1, ACBB_ROLE_NORMAL, "%s", item[k]);
        if (per_row == 2) acbb_put(a, r.y + row, r.x + half, r.w - half, ACBB_ROLE_NORMAL, "%s", item[k + 1]);
    }
}

/* A run following a [schedule] (schedule.h): the row reached and the speed
 * there, after the state text. */
static void schedule_text(const acbb_app *a, char *buf, size_t n)
{
    const acbb_scene *sc = &a->st.scene;
    if (sc->schedule_n == 0 || a->st.phase == ACBB_WORKER_NO_SIM) return;
    acbb_operating op;
    if (sc->thermal_mode == ACBB_THERMAL_STEADY || !sc->heating) acbb_schedule_final(sc, &op);
    else acbb_schedule_at(sc, a->st.snap.time, &op);
    size_t used = strlen(buf);
    if (used + 1 < n)
        snprintf(buf + used, n - used, " Schedule row %d/%d, %.0f rpm%s.", op.row, op.n_rows,
                 acbb_rads_to_rpm(op.inner_speed), op.finished ? ", done" : "");
}

/* What the run is doing, in words: never "running" when nothing runs
 * (at launch, after R, after x), and a failure's reason in full. */
void acbb_run_state_text(const acbb_app *a, char *buf, size_t n, acbb_role *role)
{
    const acbb_snapshot *s = &a->st.snap;
    *role = ACBB_ROLE_NORMAL;
    switch (a->st.phase) {
    case ACBB_WORKER_IDLE: snprintf(buf, n, "Idle at ambient: r starts a run."); break;
    case ACBB_WORKER_RUNNING:
        snprintf(buf, n, "Running: t = %.0f s, step %.3g s, heating towards steady state.", s->time, s->dt);
        break;
    case ACBB_WORKER_PAUSED: snprintf(buf, n, "Paused at t = %.0f s (space resumes).", s->time); break;
    case ACBB_WORKER_STOPPED:
        snprintf(buf, n, "Stopped by the user at t = %.0f s (r runs again).", s->time);
        break;
    case ACBB_WORKER_DONE:
        *role = s->state == ACBB_RUN_CONVERGED ? ACBB_ROLE_OK : ACBB_ROLE_ERROR;
        snprintf(buf, n, "%s: %s", s->state == ACBB_RUN_CONVERGED ? "Steady state" : "Run failed",
                 s->message);
        break;
    case ACBB_WORKER_NO_SIM:
        *role = ACBB_ROLE_ERROR;
        snprintf(buf, n, "No simulation: %s", a->st.message);
        break;
    }
    schedule_text(a, buf, n);
}

/* A life in hours, "%.3g"; ">1e+09" at the cap lives are reported as
 * (ACBB_LIFE_CAP_H: the true life is longer, issue 29 item 7). */
static void fmt_life(double h, char *buf, size_t n)
{
    snprintf(buf, n, "%s%.3g", h >= ACBB_LIFE_CAP_H ? ">" : "", h);
}

/* One line of rating life and static safety (MODEL.md 15, life.h) of the
 * bearing shown (a set's chosen one: the worker publishes its snapshot):
 * C, L10r, Lnm, s0 and the shoulder margin, then a_ISO and kappa (Lnm =
 * a1 a_ISO L10r, so a_ISO says why Lnm is 50 x L10r at its cap). The
 * widest form that fits: double-spaced with both, single-spaced with
 * both, with a_ISO alone, without them (never cut inside a number). */
static int life_line(acbb_app *a, int y, acbb_rect r)
{
    const acbb_life *L = &a->st.snap.life;
    if (r.h < 6) return 0;
    char who[16] = "", edge[48], line[256], l10[24], lnm[24];
    if (a->st.snap.n_bearings > 1) snprintf(who, sizeof who, " b%d", a->bearing);
    if (L->edge_ball < 0) snprintf(edge, sizeof edge, "edge -");
    else snprintf(edge, sizeof edge, "%s %.1f deg", L->edge_loaded ? "EDGE" : "edge", L->edge_margin_deg);
    fmt_life(L->L10r_h, l10, sizeof l10);
    fmt_life(L->Lnmr_h, lnm, sizeof lnm);
    static const struct { int gap, extra; } forms[] = { { 2, 2 }, { 1, 2 }, { 1, 1 }, { 2, 0 }, { 1, 0 } };
    for (size_t f = 0; f < sizeof forms / sizeof forms[0]; f++) {
        int gap = forms[f].gap;
        int n = snprintf(line, sizeof line, "Life%s: C %.3g kN%s%*sL10r %s h%*sLnm %s h%*ss0 %.3g%*s%s", who,
                         L->C * 1e-3, L->estimated ? " est." : "", gap, "", l10, gap, "", lnm, gap, "",
                         L->s0_min, gap, "", edge);
        if (n > 0 && forms[f].extra > 0 && (size_t)n < sizeof line)
            n += snprintf(line + n, sizeof line - (size_t)n, "%*sa_ISO %.3g", gap, "", L->a_iso);
        if (n > 0 && forms[f].extra > 1 && (size_t)n < sizeof line)
            n += snprintf(line + n, sizeof line - (size_t)n, "%*skappa %.3g%s", gap, "", L->kappa,
                          L->kappa_clamped ? " (<0.1: a_ISO at 0.1)" : "");
        if (n <= r.w) break;
    }
    acbb_put(a, y, r.x, r.w, L->edge_loaded ? ACBB_ROLE_ERROR : ACBB_ROLE_NORMAL, "%s", line);
    return 1;
}

/* The state line(s) at the top of r, the chart of the ring and ball
 * temperatures below. */
static void state_and_chart(acbb_app *a, acbb_rect r)
{
    char text[512];
    acbb_role role;
    acbb_run_state_text(a, text, sizeof text, &role);
    int used = acbb_put_wrap(a, r.y, r.x, r.w, 3, role, text);
    /* With a baseline pinned, an input the running scene cannot feel
     * explains a change of 0 (issue 29 item 1: preload_N under a force
     * preload showed +0.00 everywhere, silently). */
    acbb_inactive_effect in[4];
    if (rn(a)->has_base && r.h > 8 && acbb_scene_inactive_effects(&a->st.scene, in, 4) > 0) {
        snprintf(text, sizeof text, "note: %s has no effect here: %s", in[0].key, in[0].why);
        used += acbb_put_wrap(a, r.y + used, r.x, r.w, 2, ACBB_ROLE_WARN, text);
    }
    used += life_line(a, r.y + used, r);
    acbb_rect c = { r.y + used, r.x, r.h - used, r.w };
    acbb_draw_temp_chart(a, c);
}

static void draw(acbb_app *a)
{
    if (!a->st.has_snapshot) {
        acbb_put_wrap(a, a->lay.body.y + 1, 2, a->lay.body.w - 4, 4, ACBB_ROLE_ERROR,
                      a->st.message[0] ? a->st.message : "no simulation yet");
        return;
    }
    if (rn(a)->bigview) {
        acbb_draw_bigview(a, a->lay.body, rn(a)->has_base ? &rn(a)->base : NULL);
        return;
    }
    temps_panel(a, a->lay.temps);
    losses_panel(a, a->lay.losses);
    mech_panel(a, a->lay.mech);
    state_and_chart(a, a->lay.chart);
}

/* m: pin the result on screen as the what-if baseline; M clears it. */
void acbb_screen_run_pin(acbb_app *a, int pin)
{
    run_ui *p = rn(a);
    if (!pin) {
        p->has_base = 0;
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "baseline cleared");
    } else if (!a->st.has_snapshot) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "no result to pin yet (r runs one)");
    } else {
        p->base = a->st.snap;
        p->has_base = 1;
        acbb_app_msg(a, ACBB_ROLE_OK, "baseline pinned (t = %.0f s): Run shows changes against it; M clears",
                     p->base.time);
    }
}

/* v: the presentation view or the panels, on this screen. */
void acbb_screen_run_view(acbb_app *a)
{
    rn(a)->bigview = !rn(a)->bigview;
    acbb_screen_show(a, acbb_screen_index(&acbb_screen_run));
    acbb_app_msg(a, ACBB_ROLE_NORMAL, rn(a)->bigview ? "presentation view (v: back)" : "panels view");
}

/* Another preset was opened: a baseline of the last one means nothing here. */
static void drop(acbb_app *a) { rn(a)->has_base = 0; }

const acbb_screen acbb_screen_run = {
    .name = "Run", .key = '1', .draw = draw, .state_size = sizeof(run_ui), .drop = drop,
};
