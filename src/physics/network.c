/* acbb — the bearing's thermal networks (MODEL.md section 8.1: 46 nodes,
 * section 8.3: 7-node teaching network) built on the general acbb_tnet.
 *
 * Resistance types (MODEL.md 8.1): RC radial conduction, AC axial
 * conduction, TC thermal contact, SP contact-spot constriction, BI ball
 * interior, CV convection, GF cage guide-gap film, ADV oil-air advection.
 * Bearing dimensions come from the scene; the housing, shaft segment and end
 * cap around the bearing are not in the seed paper [S]: they come from the
 * scene's [surroundings], unset sizes scaled from the seed's ASSUMED 7008C
 * rig (acbb_scene_surroundings; MODEL.md 8.1 "Geometry for the network",
 * 13 "Surroundings"), and so do the boundary conditions of the cooled faces.
 *
 * Edges whose resistance depends on the running state (SP spots, the
 * speed-dependent CV films and the ADV edge) are recomputed by
 * acbb_network_update in a fixed order shared with the build, so their edge
 * indices are recorded once (edge_sp_*, edge_cv[]). */
#include <math.h>
#include <string.h>
#include "contact_heat.h"
#include "network.h"
#include "acbb/tools/surroundings.h"

#define R_OPEN 1e6             /* "no contact" spot / no-flow resistance, K/W */
#define RE_DISC_TURB 2.4e5     /* rotating-disc laminar/turbulent transition (UNSURE) */

/* Derived radii and lengths of one bearing in its surroundings, m. */
typedef struct {
    double Bw, Wc, D, dm;
    int Z;
    double r_o, r_race_o, r_land_o, r_mid_o;      /* outer ring */
    double r_b, r_race_i, r_land_i, r_mid_i;      /* inner ring, r_b = bore/2 */
    double r_c, r_cin, r_cmid;                    /* cage */
    double r_sb;                                  /* shaft bore radius */
    double r_sh, r_hm, r_36;                      /* housing shoulder, mid, node 36 */
    double r_cap_in;
    /* surroundings (acbb_surroundings): housing outer radius and length,
     * shoulder thickness, |x| of node 36, cap outer radius and thickness,
     * shaft segment length */
    double r_h, L_h, t_sh, x36, r_cap_out, t_cap, L_s;
    double A_face_o;                              /* OR end-face annulus */
    double A_cap_cav;                             /* cap area wetted by the cavity */
    double V_h, V_or, V_ir, V_ball, V_cage, V_shaft, V_cap, V_cav;
} net_geom;

/* Oil-air mixture properties for the cavity films (MODEL.md 6 note (ii)). */
typedef struct {
    double nu;          /* kinematic viscosity, m^2/s */
    double k;           /* conductivity k_f (mix_k), W/(m K) */
    double pr;          /* Prandtl number (air: the mixture is ~all air) */
    double rho_cp;      /* volumetric heat capacity, J/(m^3 K) */
    double G_adv;       /* mass flow * cp of the through-flow, W/K */
} net_fluid;

/* One recomputed edge: end nodes and resistance. */
typedef struct {
    int a, b;
    double R;
} net_edge;

static double sq(double x) { return x * x; }

/* ---- resistance types (MODEL.md 8.1) ---- */
static double r_rc(double r1, double r2, double k, double L)
{
    return log(fmax(r1, r2) / fmin(r1, r2)) / (2.0 * M_PI * k * L);
}
static double r_ac(double dx, double k, double A) { return dx / (k * A); }
static double r_film(double h, double A) { return 1.0 / (h * A); }
static double annulus(double r1, double r2) { return M_PI * fabs(sq(r2) - sq(r1)); }

