/* acbb CLI — output writers (see output.h).
 *
 * JSON goes through the engine's writer (acbb/tools/json.h). Numbers use %.17g in
 * JSON and CSV: the double itself (issue 21 item 10); the summary table
 * uses fixed widths that keep every line within 80 columns. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "acbb/tools/json.h"
#include "acbb/tools/life_eval.h"
#include "acbb/outputs.h"
#include "acbb/tools/physics_profile.h"
#include "acbb/units.h"
#include "acbb/tools/set.h"
#include "wrap.h"
#include "acbb/tools/scene_schema.h"
#include "output.h"

#define CLI_UM 1e6                                   /* m -> um */

void acbb_cli_out_init(acbb_cli_out *o, FILE *f)
{
    memset(o, 0, sizeof *o);
    o->f = f;
}

bool acbb_cli_point_ok(const acbb_cli_point *p)
{
    return p->have_snap && !p->internal_error &&
           p->snap.state == ACBB_RUN_CONVERGED;
}

const char *acbb_cli_point_status(const acbb_cli_point *p)
{
    if (!p->have_snap) return acbb_status_name(p->status);
    return acbb_run_status_name(&p->snap);
}

/* ---- plain-table cells: never print nan/inf, count them instead ---- */

static void put_num(acbb_cli_out *o, int width, int prec, char conv, double v)
{
    if (!isfinite(v)) {
        o->nonfinite++;
        fprintf(o->f, "%*s", width, "-");
    } else if (conv == 'g') {
        fprintf(o->f, "%*.*g", width, prec, v);
    } else {
        fprintf(o->f, "%*.*f", width, prec, v);
    }
}

/* A table cell `width` wide that always starts with a blank, so a value
 * wider than planned (an exponent) shifts the row but never fuses with its
 * neighbour. */
static void cell(acbb_cli_out *o, int width, int prec, char conv, double v)
{
    fputc(' ', o->f);
    put_num(o, width - 1, prec, conv, v);
}

void acbb_cli_num(acbb_cli_out *o, int width, int prec, char conv, double v)
{
    put_num(o, width, prec, conv, v);
}

void acbb_cli_cell(acbb_cli_out *o, int width, int prec, char conv, double v)
{
    cell(o, width, prec, conv, v);
}

/* ---- CSV ---- */

static void c_num(acbb_cli_out *o, double v, bool last)
{
    if (isfinite(v)) fprintf(o->f, "%.17g", v);
    else o->nonfinite++;
    fputc(last ? '\n' : ',', o->f);
}

/* ---- columns of the output table (outputs.h) ---- */

/* The entries of a static column list: paths of the output table, or
 * "SECTION.*" for every per-loss entry of a bearing SECTION (a new loss
 * kind becomes a column by itself). A path the table lacks is a bug. */
static size_t resolve(const char *const *spec, size_t n, acbb_cli_col *c)
{
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        size_t len = strlen(spec[i]);
        acbb_output e;
        long k;
        if (len > 2 && strcmp(spec[i] + len - 2, ".*") == 0) {
            for (size_t j = 0; acbb_output_get(j, &e) && m < ACBB_CLI_COLS; j++)
                if (e.loss >= 0 && e.row->scope == ACBB_OUT_BEARING &&
                    strncmp(e.row->section, spec[i], len - 2) == 0)
                    c[m++] = (acbb_cli_col){ e, -1 };
            continue;
        }
        if (m >= ACBB_CLI_COLS || acbb_output_find(spec[i], &e, &k, NULL) != ACBB_OK) abort();
        c[m++] = (acbb_cli_col){ e, (int)k };
    }
    return m;
}

/* The columns of `spec`, resolved once per writer (a CSV row per step). */
#define COLS(o, spec, n) cols(o, spec, sizeof spec / sizeof spec[0], n)
static const acbb_cli_col *cols(acbb_cli_out *o, const char *const *spec, size_t nspec,
                                size_t *n)
{
    acbb_cli_colset *set = NULL;
    for (int i = 0; i < ACBB_CLI_COLSETS && !set; i++)
        if (o->cols[i].spec == spec || !o->cols[i].spec) set = &o->cols[i];
    if (!set) abort(); /* more lists than ACBB_CLI_COLSETS: a bug */
    if (!set->spec) {
        set->n = resolve(spec, nspec, set->c);
        set->spec = spec;
    }
    *n = set->n;
    return set->c;
}

static double col_value(const acbb_cli_col *c, const acbb_snapshot *s)
{
    return acbb_output_value(&c->e, s, c->ball);
}

/* ---- acbb run ---- */

static const char *onoff(bool b) { return b ? "on" : "off"; }

/* The loads as the mounting reads them (MODEL.md 14): a single bearing
 * under a displacement preload has no axial force input (dx is fixed by
 * preload_N at assembly); a set adds its preload, its loads act at the
 * nose. The default mounting (one bearing, axial force) prints no line. */
