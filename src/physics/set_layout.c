/* acbb — the layout of a bearing set (MODEL.md section 14, acbb/set.h).
 * Orientations: DB (O) +-, DF (X) -+, DT tandem ++.., DBT ++-, QBC ++--
 * [HK-EC, preloading chapter]; bearings numbered by increasing x. */
#include <stddef.h>
#include "acbb/set.h"

const char *acbb_set_arrangement_name(acbb_set_arrangement a)
{
    static const char *const names[] = { "single", "DB", "DF", "DT", "DBT", "QBC" };
    return (unsigned)a < sizeof names / sizeof names[0] ? names[a] : "?";
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
    static const int n[] = { 1, 2, 2, 2, 3, 4 };
    if (s->set_n_bearings > 0) return s->set_n_bearings;
    return (unsigned)s->set_arrangement < 6 ? n[s->set_arrangement] : 1;
}

static int orientation(acbb_set_arrangement a, int n, int k)
{
    switch (a) {
    case ACBB_SET_DB: return k == 0 ? 1 : -1;
    case ACBB_SET_DF: return k == 0 ? -1 : 1;
    case ACBB_SET_DBT: case ACBB_SET_QBC: return 2 * k < n ? 1 : -1;
    default: return 1;
    }
}

int acbb_set_layout(const acbb_scene *s, int orient[ACBB_MAX_SET], double x[ACBB_MAX_SET])
{
    int n = count(s);
    double c = acbb_set_pitch(s);
    for (int k = 0; k < n && k < ACBB_MAX_SET; k++) {
        if (orient) orient[k] = orientation(s->set_arrangement, n, k);
        if (x) x[k] = (k - 0.5 * (n - 1)) * c;
    }
    return n;
}
