/* acbb CLI — the command handlers the command table (main.c) points at.
 * Each gets its parsed arguments (args.h) and returns an exit status
 * (exit.h). */
#ifndef ACBB_CLI_COMMANDS_H
#define ACBB_CLI_COMMANDS_H

#include "args.h"

/* cli.c */
int acbb_cli_cmd_run(const acbb_cli_args *a);
int acbb_cli_cmd_check(const acbb_cli_args *a);
int acbb_cli_cmd_edit(const acbb_cli_args *a);     /* edit.c */
int acbb_cli_cmd_sweep(const acbb_cli_args *a);
int acbb_cli_cmd_study(const acbb_cli_args *a);
int acbb_cli_cmd_bench_speed(const acbb_cli_args *a);
int acbb_cli_cmd_keys(const acbb_cli_args *a);

/* preload_map.c */
int acbb_cli_cmd_preload_map(const acbb_cli_args *a);

/* sensitivity.c */
int acbb_cli_cmd_sensitivity(const acbb_cli_args *a);

/* plot.c, accuracy.c, presets.c */
int acbb_cli_plot(const acbb_cli_args *a);
int acbb_cli_bench_accuracy(const acbb_cli_args *a);
int acbb_cli_cmd_presets(const acbb_cli_args *a);

/* schema.c */
int acbb_cli_cmd_schema(const acbb_cli_args *a);

#endif
