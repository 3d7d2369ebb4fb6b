/* overdamped.c - assembly and iterative solution of the m = 0 DPD velocity
 * system A v = f (Phan-Thien, Mai-Duy, Khoo & Duong-Hong 2016, eqs 14-46).
 * See overdamped.h for the layout and the list of solvers. */
#include <stdlib.h>
#include <stddef.h>
#include <string.h>
#include <math.h>
#include <gsl/gsl_cblas.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_linalg.h>
#include "overdamped.h"
#include "forces.h"
#include "pair_style.h"
#include "integrator.h"
#include "random.h"
#include "timers.h"

#define SINGULAR_REL 1e-12   /* det below this x (trace/dim)^dim: block treated as singular */

void od_init(OdSystem *od)
{
    memset(od, 0, sizeof *od);
}

void od_free(OdSystem *od)
{
    free(od->row_of); free(od->part_of); free(od->diag); free(od->dinv);
    free(od->ostart); free(od->ocol); free(od->oblk); free(od->f); free(od->wrow);
    free(od->work); free(od->agg); free(od->coarse);
    memset(od, 0, sizeof *od);
}

/* ------------------------------------------------------------ small blocks */

/* b += g e e^T (3x3 row-major), entries (a,c) and (c,a) bit-identical */
static inline void add_outer(double *b, double g, const double e[3])
{
    for (int a = 0; a < 3; a++) {
        const double ga = g * e[a];
        b[4 * a] += ga * e[a];
        for (int c = a + 1; c < 3; c++) {
            const double q = ga * e[c];
            b[3 * a + c] += q;
            b[3 * c + a] += q;
        }
    }
}

/* y (+)= B x for a 3x3 block */
static inline void blk_mul_add(const double *B, const double *x, double *y)
{
    y[0] += B[0] * x[0] + B[1] * x[1] + B[2] * x[2];
    y[1] += B[3] * x[0] + B[4] * x[1] + B[5] * x[2];
    y[2] += B[6] * x[0] + B[7] * x[1] + B[8] * x[2];
}

static inline void blk_mul(const double *B, const double *x, double *y)
{
    y[0] = y[1] = y[2] = 0.0;
    blk_mul_add(B, x, y);
}

/* Moore-Penrose pseudo-inverse of the leading dim x dim part of a symmetric
 * block, eigenvalues below rel x largest dropped (gsl_eigen_symmv). */
static void sym_pinv(const double *B, int dim, double *Binv)
{
    memset(Binv, 0, 9 * sizeof(double));
    gsl_matrix *m = gsl_matrix_alloc((size_t)dim, (size_t)dim);
    gsl_matrix *evec = gsl_matrix_alloc((size_t)dim, (size_t)dim);
    gsl_vector *eval = gsl_vector_alloc((size_t)dim);
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc((size_t)dim);
    if (!m || !evec || !eval || !w) goto out;
    for (int a = 0; a < dim; a++)
        for (int c = 0; c < dim; c++) gsl_matrix_set(m, (size_t)a, (size_t)c, B[3 * a + c]);
    gsl_eigen_symmv(m, eval, evec, w);
    double lmax = 0.0;
    for (int k = 0; k < dim; k++) lmax = fmax(lmax, fabs(gsl_vector_get(eval, (size_t)k)));
    for (int k = 0; k < dim; k++) {
        const double l = gsl_vector_get(eval, (size_t)k);
        if (l <= 1e-10 * lmax || l <= 0.0) continue;
        for (int a = 0; a < dim; a++)
            for (int c = 0; c < dim; c++)
                Binv[3 * a + c] += gsl_matrix_get(evec, (size_t)a, (size_t)k)
                                 * gsl_matrix_get(evec, (size_t)c, (size_t)k) / l;
    }
out:
    if (w) gsl_eigen_symmv_free(w);
    gsl_vector_free(eval); gsl_matrix_free(evec); gsl_matrix_free(m);
}

/* Inverse of a symmetric 2x2 / 3x3 block by the adjugate formula; falls back
 * to the pseudo-inverse (and returns 1) when the block is singular, e.g. a
 * particle with a single neighbour (its velocity across e_ij is then free:
 * the pseudo-inverse picks zero for that component). eq. 22 */
static int sym_inverse(const double *B, int dim, double *Binv)
{
    memset(Binv, 0, 9 * sizeof(double));
    const double tr = dim == 2 ? B[0] + B[4] : B[0] + B[4] + B[8];
    if (!(tr > 0.0)) return 1;            /* no neighbour at all: v_i left at 0 */
    const double sc = tr / dim;
    if (dim == 2) {
        const double det = B[0] * B[4] - B[1] * B[3];
        if (det <= SINGULAR_REL * sc * sc) { sym_pinv(B, dim, Binv); return 1; }
        Binv[0] = B[4] / det; Binv[4] = B[0] / det;
        Binv[1] = -B[1] / det; Binv[3] = -B[3] / det;
        return 0;
    }
    const double c00 = B[4] * B[8] - B[5] * B[7];
    const double c01 = B[5] * B[6] - B[3] * B[8];
    const double c02 = B[3] * B[7] - B[4] * B[6];
    const double det = B[0] * c00 + B[1] * c01 + B[2] * c02;
    if (det <= SINGULAR_REL * sc * sc * sc) { sym_pinv(B, dim, Binv); return 1; }
    const double id = 1.0 / det;
    Binv[0] = c00 * id; Binv[1] = c01 * id; Binv[2] = c02 * id;
    Binv[3] = c01 * id; Binv[4] = (B[0] * B[8] - B[2] * B[6]) * id; Binv[5] = (B[2] * B[3] - B[0] * B[5]) * id;
    Binv[6] = c02 * id; Binv[7] = Binv[5];                     Binv[8] = (B[0] * B[4] - B[1] * B[3]) * id;
    return 0;
}

