/* tcaf.c - transverse current autocorrelation functions and eta(k)
 * (Mai-Duy et al. 2019, eqs 22-28). See tcaf.h. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_statistics_double.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "tcaf.h"
#include "blockavg.h"

static int selected(const Tcaf *t, const System *s, int i)
{
    return !s->types[s->type[i]].frozen && (t->p.type < 0 || s->type[i] == t->p.type);
}

/* Order of shells: by |k|. */
typedef struct { double k; int n2; } ShellKey;

int tcaf_init(Tcaf *t, const TcafParams *p, const System *s, int nblocks, long long prod_steps)
{
    const int dim = s->box.dim;
    memset(t, 0, sizeof *t);
    t->on = 1;
    t->p = *p;
    t->nblocks = nblocks;
    t->nlags = t->p.window / t->p.every + 1;
    t->nslots = t->p.window / t->p.origin_every + 1;
    t->norig_expected = prod_steps >= t->p.window ? (prod_steps - t->p.window) / t->p.origin_every + 1 : 0;
    const int ns2 = (int)floor(sqrt((double)t->p.n2max) + 1e-9);
    const int nm = t->p.axis_nmax > ns2 ? t->p.axis_nmax : ns2;
    if (nm > TCAF_NMAX) return -1;   /* phase tables of tcaf_current */
    for (int d = 0; d < 3; d++) t->nmax[d] = d < dim ? nm : 0;
    /* half space of integer vectors: i > 0, or i = 0 and j > 0, or i = j = 0 and l > 0 */
    int cap = (2 * nm + 1) * (2 * nm + 1) * (2 * nm + 1);
    t->vec = malloc((size_t)cap * 3 * sizeof(int));
    t->kvec = malloc((size_t)cap * 3 * sizeof(double));
    t->shell_of = malloc((size_t)cap * sizeof(int));
    ShellKey *keys = malloc((size_t)cap * sizeof *keys);
    if (!t->vec || !t->kvec || !t->shell_of || !keys) { free(keys); return -1; }
    int nv = 0;
    for (int i = 0; i <= t->nmax[0]; i++)
        for (int j = -t->nmax[1]; j <= t->nmax[1]; j++)
            for (int l = -t->nmax[2]; l <= t->nmax[2]; l++) {
                if (i == 0 && (j < 0 || (j == 0 && l <= 0))) continue;
                const int n2 = i * i + j * j + l * l;
                /* the sphere n^2 <= n2max, plus the axes up to axis_nmax */
                const int on_axis = (i != 0) + (j != 0) + (l != 0) == 1;
                if (n2 > t->p.n2max && !(on_axis && n2 <= t->p.axis_nmax * t->p.axis_nmax)) continue;
                const int c[3] = {i, j, l};
                for (int d = 0; d < 3; d++) {
                    t->vec[3 * nv + d] = c[d];
                    t->kvec[3 * nv + d] = d < dim ? 2.0 * M_PI * c[d] / s->box.L[d] : 0.0;
                }
                nv++;
            }
    t->nvec = nv;
    /* shells: equal |k| (to rounding) */
    int ns = 0;
    for (int v = 0; v < nv; v++) {
        const double *k = t->kvec + 3 * v;
        const double kk = sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
        const int *c = t->vec + 3 * v;
        int found = -1;
        for (int q = 0; q < ns; q++) if (fabs(keys[q].k - kk) <= 1e-9 * kk) { found = q; break; }
        if (found < 0) { keys[ns].k = kk; keys[ns].n2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2]; found = ns++; }
        t->shell_of[v] = found;
    }
    /* sort shells by |k| and renumber */
    int *order = malloc((size_t)(ns > 0 ? ns : 1) * sizeof(int)), *rank = malloc((size_t)(ns > 0 ? ns : 1) * sizeof(int));
    if (!order || !rank) { free(order); free(rank); free(keys); return -1; }
    for (int q = 0; q < ns; q++) order[q] = q;
    for (int a = 1; a < ns; a++)
        for (int b = a; b > 0 && keys[order[b]].k < keys[order[b - 1]].k; b--) {
            int x = order[b]; order[b] = order[b - 1]; order[b - 1] = x;
        }
    for (int q = 0; q < ns; q++) rank[order[q]] = q;
    t->nshell = ns;
    t->shell_k = malloc((size_t)(ns > 0 ? ns : 1) * sizeof(double));
    t->shell_n2 = calloc((size_t)(ns > 0 ? ns : 1), sizeof(int));
    t->shell_nvec = calloc((size_t)(ns > 0 ? ns : 1), sizeof(int));
    if (!t->shell_k || !t->shell_n2 || !t->shell_nvec) { free(order); free(rank); free(keys); return -1; }
    for (int q = 0; q < ns; q++) { t->shell_k[rank[q]] = keys[q].k; t->shell_n2[rank[q]] = keys[q].n2; }
    for (int v = 0; v < nv; v++) { t->shell_of[v] = rank[t->shell_of[v]]; t->shell_nvec[t->shell_of[v]]++; }
    free(order); free(rank); free(keys);
    /* selection */
    double mass = 0.0;
    t->count = 0;
    for (int i = 0; i < s->n; i++)
        if (selected(t, s, i)) { t->count++; mass += s->types[s->type[i]].mass; }
    double V = 1.0;
    for (int d = 0; d < dim; d++) V *= s->box.L[d];
    t->rho = mass / V;
    t->J = calloc((size_t)nv * 3 + 1, sizeof(double complex));
    t->origin = calloc((size_t)t->nslots * nv * 3 + 1, sizeof(double complex));
    t->origin_step = malloc((size_t)t->nslots * sizeof(long long));
    t->origin_index = calloc((size_t)t->nslots, sizeof(long long));
    t->curve = calloc((size_t)t->nslots * ns * t->nlags + 1, sizeof(double));
    t->acc = calloc((size_t)nblocks * ns * t->nlags + 1, sizeof(double));
    t->acc_n = calloc((size_t)nblocks, sizeof(long long));
    if (!t->J || !t->origin || !t->origin_step || !t->origin_index || !t->curve || !t->acc || !t->acc_n) return -1;
    for (int k = 0; k < t->nslots; k++) t->origin_step[k] = -1;
    t->nstarted = t->ndone = 0;
    return 0;
}

