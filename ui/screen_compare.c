/* acbb TUI — TE vs WTE: the edited scene run to steady state with
 * effects.thermal_expansion on and off (the seed's comparison), side by
 * side with the difference. The worker runs both (ACBB_CMD_COMPARE). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "acbb/units.h"
#include "loss_rows.h"
#include "results.h"
#include "screens.h"

extern const acbb_screen acbb_screen_compare;

typedef struct {
    int hidden;                    /* the result belongs to a preset no longer open (results.c) */
    acbb_scene ran_on;             /* the scene its last job started on (results.c) */
} compare_ui;

static compare_ui *cmp(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_compare);
}

typedef struct {
    const char *name;
    size_t off;      /* offset of a double in acbb_snapshot */
    double scale;
    int detail;      /* 1: shown only when the body has room (the squeeze comes first) */
} row_spec;

#define ROOM_FOR_DETAIL 32 /* body rows that hold every row */

static double field(const acbb_snapshot *s, size_t off)
{
    return *(const double *)((const char *)s + off);
}

static void ball_row(acbb_app *a, int y, const acbb_compare_result *c, const char *name,
                     size_t off, double scale)
{
    double v[2];
    for (int k = 0; k < 2; k++)
        v[k] = c->snap[k].n_balls > 0 ? *(const double *)((const char *)&c->snap[k].balls[0] + off) * scale
                                      : NAN;
    acbb_put(a, y, a->lay.body.x, a->lay.body.w, ACBB_ROLE_NORMAL, "%-24s %12.3f %12.3f %+12.3f",
             name, v[0], v[1], v[0] - v[1]);
}

/* Why TE raises or lowers the loads, in numbers (MODEL.md 13): the
 * squeeze terms of each variant in um, the net first, then one line that
 * says what the sign means. Returns the next free row. */
static int squeeze_rows(acbb_app *a, int y, const acbb_compare_result *c)
{
    const acbb_rect b = a->lay.body;
    const row_spec rows[] = {
        { "Squeeze net um", offsetof(acbb_snapshot, squeeze.net), 1e6, 0 },
        { "  inner ring thermal", offsetof(acbb_snapshot, squeeze.inner_thermal), 1e6, 0 },
        { "  inner centrifugal", offsetof(acbb_snapshot, squeeze.inner_centrifugal), 1e6, 0 },
        { "  outer ring (-)", offsetof(acbb_snapshot, squeeze.outer), 1e6, 0 },
        { "  ball", offsetof(acbb_snapshot, squeeze.ball), 1e6, 0 },
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0] && y < b.y + b.h; i++) {
        double v0 = field(&c->snap[0], rows[i].off) * rows[i].scale;
        double v1 = field(&c->snap[1], rows[i].off) * rows[i].scale;
        acbb_put(a, y++, b.x, b.w, i == 0 ? ACBB_ROLE_HEADER : ACBB_ROLE_NORMAL,
                 "%-24s %12.3f %12.3f %+12.3f", rows[i].name, v0, v1, v0 - v1);
    }
    if (y < b.y + b.h && c->phase == ACBB_CMP_DONE && c->ok[0]) {
        double net = c->snap[0].squeeze.net * 1e6;
        char text[256];
        snprintf(text, sizeof text,
                 "TE net %+.3f um: %s (net > 0 squeezes the balls: loads rise, angles fall; < 0 loosens)",
                 net, net > 0 ? "the balls are squeezed, loads rise" : "the balls are loosened, loads fall");
        y += acbb_put_wrap(a, y, b.x, b.w, b.y + b.h - y, ACBB_ROLE_OK, text);
    }
    return y;
}

/* Rows TE, WTE, TE-WTE; detail rows only when the body has room. Returns
 * the next free row. */
static int put_rows(acbb_app *a, int y, const acbb_compare_result *c, const row_spec *rows,
                    size_t n)
{
    const acbb_rect b = a->lay.body;
    for (size_t i = 0; i < n && y < b.y + b.h; i++) {
        if (rows[i].detail && b.h < ROOM_FOR_DETAIL) continue;
        double v0 = field(&c->snap[0], rows[i].off) * rows[i].scale;
        double v1 = field(&c->snap[1], rows[i].off) * rows[i].scale;
        acbb_put(a, y++, b.x, b.w, ACBB_ROLE_NORMAL, "%-24s %12.3f %12.3f %+12.3f", rows[i].name, v0,
                 v1, v0 - v1);
    }
    return y;
}

/* Every loss the compared scene switches on, from the loss table (detail
 * rows under the total). */
static int loss_rows(acbb_app *a, int y, const acbb_compare_result *c)
{
    acbb_loss_kind k[ACBB_LOSS_KINDS];
    int n = acbb_loss_rows(&cmp(a)->ran_on, k);
    char label[ACBB_LOSS_KINDS][32];
    row_spec rows[ACBB_LOSS_KINDS];
    for (int i = 0; i < n; i++) {
        acbb_loss_row_label(k[i], label[i], sizeof label[i]);
        rows[i] = (row_spec){ label[i], offsetof(acbb_snapshot, losses.P) + (size_t)k[i] * sizeof(double),
                              1, 1 };
    }
    return put_rows(a, y, c, rows, (size_t)n);
}