/* -------------------------------------------------------------- assembly */

static int grow(void **p, size_t n, size_t size)
{
    void *q = realloc(*p, n * size + 1);
    if (!q) return -1;
    *p = q;
    return 0;
}

/* Pass 1 of the assembly: the off-diagonal blocks of each row (pairs of two
 * mobile particles, listed under the row of i). */
static void count_block(void *ctx, int i, int j, const double d[3], double r2, double image_vx)
{
    OdSystem *od = ctx;
    (void)d; (void)r2; (void)image_vx;
    const int ri = od->row_of[i];
    if (ri >= 0 && od->row_of[j] >= 0) od->ostart[ri + 1]++;
}

typedef struct {
    OdSystem *od;
    const System *s;
    const PairStyle *style;   /* the scene's pair style: each pair's terms */
    double inv_sqrt_dt;
    int fill;                 /* blocks written: rows in order, so row ri's land in ostart[ri] .. */
} AssemblyPass;

/* Pass 2: one pair's share of A (eq. 16) and f (eq. 18), from the pair
 * style's terms F_ij = (fcr - g e_ij . v_ij) e_ij (PairStyle.overdamped).
 * image_vx is the x velocity of j's Lees-Edwards image relative to j: the
 * relative velocity is v_i - v_j - image_vx, and its known part goes into f. */
static void assemble_pair(void *ctx, int i, int j, const double d[3], double r2, double image_vx)
{
    AssemblyPass *ap = ctx;
    OdSystem *od = ap->od;
    const System *s = ap->s;
    const int ri = od->row_of[i], rj = od->row_of[j];
    if (ri < 0 && rj < 0) return;                               /* frozen-frozen: no unknown */
    const double r = sqrt(r2);
    const double e[3] = {d[0] / r, d[1] / r, d[2] / r};
    const PairParams *p = &s->pair[s->type[i]][s->type[j]];
    const double theta = rng_pair_normal(s->seed, s->step, s->id[i], s->id[j]);
    double fcr, g;   /* eq. 18's first part, and A's coefficient (eq. 16) */
    ap->style->overdamped(p, r, theta, ap->inv_sqrt_dt, &fcr, &g);
    const double ee_img = g * e[0] * image_vx;                  /* g e e^T (image_vx, 0, 0) = ee_img e */
    if (ri >= 0 && rj >= 0) {                                   /* eq. 16: both unknown */
        add_outer(od->diag + 9 * (size_t)ri, g, e);
        add_outer(od->diag + 9 * (size_t)rj, g, e);
        double *B = od->oblk + 9 * (size_t)ap->fill;
        memset(B, 0, 9 * sizeof(double));
        add_outer(B, -g, e);
        od->ocol[ap->fill++] = rj;
        for (int a = 0; a < 3; a++) {
            od->f[3 * ri + a] += (fcr + ee_img) * e[a];
            od->f[3 * rj + a] -= (fcr + ee_img) * e[a];
        }
    } else if (ri >= 0) {                                       /* j frozen: eq. 18, last part */
        add_outer(od->diag + 9 * (size_t)ri, g, e);
        add_outer(od->wrow + 9 * (size_t)ri, g, e);
        const double *vj = s->v + 3 * j;
        const double edv = e[0] * (vj[0] + image_vx) + e[1] * vj[1] + e[2] * vj[2];
        for (int a = 0; a < 3; a++) od->f[3 * ri + a] += (fcr + g * edv) * e[a];
    } else {                                                    /* i frozen, j mobile */
        add_outer(od->diag + 9 * (size_t)rj, g, e);
        add_outer(od->wrow + 9 * (size_t)rj, g, e);
        const double *vi = s->v + 3 * i;
        const double edv = e[0] * (vi[0] - image_vx) + e[1] * vi[1] + e[2] * vi[2];
        for (int a = 0; a < 3; a++) od->f[3 * rj + a] += (-fcr + g * edv) * e[a];
    }
}