void tcaf_io(Io *io, Tcaf *t)
{
    io_array(io, t->origin, (size_t)t->nslots * t->nvec * 3, sizeof(double complex), "tcaf origins");
    io_array(io, t->origin_step, (size_t)t->nslots, sizeof(long long), "tcaf origin steps");
    io_array(io, t->origin_index, (size_t)t->nslots, sizeof(long long), "tcaf origin indices");
    io_array(io, t->curve, (size_t)t->nslots * t->nshell * t->nlags, sizeof(double), "tcaf curves");
    io_array(io, t->acc, (size_t)t->nblocks * t->nshell * t->nlags, sizeof(double), "tcaf blocks");
    io_array(io, t->acc_n, (size_t)t->nblocks, sizeof(long long), "tcaf block origins");
    io_bytes(io, &t->nstarted, sizeof t->nstarted, "tcaf origins started");
    io_bytes(io, &t->ndone, sizeof t->ndone, "tcaf origins done");
}

void tcaf_free(Tcaf *t)
{
    free(t->vec); free(t->kvec); free(t->shell_of); free(t->shell_k); free(t->shell_n2);
    free(t->shell_nvec); free(t->J); free(t->origin); free(t->origin_step); free(t->origin_index);
    free(t->curve); free(t->acc); free(t->acc_n);
    memset(t, 0, sizeof *t);
}

#define TCAF_CHUNKS 4   /* fixed partial sums of J(k): independent of the thread count */

/* J(k) = sum_j v_j exp(i k.r_j) (eq. 23). The phases come from per-particle
 * tables exp(i 2 pi m x_d / L_d), m = -nmax..nmax, so each vector costs two
 * complex products per particle. The particles are cut into TCAF_CHUNKS
 * fixed ranges summed apart and added in chunk order, so J does not depend
 * on the thread count (as the forces, forces.h). */
