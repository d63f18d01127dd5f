/* acbb — the physics profiles' table (physics_profile.h, issue 25).
 *
 * One row per key a profile sets: the key and its value under each
 * profile, in preset text. Adding a key to the profiles is one row here
 * (at most 32 rows: scene.h's profile_given bitmask). Each reference value
 * is cited where its physics lives:
 * - rolling hysteresis, Johnson's sphere: K. L. Johnson, Contact Mechanics,
 *   1985, ch. 9 (src/physics/losses.c);
 * - EHL rolling resistance: MODEL.md 16 (src/physics/ehl_rolling.c);
 * - churning / jet momentum by lubrication method: MODEL.md 16
 *   (src/physics/churning.c); the drag medium by method is in both
 *   profiles already (lubricant.method);
 * - cage-land shear, Petroff: MODEL.md 6 (iii) (src/physics/losses.c).
 * Mixed-film friction below Lambda ~ 2.3 (the asperity load share of
 * MODEL.md 5) is on in both profiles; see docs/losses_validation.md for
 * what the reference profile still lacks. */
#include <stdio.h>
#include <string.h>

#include "acbb/tools/physics_profile.h"
#include "acbb/tools/scene_schema.h"
#include "scene_internal.h"

typedef struct {
    const char *key;             /* "section.key" */
    const char *value[2];        /* [ACBB_PROFILE_SEED], [ACBB_PROFILE_REFERENCE] */
} profile_row;

static const profile_row k_rows[] = {
    /* key                              seed      reference */
    { "fidelity.rolling_hysteresis", { "seed", "johnson" } },
    { "effects.loss_ehl_rolling", { "off", "on" } },
    { "effects.loss_churning", { "off", "on" } },
    { "effects.loss_cage", { "off", "on" } },
    /* contact heat through moving-source spot resistances (docs/contact_heat.md) */
    { "thermal.contact_model", { "stationary", "moving" } },
};

#define N_ROWS (sizeof k_rows / sizeof k_rows[0])
_Static_assert(N_ROWS <= 8 * sizeof(unsigned), "profile_given holds one bit per row");

static const char *const k_names[] = { "seed", "reference" };

const char *acbb_profile_name(acbb_physics_profile p)
{
    return p == ACBB_PROFILE_SEED || p == ACBB_PROFILE_REFERENCE ? k_names[p] : "?";
}

size_t acbb_profile_row_count(void) { return N_ROWS; }

const char *acbb_profile_row_key(size_t k)
{
    return k < N_ROWS ? k_rows[k].key : NULL;
}

const char *acbb_profile_row_value(size_t k, acbb_physics_profile p)
{
    return k < N_ROWS && (p == ACBB_PROFILE_SEED || p == ACBB_PROFILE_REFERENCE)
               ? k_rows[k].value[p] : NULL;
}

const acbb_sfield *acbb_sf_profile_field(size_t k)
{
    if (k >= N_ROWS) return NULL;
    const char *dot = strchr(k_rows[k].key, '.');
    char section[32];
    snprintf(section, sizeof section, "%.*s", (int)(dot - k_rows[k].key), k_rows[k].key);
    return acbb_sf_find(section, dot + 1);
}

/* By name: every key edit asks (scene_value.c note_profile), and looking
 * each row's field up was 70 % of an edit (issue 30). The rows name
 * fields as acbb_sf_find does (test scene: row k's field is row k). */
int acbb_sf_profile_row(const acbb_sfield *f)
{
    if (!f) return -1;
    size_t n = strlen(f->info.section);
    for (size_t k = 0; k < N_ROWS; k++)
        if (strncmp(k_rows[k].key, f->info.section, n) == 0 && k_rows[k].key[n] == '.'
            && strcmp(k_rows[k].key + n + 1, f->info.key) == 0)
            return (int)k;
    return -1;
}

bool acbb_sf_profile_own(const acbb_scene *s, const char *section, const char *key)
{
    const acbb_sfield *f = acbb_sf_find(section, key);
    if (!f || acbb_sf_profile_row(f) < 0) return true;
    acbb_scene d;
    acbb_sf_profile_defaults(&d, s->profile);
    size_t i = (size_t)(f - acbb_sf_table);
    char mine[64], its[64];
    acbb_scene_field_format(s, i, mine, sizeof mine);
    acbb_scene_field_format(&d, i, its, sizeof its);
    return strcmp(mine, its) != 0;
}

void acbb_profile_apply(acbb_scene *s)
{
    acbb_physics_profile p = s->profile == ACBB_PROFILE_REFERENCE ? s->profile : ACBB_PROFILE_SEED;
    for (size_t k = 0; k < N_ROWS; k++) {
        if (s->profile_given & (1u << k)) continue;
        const acbb_sfield *f = acbb_sf_profile_field(k);
        acbb_error e;
        /* The table's values are valid choices (test_profile checks each
         * row parses): nothing to report here. */
        if (f) (void)acbb_sf_apply(s, f, k_rows[k].value[p], &e);
    }
}

void acbb_sf_profile_defaults(acbb_scene *d, acbb_physics_profile p)
{
    acbb_scene_default(d);
    d->profile = p;
    acbb_profile_apply(d);
    /* The profile key's own default stays seed (a preset without it). */
    d->profile = ACBB_PROFILE_SEED;
}