static void summary_mounting(FILE *f, const acbb_scene *sc)
{
    bool rigid = sc->preload == ACBB_PRELOAD_DISPLACEMENT;
    if (sc->set_arrangement == ACBB_SET_SINGLE && rigid)
        fprintf(f, "%-13srigid preload %g N at assembly (axial offset fixed)\n", "mounting",
                sc->preload_force);
    else if (sc->set_arrangement != ACBB_SET_SINGLE)
        fprintf(f, "%-13s%s set, %s preload %g N at assembly, loads at the nose\n", "mounting",
                acbb_set_arrangement_name(sc->set_arrangement), rigid ? "rigid" : "spring",
                sc->preload_force);
}

static void summary_header(acbb_cli_out *o, const char *preset,
                           const acbb_scene *sc, const acbb_snapshot *s)
{
    FILE *f = o->f;
    fprintf(f, "acbb run %s\n", preset);
    fprintf(f, "%-13s%.0f rpm, ", "scene", acbb_rads_to_rpm(sc->inner_speed));
    if (sc->set_arrangement != ACBB_SET_SINGLE || sc->preload != ACBB_PRELOAD_DISPLACEMENT)
        fprintf(f, "Fx %g N, ", sc->axial_load);
    fprintf(f, "Fr %g N, thermal expansion %s, %s\n", sc->radial_load,
            onoff(sc->thermal_expansion), acbb_model_level_name(sc->model));
    fprintf(f, "%-13s%s profile (physics.profile)\n", "physics", acbb_profile_name(sc->profile));
    summary_mounting(f, sc);
    /* The whole message, wrapped under itself within 80 columns (it was
     * cut at 60 characters, mid-word). */
    int col = fprintf(f, "%-13s%s%s", "status", acbb_run_status_name(s),
                      s->message[0] ? ":" : "");
    if (s->message[0]) acbb_cli_wrap(f, s->message, col > 0 ? (size_t)col : 0, 13);
    fprintf(f, "\n%-13s%-10ld simulated time ", "iterations", s->iteration);
    put_num(o, 1, 1, 'f', s->time);
    fputs(" s   wall ", f);
    put_num(o, 1, 1, 'f', s->wall_ms);
    fprintf(f, " ms\n%-13s", "residual");
    put_num(o, 1, 3, 'g', s->residual);
    fputs(" K/s   energy in ", f);
    put_num(o, 1, 6, 'g', s->heat_in);
    fputs(" W, out ", f);
    put_num(o, 1, 6, 'g', s->heat_out);
    fputs(" W\n\n", f);
}

static void summary_losses(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s);

/* The losses switched on in the scene (the loss table's order) and the total,
 * at most LOSS_COLS columns a block so the summary keeps to 80 columns
 * (13 + 7 x 9); the seed's five and the total are one block as before. */
#define LOSS_COLS 7
static void summary_losses(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s)
{
    FILE *f = o->f;
    const acbb_losses *L = &s->losses;
    double P[ACBB_LOSS_KINDS + 1];
    const char *name[ACBB_LOSS_KINDS + 1];
    int n = 0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        if (!acbb_loss_enabled(sc, (acbb_loss_kind)l)) continue;
        name[n] = acbb_loss_name((acbb_loss_kind)l);
        P[n++] = L->P[l];
    }
    name[n] = "total";
    P[n++] = L->total;
    for (int b = 0; b < n; b += LOSS_COLS) {
        int e = b + LOSS_COLS < n ? b + LOSS_COLS : n;
        fprintf(f, b ? "\n%-13s" : "\n\n%-13s", b ? "" : "losses");
        for (int i = b; i < e; i++) fprintf(f, "%9.8s", name[i]); /* 8 wide: ehl_roll */
        fprintf(f, "\n%-13s", "  W");
        for (int i = b; i < e; i++) cell(o, 9, 4, 'g', P[i]);
        fprintf(f, "\n%-13s", "  %");
        for (int i = b; i < e; i++) {
            if (L->total > 0.0) cell(o, 9, 1, 'f', 100.0 * P[i] / L->total);
            else fprintf(f, "%9s", "-");
        }
    }
    fprintf(f, "\n%-13s%s", "loss set", acbb_loss_set(sc)); /* MODEL.md 16: seed | extended */
}

static void summary_thermal(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s)
{
    FILE *f = o->f;
    const double T[6] = { s->T_outer_ring, s->T_inner_ring, s->T_ball,
                          s->T_housing, s->T_shaft, s->T_cavity };
    fprintf(f, "%-13s%11s%11s%11s%11s%11s%11s\n%13s", "temperature C",
            "outer ring", "inner ring", "ball", "housing", "shaft", "cavity", "");
    for (int i = 0; i < 6; i++) cell(o, 11, 2, 'f', T[i]);

    summary_losses(o, sc, s);

    const double X[5] = { s->exp_ball, s->exp_inner + s->exp_inner_cen,
                          s->exp_inner, s->exp_inner_cen, s->exp_outer };
    fprintf(f, "\n\n%-13s%11s%11s%11s%11s%11s\n%13s", "expansion um", "ball",
            "inner ring", "IR thermal", "IR centrif", "outer ring", "");
    for (int i = 0; i < 5; i++) cell(o, 11, 4, 'f', X[i] * CLI_UM);
    fputs("\n\n", f);
}