void tcaf_current(Tcaf *t, const System *s)
{
    const int nv = t->nvec, n = s->n;
    const int M[3] = {t->nmax[0], t->nmax[1], t->nmax[2]};
    const int W = 2 * (M[0] > M[1] ? (M[0] > M[2] ? M[0] : M[2]) : (M[1] > M[2] ? M[1] : M[2])) + 1;
    double complex *part = calloc((size_t)TCAF_CHUNKS * nv * 3 + 1, sizeof(double complex));
    if (!part) { memset(t->J, 0, (size_t)nv * 3 * sizeof(double complex)); return; }
    #pragma omp parallel for schedule(static, 1)
    for (int chunk = 0; chunk < TCAF_CHUNKS; chunk++) {
        double complex *Jp = part + (size_t)chunk * nv * 3;
        /* phase tables as (re, im) pairs: plain real arithmetic (complex
         * products in C11 without -ffast-math go through a NaN-safe libcall) */
        double er[3][2 * TCAF_NMAX + 1], ei[3][2 * TCAF_NMAX + 1];
        const int off = (W - 1) / 2;
        const int i0 = (int)((long long)n * chunk / TCAF_CHUNKS), i1 = (int)((long long)n * (chunk + 1) / TCAF_CHUNKS);
        for (int i = i0; i < i1; i++) {
            if (!selected(t, s, i)) continue;
            for (int d = 0; d < 3; d++) {
                const double ph = M[d] > 0 ? 2.0 * M_PI * s->x[3 * i + d] / s->box.L[d] : 0.0;
                const double br = cos(ph), bi = sin(ph);
                er[d][off] = 1.0; ei[d][off] = 0.0;
                for (int m = 1; m <= M[d]; m++) {
                    er[d][off + m] = er[d][off + m - 1] * br - ei[d][off + m - 1] * bi;
                    ei[d][off + m] = er[d][off + m - 1] * bi + ei[d][off + m - 1] * br;
                    er[d][off - m] = er[d][off + m];
                    ei[d][off - m] = -ei[d][off + m];
                }
            }
            const double *v = s->v + 3 * i;
            double *Jr = (double *)Jp;   /* complex = (re, im) array, C11 6.2.5 */
            for (int q = 0; q < nv; q++) {
                const int *c = t->vec + 3 * q;
                const double ar = er[0][off + c[0]], ai = ei[0][off + c[0]];
                const double br = er[1][off + c[1]], bi = ei[1][off + c[1]];
                const double cr = er[2][off + c[2]], ci = ei[2][off + c[2]];
                const double abr = ar * br - ai * bi, abi = ar * bi + ai * br;
                const double pr = abr * cr - abi * ci, pi = abr * ci + abi * cr;
                double *o = Jr + 6 * q;
                o[0] += v[0] * pr; o[1] += v[0] * pi;
                o[2] += v[1] * pr; o[3] += v[1] * pi;
                o[4] += v[2] * pr; o[5] += v[2] * pi;
            }
        }
    }
    for (int q = 0; q < 3 * nv; q++) {
        double complex sum = 0.0;
        for (int h = 0; h < TCAF_CHUNKS; h++) sum += part[(size_t)h * nv * 3 + q];
        t->J[q] = sum;
    }
    free(part);
    /* momentum of rigid bodies (spring-model colloids), if asked for */
    for (int b = 0; b < t->nbody; b++)
        for (int q = 0; q < nv; q++) {
            const double *k = t->kvec + 3 * q, *R = t->body_R + 3 * b, *V = t->body_V + 3 * b;
            const double ph = k[0] * R[0] + k[1] * R[1] + k[2] * R[2];
            const double complex e = cos(ph) + I * sin(ph);
            for (int d = 0; d < 3; d++) t->J[3 * q + d] += t->body_mass * V[d] * e;
        }
}

void tcaf_set_bodies(Tcaf *t, const System *s, int nbody, const double *R, const double *V, double M)
{
    double vol = 1.0;
    for (int d = 0; d < s->box.dim; d++) vol *= s->box.L[d];
    t->nbody = nbody;
    t->body_R = R;
    t->body_V = V;
    t->body_mass = M;
    t->rho += nbody * M / vol;
}

void tcaf_transverse(const double k[3], const double complex J[3], double complex out[3])
{
    const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    const double complex kJ = k[0] * J[0] + k[1] * J[1] + k[2] * J[2];
    for (int d = 0; d < 3; d++) out[d] = J[d] - k[d] * kJ / k2;   /* (1 - k k / k^2) J, eq. 25 */
}

