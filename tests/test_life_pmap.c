/* The preload window (include/acbb/tools/preload_map.h): the skid criterion
 * recomputed from the ball speeds of an independent run of the same cell,
 * a window that runaway bounds from above, named statuses, no NaN. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "acbb/acbb.h"
#include "acbb/tools/preload_map.h"
#include "tap.h"

/* M_g / (mu Q_i D/2), worst ball, from a run of the cell's scene. */
static double skid_by_hand(const acbb_scene *base, double rpm, double preload)
{
    acbb_scene s = *base;
    s.preload = ACBB_PRELOAD_DISPLACEMENT;
    s.preload_force = preload;
    s.inner_speed = rpm * ACBB_RPM;
    acbb_error e;
    acbb_sim *sim;
    static acbb_snapshot sn;
    if (acbb_sim_create(&s, NULL, &sim, &e) != ACBB_OK) return NAN;
    acbb_sim_run(sim);
    acbb_sim_snapshot(sim, &sn);
    acbb_sim_free(sim);
    double D = s.ball_diameter, m = s.ball.rho * M_PI * D * D * D / 6, J = m * D * D / 10;
    double worst = 0;
    for (int j = 0; j < sn.n_balls; j++) {
        const acbb_ball_view *b = &sn.balls[j];
        double Mg = J * b->omega_m * sqrt(b->omega_y * b->omega_y + b->omega_z * b->omega_z);
        worst = fmax(worst, Mg / (s.lambda_lim * b->Qi * D / 2));
    }
    return worst;
}

/* Five preloads lo..hi at one speed. */
static int map5(const acbb_scene *s, double rpm, double lo, double hi, acbb_pmap_cell *c,
                acbb_pmap_row *r)
{
    acbb_error e;
    acbb_pmap_opts o = { .speed_lo = rpm, .speed_hi = rpm, .n_speeds = 1, .preload_lo = lo,
                         .preload_hi = hi, .n_preloads = 5, .jobs = 2 };
    return acbb_preload_map(s, &o, c, r, &e) == ACBB_OK;
}

/* Isothermal 7008C at 30 000 rpm on a film of limiting traction 0.05: the
 * light preloads skid, the heavier ones do not. */
static void skid_limit(void)
{
    acbb_scene s;
    acbb_error e;
    const char *ed[] = { "effects.heating=off", "lubricant.limiting_shear_ratio=0.05" };
    ok(acbb_scene_load("presets/7008C.ini", &s, &e) == ACBB_OK &&
       acbb_scene_apply_edits(&s, ed, 2, &e) == ACBB_OK, "isothermal 7008C, traction 0.05");
    acbb_pmap_cell c[5];
    acbb_pmap_row r;
    ok(map5(&s, 30000, 1, 201, c, &r), "the map runs");
    int agree = 1, skids = 0, free_ = 0, mono = 1;
    double first_free = -1;
    for (int p = 0; p < 5; p++) {
        double want = skid_by_hand(&s, 30000, c[p].preload_N);
        agree &= fabs(c[p].skid - want) <= 1e-9 * want &&
                 !!(c[p].flags & ACBB_PMAP_SKID) == (want > 1.0);
        if (want > 1.0) skids++;
        else if (!free_++) first_free = c[p].preload_N;
        if (p) mono &= c[p].skid < c[p - 1].skid;
        printf("# %g N: skid %.4f (by hand %.4f) %s\n", c[p].preload_N, c[p].skid, want,
               acbb_pmap_verdict(&c[p]));
    }
    ok(agree, "each cell's skid ratio is M_g / (mu Q_i D/2) of its own run, flagged when > 1");
    ok(skids > 0 && free_ > 0 && mono, "the limit lies inside the grid: %d skid, %d free, the ratio "
       "falls with preload", skids, free_);
    ok(r.skid_free_N == first_free && r.lo_N == first_free,
       "the floor is the first preload that does not skid (%g N)", r.skid_free_N);
}

/* 7008C with heat at 16 000 rpm: a held preload above some 400 N runs away
 * (presets/runaway-rigid-preload.ini at 1000 N), the light ones converge. */
static void runaway_ceiling(void)
{
    acbb_scene s;
    acbb_error e;
    ok(acbb_scene_load("presets/7008C.ini", &s, &e) == ACBB_OK, "7008C loads");
    acbb_pmap_cell c[5];
    acbb_pmap_row r;
    ok(map5(&s, 16000, 100, 1500, c, &r), "the map runs");
    int runaway = 0, named = 1, finite = 1, below = 1;
    for (int p = 0; p < 5; p++) {
        const char *v = acbb_pmap_verdict(&c[p]);
        if (c[p].status == ACBB_RUNAWAY) {
            runaway++;
            named &= !strcmp(c[p].status_name, "runaway") && !strcmp(v, "runaway");
        } else {
            below &= runaway == 0; /* nothing converges above a runaway */
            named &= !strcmp(c[p].status_name, "converged");
        }
        finite &= isfinite(c[p].skid) && isfinite(c[p].rise_K) && isfinite(c[p].Lnmr_h) &&
                  isfinite(c[p].s0_min);
        printf("# %g N: %s, rise %.1f K\n", c[p].preload_N, c[p].status_name, c[p].rise_K);
    }
    ok(runaway > 0 && runaway < 5 && below, "runaway above a preload, converged below (%d of 5)",
       runaway);
    ok(named, "failed cells carry the run's named status");
    ok(finite, "no NaN or Inf in any cell");
    ok(r.upper_N >= 0 && r.upper_N < 1500 && r.hi_N == r.upper_N,
       "the ceiling is the last preload before the runaway (%g N)", r.upper_N);
}

static void refusals(void)
{
    acbb_scene s;
    acbb_scene_default(&s);
    acbb_error e = { { 0 } };
    acbb_pmap_cell c[1];
    acbb_pmap_row r;
    acbb_pmap_opts o = { .speed_lo = 0, .speed_hi = 1000, .n_speeds = 1, .preload_lo = 10,
                         .preload_hi = 10, .n_preloads = 1 };
    ok(acbb_preload_map(&s, &o, c, &r, &e) == ACBB_EINVAL && strstr(e.msg, "speeds"),
       "a zero speed is refused: %s", e.msg);
    o.speed_lo = 100;
    o.n_preloads = 0;
    ok(acbb_preload_map(&s, &o, c, &r, &e) == ACBB_EINVAL && strstr(e.msg, "1..100"),
       "an empty grid is refused: %s", e.msg);
}

int main(void)
{
    skid_limit();
    runaway_ceiling();
    refusals();
    return done_testing();
}
