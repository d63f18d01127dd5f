/* acbb — the seed's figures as tables (figures.h): one row per panel of
 * Figs. 7-19 and one row per seed figure (caption, what the model cannot
 * compute, the MODEL.md section 12 items that cite it). Captions are the
 * seed's (seed sections 3-4), condensed; quantities are ball 0's where per
 * ball, as in the study (study.h). */
#include <math.h>
#include <stddef.h>
#include "acbb/tools/figures.h"
#include "acbb/units.h"

/* ---- getters over a steady snapshot ---- */

static double g_T5(const acbb_snapshot *s) { return s->T_outer_ring; }
static double g_wx_abs(const acbb_snapshot *s) { return fabs(s->balls[0].omega_x); }
static double g_wy(const acbb_snapshot *s) { return s->balls[0].omega_y; }
static double g_wz(const acbb_snapshot *s) { return s->balls[0].omega_z; }
static double g_Qi(const acbb_snapshot *s) { return s->balls[0].Qi; }
static double g_Qo(const acbb_snapshot *s) { return s->balls[0].Qo; }
static double g_ai(const acbb_snapshot *s) { return s->balls[0].alpha_i; }
static double g_ao(const acbb_snapshot *s) { return s->balls[0].alpha_o; }
static double g_slide_i(const acbb_snapshot *s) { return s->balls[0].slide_i; }
static double g_slide_o(const acbb_snapshot *s) { return s->balls[0].slide_o; }
static double g_spin_i(const acbb_snapshot *s) { return s->balls[0].spin_i; }
static double g_spin_o(const acbb_snapshot *s) { return s->balls[0].spin_o; }
static double g_film_i(const acbb_snapshot *s) { return s->balls[0].film_i; }
static double g_film_o(const acbb_snapshot *s) { return s->balls[0].film_o; }
static double g_total(const acbb_snapshot *s) { return s->losses.total; }

/* The seed's five losses by acbb_loss_kind, so the losses touch one list. */
#define LOSS_GETTER(name, kind) \
    static double name(const acbb_snapshot *s) { return s->losses.P[kind]; }
LOSS_GETTER(g_PL, ACBB_LOSS_SHEAR)
LOSS_GETTER(g_Pt, ACBB_LOSS_SLIP)
LOSS_GETTER(g_Ps, ACBB_LOSS_SPIN)
LOSS_GETTER(g_Pr, ACBB_LOSS_ROLLING)
LOSS_GETTER(g_Pv, ACBB_LOSS_DRAG)

#define RAD2DEG (180.0 / ACBB_PI)
#define UM 1e6
#define F(field) offsetof(acbb_fig_step, field)
/* A sweep quantity and a trajectory quantity. */
#define QS(label, get, scale) { label, get, 0, scale }
#define QT(label, field, scale) { label, NULL, F(field), scale }

/* Axis labels are words with units, symbols as the seed writes them
 * (subscripts as "_x": plot_markup.c); titles say what is drawn, without
 * file names or the study's shorthand (issue 29 item 9). */
#define IT "iteration step (-)"
#define FX "axial force F_x (N)"
#define NI "inner-ring speed (rpm)"
#define TRAJ ACBB_FIG_TRAJ_ITER
#define SW ACBB_FIG_SWEEP
#define LD ACBB_STUDY_LOAD
#define S1 ACBB_STUDY_S100
#define S2 ACBB_STUDY_S1000
#define SB ACBB_FIG_SPEED_SWEEPS
#define EXPANSIONS { QT("inner theta_i+theta_icen", exp_in, UM), \
                     QT("outer theta_o", exp_out, UM), QT("ball theta_ba", exp_ball, UM) }
#define GROOVES { QT("axial A_1 (= delta_x)", dA1, UM), QT("radial A_2", dA2, UM) }
#define SLIDES { QS("inner contact", g_slide_i, 1), QS("outer contact", g_slide_o, 1) }
#define SPINS { QS("inner omega_si", g_spin_i, 1), QS("outer omega_so", g_spin_o, 1) }
#define LOADS { QS("inner Q_i", g_Qi, 1), QS("outer Q_o", g_Qo, 1) }
#define ANGLES { QS("inner alpha_i", g_ai, RAD2DEG), QS("outer alpha_o", g_ao, RAD2DEG) }
#define FILMS { QS("inner H_i", g_film_i, UM), QS("outer H_o", g_film_o, UM) }