/* All balls carry the same state (pure axial load): one row says it all. */
static bool balls_identical(const acbb_snapshot *s)
{
    const acbb_ball_view *b0 = &s->balls[0];
    for (int k = 1; k < s->n_balls; k++) {
        const acbb_ball_view *b = &s->balls[k];
        const double a[10] = { b0->Qi, b0->Qo, b0->alpha_i, b0->alpha_o, b0->slide_i,
                               b0->slide_o, b0->spin_i, b0->spin_o, b0->film_i, b0->film_o };
        const double c[10] = { b->Qi, b->Qo, b->alpha_i, b->alpha_o, b->slide_i,
                               b->slide_o, b->spin_i, b->spin_o, b->film_i, b->film_o };
        for (int j = 0; j < 10; j++)
            if (!(fabs(a[j] - c[j]) <= 1e-6 * fmax(fabs(a[j]), fabs(c[j])))) return false;
    }
    return true;
}

static void ball_rows(acbb_cli_out *o, const char *label, const acbb_ball_view *b,
                      bool show_psi)
{
    fprintf(o->f, "%-13s", label);
    if (show_psi) cell(o, 8, 2, 'f', acbb_rad_to_deg(b->psi));
    else fprintf(o->f, "%8s", "-");
    fprintf(o->f, "  %-5s", "inner");
    cell(o, 9, 2, 'f', b->Qi);
    cell(o, 11, 3, 'f', acbb_rad_to_deg(b->alpha_i));
    cell(o, 11, 4, 'g', b->slide_i);
    cell(o, 11, 4, 'g', b->spin_i);
    cell(o, 9, 4, 'f', b->film_i * CLI_UM);
    fprintf(o->f, "\n%13s%8s  %-5s", "", "", "outer");
    cell(o, 9, 2, 'f', b->Qo);
    cell(o, 11, 3, 'f', acbb_rad_to_deg(b->alpha_o));
    cell(o, 11, 4, 'g', b->slide_o);
    cell(o, 11, 4, 'g', b->spin_o);
    cell(o, 9, 4, 'f', b->film_o * CLI_UM);
    fputc('\n', o->f);
}

static void summary_balls(acbb_cli_out *o, const acbb_snapshot *s)
{
    fprintf(o->f, "%-13s%8s  %-5s%9s%11s%11s%11s%9s\n", "balls", "psi deg", "race",
            "Q N", "alpha deg", "slide m/s", "spin rad/s", "film um");
    if (s->n_balls <= 0) {
        fputs("(no balls)\n", o->f);
        return;
    }
    if (s->n_balls > 1 && balls_identical(s)) {
        char label[32];
        snprintf(label, sizeof label, "all %d balls", s->n_balls);
        ball_rows(o, label, &s->balls[0], false);
        return;
    }
    for (int k = 0; k < s->n_balls && k < ACBB_MAX_BALLS; k++) {
        char label[32];
        snprintf(label, sizeof label, "ball %d", k);
        ball_rows(o, label, &s->balls[k], true);
    }
}

/* MODEL.md 15: ratings, lives, static safety and the shoulders (life.h):
 * four lines of "text number" items (five when kappa is below ISO 281's
 * 0.1), each under 80 columns at the presets' numbers. */
static void summary_life(acbb_cli_out *o, const acbb_snapshot *s)
{
    const acbb_life *L = &s->life;
    char s0c[32], edc[32], tail[80];
    acbb_life_contact_name(L->s0_ball, L->s0_race, s0c, sizeof s0c);
    acbb_life_contact_name(L->edge_ball, L->edge_race, edc, sizeof edc);
    snprintf(tail, sizeof tail, " deg (%s)%s\n", edc, L->edge_loaded ? ": EDGE LOADED" : "");
    char c0[96];
    snprintf(c0, sizeof c0, " kN (%s%s)\n             L10r ",
             L->C0_table ? "ISO 76 Table 1" : "4200 MPa, real grooves",
             L->estimated ? "; internals estimated" : "");
    const struct { const char *pre; double v; } it[] = {
        { "\nlife         C ", L->C * 1e-3 }, { " kN, C0 ", L->C0 * 1e-3 }, { c0, L->L10r_h },
        { " h, Lnmr ", L->Lnmr_h }, { " h (a1 ", L->a1 }, { ", a_ISO ", L->a_iso },
        { ", kappa ", L->kappa },
        { L->kappa_clamped ? ")\n             kappa below 0.1, where ISO 281 has no a_ISO: "
                             "a_ISO taken at 0.1\n             s0 "
                           : ")\n             s0 ", L->s0_min },
        { NULL, 0 }, { ", P0 ", L->P0 },
        { " N (static equivalent load)\n             shoulder margin ", L->edge_margin_deg },
    };
    for (size_t i = 0; i < sizeof it / sizeof it[0]; i++) {
        if (!it[i].pre) {
            fprintf(o->f, " (%s)", s0c);
            continue;
        }
        fputs(it[i].pre, o->f);
        put_num(o, 1, 4, 'g', it[i].v);
    }
    fputs(tail, o->f);
}

