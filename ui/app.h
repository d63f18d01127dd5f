/* acbb TUI — the application state shared by the event loop and screens.
 *
 * Owned by the UI thread only. Engine state never appears here: `st` and
 * `hist` are copies of what the worker published, taken once per frame. */
#ifndef ACBB_UI_APP_H
#define ACBB_UI_APP_H

#include <limits.h>
#include "acbb/tools/history.h"
#include "bench.h"
#include "chart.h"
#include "editor.h"
#include "layout.h"
#include "picker.h"
#include "progress.h"
#include "term.h"
#include "whatif.h"
#include "worker.h"

typedef enum {
    ACBB_MODE_NORMAL, ACBB_MODE_PROMPT, ACBB_MODE_CONFIRM, ACBB_MODE_HELP, ACBB_MODE_BROWSE
} acbb_mode;

typedef enum {
    ACBB_PROMPT_VALUE, ACBB_PROMPT_SAVE_AS, ACBB_PROMPT_OPEN, ACBB_PROMPT_SEARCH,
    ACBB_PROMPT_CALL               /* a screen's question: prompt.commit gets the answer */
} acbb_prompt_kind;
typedef enum { ACBB_CONFIRM_QUIT, ACBB_CONFIRM_OPEN, ACBB_CONFIRM_RECOVER,
               ACBB_CONFIRM_CHANGED, ACBB_CONFIRM_QUIT_RUN } acbb_confirm_kind;

#define ACBB_BROWSE_MAX 64

/* A chart's axis ranges kept between frames, so they only widen while
 * `key` (run and x mode) stays the same (draw_chart.c). */
typedef struct {
    unsigned long key;
    int valid;
    double r[4];                   /* xlo, xhi, ylo, yhi */
} acbb_axis_memo;

#define ACBB_MAX_TABS 16

typedef struct acbb_app acbb_app;
typedef void (*acbb_prompt_fn)(acbb_app *a, const char *text);

struct acbb_app {
    acbb_term term;
    acbb_layout lay;
    acbb_worker *worker;
    acbb_worker_state st;          /* copy of the worker's published state */
    acbb_history hist;             /* copy of the worker's history */
    acbb_editor ed;
    acbb_progress prog;
    unsigned long prog_run;        /* run the progress estimate belongs to */
    int screen;                    /* index into acbb_screens (screens.c) */
    acbb_mode mode;
    struct {
        acbb_prompt_kind kind;
        char label[128];
        char buf[PATH_MAX];
        size_t len;
        acbb_prompt_fn commit;     /* ACBB_PROMPT_CALL: the answer goes here */
        acbb_name_fn names;        /* Tab completes among these (NULL: no completion) */
        char shown[256];           /* the last completion's matches */
    } prompt;
    struct {
        acbb_confirm_kind kind;
        char path[PATH_MAX];       /* file to open after the answer */
    } confirm;
    struct {
        char names[ACBB_BROWSE_MAX][256];
        int n, sel;
    } browse;
    char msg[512];                 /* message line */
    acbb_role msg_role;
    unsigned long msg_cmd;         /* the message announces this worker command (0: none) */
    char edit_error[512];          /* last refused value, shown in the editor */
    int pace_idx;
    char plot_dir[PATH_MAX];
    bool (*installed)(const char *path, char *dir, size_t n); /* NULL: none */
    int help_top;                  /* the `?` screen (a mode, not a tab): first row shown */
    unsigned long shown_err;       /* worker error already shown */
    int exit_after_steady;
    unsigned long start_cmd;       /* command that started the watched run */
    unsigned acc_knobs;            /* the accuracy screen's knob mask for b/B (0 = all; --knobs) */
    int quit, exit_code;
    char leave_msg[768];      /* printed once the terminal is restored (recover.c) */
    acbb_chart chart;              /* scratch raster */
    acbb_axis_memo run_memo;       /* the Run screen's temperature chart (draw_chart.c) */
    char search[64];               /* last / search */
    int mouse;                     /* mouse reports on */
    int search_help;               /* the / prompt searches the help */
    int help_hit;                  /* help row of the last search hit */
    int bearing;                   /* a set's bearing the screens show (screen_set.c) */
    void *screen_state[ACBB_MAX_TABS]; /* each screen's own (screens.h init), by table index */
    int tab_x0[ACBB_MAX_TABS], tab_x1[ACBB_MAX_TABS]; /* columns of each tab, as drawn */
    unsigned edit_hid;             /* bit per screen index: an edit of the scene hid its job's result (results.c) */
};