static int block_of(const Tcaf *t, long long index)
{
    const long long nb = t->nblocks, ne = t->norig_expected > 0 ? t->norig_expected : 1;
    const long long b = index * nb / ne;
    return (int)(b >= nb ? nb - 1 : b);
}

void tcaf_sample(Tcaf *t, const System *s, long long step)
{
    const int nv = t->nvec, ns = t->nshell, L = t->nlags;
    tcaf_current(t, s);
    for (int q = 0; q < nv; q++) {
        double complex jp[3];
        tcaf_transverse(t->kvec + 3 * q, t->J + 3 * q, jp);
        memcpy(t->J + 3 * q, jp, sizeof jp);
    }
    if (step % t->p.origin_every == 0) {
        const int slot = (int)((step / t->p.origin_every) % t->nslots);
        memcpy(t->origin + (size_t)slot * nv * 3, t->J, (size_t)nv * 3 * sizeof(double complex));
        t->origin_step[slot] = step;
        t->origin_index[slot] = t->nstarted++;
        memset(t->curve + (size_t)slot * ns * L, 0, (size_t)ns * L * sizeof(double));
    }
    for (int slot = 0; slot < t->nslots; slot++) {
        const long long t0 = t->origin_step[slot];
        if (t0 < 0 || step - t0 > t->p.window) continue;
        const int lag = (int)((step - t0) / t->p.every);
        const double complex *o = t->origin + (size_t)slot * nv * 3;
        double *cur = t->curve + (size_t)slot * ns * L;
        for (int q = 0; q < nv; q++) {
            /* Re J_perp(-k,0) . J_perp(k,t), J(-k) = conj J(k) (eq. 26) */
            double c = 0.0;
            for (int d = 0; d < 3; d++)
                c += creal(o[3 * q + d]) * creal(t->J[3 * q + d]) + cimag(o[3 * q + d]) * cimag(t->J[3 * q + d]);
            cur[(size_t)t->shell_of[q] * L + lag] += c;
        }
        if (lag == L - 1) {
            const int b = block_of(t, t->origin_index[slot]);
            double *a = t->acc + (size_t)b * ns * L;
            for (int k = 0; k < ns * L; k++) a[k] += cur[k];
            t->acc_n[b]++;
            t->ndone++;
            t->origin_step[slot] = -1;
        }
    }
}

/* eq. 28: f_i = exp(-eta k^2 t_i / rho) - c_i */
typedef struct { const double *t, *c; int n; double a; } FitData;   /* a = k^2 / rho */

static int decay_f(const gsl_vector *p, void *data, gsl_vector *f)
{
    const FitData *d = data;
    const double eta = gsl_vector_get(p, 0);
    for (int i = 0; i < d->n; i++) gsl_vector_set(f, i, exp(-eta * d->a * d->t[i]) - d->c[i]);
    return GSL_SUCCESS;
}

static int decay_df(const gsl_vector *p, void *data, gsl_matrix *J)
{
    const FitData *d = data;
    const double eta = gsl_vector_get(p, 0);
    for (int i = 0; i < d->n; i++) gsl_matrix_set(J, i, 0, -d->a * d->t[i] * exp(-eta * d->a * d->t[i]));
    return GSL_SUCCESS;
}

int tcaf_fit_eta(const double *t, const double *c, int n, double k2, double rho, double *eta)
{
    *eta = NAN;
    if (n < 2 || k2 <= 0 || rho <= 0) return -1;
    FitData d = {t, c, n, k2 / rho};
    /* start from the log-slope of the first point that is positive */
    double p0 = 1.0;
    for (int i = 0; i < n; i++)
        if (t[i] > 0 && c[i] > 0 && c[i] < 1) { p0 = -log(c[i]) / (d.a * t[i]); break; }
    gsl_multifit_nlinear_fdf fdf = {.f = decay_f, .df = decay_df, .n = (size_t)n, .p = 1, .params = &d};
    gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
    gsl_multifit_nlinear_workspace *w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, (size_t)n, 1);
    if (!w) return -1;
    gsl_vector *x = gsl_vector_alloc(1);
    gsl_vector_set(x, 0, p0);
    gsl_multifit_nlinear_init(x, &fdf, w);
    int info = 0;
    const int st = gsl_multifit_nlinear_driver(200, 1e-12, 1e-12, 1e-12, NULL, NULL, &info, w);
    if (st == GSL_SUCCESS) *eta = gsl_vector_get(gsl_multifit_nlinear_position(w), 0);
    gsl_vector_free(x);
    gsl_multifit_nlinear_free(w);
    return st == GSL_SUCCESS && isfinite(*eta) ? 0 : -1;
}