static const acbb_figure_row k_rows[] = {
    { "fig07a", 7, "Outer-ring temperature rise at 15000 rpm", IT,
      "temperature rise T_5 - T_amb (K)", TRAJ, ACBB_FIG_ALL_LOADS, 0, 1,
      { QT("T_5 rise", T5_rise, 1) } },
    { "fig07b", 7, "Outer-ring temperature at 15000 rpm", FX,
      "outer-ring temperature T_5 (C)", SW, LD, 0, 1, { QS("T_5", g_T5, 1) } },
    { "fig08a", 8, "Ball angular velocity omega_x' in time",
      "time (s)", "angular velocity omega_x' (rad/s)", ACBB_FIG_TRAJ_TIME,
      ACBB_FIG_ALL_LOADS, 0, 1, { QT("omega_x'", wx, 1) } },
    { "fig08b", 8, "Ball angular velocity omega_y' in time",
      "time (s)", "angular velocity omega_y' (rad/s)", ACBB_FIG_TRAJ_TIME,
      ACBB_FIG_ALL_LOADS, 0, 1, { QT("omega_y'", wy, 1) } },
    { "fig08c", 8, "Ball angular velocity omega_z' in time",
      "time (s)", "angular velocity omega_z' (rad/s)", ACBB_FIG_TRAJ_TIME,
      ACBB_FIG_ALL_LOADS, 0, 1, { QT("omega_z'", wz, 1) } },
    { "fig08d", 8, "Ball angular velocities vs axial force", FX,
      "ball angular velocity (rad/s)", SW, LD, 1, 3,
      { QS("|omega_x'|", g_wx_abs, 1), QS("omega_y'", g_wy, 1), QS("omega_z'", g_wz, 1) } },
    { "fig09a", 9, "Thermal expansions, light loads", IT,
      "thermal expansion (um)", TRAJ, ACBB_FIG_LIGHT, 0, 3, EXPANSIONS },
    { "fig09b", 9, "Thermal expansions, large loads", IT,
      "thermal expansion (um)", TRAJ, ACBB_FIG_LARGE, 0, 3, EXPANSIONS },
    { "fig10a", 10, "Groove-centre distances, light loads", IT,
      "change of distance (um)", TRAJ, ACBB_FIG_LIGHT, 0, 2, GROOVES },
    { "fig10b", 10, "Groove-centre distances, large loads", IT,
      "change of distance (um)", TRAJ, ACBB_FIG_LARGE, 0, 2, GROOVES },
    { "fig11a", 11, "Outer-ring contact load of a ball", IT,
      "outer contact load Q_o (N)", TRAJ, ACBB_FIG_ALL_LOADS, 0, 1, { QT("Q_o", Qo, 1) } },
    { "fig11b", 11, "Inner-ring contact load of a ball", IT,
      "inner contact load Q_i (N)", TRAJ, ACBB_FIG_ALL_LOADS, 0, 1, { QT("Q_i", Qi, 1) } },
    { "fig11c", 11, "Steady contact loads vs axial force", FX, "contact load (N)", SW, LD, 0, 2,
      LOADS },
    { "fig12a", 12, "Outer-ring contact angle of a ball", IT,
      "outer contact angle alpha_o (deg)", TRAJ, ACBB_FIG_ALL_LOADS, 0, 1,
      { QT("alpha_o", alpha_o, RAD2DEG) } },
    { "fig12b", 12, "Inner-ring contact angle of a ball", IT,
      "inner contact angle alpha_i (deg)", TRAJ, ACBB_FIG_ALL_LOADS, 0, 1,
      { QT("alpha_i", alpha_i, RAD2DEG) } },
    { "fig12c", 12, "Steady contact angles vs axial force", FX, "contact angle (deg)", SW, LD,
      0, 2, ANGLES },
    { "fig13a", 13, "Total power loss at 15000 rpm", FX,
      "total power loss P_T (W)", SW, LD, 0, 1, { QS("P_T", g_total, 1) } },
    { "fig13b", 13, "Slip and tangential friction losses", FX,
      "power loss (W)", SW, LD, 1, 2,
      { QS("slip P_t", g_Pt, 1), QS("tangential P_L", g_PL, 1) } },
    { "fig13c", 13, "Spinning friction loss", FX,
      "spinning friction loss P_s (W)", SW, LD, 1, 1, { QS("P_s", g_Ps, 1) } },
    { "fig13d", 13, "Rolling and viscous friction losses", FX,
      "power loss (W)", SW, LD, 0, 2,
      { QS("rolling P_r", g_Pr, 1), QS("viscous P_v", g_Pv, 1) } },
    { "fig14a", 14, "Sliding speeds vs axial force", FX, "sliding speed (m/s)", SW, LD, 1, 2,
      SLIDES },
    { "fig14b", 14, "Spin speeds vs axial force", FX, "spin speed (rad/s)", SW, LD, 1, 2,
      SPINS },
    { "fig14c", 14, "Central oil-film thickness", FX,
      "central film thickness (um)", SW, LD, 0, 2, FILMS },
    { "fig15a", 15, "Steady outer-ring temperature vs speed", NI,
      "outer-ring temperature T_5 (C)", SW, SB, 0, 1, { QS("T_5", g_T5, 1) } },
    { "fig15b", 15, "Tangential friction loss vs speed", NI, "tangential loss P_L (W)",
      SW, SB, 1, 1, { QS("P_L", g_PL, 1) } },
    { "fig15c", 15, "Differential-slip loss vs speed", NI, "differential-slip loss P_t (W)", SW,
      SB, 0, 1, { QS("P_t", g_Pt, 1) } },
    { "fig15d", 15, "Spinning friction loss vs speed", NI, "spinning friction loss P_s (W)", SW,
      SB, 1, 1, { QS("P_s", g_Ps, 1) } },
    { "fig15e", 15, "Rolling friction loss vs speed", NI, "rolling friction loss P_r (W)", SW,
      SB, 0, 1, { QS("P_r", g_Pr, 1) } },
    { "fig15f", 15, "Viscous friction loss vs speed", NI, "viscous friction loss P_v (W)", SW,
      SB, 0, 1, { QS("P_v", g_Pv, 1) } },
    { "fig16", 16, "Central oil-film thickness vs speed", NI, "central film thickness (um)", SW,
      SB, 0, 2, FILMS },
    { "fig17a", 17, "Sliding speeds vs speed at F_x = 100 N", NI, "sliding speed (m/s)", SW, S1,
      1, 2, SLIDES },
    { "fig17b", 17, "Sliding speeds vs speed at F_x = 1000 N", NI, "sliding speed (m/s)", SW,
      S2, 1, 2, SLIDES },
    { "fig17c", 17, "Spin speeds vs speed at F_x = 100 N", NI, "spin speed (rad/s)", SW, S1, 1,
      2, SPINS },
    { "fig17d", 17, "Spin speeds vs speed at F_x = 1000 N", NI, "spin speed (rad/s)", SW, S2, 1,
      2, SPINS },
    { "fig18a", 18, "Contact loads vs speed at F_x = 100 N", NI, "contact load (N)", SW,
      S1, 0, 2, LOADS },
    { "fig18b", 18, "Contact loads vs speed at F_x = 1000 N", NI, "contact load (N)", SW,
      S2, 0, 2, LOADS },
    { "fig19a", 19, "Contact angles vs speed at F_x = 100 N", NI, "contact angle (deg)",
      SW, S1, 0, 2, ANGLES },
    { "fig19b", 19, "Contact angles vs speed at F_x = 1000 N", NI, "contact angle (deg)",
      SW, S2, 0, 2, ANGLES },
};