/* Options from the command line. */
typedef struct {
    const char *preset;            /* NULL: presets/7008C.ini */
    const char *plot_dir;          /* NULL: ./acbb-plots */
    int pace;                      /* simulated s per wall s, 0 = flat out, -1 = the default */
    int exit_after_steady;
    unsigned acc_knobs;            /* accuracy plan knob mask (0 = all) */
    int no_mouse;                  /* --no-mouse: never ask the terminal for mouse reports */
    bool (*installed)(const char *path, char *dir, size_t n); /* acbb_tui_args's */
} acbb_app_options;

/* Run the TUI until the user quits; returns the exit code. */
int acbb_app_run(const acbb_app_options *opt);

/* Message line (printf-style). */
void acbb_app_msg(acbb_app *a, acbb_role role, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Pace ladder: simulated seconds per wall second for index i (0 = flat out). */
int acbb_app_pace(int idx);
/* Open a preset into the editor (asks first when there are unsaved edits). */
void acbb_app_open(acbb_app *a, const char *path);
/* Begin a line prompt on the message row. */
void acbb_app_prompt(acbb_app *a, acbb_prompt_kind kind, const char *label, const char *init);
/* A screen's question on the message row: Enter calls commit(a, text),
 * Tab completes among names (NULL: none), Esc drops it. */
void acbb_app_ask(acbb_app *a, const char *label, const char *init, acbb_prompt_fn commit,
                  acbb_name_fn names);

/* ---- drawing helpers (draw.c) ---- */
void acbb_role_on(acbb_app *a, acbb_role r);
/* Print at (y, x), clipped to w columns, in role r. */
void acbb_put(acbb_app *a, int y, int x, int w, acbb_role r, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
/* Text wrapped at spaces into rows of w columns, at most max_rows (the
 * last one marked as cut if the text goes on); returns the rows drawn. */
int acbb_put_wrap(acbb_app *a, int y, int x, int w, int max_rows, acbb_role r, const char *text);
/* Rows acbb_put_wrap needs for the whole text. */
int acbb_wrap_count(const char *text, int w);
/* Horizontal bar of w cells filled to fraction f (eighths with UTF-8). */
void acbb_bar(acbb_app *a, int y, int x, int w, double f, acbb_role r);
void acbb_hrule(acbb_app *a, int y, int x, int w);
/* A background job's progress: "running 3/9 points [bar] 1.2s  x/Esc cancels"
 * ("cancelling" once asked), `what` naming the units counted. */
void acbb_draw_job_line(acbb_app *a, int y, int x, int w, int cancelling, double started_s,
                        size_t done, size_t total, const char *what);
/* Scroll keys (j k arrows PgUp PgDn Home) over n rows shown `page` at a
 * time: updates *top within [0, n - page]; returns 1 if ch was one of them. */
int acbb_scroll_key(int ch, int page, int n, int *top);
/* One chart: up to 3 series of n points against x (draw_chart.c). */
typedef struct {
    const char *title, *yunit, *xunit;
    const double *x;
    const double *const *ys;
    const char *const *names;
    int nser;
    size_t n;
    int polish;                    /* the last point is the steady solve: marked, not joined */
    double floor_y;                /* a value the y axis must include (NAN: none) */
    acbb_axis_memo *memo;          /* widen-only ranges; NULL: fit every frame */
    unsigned long memo_key;
    int x_fixed;                   /* the x axis spans [x0, x1] (else 0 .. the data) */
    double x0, x1;
} acbb_chart_spec;
void acbb_chart_draw(acbb_app *a, acbb_rect r, const acbb_chart_spec *sp);
/* The raster's cells at (y, x), each in the role of the series that drew
 * it; where two share a cell one moves a row aside, else the shared mark
 * is drawn (returns 1 then: the legend must name it). */
int acbb_chart_blit(acbb_app *a, const acbb_chart *c, int y, int x, const acbb_role *roles, int nroles);
/* The Run screen's ring and ball temperatures chart. */
void acbb_draw_temp_chart(acbb_app *a, acbb_rect r);
/* 1 when the history ends with the converged run's steady solve. */
int acbb_app_polished(const acbb_app *a);
/* The presentation view, changes against base (NULL: none) (bigview.c). */
void acbb_draw_bigview(acbb_app *a, acbb_rect r, const acbb_snapshot *base);
/* ---- the Run screen's words and global keys (screen_run.c) ---- */
void acbb_screen_run_pin(acbb_app *a, int pin); /* m pins the result as the baseline, M (0) clears it */
void acbb_screen_run_view(acbb_app *a);         /* v: the presentation view or the panels */
void acbb_run_state_text(const acbb_app *a, char *buf, size_t n, acbb_role *role);
void acbb_run_outer_label(const acbb_snapshot *s, char *buf, size_t n);
/* "+1.23 +4.5%": v against base, the percentage of |ref|. */
void acbb_fmt_delta(double v, double base, double ref, char *buf, size_t n);
/* The accuracy screen's error-vs-time chart of benchmark state st in rect (draw_acc_chart.c). */
void acbb_draw_accuracy_chart(acbb_app *a, acbb_rect r, const acbb_bench_state *st);
/* "1h02m", "12.3s", "--" for unknown. */
void acbb_fmt_duration(double s, char *buf, size_t n);
/* "x200" (simulated seconds per wall second) or "max" for 0. */
void acbb_fmt_pace(int pace, char *buf, size_t n);

/* ---- the bars around every screen (bars.c) ---- */
void acbb_draw_title(acbb_app *a);
void acbb_draw_status(acbb_app *a);

/* ---- what screens offer beyond their descriptor (screens.h) ---- */
/* The preset browser, a modal overlay (screen_editor.c). */
void acbb_screen_browse_begin(acbb_app *a);
/* After an accepted edit: the usual hint, or a warning naming a switch or
 * input that now has no effect (acbb_scene_inactive_effects), so the TUI
 * says what the CLI's note says. */
void acbb_screen_editor_edited(acbb_app *a, const char *hint);
void acbb_screen_browse_draw(acbb_app *a);
int acbb_screen_browse_key(acbb_app *a, int ch);
/* Export every plot kind as PNG+SVG (screen_plot.c; the global g). */
void acbb_screen_plot_export(acbb_app *a);
/* Run TE vs WTE on the edited scene and show it (screen_compare.c; t). */
void acbb_screen_compare_start(acbb_app *a);
/* Start the benchmark on the edited scene (with the dynamic level or not). */
void acbb_screen_accuracy_start(acbb_app *a, int with_dynamic);
/* The metric path and label of menu entry i (the last: a typed metric). */
const char *acbb_whatif_metric(const acbb_app *a, int i, const char **label);
/* Entries in the metric menu (with the typed one when there is one). */
int acbb_whatif_metric_count(const acbb_app *a);
/* A typed metric path becomes the menu's last entry and *slot its index;
 * 0 (and a message) if it names no metric. */
int acbb_whatif_metric_set(acbb_app *a, const char *text, int *slot);
/* The `?` screen, generated from the table (a mode, not a tab). */
void acbb_screen_help_draw(acbb_app *a);
int acbb_screen_help_key(acbb_app *a, int ch);
/* `/` n N: search keys on the current screen (in_help: the help); 1 if used. */
int acbb_app_search_key(acbb_app *a, int ch, int in_help);
/* Search the help rows for text (help screen). */
int acbb_screen_help_search(acbb_app *a, const char *text, int dir);
/* Handle one key as if typed (the mouse presses keys this way). */
void acbb_app_key(acbb_app *a, int ch);
/* A mouse event is waiting (KEY_MOUSE): act on it (mouse.c). */
void acbb_app_mouse(acbb_app *a);
/* A mouse report that arrived as keys k[0..n) (mouse.c): the keys used,
 * 0 if k does not start with one. Pure. */
int acbb_mouse_decode(const int *k, int n, int *button, int *x, int *y, int *press);
/* Act on a decoded report (only presses act; nothing with --no-mouse). */
void acbb_app_mouse_raw(acbb_app *a, int button, int x, int y, int press);
/* The message-row hint of the current screen. */
const char *acbb_app_hint(const acbb_app *a);
#define ACBB_RUN_HINT "r run  space pause  x stop  +/- pace  v view  m base  g plots  ? help  q quit"
/* Post a command to the worker, saying so on the message line (app.c). */
void acbb_app_post(acbb_app *a, acbb_worker_cmd cmd, const acbb_scene *s, int warm, const char *what);

#endif