/* ---- geometry ---- */
static acbb_status geom_from_scene(const acbb_scene *s, net_geom *g, acbb_error *err)
{
    memset(g, 0, sizeof *g);
    g->Bw = s->width;
    g->Wc = s->cage_width;
    g->D = s->ball_diameter;
    g->dm = s->pitch_diameter;
    g->Z = s->n_balls;
    g->r_o = 0.5 * s->outer_diameter;
    g->r_race_o = 0.5 * (g->dm + g->D);
    g->r_land_o = 0.5 * s->outer_land_diameter;
    g->r_mid_o = 0.5 * (g->r_race_o + g->r_o);
    g->r_b = 0.5 * s->bore;
    g->r_race_i = 0.5 * (g->dm - g->D);
    g->r_land_i = 0.5 * s->inner_land_diameter;
    g->r_mid_i = 0.5 * (g->r_b + g->r_race_i);
    acbb_surroundings u;
    acbb_scene_surroundings(s, &u);
    g->r_h = 0.5 * u.housing_od;
    g->L_h = u.housing_length;
    g->t_sh = u.shoulder_thickness;
    g->x36 = u.x_end_wall;
    g->r_cap_out = 0.5 * u.cap_od;
    g->t_cap = u.cap_thickness;
    g->L_s = u.shaft_length;
    g->r_c = 0.5 * s->cage_diameter;
    g->r_cin = 0.5 * g->dm - u.cage_clearance;
    g->r_cmid = 0.5 * (g->r_c + g->r_cin);
    g->r_sb = 0.5 * u.shaft_bore;
    g->r_sh = g->r_o - u.shoulder_inset;
    g->r_hm = 0.5 * (g->r_o + g->r_h);
    g->r_36 = 0.5 * (g->r_sh + g->r_h);
    g->r_cap_in = g->r_o - u.cap_inset;

    if (!(g->Bw > 0 && g->Wc > 0 && g->D > 0 && g->dm > 0 && g->Z >= 1))
        return acbb_error_set(err, ACBB_EINVAL, "network: width, cage width, ball "
                              "diameter, pitch diameter and ball count must be positive");
    if (!(g->r_sb >= 0 && g->r_sb < g->r_b && g->r_b < g->r_race_i &&
          g->r_race_i < g->r_land_i && g->r_land_i < g->r_cin && g->r_cin < g->r_c &&
          g->r_c < g->r_land_o && g->r_land_o < g->r_race_o && g->r_race_o < g->r_o))
        return acbb_error_set(err, ACBB_EINVAL, "network: radii must increase shaft bore "
                              "< bore < IR raceway < IR land < cage ID (d_m/2 - 1.5 mm) < "
                              "cage OD < OR land < OR raceway < OD");
    if (!(g->r_land_i < g->r_cap_in && g->r_land_o < g->r_sh))
        return acbb_error_set(err, ACBB_EINVAL, "network: the end cap bore (r = %.4g mm) must "
                              "clear the inner ring land (r = %.4g mm) and the housing shoulder "
                              "(r = %.4g mm) sit on the outer ring face (land r = %.4g mm)",
                              g->r_cap_in * 1e3, g->r_land_i * 1e3, g->r_sh * 1e3,
                              g->r_land_o * 1e3);
    if (!(g->r_o < g->r_h && g->r_o < g->r_cap_out && g->Bw + 2 * fmax(g->t_sh, g->t_cap) <=
          g->L_h * (1.0 + 1e-12) && g->Bw <= g->L_s && g->r_sb > 0))
        return acbb_error_set(err, ACBB_EINVAL, "network: the surroundings do not hold the "
                              "bearing (housing r = %.4g mm, length %.4g mm; cap r = %.4g mm, "
                              "%.4g mm thick; shaft segment %.4g mm, bore r = %.4g mm; bearing "
                              "r = %.4g mm, width %.4g mm)", g->r_h * 1e3, g->L_h * 1e3,
                              g->r_cap_out * 1e3, g->t_cap * 1e3, g->L_s * 1e3, g->r_sb * 1e3,
                              g->r_o * 1e3, g->Bw * 1e3);

    g->A_face_o = annulus(g->r_land_o, g->r_o);
    /* cap bore plus the part of its face over the cavity (inside the OR land) */
    g->A_cap_cav = 2.0 * M_PI * g->r_cap_in * g->t_cap;
    if (g->r_land_o > g->r_cap_in) g->A_cap_cav += annulus(g->r_cap_in, g->r_land_o);
    /* Capacities (MODEL.md 8.1 "Capacities"): ring sections from raceway
     * bottom to bore/OD (land ridges and groove neglected: they nearly
     * cancel), housing sleeve plus rear shoulder. */
    g->V_h = annulus(g->r_o, g->r_h) * g->L_h + annulus(g->r_sh, g->r_o) * g->t_sh;
    g->V_or = annulus(g->r_race_o, g->r_o) * g->Bw;
    g->V_ir = annulus(g->r_b, g->r_race_i) * g->Bw;
    g->V_ball = g->Z * M_PI * pow(g->D, 3) / 6.0;
    /* cage ring minus Z cylindrical pockets of diameter D */
    g->V_cage = annulus(g->r_cin, g->r_c) * g->Wc
                - g->Z * M_PI * sq(0.5 * g->D) * (g->r_c - g->r_cin);
    g->V_shaft = annulus(g->r_sb, g->r_b) * g->L_s;
    g->V_cap = annulus(g->r_cap_in, g->r_cap_out) * g->t_cap;
    g->V_cav = annulus(g->r_land_i, g->r_land_o) * g->Bw - g->V_ball - fmax(g->V_cage, 0.0);
    if (!(g->V_cage > 0 && g->V_cav > 0))
        return acbb_error_set(err, ACBB_EINVAL, "network: balls and cage do not fit "
                              "between the ring lands (cage or cavity volume <= 0)");
    return ACBB_OK;
}

static int material_ok(const acbb_material *m)
{
    return m->rho > 0 && m->cp > 0 && m->k > 0 && isfinite(m->rho * m->cp * m->k);
}

static acbb_status check_scene(const acbb_scene *s, acbb_error *err)
{
    if (!material_ok(&s->ball) || !material_ok(&s->ring) || !material_ok(&s->shaft) ||
        !material_ok(&s->housing) || !material_ok(&s->cage))
        return acbb_error_set(err, ACBB_EINVAL, "network: every material needs rho, "
                              "cp and k > 0");
    if (!(s->h_fit_outer > 0 && s->h_fit_inner > 0 && s->h_face > 0 && s->h_natural > 0))
        return acbb_error_set(err, ACBB_EINVAL, "network: contact and natural "
                              "convection coefficients must be > 0");
    if (!(s->mix_k > 0 && s->air_k > 0 && s->air_eta > 0 && s->air_density > 0 &&
          s->air_cp > 0 && s->air_pr > 0 && s->oil_density > 0 && s->oil_cp > 0 &&
          s->q_air >= 0 && s->q_oil >= 0))
        return acbb_error_set(err, ACBB_EINVAL, "network: air/oil properties must be "
                              "> 0 and flows >= 0");
    const acbb_face_bc *bc[2] = {&s->bore_bc, &s->cap_bc};
    for (int i = 0; i < 2; i++)
        if (!(isfinite(bc[i]->dT) && (acbb_face_bc_kind(s, bc[i]) == ACBB_BC_FIXED ||
              (acbb_face_bc_kind(s, bc[i]) == ACBB_BC_CONVECTIVE && bc[i]->h > 0
               && isfinite(bc[i]->h)))))
            return acbb_error_set(err, ACBB_EINVAL, "network: a convective %s needs a film "
                                  "coefficient > 0 W/(m^2 K) and a finite coolant temperature",
                                  i ? "end cap" : "shaft bore");
    if (!(isfinite(s->ambient_C) && s->contact_multiplier > 0 &&
          s->heat_partition >= 0 && s->heat_partition <= 1))
        return acbb_error_set(err, ACBB_EINVAL, "network: ambient must be finite, "
                              "contact multiplier > 0, heat partition in [0, 1]");
    return ACBB_OK;
}

/* ---- fluid ---- */

/* Oil dynamic viscosity at T (C): Walther / ASTM D341 through (40 C, nu40)
 * and (100 C, nu100), density rho20 [1 - 6.5e-4 (T - 20)] (MODEL.md 5).
 * Written here rather than calling lubrication.c to keep the network module
 * independent; only the oil share X of the cavity mixture uses it. */
