/* acbb TUI — metric menu, units and completion (see picker.h). */
#include <stdio.h>
#include <string.h>
#include "acbb/scene.h"
#include "acbb/sensitivity.h"
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

/* The units the run's JSON writes at the end of a name (cli output). */
static int is_unit(const char *s, size_t len)
{
    static const char *const units[] = { "W", "C", "N", "deg", "um", "mrad", "mps", "radps", "s" };
    for (size_t i = 0; i < sizeof units / sizeof units[0]; i++)
        if (strlen(units[i]) == len && strncmp(s, units[i], len) == 0) return 1;
    return 0;
}

void acbb_metric_unit(const char *path, char *buf, size_t n)
{
    buf[0] = '\0';
    const char *per = strstr(path, "_per_");
    if (per) { /* "..._N_per_um": N/um */
        const char *num = per;
        while (num > path && num[-1] != '_' && num[-1] != '.') num--;
        snprintf(buf, n, "%.*s/%s", (int)(per - num), num, per + 5);
        return;
    }
    /* The last name part "..._UNIT" before a '.' or the end. */
    for (const char *p = path; *p;) {
        const char *end = strchr(p, '.');
        if (!end) end = p + strlen(p);
        const char *u = end;
        while (u > p && u[-1] != '_') u--;
        if (u > p && is_unit(u, (size_t)(end - u))) snprintf(buf, n, "%.*s", (int)(end - u), u);
        p = *end ? end + 1 : end;
    }
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
