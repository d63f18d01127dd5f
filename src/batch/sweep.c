/* acbb — sweeps in N dimensions: the grid and its points (sweep.h).
 * The worker pool is src/batch/sweep_run.c. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/sweep.h"
#include "acbb/tools/scene_schema.h"
#include "c_locale.h"

typedef struct {
    char key[ACBB_SWEEP_KEY];
    size_t n;
    char (*values)[ACBB_SWEEP_VALUE];
} sweep_dim;

struct acbb_sweep {
    size_t n_dims;
    sweep_dim dims[ACBB_SWEEP_MAX_DIMS];
    size_t n_points;
};

acbb_status acbb_sweep_new(acbb_sweep **out)
{
    *out = calloc(1, sizeof **out);
    return *out ? ACBB_OK : ACBB_ENOMEM;
}

void acbb_sweep_free(acbb_sweep *g)
{
    if (!g) return;
    for (size_t d = 0; d < g->n_dims; d++) free(g->dims[d].values);
    free(g);
}

/* "section.key" names a field of the scene schema. */
static int known_key(const char *key)
{
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        const acbb_field_info *f = acbb_scene_field(i);
        size_t ls = strlen(f->section);
        if (strncmp(key, f->section, ls) == 0 && key[ls] == '.' &&
            strcmp(key + ls + 1, f->key) == 0)
            return 1;
    }
    return 0;
}

static int parse_double(const char *s, size_t len, double *v)
{
    char buf[ACBB_SWEEP_VALUE];
    if (len == 0 || len >= sizeof buf) return 0;
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *end = NULL;
    errno = 0;
    *v = acbb_strtod_c(buf, &end);
    return errno == 0 && *end == '\0' && isfinite(*v);
}