static double oil_eta(const acbb_scene *s, double T_C)
{
    double rho = s->oil_density * (1.0 - 6.5e-4 * (T_C - 20.0));
    if (s->visc == ACBB_VISC_CONST) return s->oil_eta_const;
    double n40 = s->oil_nu40 * 1e6, n100 = s->oil_nu100 * 1e6;   /* mm^2/s */
    if (!(n40 > n100 && n100 > 0.0)) return rho * s->oil_nu40;
    double z40 = log10(log10(n40 + 0.7)), z100 = log10(log10(n100 + 0.7));
    double B = (z40 - z100) / (log10(373.15) - log10(313.15));
    double A = z40 + B * log10(313.15);
    double T_K = fmax(T_C + 273.15, 200.0);
    double nu = pow(10.0, pow(10.0, A - B * log10(T_K))) - 0.7;
    return rho * fmax(nu, 0.0) * 1e-6;
}

/* Mixture by oil volume fraction X = q_oil/(q_oil + q_air) (MODEL.md 6
 * note (ii)); rho*cp is mass weighted, so rho_eff cp_eff q_eff reduces to
 * q_oil rho_oil cp_oil + q_air rho_air cp_air (MODEL.md 8.1 ADV). */
static void fluid_at(const acbb_scene *s, double T_C, net_fluid *f)
{
    double qt = s->q_oil + s->q_air;
    /* the cavity medium by method, as acbb_mixture_at (MODEL.md 16) */
    int mist = s->lub_method == ACBB_LUB_OIL_AIR || s->lub_method == ACBB_LUB_OIL_JET;
    double X = mist && qt > 0.0 ? s->q_oil / qt : 0.0;
    double rho_oil = s->oil_density * (1.0 - 6.5e-4 * (T_C - 20.0));
    double rho = X * rho_oil + (1.0 - X) * s->air_density;
    double eta = X * oil_eta(s, T_C) + (1.0 - X) * s->air_eta;
    f->nu = eta / rho;
    f->k = s->mix_k;
    f->pr = s->air_pr;
    f->rho_cp = X * rho_oil * s->oil_cp + (1.0 - X) * s->air_density * s->air_cp;
    f->G_adv = s->q_oil * rho_oil * s->oil_cp + s->q_air * s->air_density * s->air_cp;
}

static double r_adv(const net_fluid *f)
{
    return f->G_adv > 1.0 / R_OPEN ? 1.0 / f->G_adv : R_OPEN;
}

/* ---- convection correlations (MODEL.md 8.1 CV). Every h is floored at
 * h_natural so a standing bearing (omega = 0) keeps finite films. ---- */

/* Rotating cylinder of diameter d (Kreith, used by [BT]). */
static double h_rot_cylinder(const net_fluid *f, double omega, double d)
{
    double Re = fabs(omega) * d * d / f->nu;
    return 0.133 * pow(Re, 2.0 / 3.0) * cbrt(f->pr) * f->k / d;
}

/* Rotating disc face of outer radius r (UNSURE constants). */
static double h_rot_disc(const net_fluid *f, double omega, double r)
{
    double Re = fabs(omega) * r * r / f->nu;
    double Nu = Re < RE_DISC_TURB ? 0.36 * sqrt(Re) : 0.015 * pow(Re, 0.8);
    return Nu * f->k / r;
}

/* Laminar flat plate of length L in a stream of speed u. */
static double h_plate(const net_fluid *f, double u, double L)
{
    double Re = fabs(u) * L / f->nu;
    return 0.664 * sqrt(Re) * cbrt(f->pr) * f->k / L;
}

/* Whitaker sphere of diameter D at speed v (viscosity ratio omitted). */
static double h_sphere(const net_fluid *f, double v, double D)
{
    double Re = fabs(v) * D / f->nu;
    double Nu = 2.0 + (0.4 * sqrt(Re) + 0.06 * pow(Re, 2.0 / 3.0)) * pow(f->pr, 0.4);
    return Nu * f->k / D;
}

/* Film coefficients of the bearing surfaces at the current speeds. */
typedef struct {
    double ir_cyl, ir_disc, ball, cage, or_land, h_bore, h_shoulder, cap;
} net_films;

static void films_at(const net_geom *g, const acbb_scene *s, const net_fluid *f,
                     double omega_i, double omega_m, net_films *h)
{
    double hn = s->h_natural;
    h->ir_cyl = fmax(h_rot_cylinder(f, omega_i, 2.0 * g->r_land_i), hn);
    h->ir_disc = fmax(h_rot_disc(f, omega_i, g->r_land_i), hn);
    h->ball = fmax(h_sphere(f, omega_m * 0.5 * g->dm, g->D), hn);
    /* cage and stationary cavity walls see the oil-air swirl u = omega_c r/2
     * (ASSUMED), with their axial width as the plate length */
    h->cage = fmax(h_plate(f, 0.5 * omega_m * g->r_c, g->Wc), hn);
    h->or_land = fmax(h_plate(f, 0.5 * omega_m * g->r_land_o, g->Bw), hn);
    h->h_bore = fmax(h_plate(f, 0.5 * omega_m * g->r_o, 0.5 * (g->L_h - g->Bw)), hn);
    h->h_shoulder = fmax(h_plate(f, 0.5 * omega_m * g->r_sh, g->t_sh), hn);
    h->cap = fmax(h_plate(f, 0.5 * omega_m * g->r_cap_in, g->t_cap), hn);
}

/* ---- contact spots (MODEL.md 8.1 SP, [Y]; docs/contact_heat.md) ---- */

/* One body's spot resistance, Z contacts in parallel: the stationary
 * isothermal spot (the seed) or the moving source (contact_heat.h) at the
 * body's own surface speed v through the contact and diffusivity. */
static double r_spot(const acbb_scene *s, double a, double b, const acbb_material *m,
                     double v, int Z)
{
    double r = s->contact_model == ACBB_CONTACT_MOVING
                   ? acbb_spot_r_moving(a, b, m->k, m->k / (m->rho * m->cp), v)
                   : acbb_spot_r_stationary(a, b, m->k);
    return fmin(r / Z, R_OPEN);
}