/* A bearing set (MODEL.md 14): the set's numbers, a line per bearing
 * (the tables above are bearing 0's). */
static void summary_set(acbb_cli_out *o, const acbb_snapshot *s)
{
    const acbb_set_view *v = &s->set;
    if (s->n_bearings < 2) return;
    char line[256];
    snprintf(line, sizeof line, "preload %.1f N (assembly %.1f N), lift-off thrust %.0f N "
             "(the other side keeps %.1f N there)", v->preload_N, v->preload_assembly_N,
             v->liftoff_thrust_N, v->liftoff_remainder_N);
    fprintf(o->f, "\n%-13s", "set");
    acbb_cli_wrap(o->f, line, 13, 13);
    /* In a spindle the set's own stiffness is not the nose's (the shaft
     * bends; the spindle block gives the nose's): say whose it is. */
    if (s->state == ACBB_RUN_CONVERGED) {
        snprintf(line, sizeof line, "axial %.2f, radial %.2f N/um, tilt %.2f N m/mrad %s",
                 v->stiffness_axial * 1e-6, v->stiffness_radial * 1e-6,
                 v->stiffness_tilt * 1e-3, s->spindle.n_sets ? "(set alone)" : "at the nose");
        fprintf(o->f, "\n%-13s", s->spindle.n_sets ? "set stiff" : "stiffness");
        acbb_cli_wrap(o->f, line, 13, 13);
        fputc('\n', o->f);
    } else
        fputs("\nstiffness    not computed (only at convergence)\n", o->f);
    fputs("bearing  thrust  axial N  outer C  inner C   loss W\n", o->f);
    for (int k = 0; k < s->n_bearings && k < ACBB_MAX_SET; k++)
        fprintf(o->f, "%7d  %6s %8.1f %8.2f %8.2f %8.2f%s\n", k,
                v->orientation[k] > 0 ? "+x" : "-x", v->axial_force[k], v->T_outer_ring[k],
                v->T_inner_ring[k], v->loss_total[k], v->contact_lost[k] ? "  lifted off" : "");
}

void acbb_cli_print_summary(acbb_cli_out *o, const char *preset,
                            const acbb_scene *sc, const acbb_snapshot *snap)
{
    summary_header(o, preset, sc, snap);
    summary_thermal(o, sc, snap);
    summary_balls(o, snap);
    summary_life(o, snap);
    summary_set(o, snap);
    acbb_cli_print_spindle(o, snap);
}

/* The run's JSON comes from the engine's one writer (acbb/tools/json.h); the
 * non-finite count joins the table's. */
void acbb_cli_json_run(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s)
{
    acbb_json j;
    acbb_json_init(&j, o->f);
    acbb_json_write_run(&j, sc, s);
    o->nonfinite += j.nonfinite;
}

void acbb_cli_json_run_parts(acbb_cli_out *o, const acbb_scene *sc, const acbb_snapshot *s,
                             const acbb_snapshot *bearings, const acbb_branches *br)
{
    acbb_json j;
    acbb_json_init(&j, o->f);
    acbb_json_write_run_parts(&j, sc, s, bearings, s->n_bearings, br);
    o->nonfinite += j.nonfinite;
}

void acbb_cli_json_failed(acbb_cli_out *o, const acbb_scene *sc,
                          const char *status, const char *message)
{
    acbb_json j;
    acbb_json_init(&j, o->f);
    acbb_json_write_failed(&j, sc, status, message);
    o->nonfinite += j.nonfinite;
}

/* The run CSV's table columns: those before residual_K_s, then those after
 * (ball 0 for the contacts). exp_inner_um is thermal + centrifugal, as
 * expansion_um.inner_ring in the JSON (MODEL.md 12.4). */
static const char *const csv_head[] = {
    "temperature_C.outer_ring", "temperature_C.inner_ring", "temperature_C.ball", "losses_W.*",
    "losses_W.total", "balls[0].Qi_N", "balls[0].Qo_N", "balls[0].alpha_i_deg",
    "balls[0].alpha_o_deg", "expansion_um.ball", "expansion_um.inner_ring",
    "expansion_um.outer_ring",
};
static const char *const csv_tail[] = {
    "ring.delta_x_um", "ring.delta_z_um", "ring.tilt_y_mrad", "balls[0].film_i_um",
    "balls[0].film_o_um", "balls[0].hmin_i_um", "balls[0].hmin_o_um",
    "squeeze_um.inner_thermal", "squeeze_um.inner_centrifugal", "squeeze_um.outer",
    "squeeze_um.ball", "squeeze_um.net",
    "life.L10r_h", "life.Lnmr_h", "life.a_iso", "life.kappa", "life.s0_min",
};

