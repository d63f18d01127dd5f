/* acbb CLI — the seed's conclusions under three mountings (mountings.h). */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include "mountings.h"

/* ---- mountings (issue 17 item 7; MODEL.md 14) ----
 * Each seed conclusion is judged under the seed rig's constant force and
 * under rigid preload of the same bearing: the study as the scene says, and
 * again with the other mounting.preload (under displacement the study's
 * thrust of each point is the assembly preload, study.c set_point), and
 * as a rigid DB pair of the same bearing with the same preload (the set's
 * other keys as the scene has them; MODEL.md 14: the pair's own bearing
 * carries the preload, the shaft's growth between them adds to it). */
const acbb_cli_mounting acbb_cli_mountings[N_MOUNTINGS] = {
    [M_FORCE] = { "constant force", "constant_force", "force" },
    [M_RIGID] = { "rigid preload", "rigid_preload", "rigid" },
    [M_DB] = { "DB pair", "db_pair", "DB" },
};

/* The scene of mounting m from the preset's scene. */
void acbb_cli_mounting_scene(const acbb_scene *base, int m, acbb_scene *out)
{
    *out = *base;
    out->preload = m == M_FORCE ? ACBB_PRELOAD_FORCE : ACBB_PRELOAD_DISPLACEMENT;
    if (m != M_FORCE && !(out->preload_force > 0.0)) out->preload_force = out->axial_load;
    out->set_arrangement = m == M_DB ? ACBB_SET_DB : ACBB_SET_SINGLE;
    if (m != M_DB) out->set_n_bearings = 0;
    /* The mountings are the bearing's: a spindle scene's front bearing on a
     * rigid shaft, as for any other scene (docs/spindle.md "Questions"). */
    out->shaft_segments = 0;
}

/* The mounting the scene itself is, or -1 (another set, a spring pair):
 * then the study of the scene is shown above and every mounting below. */
int acbb_cli_own_mounting(const acbb_scene *base)
{
    if (base->shaft_segments > 0) return -1; /* a spindle is none of them */
    bool rigid = base->preload == ACBB_PRELOAD_DISPLACEMENT;
    if (base->set_arrangement == ACBB_SET_SINGLE) return rigid ? M_RIGID : M_FORCE;
    return base->set_arrangement == ACBB_SET_DB && rigid ? M_DB : -1;
}

const acbb_study_check *acbb_cli_find_check(const acbb_study *s, const char *id)
{
    const acbb_study_check *ch = acbb_study_find_check(s, id);
    const acbb_study_item *it = acbb_study_item_at(s, (size_t)(atoi(id) - 1));
    return ch ? ch : it && it->n_checks > 0 ? &it->checks[0] : NULL;
}

/* "all three", "constant force only", "rigid preload, DB pair", "none"
 * for conclusion i; buf >= 40 bytes. */
const char *acbb_cli_holds_under(const acbb_study *const *by, size_t i, char *buf, size_t cap)
{
    int n = 0, last = 0;
    size_t u = 0;
    buf[0] = '\0';
    for (int m = 0; m < N_MOUNTINGS; m++) {
        if (acbb_study_conclusion_verdict(by[m], i) != ACBB_VERDICT_HELD) continue;
        u += (size_t)snprintf(buf + u, u < cap ? cap - u : 0, "%s%s", n ? ", " : "",
                              acbb_cli_mountings[m].name);
        n++;
        last = m;
    }
    if (n == 0) return "none";
    if (n == N_MOUNTINGS) return "all three";
    if (n == 1) snprintf(buf, cap, "%s only", acbb_cli_mountings[last].name);
    return buf;
}

const char acbb_cli_mount_intro[] =
    "Seed conclusions by mounting (docs/physics.md section 14): the same study under the seed "
    "rig's constant "
    "force, under rigid preload of the same bearing (mounting.preload = displacement, each "
    "point's thrust the assembly preload) and as a rigid DB pair of it with the same preload "
    "(set.arrangement = DB; the numbers are bearing 0's); where a transient runs away, the "
    "steady values are the steady solve's and the transient checks say so. The checks' numbers "
    "under each:";

void acbb_cli_md_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '|' || *s == '*' || *s == '_') fputc('\\', f);
        fputc(*s, f);
    }
}

void acbb_cli_mountings_md_row(FILE *f, const acbb_study *const *by, size_t i)
{
    char where[64];
    for (int m = 0; m < N_MOUNTINGS; m++)
        fprintf(f, " %s |", acbb_verdict_name(acbb_study_conclusion_verdict(by[m], i)));
    fprintf(f, " %s |\n", acbb_cli_holds_under(by, i, where, sizeof where));
}

void acbb_cli_mountings_md(FILE *f, const acbb_study *const *by)
{
    size_t nc;
    const acbb_study_conclusion *cc = acbb_study_conclusions(&nc);
    acbb_cli_md_text(f, acbb_cli_mount_intro);
    fputs("\n\n| # | constant force | rigid preload | DB pair | holds under |\n"
          "|---|---|---|---|---|\n", f);
    for (size_t i = 0; i < nc; i++) {
        fprintf(f, "| (%zu) |", i + 1);
        acbb_cli_mountings_md_row(f, by, i);
    }
    fputc('\n', f);
    for (size_t i = 0; i < nc; i++)
        for (int k = 0; k < ACBB_STUDY_CONCL_CHECKS && cc[i].checks[k]; k++)
            for (int m = 0; m < N_MOUNTINGS; m++) {
                const acbb_study_check *ch = acbb_cli_find_check(by[m], cc[i].checks[k]);
                fprintf(f, "- (%zu) **%s %s**, %s: ", i + 1, cc[i].checks[k],
                        ch ? acbb_verdict_name(ch->verdict) : "NOT EVALUATED", acbb_cli_mountings[m].name);
                acbb_cli_md_text(f, ch ? ch->text : "not evaluated");
                fputc('\n', f);
            }
}
