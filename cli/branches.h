/* acbb CLI — `acbb run`'s two branches (acbb/tools/branches.h) and schedule line
 * (acbb/tools/schedule.h) in the table and the JSON. */
#ifndef ACBB_CLI_BRANCHES_H
#define ACBB_CLI_BRANCHES_H

#include <stdbool.h>
#include "acbb/tools/branches.h"
#include "args.h"
#include "output.h"

/* --branches, or a scene where the two may differ (acbb_branches_wanted). */
bool acbb_cli_branches_wanted(const acbb_cli_args *a, const acbb_scene *sc);
/* The "branches" block of the table: verdict, criterion, both states. */
void acbb_cli_print_branches(acbb_cli_out *o, const acbb_branches *b);
/* The scene as the table's "scene" line shows it: at the schedule's last
 * row (the [operating] values do not act with a schedule). */
void acbb_cli_schedule_shown(const acbb_scene *sc, acbb_scene *shown);
/* The "schedule" line: the row reached, the operating point there. */
void acbb_cli_print_schedule(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s);

#endif