/* A (eq. 16) and f (eq. 18): block CSR over the mobile particles. */
int od_assemble(OdSystem *od, const System *s, const NeighborList *nl)
{
    const int n = s->n, dim = s->box.dim;
    od->dim = dim;
    od->n = n;
    /* map mobile particles to rows (eq. 17: i = 1 .. Ns) */
    if ((size_t)n > od->cap_rows || !od->row_of) {
        if (grow((void **)&od->row_of, (size_t)n, sizeof(int)) || grow((void **)&od->part_of, (size_t)n, sizeof(int))
            || grow((void **)&od->diag, 9 * (size_t)n, sizeof(double)) || grow((void **)&od->dinv, 9 * (size_t)n, sizeof(double))
            || grow((void **)&od->wrow, 9 * (size_t)n, sizeof(double)) || grow((void **)&od->ostart, (size_t)n + 1, sizeof(int))
            || grow((void **)&od->f, 3 * (size_t)n, sizeof(double)) || grow((void **)&od->work, 18 * (size_t)n, sizeof(double)))
            return -1;
        od->cap_rows = (size_t)n;
    }
    int nm = 0;
    for (int i = 0; i < n; i++) {
        if (s->types[s->type[i]].frozen) { od->row_of[i] = -1; continue; }
        od->row_of[i] = nm;
        od->part_of[nm++] = i;
    }
    od->nm = nm;
    /* count the mobile-mobile pairs, listed under the row of i */
    memset(od->ostart, 0, ((size_t)nm + 1) * sizeof(int));
    pair_visit(s, nl, count_block, od);
    for (int r = 0; r < nm; r++) od->ostart[r + 1] += od->ostart[r];
    const size_t nb = (size_t)od->ostart[nm];
    if (nb > od->cap_blk || !od->ocol) {
        if (grow((void **)&od->ocol, nb, sizeof(int)) || grow((void **)&od->oblk, 9 * nb, sizeof(double)))
            return -1;
        od->cap_blk = nb;
    }
    memset(od->diag, 0, 9 * (size_t)nm * sizeof(double));
    memset(od->wrow, 0, 9 * (size_t)nm * sizeof(double));
    memset(od->f, 0, 3 * (size_t)nm * sizeof(double));
    memset(od->wall, 0, sizeof od->wall);
    memset(od->fbody, 0, sizeof od->fbody);
    AssemblyPass pass = {.od = od, .s = s, .style = pair_style_of(s), .inv_sqrt_dt = 1.0 / sqrt(s->dt)};
    if (!pass.style || !pass.style->overdamped || pass.style->nvar != 1) return -1;   /* no m = 0 form */
    pair_visit(s, nl, assemble_pair, &pass);
    /* body force of the mobile particles, as body_forces() in forces.c */
    if (s->has_body_force)
        for (int r = 0; r < nm; r++) {
            const int i = od->part_of[r];
            const ParticleType *t = &s->types[s->type[i]];
            double sign = 1.0;
            if (t->body_force_flip_axis >= 0) {
                const int a = t->body_force_flip_axis;
                sign = s->x[3 * i + a] < s->box.half[a] ? 1.0 : -1.0;
            }
            for (int d = 0; d < 3; d++) {
                od->f[3 * r + d] += sign * t->body_force[d];
                od->fbody[d] += sign * t->body_force[d];
            }
        }
    if (dim == 2) for (int r = 0; r < nm; r++) od->f[3 * r + 2] = 0.0;
    od->n_singular = 0;
    for (int r = 0; r < nm; r++) {
        od->n_singular += sym_inverse(od->diag + 9 * (size_t)r, dim, od->dinv + 9 * (size_t)r);
        for (int a = 0; a < 9; a++) od->wall[a] += od->wrow[9 * (size_t)r + a];
    }
    sym_inverse(od->wall, dim, od->wall_inv);     /* pseudo-inverse if no wall contact */
    od->fnorm = cblas_dnrm2(3 * nm, od->f, 1);
    /* coarse cells of side about 2 rc for the two-level preconditioner */
    od->coarse_ok = 0;
    if (grow((void **)&od->agg, (size_t)n, sizeof(int))) return -1;
    int nc[3] = {1, 1, 1}, ncell = 1;
    for (int d = 0; d < dim; d++) { nc[d] = (int)(s->box.L[d] / (2.0 * s->rc_max)); if (nc[d] < 1) nc[d] = 1; ncell *= nc[d]; }
    for (int r = 0; r < nm; r++) {
        const double *x = s->x + 3 * (size_t)od->part_of[r];
        int c = 0;
        for (int d = dim - 1; d >= 0; d--) {
            int k = (int)(x[d] / s->box.L[d] * nc[d]);
            k = k < 0 ? 0 : (k >= nc[d] ? nc[d] - 1 : k);
            c = c * nc[d] + k;
        }
        od->agg[r] = c;
    }
    od->ncoarse = ncell * dim;
    return 0;
}

/* -------------------------------------------------------- products, norms */

/* The same in 2D, on the blocks' leading 2 x 2 (their z row and column are
 * zero, as are the z components of every vector the solvers multiply), in the
 * order of blk_mul_add's first two terms. y's z components stay 0. */
static void offdiag_mul_2d(const OdSystem *od, const double *restrict v, double *restrict y)
{
    for (int r = 0; r < od->nm; r++) {
        const double vr0 = v[3 * (size_t)r], vr1 = v[3 * (size_t)r + 1];
        double yr0 = y[3 * (size_t)r], yr1 = y[3 * (size_t)r + 1];
        for (int k = od->ostart[r]; k < od->ostart[r + 1]; k++) {
            const size_t c = 3 * (size_t)od->ocol[k];
            const double *B = od->oblk + 9 * (size_t)k;
            yr0 += B[0] * v[c] + B[1] * v[c + 1];
            yr1 += B[3] * v[c] + B[4] * v[c + 1];
            y[c] += B[0] * vr0 + B[1] * vr1;                          /* A_cr = A_rc^T = A_rc */
            y[c + 1] += B[3] * vr0 + B[4] * vr1;
        }
        y[3 * (size_t)r] = yr0; y[3 * (size_t)r + 1] = yr1;
    }
}

/* y = K v: off-diagonal part of A (eq. 21), each stored block used twice.
 * Row r's own sum is kept in registers through its blocks (c != r, and v and
 * y never overlap), added in the order of y[r] += B v_c one block at a time:
 * the same sums, without a store and a reload of y[r] per block. */
static void offdiag_mul(const OdSystem *od, const double *restrict v, double *restrict y)
{
    memset(y, 0, 3 * (size_t)od->nm * sizeof(double));
    if (od->dim == 2) { offdiag_mul_2d(od, v, y); return; }
    for (int r = 0; r < od->nm; r++) {
        const double *vr = v + 3 * (size_t)r;
        double yr[3] = {y[3 * (size_t)r], y[3 * (size_t)r + 1], y[3 * (size_t)r + 2]};
        for (int k = od->ostart[r]; k < od->ostart[r + 1]; k++) {
            const int c = od->ocol[k];
            const double *B = od->oblk + 9 * (size_t)k;
            blk_mul_add(B, v + 3 * (size_t)c, yr);
            blk_mul_add(B, vr, y + 3 * (size_t)c);                  /* A_cr = A_rc^T = A_rc */
        }
        y[3 * (size_t)r] = yr[0]; y[3 * (size_t)r + 1] = yr[1]; y[3 * (size_t)r + 2] = yr[2];
    }
}