int tcaf_extrapolate(const double *k, const double *eta, const double *w, int n, int order, double *coef)
{
    return tcaf_extrapolate_cov(k, eta, w, n, order, coef, NULL, NULL);
}

int tcaf_extrapolate_cov(const double *k, const double *eta, const double *w, int n, int order, double *coef,
                         double *covariance, double *chi2_out)
{
    const int p = order + 1;
    for (int j = 0; j < p; j++) coef[j] = NAN;
    if (n < p || order < 0) return -1;
    gsl_matrix *X = gsl_matrix_alloc((size_t)n, (size_t)p), *cov = gsl_matrix_alloc((size_t)p, (size_t)p);
    gsl_vector *y = gsl_vector_alloc((size_t)n), *wv = gsl_vector_alloc((size_t)n), *c = gsl_vector_alloc((size_t)p);
    gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc((size_t)n, (size_t)p);
    int rc = -1;
    if (X && cov && y && wv && c && ws) {
        for (int i = 0; i < n; i++) {
            double xp = 1.0;
            for (int j = 0; j < p; j++) { gsl_matrix_set(X, i, j, xp); xp *= k[i] * k[i]; }
            gsl_vector_set(y, i, eta[i]);
            gsl_vector_set(wv, i, w[i]);
        }
        double chi2;
        if (gsl_multifit_wlinear(X, wv, y, c, cov, &chi2, ws) == GSL_SUCCESS) {
            for (int j = 0; j < p; j++) coef[j] = gsl_vector_get(c, j);
            if (covariance)
                for (int a = 0; a < p; a++)
                    for (int b = 0; b < p; b++) covariance[a * p + b] = gsl_matrix_get(cov, (size_t)a, (size_t)b);
            if (chi2_out) *chi2_out = chi2;
            rc = 0;
        }
    }
    gsl_matrix_free(X); gsl_matrix_free(cov); gsl_vector_free(y); gsl_vector_free(wv); gsl_vector_free(c);
    gsl_multifit_linear_free(ws);
    return rc;
}

/* Mean and standard error of the finite values among n <= MAX_BLOCKS. */
static double mean_se(const double *v, int n, double *se)
{
    int m = 0;
    double buf[MAX_BLOCKS];
    if (n > MAX_BLOCKS) { *se = NAN; return NAN; }   /* more than buf holds */
    for (int i = 0; i < n; i++) if (isfinite(v[i])) buf[m++] = v[i];
    *se = m > 1 ? gsl_stats_sd(buf, 1, (size_t)m) / sqrt((double)m) : NAN;
    return m > 0 ? gsl_stats_mean(buf, 1, (size_t)m) : NAN;
}

/* eta(k -> 0): the polynomial in k^2 weighted by 1/se^2 over the shells with
 * |k| <= extrap_kmax and a finite error (coef), its error from the same fit of
 * each of the B blocks (coef_se), and the largest |k| used. Returns the number
 * of shells used, or -1 (out of memory, or B or the order beyond the arrays). */
