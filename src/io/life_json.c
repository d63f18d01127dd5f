/* acbb — the `life` object of a run's JSON (MODEL.md 15, life.h): the
 * output table's "life" rows (so the JSON, CSV and metrics agree), then
 * the flags and the contacts they name. */
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/tools/life_eval.h"
#include "acbb/outputs.h"
#include "life_json.h"

void acbb_json_write_life(acbb_json *j, const acbb_snapshot *s)
{
    const acbb_life *L = &s->life;
    char name[32];
    acbb_json_open(j, "life", '{', false);
    acbb_output e;
    for (size_t i = 0; acbb_output_get(i, &e); i++)
        if (e.row->section && !strcmp(e.row->section, "life"))
            acbb_json_num(j, e.key, acbb_output_value(&e, s, -1));
    acbb_json_str(j, "C0_basis", L->C0_table ? "ISO 76 Table 1" : "4200 MPa, real grooves");
    acbb_json_bool(j, "kappa_clamped", L->kappa_clamped);
    acbb_life_contact_name(L->s0_ball, L->s0_race, name, sizeof name);
    acbb_json_str(j, "s0_contact", name);
    acbb_json_bool(j, "edge_loaded", L->edge_loaded);
    acbb_life_contact_name(L->edge_ball, L->edge_race, name, sizeof name);
    acbb_json_str(j, "edge_contact", name);
    acbb_json_bool(j, "estimated", L->estimated);
    acbb_json_close(j, '}');
}
