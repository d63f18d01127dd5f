/* acbb CLI — the spindle block of `acbb run`'s summary (spindle.h,
 * docs/spindle.md): where the sets sit, the nose's thermal drift, its
 * displacement and static stiffness, the heat split, the coolant, the
 * temperatures along the shaft and the housing, and a row per set. Every line keeps within 80 columns at the widths below
 * (a number wider than planned shifts its row, never fuses with the next). */
#include <stdbool.h>
#include "output.h"

#define UM 1e6                                       /* m -> um */

static const char *const k_pos[ACBB_SPINDLE_SETS] = { "front", "rear" };

/* "front set at 45.0 mm (2 bearings), rear at 330.0 mm (1 bearing)" */
static void where(acbb_cli_out *o, const acbb_spindle_view *v)
{
    fprintf(o->f, "\n%-13s", "spindle");
    for (int k = 0; k < v->n_sets && k < ACBB_SPINDLE_SETS; k++) {
        const acbb_spindle_set_view *t = &v->sets[k];
        fprintf(o->f, "%s%s%s at ", k ? ", " : "", k_pos[k], k ? "" : " set");
        acbb_cli_num(o, 1, 1, 'f', t->x * 1e3);
        fprintf(o->f, " mm (%d bearing%s)", t->n_bearings, t->n_bearings == 1 ? "" : "s");
    }
    fputc('\n', o->f);
}

/* "LABEL  a NAME0 U0, NAME1 U1..." for n numbers in %.4g. */
static void items(acbb_cli_out *o, const char *label, const char *const *text,
                  const double *v, int n, const char *tail)
{
    fprintf(o->f, "%-13s", label);
    for (int i = 0; i < n; i++) {
        fputs(text[2 * i], o->f);
        acbb_cli_num(o, 1, 4, 'g', v[i]);
        fputs(text[2 * i + 1], o->f);
    }
    fprintf(o->f, "%s\n", tail);
}

static void nose(acbb_cli_out *o, const acbb_spindle_view *v)
{
    static const char *const drift[] = { "axial ", " um, ", "radial ", " um; ",
                                         "rear shift ", " um" };
    const double d[] = { v->nose_drift_axial * UM, v->nose_drift_radial * UM,
                         v->rear_shift * UM };
    items(o, "nose drift", drift, d, 3, " (thermal)");
    static const char *const moves[] = { "axial ", " um, ", "radial ", " um, ", "tilt ",
                                         " urad" };
    const double m[] = { v->nose_u * UM, v->nose_w * UM, v->nose_theta * UM };
    items(o, "nose moves", moves, m, 3, " (loads)");
    if (v->nose_k_radial == 0.0 && v->nose_k_axial == 0.0 && v->nose_k_tilt == 0.0) {
        fprintf(o->f, "%-13snot computed\n", "nose stiff");
        return;
    }
    static const char *const k[] = { "radial ", " N/um, ", "axial ", " N/um, ", "tilt ",
                                     " N m/mrad" };
    const double kv[] = { v->nose_k_radial * 1e-6, v->nose_k_axial * 1e-6,
                          v->nose_k_tilt * 1e-3 };
    items(o, "nose stiff", k, kv, 3, "");
}

static void heat(acbb_cli_out *o, const acbb_spindle_view *v)
{
    static const char *const h[] = { "motor ", ", ", "bearings ", "; to coolant ", "", ", ",
                                     "to air ", "" };
    const double q[] = { v->Q_motor_W, v->Q_bearings_W, v->Q_coolant_W, v->Q_air_W };
    items(o, "heat W", h, q, 4, "");
    static const char *const c[] = { "inlet ", ", ", "outlet ", "" };
    const double t[] = { v->T_coolant_in_C, v->T_coolant_out_C };
    items(o, "coolant C", c, t, 2, "");
}

/* The coldest and hottest of n cells; *at the hottest's x. 0: no cell. */
static int span(int n, const double *x, const double *T, double *lo, double *hi, double *at)
{
    n = n < ACBB_SPINDLE_MAX_CELLS ? n : ACBB_SPINDLE_MAX_CELLS;
    for (int i = 0; i < n; i++) {
        if (i == 0 || T[i] < *lo) *lo = T[i];
        if (i == 0 || T[i] > *hi) *hi = T[i], *at = x[i];
    }
    return n > 0;
}

/* "along x      shaft 47.6..106.1 C (hottest at 155 mm), housing 29.9..39.5 C" */
static void along(acbb_cli_out *o, const acbb_spindle_view *v)
{
    double lo = 0, hi = 0, at = 0, hlo = 0, hhi = 0, hat = 0;
    if (!span(v->n_shaft, v->shaft_x, v->shaft_T_C, &lo, &hi, &at)) return;
    fprintf(o->f, "%-13sshaft ", "along x");
    acbb_cli_num(o, 1, 1, 'f', lo);
    fputs("..", o->f);
    acbb_cli_num(o, 1, 1, 'f', hi);
    fputs(" C (hottest at ", o->f);
    acbb_cli_num(o, 1, 0, 'f', at * 1e3);
    fputs(" mm)", o->f);
    if (span(v->n_housing, v->housing_x, v->housing_T_C, &hlo, &hhi, &hat)) {
        fputs(", housing ", o->f);
        acbb_cli_num(o, 1, 1, 'f', hlo);
        fputs("..", o->f);
        acbb_cli_num(o, 1, 1, 'f', hhi);
        fputs(" C", o->f);
    }
    fputc('\n', o->f);
}

/* A row per set (the hottest bearing's temperatures), then which lifted off. */
static void sets(acbb_cli_out *o, const acbb_spindle_view *v)
{
    fprintf(o->f, "%-5s%10s%9s%10s%11s%8s%9s%9s%8s\n", "set", "preload N", "axial N",
            "radial N", "moment Nm", "loss W", "inner C", "outer C", "ball C");
    for (int k = 0; k < v->n_sets && k < ACBB_SPINDLE_SETS; k++) {
        const acbb_spindle_set_view *t = &v->sets[k];
        fprintf(o->f, "%-5s", k_pos[k]);
        acbb_cli_cell(o, 10, 1, 'f', t->preload_N);
        acbb_cli_cell(o, 9, 1, 'f', t->axial_N);
        acbb_cli_cell(o, 10, 1, 'f', t->radial_N);
        acbb_cli_cell(o, 11, 2, 'f', t->moment_Nm);
        acbb_cli_cell(o, 8, 2, 'f', t->loss_W);
        acbb_cli_cell(o, 9, 2, 'f', t->T_inner_C);
        acbb_cli_cell(o, 9, 2, 'f', t->T_outer_C);
        acbb_cli_cell(o, 8, 2, 'f', t->T_ball_C);
        fputc('\n', o->f);
    }
    for (int k = 0; k < v->n_sets && k < ACBB_SPINDLE_SETS; k++)
        if (v->sets[k].contact_lost)
            fprintf(o->f, "%-13sa bearing of the %s set has lifted off\n", "contact lost",
                    k_pos[k]);
}

void acbb_cli_print_spindle(acbb_cli_out *o, const acbb_snapshot *s)
{
    const acbb_spindle_view *v = &s->spindle;
    if (v->n_sets <= 0) return;
    where(o, v);
    nose(o, v);
    heat(o, v);
    along(o, v);
    sets(o, v);
}