static int extrapolate_k0(const Tcaf *t, const double *eta, const double *eta_se, const double *etab, int B,
                          double *coef, double *coef_se, double *kend)
{
    const int ns = t->nshell;
    double cb_all[MAX_BLOCKS], coefb[TCAF_MAX_ORDER + 1];
    if (B > MAX_BLOCKS || t->p.extrap_order > TCAF_MAX_ORDER) return -1;
    double *kx = calloc((size_t)ns + 1, sizeof(double)), *ex = calloc((size_t)ns + 1, sizeof(double));
    double *wx = calloc((size_t)ns + 1, sizeof(double)), *eb = calloc((size_t)ns + 1, sizeof(double));
    int *idx = calloc((size_t)ns + 1, sizeof(int)), nx = 0;
    if (!kx || !ex || !wx || !eb || !idx) { free(kx); free(ex); free(wx); free(eb); free(idx); return -1; }
    for (int q = 0; q < ns; q++)
        if (t->shell_k[q] <= t->p.extrap_kmax * (1 + 1e-12) && isfinite(eta[q]) && isfinite(eta_se[q]) && eta_se[q] > 0) {
            kx[nx] = t->shell_k[q]; ex[nx] = eta[q]; wx[nx] = 1.0 / (eta_se[q] * eta_se[q]); idx[nx] = q; nx++;
        }
    tcaf_extrapolate(kx, ex, wx, nx, t->p.extrap_order, coef);
    for (int p = 0; p <= t->p.extrap_order; p++) {
        for (int j = 0; j < B; j++) {
            for (int i = 0; i < nx; i++) eb[i] = etab[(size_t)j * ns + idx[i]];
            tcaf_extrapolate(kx, eb, wx, nx, t->p.extrap_order, coefb);
            cb_all[j] = coefb[p];
        }
        mean_se(cb_all, B, &coef_se[p]);
    }
    *kend = 0.0;
    for (int i = 0; i < nx; i++) *kend = fmax(*kend, kx[i]);
    free(kx); free(ex); free(wx); free(eb); free(idx);
    return nx;
}