/* ---- names ---- */
static const char *const names46[46] = {
    "0 ambient", "1 housing outer front", "2 housing bore front",
    "3 housing outer rear", "4 housing bore rear", "5 OR outer front (sensor)",
    "6 OR interior front", "7 OR raceway", "8 OR outer rear", "9 OR interior rear",
    "10 OR land", "11 OR rear face", "12 OR front face", "13 ball outer side",
    "14 cage body", "15 ball centre", "16 oil-air at balls", "17 ball inner side",
    "18 cage outer surface", "19 IR raceway", "20 IR interior front",
    "21 IR bore front", "22 IR land", "23 IR interior rear", "24 IR bore rear",
    "25 IR front face", "26 IR rear face", "27 shaft under IR front",
    "28 shaft bore front", "29 shaft under IR rear", "30 shaft bore rear",
    "31 housing shoulder face", "32 housing rear face", "33 housing front face",
    "34 housing bore in cavity front", "35 housing shoulder in cavity",
    "36 housing end wall", "37 cap face at OR", "38 cap outer inner",
    "39 cap face in cavity", "40 cap outer middle", "41 cap body",
    "42 cap outer outer", "43 oil-air chamber", "44 inner contact",
    "45 outer contact",
};

static const char *const names7[8] = {
    "0 ambient", "1 housing", "2 outer ring", "3 balls and cage", "4 inner ring",
    "5 shaft", "6 oil-air", "7 shaft bore coolant",
};

/* ---- the state-dependent edges, in the order shared by build and update ---- */

/* 46-node: eleven speed-dependent CV films, then ADV 43-0. */
static int cv_edges46(const net_geom *g, const acbb_scene *s, const net_fluid *f,
                      double omega_i, double omega_m, net_edge *e)
{
    net_films h;
    films_at(g, s, f, omega_i, omega_m, &h);
    double A_ball = g->Z * M_PI * sq(g->D);
    double A_disc = annulus(g->r_b, g->r_land_i);
    double r_ball_half = 1.0 / (2.0 * h.ball * A_ball);   /* 15-16, 16-43 split */
    int n = 0;
    e[n++] = (net_edge){34, 43, r_film(h.h_bore, 2 * M_PI * g->r_o * 0.5 * (g->L_h - g->Bw))};
    e[n++] = (net_edge){35, 43, r_film(h.h_shoulder, 2 * M_PI * g->r_sh * g->t_sh)};
    e[n++] = (net_edge){10, 43, r_film(h.or_land, 2 * M_PI * g->r_land_o * g->Bw)};
    e[n++] = (net_edge){39, 43, r_film(h.cap, g->A_cap_cav)};
    e[n++] = (net_edge){15, 16, r_ball_half};
    e[n++] = (net_edge){16, 43, r_ball_half};
    e[n++] = (net_edge){14, 16, r_film(h.cage, g->Z * M_PI * g->D * g->Wc / 2.0)};
    e[n++] = (net_edge){18, 43, r_film(h.cage, 2 * M_PI * g->r_c * g->Wc)};
    e[n++] = (net_edge){22, 43, r_film(h.ir_cyl, 2 * M_PI * g->r_land_i * g->Bw)};
    e[n++] = (net_edge){25, 43, r_film(h.ir_disc, A_disc)};
    e[n++] = (net_edge){26, 43, r_film(h.ir_disc, A_disc)};
    e[n++] = (net_edge){43, 0, r_adv(f)};
    return n;
}

/* 7-node: OR land, balls + cage, IR cylinder + both faces, then ADV 6-0. */
static int cv_edges7(const net_geom *g, const acbb_scene *s, const net_fluid *f,
                     double omega_i, double omega_m, net_edge *e)
{
    net_films h;
    films_at(g, s, f, omega_i, omega_m, &h);
    double G_ball = h.ball * g->Z * M_PI * sq(g->D) + h.cage * 2 * M_PI * g->r_c * g->Wc;
    double G_ir = h.ir_cyl * 2 * M_PI * g->r_land_i * g->Bw
                  + 2.0 * h.ir_disc * annulus(g->r_b, g->r_land_i);
    int n = 0;
    e[n++] = (net_edge){2, 6, r_film(h.or_land, 2 * M_PI * g->r_land_o * g->Bw)};
    e[n++] = (net_edge){3, 6, 1.0 / G_ball};
    e[n++] = (net_edge){4, 6, 1.0 / G_ir};
    e[n++] = (net_edge){6, 0, r_adv(f)};
    return n;
}

/* Ball interior, hemispherical shell D/4 -> D/2, Z balls in parallel. */
static double r_bi(const net_geom *g, const acbb_scene *s)
{
    return 1.0 / (M_PI * s->ball.k * g->D) / g->Z;
}

/* ---- building ---- */

typedef struct {
    acbb_network *nw;
    acbb_status st;
} net_builder;

static int add(net_builder *b, int n1, int n2, double R)
{
    if (b->st != ACBB_OK) return -1;
    int e = acbb_tnet_add_edge(b->nw->net, n1, n2, R);
    if (e < 0) b->st = (acbb_status)e;
    return e;
}

static void cap(net_builder *b, int node, double C)
{
    if (b->st != ACBB_OK) return;
    acbb_status st = acbb_tnet_set_capacity(b->nw->net, node, C);
    if (st != ACBB_OK) b->st = st;
}

static void fix(net_builder *b, int node, double T)
{
    if (b->st != ACBB_OK) return;
    acbb_status st = acbb_tnet_set_fixed(b->nw->net, node, T);
    if (st != ACBB_OK) b->st = st;
}

static void set_avg(int *dst, int *n, const int *src, int count)
{
    for (int i = 0; i < count; i++) dst[i] = src[i];
    *n = count;
}

/* Series film of a convective face (0 for a fixed one): the face node then
 * stands for the coolant, held at ambient + dT like a fixed face, and the
 * algebraic surface node between conduction and film is eliminated
 * exactly (MODEL.md 8.1 CV, 13 "Surroundings"). */
static double r_face(const acbb_scene *s, const acbb_face_bc *bc, double A)
{
    return acbb_face_bc_kind(s, bc) == ACBB_BC_CONVECTIVE ? r_film(bc->h, A) : 0.0;
}