/* The flat names of columns c[0..n), each followed by `sep`. */
static void csv_names(acbb_cli_out *o, const acbb_cli_col *c, size_t n, const char *sep)
{
    for (size_t i = 0; i < n; i++) {
        char name[64];
        acbb_output_flat(&c[i].e, name, sizeof name);
        fprintf(o->f, "%s%s", name, i + 1 < n ? "," : sep);
    }
}

/* A spindle's columns (issue 31): the warm-up curve of the nose drift,
 * each set's preload and outer ring, the coolant's outlet. */
static const char *const csv_spindle[] = {
    "spindle.nose_drift_um", "spindle.nose_radial_drift_um", "spindle.rear_shift_um",
    "spindle.sets[0].preload_N", "spindle.sets[1].preload_N", "spindle.sets[0].T_outer_C",
    "spindle.sets[1].T_outer_C", "spindle.coolant_C.outlet",
};

void acbb_cli_csv_header(acbb_cli_out *o)
{
    size_t n;
    bool set = o->set_n > 1, sp = o->spindle;
    fputs("iteration,time_s,dt_s,", o->f);
    const acbb_cli_col *c = COLS(o, csv_head, &n);
    csv_names(o, c, n, ",residual_K_s,");
    c = COLS(o, csv_tail, &n);
    csv_names(o, c, n, set || sp ? "," : "\n");
    if (set) {
        /* A set (MODEL.md 14): its preload and each bearing's outer ring. */
        fputs("set.preload_N", o->f); /* the run JSON's paths (outputs.h) */
        for (int k = 0; k < o->set_n; k++)
            fprintf(o->f, ",bearings[%d].temperature_C.outer_ring", k);
        fputs(sp ? "," : "\n", o->f);
    }
    if (sp) {
        c = COLS(o, csv_spindle, &n);
        csv_names(o, c, n, "\n");
    }
}

void acbb_cli_csv_row(acbb_cli_out *o, const acbb_snapshot *s)
{
    size_t n;
    bool set = o->set_n > 1, sp = o->spindle;
    fprintf(o->f, "%ld,", s->iteration);
    c_num(o, s->time, false);
    c_num(o, s->dt, false);
    const acbb_cli_col *c = COLS(o, csv_head, &n);
    for (size_t i = 0; i < n; i++) c_num(o, col_value(&c[i], s), false);
    c_num(o, s->residual, false);
    c = COLS(o, csv_tail, &n);
    for (size_t i = 0; i < n; i++) c_num(o, col_value(&c[i], s), i + 1 == n && !set && !sp);
    if (set) {
        c_num(o, s->set.preload_N, false);
        for (int k = 0; k < o->set_n; k++) c_num(o, s->set.T_outer_ring[k], k + 1 == o->set_n && !sp);
    }
    if (!sp) return;
    c = COLS(o, csv_spindle, &n);
    for (size_t i = 0; i < n; i++) c_num(o, col_value(&c[i], s), i + 1 == n);
}

void acbb_cli_list_metrics(FILE *f)
{
    acbb_output e;
    fprintf(f, "%-32s %-9s %s\n", "metric", "unit", "what");
    for (size_t i = 0; acbb_output_get(i, &e); i++) {
        char path[64];
        acbb_output_path(&e, "i", path, sizeof path);
        /* the label wrapped under its column (43) within 80 columns */
        int col = fprintf(f, "%-32s %-9s", path, e.unit);
        if (col < 43) col += fprintf(f, "%*s", 43 - col, "");
        acbb_cli_wrap(f, e.label, col > 0 ? (size_t)col : 0, 43);
        fputc('\n', f);
    }
}

cJSON *acbb_cli_json_number(double v)
{
    char text[32];
    if (!isfinite(v)) return cJSON_CreateNull();
    snprintf(text, sizeof text, "%.17g", v);
    return cJSON_CreateRaw(text);
}

void acbb_cli_json_exact(cJSON *o)
{
    cJSON *it = o ? o->child : NULL;
    while (it) {
        cJSON *next = it->next;
        if (!cJSON_IsNumber(it)) acbb_cli_json_exact(it);
        else if (it->string) /* keeps the key (ViaPointer would drop it) */
            cJSON_ReplaceItemInObjectCaseSensitive(o, it->string, acbb_cli_json_number(it->valuedouble));
        else cJSON_ReplaceItemViaPointer(o, it, acbb_cli_json_number(it->valuedouble));
        it = next;
    }
}

void acbb_cli_list_metrics_json(FILE *f)
{
    acbb_output e;
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "schema_version", ACBB_JSON_SCHEMA_VERSION);
    cJSON *arr = cJSON_AddArrayToObject(o, "metrics");
    for (size_t i = 0; arr && acbb_output_get(i, &e); i++) {
        char path[64], col[64];
        acbb_output_path(&e, "i", path, sizeof path);
        acbb_output_flat(&e, col, sizeof col);
        cJSON *m = cJSON_CreateObject();
        cJSON_AddStringToObject(m, "path", path);
        cJSON_AddStringToObject(m, "column", col);
        cJSON_AddStringToObject(m, "unit", e.unit);
        cJSON_AddStringToObject(m, "label", e.label);
        cJSON_AddItemToArray(arr, m);
    }
    char *text = cJSON_Print(o);
    cJSON_Delete(o);
    if (text) fprintf(f, "%s\n", text);
    cJSON_free(text);
}

