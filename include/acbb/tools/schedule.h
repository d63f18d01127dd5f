/* acbb — run-in schedules (MODEL.md 14 "Run-in schedule").
 *
 * A scene's [schedule] is a table of rows (t, speed, axial load, radial
 * load), one `row = t_s, speed_rpm, axial_N, radial_N` line each, times
 * strictly increasing from 0, at most ACBB_SCHEDULE_MAX rows, each value in
 * the range of its [operating] key. The transient's operating point is
 * linear between rows and held after the last; the steady solve (and a
 * run with fidelity.thermal_mode = steady) uses the last row. A scene
 * without rows runs at its [operating] values, as before.
 *
 * Every function here is pure (no state); whoever runs a scene (one bearing
 * or a set) takes its operating point from acbb_schedule_at, so all runs
 * follow the same rows the same way. */
#ifndef ACBB_SCHEDULE_H
#define ACBB_SCHEDULE_H

#include <stdbool.h>
#include <stddef.h>
#include "acbb/scene.h"
#include "acbb/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The operating point at one time. */
typedef struct {
    double inner_speed;     /* rad/s */
    double axial_load;      /* N */
    double radial_load;     /* N */
    int row;                /* 1-based: the last row reached (k of n_rows); 0: no schedule */
    int n_rows;             /* rows in the schedule, 0: none */
    bool finished;          /* t at or past the last row's time (always true without rows) */
} acbb_operating;

/* The operating point of scene s at time t (s); without rows the scene's
 * [operating] values. */
void acbb_schedule_at(const acbb_scene *s, double t, acbb_operating *op);

/* The last row's operating point (the steady solve's); the [operating]
 * values without rows. */
void acbb_schedule_final(const acbb_scene *s, acbb_operating *op);

/* Write op's speed and loads into s's [operating] members (the rows stay). */
void acbb_schedule_apply(acbb_scene *s, const acbb_operating *op);

/* The last row's time, s (0 without rows). */
double acbb_schedule_end(const acbb_scene *s);

/* The rows' own rules (first time 0, strictly increasing, values in their
 * keys' ranges, at most ACBB_SCHEDULE_MAX rows) and, for each row, the
 * scene's rules at that row's operating point (a radial load needs thrust:
 * MODEL.md 11). The message names the row: "schedule row 3 (t = 20 s): ...".
 * Part of acbb_scene_validate. */
acbb_status acbb_schedule_validate(const acbb_scene *s, acbb_error *err);

/* Row i as the text of its `row = ` line ("20, 15000, 1000, 0"), in preset
 * units, exact (reading it back gives the same doubles); buf >= 128 bytes. */
void acbb_schedule_format_row(const acbb_scene *s, int i, char *buf, size_t n);

/* Parse the text of a `row = ` line into a row (range of each value
 * checked; the order of rows is not). ACBB_EINVAL with the reason. */
acbb_status acbb_schedule_parse_row(const char *text, acbb_schedule_row *row, acbb_error *err);

#ifdef __cplusplus
}
#endif

#endif
