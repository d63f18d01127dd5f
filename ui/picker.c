/* acbb TUI — metric menu, units and completion (see picker.h). */
#include <stdio.h>
#include <string.h>
#include "acbb/outputs.h"
#include "acbb/scene.h"
#include "acbb/tools/sensitivity.h"
#include "acbb/tools/scene_schema.h"
#include "picker.h"

const acbb_metric_item acbb_metric_menu[] = {
    { "losses_W.total", "total loss" },
    { "temperature_C.outer_ring", "outer ring T" },
    { "temperature_C.ball", "ball T" },
    { "balls[0].Qi_N", "Qi ball 0" },
    { "balls[0].alpha_i_deg", "alpha_i ball 0" },
    { "squeeze_um.net", "net squeeze" },
    { "ring.stiffness_axial_N_per_um", "axial stiffness" },
};
const int acbb_metric_menu_n = (int)(sizeof acbb_metric_menu / sizeof acbb_metric_menu[0]);

/* The output table's unit (outputs.h): the one the run's JSON converts to. */
void acbb_metric_unit(const char *path, char *buf, size_t n)
{
    acbb_output o;
    long k;
    snprintf(buf, n, "%s", acbb_output_find(path, &o, &k, NULL) == ACBB_OK ? o.unit : "");
}

int acbb_scene_key_name(size_t i, char *buf, size_t n)
{
    const acbb_field_info *f = acbb_scene_field(i);
    if (!f) return 0;
    snprintf(buf, n, "%s.%s", f->section, f->key);
    return 1;
}

int acbb_metric_choice(size_t i, char *buf, size_t n)
{
    char name[128];
    if (!acbb_metric_name(i, name, sizeof name)) return 0;
    char *at = strstr(name, "[i]");
    if (at) snprintf(buf, n, "%.*s[0]%s", (int)(at - name), name, at + 3);
    else snprintf(buf, n, "%s", name);
    return 1;
}

/* Length of the common start of a and b. */
static size_t common(const char *a, const char *b)
{
    size_t k = 0;
    while (a[k] && a[k] == b[k]) k++;
    return k;
}

int acbb_complete(char *text, size_t cap, acbb_name_fn name_at, char *shown, size_t shown_n)
{
    char name[128], best[128] = "";
    size_t tl = strlen(text), used = 0;
    int count = 0;
    if (shown_n) shown[0] = '\0';
    for (int pass = 0; pass < 2 && count == 0; pass++) { /* prefix, then substring */
        for (size_t i = 0; name_at(i, name, sizeof name); i++) {
            int hit = pass == 0 ? strncmp(name, text, tl) == 0 : strstr(name, text) != NULL;
            if (!hit) continue;
            if (count++ == 0) snprintf(best, sizeof best, "%s", name);
            else best[common(best, name)] = '\0';
            size_t need = strlen(name) + (used ? 1 : 0);
            if (used + need + 1 < shown_n) {
                used += (size_t)snprintf(shown + used, shown_n - used, "%s%s", used ? " " : "", name);
            }
        }
    }
    if (count > 0 && strlen(best) > tl && strlen(best) < cap) snprintf(text, cap, "%s", best);
    return count;
}