/* ---- acbb sweep ---- */

/* The numbers a sweep reports for one point (ball 0 for the contacts):
 * the columns of sweep_spec, in the order of this enum. */
enum { SW_T, SW_LOSS0, SW_TOTAL = SW_LOSS0 + ACBB_LOSS_KINDS,
       SW_QI, SW_QO, SW_AI, SW_AO, SW_N };
static const char *const sweep_spec[] = {
    "temperature_C.outer_ring", "losses_W.*", "losses_W.total", "balls[0].Qi_N",
    "balls[0].Qo_N", "balls[0].alpha_i_deg", "balls[0].alpha_o_deg",
};

static const acbb_cli_col *sweep_cols(acbb_cli_out *o)
{
    size_t n;
    const acbb_cli_col *c = COLS(o, sweep_spec, &n);
    if (n != SW_N) abort(); /* enum and list differ: a bug */
    return c;
}

/* Column k's key, the table's flat name ("T_outer_ring_C", "P_spin_W"). */
static const char *sweep_key(acbb_cli_out *o, int k, char *buf, size_t cap)
{
    acbb_output_flat(&sweep_cols(o)[k].e, buf, cap);
    return buf;
}

static void sweep_values(acbb_cli_out *o, const acbb_cli_point *p, double v[SW_N])
{
    const acbb_cli_col *c = sweep_cols(o);
    for (int k = 0; k < SW_N; k++) v[k] = col_value(&c[k], &p->snap);
}

static void sweep_failures(acbb_cli_out *o, const acbb_cli_point *pts, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const acbb_cli_point *p = &pts[i];
        if (acbb_cli_point_ok(p)) continue;
        char line[600];
        snprintf(line, sizeof line, "%s: %s: %s", p->value, acbb_cli_point_status(p),
                 p->have_snap ? p->snap.message : p->message);
        fputs("  ", o->f);
        acbb_cli_wrap(o->f, line, 2, 4);
        fputc('\n', o->f);
    }
}

enum { SW_COL_TOTAL = -1, SW_COL_WALL = -2 }; /* after the loss kinds */

static const char *sweep_col_name(int c)
{
    return c >= 0 ? acbb_loss_name((acbb_loss_kind)c) : c == SW_COL_TOTAL ? "total" : "wall ms";
}

/* 9 wide, or the name's width plus one ("ehl_rolling") */
static int sweep_col_width(int c)
{
    int w = (int)strlen(sweep_col_name(c)) + 1;
    return w > 9 ? w : 9;
}

/* One block of the losses table: columns col[c0 .. c1-1]. */
static void sweep_loss_block(acbb_cli_out *o, const acbb_cli_point *pts, size_t n,
                             const int *col, int c0, int c1)
{
    FILE *f = o->f;
    fprintf(f, "\n%-10s", "losses W");
    for (int c = c0; c < c1; c++) fprintf(f, " %8s", sweep_col_name(col[c]));
    fputc('\n', f);
    for (size_t i = 0; i < n; i++) {
        const acbb_cli_point *p = &pts[i];
        fprintf(f, "%-10s", p->value);
        if (!p->have_snap) {
            fputs("        -\n", f);
            continue;
        }
        double v[SW_N];
        sweep_values(o, p, v);
        for (int c = c0; c < c1; c++) {
            int cw = sweep_col_width(col[c]);
            if (col[c] >= 0) cell(o, cw, 4, 'g', v[SW_LOSS0 + col[c]]);
            else if (col[c] == SW_COL_TOTAL) cell(o, cw, 4, 'g', v[SW_TOTAL]);
            else cell(o, cw, 1, 'f', p->wall_ms);
        }
        fputc('\n', f);
    }
}

/* The sweep's losses (the switched-on kinds), total and wall time, in
 * blocks that keep to 80 columns; the reference profile's eight kinds
 * take two blocks (one line was 103 columns). */
static void sweep_losses(acbb_cli_out *o, const acbb_cli_point *pts, size_t n)
{
    int col[ACBB_LOSS_KINDS + 2], nc = 0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        if (n > 0 && acbb_loss_enabled(&pts[0].scene, (acbb_loss_kind)l)) col[nc++] = l;
    col[nc++] = SW_COL_TOTAL;
    col[nc++] = SW_COL_WALL;
    for (int c0 = 0, c1; c0 < nc; c0 = c1) {
        int w = 10;
        for (c1 = c0; c1 < nc && (c1 == c0 || w + sweep_col_width(col[c1]) <= 80); c1++)
            w += sweep_col_width(col[c1]);
        sweep_loss_block(o, pts, n, col, c0, c1);
    }
}

