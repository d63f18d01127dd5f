/* acbb TUI — the application state shared by the event loop and screens.
 *
 * Owned by the UI thread only. Engine state never appears here: `st` and
 * `hist` are copies of what the worker published, taken once per frame. */
#ifndef ACBB_UI_APP_H
#define ACBB_UI_APP_H

#include <limits.h>
#include "acbb/history.h"
#include "bench.h"
#include "chart.h"
#include "editor.h"
#include "layout.h"
#include "progress.h"
#include "term.h"
#include "worker.h"

typedef enum {
    ACBB_MODE_NORMAL, ACBB_MODE_PROMPT, ACBB_MODE_CONFIRM, ACBB_MODE_HELP, ACBB_MODE_BROWSE
} acbb_mode;

typedef enum { ACBB_PROMPT_VALUE, ACBB_PROMPT_SAVE_AS, ACBB_PROMPT_OPEN } acbb_prompt_kind;
typedef enum { ACBB_CONFIRM_QUIT, ACBB_CONFIRM_OPEN } acbb_confirm_kind;

#define ACBB_BROWSE_MAX 64
#define ACBB_PREVIEW_MAX 65536

typedef struct {
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
    char edit_error[512];          /* last refused value, shown in the editor */
    int pace_idx;
    char plot_dir[PATH_MAX];
    int node_top, ball_top, help_top;
    int chart_by_time;             /* charts: x = simulated time (1) or iteration (0) */
    int plot_kind;                 /* preview kind (acbb_plot_kind) */
    char *preview;                 /* gnuplot dumb text, ACBB_PREVIEW_MAX bytes */
    int preview_ok;
    unsigned long shown_err;       /* worker error already shown */
    int exit_after_steady;
    unsigned long start_cmd;       /* command that started the watched run */
    /* accuracy screen */
    acbb_bench *bench;             /* the benchmark thread's hand-off */
    acbb_bench_state bst;          /* copy of its published state, once per frame */
    unsigned acc_knobs;            /* knob mask for b/B (0 = all) */
    char acc_scene[256];           /* name of the scene the benchmark ran on */
    unsigned long acc_seen_run;    /* run whose end was already announced */
    int acc_top;                   /* first table row shown */
    int quit, exit_code;
    acbb_chart chart;              /* scratch raster */
} acbb_app;

/* Options from the command line. */
typedef struct {
    const char *preset;            /* NULL: presets/7008C.ini */
    const char *plot_dir;          /* NULL: ./acbb-plots */
    int pace;                      /* steps per second, 0 = flat out */
    int exit_after_steady;
    unsigned acc_knobs;            /* accuracy plan knob mask (0 = all) */
} acbb_app_options;

/* Run the TUI until the user quits; returns the exit code. */
int acbb_app_run(const acbb_app_options *opt);

/* Message line (printf-style). */
void acbb_app_msg(acbb_app *a, acbb_role role, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Pace ladder: steps per second for index i (0 = flat out). */
int acbb_app_pace(int idx);
/* Open a preset into the editor (asks first when there are unsaved edits). */
void acbb_app_open(acbb_app *a, const char *path);
/* Begin a line prompt on the message row. */
void acbb_app_prompt(acbb_app *a, acbb_prompt_kind kind, const char *label, const char *init);

/* ---- drawing helpers (draw.c) ---- */
void acbb_role_on(acbb_app *a, acbb_role r);
/* Print at (y, x), clipped to w columns, in role r. */
void acbb_put(acbb_app *a, int y, int x, int w, acbb_role r, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
/* Horizontal bar of w cells filled to fraction f (eighths with UTF-8). */
void acbb_bar(acbb_app *a, int y, int x, int w, double f, acbb_role r);
void acbb_hrule(acbb_app *a, int y, int x, int w);
/* Scroll keys (j k arrows PgUp PgDn Home) over n rows shown `page` at a
 * time: updates *top within [0, n - page]; returns 1 if ch was one of them. */
int acbb_scroll_key(int ch, int page, int n, int *top);
/* A chart in rect: title row, y labels on the left; up to 3 series. */
void acbb_draw_chart(acbb_app *a, acbb_rect r, const char *title, const double *x,
                     const double *const *ys, const char *const *names, int nser, size_t n);
/* The accuracy screen's error-vs-time chart of a->bst in rect (draw_acc_chart.c). */
void acbb_draw_accuracy_chart(acbb_app *a, acbb_rect r);
/* "1h02m", "12.3s", "--" for unknown. */
void acbb_fmt_duration(double s, char *buf, size_t n);

/* ---- the bars around every screen (bars.c) ---- */
void acbb_draw_title(acbb_app *a);
void acbb_draw_status(acbb_app *a);

/* ---- what screens offer beyond their descriptor (screens.h) ---- */
/* The preset browser, a modal overlay (screen_editor.c). */
void acbb_screen_browse_begin(acbb_app *a);
void acbb_screen_browse_draw(acbb_app *a);
int acbb_screen_browse_key(acbb_app *a, int ch);
/* Export every plot kind as PNG+SVG (screen_plot.c; the global g). */
void acbb_screen_plot_export(acbb_app *a);
/* Run TE vs WTE on the edited scene and show it (screen_compare.c; t). */
void acbb_screen_compare_start(acbb_app *a);
/* Start the benchmark on the edited scene (with the dynamic level or not). */
void acbb_screen_accuracy_start(acbb_app *a, int with_dynamic);
/* Announce the end of a benchmark on the message line (once per run). */
void acbb_screen_accuracy_follow(acbb_app *a);
/* The `?` screen, generated from the table (a mode, not a tab). */
void acbb_screen_help_draw(acbb_app *a);
int acbb_screen_help_key(acbb_app *a, int ch);
/* Post a command to the worker, saying so on the message line (app.c). */
void acbb_app_post(acbb_app *a, acbb_worker_cmd cmd, const acbb_scene *s, int warm, const char *what);

#endif
