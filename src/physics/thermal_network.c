/* acbb — general lumped thermal network, backward Euler and steady solves
 * (MODEL.md section 8.2).
 *
 * Unknowns are the free (non-Dirichlet) nodes only; fixed nodes enter the
 * right-hand side through G_D T_D. Two Cholesky factorisations are cached: one of
 * (C/dt + G) for the transient step and one of G for the steady solve, each
 * with its own dirty flag, so alternating step/steady calls never force a
 * refactorisation. The matrices are dense (40-ish unknowns) symmetric
 * M-matrices, positive definite once every component touches a fixed node
 * or carries capacity (checked on the graph first). Their rows are sparse
 * (a node has a few neighbours): an envelope Cholesky (skyline.h) skips
 * the zeros left of each row's first coupling, 4x fewer instructions than
 * GSL's dense one on the 46-node network (issue 30 lever 3). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>
#include "thermal_network.h"
#include "skyline.h"

/* One cached factorisation (transient or steady). The n x n buffer is
 * allocated once in acbb_tnet_new and used through an nf x nf view. */
typedef struct {
    gsl_matrix *lu;          /* n x n storage, top-left nf x nf in use (Cholesky factor) */
    int *first;              /* n-long: each factor row's envelope start (skyline.h) */
    int dirty;               /* matrix inputs changed since factorisation */
    int valid;               /* a successful factorisation is stored */
    double dt;               /* transient only: dt of the stored factors */
    long conn_topo;          /* the net's topo when components_ok last held (0: never) */
} tn_factor;

struct acbb_tnet {
    int n;
    double *C;               /* capacities, J/K */
    int *fixed;              /* 1 if Dirichlet */
    double *Tfix;            /* Dirichlet values, C */
    int *fidx;               /* node -> free index, or -1 */
    int nf;                  /* number of free nodes */
    int map_dirty;           /* fidx/nf need recomputing */
    long topo;               /* bumped when components_ok's answer may change (fixed
                              * nodes, capacities, edges): most factorisations follow
                              * a new resistance only (issue 30) */

    int n_edges, cap_edges;
    int *ea, *eb;
    double *R;

    tn_factor tr, st;
    gsl_vector *rhs, *x;     /* n-long work vectors */
    int *parent, *good;      /* (n+1)-long work arrays for connectivity */
    long n_fact;
};

static int node_ok(const acbb_tnet *net, int node)
{
    return net && node >= 0 && node < net->n;
}

static void mark_dirty(acbb_tnet *net, int transient, int steady)
{
    if (transient) net->tr.dirty = 1;
    if (steady) net->st.dirty = 1;
}

acbb_tnet *acbb_tnet_new(int n_nodes)
{
    if (n_nodes <= 0) return NULL;
    acbb_tnet *net = calloc(1, sizeof *net);
    if (!net) return NULL;
    size_t n = (size_t)n_nodes;
    net->n = n_nodes;
    net->C = calloc(n, sizeof *net->C);
    net->fixed = calloc(n, sizeof *net->fixed);
    net->Tfix = calloc(n, sizeof *net->Tfix);
    net->fidx = calloc(n, sizeof *net->fidx);
    net->parent = calloc(n + 1, sizeof *net->parent);
    net->good = calloc(n + 1, sizeof *net->good);
    net->tr.lu = gsl_matrix_alloc(n, n);
    net->st.lu = gsl_matrix_alloc(n, n);
    net->tr.first = calloc(n, sizeof *net->tr.first);
    net->st.first = calloc(n, sizeof *net->st.first);
    net->rhs = gsl_vector_alloc(n);
    net->x = gsl_vector_alloc(n);
    if (!net->C || !net->fixed || !net->Tfix || !net->fidx || !net->parent || !net->good ||
        !net->tr.lu || !net->st.lu || !net->tr.first || !net->st.first || !net->rhs || !net->x) {
        acbb_tnet_free(net);
        return NULL;
    }
    net->map_dirty = 1;
    net->topo = 1;
    net->tr.dirty = net->st.dirty = 1;
    return net;
}