/* Fixed nodes: ambient, the shaft bore (28, 30) and the cap's outer face
 * (38, 40, 42) at their coolant temperature ([S] section 3: ambient), the
 * housing exterior (1, 3, 32, 33) when it is fixed; else its natural
 * convection to ambient. */
static void boundaries46(net_builder *b, const acbb_scene *s, const net_geom *g)
{
    const double hn = s->h_natural;
    fix(b, 0, s->ambient_C);
    fix(b, 28, s->ambient_C + s->bore_bc.dT);
    fix(b, 30, s->ambient_C + s->bore_bc.dT);
    for (int n = 38; n <= 42; n += 2) fix(b, n, s->ambient_C + s->cap_bc.dT);
    if (s->housing_bc == ACBB_BC_FIXED) {
        static const int ext[] = {1, 3, 32, 33};
        for (int i = 0; i < 4; i++) fix(b, ext[i], s->ambient_C);
        return;
    }
    add(b, 0, 1, r_film(hn, 2 * M_PI * g->r_h * 0.5 * g->L_h));
    add(b, 0, 3, r_film(hn, 2 * M_PI * g->r_h * 0.5 * g->L_h));
    add(b, 0, 32, r_film(hn, annulus(g->r_o, g->r_h)));
    add(b, 0, 33, r_film(hn, annulus(g->r_o, g->r_h)));
}

/* Housing body: outer (r_hm..r_h) and inner (r_o..r_hm) half annuli, rear
 * shoulder wall; housing <-> OR: fit halves and the shoulder face. */
static void housing46(net_builder *b, const acbb_scene *s, const net_geom *g)
{
    const double kh = s->housing.k, hB = 0.5 * g->Bw, qB = 0.25 * g->Bw, L = g->L_h;
    const double A_ho = annulus(g->r_hm, g->r_h), A_hi = annulus(g->r_o, g->r_hm);
    add(b, 1, 2, r_rc(g->r_o, g->r_h, kh, 0.5 * L));
    add(b, 3, 4, r_rc(g->r_o, g->r_h, kh, 0.5 * L));
    add(b, 1, 3, r_ac(0.5 * L, kh, A_ho));
    add(b, 2, 4, r_ac(hB, kh, A_hi));
    add(b, 2, 34, r_ac(0.5 * (hB + 0.5 * L) - qB, kh, A_hi));
    add(b, 1, 33, r_ac(0.25 * L, kh, A_ho));
    add(b, 34, 33, r_ac(0.5 * L - 0.5 * (hB + 0.5 * L), kh, A_hi));
    add(b, 3, 36, r_rc(g->r_36, g->r_h, kh, g->t_sh));
    add(b, 4, 36, r_ac(g->x36 - qB, kh, A_hi));
    add(b, 36, 31, r_rc(0.5 * (g->r_o + g->r_race_o), g->r_36, kh, g->t_sh));
    add(b, 36, 32, r_ac(0.5 * L - g->x36, kh, annulus(g->r_sh, g->r_h)));
    add(b, 36, 35, r_rc(g->r_sh, g->r_36, kh, g->t_sh));
    add(b, 2, 5, r_film(s->h_fit_outer, M_PI * 2 * g->r_o * hB));
    add(b, 4, 8, r_film(s->h_fit_outer, M_PI * 2 * g->r_o * hB));
    add(b, 31, 11, r_film(s->h_face, g->A_face_o));
}

/* OR body, cage guide film, OR <-> cap face, and the cap (housing
 * material, ASSUMED) whose outer face is split in three annuli. */
static void outer46(net_builder *b, const acbb_scene *s, const net_geom *g)
{
    const double kh = s->housing.k, kr = s->ring.k, hB = 0.5 * g->Bw, qB = 0.25 * g->Bw;
    const double A_or = annulus(g->r_race_o, g->r_o), hT = 0.5 * g->t_cap;
    const double r_cap1 = g->r_cap_in + (g->r_cap_out - g->r_cap_in) / 3.0;
    const double r_cap2 = g->r_cap_in + 2.0 * (g->r_cap_out - g->r_cap_in) / 3.0;
    const double A1 = annulus(g->r_cap_in, r_cap1), A2 = annulus(r_cap1, r_cap2),
                 A3 = annulus(r_cap2, g->r_cap_out);
    add(b, 5, 6, r_rc(g->r_mid_o, g->r_o, kr, hB));
    add(b, 8, 9, r_rc(g->r_mid_o, g->r_o, kr, hB));
    add(b, 6, 7, r_rc(g->r_race_o, g->r_mid_o, kr, hB));
    add(b, 9, 7, r_rc(g->r_race_o, g->r_mid_o, kr, hB));
    add(b, 6, 10, r_rc(g->r_land_o, g->r_mid_o, kr, hB));
    add(b, 9, 10, r_rc(g->r_land_o, g->r_mid_o, kr, hB));
    add(b, 6, 9, r_ac(hB, kr, A_or));
    add(b, 6, 12, r_ac(qB, kr, A_or));
    add(b, 9, 11, r_ac(qB, kr, A_or));
    add(b, 10, 18, r_rc(g->r_c, g->r_land_o, s->mix_k, g->Wc));
    add(b, 12, 37, r_film(s->h_face, g->A_face_o));
    add(b, 37, 41, r_ac(hT, kh, g->A_face_o));
    add(b, 39, 41, r_ac(hT, kh, g->A_cap_cav));
    add(b, 41, 38, r_ac(hT, kh, A1) + r_face(s, &s->cap_bc, A1));
    add(b, 41, 40, r_ac(hT, kh, A2) + r_face(s, &s->cap_bc, A2));
    add(b, 41, 42, r_ac(hT, kh, A3) + r_face(s, &s->cap_bc, A3));
}

/* Contacts (open until the first update), ball interior, cage body, IR
 * body, IR <-> shaft fit halves and the shaft segment to its bore. */