/* y = A v, eq. 15 */
void od_matvec(const OdSystem *od, const double *v, double *y)
{
    offdiag_mul(od, v, y);
    for (int r = 0; r < od->nm; r++)
        blk_mul_add(od->diag + 9 * (size_t)r, v + 3 * (size_t)r, y + 3 * (size_t)r);
}

static double rel_to_f(const OdSystem *od, double rnorm)
{
    return od->fnorm > 0.0 ? rnorm / od->fnorm : rnorm;
}

double od_residual(const OdSystem *od, const double *v)
{
    const int n3 = 3 * od->nm;
    double *y = malloc((size_t)n3 * sizeof(double) + 1);
    if (!y) return NAN;
    od_matvec(od, v, y);
    for (int k = 0; k < n3; k++) y[k] = od->f[k] - y[k];
    const double rn = cblas_dnrm2(n3, y, 1);
    free(y);
    return rel_to_f(od, rn);
}

void od_gather(const OdSystem *od, const System *s, double *v)
{
    for (int r = 0; r < od->nm; r++) {
        const int i = od->part_of[r];
        for (int a = 0; a < 3; a++) v[3 * r + a] = s->v[3 * i + a];
        if (od->dim == 2) v[3 * r + 2] = 0.0;
    }
}

void od_scatter(const OdSystem *od, System *s, const double *v)
{
    for (int r = 0; r < od->nm; r++) {
        const int i = od->part_of[r];
        for (int a = 0; a < od->dim; a++) s->v[3 * i + a] = v[3 * r + a];
    }
}

/* |f - A v| from t = f - K v (already computed): f - A v = t - D v. */
static double residual_from_t(const OdSystem *od, const double *t, const double *v, double *sum)
{
    double rn2 = 0.0;
    if (sum) sum[0] = sum[1] = sum[2] = 0.0;
    for (int r = 0; r < od->nm; r++) {
        double dv[3];
        blk_mul(od->diag + 9 * (size_t)r, v + 3 * (size_t)r, dv);
        for (int a = 0; a < 3; a++) {
            const double q = t[3 * r + a] - dv[a];
            rn2 += q * q;
            if (sum) sum[a] += q;
        }
    }
    return sqrt(rn2);
}

/* The start of a Picard sweep: t = f - K v^{l-1} (one product with K) and the
 * relative residual of v^{l-1}, recorded in res (with the residual's
 * component sums in sum, when asked for). */
static void sweep_rhs(const OdSystem *od, const double *v, double *t, double *sum, OdResult *res)
{
    offdiag_mul(od, v, t);
    res->matvecs++;
    for (int k = 0; k < 3 * od->nm; k++) t[k] = od->f[k] - t[k];
    res->rel_residual = rel_to_f(od, residual_from_t(od, t, v, sum));
}

static int stop_change(double dnorm, double vnorm, double tol)
{
    return dnorm < tol * vnorm;                  /* eq. 27 */
}

/* Bookkeeping after a Picard sweep that changed v by |dv|^2 = d2: counts the
 * sweep, records the change, and applies eq. 27 when that is the rule.
 * Returns 1 when converged (the residual of the final v is then recorded). */
static int end_of_sweep(const OdSystem *od, const double *v, double d2, OdStop stop, double tol,
                        OdResult *res)
{
    const double vnorm = cblas_dnrm2(3 * od->nm, v, 1), dnorm = sqrt(d2);
    res->iterations++;
    res->change = vnorm > 0.0 ? dnorm / vnorm : dnorm;
    if (stop != OD_STOP_CHANGE || !stop_change(dnorm, vnorm, tol)) return 0;
    res->converged = 1;
    res->rel_residual = od_residual(od, v);
    return 1;
}

/* ---------------------------------------------------------------- Scheme 1 */

/* Picard / block Jacobi: v^l = -H v^{l-1} + b = D^{-1} (f - K v^{l-1}),
 * eqs 23-26. One product with K per sweep; the residual of v^{l-1} comes for
 * free from t = f - K v^{l-1} (f - A v = t - D v). */
static OdResult scheme1(OdSystem *od, double *v, OdStop stop, double tol, int max_iter)
{
    const int nm = od->nm, n3 = 3 * nm;
    double *t = od->work, *vn = od->work + n3;
    OdResult res = {0};
    for (int l = 0;; l++) {
        sweep_rhs(od, v, t, NULL, &res);
        if (stop == OD_STOP_RESIDUAL && res.rel_residual < tol) { res.converged = 1; break; }
        if (l == max_iter) break;
        for (int r = 0; r < nm; r++) blk_mul(od->dinv + 9 * (size_t)r, t + 3 * (size_t)r, vn + 3 * (size_t)r); /* eq. 26 */
        double d2 = 0.0;
        for (int k = 0; k < n3; k++) { const double q = vn[k] - v[k]; d2 += q * q; v[k] = vn[k]; }
        if (end_of_sweep(od, v, d2, stop, tol, &res)) break;
    }
    return res;
}

/* ------------------------------------------------------ Scheme 2 (paper) */