const acbb_figure_row *acbb_figure_table(size_t *n)
{
    *n = sizeof k_rows / sizeof k_rows[0];
    return k_rows;
}

static const acbb_seed_figure k_seed[] = {
    { 7, "a: outer-ring temperature rise at various axial forces during the iterative "
         "calculation; b: calculated vs tested outer-ring temperature vs axial force",
      "the tested temperatures of 7b (the seed's rig; no test data here, docs/physics.md section 12): "
      "only the model's curves are drawn", { 7, 0 } },
    { 8, "angular velocity components omega_x, omega_y, omega_z of ball j=1 with time and "
         "axial load (a-c); d: |omega_x|, omega_y, omega_z in the convergent state, TE and WTE",
      NULL, { 17, 0 } },
    { 9, "thermal expansions of ball and inner and outer rings: a light loads, b large loads",
      NULL, { 4, 0 } },
    { 10, "axial and radial distances between the groove curvature centres of the inner and "
          "outer raceways: a light loads, b large loads",
      "absolute distances: drawn as their changes (A0 sin(alpha0) and A0 cos(alpha0) "
      "subtracted), which carry the whole variation", { 5, 0 } },
    { 11, "contact loads between a ball and the inner and outer rings during the iterative "
          "calculation: a outer, b inner, c initial (WTE) and final (TE)", NULL, { 5, 0 } },
    { 12, "contact angles between balls and raceways during the iterative calculation: a outer, "
          "b inner, c at room temperature and at final temperature rise", NULL, { 6, 0 } },
    { 13, "power losses with and without thermal expansion vs axial force: a P_T, b P_t and P_L, "
          "c P_s, d P_r and P_v", NULL, { 1, 2, 3, 10, 11, 12 } },
    { 14, "a sliding velocity, b spinning velocities omega_si and omega_so, c oil film "
          "thickness H_o and H_i (vs axial force)", NULL, { 14, 15, 16, 0 } },
    { 15, "outer-ring temperature and the five power losses vs speed at Fx = 100 N and 1000 N: "
          "a T5, b P_L, c P_t, d P_s, e P_r, f P_v", NULL, { 3, 8, 9, 13, 0 } },
    { 16, "centre film thickness vs speed without and with thermal expansion, Fx = 100 N and "
          "1000 N", NULL, { 14, 0 } },
    { 17, "sliding speeds (a 100 N, b 1000 N) and spinning speeds (c 100 N, d 1000 N) vs speed",
      NULL, { 15, 16, 0 } },
    { 18, "contact loads vs speed without and with thermal expansion: a 100 N, b 1000 N", NULL,
      { 0 } },
    { 19, "contact angles vs speed without and with thermal expansion: a 100 N, b 1000 N", NULL,
      { 0 } },
};

const acbb_seed_figure *acbb_seed_figure_table(size_t *n)
{
    *n = sizeof k_seed / sizeof k_seed[0];
    return k_seed;
}