static void inner46(net_builder *b, const acbb_scene *s, const net_geom *g)
{
    acbb_network *nw = b->nw;
    const double kr = s->ring.k, ks = s->shaft.k, hB = 0.5 * g->Bw, qB = 0.25 * g->Bw;
    const double A_ir = annulus(g->r_b, g->r_race_i), A_sh = annulus(g->r_sb, g->r_b);
    const double A_bore = 2 * M_PI * g->r_sb * 0.5 * g->L_s;   /* per half */
    nw->edge_sp_race_o = add(b, 7, 45, R_OPEN);
    nw->edge_sp_ball_o = add(b, 45, 13, R_OPEN);
    nw->edge_sp_race_i = add(b, 19, 44, R_OPEN);
    nw->edge_sp_ball_i = add(b, 44, 17, R_OPEN);
    add(b, 13, 15, r_bi(g, s));
    add(b, 17, 15, r_bi(g, s));
    add(b, 14, 18, r_rc(g->r_cmid, g->r_c, s->cage.k, g->Wc));
    add(b, 19, 20, r_rc(g->r_mid_i, g->r_race_i, kr, hB));
    add(b, 19, 23, r_rc(g->r_mid_i, g->r_race_i, kr, hB));
    add(b, 20, 21, r_rc(g->r_b, g->r_mid_i, kr, hB));
    add(b, 23, 24, r_rc(g->r_b, g->r_mid_i, kr, hB));
    add(b, 20, 22, r_rc(g->r_mid_i, g->r_land_i, kr, hB));
    add(b, 23, 22, r_rc(g->r_mid_i, g->r_land_i, kr, hB));
    add(b, 20, 23, r_ac(hB, kr, A_ir));
    add(b, 20, 25, r_ac(qB, kr, A_ir));
    add(b, 23, 26, r_ac(qB, kr, A_ir));
    add(b, 21, 27, r_film(s->h_fit_inner, M_PI * s->bore * hB));
    add(b, 24, 29, r_film(s->h_fit_inner, M_PI * s->bore * hB));
    add(b, 27, 28, r_rc(g->r_sb, g->r_b, ks, 0.5 * g->L_s) + r_face(s, &s->bore_bc, A_bore));
    add(b, 29, 30, r_rc(g->r_sb, g->r_b, ks, 0.5 * g->L_s) + r_face(s, &s->bore_bc, A_bore));
    add(b, 27, 29, r_ac(hB, ks, A_sh));
}

/* Capacities C = rho cp V (MODEL.md 8.1 "Capacities"). */
static void capacities46(net_builder *b, const acbb_scene *s, const net_geom *g,
                         const net_fluid *f)
{
    double ch = s->housing.rho * s->housing.cp, cr = s->ring.rho * s->ring.cp;
    static const int housing_nodes[] = {1, 2, 3, 4, 36};
    for (int i = 0; i < 5; i++) cap(b, housing_nodes[i], ch * g->V_h / 5.0);
    cap(b, 6, 0.5 * cr * g->V_or);
    cap(b, 9, 0.5 * cr * g->V_or);
    cap(b, 20, 0.5 * cr * g->V_ir);
    cap(b, 23, 0.5 * cr * g->V_ir);
    cap(b, 15, s->ball.rho * s->ball.cp * g->V_ball);
    cap(b, 14, s->cage.rho * s->cage.cp * g->V_cage);
    cap(b, 27, 0.5 * s->shaft.rho * s->shaft.cp * g->V_shaft);
    cap(b, 29, 0.5 * s->shaft.rho * s->shaft.cp * g->V_shaft);
    cap(b, 41, ch * g->V_cap);
    cap(b, 16, 0.5 * f->rho_cp * g->V_cav);
    cap(b, 43, 0.5 * f->rho_cp * g->V_cav);
}

/* Key nodes, heat destinations, part averages (MODEL.md 7 table) and
 * lubricant inlet nodes (MODEL.md 5). */
static void roles46(acbb_network *nw)
{
    nw->names = names46;
    nw->node_ambient = 0;
    nw->node_outer_ring = 5;
    nw->node_inner_ring = 19;
    nw->node_ball = 15;
    nw->node_housing = 2;
    nw->node_shaft = 27;
    nw->node_cavity = 43;
    nw->node_cage = 14;
    nw->heat_inner = 44;
    nw->heat_outer = 45;
    nw->heat_spin = 15;
    nw->heat_drag = 43;
    set_avg(nw->avg_ball, &nw->n_avg_ball, (const int[]){15}, 1);
    set_avg(nw->avg_inner, &nw->n_avg_inner, (const int[]){19, 20, 22, 23}, 4);
    set_avg(nw->avg_shaft, &nw->n_avg_shaft, (const int[]){27, 29}, 2);
    set_avg(nw->avg_housing, &nw->n_avg_housing, (const int[]){1, 2, 3, 4}, 4);
    set_avg(nw->avg_outer, &nw->n_avg_outer, (const int[]){5, 6, 8, 9}, 4);
    nw->inlet_inner[0] = 19;
    nw->inlet_inner[1] = 17;
    nw->inlet_outer[0] = 7;
    nw->inlet_outer[1] = 13;
}

/* 46-node network (MODEL.md 8.1): fixed edges in the seed order, then the
 * speed-dependent films and the advection edge at standstill. */
static void build46(net_builder *b, const acbb_scene *s, const net_geom *g)
{
    boundaries46(b, s, g);
    housing46(b, s, g);
    outer46(b, s, g);
    inner46(b, s, g);
    net_fluid f;
    net_edge cv[16];
    fluid_at(s, s->ambient_C, &f);
    b->nw->n_edge_cv = cv_edges46(g, s, &f, 0.0, 0.0, cv);
    for (int i = 0; i < b->nw->n_edge_cv; i++)
        b->nw->edge_cv[i] = add(b, cv[i].a, cv[i].b, cv[i].R);
    capacities46(b, s, g, &f);
    roles46(b->nw);
}

/* 7-node network (MODEL.md 8.3). Node 5 (shaft) stays free: its edge 5-0 is
 * conduction to the shaft bore, and the bore surface is at ambient as [S]
 * assumes for nodes 28/30 ("thorough" bore convection) unless
 * surroundings.shaft_bore is convective (film in series) or its coolant is
 * not at ambient (an eighth, fixed node). This keeps the shaft expansion of
 * MODEL.md 7 alive, unlike a Dirichlet node 5. The 7-node network has no
 * end cap: the cap keys do not apply to it. */
