/* acbb — robustness of the seed study's verdicts over the plausible ranges
 * (study.h): the study's own check table re-evaluated on the run set of
 * every single plausible change, all perturbed runs in one pool.
 * MODEL.md 13: the heavy-load TE/WTE statements rest on sub-micron
 * balances, so each verdict is reported with the single changes that turn
 * it. Nothing here changes the physics; it only re-runs the study. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/measure.h"
#include "acbb/tools/scene_schema.h"
#include "acbb/tools/surroundings.h"
#include "study_priv.h"
#include "cancel.h"

/* Item 18 (sanity: zero speed, energy balance, closed forms) holds for any
 * parameter values: MODEL.md 12 does not ask for its robustness. */
#define SANITY_ITEM 18

typedef struct {
    acbb_sens_input in;
    char value[64];              /* the end, as preset text */
    acbb_study_runs runs;
} rob_end;

/* Points on which an input provably has no effect, so the base study's run
 * is that point's run (each case is checked bit-for-bit against a direct
 * run in tests/test_study_sens.c):
 * - the expansion coefficients in a WTE run: expansion.c returns all
 *   expansions 0 without thermal expansion (MODEL.md 9, 12);
 * - a surroundings film coefficient on a face held fixed: network.c adds
 *   the film resistance only to a convective face (MODEL.md 8.1, 13);
 * - phi_p in the 46-node network: it splits the contact heat of the
 *   7-node network only (MODEL.md 8.3). */
static int inert(const char *key, const acbb_scene *p)
{
    size_t n = strlen(key);
    if (strncmp(key, "materials.", 10) == 0 && n > 16 && strcmp(key + n - 16, "_expansion_ppm_K") == 0)
        return !p->thermal_expansion;
    if (strcmp(key, "surroundings.shaft_bore_h_W_m2K") == 0)
        return acbb_face_bc_kind(p, &p->bore_bc) != ACBB_BC_CONVECTIVE;
    if (strcmp(key, "surroundings.cap_h_W_m2K") == 0)
        return acbb_face_bc_kind(p, &p->cap_bc) != ACBB_BC_CONVECTIVE;
    if (strcmp(key, "thermal.heat_partition") == 0) return p->network == ACBB_NET_46;
    return 0;
}

static int selected(const acbb_study_rob_opts *o, const char *key)
{
    if (!o->keys) return 1;
    for (size_t i = 0; i < o->n_keys; i++)
        if (strcmp(o->keys[i], key) == 0) return 1;
    return 0;
}

static acbb_status check_keys(const acbb_study_rob_opts *o, const acbb_sens_input *in, size_t n,
                              acbb_error *err)
{
    for (size_t k = 0; o->keys && k < o->n_keys; k++) {
        size_t i = 0;
        while (i < n && strcmp(in[i].key, o->keys[k]) != 0) i++;
        if (i == n)
            return acbb_error_set(err, ACBB_EINVAL, "%s is not an uncertain input (one with a "
                                  "plausible range)", o->keys[k]);
    }
    return ACBB_OK;
}

acbb_status acbb_study_rob_check_keys(const acbb_scene *s, const acbb_study_rob_opts *o,
                                      acbb_error *err)
{
    acbb_sens_input in[ACBB_SENS_MAX];
    return check_keys(o, in, acbb_sens_inputs(s, in, ACBB_SENS_MAX), err);
}

int acbb_study_plan_end(acbb_study_runs *r, const acbb_study_runs *b, const acbb_sens_input *in,
                        int hi)
{
    for (size_t i = 0; i < b->n; i++)
        if (b->all[i].skip) return 0;
    *r = (acbb_study_runs){ .model = b->model, .n = b->n };
    if (!(r->all = calloc(b->n, sizeof *r->all))) return 0;
    for (int lv = 0; lv < 2; lv++)
        for (int k = 0; k < ACBB_STUDY_NSWEEPS; k++)
            r->sweep[lv][k] = r->all + (b->sweep[lv][k] - b->all);
    r->zero = r->all + (b->zero - b->all);
    r->statics = r->all + (b->statics - b->all);
    for (size_t i = 0; i < b->n; i++) {
        acbb_study_point *p = &r->all[i];
        acbb_error err = { { 0 } };
        p->scene = b->all[i].scene;
        p->record = b->all[i].record;
        p->min_loss = INFINITY;
        memcpy(p->label, b->all[i].label, sizeof p->label);
        acbb_status st = acbb_sens_apply(&p->scene, in, hi, &err);
        if (st == ACBB_OK) st = acbb_scene_validate(&p->scene, &err);
        if (st != ACBB_OK) {
            p->status = st;
            p->skip = 1;
            snprintf(p->message, sizeof p->message, "%s", err.msg);
        }
    }
    return 1;
}

/* The ends of the selected inputs that differ from the scene's value, each
 * with its (unrun) run set. */
