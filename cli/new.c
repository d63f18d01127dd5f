/* acbb CLI — `acbb new`: a preset from a bearing designation.
 *
 * The engine makes the scene (designation.h: ISO 15 boundary dimensions,
 * estimated internal geometry) and saves it (acbb_scene_save, every key
 * with its help and range); this handler then adds a header and, above
 * each estimated key, a "; estimated: RULE" line, rewriting the file
 * through the atomic writer (outfile.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "acbb/tools/designation.h"
#include "acbb/tools/physics_profile.h"
#include "acbb/tools/outfile.h"
#include "common.h"
#include "exit.h"
#include "new.h"
#include "say.h"

#define MAX_NOTES 24

static int fail(const char *msg)
{
    acbb_cli_say("new: %s\n", msg);
    return ACBB_EXIT_INPUT;
}

/* A number from option o, whole text: 0, or 2 with a message. */
static int number(const acbb_cli_args *a, acbb_cli_opt o, double *v)
{
    const char *t = a->val[o];
    char *end;
    errno = 0;
    *v = strtod(t, &end);
    if (end == t || *end || errno) {
        acbb_cli_say("new: --%s %s: not a number\n", acbb_cli_options[o].name, t);
        return ACBB_EXIT_INPUT;
    }
    return 0;
}

static int designation(const acbb_cli_args *a, acbb_designation *d)
{
    acbb_error e;
    int expl = a->val[CLI_OPT_SERIES] || a->val[CLI_OPT_BORE] || a->val[CLI_OPT_ANGLE];
    if (a->n_pos == 1 && expl)
        return fail("give a DESIGNATION or --series/--bore/--angle, not both");
    if (a->n_pos == 1)
        return acbb_designation_parse(a->pos[0], d, &e) == ACBB_OK ? 0 : fail(e.msg);
    if (!a->val[CLI_OPT_SERIES] || !a->val[CLI_OPT_BORE])
        return fail("needs a DESIGNATION (e.g. 7014C, 6205) or --series and --bore "
                    "(try `acbb help new`)");
    double series, bore, angle = -1.0;
    int rc = number(a, CLI_OPT_SERIES, &series);
    if (!rc) rc = number(a, CLI_OPT_BORE, &bore);
    if (!rc && a->val[CLI_OPT_ANGLE]) rc = number(a, CLI_OPT_ANGLE, &angle);
    if (rc) return rc;
    if (series != (int)series) return fail("--series: a series number such as 70 or 719");
    if (acbb_designation_make((int)series, bore, angle, d, &e) != ACBB_OK) return fail(e.msg);
    return 0;
}

static const char *estimated(const char *section, const char *line, const acbb_estimate *notes,
                             size_t n)
{
    size_t kl = strcspn(line, " =");
    for (size_t i = 0; i < n; i++) {
        size_t sl = strlen(section);
        const char *k = notes[i].key;
        if (!strncmp(k, section, sl) && k[sl] == '.' && strlen(k + sl + 1) == kl &&
            !strncmp(k + sl + 1, line, kl))
            return notes[i].rule;
    }
    return NULL;
}

/* Rewrite the saved preset with the header and the estimate notes. */
static int annotate(const char *path, const acbb_designation *d, const acbb_estimate *notes,
                    size_t n)
{
    FILE *in = fopen(path, "r");
    if (!in) return fail(strerror(errno));
    acbb_out *o;
    FILE *f;
    acbb_error e;
    if (acbb_out_open(path, &o, &f, &e) != ACBB_OK) {
        fclose(in);
        return fail(e.msg);
    }
    fprintf(f, "; %s: %s ball bearing, made by `acbb new %s`.\n; d x D x B = %g x %g x %g mm: "
               "ISO 15:2017 general plan (boundary dimensions).\n; Lines \"; estimated: ...\" "
               "mark internal geometry that catalogues do not publish\n; and the default "
               "operating point, estimated by the rule given\n; (src/scene/designation.c); "
               "overwrite any of it.\n; Physics: physics.profile = reference (the "
               "best-founded losses; seed gives the seed paper's).\n",
            d->name, d->deep_groove ? "deep-groove" : "angular-contact", d->name,
            d->bore * 1e3, d->outer_diameter * 1e3, d->width * 1e3);
    char line[512], section[64] = "";
    while (fgets(line, sizeof line, in)) {
        if (line[0] == '[') snprintf(section, sizeof section, "%.*s",
                                     (int)strcspn(line + 1, "]"), line + 1);
        const char *rule = line[0] != ';' && line[0] != '[' ? estimated(section, line, notes, n)
                                                            : NULL;
        if (rule) fprintf(f, "; estimated: %s\n", rule);
        fputs(line, f);
    }
    int bad = ferror(in);
    fclose(in);
    if (bad) {
        acbb_out_abort(o);
        return fail("cannot read back the saved preset");
    }
    if (acbb_out_commit(o, &e) == ACBB_OK) return 0;
    acbb_cli_say("new: %s\n", e.msg);
    return ACBB_EXIT_INTERNAL; /* opened, then the write failed (disk full) */
}

int acbb_cli_cmd_new(const acbb_cli_args *a)
{
    acbb_designation d;
    int rc = designation(a, &d);
    if (rc) return rc;
    acbb_scene s;
    acbb_estimate notes[MAX_NOTES];
    size_t n = acbb_designation_scene(&d, &s, notes, MAX_NOTES);
    /* A new design states the reference physics profile (physics_profile.h):
     * the seed's physics is the seed presets' own, a lower bound elsewhere. */
    s.profile = ACBB_PROFILE_REFERENCE;
    s.profile_given = 0;
    acbb_profile_apply(&s);
    char def[64];
    snprintf(def, sizeof def, "%s.ini", d.name);
    const char *path = a->val[CLI_OPT_OUT] ? a->val[CLI_OPT_OUT] : def;
    if (access(path, F_OK) == 0) {
        acbb_cli_say("new: %s exists; remove it or choose another --out\n", path);
        return ACBB_EXIT_INPUT;
    }
    acbb_error e;
    acbb_status st = acbb_scene_save(path, &s, &e);
    if (st != ACBB_OK) {
        acbb_cli_say("new: %s\n", acbb_cli_err_text(&e, st));
        /* The guard (out_guard.h) found the path writable: a failed write
         * now is the disk's (README "Exit codes"), not bad input. */
        return st == ACBB_EIO ? ACBB_EXIT_INTERNAL : acbb_cli_exit_for(st);
    }
    if ((rc = annotate(path, &d, notes, n)) != 0) return rc;
    printf("%s: %s, %g x %g x %g mm, %d balls of %.4g mm on %.4g mm (estimated)\n", path, d.name,
           d.bore * 1e3, d.outer_diameter * 1e3, d.width * 1e3, s.n_balls,
           s.ball_diameter * 1e3, s.pitch_diameter * 1e3);
    return acbb_cli_stdout_check(0);
}
