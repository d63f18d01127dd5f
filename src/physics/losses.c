/* acbb — power losses per contact, MODEL.md section 6 (seed eqs 14-18,
 * cleaned). The integrals run over the contact ellipse mapped to the unit
 * square: x'' = a xi, y'' = b sqrt(1-xi^2) t, dA = ab sqrt(1-xi^2) dxi dt,
 * p = pmax sqrt(1-xi^2) sqrt(1-t^2). */
#include <math.h>
#include <gsl/gsl_integration.h>
#include "losses.h"
#include "traction.h"
#include "ehl_rolling.h"
#include "churning.h"

acbb_status acbb_quad_init(acbb_quad *q, int n)
{
    if (n < 1 || n > ACBB_QUAD_MAX)
        return ACBB_EINVAL;
    gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc((size_t)n);
    if (!t)
        return ACBB_ENOMEM;
    q->n = n;
    for (int i = 0; i < n; i++)
        gsl_integration_glfixed_point(-1.0, 1.0, (size_t)i, &q->x[i], &q->w[i], t);
    gsl_integration_glfixed_table_free(t);
    return ACBB_OK;
}

/* Height of the deformed contact surface above the ball centre at x''
 * (MODEL.md section 4): the pressure surface has radius R_d = 2fD/(2f+1). */
static double surface_height(const acbb_contact_in *c, double x)
{
    double Rd = 2.0 * c->f * c->D / (2.0 * c->f + 1.0);
    double a2 = c->a * c->a;
    return sqrt(acbb_nonneg(Rd * Rd - x * x)) - sqrt(acbb_nonneg(Rd * Rd - a2))
         + sqrt(acbb_nonneg(0.25 * c->D * c->D - a2));
}

/* V = s h w_roll + w_race (r_m + s h cos(alpha)), s = +1 outer, -1 inner:
 * ball surface speed minus race surface speed in the rolling direction,
 * at surface height h, ca = cos(alpha). */
static double slip_velocity_at(const acbb_contact_in *c, double h, double ca)
{
    double sg = c->inner ? -1.0 : 1.0;
    return sg * h * c->roll + c->race * (0.5 * c->dm + sg * h * ca);
}

double acbb_slip_velocity(const acbb_contact_in *c, double x)
{
    return slip_velocity_at(c, surface_height(c, x), cos(c->alpha));
}

/* acbb_slip_speed with cos(alpha) given (once per contact, not per row)
 * and the surface height computed once for both terms: the same bits. */
static double slip_speed_ca(const acbb_contact_in *c, double x, double ca)
{
    double h = surface_height(c, x), V = slip_velocity_at(c, h, ca);
    if (c->pivot == 0.0) return fabs(V);
    return hypot(V, c->pivot * h);
}

double acbb_slip_speed(const acbb_contact_in *c, double x)
{
    return slip_speed_ca(c, x, cos(c->alpha));
}

/* ---- the formulas (MODEL.md section 6, clean form unless seed) ---- */

static double shear_point(const acbb_loss_point *q)
{
    return q->seed ? q->tauV : q->film->phi_f * q->tauV * q->V;
}

/* Seed eq (14) multiplies a force by omega_m D; kept only as an option. */
static double shear_finish(const acbb_contact_in *c, int seed, double sum)
{
    return seed ? sum * fabs(c->omega_m) * c->D : sum;
}

static double slip_point(const acbb_loss_point *q)
{
    const acbb_film *fl = q->film;
    double mu = q->s->mu_bd;
    return q->seed ? (fl->phi_a * mu * q->p + fl->phi_f * q->tauV) * q->V
                   : fl->phi_a * mu * q->p * q->V;
}

/* acbb_tau_lubricant at this point for a slip speed du >= 0: the Eyring
 * branch inline (acbb_eyring_capped, the same operations and bits). */
static double point_tau_lub(const acbb_loss_point *q, double du)
{
    if (q->eyring) return acbb_eyring_capped(q->s->tau_eyring, q->eta, du, q->H, q->tlim);
    return acbb_tau_lubricant(q->s, q->eta, du, q->film->hc, q->p);
}

static double spin_point(const acbb_loss_point *q)
{
    const acbb_film *fl = q->film;
    double r = hypot(q->x, q->y);
    double us = fabs(q->c->spin) * r;
    double tauS = fl->phi_f > 0.0 ? point_tau_lub(q, us) : 0.0;
    return (fl->phi_a * q->s->mu_bd * q->p + fl->phi_f * tauS) * r;
}