void acbb_tnet_free(acbb_tnet *net)
{
    if (!net) return;
    free(net->C);
    free(net->fixed);
    free(net->Tfix);
    free(net->fidx);
    free(net->parent);
    free(net->good);
    free(net->ea);
    free(net->eb);
    free(net->R);
    if (net->tr.lu) gsl_matrix_free(net->tr.lu);
    if (net->st.lu) gsl_matrix_free(net->st.lu);
    free(net->tr.first);
    free(net->st.first);
    if (net->rhs) gsl_vector_free(net->rhs);
    if (net->x) gsl_vector_free(net->x);
    free(net);
}

int acbb_tnet_node_count(const acbb_tnet *net) { return net ? net->n : 0; }
int acbb_tnet_edge_count(const acbb_tnet *net) { return net ? net->n_edges : 0; }

acbb_status acbb_tnet_set_capacity(acbb_tnet *net, int node, double C)
{
    if (!node_ok(net, node) || !isfinite(C) || C < 0.0) return ACBB_EINVAL;
    if (net->C[node] != C) {
        net->C[node] = C;
        net->topo++;
        mark_dirty(net, 1, 0);   /* the steady matrix G does not use C */
    }
    return ACBB_OK;
}

double acbb_tnet_capacity(const acbb_tnet *net, int node)
{
    return node_ok(net, node) ? net->C[node] : NAN;
}

acbb_status acbb_tnet_set_fixed(acbb_tnet *net, int node, double T)
{
    if (!node_ok(net, node) || !isfinite(T)) return ACBB_EINVAL;
    net->Tfix[node] = T;         /* a new value only changes the RHS */
    if (!net->fixed[node]) {
        net->fixed[node] = 1;
        net->map_dirty = 1;
        net->topo++;
        mark_dirty(net, 1, 1);
    }
    return ACBB_OK;
}

int acbb_tnet_is_fixed(const acbb_tnet *net, int node)
{
    return node_ok(net, node) ? net->fixed[node] : 0;
}

int acbb_tnet_add_edge(acbb_tnet *net, int a, int b, double R)
{
    if (!node_ok(net, a) || !node_ok(net, b) || a == b || !isfinite(R) || R <= 0.0)
        return ACBB_EINVAL;
    if (net->n_edges == net->cap_edges) {
        int cap = net->cap_edges ? 2 * net->cap_edges : 64;
        int *ea = realloc(net->ea, (size_t)cap * sizeof *ea);
        if (ea) net->ea = ea;
        int *eb = realloc(net->eb, (size_t)cap * sizeof *eb);
        if (eb) net->eb = eb;
        double *Rv = realloc(net->R, (size_t)cap * sizeof *Rv);
        if (Rv) net->R = Rv;
        if (!ea || !eb || !Rv) return ACBB_ENOMEM;
        net->cap_edges = cap;
    }
    int e = net->n_edges++;
    net->topo++;
    net->ea[e] = a;
    net->eb[e] = b;
    net->R[e] = R;
    mark_dirty(net, 1, 1);
    return e;
}

acbb_status acbb_tnet_set_resistance(acbb_tnet *net, int edge, double R)
{
    if (!net || edge < 0 || edge >= net->n_edges || !isfinite(R) || R <= 0.0)
        return ACBB_EINVAL;
    if (net->R[edge] != R) {
        net->R[edge] = R;
        mark_dirty(net, 1, 1);
    }
    return ACBB_OK;
}

double acbb_tnet_resistance(const acbb_tnet *net, int edge)
{
    if (!net || edge < 0 || edge >= net->n_edges) return NAN;
    return net->R[edge];
}

acbb_status acbb_tnet_edge_nodes(const acbb_tnet *net, int edge, int *a, int *b)
{
    if (!net || edge < 0 || edge >= net->n_edges || !a || !b) return ACBB_EINVAL;
    *a = net->ea[edge];
    *b = net->eb[edge];
    return ACBB_OK;
}

long acbb_tnet_factorisations(const acbb_tnet *net) { return net ? net->n_fact : 0; }

/* Free-node numbering (recomputed only after a node became fixed). */
static void update_map(acbb_tnet *net)
{
    if (!net->map_dirty) return;
    int k = 0;
    for (int i = 0; i < net->n; i++)
        net->fidx[i] = net->fixed[i] ? -1 : k++;
    net->nf = k;
    net->map_dirty = 0;
}

