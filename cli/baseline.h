/* acbb CLI — `acbb run ... --baseline FILE`: what an edit or an effect did.
 * FILE is a saved `acbb run --json`; every number of this run (results and
 * scene) is compared with it by its JSON path. cJSON reads both documents:
 * this run's JSON is the one acbb_cli_json_run writes, so the comparison
 * sees exactly what a user would save. */
#ifndef ACBB_CLI_BASELINE_H
#define ACBB_CLI_BASELINE_H

#include <stdbool.h>
#include "acbb/sim.h"

/* Text: the run's summary is already printed; this adds a table of the
 * values that changed (baseline, now, change, %). JSON: prints this run's
 * JSON with a "vs_baseline" array added. Returns an exit status (0, 2 for
 * an unreadable baseline, 4 for an output failure). `quiet` (text only):
 * the baseline is still read and checked, nothing printed. */
/* Before the run: 0 when FILE is a regular file that can be read, else 2
 * with the message (a FIFO, a device or a directory is refused at once,
 * not waited on). */
int acbb_cli_baseline_check(const char *path);

int acbb_cli_baseline(const char *path, const acbb_scene *sc, const acbb_snapshot *snap,
                      bool json, bool quiet);

#endif