/* spin_point at node (i, k), or its mirror node's value when that node
 * (filled earlier) has the same |x|, |y| and pressure: the same bits. */
static double spin_mirror(const acbb_loss_point *pt, const acbb_quad *q, const double *P,
                          const double *spin, int i, int k)
{
    int n = q->n, node = i * n + k, mi = (n - 1 - i) * n + k, mk = i * n + (n - 1 - k);
    if (mi < node && P[mi] == P[node] && q->x[n - 1 - i] == -q->x[i]) return spin[mi];
    if (mk < node && P[mk] == P[node] && q->x[n - 1 - k] == -q->x[k]) return spin[mk];
    return spin_point(pt);
}

/* The lubricant stress at the row's slip speed at node (i, k), or that of
 * its mirror node across the row (filled earlier) when the pressure bits
 * agree: the same row's slip speed, pressure and viscosity, so the same
 * bits (half the Eyring asinh of the quadrature, issue 30); likewise the
 * mirror node of the mirror row when its slip speed V has the same bits
 * (a row's slip speed depends on x through x^2: a quarter in all). */
static double tauV_mirror(const acbb_loss_point *pt, const double *P, const double *tauV,
                          const double *V, int n, int i, int k)
{
    int node = i * n + k, mk = i * n + (n - 1 - k), mi = (n - 1 - i) * n + k;
    if (mk < node && P[mk] == P[node]) return tauV[mk];
    if (mi < node && P[mi] == P[node] && V[n - 1 - i] == V[i]) return tauV[mi];
    return point_tau_lub(pt, pt->V);
}


static double spin_finish(const acbb_contact_in *c, int seed, double sum)
{
    (void)seed;
    return fabs(c->spin) * sum;
}

/* Rolling resistance by elastic hysteresis of a sphere rolling in a groove
 * (rolling_hysteresis = johnson): K. L. Johnson, Contact Mechanics, 1985,
 * ch. 9 (rolling resistance, elastic hysteresis): a sphere's resistance
 * moment is (3/16) alpha W b, b the contact semi-axis in the rolling
 * direction, so its force is F = (3/16) alpha W b / R with R the rolling
 * radius, here R_x of the contact (MODEL.md 2); alpha is the hysteresis
 * loss factor, the scene's eps (MODEL.md 6, UNSURE 0.005-0.01). Johnson
 * derives it for alpha << 1 (a small loss per cycle), which bearing steel
 * (eps ~ 0.007) is. The force times the entrainment speed u is the power. */
static double johnson_rolling(const acbb_contact_form *f)
{
    const acbb_contact_in *c = f->c;
    return 3.0 / 16.0 * f->s->hysteresis * c->Q * c->b / c->Rx * f->u;
}

/* The seed's Eq. 18 (MODEL.md 6): 4 eps Q a_c / (3 pi D) times u, a_c the
 * ellipse's long axis (hysteresis_axis = major, the seed's) or its short
 * one; or Johnson's sphere in the rolling direction (above). */
static double rolling_contact(const acbb_contact_form *f)
{
    const acbb_scene *s = f->s;
    const acbb_contact_in *c = f->c;
    double u = f->u;
    if (s->roll_hyst == ACBB_ROLL_HYST_JOHNSON) return johnson_rolling(f);
    double ac = s->hyst_axis == ACBB_HYST_MINOR ? c->b : c->a;
    if (s->loss_form == ACBB_LOSS_SEED) {
        double arm = c->dm + (c->inner ? -2.0 : 2.0) * c->delta;
        return 2.0 * s->hysteresis * c->Q * ac * arm / (3.0 * M_PI * c->D) * fabs(c->omega_m);
    }
    return 4.0 * s->hysteresis * c->Q * ac / (3.0 * M_PI * c->D) * u;
}

/* EHL rolling resistance (ehl_rolling.c, MODEL.md 16): the isothermal
 * force with the film's inlet-heating factor and the method's starvation
 * factor, times the entrainment speed. No film, no force. */