void acbb_cli_sweep_table(acbb_cli_out *o, const char *param,
                          const acbb_cli_point *pts, size_t n)
{
    FILE *f = o->f;
    fprintf(f, "sweep of %s (%zu points); contacts of ball 0\n", param, n);
    fprintf(f, "%-10s %-13s %6s %8s %8s %8s %7s %7s\n", "value", "status", "iter",
            "T_or C", "Qi N", "Qo N", "a_i deg", "a_o deg");
    for (size_t i = 0; i < n; i++) {
        const acbb_cli_point *p = &pts[i];
        fprintf(f, "%-10s %-13s ", p->value, acbb_cli_point_status(p));
        if (!p->have_snap) {
            fputs("     -\n", f);
            continue;
        }
        double v[SW_N];
        sweep_values(o, p, v);
        fprintf(f, "%6ld", p->snap.iteration);
        cell(o, 9, 2, 'f', v[SW_T]);
        cell(o, 9, 2, 'f', v[SW_QI]);
        cell(o, 9, 2, 'f', v[SW_QO]);
        cell(o, 8, 3, 'f', v[SW_AI]);
        cell(o, 8, 3, 'f', v[SW_AO]);
        fputc('\n', f);
    }
    sweep_losses(o, pts, n);
    for (size_t i = 0; i < n; i++) {
        if (!acbb_cli_point_ok(&pts[i])) {
            fputs("\nfailed points:\n", f);
            sweep_failures(o, pts, n);
            break;
        }
    }
}

void acbb_cli_sweep_json(acbb_cli_out *o, const char *param,
                         const acbb_cli_point *pts, size_t n)
{
    acbb_json j;
    acbb_json_init(&j, o->f);
    acbb_json_open(&j, NULL, '[', false);
    for (size_t i = 0; i < n; i++) {
        const acbb_cli_point *p = &pts[i];
        acbb_json_open(&j, NULL, '{', true);
        acbb_json_long(&j, "schema_version", ACBB_JSON_SCHEMA_VERSION);
        acbb_json_str(&j, "param", param);
        acbb_json_value_text(&j, "value", p->value);
        acbb_json_str(&j, "status", acbb_cli_point_status(p));
        acbb_json_str(&j, "message", p->have_snap ? p->snap.message : p->message);
        acbb_json_long(&j, "iterations", p->have_snap ? p->snap.iteration : 0);
        acbb_json_num(&j, "wall_ms", p->wall_ms);
        double v[SW_N];
        if (p->have_snap) sweep_values(o, p, v);
        for (int k = 0; k < SW_N; k++) {
            char buf[48];
            const char *key = sweep_key(o, k, buf, sizeof buf);
            if (p->have_snap) acbb_json_num(&j, key, v[k]);
            else acbb_json_null(&j, key);
        }
        acbb_json_close(&j, '}');
    }
    acbb_json_close(&j, ']');
    o->nonfinite += j.nonfinite;
}

void acbb_cli_sweep_csv(acbb_cli_out *o, const char *param,
                        const acbb_cli_point *pts, size_t n)
{
    fprintf(o->f, "%s,status,iterations,wall_ms", param);
    char buf[48];
    for (int k = 0; k < SW_N; k++) fprintf(o->f, ",%s", sweep_key(o, k, buf, sizeof buf));
    fputc('\n', o->f);
    for (size_t i = 0; i < n; i++) {
        const acbb_cli_point *p = &pts[i];
        fprintf(o->f, "%s,%s,%ld,", p->value, acbb_cli_point_status(p),
                p->have_snap ? p->snap.iteration : 0L);
        c_num(o, p->wall_ms, false);
        double v[SW_N];
        if (p->have_snap) sweep_values(o, p, v);
        for (int k = 0; k < SW_N; k++) {
            if (p->have_snap) c_num(o, v[k], k == SW_N - 1);
            else fputs(k == SW_N - 1 ? "\n" : ",", o->f);
        }
    }
}

/* ---- acbb study ---- */

static void study_cells(acbb_cli_out *o, const acbb_cli_point *te,
                        const acbb_cli_point *wte)
{
    const acbb_cli_point *pair[2] = { te, wte };
    for (int m = 0; m < 2; m++) {
        if (pair[m]->have_snap) cell(o, 8, 2, 'f', pair[m]->snap.T_outer_ring);
        else fprintf(o->f, "%8s", "-");
    }
    for (int m = 0; m < 2; m++) {
        if (pair[m]->have_snap) cell(o, 9, 3, 'f', pair[m]->snap.losses.total);
        else fprintf(o->f, "%9s", "-");
    }
    if (te->have_snap && wte->have_snap) {
        double d = te->snap.losses.total - wte->snap.losses.total;
        double w = wte->snap.losses.total;
        cell(o, 9, 3, 'f', d);
        if (w > 0.0) cell(o, 7, 1, 'f', 100.0 * d / w);
        else fprintf(o->f, "%7s", "-");
    } else {
        fprintf(o->f, "%9s%7s", "-", "-");
    }
    for (int m = 0; m < 2; m++) {
        const acbb_snapshot *s = &pair[m]->snap;
        if (pair[m]->have_snap && s->n_balls > 0) cell(o, 8, 1, 'f', s->balls[0].Qi);
        else fprintf(o->f, "%8s", "-");
    }
    /* What heat costs in life (MODEL.md 15): L_nmr(TE) against L_nmr(WTE). */
    double lw = wte->snap.life.Lnmr_h;
    if (te->have_snap && wte->have_snap && lw > 0.0)
        cell(o, 7, 1, 'f', 100.0 * (te->snap.life.Lnmr_h - lw) / lw);
    else fprintf(o->f, "%7s", "-");
    fputc('\n', o->f);
}

