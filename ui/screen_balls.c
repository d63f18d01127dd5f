/* acbb TUI — the contact table: one row per ball with loads, angles,
 * sliding, spin and film, and bars of Qi and Qo so the load zone under a
 * radial load is visible at a glance. */
#include <curses.h>
#include <math.h>
#include "acbb/units.h"
#include "screens.h"

/* Column widths: the fixed part "%2d %5.1f %6.1f %6.1f %5.2f %5.2f %8.4f"
 * is 43 cells, spin_i 8, the films 14; the wide extras (slide_o, spin_o) 9 + 8. */
#define FIXED_W 65
#define EXTRA_W 17

/* The Hertz view (MODEL.md 2): load, maximum pressure and the semi-axes
 * of each contact ellipse, what hertz-contact's "Look at" asks for. */
extern const acbb_screen acbb_screen_balls;

/* This screen's own state (screens.h init). */
typedef struct {
    int top;                       /* first ball shown */
    int contact;                   /* 1 = Hertz columns (pmax, a, b), 0 = kinematics */
} balls_ui;

static balls_ui *bl(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_balls);
}

static void draw_contact(acbb_app *a)
{
    const acbb_snapshot *s = &a->st.snap;
    acbb_rect b = a->lay.body;
    const double R2D = 1.0 / ACBB_DEG, GPA = 1e-9, MM = 1e3;
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "%2s %5s %6s %6s %7s %7s %6s %6s %6s %6s  c: kinematics",
             "#", "psi", "Qi N", "Qo N", "pi GPa", "po GPa", "a_i mm", "b_i mm", "a_o mm", "b_o mm");
    for (int r = 0; r < a->lay.table_rows; r++) {
        int i = bl(a)->top + r;
        if (i >= s->n_balls) break;
        const acbb_ball_view *v = &s->balls[i];
        acbb_put(a, b.y + 1 + r, b.x, b.w, ACBB_ROLE_NORMAL,
                 "%2d %5.1f %6.1f %6.1f %7.3f %7.3f %6.3f %6.3f %6.3f %6.3f", i, v->psi * R2D, v->Qi,
                 v->Qo, v->pmax_i * GPA, v->pmax_o * GPA, v->a_i * MM, v->b_i * MM, v->a_o * MM,
                 v->b_o * MM);
    }
}

static void draw(acbb_app *a)
{
    if (bl(a)->contact) {
        draw_contact(a);
        return;
    }
    const acbb_snapshot *s = &a->st.snap;
    acbb_rect b = a->lay.body;
    const double R2D = 1.0 / ACBB_DEG /* deg per rad */, UM = 1e6;
    int wide = b.w - FIXED_W - EXTRA_W >= 30; /* room for the outer-race slide and spin */
    int used = FIXED_W + (wide ? EXTRA_W : 0);
    int bw = (b.w - used - 2) / 2;              /* two bars: Qi and Qo */
    char head[256];
    int n = snprintf(head, sizeof head, "%2s %5s %6s %6s %5s %5s %8s", "#", "psi", "Qi N", "Qo N",
                     "a_i", "a_o", "sl_i m/s");
    if (wide) n += snprintf(head + n, sizeof head - (size_t)n, " %8s", "sl_o m/s");
    n += snprintf(head + n, sizeof head - (size_t)n, " %7s", "spin_i");
    if (wide) n += snprintf(head + n, sizeof head - (size_t)n, " %7s", "spin_o");
    snprintf(head + n, sizeof head - (size_t)n, " %6s %6s  %s", "h_i um", "h_o um",
             bw >= 7 ? "Qi | Qo" : bw >= 3 ? "Qi|Qo" : "");
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER, "%s", head);
    double qmax = 1e-9;
    for (int i = 0; i < s->n_balls; i++) qmax = fmax(qmax, fmax(s->balls[i].Qi, s->balls[i].Qo));
    for (int r = 0; r < a->lay.table_rows; r++) {
        int i = bl(a)->top + r;
        if (i >= s->n_balls) break;
        const acbb_ball_view *v = &s->balls[i];
        char row[256];
        int m = snprintf(row, sizeof row, "%2d %5.1f %6.1f %6.1f %5.2f %5.2f %8.4f", i, v->psi * R2D,
                         v->Qi, v->Qo, v->alpha_i * R2D, v->alpha_o * R2D, v->slide_i);
        if (wide) m += snprintf(row + m, sizeof row - (size_t)m, " %8.4f", v->slide_o);
        m += snprintf(row + m, sizeof row - (size_t)m, " %7.1f", v->spin_i);
        if (wide) m += snprintf(row + m, sizeof row - (size_t)m, " %7.1f", v->spin_o);
        snprintf(row + m, sizeof row - (size_t)m, " %6.3f %6.3f", v->film_i * UM, v->film_o * UM);
        int y = b.y + 1 + r;
        acbb_put(a, y, b.x, b.w, ACBB_ROLE_NORMAL, "%s", row);
        if (bw >= 3) {
            acbb_bar(a, y, b.x + used + 1, bw, v->Qi / qmax, ACBB_ROLE_BAR);
            acbb_bar(a, y, b.x + used + 2 + bw, bw, v->Qo / qmax, ACBB_ROLE_BAR2);
        }
    }
}

static int on_key(acbb_app *a, int ch)
{
    if (ch == 'c') {
        bl(a)->contact = !bl(a)->contact;
        return 1;
    }
    return acbb_scroll_key(ch, a->lay.table_rows, a->st.snap.n_balls, &bl(a)->top);
}

static const acbb_help_line help[] = {
    { "j k PgUp/Dn", "scroll the balls" },
    { "c", "contact view: pmax and the semi-axes a, b of each ellipse / kinematics" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_balls = {
    .state_size = sizeof(balls_ui),
    .name = "Balls", .key = '3', .draw = draw, .on_key = on_key, .help = help,
    .hint = "c pmax/semi-axes  j/k scroll  r run  x stop  ? help  q quit",
};
