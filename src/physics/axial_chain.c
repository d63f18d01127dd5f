/* acbb — cells of a stepped cylinder along the axis in a thermal network
 * (finite volumes; docs/spindle.md "Heat"). */
#include <math.h>
#include <stdlib.h>
#include "axial_chain.h"

acbb_status acbb_axial_chain_make(const acbb_shaft_seg *s, int n_seg, double x_start,
                                  int n_div, int first, acbb_axial_chain *c, acbb_error *err)
{
    c->n = 0;
    c->x0 = c->x1 = NULL;
    c->seg = NULL;
    if (n_div < 1 || n_div > 1000)
        return acbb_error_set(err, ACBB_EINVAL,
                              "thermal cells per segment = %d (must be in [1, 1000])", n_div);
    size_t n = (size_t)n_seg * (size_t)n_div;
    c->x0 = malloc(n * sizeof *c->x0);
    c->x1 = malloc(n * sizeof *c->x1);
    c->seg = malloc(n * sizeof *c->seg);
    if (!c->x0 || !c->x1 || !c->seg) {
        acbb_axial_chain_free(c);
        return acbb_error_set(err, ACBB_ENOMEM, "axial chain: out of memory");
    }
    double x = x_start;
    for (int k = 0; k < n_seg; k++) {
        for (int j = 0; j < n_div; j++) {
            c->x0[c->n] = x + s[k].L * j / n_div;
            c->x1[c->n] = x + s[k].L * (j + 1) / n_div;
            c->seg[c->n++] = &s[k];
        }
        x += s[k].L;
    }
    c->first = first;
    return ACBB_OK;
}

void acbb_axial_chain_free(acbb_axial_chain *c)
{
    free(c->x0);
    free(c->x1);
    free((void *)c->seg);
    c->x0 = c->x1 = NULL;
    c->seg = NULL;
    c->n = 0;
}

static double half_R(const acbb_axial_chain *c, int i)
{
    return 0.5 * (c->x1[i] - c->x0[i]) / (c->seg[i]->k * acbb_seg_area(c->seg[i]));
}

acbb_status acbb_axial_chain_add(acbb_tnet *net, const acbb_axial_chain *c)
{
    for (int i = 0; i < c->n; i++) {
        const acbb_shaft_seg *s = c->seg[i];
        double C = s->rho * s->c * acbb_seg_area(s) * (c->x1[i] - c->x0[i]);
        acbb_status st = acbb_tnet_set_capacity(net, c->first + i, C);
        if (st != ACBB_OK) return st;
        if (i + 1 < c->n) {
            int e = acbb_tnet_add_edge(net, c->first + i, c->first + i + 1,
                                       half_R(c, i) + half_R(c, i + 1));
            if (e < 0) return (acbb_status)e;
        }
    }
    return ACBB_OK;
}

double acbb_axial_chain_end_resistance(const acbb_axial_chain *c, int end)
{
    return half_R(c, end ? c->n - 1 : 0);
}

acbb_status acbb_axial_chain_convect(acbb_tnet *net, const acbb_axial_chain *c, double h,
                                     int to)
{
    if (!(h > 0.0)) return ACBB_OK;
    for (int i = 0; i < c->n; i++) {
        double A = M_PI * c->seg[i]->d_out * (c->x1[i] - c->x0[i]);
        int e = acbb_tnet_add_edge(net, c->first + i, to, 1.0 / (h * A));
        if (e < 0) return (acbb_status)e;
    }
    return ACBB_OK;
}

int acbb_axial_chain_cell_at(const acbb_axial_chain *c, double x)
{
    for (int i = 0; i < c->n; i++)
        if (x >= c->x0[i] && (x < c->x1[i] || (i == c->n - 1 && x <= c->x1[i]))) return i;
    return -1;
}

double acbb_overlap(double a0, double a1, double b0, double b1)
{
    double lo = fmax(a0, b0), hi = fmin(a1, b1);
    return hi > lo ? hi - lo : 0.0;
}

double acbb_axial_chain_growth(const acbb_axial_chain *c, const double *T, double T_ref,
                               double xa, double xb)
{
    double g = 0.0;
    for (int i = 0; i < c->n; i++)
        g += c->seg[i]->alpha * (T[c->first + i] - T_ref) *
             acbb_overlap(c->x0[i], c->x1[i], xa, xb);
    return g;
}