static double ehl_rolling_contact(const acbb_contact_form *f)
{
    const acbb_contact_in *c = f->c;
    if (!(f->film->hc > 0.0)) return 0.0;
    double E = c->E_eff;
    double U = f->oil->eta0 * f->u / (E * c->Rx);
    double G = f->s->oil_alpha_pv * E;
    double W = c->Q / (E * c->Rx * c->Rx);
    double F = acbb_ehl_rolling_force(E, c->Rx, c->kappa, U, G, W) * f->film->phi_T
             * acbb_starvation_factor(f->s, f->oil->nu * 1e6);
    return F * f->u;
}

/* The air (oil-air) drag acts on the balls outside an oil bath. */
static double drag_bearing(const acbb_bearing_in *in)
{
    double P = acbb_drag_loss(in->s, in->mix, in->omega_m);
    return in->s->lub_method == ACBB_LUB_OIL_BATH ? P * (1.0 - acbb_bath_immersion(in->s)) : P;
}

static double churning_bearing(const acbb_bearing_in *in)
{
    return in->oil ? acbb_churning_loss(in->s, in->oil, in->omega_m) : 0.0;
}

static double cage_bearing(const acbb_bearing_in *in)
{
    return acbb_cage_loss(in->s, in->mix, in->omega_m);
}

#define FLAG(f) offsetof(acbb_scene, f)
const acbb_loss_desc acbb_loss_table[ACBB_LOSS_KINDS] = {
    [ACBB_LOSS_SHEAR] = { "shear", "P_L", "lubricant shear", "loss_shear", FLAG(loss_shear),
                          ACBB_HEAT_CONTACT, .point = shear_point, .finish = shear_finish },
    [ACBB_LOSS_SLIP] = { "slip", "P_t", "differential slip", "loss_slip", FLAG(loss_slip),
                         ACBB_HEAT_CONTACT, .point = slip_point },
    [ACBB_LOSS_SPIN] = { "spin", "P_s", "spinning", "loss_spin", FLAG(loss_spin),
                         ACBB_HEAT_BALL, .point = spin_point, .finish = spin_finish },
    [ACBB_LOSS_ROLLING] = { "rolling", "P_r", "rolling hysteresis", "loss_rolling",
                            FLAG(loss_rolling), ACBB_HEAT_CONTACT, .contact = rolling_contact },
    [ACBB_LOSS_DRAG] = { "drag", "P_v", "oil-air drag", "loss_drag", FLAG(loss_drag),
                         ACBB_HEAT_CAVITY, .bearing = drag_bearing },
    [ACBB_LOSS_CAGE] = { "cage", "P_c", "cage-land shear", "loss_cage", FLAG(loss_cage),
                         ACBB_HEAT_CAGE, .bearing = cage_bearing },
    [ACBB_LOSS_EHL_ROLLING] = { "ehl_rolling", "P_e", "EHL rolling resistance", "loss_ehl_rolling",
                                FLAG(loss_ehl_rolling), ACBB_HEAT_CONTACT,
                                .contact = ehl_rolling_contact },
    [ACBB_LOSS_CHURNING] = { "churning", "P_ch", "oil churning / jet", "loss_churning",
                             FLAG(loss_churning), ACBB_HEAT_CAVITY, .bearing = churning_bearing },
};
#undef FLAG

const char *acbb_loss_name(acbb_loss_kind k) { return acbb_loss_table[k].name; }
const char *acbb_loss_symbol(acbb_loss_kind k) { return acbb_loss_table[k].symbol; }
const char *acbb_loss_label(acbb_loss_kind k) { return acbb_loss_table[k].label; }

const char *acbb_loss_set(const acbb_scene *s)
{
    return s->loss_ehl_rolling || s->loss_churning ? "extended" : "seed";
}

int acbb_loss_enabled(const acbb_scene *s, acbb_loss_kind k)
{
    return *(const bool *)((const char *)s + acbb_loss_table[k].flag);
}

/* The integrand losses share one pass over the ellipse (pressure, slip and
 * viscosity are computed once per point). */