/* Scheme 2 as published, eq. 46:
 *   v^l_i = -H_i v^{l-1} - sum_k eps_k <v^{l-1}, eps_k> + b~_i,
 *   b~_i  = D_i^{-1} (f_i - F~ / Ns)                         (eqs 26, 45)
 * eps_k (eqs 42-44) is the normalised uniform translation along axis k, so
 * sum_k eps_k <v, eps_k> is the mean fluid velocity in every slot.
 *
 * Readings where the text leaves a choice (documented, see also overdamped.h):
 *  1. F~ (eq. 31) is the net DPD force on the fluid from the frozen particles.
 *     It contains the dissipative force, so it depends on the unknown
 *     velocities; the text gives no rule for when to evaluate it. We take it
 *     from the current iterate, F~ = sum_i (f - A v^{l-1})_i: the net force on
 *     the fluid, which is the only reading under which the converged field has
 *     the zero velocity sum the paper reports (< 1e-8). (Evaluated once per
 *     time step from v^0 instead, the sum would not vanish.)
 *  2. Body force: eq. 31 has none. With the brief's "the fluid's total force is
 *     zero" F~ includes the body forces of the fluid particles (default). With
 *     od->s2_exclude_body = 1, F~ counts the DPD forces only (eq. 31 verbatim).
 *  3. The deflation term of eq. 41/46 is added after the multiplication by
 *     I^{-1} (it is not premultiplied by I^{-1}), while the -F~/Ns shift is
 *     (eq. 45); implemented literally. Eq. 41 writes [.,.] and eq. 46 <.,.>
 *     for the same natural inner product.
 *  4. In 2D only eps_x and eps_y exist (U_z would have no slot).
 *  5. "Hereafter ... notations in the moving frame are taken to be the same
 *     as in the fixed frame": the frozen velocities in f are used unchanged
 *     (not shifted by the centre-of-mass velocity), and the velocities
 *     returned are the moving-frame ones.
 * Fixed point: A v + D P v = f - 1 F~/Ns with F~ = 1^T (f - A v) gives
 * 1^T D P v = 0, so the mean fluid velocity is zero and A v = f - 1 F~/Ns:
 * not a solution of A v = f unless F~ = 0. */
static OdResult scheme2_paper(OdSystem *od, double *v, OdStop stop, double tol, int max_iter)
{
    const int nm = od->nm, n3 = 3 * nm, dim = od->dim;
    double *t = od->work, *vn = od->work + n3;
    OdResult res = {0};
    for (int l = 0;; l++) {
        double Ft[3];                                           /* eq. 31 at v^{l-1} */
        sweep_rhs(od, v, t, Ft, &res);
        if (od->s2_exclude_body) for (int a = 0; a < 3; a++) Ft[a] -= od->fbody[a];
        if (stop == OD_STOP_RESIDUAL && res.rel_residual < tol) { res.converged = 1; break; }
        if (l == max_iter) break;
        double mean[3] = {0.0, 0.0, 0.0};                       /* eps_k <v, eps_k>, eqs 42-44 */
        for (int r = 0; r < nm; r++) for (int a = 0; a < dim; a++) mean[a] += v[3 * r + a];
        for (int a = 0; a < 3; a++) { mean[a] /= nm; Ft[a] /= nm; }
        double d2 = 0.0;
        for (int r = 0; r < nm; r++) {
            double q[3] = {t[3 * r] - Ft[0], t[3 * r + 1] - Ft[1], t[3 * r + 2] - Ft[2]}; /* eq. 45 */
            blk_mul(od->dinv + 9 * (size_t)r, q, vn + 3 * (size_t)r);
            for (int a = 0; a < dim; a++) {
                vn[3 * r + a] -= mean[a];                       /* eq. 46 */
                const double dd = vn[3 * r + a] - v[3 * r + a];
                d2 += dd * dd;
            }
        }
        memcpy(v, vn, (size_t)n3 * sizeof(double));
        if (end_of_sweep(od, v, d2, stop, tol, &res)) break;
    }
    return res;
}

/* -------------------------------------------------- Scheme 2 (consistent) */

/* A Jacobi sweep (eq. 26) then a uniform correction c that zeroes the net
 * residual force on the fluid, 1^T (f - A (v' + 1 c)) = 0:
 *   (1^T A 1) c = 1^T f - 1^T A v',  1^T A 1 = W (sum of frozen couplings),
 *   1^T A v' = sum_i W_i v'_i (the Laplacian part has zero column sums).
 * The correction minimises the A-norm error over uniform shifts (a two-level
 * method with the rigid translation as coarse space), so the iteration
 * converges to the solution of A v = f. No extra product with A is needed.
 * Without any frozen contact W = 0 (A singular): c is then -mean(v'), i.e.
 * the zero-mean solution is picked. */
static OdResult scheme2_consistent(OdSystem *od, double *v, OdStop stop, double tol, int max_iter)
{
    const int nm = od->nm, n3 = 3 * nm, dim = od->dim;
    double *t = od->work, *vn = od->work + n3;
    const int has_wall = od->wall[0] + od->wall[4] + od->wall[8] > 0.0;
    double fsum[3] = {0.0, 0.0, 0.0};
    for (int r = 0; r < nm; r++) for (int a = 0; a < 3; a++) fsum[a] += od->f[3 * r + a];
    OdResult res = {0};
    for (int l = 0;; l++) {
        sweep_rhs(od, v, t, NULL, &res);
        if (stop == OD_STOP_RESIDUAL && res.rel_residual < tol) { res.converged = 1; break; }
        if (l == max_iter) break;
        double net[3] = {fsum[0], fsum[1], fsum[2]}, mean[3] = {0.0, 0.0, 0.0};
        for (int r = 0; r < nm; r++) {
            blk_mul(od->dinv + 9 * (size_t)r, t + 3 * (size_t)r, vn + 3 * (size_t)r); /* eq. 26 */
            double wv[3];
            blk_mul(od->wrow + 9 * (size_t)r, vn + 3 * (size_t)r, wv);
            for (int a = 0; a < 3; a++) { net[a] -= wv[a]; mean[a] += vn[3 * r + a]; }
        }
        double c[3];
        if (has_wall) blk_mul(od->wall_inv, net, c);
        else for (int a = 0; a < 3; a++) c[a] = -mean[a] / nm;
        if (dim == 2) c[2] = 0.0;
        double d2 = 0.0;
        for (int r = 0; r < nm; r++)
            for (int a = 0; a < 3; a++) {
                vn[3 * r + a] += c[a];
                const double dd = vn[3 * r + a] - v[3 * r + a];
                d2 += dd * dd;
            }
        memcpy(v, vn, (size_t)n3 * sizeof(double));
        if (end_of_sweep(od, v, d2, stop, tol, &res)) break;
    }
    return res;
}