static acbb_status plan_ends(const acbb_scene *base, const acbb_study_runs *base_runs,
                             const acbb_study_rob_opts *o, rob_end **out, size_t *n_out,
                             acbb_study_rob *r, acbb_error *err)
{
    acbb_sens_input in[ACBB_SENS_MAX];
    size_t n = acbb_sens_inputs(base, in, ACBB_SENS_MAX), m = 0;
    acbb_status st = check_keys(o, in, n, err);
    rob_end *e = calloc(2 * n + 1, sizeof *e);
    if (st == ACBB_OK && !e) st = acbb_error_set(err, ACBB_ENOMEM, "robustness: out of memory");
    for (size_t i = 0; st == ACBB_OK && i < n; i++) {
        if (!selected(o, in[i].key)) continue;
        r->n_inputs++;
        for (int hi = 0; st == ACBB_OK && hi < 2; hi++) {
            acbb_scene t = *base;
            st = acbb_sens_apply(&t, &in[i], hi, err);
            char now[64];
            acbb_scene_field_format(&t, in[i].field, now, sizeof now);
            if (st != ACBB_OK) break;
            if (strcmp(now, in[i].base) == 0) {
                r->n_same++;
                continue;
            }
            e[m].in = in[i];
            snprintf(e[m].value, sizeof e[m].value, "%s", hi ? in[i].hi : in[i].lo);
            if (!acbb_study_plan_end(&e[m].runs, base_runs, &in[i], hi)
                && acbb_study_plan_runs(&e[m].runs, &t) != ACBB_OK)
                st = acbb_error_set(err, ACBB_ENOMEM, "robustness: out of memory");
            m++;
        }
    }
    *out = e;
    *n_out = m;
    r->n_ends = m;
    return st;
}

static void copy_point(acbb_study_point *p, const acbb_study_point *b)
{
    p->ok = b->ok;
    p->status = b->status;
    memcpy(p->message, b->message, sizeof p->message);
    p->first = b->first;
    p->last = b->last;
    p->min_loss = b->min_loss;
    p->oom = b->oom;
    p->n_traj = 0;
    if (!b->n_traj) return;
    p->traj = malloc(b->n_traj * sizeof *p->traj);
    if (!p->traj) {
        p->ok = 0;
        p->status = ACBB_ENOMEM;
        snprintf(p->message, sizeof p->message, "out of memory copying the transient");
        return;
    }
    memcpy(p->traj, b->traj, b->n_traj * sizeof *p->traj);
    p->n_traj = p->cap_traj = b->n_traj;
}

/* Points of end e to run go to list; the others are skipped (the zero-speed
 * run: item 18 only) or taken from the base study. */
static size_t share(rob_end *e, const acbb_study_runs *base, acbb_study_point **list,
                    acbb_study_rob *r)
{
    size_t n = 0;
    for (size_t i = 0; i < e->runs.n; i++) {
        acbb_study_point *p = &e->runs.all[i];
        if (p->skip) continue;
        if (p == e->runs.zero) {
            p->skip = 1;
            snprintf(p->message, sizeof p->message, "not run: item %d is not varied", SANITY_ITEM);
        } else if (inert(e->in.key, &p->scene)) {
            copy_point(p, &base->all[i]);
            r->n_shared++;
        } else {
            p->warm_from = base->all[i].warm; /* steady points (batch.c) */
            list[n++] = p;
        }
    }
    return n;
}

/* Check k of `it` changed against the base's `b` (not an info check). */
static int changed(const acbb_study_item *b, const acbb_study_item *it, int k)
{
    const acbb_study_check *c = &it->checks[k];
    int same = k < b->n_checks && strcmp(b->checks[k].id, c->id) == 0 &&
               b->checks[k].verdict == c->verdict;
    return !same && !c->info;
}

static int flips(const acbb_study_item *b, const acbb_study_item *it)
{
    int n = it->verdict != b->verdict;
    for (int k = 0; !n && k < it->n_checks; k++) n = changed(b, it, k);
    return n;
}

/* End e's item `it` against the base's `b`: a flip if a check (not info)
 * changed its verdict; item turns are kept ahead of partial ones. */
static acbb_status add_flip(acbb_study_item_rob *ir, const rob_end *e, const acbb_study_item *b,
                            const acbb_study_item *it)
{
    if (!flips(b, it)) return ACBB_OK;
    acbb_study_flip f = { .verdict = it->verdict, .turns_item = it->verdict != b->verdict };
    for (int k = 0; k < it->n_checks; k++)
        if (changed(b, it, k)) f.checks[f.n_checks++] = it->checks[k];
    acbb_study_flip *a = realloc(ir->flips, (ir->n_flips + 1) * sizeof *a);
    if (!a) return ACBB_ENOMEM;
    ir->flips = a;
    snprintf(f.key, sizeof f.key, "%s", e->in.key);
    snprintf(f.value, sizeof f.value, "%s", e->value);
    size_t at = f.turns_item ? ir->n_turns++ : ir->n_flips;
    memmove(&a[at + 1], &a[at], (ir->n_flips - at) * sizeof *a);
    a[at] = f;
    ir->n_flips++;
    return ACBB_OK;
}

