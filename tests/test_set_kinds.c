/* The set arrangements are one table (ACBB_SET_ARRANGEMENT_TABLE, scene.h):
 * the [set] arrangement key's choices, the names, the bearing counts, the
 * orientations (MODEL.md 14, [HK-EC] preloading chapter: DB (O) +-, DF (X)
 * -+, DT tandem ++.., DBT ++-, QBC ++--) and the count check all read it. */
#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "acbb/tools/set.h"
#include "acbb/tools/scene_schema.h"

/* The orientation signs of arrangement `arr` with edits, as "+-..". */
static int layout(const char *arr, const char *n_bearings, char *signs, acbb_error *err)
{
    static acbb_scene s;
    char a[64], nb[64];
    snprintf(a, sizeof a, "set.arrangement=%s", arr);
    snprintf(nb, sizeof nb, "set.n_bearings=%s", n_bearings);
    const char *edits[] = { a, nb, "operating.axial_load_N=500" }; /* a tandem set needs thrust */
    if (acbb_scene_load("presets/pair-DB-heated.ini", &s, err) != ACBB_OK ||
        acbb_scene_apply_edits(&s, edits, 3, err) != ACBB_OK)
        return -1;
    int o[ACBB_MAX_SET];
    int n = acbb_set_layout(&s, o, NULL);
    for (int k = 0; k < n; k++) signs[k] = o[k] > 0 ? '+' : '-';
    signs[n] = '\0';
    return n;
}

static void test_orientations(void)
{
    const struct { const char *arr, *n, *signs; } want[] = {
        { "DB", "0", "+-" }, { "DF", "0", "-+" }, { "DT", "0", "++" }, { "DT", "4", "++++" },
        { "DBT", "0", "++-" }, { "QBC", "0", "++--" }, { "single", "0", "+" },
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        char signs[ACBB_MAX_SET + 1] = "";
        acbb_error err = { "" };
        int n = layout(want[i].arr, want[i].n, signs, &err);
        ok(n == (int)strlen(want[i].signs) && strcmp(signs, want[i].signs) == 0,
           "%s n_bearings=%s: thrust directions %s (got %s %s)", want[i].arr, want[i].n,
           want[i].signs, signs, err.msg);
    }
}

static void test_counts(void)
{
    char signs[ACBB_MAX_SET + 1];
    acbb_error err = { "" };
    ok(layout("DB", "3", signs, &err) < 0 &&
           strstr(err.msg, "set.n_bearings = 3 with set.arrangement = DB: DB has 2 bearings"),
       "DB with 3 bearings refused: %s", err.msg);
    err.msg[0] = '\0';
    ok(layout("DT", "1", signs, &err) < 0 && strstr(err.msg, "DT has 2 to 4 bearings"),
       "DT with 1 bearing refused, the range from the table: %s", err.msg);
}

static void test_names(void)
{
    const acbb_field_info *f = NULL;
    for (size_t i = 0; i < acbb_scene_field_count(); i++)
        if (strcmp(acbb_scene_field(i)->section, "set") == 0 &&
            strcmp(acbb_scene_field(i)->key, "arrangement") == 0)
            f = acbb_scene_field(i);
    int same = f != NULL;
    for (int a = 0; same && a < ACBB_SET_ARRANGEMENTS; a++)
        same = f->choices[a] && strcmp(f->choices[a], acbb_set_arrangement_name(a)) == 0;
    ok(same && f->choices[ACBB_SET_ARRANGEMENTS] == NULL,
       "the key's %d choices are the table's names, in enum order", ACBB_SET_ARRANGEMENTS);
    ok(strcmp(acbb_set_arrangement_name(ACBB_SET_QBC), "QBC") == 0 &&
           strcmp(acbb_set_arrangement_name(ACBB_SET_ARRANGEMENTS), "?") == 0,
       "names: QBC, and ? past the table");
}

int main(void)
{
    test_orientations();
    test_counts();
    test_names();
    return done_testing();
}
