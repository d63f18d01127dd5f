/* Tests for src/physics/expansion.c: seed eqs (1), (3), (4), (9) and the SEED
 * projections (MODEL.md section 7) against hand values. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "expansion.h"
#include "tap.h"

#define DEG (M_PI / 180.0)

static void set_material(acbb_material *m, double E, double nu, double rho, double chi)
{
    m->E = E;
    m->nu = nu;
    m->rho = rho;
    m->chi = chi;
}

/* 7008C of MODEL.md section 10, built by hand. */
static void make_scene(acbb_scene *s)
{
    memset(s, 0, sizeof *s);
    s->pitch_diameter = 54e-3;
    s->ball_diameter = 6.35e-3;
    s->inner_groove_radius = 3.43e-3;
    s->outer_groove_radius = 3.43e-3;
    s->contact_angle0 = 15.0 * DEG;
    s->bore = 40e-3;
    s->outer_diameter = 68e-3;
    set_material(&s->ball, 207e9, 0.3, 7810.0, 12.5e-6);
    set_material(&s->ring, 207e9, 0.3, 7810.0, 12.5e-6);
    set_material(&s->shaft, 212e9, 0.298, 7860.0, 11.5e-6);
    set_material(&s->housing, 143e9, 0.27, 7300.0, 10.5e-6);
    set_material(&s->cage, 206e9, 0.254, 7830.0, 11.7e-6);
    s->inner_speed = 15000.0 * 2.0 * M_PI / 60.0;
    s->ambient_C = 26.0;
    s->thermal_expansion = true;
    s->ring_centrifugal = true;
    s->geometry = ACBB_GEOM_CLEAN;
}

/* d_i / 2 from MODEL.md section 1, recomputed here. */
static double r_il_7008c(void)
{
    double A0 = 2 * 3.43e-3 - 6.35e-3;
    double Pd = 2 * A0 * (1 - cos(15 * DEG));
    return (54e-3 - 6.35e-3 - Pd / 2) / 2;
}

static void test_equations(void)
{
    is_close(acbb_expansion_ball(12.5e-6, 30.0, 6.35e-3), 1.190625e-6, 1e-12, 0,
             "eq (1): 12.5e-6 * 30 K * 3.175 mm = 1.190625 um");
    is_close(acbb_expansion_inner(12.5e-6, 20.0, 11.5e-6, 15.0, 0.298, 0.02, 0.025),
             5.83248e-6, 1e-12, 0,
             "eq (3): 6.25 um - 2.6095e-5 * 0.016 m = 5.83248 um");
    is_close(acbb_expansion_inner(12e-6, 40.0, 12e-6, 40.0, 0.0, 0.02, 0.025),
             12e-6 * 40.0 * 0.025, 1e-12, 0,
             "eq (3): same chi and dT, nu_s = 0 -> free ring growth");
    is_close(acbb_expansion_outer(10.5e-6, 10.0, 0.27, 0.034), 4.5339e-6, 1e-12, 0,
             "eq (4): 10.5e-6 * 10 K * 1.27 * 34 mm = 4.5339 um");

    /* Timoshenko & Goodier rotating annular disc (plane stress):
     * u(r) = (3+nu)(1-nu)/(8E) rho w^2 r [a^2 + b^2 + (1+nu)/(1-nu) a^2 b^2/r^2
     *        - (1+nu)/(3+nu) r^2], evaluated at r = b. */
    double rho = 7810, w = 1000.0, E = 207e9, nu = 0.3, a = 0.02, b = 0.024;
    double u = (3 + nu) * (1 - nu) / (8 * E) * rho * w * w * b *
               (a * a + b * b + (1 + nu) / (1 - nu) * a * a - (1 + nu) / (3 + nu) * b * b);
    is_close(acbb_expansion_centrifugal(rho, w, E, nu, a, b), u, 1e-12, 0,
             "eq (9) equals the Lame disc displacement at the outer radius");
    is_close(acbb_expansion_centrifugal(rho, 2 * w, E, nu, a, b), 4 * u, 1e-12, 0,
             "eq (9) scales with omega^2");
    is_close(acbb_expansion_centrifugal(7810, 15000 * M_PI / 30, 207e9, 0.3, 0.02,
                                        r_il_7008c()), 0.95e-6, 0.01, 0,
             "eq (9): 7008C at 15000 rpm = 0.95 um (MODEL 7)");
}

