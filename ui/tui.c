/* acbb TUI — entry point: `acbb`, `acbb tui [options] [PRESET]`. The
 * options come parsed from the CLI's command table (cli/main.c); this
 * checks their values and the environment, then runs the app. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../cli/exit.h"
#include "app.h"
#include "tui.h"

static int parse_int(const char *s, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < 0 || v > 1000000) return -1;
    *out = (int)v;
    return 0;
}

/* "contact_grid,hertz" -> knob mask; -1 (message printed) on an unknown name. */
static int parse_knobs(const char *text, unsigned *mask)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", text);
    *mask = 0;
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int k = acbb_accuracy_knob_from_name(tok);
        if (k < 0) {
            fprintf(stderr, "acbb: tui: ACBB_TUI_ACCURACY_KNOBS: unknown knob '%s' (model "
                            "contact_grid hertz mech_tol steady_tol thermal network)\n", tok);
            return -1;
        }
        *mask |= ACBB_ACCURACY_KNOB_BIT(k);
    }
    return 0;
}

int acbb_tui_main(const acbb_tui_args *args)
{
    acbb_app_options o = { .pace = -1, .preset = args->preset, .plot_dir = args->plot_dir,
                           .no_mouse = args->no_mouse, .installed = args->installed };
    const char *knobs = getenv("ACBB_TUI_ACCURACY_KNOBS");
    if (knobs && knobs[0] && parse_knobs(knobs, &o.acc_knobs) != 0) return ACBB_EXIT_INPUT;
    const char *env = getenv("ACBB_TUI_EXIT_AFTER_STEADY");
    o.exit_after_steady = args->exit_after_steady || (env && env[0] && strcmp(env, "0") != 0);
    if (args->pace && parse_int(args->pace, &o.pace) != 0) {
        fprintf(stderr, "acbb: tui: --pace wants simulated seconds per second (0 .. 1000000), "
                        "got '%s'\n", args->pace);
        return ACBB_EXIT_INPUT;
    }
    return acbb_app_run(&o);
}