static int find_root(int *parent, int i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return parent[i];
}

/* A component of free nodes joined by edges is solvable when it touches a
 * fixed node (G is then an irreducibly diagonally dominant M-matrix) or, for
 * the transient matrix, when it holds some capacity (C/dt > 0 on the
 * diagonal). Checked on the graph rather than inferred from a tiny LU pivot,
 * which would depend on scaling. Union-find over the free nodes; fixed nodes
 * all map to one "ground" root n. */
static int components_ok(acbb_tnet *net, int need_fixed_only)
{
    int n = net->n;
    int *parent = net->parent, *good = net->good;
    for (int i = 0; i <= n; i++) {
        parent[i] = i;
        good[i] = 0;
    }
    for (int e = 0; e < net->n_edges; e++) {
        int a = net->fixed[net->ea[e]] ? n : net->ea[e];
        int b = net->fixed[net->eb[e]] ? n : net->eb[e];
        int ra = find_root(parent, a), rb = find_root(parent, b);
        if (ra != rb) parent[ra] = rb;
    }
    good[find_root(parent, n)] = 1;
    if (!need_fixed_only)
        for (int i = 0; i < n; i++)
            if (!net->fixed[i] && net->C[i] > 0.0) good[find_root(parent, i)] = 1;
    for (int i = 0; i < n; i++)
        if (!net->fixed[i] && !good[find_root(parent, i)]) return 0;
    return 1;
}

/* Assemble diag(C inv_dt) + G over the free nodes into f->lu and factorise.
 * inv_dt = 1/dt for the transient matrix, 0 for the steady one. */
static acbb_status factorise(acbb_tnet *net, tn_factor *f, double inv_dt)
{
    int nf = net->nf;
    f->valid = 0;
    if (nf == 0) {
        f->dirty = 0;
        f->valid = 1;
        return ACBB_OK;
    }
    if (f->conn_topo != net->topo) {
        if (!components_ok(net, inv_dt == 0.0)) return ACBB_SINGULAR;
        f->conn_topo = net->topo;
    }
    gsl_matrix_view A = gsl_matrix_submatrix(f->lu, 0, 0, (size_t)nf, (size_t)nf);
    double *a = A.matrix.data;
    size_t lda = A.matrix.tda;
    /* Only the lower triangle from each row's first coupling is assembled
     * (the factor reads nothing else, skyline.h): the same sums, in the
     * same order, as the whole matrix's (issue 30). */
    int *first = f->first;
    for (int i = 0; i < nf; i++) first[i] = i;
    for (int e = 0; e < net->n_edges; e++) {
        int ia = net->fidx[net->ea[e]], ib = net->fidx[net->eb[e]];
        if (ia >= 0 && ib >= 0) {
            int hi = ia > ib ? ia : ib, lo = ia + ib - hi;
            if (lo < first[hi]) first[hi] = lo;
        }
    }
    for (int i = 0; i < nf; i++)
        for (int k = first[i]; k <= i; k++) a[(size_t)i * lda + (size_t)k] = 0.0;
    for (int i = 0; i < net->n; i++)
        if (net->fidx[i] >= 0)
            a[(size_t)net->fidx[i] * (lda + 1)] = net->C[i] * inv_dt;
    for (int e = 0; e < net->n_edges; e++) {
        int ia = net->fidx[net->ea[e]], ib = net->fidx[net->eb[e]];
        double g = 1.0 / net->R[e];
        if (ia >= 0) a[(size_t)ia * (lda + 1)] += g;
        if (ib >= 0) a[(size_t)ib * (lda + 1)] += g;
        if (ia >= 0 && ib >= 0) {
            int hi = ia > ib ? ia : ib, lo = ia + ib - hi;
            a[(size_t)hi * lda + (size_t)lo] -= g;
        }
    }
    net->n_fact++;
    if (!acbb_skyline_factor(a, nf, (int)lda, first))
        return ACBB_SINGULAR;
    f->dirty = 0;
    f->valid = 1;
    return ACBB_OK;
}

