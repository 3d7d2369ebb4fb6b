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
#include "simd.h"
#include "tcaf_sums.h"

static int selected(const Tcaf *t, const System *s, int i)
{
    return !s->types[s->type[i]].frozen && (t->p.type < 0 || s->type[i] == t->p.type);
}

/* Order of shells: by |k|. */
typedef struct { double k; int n2; } ShellKey;

/* The wave vectors: the half space of integer vectors (i > 0, or i = 0 and
 * j > 0, or i = j = 0 and l > 0) in the sphere n^2 <= n2max, plus the axes up
 * to axis_nmax; components up to nmax[d]. */
static int wave_vectors(Tcaf *t, const Box *box)
{
    const int dim = box->dim, nm = t->nmax[0];
    const int cap = (2 * nm + 1) * (2 * nm + 1) * (2 * nm + 1);
    t->vec = malloc((size_t)cap * 3 * sizeof(int));
    t->kvec = malloc((size_t)cap * 3 * sizeof(double));
    t->shell_of = malloc((size_t)cap * sizeof(int));
    if (!t->vec || !t->kvec || !t->shell_of) return -1;
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
                    t->kvec[3 * nv + d] = d < dim ? 2.0 * M_PI * c[d] / box->L[d] : 0.0;
                }
                nv++;
            }
    t->nvec = nv;
    return 0;
}

/* Shells of equal |k| (to rounding), numbered by |k|, with their n^2 and
 * number of vectors. */
static int shells(Tcaf *t)
{
    const int nv = t->nvec;
    ShellKey *keys = malloc((size_t)(nv > 0 ? nv : 1) * sizeof *keys);
    if (!keys) return -1;
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
    return 0;
}