static void test_compute(void)
{
    acbb_scene s;
    acbb_part_temps t = { .ball = 56.0, .inner_ring = 50.0, .shaft = 45.0,
                          .housing = 36.0, .outer_ring = 40.0 };
    acbb_expansion e;
    double r_il = r_il_7008c(), rb = 0.02;

    make_scene(&s);
    is_close(2 * r_il, 47.633e-3, 1e-5, 0, "d_i = 47.633 mm (MODEL 1)");

    acbb_expansion_compute(&s, &t, &e);
    is_close(e.ball, 12.5e-6 * 30.0 * 3.175e-3, 1e-12, 0, "compute: ball, dT = 30 K");
    double inner = 12.5e-6 * 24.0 * r_il +
                   (11.5e-6 * 19.0 * 1.298 - 12.5e-6 * 24.0) * rb * rb / r_il;
    is_close(e.inner, inner, 1e-12, 0, "compute: eq (3) with r_il = d_i/2, r_ik = bore/2");
    is_close(e.outer, 10.5e-6 * 10.0 * 1.27 * 0.034, 1e-12, 0,
             "compute: eq (4) with r_h = OD/2, housing material");
    double cen = 7810.0 * pow(s.inner_speed, 2) * r_il / (4 * 207e9) *
                 (3.3 * rb * rb + 0.7 * r_il * r_il);
    is_close(e.inner_cen, cen, 1e-12, 0, "compute: eq (9) with ring material");
    is_close(e.inner_cen, 0.95e-6, 0.01, 0, "compute: inner_cen = 0.95 um at 15000 rpm");

    /* Free growth check of r_il: shaft term cancels the ring term when
     * chi_s (1 + nu_s) dT_s = chi_i dT_i. */
    acbb_scene f = s;
    f.shaft.chi = f.ring.chi / (1.0 + f.shaft.nu);
    acbb_part_temps tf = t;
    tf.shaft = tf.inner_ring;
    acbb_expansion_compute(&f, &tf, &e);
    is_close(e.inner / (12.5e-6 * 24.0), r_il, 1e-12, 0,
             "eq (3) first term uses the raceway radius d_i/2");

    /* Materials are taken from the right parts. */
    f = s;
    f.ball.chi = 2 * s.ball.chi;
    f.cage.chi = 1.0;
    acbb_expansion_compute(&f, &t, &e);
    is_close(e.ball, 2 * 12.5e-6 * 30.0 * 3.175e-3, 1e-12, 0, "ball uses s->ball.chi");
    is_close(e.inner, inner, 1e-12, 0, "inner does not use ball or cage chi");

    /* Ambient reference. */
    acbb_part_temps ta = { 26.0, 26.0, 26.0, 26.0, 26.0 };
    s.ring_centrifugal = false;
    acbb_expansion_compute(&s, &ta, &e);
    ok(e.ball == 0 && e.inner == 0 && e.outer == 0 && e.inner_cen == 0,
       "all parts at ambient, no rotation growth: zero expansion");
    s.ambient_C = 20.0;
    acbb_expansion_compute(&s, &ta, &e);
    is_close(e.ball, 12.5e-6 * 6.0 * 3.175e-3, 1e-12, 0, "dT is relative to ambient_C");
    ok(e.inner_cen == 0, "ring_centrifugal off: inner_cen = 0 with TE on");
}

static void test_switches(void)
{
    acbb_scene s;
    acbb_part_temps t = { .ball = 56.0, .inner_ring = 50.0, .shaft = 45.0,
                          .housing = 36.0, .outer_ring = 40.0 };
    acbb_expansion e, c;
    double r_il = r_il_7008c(), rb = 0.02;

    make_scene(&s);
    acbb_expansion_compute(&s, &t, &c);
    s.thermal_expansion = false;
    acbb_expansion_compute(&s, &t, &e);
    ok(e.ball == 0 && e.inner == 0 && e.outer == 0, "WTE: thermal terms are 0");
    ok(c.inner_cen > 0 && e.inner_cen == 0, "WTE: the centrifugal growth is forced to 0 too");

    make_scene(&s);
    s.geometry = ACBB_GEOM_SEED;
    acbb_expansion_compute(&s, &t, &e);
    double seed = 12.5e-6 * 24.0 * rb +
                  (11.5e-6 * 19.0 * 1.298 - 12.5e-6 * 24.0) * rb * rb / r_il;
    is_close(e.inner, seed, 1e-12, 0, "SEED: eq (3) first term uses the bore radius");
    is_close(c.inner - e.inner, 12.5e-6 * 24.0 * (r_il - rb), 1e-9, 0,
             "SEED differs from CLEAN by chi_i dT_i (r_il - r_ik)");
    ok(e.ball == c.ball && e.outer == c.outer && e.inner_cen == c.inner_cen,
       "SEED changes only eq (3)");
}

static void test_projection(void)
{
    acbb_expansion e = { .ball = 1.2e-6, .inner = 8e-6, .inner_cen = 1e-6,
                         .outer = 5e-6 };
    acbb_seed_projection p;
    double ai = 20 * DEG, ao = 12 * DEG;
    acbb_expansion_seed_project(&e, ai, ao, &p);
    double onl = 5e-6 * cos(ao), inl = onl * cos(ai - ao);
    is_close(p.onl, onl, 1e-14, 0, "eq (5): onl = theta_o cos(alpha_o)");
    is_close(p.inl, inl, 1e-14, 0, "eq (6): inl = onl cos(alpha_i - alpha_o)");
    is_close(p.ix, inl * sin(ai), 1e-14, 0, "eq (7): ix = inl sin(alpha_i)");
    is_close(p.iz, inl * cos(ai), 1e-14, 0, "eq (8): iz = inl cos(alpha_i)");
    is_close(p.bax, 1.2e-6 * sin(ai), 1e-14, 0, "eq (10): bax = ball sin(alpha_i)");
    is_close(p.baz, 1.2e-6 * cos(ai), 1e-14, 0, "eq (11): baz = ball cos(alpha_i)");
    is_close(hypot(p.ix, p.iz), p.inl, 1e-14, 0, "ix, iz are components of inl");
}

int main(void)
{
    gsl_set_error_handler_off();
    test_equations();
    test_compute();
    test_switches();
    test_projection();
    return done_testing();
}