/* -------------------------------------------------------------------- PCG */

/* Coarse operator P^T A P of the aggregation (P: one block of identity per
 * row in its cell's slot), Cholesky-factored (GSL). Empty cells get a unit
 * diagonal. Returns 0, or -1 if P^T A P is not positive definite (no frozen
 * contact: the uniform translation is then in its null space). */
static int coarse_build(OdSystem *od)
{
    const int nc = od->ncoarse, dim = od->dim;
    if ((size_t)nc * nc > od->cap_coarse) {
        if (grow((void **)&od->coarse, (size_t)nc * nc, sizeof(double))) return -1;
        od->cap_coarse = (size_t)nc * nc;
    }
    double *C = od->coarse;
    memset(C, 0, (size_t)nc * nc * sizeof(double));
    for (int r = 0; r < od->nm; r++) {
        const int I = od->agg[r] * dim;
        const double *B = od->diag + 9 * (size_t)r;
        for (int a = 0; a < dim; a++) for (int b = 0; b < dim; b++) C[(size_t)(I + a) * nc + I + b] += B[3 * a + b];
        for (int k = od->ostart[r]; k < od->ostart[r + 1]; k++) {
            const int J = od->agg[od->ocol[k]] * dim;
            const double *O = od->oblk + 9 * (size_t)k;
            for (int a = 0; a < dim; a++)
                for (int b = 0; b < dim; b++) {
                    C[(size_t)(I + a) * nc + J + b] += O[3 * a + b];
                    C[(size_t)(J + a) * nc + I + b] += O[3 * b + a];
                }
        }
    }
    for (int i = 0; i < nc; i++) if (C[(size_t)i * nc + i] == 0.0) C[(size_t)i * nc + i] = 1.0;
    gsl_matrix_view m = gsl_matrix_view_array(C, (size_t)nc, (size_t)nc);
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    const int bad = gsl_linalg_cholesky_decomp1(&m.matrix);
    gsl_set_error_handler(old);
    return bad ? -1 : 0;
}

/* Without frozen contact A is singular (a uniform translation costs nothing)
 * and the block-Jacobi preconditioner does not keep the iterates out of that
 * null space: the mean velocity then drifts from step to step. Projecting
 * the warm start and every preconditioned residual onto zero mean picks the
 * solution whose centre of mass is at rest (the constraint of Scheme 2,
 * eqs 41-44, which is exact when there are no frozen particles). */
static void remove_mean(const OdSystem *od, double *v)
{
    double mean[3] = {0.0, 0.0, 0.0};
    for (int r = 0; r < od->nm; r++) for (int a = 0; a < 3; a++) mean[a] += v[3 * (size_t)r + a];
    for (int a = 0; a < 3; a++) mean[a] /= od->nm;
    for (int r = 0; r < od->nm; r++) for (int a = 0; a < 3; a++) v[3 * (size_t)r + a] -= mean[a];
}

/* z = M^{-1} r: block Jacobi (eq. 22), plus P (P^T A P)^{-1} P^T r when two-level. */
static void precondition(const OdSystem *od, const double *r, double *z, int twolevel, double *rc)
{
    for (int i = 0; i < od->nm; i++) blk_mul(od->dinv + 9 * (size_t)i, r + 3 * (size_t)i, z + 3 * (size_t)i);
    if (!twolevel) return;
    const int nc = od->ncoarse, dim = od->dim;
    memset(rc, 0, (size_t)nc * sizeof(double));
    for (int i = 0; i < od->nm; i++)
        for (int a = 0; a < dim; a++) rc[od->agg[i] * dim + a] += r[3 * (size_t)i + a];
    gsl_matrix_const_view m = gsl_matrix_const_view_array(od->coarse, (size_t)nc, (size_t)nc);
    gsl_vector_view v = gsl_vector_view_array(rc, (size_t)nc);
    gsl_linalg_cholesky_svx(&m.matrix, &v.vector);
    for (int i = 0; i < od->nm; i++)
        for (int a = 0; a < dim; a++) z[3 * (size_t)i + a] += rc[od->agg[i] * dim + a];
}

/* Preconditioned conjugate gradients (Hestenes & Stiefel 1952) with the
 * block-Jacobi preconditioner M = I of eq. 20 (z = I^{-1} r, eq. 22). A is
 * symmetric positive definite when frozen particles pin the translations.
 * The "change" of eq. 27 is |alpha p|, the residual the recurrence one
 * (the true residual is recomputed at the end). */