/* Add G_D T_D: for each free node, sum over fixed neighbours of T_D / R. */
static void add_boundary_rhs(const acbb_tnet *net, gsl_vector *rhs)
{
    for (int e = 0; e < net->n_edges; e++) {
        int a = net->ea[e], b = net->eb[e];
        int ia = net->fidx[a], ib = net->fidx[b];
        if (ia >= 0 && ib < 0) *gsl_vector_ptr(rhs, (size_t)ia) += net->Tfix[b] / net->R[e];
        if (ib >= 0 && ia < 0) *gsl_vector_ptr(rhs, (size_t)ib) += net->Tfix[a] / net->R[e];
    }
}

/* Solve with the stored factors and scatter into T (fixed nodes too). */
static acbb_status solve_scatter(acbb_tnet *net, tn_factor *f, double *T)
{
    int nf = net->nf;
    if (nf > 0) {
        gsl_matrix_view A = gsl_matrix_submatrix(f->lu, 0, 0, (size_t)nf, (size_t)nf);
        gsl_vector_view b = gsl_vector_subvector(net->rhs, 0, (size_t)nf);
        gsl_vector_view x = gsl_vector_subvector(net->x, 0, (size_t)nf);
        acbb_skyline_solve(A.matrix.data, nf, (int)A.matrix.tda, f->first, b.vector.data,
                           x.vector.data);
        for (int i = 0; i < nf; i++)
            if (!isfinite(gsl_vector_get(&x.vector, (size_t)i))) return ACBB_NONFINITE;
    }
    for (int i = 0; i < net->n; i++)
        T[i] = net->fixed[i] ? net->Tfix[i] : gsl_vector_get(net->x, (size_t)net->fidx[i]);
    return ACBB_OK;
}

static int free_entries_finite(const acbb_tnet *net, const double *v)
{
    for (int i = 0; i < net->n; i++)
        if (!net->fixed[i] && !isfinite(v[i])) return 0;
    return 1;
}

acbb_status acbb_tnet_step(acbb_tnet *net, const double *q, double dt, double *T)
{
    if (!net || !q || !T || !isfinite(dt) || dt <= 0.0) return ACBB_EINVAL;
    if (!free_entries_finite(net, q) || !free_entries_finite(net, T)) return ACBB_EINVAL;
    update_map(net);
    tn_factor *f = &net->tr;
    if (f->dirty || !f->valid || f->dt != dt) {
        acbb_status st = factorise(net, f, 1.0 / dt);
        if (st != ACBB_OK) return st;
        f->dt = dt;
    }
    gsl_vector_set_zero(net->rhs);
    for (int i = 0; i < net->n; i++) {
        int k = net->fidx[i];
        if (k >= 0) gsl_vector_set(net->rhs, (size_t)k, net->C[i] / dt * T[i] + q[i]);
    }
    add_boundary_rhs(net, net->rhs);
    return solve_scatter(net, f, T);
}

acbb_status acbb_tnet_steady(acbb_tnet *net, const double *q, double *T)
{
    if (!net || !q || !T) return ACBB_EINVAL;
    if (!free_entries_finite(net, q)) return ACBB_EINVAL;
    update_map(net);
    tn_factor *f = &net->st;
    if (f->dirty || !f->valid) {
        acbb_status st = factorise(net, f, 0.0);
        if (st != ACBB_OK) return st;
    }
    gsl_vector_set_zero(net->rhs);
    for (int i = 0; i < net->n; i++) {
        int k = net->fidx[i];
        if (k >= 0) gsl_vector_set(net->rhs, (size_t)k, q[i]);
    }
    add_boundary_rhs(net, net->rhs);
    return solve_scatter(net, f, T);
}

double acbb_tnet_heat_to_fixed(const acbb_tnet *net, const double *T)
{
    if (!net || !T) return NAN;
    /* the stored Dirichlet values are used, so T's fixed entries may be stale */
    double sum = 0.0;
    for (int e = 0; e < net->n_edges; e++) {
        int a = net->ea[e], b = net->eb[e];
        if (net->fixed[a] == net->fixed[b]) continue;   /* free-free or fixed-fixed */
        int fr = net->fixed[a] ? b : a, fx = net->fixed[a] ? a : b;
        sum += (T[fr] - net->Tfix[fx]) / net->R[e];
    }
    return sum;
}