static void integrate(const acbb_scene *s, const acbb_quad *q, const acbb_contact_in *c,
                      const acbb_oil_state *oil, acbb_contact_loss *out, const int *on)
{
    const acbb_film *fl = &out->film;
    int fluid = fl->phi_f > 0.0;
    double ab = c->a * c->b, sum[ACBB_LOSS_KINDS] = { 0 }, sumPV = 0, sumP = 0;
    acbb_loss_point pt = { .s = s, .c = c, .film = fl, .oil = oil,
                           .seed = s->loss_form == ACBB_LOSS_SEED };
    /* The pressure-viscosity law's per-oil part once per contact
     * (acbb_viscosity_at_pressure is init + eval: the same bits). */
    acbb_visc_law visc;
    acbb_visc_law_init(s, oil, &visc);
    pt.eyring = s->traction != ACBB_TRACTION_BAIR_WINER && s->tau_eyring > 0.0;
    pt.H = fmax(fl->hc, 1e-9);
    /* Per node (row-major): pressure, viscosity, and the spin integrand,
     * which depends on the node through |x|, |y| and p alone, so a mirror
     * node of the same bits shares it (issue 30). */
    double P[ACBB_QUAD_MAX * ACBB_QUAD_MAX], eta[ACBB_QUAD_MAX * ACBB_QUAD_MAX];
    double spin[ACBB_QUAD_MAX * ACBB_QUAD_MAX], tauV[ACBB_QUAD_MAX * ACBB_QUAD_MAX];
    double sh[ACBB_QUAD_MAX * ACBB_QUAD_MAX], sl[ACBB_QUAD_MAX * ACBB_QUAD_MAX];
    /* The shear, slip and spin integrands are called directly (inlined,
     * no call through the table per node); any other kind with an
     * integrand goes through the table. Each kind's sum runs over the
     * nodes in the same order as before: the same bits. */
    int n = q->n, other[ACBB_LOSS_KINDS], n_other = 0;
    int shear = on[ACBB_LOSS_SHEAR], slip = on[ACBB_LOSS_SLIP], spins = on[ACBB_LOSS_SPIN];
    for (int l = 0; l < ACBB_LOSS_KINDS; l++)
        if (on[l] && l != ACBB_LOSS_SHEAR && l != ACBB_LOSS_SLIP && l != ACBB_LOSS_SPIN)
            other[n_other++] = l;
    double Vrow[ACBB_QUAD_MAX], ca = cos(c->alpha), st[ACBB_QUAD_MAX];
    int colmir[ACBB_QUAD_MAX]; /* column k mirrors an earlier one at -y */
    for (int k = 0; k < n; k++) {
        st[k] = sqrt(1.0 - q->x[k] * q->x[k]);
        colmir[k] = n - 1 - k < k && q->x[n - 1 - k] == -q->x[k] && !n_other;
    }
    for (int i = 0; i < n; i++) {
        double xi = q->x[i], sq = sqrt(1.0 - xi * xi);
        pt.x = c->a * xi;
        /* The mirror row at -x (filled earlier) has the same slip speed:
         * it depends on x through x^2 alone (acbb_slip_velocity). */
        int mr = n - 1 - i, mirror = mr < i && q->x[mr] == -xi && !n_other;
        pt.V = Vrow[i] = mr < i && q->x[mr] == -xi ? Vrow[mr] : slip_speed_ca(c, pt.x, ca);
        for (int k = 0; k < n; k++) {
            double t = q->x[k];
            double w = q->w[i] * q->w[k] * ab * sq;   /* dA */
            int node = i * n + k, mi = mr * n + k;
            pt.p = P[node] = c->pmax * sq * st[k];
            /* A node of the mirror row at -x with the same pressure bits (the
             * same sq and column): its slip speed, viscosity, stresses and so
             * every integrand are its mirror node's; only the weight is its
             * own (issue 30: half the nodes without the per-node work). */
            /* Likewise a node of the mirror column at -y in the same row
             * (the same row's slip speed and |y|). */
            int src = mirror && P[mi] == pt.p ? mi
                    : colmir[k] && P[node + n - 1 - 2 * k] == pt.p ? node + n - 1 - 2 * k : -1;
            if (src >= 0) {
                eta[node] = eta[src];
                tauV[node] = tauV[src];
                sumP += pt.p * w;
                sumPV += pt.p * pt.V * w;
                if (shear) sum[ACBB_LOSS_SHEAR] += (sh[node] = sh[src]) * w;
                if (slip) sum[ACBB_LOSS_SLIP] += (sl[node] = sl[src]) * w;
                if (spins) sum[ACBB_LOSS_SPIN] += (spin[node] = spin[src]) * w;
                continue;
            }
            pt.y = c->b * sq * t;
            pt.eta = eta[node] = fluid ? acbb_visc_law_eval_mirror(&visc, P, eta, n, i, k) : 0.0;
            pt.tlim = s->lambda_lim * acbb_nonneg(pt.p);
            pt.tauV = tauV[node] = fluid ? tauV_mirror(&pt, P, tauV, Vrow, n, i, k) : 0.0;
            sumP += pt.p * w;
            sumPV += pt.p * pt.V * w;
            if (shear) sum[ACBB_LOSS_SHEAR] += (sh[node] = shear_point(&pt)) * w;
            if (slip) sum[ACBB_LOSS_SLIP] += (sl[node] = slip_point(&pt)) * w;
            if (spins) sum[ACBB_LOSS_SPIN] += (spin[node] = spin_mirror(&pt, q, P, spin, i, k)) * w;
            for (int a = 0; a < n_other; a++)
                sum[other[a]] += acbb_loss_table[other[a]].point(&pt) * w;
        }
    }
    out->slide = sumP > 0.0 ? sumPV / sumP : 0.0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        const acbb_loss_desc *d = &acbb_loss_table[l];
        if (on[l]) out->P[l] = d->finish ? d->finish(c, pt.seed, sum[l]) : sum[l];
    }
}