int tcaf_write(const Tcaf *t, const System *s, FILE *summary, const char *dir)
{
    const int ns = t->nshell, L = t->nlags, dim = s->box.dim, npol = dim - 1;
    const double dts = t->p.every * s->dt;
    /* blocks that completed at least one origin */
    int B = 0, blk[MAX_BLOCKS];
    if (t->nblocks > MAX_BLOCKS) return -1;   /* more than blk and the per-block statistics hold */
    for (int b = 0; b < t->nblocks; b++) if (t->acc_n[b] > 0) blk[B++] = b;
    /* mean 1/m of the selection: equipartition C(k,0) = k^2 kBT <1/m> */
    double invm = 0.0;
    for (int i = 0; i < s->n; i++) if (selected(t, s, i)) invm += 1.0 / s->types[s->type[i]].mass;
    invm = t->count > 0 ? invm / t->count : NAN;
    /* C_perp per block (eq. 26) and over all origins */
    double *Cb = calloc((size_t)(B > 0 ? B : 1) * ns * L, sizeof(double)), *C = calloc((size_t)ns * L + 1, sizeof(double));
    double *eta = malloc((size_t)ns * sizeof(double)), *eta_se = malloc((size_t)ns * sizeof(double));
    double *etab = malloc((size_t)(B > 0 ? B : 1) * ns * sizeof(double));
    double *c0r = malloc((size_t)ns * sizeof(double)), *c0r_se = malloc((size_t)ns * sizeof(double));
    int *nfit = calloc((size_t)ns, sizeof(int));
    double *tt = malloc((size_t)L * sizeof(double)), *cc = malloc((size_t)L * sizeof(double)), *tmp = malloc(MAX_BLOCKS * sizeof(double));
    if (!Cb || !C || !eta || !eta_se || !etab || !c0r || !c0r_se || !nfit || !tt || !cc || !tmp) {
        free(Cb); free(C); free(eta); free(eta_se); free(etab); free(c0r); free(c0r_se); free(nfit); free(tt); free(cc); free(tmp);
        return -1;
    }
    for (int q = 0; q < ns; q++) {
        const double k2 = t->shell_k[q] * t->shell_k[q];
        const double norm = k2 / (t->count * (double)npol * t->shell_nvec[q]);
        for (int l = 0; l < L; l++) {
            double sum = 0.0;
            for (int j = 0; j < B; j++) {
                const double *a = t->acc + (size_t)blk[j] * ns * L;
                Cb[((size_t)j * ns + q) * L + l] = a[(size_t)q * L + l] * norm / t->acc_n[blk[j]];
                sum += a[(size_t)q * L + l];
            }
            C[(size_t)q * L + l] = t->ndone > 0 ? sum * norm / t->ndone : NAN;
        }
        /* equipartition check */
        for (int j = 0; j < B; j++) tmp[j] = Cb[((size_t)j * ns + q) * L] / (k2 * s->kBT * invm);
        double se;
        mean_se(tmp, B, &se);
        c0r[q] = C[(size_t)q * L] / (k2 * s->kBT * invm);
        c0r_se[q] = se;
        /* fit window: lags 1.. while the average normalised TCAF stays >= fit_min */
        int n = 0;
        for (int l = 1; l < L; l++) {
            const double c = C[(size_t)q * L + l] / C[(size_t)q * L];
            if (!(c >= t->p.fit_min)) break;
            n++;
        }
        nfit[q] = n;
        eta[q] = eta_se[q] = NAN;
        for (int j = 0; j < B; j++) etab[(size_t)j * ns + q] = NAN;
        if (n < 3) continue;   /* decay not resolved by the sampling interval */
        for (int l = 0; l < n; l++) { tt[l] = (l + 1) * dts; cc[l] = C[(size_t)q * L + l + 1] / C[(size_t)q * L]; }
        tcaf_fit_eta(tt, cc, n, k2, t->rho, &eta[q]);
        for (int j = 0; j < B; j++) {
            const double *cb = Cb + ((size_t)j * ns + q) * L;
            for (int l = 0; l < n; l++) cc[l] = cb[l + 1] / cb[0];
            double e;
            tcaf_fit_eta(tt, cc, n, k2, t->rho, &e);
            etab[(size_t)j * ns + q] = e;
            tmp[j] = e;
        }
        mean_se(tmp, B, &eta_se[q]);
    }
    /* k -> 0: weighted polynomial in k^2 over the shells with |k| <= extrap_kmax */
    const int P = t->p.extrap_order + 1;
    double coef[TCAF_MAX_ORDER + 1], coef_se[TCAF_MAX_ORDER + 1], kend = 0.0;
    const int nx = extrapolate_k0(t, eta, eta_se, etab, B, coef, coef_se, &kend);
    if (nx < 0) {
        free(Cb); free(C); free(eta); free(eta_se); free(etab); free(c0r); free(c0r_se); free(nfit); free(tt); free(cc); free(tmp);
        return -1;
    }
    /* eta(first shell) - eta(last fitted shell), block by block */
    int qlast = -1;
    for (int q = 0; q < ns; q++) if (isfinite(eta[q])) qlast = q;
    double drop = NAN, drop_se = NAN;
    if (qlast > 0 && isfinite(eta[0])) {
        drop = eta[0] - eta[qlast];
        for (int j = 0; j < B; j++) tmp[j] = etab[(size_t)j * ns] - etab[(size_t)j * ns + qlast];
        mean_se(tmp, B, &drop_se);
    }
    /* summary */
    fprintf(summary, "tcaf_eta_k0\t%.10g\t%.4g\n", coef[0], coef_se[0]);
    if (P > 1) fprintf(summary, "tcaf_eta_k2_coefficient\t%.10g\t%.4g\n", coef[1], coef_se[1]);
    if (P > 2) fprintf(summary, "tcaf_eta_k4_coefficient\t%.10g\t%.4g\n", coef[2], coef_se[2]);
    fprintf(summary, "tcaf_eta_drop\t%.10g\t%.4g\n", drop, drop_se);
    for (int q = 0; q < ns; q++)
        fprintf(summary, "tcaf_eta_n2_%d\t%.10g\t%.4g\n", t->shell_n2[q], eta[q], eta_se[q]);
    {
        double r = 0.0;
        int m = 0;
        for (int j = 0; j < B; j++) {
            double sum = 0.0;
            for (int q = 0; q < ns; q++) sum += Cb[((size_t)j * ns + q) * L] / (t->shell_k[q] * t->shell_k[q] * s->kBT * invm);
            tmp[m++] = sum / ns;
        }
        double se;
        for (int q = 0; q < ns; q++) r += c0r[q];
        mean_se(tmp, m, &se);
        fprintf(summary, "tcaf_C0_equipartition_ratio\t%.10g\t%.4g\n", ns > 0 ? r / ns : NAN, se);
    }
    fprintf(summary, "tcaf_origins\t%lld\t0\n", t->ndone);
    fprintf(summary, "tcaf_vectors\t%d\t0\n", t->nvec);
    fprintf(summary, "tcaf_shells\t%d\t0\n", ns);
    fprintf(summary, "tcaf_extrapolation_shells\t%d\t0\n", nx);
    fprintf(summary, "tcaf_mass_density\t%.10g\t0\n", t->rho);
    /* tables */
    int rc = 0;
    char path[1024];
    snprintf(path, sizeof path, "%s/tcaf.tsv", dir);
    FILE *f = fopen(path, "w");
    if (f) {
        fprintf(f, "# C_perp(k,t)/C_perp(k,0) (eqs 26, 28) averaged over %lld time origins; se over %d blocks of origins\n", t->ndone, B);
        fprintf(f, "# column 2+2q: shell q (0-based) of tcaf_eta.tsv\n");
        fprintf(f, "t");
        for (int q = 0; q < ns; q++) fprintf(f, "\tc_n2_%d\tc_n2_%d_se", t->shell_n2[q], t->shell_n2[q]);
        fputc('\n', f);
        for (int l = 0; l < L; l++) {
            fprintf(f, "%.6g", l * dts);
            for (int q = 0; q < ns; q++) {
                for (int j = 0; j < B; j++) { const double *cb = Cb + ((size_t)j * ns + q) * L; tmp[j] = cb[l] / cb[0]; }
                double se;
                mean_se(tmp, B, &se);
                fprintf(f, "\t%.6g\t%.3g", C[(size_t)q * L + l] / C[(size_t)q * L], se);
            }
            fputc('\n', f);
        }
        rc |= fclose(f);
    } else rc = -1;
    snprintf(path, sizeof path, "%s/tcaf_eta.tsv", dir);
    f = fopen(path, "w");
    if (f) {
        fprintf(f, "# eta(k) from C/C0 = exp(-eta k^2 t / rho) (eq. 28), rho = %g, fit over the lags with <C/C0> >= %g;\n"
                   "# se from %d blocks of time origins; k -> 0: weighted polynomial of degree %d in k^2 over |k| <= %g:",
                t->rho, t->p.fit_min, B, t->p.extrap_order, t->p.extrap_kmax);
        for (int p = 0; p < P; p++) fprintf(f, " c%d = %.6g +- %.3g", p, coef[p], coef_se[p]);
        fprintf(f, "\nk\tn2\tvectors\teta\teta_se\tfit_points\tfit_tmax\tC0_ratio\tC0_ratio_se\teta_extrapolation\n");
        for (int q = 0; q < ns; q++) {
            double fit = 0.0, xp = 1.0;
            for (int p = 0; p < P; p++) { fit += coef[p] * xp; xp *= t->shell_k[q] * t->shell_k[q]; }
            fprintf(f, "%.6g\t%d\t%d\t%.8g\t%.3g\t%d\t%.4g\t%.6g\t%.3g\t%.6g\n", t->shell_k[q], t->shell_n2[q],
                    t->shell_nvec[q], eta[q], eta_se[q], nfit[q], nfit[q] * dts, c0r[q], c0r_se[q],
                    t->shell_k[q] <= t->p.extrap_kmax * (1 + 1e-12) ? fit : NAN);
        }
        rc |= fclose(f);
    } else rc = -1;
    /* the k -> 0 fit as a curve from k = 0 */
    snprintf(path, sizeof path, "%s/tcaf_extrapolation.tsv", dir);
    f = fopen(path, "w");
    if (f) {
        fprintf(f, "k\teta_fit\n");
        for (int i = 0; i <= 40; i++) {
            const double k = kend * i / 40.0;
            double fit = 0.0, xp = 1.0;
            for (int p = 0; p < P; p++) { fit += coef[p] * xp; xp *= k * k; }
            fprintf(f, "%.6g\t%.8g\n", k, fit);
        }
        rc |= fclose(f);
    } else rc = -1;
    free(Cb); free(C); free(eta); free(eta_se); free(etab); free(c0r); free(c0r_se); free(nfit); free(tt); free(cc); free(tmp);
    return rc ? -1 : 0;
}