static void build7(net_builder *b, const acbb_scene *s, const net_geom *g)
{
    acbb_network *nw = b->nw;
    const double kh = s->housing.k, kr = s->ring.k, ks = s->shaft.k;
    const double r_smid = 0.5 * (g->r_sb + g->r_b);

    fix(b, 0, s->ambient_C);
    /* housing exterior: outer cylinder and both end annuli */
    if (s->housing_bc == ACBB_BC_FIXED)
        fix(b, 1, s->ambient_C);
    else
        add(b, 0, 1, r_film(s->h_natural, 2 * M_PI * g->r_h * g->L_h
                                          + 2.0 * annulus(g->r_o, g->r_h)));
    /* housing mid radius -> bore, fit, OR OD -> OR centroid (series) */
    add(b, 1, 2, r_rc(g->r_o, g->r_hm, kh, g->L_h)
                 + r_film(s->h_fit_outer, 2 * M_PI * g->r_o * g->Bw)
                 + r_rc(g->r_mid_o, g->r_o, kr, g->Bw));
    nw->edge_sp_race_o = add(b, 2, 3, R_OPEN);
    nw->edge_sp_race_i = add(b, 3, 4, R_OPEN);
    nw->edge_sp_ball_o = nw->edge_sp_ball_i = -1;   /* lumped into the edges above */
    add(b, 4, 5, r_rc(g->r_b, g->r_mid_i, kr, g->Bw)
                 + r_film(s->h_fit_inner, 2 * M_PI * g->r_b * g->Bw)
                 + r_rc(r_smid, g->r_b, ks, g->L_s));
    /* shaft -> its bore, plus the bore film when convective; a coolant
     * other than ambient is its own fixed node 7 */
    int sink = nw->n > 7 ? 7 : 0;
    if (sink) fix(b, sink, s->ambient_C + s->bore_bc.dT);
    add(b, 5, sink, r_rc(g->r_sb, r_smid, ks, g->L_s)
                    + r_face(s, &s->bore_bc, 2 * M_PI * g->r_sb * g->L_s));

    net_fluid f;
    net_edge cv[16];
    fluid_at(s, s->ambient_C, &f);
    nw->n_edge_cv = cv_edges7(g, s, &f, 0.0, 0.0, cv);
    for (int i = 0; i < nw->n_edge_cv; i++) nw->edge_cv[i] = add(b, cv[i].a, cv[i].b, cv[i].R);

    cap(b, 1, s->housing.rho * s->housing.cp * g->V_h);
    cap(b, 2, s->ring.rho * s->ring.cp * g->V_or);
    cap(b, 3, s->ball.rho * s->ball.cp * g->V_ball + s->cage.rho * s->cage.cp * g->V_cage);
    cap(b, 4, s->ring.rho * s->ring.cp * g->V_ir);
    cap(b, 5, s->shaft.rho * s->shaft.cp * g->V_shaft);
    cap(b, 6, f.rho_cp * g->V_cav);

    nw->names = names7;
    nw->node_ambient = 0;
    nw->node_housing = 1;
    nw->node_outer_ring = 2;
    nw->node_ball = 3;
    nw->node_cage = 3;
    nw->node_inner_ring = 4;
    nw->node_shaft = 5;
    nw->node_cavity = 6;
    /* race shares of the contact heat go to 4 / 2, the rest to 3 */
    nw->heat_inner = 4;
    nw->heat_outer = 2;
    nw->heat_spin = 3;
    nw->heat_drag = 6;
    set_avg(nw->avg_ball, &nw->n_avg_ball, (const int[]){3}, 1);
    set_avg(nw->avg_inner, &nw->n_avg_inner, (const int[]){4}, 1);
    set_avg(nw->avg_shaft, &nw->n_avg_shaft, (const int[]){5}, 1);
    set_avg(nw->avg_housing, &nw->n_avg_housing, (const int[]){1}, 1);
    set_avg(nw->avg_outer, &nw->n_avg_outer, (const int[]){2}, 1);
    nw->inlet_inner[0] = 4;
    nw->inlet_inner[1] = 3;
    nw->inlet_outer[0] = 2;
    nw->inlet_outer[1] = 3;
}

acbb_status acbb_network_build(const acbb_scene *s, acbb_network *out, acbb_error *err)
{
    if (!s || !out) return acbb_error_set(err, ACBB_EINVAL, "network: null argument");
    memset(out, 0, sizeof *out);
    if (s->network != ACBB_NET_46 && s->network != ACBB_NET_7)
        return acbb_error_set(err, ACBB_EINVAL, "network: unknown network kind %d",
                              (int)s->network);
    net_geom g;
    acbb_status st = check_scene(s, err);
    if (st == ACBB_OK) st = geom_from_scene(s, &g, err);
    if (st != ACBB_OK) return st;

    out->kind = s->network;
    out->n = s->network == ACBB_NET_46 ? 46 : 7 + (s->bore_bc.dT != 0.0);
    out->net = acbb_tnet_new(out->n);
    if (!out->net) return acbb_error_set(err, ACBB_ENOMEM, "network: out of memory");
    net_builder b = {out, ACBB_OK};
    if (s->network == ACBB_NET_46)
        build46(&b, s, &g);
    else
        build7(&b, s, &g);
    if (b.st != ACBB_OK) {
        acbb_network_free(out);
        return acbb_error_set(err, b.st, "network: a resistance or capacity came out "
                              "non-positive or non-finite (check the geometry)");
    }
    return ACBB_OK;
}

void acbb_network_free(acbb_network *nw)
{
    if (!nw) return;
    acbb_tnet_free(nw->net);
    nw->net = NULL;
}

static int inputs_ok(const acbb_net_inputs *in)
{
    const double v[] = {in->a_i, in->b_i, in->a_o, in->b_o,
                        in->v_race_i, in->v_ball_i, in->v_race_o, in->v_ball_o};
    for (int i = 0; i < 8; i++)
        if (!isfinite(v[i]) || v[i] < 0.0) return 0;
    return isfinite(in->omega_i) && isfinite(in->omega_m) && isfinite(in->T_cavity_C);
}

