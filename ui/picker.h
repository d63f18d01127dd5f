/* acbb TUI — picking what the what-if screens vary and measure (no curses
 * here): the short menu of metrics both screens cycle through, a metric's
 * unit (the output table's), and Tab completion of a typed scene key or
 * metric path. */
#ifndef ACBB_UI_PICKER_H
#define ACBB_UI_PICKER_H

#include <stddef.h>

typedef struct {
    const char *path;            /* acbb_metric_value's path */
    const char *label;           /* for titles, e.g. "total loss" */
} acbb_metric_item;

/* The menu: total loss, outer-ring and ball temperatures, Qi and alpha_i
 * of ball 0, net squeeze, axial stiffness. */
extern const acbb_metric_item acbb_metric_menu[];
extern const int acbb_metric_menu_n;

/* The display unit of a metric path, from the output table (outputs.h:
 * "losses_W.total": "W", "balls[0].slide_i_mps": "m/s",
 * "ring.stiffness_axial_N_per_um": "N/um"); "" for an unknown path. */
void acbb_metric_unit(const char *path, char *buf, size_t n);

/* Name i of the scene keys ("section.key"), as acbb_metric_name does for
 * metrics: 1 with the name in buf, 0 past the end. */
int acbb_scene_key_name(size_t i, char *buf, size_t n);

/* Metric name i as one can type it: acbb_metric_name with ball fields
 * for ball 0 ("balls[0].Qi_N"); 0 past the end. */
int acbb_metric_choice(size_t i, char *buf, size_t n);

/* Complete `text` among the names listed by name_at: the names starting
 * with it, or (when none does) those containing it. `text` becomes their
 * longest common start when longer (the name itself when one is left).
 * `shown` gets up to its size of the matches, space-separated. Returns how
 * many matched. */
typedef int (*acbb_name_fn)(size_t i, char *buf, size_t n);
int acbb_complete(char *text, size_t cap, acbb_name_fn name_at, char *shown, size_t shown_n);

#endif