/* The pressure-weighted mean slip alone (kinematics, no loss integrand):
 * what a scene with every contact loss switched off still reports. */
static double mean_slide(const acbb_quad *q, const acbb_contact_in *c)
{
    double sumP = 0.0, sumPV = 0.0;
    for (int i = 0; i < q->n; i++) {
        double xi = q->x[i], sq = sqrt(1.0 - xi * xi);
        double V = acbb_slip_speed(c, c->a * xi);
        for (int k = 0; k < q->n; k++) {
            double t = q->x[k];
            double pw = q->w[i] * q->w[k] * sq * sq * sqrt(1.0 - t * t);
            sumP += pw;
            sumPV += pw * V;
        }
    }
    return sumP > 0.0 ? sumPV / sumP : 0.0;
}

acbb_status acbb_contact_losses(const acbb_scene *s, const acbb_quad *q,
                                const acbb_contact_in *c, const acbb_oil_state *oil,
                                acbb_contact_loss *out)
{
    *out = (acbb_contact_loss){ 0 };
    if (c->Q <= 1e-6 || c->a <= 0.0 || c->b <= 0.0) {
        out->film.phi_a = 1.0;
        out->film.phi_T = 1.0;
        return ACBB_OK;
    }
    double u = fabs(c->u);
    double V0 = acbb_slip_speed(c, 0.0);
    double srr = u > 1e-6 ? fmin(fabs(V0) / u, 2.0) : 0.0;
    acbb_film_compute(s, oil, u, c->Q, c->Rx, c->kappa, c->E_eff, c->pmax, srr, &out->film);
    int on[ACBB_LOSS_KINDS] = { 0 };
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        const acbb_loss_desc *d = &acbb_loss_table[l];
        on[l] = d->point && acbb_loss_enabled(s, (acbb_loss_kind)l);
    }
    int any = 0;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) any |= on[l];
    if (any) integrate(s, q, c, oil, out, on);
    else out->slide = mean_slide(q, c);
    out->integrated = any;
    for (int l = 0; l < ACBB_LOSS_KINDS; l++) {
        const acbb_loss_desc *d = &acbb_loss_table[l];
        if (d->contact && acbb_loss_enabled(s, (acbb_loss_kind)l))
            out->P[l] = d->contact(&(acbb_contact_form){ s, c, oil, &out->film, u });
        if (!isfinite(out->P[l])) return ACBB_NONFINITE;
    }
    return ACBB_OK;
}

double acbb_drag_force(const acbb_scene *s, const acbb_mixture *mix, double omega_m)
{
    double v = omega_m * s->pitch_diameter;
    return M_PI / 32.0 * s->drag_cd * mix->rho * s->ball_diameter * s->ball_diameter * v * v;
}

double acbb_drag_loss(const acbb_scene *s, const acbb_mixture *mix, double omega_m)
{
    return s->n_balls * fabs(omega_m) * acbb_drag_force(s, mix, omega_m)
         * 0.5 * s->pitch_diameter;
}

double acbb_cage_loss(const acbb_scene *s, const acbb_mixture *mix, double omega_m)
{
    double rc = 0.5 * s->cage_diameter;
    double gap = 0.5 * (s->outer_land_diameter - s->cage_diameter);
    return 2.0 * M_PI * mix->eta * rc * rc * rc * s->cage_width * omega_m * omega_m / gap;
}
