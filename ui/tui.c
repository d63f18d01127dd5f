/* acbb TUI — entry point: `acbb`, `acbb tui [options] [PRESET]`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "app.h"
#include "tui.h"

static const char usage_text[] =
    "usage: acbb tui [--pace N] [--plot-dir DIR] [--no-mouse] [--exit-after-steady] [PRESET]\n"
    "  PRESET               scene to open (default presets/7008C.ini)\n"
    "  --pace N             simulated seconds per wall second (default 200,\n"
    "                       0 = flat out; + and - change it live)\n"
    "  --plot-dir DIR       where g writes PNG+SVG plots (default ./acbb-plots)\n"
    "  --no-mouse           leave the mouse to the terminal (no clicks, no wheel)\n"
    "  --exit-after-steady  start the run at once and exit when it ends\n"
    "                       (also ACBB_TUI_EXIT_AFTER_STEADY=1; exit 0 converged, 3 not)\n"
    "Environment:\n"
    "  ACBB_TUI_ACCURACY_KNOBS=k1,k2  knobs the accuracy screen's benchmark (b) varies\n"
    "                       (model contact_grid hertz mech_tol steady_tol thermal network;\n"
    "                       default all), e.g. contact_grid for a run of a few seconds\n"
    "Inside, press ? for every key.\n";

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
            fprintf(stderr, "acbb tui: ACBB_TUI_ACCURACY_KNOBS: unknown knob '%s'\n%s", tok, usage_text);
            return -1;
        }
        *mask |= ACBB_ACCURACY_KNOB_BIT(k);
    }
    return 0;
}

int acbb_tui_main(int argc, char **argv)
{
    acbb_app_options o = { .pace = -1 };
    const char *knobs = getenv("ACBB_TUI_ACCURACY_KNOBS");
    if (knobs && knobs[0] && parse_knobs(knobs, &o.acc_knobs) != 0) return 2;
    const char *env = getenv("ACBB_TUI_EXIT_AFTER_STEADY");
    o.exit_after_steady = env && env[0] && strcmp(env, "0") != 0;
    /* argv[0] is "tui" or the program name; options follow. */
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            fputs(usage_text, stdout);
            return 0;
        } else if (strcmp(s, "--pace") == 0 && i + 1 < argc) {
            if (parse_int(argv[++i], &o.pace) != 0) {
                fprintf(stderr, "acbb tui: --pace wants simulated seconds per second (0 .. 1000000), got '%s'\n", argv[i]);
                return 2;
            }
        } else if (strcmp(s, "--plot-dir") == 0 && i + 1 < argc) {
            o.plot_dir = argv[++i];
        } else if (strcmp(s, "--no-mouse") == 0) {
            o.no_mouse = 1;
        } else if (strcmp(s, "--exit-after-steady") == 0) {
            o.exit_after_steady = 1;
        } else if (s[0] == '-' && s[1]) {
            fprintf(stderr, "acbb tui: unknown option '%s'\n%s", s, usage_text);
            return 2;
        } else if (!o.preset) {
            o.preset = s;
        } else {
            fprintf(stderr, "acbb tui: one preset only ('%s' and '%s')\n%s", o.preset, s, usage_text);
            return 2;
        }
    }
    return acbb_app_run(&o);
}
