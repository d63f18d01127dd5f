/* acbb TUI — the presentation view (v on the Run screen): the headline
 * numbers in digits five rows tall, readable from the back of a room at
 * 80x24 (a projector shows 24 rows about 1.5 m tall: a 5-row digit is
 * then ~30 cm), with the temperature chart below. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "acbb/units.h"
#include "app.h"

#define GLYPH_H 5

/* 3-column glyphs ('.' one column); '#' is a lit cell. */
static const char *glyph(char c)
{
    switch (c) {
    case '0': return "####.##.##.####";
    case '1': return ".#.##..#..#.###";
    case '2': return "###..#####..###";
    case '3': return "###..####..####";
    case '4': return "#.##.####..#..#";
    case '5': return "####..###..####";
    case '6': return "####..####.####";
    case '7': return "###..#..#..#..#";
    case '8': return "####.#####.####";
    case '9': return "####.####..####";
    case '-': return "......###......";
    case '+': return "....#.###.#....";
    case '/': return "..#..#.#.#..#..";
    case '.': return "....#";
    default: return "...............";
    }
}

static void big_text(acbb_app *a, int y, int x, int maxw, acbb_role role, const char *s)
{
    const char *on = a->term.g.utf8 ? "\u2588" : "#";
    acbb_role_on(a, role);
    for (; *s; s++) {
        const char *g = glyph(*s);
        int gw = *s == '.' ? 1 : 3;
        if (gw > maxw) break;
        for (int r = 0; r < GLYPH_H; r++)
            for (int c = 0; c < gw; c++)
                if (g[r * gw + c] == '#') mvaddstr(y + r, x + c, on);
        x += gw + 1;
        maxw -= gw + 1;
    }
    acbb_role_on(a, ACBB_ROLE_NORMAL);
}

typedef struct {
    char label[64], value[32], delta[112];
} headline;

/* The most loaded ball: its loads and angles are the ones a class asks about. */
static int loaded_ball(const acbb_snapshot *s)
{
    int k = 0;
    for (int i = 1; i < s->n_balls; i++)
        if (s->balls[i].Qi > s->balls[k].Qi) k = i;
    return k;
}

static void headlines(acbb_app *a, headline h[4], const acbb_snapshot *b)
{
    const acbb_snapshot *s = &a->st.snap;
    const double R2D = 1.0 / ACBB_DEG;
    int k = loaded_ball(s);
    const acbb_ball_view *v = &s->balls[k];
    char outer[32];
    acbb_run_outer_label(s, outer, sizeof outer);
    snprintf(h[0].label, sizeof h[0].label, "%s, C", outer);
    snprintf(h[0].value, sizeof h[0].value, "%.1f", s->T_outer_ring);
    snprintf(h[1].label, sizeof h[1].label, "Total loss, W");
    snprintf(h[1].value, sizeof h[1].value, "%.1f", s->losses.total);
    snprintf(h[2].label, sizeof h[2].label, "Qi/Qo, N (ball %d)", k);
    snprintf(h[2].value, sizeof h[2].value, "%.0f/%.0f", v->Qi, v->Qo);
    snprintf(h[3].label, sizeof h[3].label, "Contact angles in/out, deg");
    snprintf(h[3].value, sizeof h[3].value, "%.1f/%.1f", v->alpha_i * R2D, v->alpha_o * R2D);
    for (int i = 0; i < 4; i++) h[i].delta[0] = '\0';
    if (!b || s->n_balls == 0) return;
    const acbb_ball_view *vb = &b->balls[loaded_ball(b)];
    double amb = a->st.scene.ambient_C;
    acbb_fmt_delta(s->T_outer_ring, b->T_outer_ring, b->T_outer_ring - amb, h[0].delta, sizeof h[0].delta);
    acbb_fmt_delta(s->losses.total, b->losses.total, b->losses.total, h[1].delta, sizeof h[1].delta);
    char d[2][48];
    acbb_fmt_delta(v->Qi, vb->Qi, vb->Qi, d[0], sizeof d[0]);
    acbb_fmt_delta(v->Qo, vb->Qo, vb->Qo, d[1], sizeof d[1]);
    snprintf(h[2].delta, sizeof h[2].delta, "Qi %s Qo %s", d[0], d[1]);
    acbb_fmt_delta(v->alpha_i * R2D, vb->alpha_i * R2D, vb->alpha_i * R2D, d[0], sizeof d[0]);
    acbb_fmt_delta(v->alpha_o * R2D, vb->alpha_o * R2D, vb->alpha_o * R2D, d[1], sizeof d[1]);
    snprintf(h[3].delta, sizeof h[3].delta, "in %s out %s", d[0], d[1]);
}

void acbb_draw_bigview(acbb_app *a, acbb_rect r, const acbb_snapshot *base)
{
    headline h[4];
    headlines(a, h, base);
    int per_row = r.w >= 4 * 40 ? 4 : 2, cw = r.w / per_row, ch = GLYPH_H + 2;
    for (int i = 0; i < 4; i++) {
        int y = r.y + (i / per_row) * ch, x = r.x + (i % per_row) * cw;
        acbb_put(a, y, x, cw - 1, ACBB_ROLE_HEADER, "%s", h[i].label);
        big_text(a, y + 1, x + 1, cw - 2, ACBB_ROLE_NORMAL, h[i].value);
        if (h[i].delta[0]) /* the row under the digits */
            acbb_put(a, y + 1 + GLYPH_H, x, cw - 1, ACBB_ROLE_WARN, "%s%s", i < 2 ? "vs base " : "",
                     h[i].delta);
    }
    int used = (4 / per_row) * ch;
    char text[512];
    acbb_role role;
    acbb_run_state_text(a, text, sizeof text, &role);
    acbb_put(a, r.y + used, r.x, r.w, role, "%s   v: back to the panels", text);
    acbb_rect c = { r.y + used + 1, r.x, r.h - used - 1, r.w };
    acbb_draw_temp_chart(a, c);
}
