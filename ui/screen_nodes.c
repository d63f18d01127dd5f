/* acbb TUI — every node temperature of the thermal network, in columns. */
#include <curses.h>
#include <string.h>
#include <strings.h>
#include "screens.h"

extern const acbb_screen acbb_screen_nodes;

/* This screen's own state (screens.h init). */
typedef struct {
    int top;                       /* first node shown */
    int hit;                       /* the node the last search found */
} nodes_ui;

static nodes_ui *nd(const acbb_app *a)
{
    return acbb_screen_state(a, &acbb_screen_nodes);
}

static int rows_per_col(const acbb_app *a)
{
    int r = a->lay.table_rows;
    return r < 1 ? 1 : r;
}

static void draw(acbb_app *a)
{
    const acbb_snapshot *s = &a->st.snap;
    acbb_rect b = a->lay.body;
    int ncol = a->lay.node_columns, per = rows_per_col(a);
    int cw = b.w / ncol;
    double amb = a->st.scene.ambient_C;
    acbb_put(a, b.y, b.x, b.w, ACBB_ROLE_HEADER,
             "%d nodes (C, rise above ambient %.1f)   j/k PgUp/PgDn scroll", s->n_nodes, amb);
    for (int c = 0; c < ncol; c++) {
        for (int r = 0; r < per - 1; r++) {
            int i = nd(a)->top + c * (per - 1) + r;
            if (i >= s->n_nodes) return;
            const char *name = s->node_names ? s->node_names[i] : "?";
            acbb_role role = i == nd(a)->hit ? ACBB_ROLE_SELECTED : ACBB_ROLE_NORMAL;
            /* A name longer than its column ends in an ellipsis, not silently
             * cut (issue 29 item 7); / finds a node by any part of it. */
            int nw = cw - 1 - 14, x = b.x + c * cw; /* " 123.45 +12.34" */
            if (nw < 8) nw = 8;
            if ((int)strlen(name) <= nw) acbb_put(a, b.y + 1 + r, x, nw, role, "%s", name);
            else acbb_put(a, b.y + 1 + r, x, nw, role, "%.*s%s", nw - 1, name, a->term.g.ellipsis);
            acbb_put(a, b.y + 1 + r, x + nw, cw - 1 - nw, role, " %6.2f %+6.2f", s->T[i], s->T[i] - amb);
        }
    }
}

static int on_key(acbb_app *a, int ch)
{
    int page = (rows_per_col(a) - 1) * a->lay.node_columns;
    return acbb_scroll_key(ch, page, a->st.snap.n_nodes, &nd(a)->top);
}

/* `/`: the next node whose name holds the text (e.g. /raceway, /shaft). */
static int search(acbb_app *a, const char *text, int dir)
{
    const acbb_snapshot *s = &a->st.snap;
    int n = s->n_nodes, from = nd(a)->hit >= 0 && nd(a)->hit < n ? nd(a)->hit : 0;
    size_t len = strlen(text);
    for (int k = dir == 0 ? 0 : 1; n > 0 && k <= n; k++) {
        int i = ((from + (dir < 0 ? -k : k)) % n + n) % n;
        const char *name = s->node_names ? s->node_names[i] : "";
        for (const char *p = name; *p; p++)
            if (strncasecmp(p, text, len) == 0) {
                int page = (rows_per_col(a) - 1) * a->lay.node_columns;
                nd(a)->hit = i;
                if (i < nd(a)->top || i >= nd(a)->top + page) nd(a)->top = i;
                if (nd(a)->top > n - page) nd(a)->top = n - page;
                if (nd(a)->top < 0) nd(a)->top = 0;
                return 1;
            }
    }
    return 0;
}

static const acbb_help_line help[] = {
    { "/  n  N", "find a node by name, next / previous" },
    { "j k PgUp/Dn", "scroll the nodes" },
    { NULL, NULL },
};

const acbb_screen acbb_screen_nodes = {
    .state_size = sizeof(nodes_ui),
    .name = "Nodes", .key = '2', .draw = draw, .on_key = on_key, .help = help, .search = search,
};
