/* acbb — the one table of a snapshot's scalar outputs: where each lives in
 * the run's JSON (section and key), which snapshot member holds it, the
 * SI-to-display conversion, the display unit and a short label.
 *
 * Every client names and converts results through it: the metrics of
 * `acbb sensitivity --metric`, the sweeps and the TUI's what-if screens
 * (sensitivity.h: acbb_metric_value), `acbb run --json` / `--csv`, the TUI's
 * units and `acbb metrics`. Adding an output is one row here (and a
 * snapshot member); a row with key NULL stands for one entry per loss kind
 * of acbb_loss_table (losses.h), so a new loss shows up by itself.
 *
 * Entries are the table's rows with the per-loss rows expanded, in JSON
 * order. A bearing entry's path is "section.key" ("ring.delta_x_um"; a
 * section may itself be a path: "spindle.sets[0].preload_N"); a
 * ball entry's is "balls[K].key" or "balls[K].section.key"
 * ("balls[0].losses_W.spin"). */
#ifndef ACBB_OUTPUTS_H
#define ACBB_OUTPUTS_H

#include <stddef.h>
#include "acbb/sim.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    ACBB_OUT_BEARING,            /* a member of acbb_snapshot */
    ACBB_OUT_BALL                /* a member of acbb_ball_view (snapshot.balls[K]) */
} acbb_output_scope;

typedef struct {
    const char *section;         /* JSON object ("temperature_C"); ball rows: NULL
                                    (directly in balls[K]) or "losses_W" */
    const char *key;             /* key in it; NULL: one entry per loss kind */
    const char *flat;            /* the CSV / sweep column name before schema 3
                                    ("T_outer_ring_C"), now an alias a path may
                                    use; "%s" stands for the loss name */
    const char *unit;            /* display unit ("W", "um", "N/um", "m/s") */
    const char *label;           /* short help (per-loss rows: the loss's label) */
    acbb_output_scope scope;
    size_t off;                  /* offset of the double (per-loss rows: of P[0] /
                                    loss_kind[0]); unused when `get` is set */
    double (*get)(const acbb_snapshot *s); /* a bearing value made of several members */
    double scale, div;           /* display = SI * scale / div (exactly as the
                                    writers always computed it) */
} acbb_output_row;

/* One entry: a row, and for a per-loss row the loss kind. */
typedef struct {
    const acbb_output_row *row;
    int loss;                    /* loss kind, or -1 */
    const char *key;             /* the row's key or the loss name */
    const char *label;
    const char *unit;
} acbb_output;

/* Entry i into *o: 1, or 0 past the end. */
int acbb_output_get(size_t i, acbb_output *o);
/* How many entries there are. */
size_t acbb_output_count(void);

/* The entry's path into buf; ball entries with `ball` as the index text
 * ("i" for the listing, "0"). Returns snprintf's count. */
int acbb_output_path(const acbb_output *o, const char *ball, char *buf, size_t n);
/* The entry's CSV / sweep column name into buf: one name per quantity
 * (issue 21 item 10), the run JSON's path, ball entries of ball 0
 * ("temperature_C.outer_ring", "balls[0].Qi_N"). */
int acbb_output_flat(const acbb_output *o, char *buf, size_t n);
/* The entry's old column name (schema 2 and before: "T_outer_ring_C"),
 * accepted by acbb_output_find as an alias. */
int acbb_output_old_name(const acbb_output *o, char *buf, size_t n);

/* The entry's value in `s` in display units; ball entries of ball k (NAN
 * when k is not a ball of the snapshot). */
double acbb_output_value(const acbb_output *o, const acbb_snapshot *s, int k);

/* Why the entry has no value in `s` (a stiffness probe that failed,
 * acbb_snapshot.stiffness_failed; a "spindle..." entry of a scene that is
 * not a spindle, spindle.n_sets = 0), or NULL when it has one. Writers print
 * a missing value as null (JSON) or an empty cell, never the 0 the
 * snapshot holds. */
const char *acbb_output_missing(const acbb_output *o, const acbb_snapshot *s);

/* The entry a path (or an old column name, acbb_output_old_name: ball 0)
 * names, and its ball index (-1 for a bearing entry).
 * ACBB_EINVAL with the reason when the path names none. The ball index is
 * checked against ACBB_MAX_BALLS only. */
acbb_status acbb_output_find(const char *path, acbb_output *o, long *ball, acbb_error *err);

#ifdef __cplusplus
}
#endif

#endif
