/* acbb — the seed's Figs. 7-19 from the study's runs (MODEL.md section 12;
 * seed sections 3-4): the same quantities and axes as the paper's panels,
 * as data series, data files and PNG/SVG plots.
 *
 * The figures are data: a table of panel rows {id "fig07a", seed figure,
 * title, x and y labels with units, the series extractor: a kind (per-step
 * trajectory of the TE load-sweep runs, or a steady-state sweep with TE and
 * WTE) and up to three quantities}. A table of the seed's figures gives
 * each one's caption, what of it the model cannot compute and why, and the
 * MODEL.md section 12 items that cite it.
 *
 * The study keeps only a few per-step numbers; the trajectory panels need
 * more (outer-ring temperature, ball angular velocities, contact angles),
 * so acbb_figures_record re-drives the study's TE load-sweep points (eight
 * runs, the same scenes) through acbb_sim_drive with its own hook.
 *
 * Ownership: acbb_figures_record allocates an input that
 * acbb_figures_input_free releases; acbb_fig_data holds malloc'd series
 * that acbb_fig_data_free releases. No printing; no global state. */
#ifndef ACBB_FIGURES_H
#define ACBB_FIGURES_H

#include "acbb/cancel_flag.h"
#include <stddef.h>
#include "acbb/sim.h"
#include "acbb/status.h"
#include "acbb/tools/study.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- inputs ---- */

/* One step of a re-driven TE load-sweep run (ball 0 where per ball). */
typedef struct {
    double iteration;            /* coupled step ("iteration step" of the seed) */
    double t;                    /* simulated time, s */
    double T5_rise;              /* outer ring (seed node 5) minus ambient, K */
    double exp_in, exp_out, exp_ball; /* theta_i + theta_icen, theta_o, theta_ba, m */
    double dA1, dA2;             /* A1 - A0 sin(alpha0) = delta_x; A2 - A0 cos(alpha0) =
                                  * theta_i + theta_icen - theta_o (MODEL.md 3, CLEAN), m */
    double Qi, Qo;               /* N */
    double alpha_i, alpha_o;     /* rad */
    double wx, wy, wz;           /* omega_x', omega_y', omega_z', rad/s */
} acbb_fig_step;

typedef struct {
    acbb_fig_step *p;
    size_t n, cap;
    int oom;
    acbb_status status;          /* ACBB_OK when the run reached steady state */
    char message[520];
} acbb_fig_traj;

typedef struct {
    const acbb_study_runs *runs; /* not owned */
    acbb_fig_traj traj[ACBB_STUDY_NPTS]; /* TE load sweep, by acbb_study_loads index */
    double wall_ms;              /* of the re-driven runs */
} acbb_fig_input;

/* Re-drive the TE load-sweep points of `runs` (base level) with `jobs`
 * workers (0: acbb_batch_cpus()) and record every step of the transient.
 * ACBB_ENOMEM or ACBB_CANCELLED; a failed run is kept in its traj's status (its panels'
 * series leave it out). `runs` must outlive the input. */
acbb_status acbb_figures_record(const acbb_study_runs *runs, int jobs, const acbb_atomic_int *cancel,
                                acbb_fig_input **out, acbb_error *err);
void acbb_figures_input_free(acbb_fig_input *in);

/* ---- the tables ---- */

typedef enum {
    ACBB_FIG_TRAJ_ITER,          /* x = iteration step of the TE load-sweep runs */
    ACBB_FIG_TRAJ_TIME,          /* x = simulated time, s */
    ACBB_FIG_SWEEP               /* x = the sweep's load or speed; TE solid, WTE dashed */
} acbb_fig_kind;

/* Which loads a trajectory panel shows (seed: "light" and "large" loads). */
enum { ACBB_FIG_ALL_LOADS, ACBB_FIG_LIGHT, ACBB_FIG_LARGE };
/* A sweep panel's `sel`: one study sweep (ACBB_STUDY_LOAD, _S100, _S1000) or
 * both speed sweeps in one panel, as the seed's Figs. 15 and 16 draw them. */