static double kappa_of(const acbb_material *m) { return m->k / (m->rho * m->cp); }

void acbb_network_spot_add(acbb_net_inputs *in, const acbb_scene *s, int inner, double a, double b,
                           double v_race, double v_ball)
{
    double gr = 1.0 / acbb_spot_r_moving(a, b, s->ring.k, kappa_of(&s->ring), v_race);
    double gb = 1.0 / acbb_spot_r_moving(a, b, s->ball.k, kappa_of(&s->ball), v_ball);
    if (!isfinite(gr) || !isfinite(gb)) return;
    if (inner) { in->g_race_i += gr; in->g_ball_i += gb; }
    else { in->g_race_o += gr; in->g_ball_o += gb; }
}

/* A summed spot conductance as a resistance, open when nothing conducts. */
static double r_of_sum(double g)
{
    return g > 0.0 ? fmin(1.0 / g, R_OPEN) : R_OPEN;
}

acbb_status acbb_network_update(acbb_network *nw, const acbb_scene *s,
                                const acbb_net_inputs *in)
{
    if (!nw || !nw->net || !s || !in || !inputs_ok(in)) return ACBB_EINVAL;
    net_geom g;
    acbb_status st = geom_from_scene(s, &g, NULL);
    if (st != ACBB_OK) return st;
    const double cmv = s->contact_multiplier;
    /* Only the balls in contact conduct through a spot (load zone). */
    int Zi = in->n_loaded_i > 0 ? in->n_loaded_i : g.Z;
    int Zo = in->n_loaded_o > 0 ? in->n_loaded_o : g.Z;
    double race_i = cmv * r_spot(s, in->a_i, in->b_i, &s->ring, in->v_race_i, Zi);
    double ball_i = r_spot(s, in->a_i, in->b_i, &s->ball, in->v_ball_i, Zi);
    double race_o = cmv * r_spot(s, in->a_o, in->b_o, &s->ring, in->v_race_o, Zo);
    double ball_o = r_spot(s, in->a_o, in->b_o, &s->ball, in->v_ball_o, Zo);
    if (s->contact_model == ACBB_CONTACT_MOVING && in->g_race_i + in->g_race_o > 0.0) {
        /* each loaded ball's own moving spot, in parallel (the sums) */
        race_i = cmv * r_of_sum(in->g_race_i);
        ball_i = r_of_sum(in->g_ball_i);
        race_o = cmv * r_of_sum(in->g_race_o);
        ball_o = r_of_sum(in->g_ball_o);
    }

    net_fluid f;
    net_edge cv[16];
    int n_cv;
    fluid_at(s, in->T_cavity_C, &f);
    if (nw->kind == ACBB_NET_46) {
        st = acbb_tnet_set_resistance(nw->net, nw->edge_sp_race_i, race_i);
        if (st == ACBB_OK) st = acbb_tnet_set_resistance(nw->net, nw->edge_sp_ball_i, ball_i);
        if (st == ACBB_OK) st = acbb_tnet_set_resistance(nw->net, nw->edge_sp_race_o, race_o);
        if (st == ACBB_OK) st = acbb_tnet_set_resistance(nw->net, nw->edge_sp_ball_o, ball_o);
        n_cv = cv_edges46(&g, s, &f, in->omega_i, in->omega_m, cv);
    } else {
        double bi = r_bi(&g, s);
        st = acbb_tnet_set_resistance(nw->net, nw->edge_sp_race_i, race_i + ball_i + bi);
        if (st == ACBB_OK)
            st = acbb_tnet_set_resistance(nw->net, nw->edge_sp_race_o, race_o + ball_o + bi);
        n_cv = cv_edges7(&g, s, &f, in->omega_i, in->omega_m, cv);
    }
    for (int i = 0; i < n_cv && st == ACBB_OK; i++)
        st = acbb_tnet_set_resistance(nw->net, nw->edge_cv[i], cv[i].R);
    return st;
}

void acbb_network_heat(const acbb_network *nw, const acbb_scene *s,
                       const acbb_heat_sources *h, double *q)
{
    for (int i = 0; i < nw->n; i++) q[i] = 0.0;
    if (nw->kind == ACBB_NET_46) {
        q[nw->heat_inner] += h->inner_contact;
        q[nw->heat_outer] += h->outer_contact;
        q[nw->heat_spin] += h->ball;
        q[nw->heat_drag] += h->cavity;
        q[nw->node_cage] += h->cage;
        return;
    }
    /* MODEL.md 8.3: race share phi_p of each contact to its ring, the rest
     * and the spin loss to the ball node */
    double phi = s->heat_partition;
    q[nw->heat_outer] += phi * h->outer_contact;
    q[nw->heat_inner] += phi * h->inner_contact;
    q[nw->heat_spin] += (1.0 - phi) * (h->inner_contact + h->outer_contact) + h->ball;
    q[nw->heat_drag] += h->cavity;
    q[nw->node_cage] += h->cage;
}

static double mean_of(const double *T, const int *idx, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; i++) s += T[idx[i]];
    return n > 0 ? s / n : NAN;
}

void acbb_network_part_temps(const acbb_network *nw, const double *T,
                             acbb_part_temps *out)
{
    out->ball = mean_of(T, nw->avg_ball, nw->n_avg_ball);
    out->inner_ring = mean_of(T, nw->avg_inner, nw->n_avg_inner);
    out->shaft = mean_of(T, nw->avg_shaft, nw->n_avg_shaft);
    out->housing = mean_of(T, nw->avg_housing, nw->n_avg_housing);
    out->outer_ring = mean_of(T, nw->avg_outer, nw->n_avg_outer);
}

void acbb_network_inlet_temps(const acbb_network *nw, const double *T,
                              double *T_in_inner, double *T_in_outer)
{
    *T_in_inner = mean_of(T, nw->inlet_inner, 2);
    *T_in_outer = mean_of(T, nw->inlet_outer, 2);
}