/* The selected particles, their mass density, and the sample buffers. */
static int buffers(Tcaf *t, const System *s)
{
    const int nv = t->nvec, ns = t->nshell, nblocks = t->nblocks;
    double mass = 0.0;
    t->count = 0;
    for (int i = 0; i < s->n; i++)
        if (selected(t, s, i)) { t->count++; mass += s->types[s->type[i]].mass; }
    double V = 1.0;
    for (int d = 0; d < s->box.dim; d++) V *= s->box.L[d];
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

static int work_arrays(Tcaf *t);

int tcaf_init(Tcaf *t, const TcafParams *p, const System *s, int nblocks, long long prod_steps)
{
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
    for (int d = 0; d < 3; d++) t->nmax[d] = d < s->box.dim ? nm : 0;
    return wave_vectors(t, &s->box) || shells(t) || buffers(t, s) || work_arrays(t) ? -1 : 0;
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
    free(t->run); free(t->item); free(t->lane_sum); free(t->tabs); free(t->abuf);
    memset(t, 0, sizeof *t);
}

#define TCAF_CHUNKS 4   /* fixed partial sums of J(k): independent of the thread count */

/* J(k) = sum_j v_j exp(i k.r_j) (eq. 23), eight particles side by side.
 *
 * Phases: per particle the tables e^{i m k_d x_d}, m = 0 ... nmax[d], from one
 * sine and cosine and a recurrence; e^{-i m k_d x_d} is their conjugate. The
 * wave vectors come in runs of fixed (i, j) and consecutive l (the order of
 * wave_vectors): e^{i(k_x x + k_y y)} is formed once per run, then times
 * e^{+-i l k_z z}. The vectors l and -l of a run share the four products
 * ab_r c_r, ab_i c_i, ab_r c_i, ab_i c_r, and each still gets the bits of its
 * own complex product (ab)(c) or (ab)(conj c).
 *
 * Sums: lane k of a tile of TCAF_LANES particles keeps its own running sums
 * (nvec x 6 x TCAF_LANES), added over the lanes in lane order at the end, and
 * the TCAF_CHUNKS fixed particle ranges in chunk order: J does not depend on
 * the thread count, nor on the instruction set (the same IEEE operations in
 * every lane, no contraction). Particles side by side, not wave vectors: the
 * runs are 1 to 11 vectors long, which lanes of wave vectors had to pad.
 * TCAF_LANES, the runs and items, the layout and the block sums: tcaf_sums.h. */
#define TCAF_TILES 32   /* tiles of TCAF_LANES particles per block (80 KB of tables at n2max = 25; 8, 16, 32, 64: 0.98, 0.88, 0.86, 0.85 s per 600 steps of fig01's scene) */

static TcafLayout tcaf_layout(const Tcaf *t)
{
    const int *M = t->nmax;
    const int b = 2 * (M[0] + 1), c = b + 2 * (M[1] + 1), v = c + 2 * (M[2] + 1);
    return (TcafLayout){.a = 0, .b = b, .c = c, .v = v, .stride = v + 3};
}

static int find_vector(const Tcaf *t, int q0, int q1, int l)
{
    for (int q = q0; q < q1; q++) if (t->vec[3 * q + 2] == l) return q;
    return -1;
}

/* The runs and their items; the lanes' sums, the tiles and the run factors
 * per chunk, 64-byte aligned for the vector loads. */
static int work_arrays(Tcaf *t)
{
    const TcafLayout lay = tcaf_layout(t);
    t->run = malloc((size_t)t->nvec * sizeof *t->run + 1);
    t->item = malloc((size_t)t->nvec * sizeof *t->item + 1);
    if (!t->run || !t->item) return -1;
    int nr = 0, ni = 0;
    for (int q0 = 0, q1; q0 < t->nvec; q0 = q1) {
        const int *c = t->vec + 3 * q0;
        int lmax = abs(c[2]);
        for (q1 = q0 + 1; q1 < t->nvec && t->vec[3 * q1] == c[0] && t->vec[3 * q1 + 1] == c[1]; q1++)
            if (abs(t->vec[3 * q1 + 2]) > lmax) lmax = abs(t->vec[3 * q1 + 2]);
        t->run[nr] = (TcafRun){.i = c[0], .j = abs(c[1]), .jneg = c[1] < 0, .it0 = ni};
        for (int l = 0; l <= lmax; l++) {
            const TcafItem it = {.l = l, .qp = find_vector(t, q0, q1, l), .qm = l > 0 ? find_vector(t, q0, q1, -l) : -1};
            if (it.qp < 0 && it.qm >= 0) return -1;   /* not a half space */
            if (it.qp >= 0) t->item[ni++] = it;
        }
        t->run[nr++].it1 = ni;
    }
    t->nrun = nr;
    const size_t lanes = (size_t)TCAF_CHUNKS * t->nvec * 6 * TCAF_LANES;
    const size_t tabs = (size_t)TCAF_CHUNKS * TCAF_TILES * lay.stride * TCAF_LANES;
    const size_t abuf = (size_t)TCAF_CHUNKS * TCAF_TILES * 2 * TCAF_LANES;
    t->lane_sum = aligned_alloc(64, (lanes * sizeof(double) + 63) / 64 * 64);
    t->tabs = aligned_alloc(64, (tabs * sizeof(double) + 63) / 64 * 64);
    t->abuf = aligned_alloc(64, (abuf * sizeof(double) + 63) / 64 * 64);
    return t->lane_sum && t->tabs && t->abuf ? 0 : -1;
}

/* Lane k of tile p: particle i's tables and velocity. The three recurrences
 * run side by side (each is a chain of dependent products). */
static void phase_tables(double *p, int k, TcafLayout lay, const System *s, int i, const int M[3])
{
    const int row0[3] = {lay.a, lay.b, lay.c}, mmax = M[0] > M[1] ? (M[0] > M[2] ? M[0] : M[2]) : (M[1] > M[2] ? M[1] : M[2]);
    double br[3], bi[3], *e[3];
    for (int d = 0; d < 3; d++) {
        const double a = M[d] > 0 ? 2.0 * M_PI * s->x[3 * i + d] / s->box.L[d] : 0.0;
        br[d] = cos(a); bi[d] = sin(a);
        e[d] = p + (size_t)row0[d] * TCAF_LANES + k;
        e[d][0] = 1.0; e[d][TCAF_LANES] = 0.0;
        p[(size_t)(lay.v + d) * TCAF_LANES + k] = s->v[3 * i + d];
    }
    for (int m = 1; m <= mmax; m++)
        for (int d = 0; d < 3; d++) {
            if (m > M[d]) continue;
            const double *o = e[d] + (size_t)(2 * m - 2) * TCAF_LANES;
            double *n = e[d] + (size_t)(2 * m) * TCAF_LANES;
            n[0] = o[0] * br[d] - o[TCAF_LANES] * bi[d];
            n[TCAF_LANES] = o[0] * bi[d] + o[TCAF_LANES] * br[d];
        }
}

/* A tile's lanes beyond the last particle: zero tables and velocity, which
 * add zeros to those lanes' sums. */
static void clear_lanes(double *p, int k0, TcafLayout lay)
{
    for (int r = 0; r < lay.stride; r++)
        for (int k = k0; k < TCAF_LANES; k++) p[(size_t)r * TCAF_LANES + k] = 0.0;
}

/* The block sums (tcaf_sums.h) on two lanes at a time, for any x86-64 (SSE2);
 * the backend has them on four (AVX2) and eight (AVX-512): simd.h
 * SimdKernels.tcaf_block_sums. */
TCAF_BLOCK_SUMS(block_sums_portable, tcaf_v2, 2, static)

void tcaf_current(Tcaf *t, const System *s)
{
    const int nv = t->nvec, n = s->n;
    const int M[3] = {t->nmax[0], t->nmax[1], t->nmax[2]};
    const TcafLayout lay = tcaf_layout(t);
    const size_t per_chunk = (size_t)nv * 6 * TCAF_LANES, tile = (size_t)lay.stride * TCAF_LANES;
    memset(t->lane_sum, 0, TCAF_CHUNKS * per_chunk * sizeof(double));
    const SimdKernels *sk = simd_kernels();
    const TcafBlockSumsFn block_sums = sk->tcaf_block_sums ? sk->tcaf_block_sums : block_sums_portable;
    #pragma omp parallel for schedule(static, 1)
    for (int chunk = 0; chunk < TCAF_CHUNKS; chunk++) {
        double *acc = t->lane_sum + chunk * per_chunk;
        double *tab = t->tabs + chunk * TCAF_TILES * tile, *abuf = t->abuf + (size_t)chunk * TCAF_TILES * 2 * TCAF_LANES;
        const int i0 = (int)((long long)n * chunk / TCAF_CHUNKS), i1 = (int)((long long)n * (chunk + 1) / TCAF_CHUNKS);
        int nb = 0;   /* particles in the block */
        for (int i = i0; i < i1; i++) {
            if (!selected(t, s, i)) continue;
            phase_tables(tab + (size_t)(nb / TCAF_LANES) * tile, nb % TCAF_LANES, lay, s, i, M);
            if (++nb == TCAF_TILES * TCAF_LANES) { block_sums(t->run, t->nrun, t->item, &lay, tab, TCAF_TILES, abuf, acc); nb = 0; }
        }
        if (nb > 0) {
            if (nb % TCAF_LANES) clear_lanes(tab + (size_t)(nb / TCAF_LANES) * tile, nb % TCAF_LANES, lay);
            block_sums(t->run, t->nrun, t->item, &lay, tab, (nb + TCAF_LANES - 1) / TCAF_LANES, abuf, acc);
        }
    }
    /* the lanes' sums in lane order, then the chunks' in chunk order (as
     * complex sums: component by component) */
    for (int q = 0; q < nv; q++)
        for (int d = 0; d < 3; d++) {
            double z[2] = {0.0, 0.0};   /* (re, im), C11 6.2.5 */
            for (int h = 0; h < TCAF_CHUNKS; h++)
                for (int c = 0; c < 2; c++) {
                    const double *lane = t->lane_sum + h * per_chunk + ((size_t)q * 6 + 2 * d + c) * TCAF_LANES;
                    double sum = 0.0;
                    for (int k = 0; k < TCAF_LANES; k++) sum += lane[k];
                    z[c] += sum;
                }
            memcpy(&t->J[3 * q + d], z, sizeof z);
        }
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

/* Scratch arrays of one analysis: the blocks that completed an origin, C_perp
 * per block and over all origins, eta per block and shell, fit buffers. */
typedef struct {
    int B, blk[MAX_BLOCKS];
    double invm;              /* mean 1/m of the selection */
    double *Cb, *C;           /* B x ns x L, ns x L */
    double *etab;             /* B x ns */
    double *tt, *cc, *tmp;    /* L, L, MAX_BLOCKS */
} Work;

static void work_free(Work *w)
{
    free(w->Cb); free(w->C); free(w->etab); free(w->tt); free(w->cc); free(w->tmp);
}

static int work_alloc(Work *w, const Tcaf *t, const System *s)
{
    const int ns = t->nshell, L = t->nlags;
    memset(w, 0, sizeof *w);
    for (int b = 0; b < t->nblocks; b++) if (t->acc_n[b] > 0) w->blk[w->B++] = b;
    /* equipartition: C(k,0) = k^2 kBT <1/m> */
    for (int i = 0; i < s->n; i++) if (selected(t, s, i)) w->invm += 1.0 / s->types[s->type[i]].mass;
    w->invm = t->count > 0 ? w->invm / t->count : NAN;
    const size_t B1 = (size_t)(w->B > 0 ? w->B : 1);
    w->Cb = calloc(B1 * ns * L, sizeof(double));
    w->C = calloc((size_t)ns * L + 1, sizeof(double));
    w->etab = malloc(B1 * ns * sizeof(double));
    w->tt = malloc((size_t)L * sizeof(double));
    w->cc = malloc((size_t)L * sizeof(double));
    w->tmp = malloc(MAX_BLOCKS * sizeof(double));
    if (w->Cb && w->C && w->etab && w->tt && w->cc && w->tmp) return 0;
    work_free(w);
    return -1;
}

static int result_alloc(TcafResult *r, int ns, int L)
{
    r->c = malloc((size_t)ns * L * sizeof(double) + 1);
    r->c_se = malloc((size_t)ns * L * sizeof(double) + 1);
    r->eta = malloc((size_t)ns * sizeof(double) + 1);
    r->eta_se = malloc((size_t)ns * sizeof(double) + 1);
    r->c0_ratio = malloc((size_t)ns * sizeof(double) + 1);
    r->c0_ratio_se = malloc((size_t)ns * sizeof(double) + 1);
    r->fit_points = calloc((size_t)ns + 1, sizeof(int));
    return r->c && r->c_se && r->eta && r->eta_se && r->c0_ratio && r->c0_ratio_se && r->fit_points ? 0 : -1;
}

void tcaf_result_free(TcafResult *r)
{
    free(r->c); free(r->c_se); free(r->eta); free(r->eta_se); free(r->c0_ratio); free(r->c0_ratio_se);
    free(r->fit_points);
    memset(r, 0, sizeof *r);
}

/* C_perp(k,t) of eq. 26 per block (Cb) and over all origins (C). */
static void correlations(const Tcaf *t, int npol, Work *w)
{
    const int ns = t->nshell, L = t->nlags;
    for (int q = 0; q < ns; q++) {
        const double k2 = t->shell_k[q] * t->shell_k[q];
        const double norm = k2 / (t->count * (double)npol * t->shell_nvec[q]);
        for (int l = 0; l < L; l++) {
            double sum = 0.0;
            for (int j = 0; j < w->B; j++) {
                const double *a = t->acc + (size_t)w->blk[j] * ns * L;
                w->Cb[((size_t)j * ns + q) * L + l] = a[(size_t)q * L + l] * norm / t->acc_n[w->blk[j]];
                sum += a[(size_t)q * L + l];
            }
            w->C[(size_t)q * L + l] = t->ndone > 0 ? sum * norm / t->ndone : NAN;
        }
    }
}

/* Shell q: C(k,0) against equipartition, C(k,t)/C(k,0) with its block
 * errors, and eta(k) from eq. 28 over all origins and block by block. */
static void analyse_shell(const Tcaf *t, const System *s, Work *w, int q, TcafResult *r)
{
    const int ns = t->nshell, L = t->nlags, B = w->B;
    const double k2 = t->shell_k[q] * t->shell_k[q];
    const double *C = w->C + (size_t)q * L;
    for (int j = 0; j < B; j++) w->tmp[j] = w->Cb[((size_t)j * ns + q) * L] / (k2 * s->kBT * w->invm);
    mean_se(w->tmp, B, &r->c0_ratio_se[q]);
    r->c0_ratio[q] = C[0] / (k2 * s->kBT * w->invm);
    for (int l = 0; l < L; l++) {
        for (int j = 0; j < B; j++) { const double *cb = w->Cb + ((size_t)j * ns + q) * L; w->tmp[j] = cb[l] / cb[0]; }
        mean_se(w->tmp, B, &r->c_se[(size_t)q * L + l]);
        r->c[(size_t)q * L + l] = C[l] / C[0];
    }
    /* fit window: lags 1.. while the average normalised TCAF stays >= fit_min */
    int n = 0;
    for (int l = 1; l < L; l++) {
        if (!(C[l] / C[0] >= t->p.fit_min)) break;
        n++;
    }
    r->fit_points[q] = n;
    r->eta[q] = r->eta_se[q] = NAN;
    for (int j = 0; j < B; j++) w->etab[(size_t)j * ns + q] = NAN;
    if (n < 3) return;   /* decay not resolved by the sampling interval */
    for (int l = 0; l < n; l++) { w->tt[l] = (l + 1) * r->dt_lag; w->cc[l] = C[l + 1] / C[0]; }
    tcaf_fit_eta(w->tt, w->cc, n, k2, t->rho, &r->eta[q]);
    for (int j = 0; j < B; j++) {
        const double *cb = w->Cb + ((size_t)j * ns + q) * L;
        for (int l = 0; l < n; l++) w->cc[l] = cb[l + 1] / cb[0];
        double e;
        tcaf_fit_eta(w->tt, w->cc, n, k2, t->rho, &e);
        w->etab[(size_t)j * ns + q] = e;
        w->tmp[j] = e;
    }
    mean_se(w->tmp, B, &r->eta_se[q]);
}

/* eta(first shell) - eta(last fitted shell), its error block by block; the
 * mean equipartition ratio over the shells, its error from the blocks. */
static void shell_summaries(const Tcaf *t, const System *s, Work *w, TcafResult *r)
{
    const int ns = t->nshell, L = t->nlags, B = w->B;
    int qlast = -1;
    for (int q = 0; q < ns; q++) if (isfinite(r->eta[q])) qlast = q;
    r->drop = r->drop_se = NAN;
    if (qlast > 0 && isfinite(r->eta[0])) {
        r->drop = r->eta[0] - r->eta[qlast];
        for (int j = 0; j < B; j++) w->tmp[j] = w->etab[(size_t)j * ns] - w->etab[(size_t)j * ns + qlast];
        mean_se(w->tmp, B, &r->drop_se);
    }
    double sum_r = 0.0;
    for (int j = 0; j < B; j++) {
        double sum = 0.0;
        for (int q = 0; q < ns; q++) sum += w->Cb[((size_t)j * ns + q) * L] / (t->shell_k[q] * t->shell_k[q] * s->kBT * w->invm);
        w->tmp[j] = sum / ns;
    }
    for (int q = 0; q < ns; q++) sum_r += r->c0_ratio[q];
    mean_se(w->tmp, B, &r->c0_ratio_mean_se);
    r->c0_ratio_mean = ns > 0 ? sum_r / ns : NAN;
}

int tcaf_analyse(const Tcaf *t, const System *s, TcafResult *r)
{
    memset(r, 0, sizeof *r);
    if (t->nblocks > MAX_BLOCKS) return -1;   /* more than Work.blk and the per-block statistics hold */
    Work w;
    if (work_alloc(&w, t, s)) return -1;
    r->nshell = t->nshell;
    r->nlags = t->nlags;
    r->nblocks = w.B;
    r->dt_lag = t->p.every * s->dt;
    if (result_alloc(r, t->nshell, t->nlags)) { work_free(&w); tcaf_result_free(r); return -1; }
    correlations(t, s->box.dim - 1, &w);
    for (int q = 0; q < t->nshell; q++) analyse_shell(t, s, &w, q, r);
    r->nextrap = extrapolate_k0(t, r->eta, r->eta_se, w.etab, w.B, r->coef, r->coef_se, &r->kend);
    shell_summaries(t, s, &w, r);
    work_free(&w);
    if (r->nextrap < 0) { tcaf_result_free(r); return -1; }
    return 0;
}

/* The k -> 0 polynomial of r at k. */
static double extrapolation_at(const Tcaf *t, const TcafResult *r, double k)
{
    double fit = 0.0, xp = 1.0;
    for (int p = 0; p <= t->p.extrap_order; p++) { fit += r->coef[p] * xp; xp *= k * k; }
    return fit;
}

static void write_summary(const Tcaf *t, const TcafResult *r, FILE *summary)
{
    const int P = t->p.extrap_order + 1;
    fprintf(summary, "tcaf_eta_k0\t%.10g\t%.4g\n", r->coef[0], r->coef_se[0]);
    if (P > 1) fprintf(summary, "tcaf_eta_k2_coefficient\t%.10g\t%.4g\n", r->coef[1], r->coef_se[1]);
    if (P > 2) fprintf(summary, "tcaf_eta_k4_coefficient\t%.10g\t%.4g\n", r->coef[2], r->coef_se[2]);
    fprintf(summary, "tcaf_eta_drop\t%.10g\t%.4g\n", r->drop, r->drop_se);
    for (int q = 0; q < t->nshell; q++)
        fprintf(summary, "tcaf_eta_n2_%d\t%.10g\t%.4g\n", t->shell_n2[q], r->eta[q], r->eta_se[q]);
    fprintf(summary, "tcaf_C0_equipartition_ratio\t%.10g\t%.4g\n", r->c0_ratio_mean, r->c0_ratio_mean_se);
    fprintf(summary, "tcaf_origins\t%lld\t0\n", t->ndone);
    fprintf(summary, "tcaf_vectors\t%d\t0\n", t->nvec);
    fprintf(summary, "tcaf_shells\t%d\t0\n", t->nshell);
    fprintf(summary, "tcaf_extrapolation_shells\t%d\t0\n", r->nextrap);
    fprintf(summary, "tcaf_mass_density\t%.10g\t0\n", t->rho);
}

static FILE *open_table(const char *dir, const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return fopen(path, "w");
}

/* tcaf.tsv: C(k,t)/C(k,0) of every shell */
static int write_curves(const Tcaf *t, const TcafResult *r, const char *dir)
{
    FILE *f = open_table(dir, "tcaf.tsv");
    if (!f) return -1;
    const int ns = t->nshell, L = t->nlags;
    fprintf(f, "# C_perp(k,t)/C_perp(k,0) (eqs 26, 28) averaged over %lld time origins; se over %d blocks of origins\n",
            t->ndone, r->nblocks);
    fprintf(f, "# column 2+2q: shell q (0-based) of tcaf_eta.tsv\n");
    fprintf(f, "t");
    for (int q = 0; q < ns; q++) fprintf(f, "\tc_n2_%d\tc_n2_%d_se", t->shell_n2[q], t->shell_n2[q]);
    fputc('\n', f);
    for (int l = 0; l < L; l++) {
        fprintf(f, "%.6g", l * r->dt_lag);
        for (int q = 0; q < ns; q++) fprintf(f, "\t%.6g\t%.3g", r->c[(size_t)q * L + l], r->c_se[(size_t)q * L + l]);
        fputc('\n', f);
    }
    return fclose(f);
}

/* tcaf_eta.tsv: eta(k) per shell with its fit and the k -> 0 polynomial */
static int write_eta(const Tcaf *t, const TcafResult *r, const char *dir)
{
    FILE *f = open_table(dir, "tcaf_eta.tsv");
    if (!f) return -1;
    fprintf(f, "# eta(k) from C/C0 = exp(-eta k^2 t / rho) (eq. 28), rho = %g, fit over the lags with <C/C0> >= %g;\n"
               "# se from %d blocks of time origins; k -> 0: weighted polynomial of degree %d in k^2 over |k| <= %g:",
            t->rho, t->p.fit_min, r->nblocks, t->p.extrap_order, t->p.extrap_kmax);
    for (int p = 0; p <= t->p.extrap_order; p++) fprintf(f, " c%d = %.6g +- %.3g", p, r->coef[p], r->coef_se[p]);
    fprintf(f, "\nk\tn2\tvectors\teta\teta_se\tfit_points\tfit_tmax\tC0_ratio\tC0_ratio_se\teta_extrapolation\n");
    for (int q = 0; q < t->nshell; q++) {
        const double k = t->shell_k[q];
        fprintf(f, "%.6g\t%d\t%d\t%.8g\t%.3g\t%d\t%.4g\t%.6g\t%.3g\t%.6g\n", k, t->shell_n2[q],
                t->shell_nvec[q], r->eta[q], r->eta_se[q], r->fit_points[q], r->fit_points[q] * r->dt_lag,
                r->c0_ratio[q], r->c0_ratio_se[q], k <= t->p.extrap_kmax * (1 + 1e-12) ? extrapolation_at(t, r, k) : NAN);
    }
    return fclose(f);
}

/* tcaf_extrapolation.tsv: the k -> 0 fit as a curve from k = 0 */
static int write_extrapolation(const Tcaf *t, const TcafResult *r, const char *dir)
{
    FILE *f = open_table(dir, "tcaf_extrapolation.tsv");
    if (!f) return -1;
    fprintf(f, "k\teta_fit\n");
    for (int i = 0; i <= 40; i++) {
        const double k = r->kend * i / 40.0;
        fprintf(f, "%.6g\t%.8g\n", k, extrapolation_at(t, r, k));
    }
    return fclose(f);
}

int tcaf_write(const Tcaf *t, const System *s, FILE *summary, const char *dir)
{
    TcafResult r;
    if (tcaf_analyse(t, s, &r)) return -1;
    write_summary(t, &r, summary);
    int rc = 0;
    rc |= write_curves(t, &r, dir);
    rc |= write_eta(t, &r, dir);
    rc |= write_extrapolation(t, &r, dir);
    tcaf_result_free(&r);
    return rc ? -1 : 0;
}