static void study_block_failures(acbb_cli_out *o, const acbb_cli_point *pts,
                                 const acbb_cli_study_block *b)
{
    for (size_t k = b->first; k < b->first + b->count; k++) {
        for (int m = 0; m < 2; m++) {
            const acbb_cli_point *p = &pts[2 * k + (size_t)m];
            if (acbb_cli_point_ok(p)) continue;
            char line[600];
            snprintf(line, sizeof line, "%s at %s %s: %s: %s", m == 0 ? "TE" : "WTE",
                     b->x_label, p->value, acbb_cli_point_status(p),
                     p->have_snap ? p->snap.message : p->message);
            fputs("  * ", o->f);
            acbb_cli_wrap(o->f, line, 4, 4);   /* whole, within 80 columns */
            fputc('\n', o->f);
        }
    }
}

void acbb_cli_study_table(acbb_cli_out *o, const acbb_cli_point *pts,
                          const acbb_cli_study_block *blocks, size_t nb)
{
    FILE *f = o->f;
    fputs("TE = with thermal expansion, WTE = without; dP = P_total(TE) - "
          "P_total(WTE)\n", f);
    fputs("dL = L_nmr(TE) / L_nmr(WTE) - 1, the modified rating life (ISO 281)\n", f);
    for (size_t i = 0; i < nb; i++) {
        const acbb_cli_study_block *b = &blocks[i];
        fprintf(f, "\n%s\n", b->title);
        /* 80 columns: the group labels right-aligned over their pairs */
        fprintf(f, "%7s%16s%18s%16s%16s%7s\n", "", "T outer ring C",
                "total loss W", "dP", "Qi ball 0 N", "dL");
        fprintf(f, "%7s%8s%8s%9s%9s%9s%7s%8s%8s%7s\n", b->x_label, "TE", "WTE",
                "TE", "WTE", "W", "%", "TE", "WTE", "%");
        for (size_t k = b->first; k < b->first + b->count; k++) {
            /* a '*' before the value: a run of the row failed (below) */
            bool bad = !acbb_cli_point_ok(&pts[2 * k]) || !acbb_cli_point_ok(&pts[2 * k + 1]);
            fprintf(f, "%c%6s", bad ? '*' : ' ', pts[2 * k].value);
            study_cells(o, &pts[2 * k], &pts[2 * k + 1]);
        }
        study_block_failures(o, pts, b);
    }
}

static void study_csv_point(acbb_cli_out *o, const acbb_cli_point *p)
{
    fprintf(o->f, ",%s,%ld", acbb_cli_point_status(p),
            p->have_snap ? p->snap.iteration : 0L);
    double v[SW_N];
    if (p->have_snap) sweep_values(o, p, v);
    for (int k = 0; k < SW_N; k++) {
        fputc(',', o->f);
        if (p->have_snap && isfinite(v[k])) fprintf(o->f, "%.17g", v[k]);
        else if (p->have_snap) o->nonfinite++;
    }
}

void acbb_cli_study_csv(acbb_cli_out *o, const acbb_cli_point *pts,
                        const acbb_cli_study_block *blocks, size_t nb)
{
    /* the scene keys by their full names, as sweeps name them (issue 28 item 7) */
    fputs("sweep,operating.inner_speed_rpm,operating.axial_load_N", o->f);
    const char *mode[2] = { "te", "wte" };
    for (int m = 0; m < 2; m++) {
        fprintf(o->f, ",%s_status,%s_iterations", mode[m], mode[m]);
        for (int k = 0; k < SW_N; k++) {
            char buf[48];
            fprintf(o->f, ",%s_%s", mode[m], sweep_key(o, k, buf, sizeof buf));
        }
    }
    fputs(",dP_total_W\n", o->f);
    for (size_t i = 0; i < nb; i++) {
        const acbb_cli_study_block *b = &blocks[i];
        for (size_t k = b->first; k < b->first + b->count; k++) {
            const acbb_cli_point *te = &pts[2 * k], *wte = &pts[2 * k + 1];
            fprintf(o->f, "%s,%.17g,%.17g", b->name, acbb_rads_to_rpm(te->scene.inner_speed),
                    te->scene.axial_load);
            study_csv_point(o, te);
            study_csv_point(o, wte);
            fputc(',', o->f);
            if (te->have_snap && wte->have_snap)
                c_num(o, te->snap.losses.total - wte->snap.losses.total, true);
            else
                fputc('\n', o->f);
        }
    }
}