/* "lo:hi:n": n evenly spaced values, both ends exact. */
static acbb_status parse_range(sweep_dim *d, const char *spec, const char *text,
                               acbb_error *err)
{
    const char *c1 = strchr(text, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    double lo, hi, n;
    if (!c2 || strchr(c2 + 1, ':') || !parse_double(text, (size_t)(c1 - text), &lo) ||
        !parse_double(c1 + 1, (size_t)(c2 - c1 - 1), &hi) ||
        !parse_double(c2 + 1, strlen(c2 + 1), &n) || n != floor(n) || n < 1 ||
        n > ACBB_SWEEP_MAX_VALUES)
        return acbb_error_set(err, ACBB_EINVAL,
                              "%s: expected lo:hi:n, two finite numbers and a whole "
                              "n in 1..%d", spec, ACBB_SWEEP_MAX_VALUES);
    d->n = (size_t)n;
    d->values = calloc(d->n, sizeof *d->values);
    if (!d->values) return ACBB_ENOMEM;
    for (size_t k = 0; k < d->n; k++) {
        /* hi exactly, not lo + (n-1)*step with its rounding. */
        double t = d->n > 1 ? (double)k / (double)(d->n - 1) : 0.0;
        double v = d->n > 1 && k + 1 == d->n ? hi : lo + (hi - lo) * t;
        snprintf(d->values[k], sizeof d->values[k], "%.10g", v);
    }
    return ACBB_OK;
}

/* "v1,v2,...": each value as typed. */
static acbb_status parse_list(sweep_dim *d, const char *spec, const char *text,
                              acbb_error *err)
{
    d->n = 1;
    for (const char *p = text; *p; p++) d->n += *p == ',';
    if (d->n > ACBB_SWEEP_MAX_VALUES)
        return acbb_error_set(err, ACBB_EINVAL, "%s: more than %d values", spec,
                              ACBB_SWEEP_MAX_VALUES);
    d->values = calloc(d->n, sizeof *d->values);
    if (!d->values) return ACBB_ENOMEM;
    const char *p = text;
    for (size_t k = 0; k < d->n; k++) {
        size_t len = strcspn(p, ",");
        if (len == 0 || len >= sizeof d->values[k])
            return acbb_error_set(err, ACBB_EINVAL,
                                  "%s: value %zu is empty or longer than %d characters",
                                  spec, k + 1, ACBB_SWEEP_VALUE - 1);
        memcpy(d->values[k], p, len);
        p += len + (p[len] == ',');
    }
    return ACBB_OK;
}

static acbb_status check_key(const acbb_sweep *g, const char *spec, const char *key,
                             size_t klen, acbb_error *err)
{
    if (klen == 0 || klen >= ACBB_SWEEP_KEY)
        return acbb_error_set(err, ACBB_EINVAL, "%s: expected section.key=VALUES", spec);
    if (g->n_dims == ACBB_SWEEP_MAX_DIMS)
        return acbb_error_set(err, ACBB_EINVAL, "%s: at most %d dimensions", spec,
                              ACBB_SWEEP_MAX_DIMS);
    char name[ACBB_SWEEP_KEY];
    memcpy(name, key, klen);
    name[klen] = '\0';
    if (!known_key(name))
        return acbb_error_set(err, ACBB_EINVAL,
                              "%s: unknown key %s", spec, name);
    for (size_t d = 0; d < g->n_dims; d++)
        if (strcmp(g->dims[d].key, name) == 0)
            return acbb_error_set(err, ACBB_EINVAL, "%s: %s is already a dimension",
                                  spec, name);
    return ACBB_OK;
}

acbb_status acbb_sweep_add(acbb_sweep *g, const char *spec, acbb_error *err)
{
    const char *eq = strchr(spec, '=');
    if (!eq)
        return acbb_error_set(err, ACBB_EINVAL,
                              "%s: expected section.key=v1,v2,... or section.key=lo:hi:n",
                              spec);
    acbb_status st = check_key(g, spec, spec, (size_t)(eq - spec), err);
    if (st != ACBB_OK) return st;
    sweep_dim d = { .n = 0 };
    memcpy(d.key, spec, (size_t)(eq - spec));
    const char *text = eq + 1;
    st = strchr(text, ':') && !strchr(text, ',') ? parse_range(&d, spec, text, err)
                                                 : parse_list(&d, spec, text, err);
    size_t total = g->n_dims ? g->n_points : 1;
    if (st == ACBB_OK && total * d.n > ACBB_SWEEP_MAX_POINTS)
        st = acbb_error_set(err, ACBB_EINVAL, "%s: the grid would have over %d points",
                            spec, ACBB_SWEEP_MAX_POINTS);
    if (st != ACBB_OK) {
        free(d.values);
        return st;
    }
    g->dims[g->n_dims++] = d;
    g->n_points = total * d.n;
    return ACBB_OK;
}

size_t acbb_sweep_n_dims(const acbb_sweep *g) { return g->n_dims; }
const char *acbb_sweep_key(const acbb_sweep *g, size_t dim) { return g->dims[dim].key; }
size_t acbb_sweep_n_values(const acbb_sweep *g, size_t dim) { return g->dims[dim].n; }
size_t acbb_sweep_n_points(const acbb_sweep *g) { return g->n_dims ? g->n_points : 0; }

const char *acbb_sweep_value(const acbb_sweep *g, size_t index, size_t dim)
{
    /* Row-major: the last dimension varies fastest. */
    for (size_t d = g->n_dims; d-- > dim + 1;) index /= g->dims[d].n;
    return g->dims[dim].values[index % g->dims[dim].n];
}

acbb_status acbb_sweep_scene(const acbb_sweep *g, const acbb_scene *base, size_t index,
                             acbb_scene *out, acbb_error *err)
{
    /* One batch, as several --set: the order of the dimensions does not
     * matter to the cross-field rules. */
    char edits[ACBB_SWEEP_MAX_DIMS][ACBB_SWEEP_KEY + ACBB_SWEEP_VALUE + 2];
    const char *list[ACBB_SWEEP_MAX_DIMS];
    for (size_t d = 0; d < g->n_dims; d++) {
        snprintf(edits[d], sizeof edits[d], "%s=%s", g->dims[d].key,
                 acbb_sweep_value(g, index, d));
        list[d] = edits[d];
    }
    *out = *base;
    return acbb_scene_apply_edits(out, list, g->n_dims, err);
}

int acbb_sweep_in_shard(size_t index, size_t k, size_t n)
{
    return n <= 1 || index % n == k - 1;
}

acbb_status acbb_sweep_check_values(const acbb_sweep *g, const acbb_scene *base, size_t *dim,
                                    size_t *value, acbb_error *err)
{
    for (size_t d = 0; d < g->n_dims; d++)
        for (size_t v = 0; v < g->dims[d].n; v++) {
            acbb_scene trial = *base;
            acbb_status st = acbb_scene_set_value(&trial, g->dims[d].key, g->dims[d].values[v], err);
            if (st != ACBB_OK) {
                *dim = d;
                *value = v;
                return st;
            }
        }
    return ACBB_OK;
}

const char *acbb_sweep_dim_value(const acbb_sweep *g, size_t dim, size_t v)
{
    return g->dims[dim].values[v];
}