static OdResult pcg(OdSystem *od, double *x, OdStop stop, double tol, int max_iter, int twolevel)
{
    const int nm = od->nm, n3 = 3 * nm;
    double *r = od->work, *z = od->work + n3, *p = od->work + 2 * n3, *q = od->work + 3 * n3;
    OdResult res = {0};
    double *rc = NULL;
    if (twolevel) {
        if (!od->coarse_ok) od->coarse_ok = coarse_build(od) == 0 ? 1 : -1;
        if (od->coarse_ok == 1) rc = malloc((size_t)od->ncoarse * sizeof(double) + 1);
        twolevel = rc != NULL;           /* no coarse operator: plain block Jacobi */
    }
    const int singular = !(od->wall[0] + od->wall[4] + od->wall[8] > 0.0);
    if (singular) remove_mean(od, x);
    od_matvec(od, x, q);
    res.matvecs++;
    for (int k = 0; k < n3; k++) r[k] = od->f[k] - q[k];
    res.rel_residual = rel_to_f(od, cblas_dnrm2(n3, r, 1));
    if (stop == OD_STOP_RESIDUAL && res.rel_residual < tol) { res.converged = 1; free(rc); return res; }
    precondition(od, r, z, twolevel, rc);
    if (singular) remove_mean(od, z);
    memcpy(p, z, (size_t)n3 * sizeof(double));
    double rz = cblas_ddot(n3, r, 1, z, 1);
    while (res.iterations < max_iter) {
        od_matvec(od, p, q);
        res.matvecs++;
        const double pq = cblas_ddot(n3, p, 1, q, 1);
        if (!(pq > 0.0)) {                        /* breakdown: A not positive definite on p */
            if (stop != OD_STOP_CHANGE) res.change = NAN;   /* the last change was not computed */
            break;
        }
        const double alpha = rz / pq;
        cblas_daxpy(n3, alpha, p, 1, x, 1);
        cblas_daxpy(n3, -alpha, q, 1, r, 1);
        res.iterations++;
        res.rel_residual = rel_to_f(od, cblas_dnrm2(n3, r, 1));
        const int residual_met = stop == OD_STOP_RESIDUAL && res.rel_residual < tol;
        /* the change |alpha p| / |x|: every iteration when it is the stopping rule (eq. 27),
         * else only on the last one, where it is reported (two norms fewer per iteration) */
        if (stop == OD_STOP_CHANGE || residual_met || res.iterations == max_iter) {
            const double dnorm = fabs(alpha) * cblas_dnrm2(n3, p, 1), vnorm = cblas_dnrm2(n3, x, 1);
            res.change = vnorm > 0.0 ? dnorm / vnorm : dnorm;
            if (residual_met || (stop == OD_STOP_CHANGE && stop_change(dnorm, vnorm, tol))) { res.converged = 1; break; }
        }
        precondition(od, r, z, twolevel, rc);
        if (singular) remove_mean(od, z);
        const double rz_new = cblas_ddot(n3, r, 1, z, 1);
        const double beta = rz_new / rz;
        rz = rz_new;
        for (int k = 0; k < n3; k++) p[k] = z[k] + beta * p[k];
    }
    res.rel_residual = od_residual(od, x);        /* true residual, not the recurrence */
    if (stop == OD_STOP_RESIDUAL) res.converged = res.rel_residual < tol;
    free(rc);
    return res;
}

/* Fixed point of the published Scheme 2 (see scheme2_paper above): the v with
 * A v = f - E c and E^T v = 0, E the dim uniform translations (eqs 42-44) and
 * c = F~/Ns. With y0 = A^{-1} f and y_a = A^{-1} E_a (tight PCG solves):
 * c = (E^T A^{-1} E)^{-1} E^T y0, v = y0 - sum_a y_a c_a. Used to measure
 * the published Scheme 2's convergence to its own fixed point. Returns 0, or
 * -1 on allocation failure or when A is singular (no frozen contact). */
int od_scheme2_paper_fixed_point(OdSystem *od, double *v, double tol)
{
    const int nm = od->nm, n3 = 3 * nm, dim = od->dim;
    if (nm == 0) return 0;
    if (!(od->wall[0] + od->wall[4] + od->wall[8] > 0.0)) return -1;
    double *y = calloc((size_t)3 * n3 + 1, sizeof(double)), *e = malloc((size_t)n3 * sizeof(double) + 1);
    if (!y || !e) { free(y); free(e); return -1; }
    double *f = od->f;
    const double fnorm = od->fnorm;
    const int cap = 100 * nm + 1000;
    od_solve_vec(od, v, OD_PCG, OD_STOP_RESIDUAL, tol, cap);         /* y0, warm-started from v */
    od->f = e;
    for (int a = 0; a < dim; a++) {
        for (int k = 0; k < n3; k++) e[k] = (k % 3 == a) ? 1.0 : 0.0;
        od->fnorm = sqrt((double)nm);
        od_solve_vec(od, y + (size_t)a * n3, OD_PCG, OD_STOP_RESIDUAL, tol, cap);
    }
    od->f = f;
    od->fnorm = fnorm;
    double M[9] = {0}, Minv[9], rhs[3] = {0}, c[3];
    for (int r = 0; r < nm; r++)
        for (int a = 0; a < dim; a++) {
            rhs[a] += v[3 * r + a];
            for (int b = 0; b < dim; b++) M[3 * a + b] += y[(size_t)b * n3 + 3 * r + a];
        }
    for (int a = 0; a < dim; a++)                                   /* symmetrise round-off */
        for (int b = a + 1; b < dim; b++) M[3 * a + b] = M[3 * b + a] = 0.5 * (M[3 * a + b] + M[3 * b + a]);
    sym_inverse(M, dim, Minv);
    blk_mul(Minv, rhs, c);
    for (int r = 0; r < nm; r++)
        for (int b = 0; b < dim; b++)
            for (int a = 0; a < dim; a++) v[3 * r + a] -= y[(size_t)b * n3 + 3 * r + a] * c[b];
    free(y); free(e);
    return 0;
}

/* ------------------------------------------------------------------ entry */

OdResult od_solve_vec(OdSystem *od, double *v, OdSolver solver, OdStop stop,
                      double tol, int max_iter)
{
    OdResult res = {0};
    if (od->nm == 0) { res.converged = 1; return res; }
    switch (solver) {
    case OD_SCHEME1:            return scheme1(od, v, stop, tol, max_iter);
    case OD_SCHEME2_PAPER:      return scheme2_paper(od, v, stop, tol, max_iter);
    case OD_SCHEME2_CONSISTENT: return scheme2_consistent(od, v, stop, tol, max_iter);
    case OD_PCG:                return pcg(od, v, stop, tol, max_iter, 0);
    case OD_PCG_2LEVEL:         return pcg(od, v, stop, tol, max_iter, 1);
    }
    return res;
}