/* Every row over every end: the ends whose verdict differs from the base. */
static acbb_status evaluate(const acbb_study_row *rows, const acbb_study_runs *base,
                            const rob_end *e, size_t n_ends, acbb_study_rob *r)
{
    acbb_study_item *b = malloc(sizeof *b), *it = malloc(sizeof *it);
    acbb_status st = b && it ? ACBB_OK : ACBB_ENOMEM;
    for (size_t k = 0; st == ACBB_OK && k < r->n_items; k++) {
        acbb_study_item_rob *ir = &r->items[k];
        acbb_study_eval_row(&rows[k], base, b);
        ir->num = rows[k].num;
        ir->verdict = b->verdict;
        ir->varied = rows[k].num != SANITY_ITEM;
        for (size_t j = 0; st == ACBB_OK && ir->varied && j < n_ends; j++) {
            /* The texts only where a flip prints them (issue 30: 0.2 G of
             * `report --sensitivity`); the same verdicts (study_priv.h). */
            if (!acbb_study_eval_verdicts(&rows[k], &e[j].runs, it) || flips(b, it))
                acbb_study_eval_row(&rows[k], &e[j].runs, it);
            st = add_flip(ir, &e[j], b, it);
        }
    }
    free(b);
    free(it);
    return st;
}

static void signs(const acbb_study_runs *base, const rob_end *e, size_t n_ends, acbb_study_rob *r)
{
    const acbb_study_sign *sg = acbb_study_signs(&r->n_signs);
    for (size_t k = 0; k < r->n_signs; k++) {
        acbb_study_robust *o = &r->signs[k];
        o->sign = &sg[k];
        o->n_inputs = r->n_inputs;
        acbb_study_sign_base(base, o);
        for (size_t j = 0; j < n_ends; j++)
            acbb_study_sign_end(&e[j].runs, e[j].in.key, e[j].value, o);
    }
}

/* Plan every end, share what need not run, run the rest in one pool. */
static acbb_status run_ends(const acbb_study *base, const acbb_study_rob_opts *o, rob_end **e,
                            size_t *n_ends, acbb_study_rob *r, acbb_error *err)
{
    acbb_status st = plan_ends(&base->base, &base->runs, o, e, n_ends, r, err);
    size_t cap = 0, n = 0;
    for (size_t j = 0; st == ACBB_OK && j < *n_ends; j++) cap += (*e)[j].runs.n;
    acbb_study_point **list = st == ACBB_OK ? malloc((cap ? cap : 1) * sizeof *list) : NULL;
    if (st == ACBB_OK && !list) st = acbb_error_set(err, ACBB_ENOMEM, "robustness: out of memory");
    for (size_t j = 0; st == ACBB_OK && j < *n_ends; j++)
        n += share(&(*e)[j], &base->runs, list + n, r);
    /* The check table reads no rating life (issue 30: 2 % of a perturbed
     * study), and no perturbed point starts another. */
    if (st == ACBB_OK) acbb_study_run_list(list, n, o->jobs, 1, o->cancel, o->progress, o->ctx);
    r->n_runs = st == ACBB_OK ? n : 0;
    for (size_t i = 0; i < r->n_runs; i++) r->n_failed += !list[i]->ok;
    free(list);
    if (st == ACBB_OK && acbb_cancelled(o->cancel))
        st = acbb_error_set(err, ACBB_CANCELLED, "cancelled");
    return st;
}

acbb_status acbb_study_robustness(const acbb_study *base, const acbb_study_rob_opts *o,
                                  acbb_study_rob *r, acbb_error *err)
{
    double t0 = acbb_now_ms();
    memset(r, 0, sizeof *r);
    const acbb_study_row *rows = o->rows;
    r->n_items = o->n_rows;
    if (!rows) rows = acbb_study_table(&r->n_items);
    size_t n_signs, n_ends = 0;
    acbb_study_signs(&n_signs);
    r->items = calloc(r->n_items ? r->n_items : 1, sizeof *r->items);
    r->signs = calloc(n_signs, sizeof *r->signs);
    rob_end *e = NULL;
    acbb_status st = r->items && r->signs ? ACBB_OK
                     : acbb_error_set(err, ACBB_ENOMEM, "robustness: out of memory");
    if (st == ACBB_OK) st = run_ends(base, o, &e, &n_ends, r, err);
    if (st == ACBB_OK) st = evaluate(rows, &base->runs, e, n_ends, r);
    if (st == ACBB_OK) signs(&base->runs, e, n_ends, r);
    for (size_t j = 0; e && j < n_ends; j++) acbb_study_free_runs(&e[j].runs);
    free(e);
    if (st == ACBB_ENOMEM) acbb_error_set(err, st, "robustness: out of memory");
    if (st != ACBB_OK) acbb_study_rob_free(r);
    r->wall_ms = acbb_now_ms() - t0;
    return st;
}

void acbb_study_rob_free(acbb_study_rob *r)
{
    for (size_t k = 0; r->items && k < r->n_items; k++) free(r->items[k].flips);
    free(r->items);
    free(r->signs);
    memset(r, 0, sizeof *r);
}
