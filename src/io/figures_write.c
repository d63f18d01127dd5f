/* acbb — writing the seed's figures (figures.h: acbb_figures_write_all):
 * per panel, DIR/<id>.csv through acbb_out (nothing half-written replaces a
 * file) and DIR/<id>.png + .svg from one gnuplot process (plot_xy.c).
 * Panels run in parallel: gnuplot start-up is the cost. Nothing prints. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/batch.h"
#include "acbb/tools/figures.h"
#include "acbb/tools/outfile.h"
#include "acbb/tools/plot.h"

/* A label in the data file: the CSV separator becomes ';' and a double
 * quote a single one, so a plain split on ',' reads every row. */
static void csv_field(FILE *f, const char *s)
{
    for (; *s; s++) fputc(*s == ',' ? ';' : *s == '"' ? '\'' : *s, f);
}

static acbb_status write_csv(const acbb_figure_row *row, const acbb_fig_data *d,
                             const char *path, acbb_error *err)
{
    acbb_out *o = NULL;
    FILE *f = NULL;
    acbb_status st = acbb_out_open(path, &o, &f, err);
    if (st != ACBB_OK) return st;
    fprintf(f, "# acbb seed figure %s (seed Fig. %d): %s\n", row->id, row->seed_fig,
            row->title);
    fputs("# one row per point; the first column names the series\nseries,", f);
    csv_field(f, row->xlabel);
    fputc(',', f);
    csv_field(f, row->ylabel);
    fputc('\n', f);
    for (int i = 0; i < d->n; i++)
        for (size_t k = 0; k < d->s[i].n; k++) {
            fputc('"', f);
            csv_field(f, d->s[i].label);
            fprintf(f, "\",%.10g,%.10g\n", d->s[i].x[k], d->s[i].y[k]);
        }
    return acbb_out_commit(o, err);
}

static acbb_status write_plot(const acbb_figure_row *row, const acbb_fig_data *d,
                              const char *png, const char *svg, int w, int h, acbb_error *err)
{
    acbb_plot_series ps[ACBB_FIG_MAX_SERIES];
    for (int i = 0; i < d->n; i++)
        ps[i] = (acbb_plot_series){ d->s[i].label, d->s[i].x, d->s[i].y, d->s[i].n,
                                    d->s[i].color, d->s[i].dash, d->s[i].points };
    acbb_plot_series key[ACBB_FIG_MAX_KEY];
    for (int i = 0; i < d->n_key; i++)
        key[i] = (acbb_plot_series){ .label = d->key[i].label, .color = d->key[i].color,
                                     .dash = d->key[i].dash, .points = d->key[i].points };
    /* The title says what is drawn; the panel's id is its file name and
     * the seed figure is REPORT.md's (issue 29 item 9). */
    acbb_plot_xy p = { row->title, row->xlabel, row->ylabel, ps, (size_t)d->n };
    acbb_plot_look look = { key, (size_t)d->n_key };
    return acbb_plot_xy_styled(&p, &look, png, svg, w, h, err);
}

static void summarize(const acbb_fig_data *d, acbb_figure_result *r)
{
    r->n_series = d->n;
    r->y_min = INFINITY;
    r->y_max = -INFINITY;
    for (int i = 0; i < d->n; i++)
        for (size_t k = 0; k < d->s[i].n; k++) {
            r->n_points++;
            r->y_min = fmin(r->y_min, d->s[i].y[k]);
            r->y_max = fmax(r->y_max, d->s[i].y[k]);
        }
}

typedef struct {
    const acbb_fig_input *in;
    const char *dir;
    int w, h;
    acbb_figure_result *res;
} write_job;

static acbb_status panel_paths(const char *dir, const char *id, char p[3][PATH_MAX],
                               acbb_error *err)
{
    static const char *const ext[3] = { "csv", "png", "svg" };
    for (int i = 0; i < 3; i++)
        if (snprintf(p[i], PATH_MAX, "%s/%s.%s", dir, id, ext[i]) >= PATH_MAX)
            return acbb_error_set(err, ACBB_EINVAL, "figure directory path too long: %s", dir);
    return ACBB_OK;
}

static void write_one(const write_job *j, size_t i)
{
    size_t n;
    const acbb_figure_row *row = &acbb_figure_table(&n)[i];
    acbb_figure_result *r = &j->res[i];
    acbb_error err = { { 0 } };
    acbb_fig_data d;
    char paths[3][PATH_MAX];
    memset(r, 0, sizeof *r);
    acbb_figure_eval(row, j->in, &d);
    summarize(&d, r);
    r->status = panel_paths(j->dir, row->id, paths, &err);
    if (r->status == ACBB_OK && d.oom)
        r->status = acbb_error_set(&err, ACBB_ENOMEM, "out of memory");
    else if (r->status == ACBB_OK && d.n == 0)
        r->status = acbb_error_set(&err, ACBB_EINVAL, "no series with two points (%s)",
                                   d.why[0] ? d.why : "no data");
    if (r->status == ACBB_OK) r->status = write_csv(row, &d, paths[0], &err);
    if (r->status == ACBB_OK)
        r->status = write_plot(row, &d, paths[1], paths[2], j->w, j->h, &err);
    snprintf(r->message, sizeof r->message, "%s",
             r->status != ACBB_OK ? err.msg : d.why);
    acbb_fig_data_free(&d);
}

static void write_index(void *ctx, size_t i) { write_one(ctx, i); }

acbb_status acbb_figures_write_all(const acbb_fig_input *in, const char *dir, int jobs,
                                   int width, int height, acbb_figure_result *res)
{
    size_t n;
    acbb_figure_table(&n);
    write_job job = { in, dir, width, height, res };
    acbb_batch_for(n, jobs, write_index, &job, NULL);
    for (size_t i = 0; i < n; i++)
        if (res[i].status != ACBB_OK) return res[i].status;
    return ACBB_OK;
}
