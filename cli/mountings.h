/* acbb CLI — the seed's conclusions under three mountings (issue 17 item 7;
 * MODEL.md 14), shared by `acbb report` and `acbb study seed --out DIR`:
 * the seed rig's constant force, rigid preload of the same bearing, and a
 * rigid DB pair of it with the same preload. Private to the executable. */
#ifndef ACBB_CLI_MOUNTINGS_H
#define ACBB_CLI_MOUNTINGS_H

#include <stdio.h>
#include "acbb/scene.h"
#include "acbb/tools/study.h"

enum { M_FORCE, M_RIGID, M_DB, N_MOUNTINGS };
typedef struct {
    const char *name, *json, *label;
} acbb_cli_mounting;
extern const acbb_cli_mounting acbb_cli_mountings[N_MOUNTINGS];

/* The scene of mounting m from the preset's scene (a spindle's: its front
 * bearing on a rigid shaft). */
void acbb_cli_mounting_scene(const acbb_scene *base, int m, acbb_scene *out);
/* The mounting the scene itself is, or -1 (another set, a spring pair, a
 * spindle). */
int acbb_cli_own_mounting(const acbb_scene *base);
/* The check `id` of s, or its item's first check; NULL if neither. */
const acbb_study_check *acbb_cli_find_check(const acbb_study *s, const char *id);
/* "all three", "constant force only", "rigid preload, DB pair", "none"
 * for conclusion i under the studies by[N_MOUNTINGS]. */
const char *acbb_cli_holds_under(const acbb_study *const *by, size_t i, char *buf, size_t cap);
/* What the three mountings are, in words. */
extern const char acbb_cli_mount_intro[];
/* Markdown text: '|', '*', '_' escaped. */
void acbb_cli_md_text(FILE *f, const char *s);
/* " HELD | NOT HELD | HELD | rigid preload, DB pair |\n": conclusion i's
 * verdicts under each mounting and where it holds, a Markdown row's end. */
void acbb_cli_mountings_md_row(FILE *f, const acbb_study *const *by, size_t i);
/* The Markdown table "conclusion x mounting" and each check's numbers
 * under each mounting (as `acbb report --md` prints it). */
void acbb_cli_mountings_md(FILE *f, const acbb_study *const *by);

#endif