OdResult od_solve(OdSystem *od, System *s, OdSolver solver, OdStop stop,
                  double tol, int max_iter)
{
    double *v = od->work + 4 * 3 * (size_t)od->nm;    /* the solvers use slots 0-3 */
    od_gather(od, s, v);
    OdResult res = od_solve_vec(od, v, solver, stop, tol, max_iter);
    od_scatter(od, s, v);
    return res;
}

/* ------------------------------------------------------ the m = 0 step */

int od_stats_init(OdStats *st, int n)
{
    memset(st, 0, sizeof *st);
    st->sol = calloc(3 * (size_t)n + 1, sizeof(double));
    st->ref = calloc(3 * (size_t)n + 1, sizeof(double));
    return st->sol && st->ref ? 0 : -1;
}

void od_stats_free(OdStats *st)
{
    series_free(&st->iterations); series_free(&st->residual); series_free(&st->seconds);
    series_free(&st->true_error); series_free(&st->cpu_seconds);
    free(st->sol); free(st->ref);
    memset(st, 0, sizeof *st);
}

/* The true error of this step's solution: its distance to a tight PCG solve
 * started from it (or, for the published Scheme 2, to its own fixed point). */
static void record_true_error(OdSystem *od, const System *s, const OdSettings *set, OdStats *st)
{
    od_gather(od, s, st->sol);
    memcpy(st->ref, st->sol, 3 * (size_t)od->nm * sizeof(double));
    if (set->reference_own && set->solver == OD_SCHEME2_PAPER)
        od_scheme2_paper_fixed_point(od, st->ref, set->reference_tol);
    else
        od_solve_vec(od, st->ref, OD_PCG, OD_STOP_RESIDUAL, set->reference_tol, 100 * od->nm + 1000);
    double num = 0.0, den = 0.0;
    for (int k = 0; k < 3 * od->nm; k++) {
        num += (st->sol[k] - st->ref[k]) * (st->sol[k] - st->ref[k]);
        den += st->ref[k] * st->ref[k];
    }
    series_push(&st->true_error, den > 0 ? sqrt(num / den) : sqrt(num));
}

int od_step_solve(OdSystem *od, System *s, const OdSettings *set, OdStats *st, int record,
                  double t0, double c0)
{
    OdResult r = od_solve(od, s, set->solver, set->stop, set->tol, set->max_iter);
    if (record) {
        series_push(&st->iterations, r.iterations);
        series_push(&st->residual, r.rel_residual);
        series_push(&st->seconds, wall_now() - t0);
        series_push(&st->cpu_seconds, cpu_now() - c0);
    }
    if (!r.converged) {
        st->unconverged++;
        if (!set->allow_unconverged) {
            static const char *names[] = {"scheme1", "scheme2_paper", "scheme2_consistent", "pcg", "pcg_2level"};
            fprintf(stderr, "dpd: the %s solve did not converge at step %llu: %d iterations, change %g, "
                    "relative residual %g (tolerance %g); raise overdamped.max_iterations or set "
                    "overdamped.allow_unconverged = true\n", names[set->solver],
                    (unsigned long long)s->step, r.iterations, r.change, r.rel_residual, set->tol);
            return -1;
        }
    }
    if (record && set->reference_tol > 0.0) record_true_error(od, s, set, st);
    memcpy(s->v_pred, s->v, 3 * (size_t)s->n * sizeof(double));
    return 0;
}

void od_move(System *s)
{
    const double dt = s->dt;
    integrate_advance_offset(s);
    int bad = 0;
    #pragma omp parallel for schedule(static) reduction(+:bad)
    for (int i = 0; i < s->n; i++) {
        double *x = s->x + 3 * i, *v = s->v + 3 * i;
        for (int d = 0; d < 3; d++) x[d] += dt * v[d];   /* eq. 28 */
        bad += box_wrap(&s->box, x, s->img + 3 * i, &v[0], &s->v_pred[3 * i]);
    }
    s->nonfinite = bad;   /* the run stops */
    s->step++;
    s->time += dt;
}

int od_stats_write(const OdStats *st, FILE *f, Tables *ts, int nblocks)
{
    /* per-step record for plots; cpu_seconds last (plots read true_rel_error as column 5) */
    FILE *sf = tables_add(ts, "solver.tsv");
    if (!sf) return -1;
    fprintf(sf, "step\titerations\trel_residual\tseconds%s\tcpu_seconds\n", st->true_error.n ? "\ttrue_rel_error" : "");
    for (size_t k = 0; k < st->iterations.n; k++) {
        fprintf(sf, "%zu\t%g\t%.4g\t%.4g", k, st->iterations.v[k], st->residual.v[k], st->seconds.v[k]);
        if (st->true_error.n) fprintf(sf, "\t%.4g", st->true_error.v[k]);
        fprintf(sf, "\t%.4g\n", k < st->cpu_seconds.n ? st->cpu_seconds.v[k] : NAN);
    }
    const int bad = table_end(ts, sf) != 0;
    static const struct { const char *name; size_t off; } rows[] = {
        {"solver_iterations", offsetof(OdStats, iterations)}, {"solver_rel_residual", offsetof(OdStats, residual)},
        {"solver_seconds_per_step", offsetof(OdStats, seconds)}, {"solver_cpu_seconds_per_step", offsetof(OdStats, cpu_seconds)}};
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        double v, se;
        series_stats((const Series *)((const char *)st + rows[k].off), nblocks, &v, &se);
        fprintf(f, "%s\t%.10g\t%.4g\n", rows[k].name, v, se);
    }
    fprintf(f, "solver_unconverged_steps\t%lld\t0\n", st->unconverged);
    if (st->true_error.n > 0) {
        double v, se;
        series_stats(&st->true_error, nblocks, &v, &se);
        fprintf(f, "solver_true_rel_error\t%.10g\t%.4g\n", v, se);
    }
    return bad ? -1 : 0;
}
