/* acbb — the layout of a bearing set (MODEL.md section 14, acbb/tools/set.h);
 * the arrangements are ACBB_SET_ARRANGEMENT_TABLE (acbb/scene.h);
 * bearings numbered by increasing x. */
#include <stddef.h>
#include <string.h>
#include "acbb/tools/set.h"

#define KIND_ROW(id, name, n, n_max, orient) [ACBB_SET_##id] = { name, n, n_max, orient },
const acbb_set_kind acbb_set_kinds[ACBB_SET_ARRANGEMENTS] = { ACBB_SET_ARRANGEMENT_TABLE(KIND_ROW) };
#define NAME_ROW(id, name, n, n_max, orient) name,
const char *const acbb_set_arrangement_names[ACBB_SET_ARRANGEMENTS + 1] = {
    ACBB_SET_ARRANGEMENT_TABLE(NAME_ROW) NULL
};

static int known(acbb_set_arrangement a)
{
    return (unsigned)a < ACBB_SET_ARRANGEMENTS;
}

const char *acbb_set_arrangement_name(acbb_set_arrangement a)
{
    return known(a) ? acbb_set_kinds[a].name : "?";
}

double acbb_set_pitch(const acbb_scene *s)
{
    return s->set_spacing > 0.0 ? s->set_spacing : s->width;
}

void acbb_set_spacers(const acbb_scene *s, double *L_inner, double *L_outer)
{
    double gap = acbb_set_pitch(s) - s->width;
    if (L_inner) *L_inner = s->set_inner_spacer > 0.0 ? s->set_inner_spacer : gap;
    if (L_outer) *L_outer = s->set_outer_spacer > 0.0 ? s->set_outer_spacer : gap;
}

static int count(const acbb_scene *s)
{
    if (s->set_n_bearings > 0) return s->set_n_bearings;
    return known(s->set_arrangement) ? acbb_set_kinds[s->set_arrangement].n : 1;
}

static int orientation(acbb_set_arrangement a, int k)
{
    if (!known(a)) return 1;
    const char *o = acbb_set_kinds[a].orient;
    size_t last = strlen(o) - 1;
    return o[(size_t)k < last ? (size_t)k : last] == '-' ? -1 : 1;
}

int acbb_set_layout(const acbb_scene *s, int orient[ACBB_MAX_SET], double x[ACBB_MAX_SET])
{
    int n = count(s);
    double c = acbb_set_pitch(s);
    for (int k = 0; k < n && k < ACBB_MAX_SET; k++) {
        if (orient) /* mirrored: read from the other end, each turned round */
            orient[k] = s->set_mirrored ? -orientation(s->set_arrangement, n - 1 - k)
                                        : orientation(s->set_arrangement, k);
        if (x) x[k] = (k - 0.5 * (n - 1)) * c;
    }
    return n;
}