static void draw(acbb_app *a)
{
    const acbb_compare_result *c = &a->st.compare;
    acbb_rect b = a->lay.body;
    int y = b.y;
    acbb_put(a, y++, b.x, b.w, ACBB_ROLE_HEADER,
             "TE vs WTE: the edited scene with thermal expansion on / off   t: run");
    if (c->phase == ACBB_CMP_NONE) {
        const char *note = acbb_results_note(a, &acbb_screen_compare);
        if (note) acbb_put_wrap(a, y + 3, b.x + 2, b.w - 2, 2, ACBB_ROLE_DIM, note);
        acbb_put(a, y + 1, b.x + 2, b.w - 2, ACBB_ROLE_NORMAL,
                 "Press t to run both variants to steady state.");
        return;
    }
    const char *st[2];
    char it[2][32];
    for (int k = 0; k < 2; k++) {
        st[k] = c->ok[k] ? acbb_run_status_name(&c->snap[k])
                : c->done[k] || c->phase == ACBB_CMP_DONE ? "failed" : "running";
        snprintf(it[k], sizeof it[k], "%ld", c->snap[k].iteration);
    }
    acbb_put(a, y++, b.x, b.w, ACBB_ROLE_HEADER, "%-24s %12s %12s %12s", "", "TE", "WTE", "TE-WTE");
    acbb_put(a, y++, b.x, b.w, ACBB_ROLE_NORMAL, "%-24s %12s %12s", "status", st[0], st[1]);
    acbb_put(a, y++, b.x, b.w, ACBB_ROLE_NORMAL, "%-24s %12s %12s", "iterations", it[0], it[1]);
    char outer[48];
    acbb_run_outer_label(&c->snap[0], outer, sizeof outer);
    strcat(outer, " T C");
    const row_spec heat[] = {
        { outer, offsetof(acbb_snapshot, T_outer_ring), 1, 0 },
        { "Inner ring T C", offsetof(acbb_snapshot, T_inner_ring), 1, 0 },
        { "Ball T C", offsetof(acbb_snapshot, T_ball), 1, 0 },
        { "Housing T C", offsetof(acbb_snapshot, T_housing), 1, 1 },
        { "Total loss W", offsetof(acbb_snapshot, losses.total), 1, 0 },
    };
    y = put_rows(a, y, c, heat, sizeof heat / sizeof heat[0]);
    y = loss_rows(a, y, c);
    const row_spec rest[] = {
        { "IR growth thermal um", offsetof(acbb_snapshot, exp_inner), 1e6, 0 },
        { "OR growth um", offsetof(acbb_snapshot, exp_outer), 1e6, 0 },
        /* What heat costs in life (MODEL.md 15). */
        { "Life L10r h", offsetof(acbb_snapshot, life.L10r_h), 1, 1 },
        { "Life Lnmr h", offsetof(acbb_snapshot, life.Lnmr_h), 1, 0 },
        { "  kappa", offsetof(acbb_snapshot, life.kappa), 1, 1 },
        { "  static safety s0", offsetof(acbb_snapshot, life.s0_min), 1, 1 },
    };
    y = put_rows(a, y, c, rest, sizeof rest / sizeof rest[0]);
    const double R2D = 1.0 / ACBB_DEG /* deg per rad */;
    if (y < b.y + b.h) ball_row(a, y++, c, "Qi ball 0 N", offsetof(acbb_ball_view, Qi), 1);
    if (y < b.y + b.h) ball_row(a, y++, c, "Qo ball 0 N", offsetof(acbb_ball_view, Qo), 1);
    if (y < b.y + b.h) ball_row(a, y++, c, "alpha_i ball 0 deg", offsetof(acbb_ball_view, alpha_i), R2D);
    if (y < b.y + b.h) ball_row(a, y++, c, "alpha_o ball 0 deg", offsetof(acbb_ball_view, alpha_o), R2D);
    y = squeeze_rows(a, y, c);
    if (c->message[0] && y < b.y + b.h)
        acbb_put_wrap(a, y, b.x, b.w, b.y + b.h - y, ACBB_ROLE_ERROR, c->message);
}

/* ---- the comparison's lifecycle (screens.h): the worker runs it, this
 * screen decides whether its result still belongs to the open scene ---- */

static void poll(acbb_app *a)
{
    if (cmp(a)->hidden ||
        acbb_results_stale(a, &acbb_screen_compare, &cmp(a)->ran_on, a->st.compare.phase == ACBB_CMP_DONE))
        memset(&a->st.compare, 0, sizeof a->st.compare);
}

static void drop(acbb_app *a) { cmp(a)->hidden = 1; }

static int running(const acbb_app *a) { return a->st.compare.phase == ACBB_CMP_RUNNING; }

const acbb_screen acbb_screen_compare = {
    .name = "TE/WTE", .key = '6', .draw = draw,
    .hint = "t run TE vs WTE  r run  ? help  q quit",
    .state_size = sizeof(compare_ui), .poll = poll, .drop = drop, .running = running,
    .job_subject = "The TE/WTE comparison", .job_noun = "comparison",
};

/* `t` is global: it starts the comparison from any screen and shows this one. */
void acbb_screen_compare_start(acbb_app *a)
{
    acbb_app_post(a, ACBB_CMD_COMPARE, &a->ed.scene, 0, "TE vs WTE comparison started");
    cmp(a)->hidden = 0; /* this one belongs to the open preset */
    cmp(a)->ran_on = a->ed.scene;
    acbb_screen_show(a, acbb_screen_index(&acbb_screen_compare));
}