#define ACBB_FIG_SPEED_SWEEPS ACBB_STUDY_NSWEEPS

typedef double (*acbb_fig_get)(const acbb_snapshot *s);

/* One plotted quantity: a getter (sweeps) or a step field (trajectories),
 * times `scale` (rad -> deg, m -> um). */
typedef struct {
    const char *label;           /* "Q_i" */
    acbb_fig_get get;
    size_t off;                  /* offsetof(acbb_fig_step, ...) */
    double scale;
} acbb_fig_quantity;

#define ACBB_FIG_MAX_Q 3
typedef struct {
    const char *id;              /* "fig07a": the file names DIR/<id>.{csv,png,svg} */
    int seed_fig;                /* 7 */
    const char *title;
    const char *xlabel, *ylabel; /* with units */
    acbb_fig_kind kind;
    int sel;                     /* trajectories: ACBB_FIG_*_LOADS; sweeps: see above */
    int l2;                      /* sweeps: read the quasi-dynamic (L2) runs */
    int nq;
    acbb_fig_quantity q[ACBB_FIG_MAX_Q];
} acbb_figure_row;

const acbb_figure_row *acbb_figure_table(size_t *n);

#define ACBB_FIG_MAX_ITEMS 6
typedef struct {
    int num;                     /* seed figure number, 7..19 */
    const char *caption;         /* the seed's caption, condensed */
    const char *not_computed;    /* what of it the model cannot compute and why, or NULL */
    int items[ACBB_FIG_MAX_ITEMS]; /* MODEL.md 12 items citing it, 0-terminated */
} acbb_seed_figure;

const acbb_seed_figure *acbb_seed_figure_table(size_t *n);

/* ---- series and files ---- */

#define ACBB_FIG_MAX_SERIES 24
#define ACBB_FIG_MAX_KEY 16
typedef struct {
    char label[64];
    double *x, *y;               /* malloc'd, n finite points */
    size_t n;
    int color, dash, points;     /* as acbb_plot_series */
} acbb_fig_series;

typedef struct {
    int n;
    acbb_fig_series s[ACBB_FIG_MAX_SERIES];
    int oom;
    char why[640];               /* why a series is missing (a failed run), else "" */
    /* The key when series differ in two ways (acbb_plot_look): one entry
     * per load or quantity family (colour and marker) and one per dash
     * (a trajectory's quantities; a sweep's TE and WTE); n_key 0: one
     * entry per series. Labels only (no points). */
    int n_key;
    acbb_fig_series key[ACBB_FIG_MAX_KEY];
} acbb_fig_data;

/* The series of one panel (clears `out`). A run that failed leaves its
 * points out and says so in out->why; non-finite values never enter. */
void acbb_figure_eval(const acbb_figure_row *row, const acbb_fig_input *in, acbb_fig_data *out);
void acbb_fig_data_free(acbb_fig_data *d);

/* What became of one panel in acbb_figures_write_all. */
typedef struct {
    acbb_status status;          /* ACBB_OK: the three files are written */
    char message[700];           /* the error, or the panel's why */
    int n_series;
    size_t n_points;
    double y_min, y_max;         /* over every series */
} acbb_figure_result;

/* Evaluate every row and write DIR/<id>.csv (a header naming the columns
 * and units, then "series,x,y" rows), DIR/<id>.png and DIR/<id>.svg (one
 * gnuplot process per panel, panels in parallel over `jobs` threads).
 * res[] has one entry per table row. Returns ACBB_OK when every panel was
 * written, else the first failure's status (the others are still tried). */
acbb_status acbb_figures_write_all(const acbb_fig_input *in, const char *dir, int jobs,
                                   int width, int height, acbb_figure_result *res);

#ifdef __cplusplus
}
#endif

#endif
