/* acbb CLI — `acbb report`: the seed's qualitative acceptance statements
 * (MODEL.md section 12, items 1-18) and its conclusions (seed section 5),
 * each judged HELD / NOT HELD / NOT EVALUATED from runs of the engine.
 * A thin client of the engine study (include/acbb/tools/study.h): it plans and
 * runs the study and formats its results; its options are rows of the
 * command table (main.c), parsed by args.c.
 *
 *   acbb report PRESET [--set section.key=value]... [--json] [--md FILE]
 *               [--sensitivity] [--inputs K1,...]
 *
 * Runs (in parallel over the CPUs): the load sweep 50..1000 N at
 * 15000 rpm and the speed sweeps 2000..16000 rpm at 100 N and 1000 N, each
 * with (TE) and without (WTE) thermal expansion, at the preset's fidelity
 * level; the same again at quasi-dynamic for the items MODEL.md marks (L2);
 * one zero-speed run at the preset's load and four at the light loads
 * (the static angles of item 6). Speed and load of the sweeps override the
 * preset's (and --set's) operating point; every other key is the preset's.
 *
 * stdout: a table fitting 80 columns (item, verdict, statement, then every
 * check with the numbers that decide it), the seed's conclusions mapped
 * onto those checks, and "N held, M not held, K not evaluated". --json
 * prints instead a JSON array of {item, statement, verdict, level,
 * seed_conclusions, evidence: {checks, values}}. --md FILE also writes the
 * report as Markdown (through acbb_out_*: nothing is replaced unless
 * complete). --sensitivity adds the robustness of every verdict over the
 * plausible ranges (acbb_study_robustness: per item, the single changes
 * that turn it, with the numbers; the TE - WTE sign conditions per input
 * end), to the text, the JSON (each item's "robustness") and the Markdown;
 * --inputs K1,... (implies --sensitivity) varies only those inputs, and an
 * input without a plausible range is bad input (exit 2).
 *
 * Every report also runs the runaway case (the bearing at 16000 rpm under
 * rigid preload set by 1000 N; include/acbb/tools/contact_study.h) under each
 * thermal.contact_model and race-side thermal.contact_multiplier 0.25, 0.5,
 * 1, 2 (8 short transient runs) and shows which branch each reaches: a
 * text section, a Markdown section, and item 9's JSON member
 * "contact_heat" (item 9's rigid-preload mounting is judged there).
 *
 * SIGINT / SIGTERM (progress.h) stop the runs within a step: no report is
 * printed (--json prints {"status": "cancelled", ...}), no --md file is
 * written, exit 3.
 *
 * Exit status: 0 the report ran (whatever the verdicts: NOT HELD is a
 * finding, not an error); 2 bad input (preset, --set, options, --md path);
 * 3 some run failed (the report is still printed; the items that needed it
 * are NOT EVALUATED with the run's status); 4 internal error (out of
 * memory, stdout or the Markdown file could not be written). */
#ifndef ACBB_CLI_REPORT_CLIENT_H
#define ACBB_CLI_REPORT_CLIENT_H

#include "args.h"

int acbb_cli_cmd_report(const acbb_cli_args *a);

#endif
