/* forces.c - DPD pair forces and body forces. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "forces.h"
#include "random.h"
#include "rotation.h"

#define R_EPSILON 1e-10   /* pairs closer than this have no direction: skipped */

int forces_init(ForceWork *w, const System *s, int nbins)
{
    const int n = s->n;
    const size_t chunk_bytes = (size_t)(FORCE_CHUNKS - 1) * 3 * (size_t)n * sizeof(double) + 1;
    memset(w, 0, sizeof *w);
    w->n = n;
    w->nbins = nbins;
    w->buf = malloc(chunk_bytes);
    if (s->rotation && !(w->tbuf = malloc(chunk_bytes))) { forces_free(w); return -1; }
    w->nblk = (n >> FORCE_BLOCK_SHIFT) + 1;
    w->mask_stride = (w->nblk + 63) / 64 * 64;   /* each chunk's mask on its own cache lines */
    w->touched = calloc((size_t)FORCE_CHUNKS * w->mask_stride, 1);
    if (!w->buf || !w->touched) { forces_free(w); return -1; }
    for (int c = 0; c < FORCE_CHUNKS; c++) {
        w->chunk[c].nbins = nbins;
        if (nbins > 0) {
            w->chunk[c].Wbin = calloc((size_t)nbins * PAIR_PARTS * 9, sizeof(double));
            if (!w->chunk[c].Wbin) { forces_free(w); return -1; }
        }
    }
    return 0;
}

void forces_free(ForceWork *w)
{
    free(w->buf);
    free(w->tbuf);
    free(w->touched);
    for (int c = 0; c < FORCE_CHUNKS; c++) free(w->chunk[c].Wbin);
    memset(w, 0, sizeof *w);
}

/* w_R = (1 - r/rc)^(s/2), so that w_D = w_R^2 = (1 - r/rc)^s (eqs 6-7). */
static inline double random_weight(double wc, double s)
{
    if (s == 2.0) return wc;
    if (s == 1.0) return sqrt(wc);
    if (s == 0.5) return sqrt(sqrt(wc));
    return pow(wc, 0.5 * s);
}

static inline void pair_magnitudes(const PairParams *p, double r, double e_dot_v, double theta,
                                   double inv_sqrt_dt, double *fc, double *fd, double *fr)
{
    const double wc = 1.0 - r / p->rc;                 /* w_C, eq. 5 */
    const double wr = random_weight(wc, p->s);         /* w_R = sqrt(w_D), eq. 7 */
    *fc = p->a * wc;                                   /* conservative, eq. 2 */
    *fd = -p->gamma * wr * wr * e_dot_v;               /* dissipative, eq. 3 */
    *fr = p->sigma * wr * theta * inv_sqrt_dt;         /* random, eq. 4 */
}

void dpd_pair_magnitudes(const PairParams *p, double r, double e_dot_v, double theta,
                         double inv_sqrt_dt, double *fc, double *fd, double *fr)
{
    pair_magnitudes(p, r, e_dot_v, theta, inv_sqrt_dt, fc, fd, fr);
}

void ik_distribute(double *Wbin, int nbins, int axis, double Laxis,
                   double xi_axis, double d_axis, const double t[9])
{
    const double h = Laxis / nbins;
    double lo = xi_axis - d_axis, hi = xi_axis;
    if (lo > hi) { double tmp = lo; lo = hi; hi = tmp; }
    const double len = hi - lo;
    (void)axis;
    if (len < 1e-14) {
        int b = (int)floor(xi_axis / h);
        b = ((b % nbins) + nbins) % nbins;
        for (int k = 0; k < 9; k++) Wbin[9 * b + k] += t[k];
        return;
    }
    int b0 = (int)floor(lo / h), b1 = (int)floor(hi / h);
    for (int b = b0; b <= b1; b++) {
        const double s0 = fmax(lo, b * h), s1 = fmin(hi, (b + 1) * h);
        if (s1 <= s0) continue;
        const double frac = (s1 - s0) / len;
        const int bb = ((b % nbins) + nbins) % nbins;
        for (int k = 0; k < 9; k++) Wbin[9 * bb + k] += frac * t[k];
    }
}

void forces_zero_virial(PairVirial *pv)
{
    double *wb = pv->Wbin;
    int nb = pv->nbins, ax = pv->bin_axis;
    memset(pv, 0, sizeof *pv);
    pv->Wbin = wb; pv->nbins = nb; pv->bin_axis = ax;
    if (wb && nb > 0) memset(wb, 0, (size_t)nb * PAIR_PARTS * 9 * sizeof(double));
}

/* Virial of one pair by part, its Irving-Kirkwood split over slabs, the pair
 * energy and the force on frozen particles. Only on measurement steps, so kept
 * out of line (the pair loop then compiles alike with and without -DDPD_BARE). */
static __attribute__((noinline, noclone)) void accumulate_virial(PairVirial *pv, const System *s, int i, int j, const double d[3],
                              double r, const double F[PAIR_PARTS], double fx, double fy, double fz)
{
    const Box *b = &s->box;
    const double inv_r = 1.0 / r;
    const PairParams *p = &s->pair[s->type[i]][s->type[j]];
    for (int q = 0; q < PAIR_PARTS; q++) {
        double t[9];
        const double g = F[q] * inv_r;
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) t[3 * a + c] = d[a] * d[c] * g;
        for (int kk = 0; kk < 9; kk++) pv->W[q][kk / 3][kk % 3] += t[kk];
        if (pv->nbins > 0)
            ik_distribute(pv->Wbin + (size_t)q * 9 * pv->nbins, pv->nbins, pv->bin_axis,
                          b->L[pv->bin_axis], s->x[3 * i + pv->bin_axis], d[pv->bin_axis], t);
    }
    const double wc = 1.0 - r / p->rc;
    pv->epot += 0.5 * p->a * p->rc * wc * wc;
    const int ti = s->type[i], tj = s->type[j];
    if (MOD_FROZEN(&s->types[tj])) {
        pv->frozen_force[tj][0] -= fx; pv->frozen_force[tj][1] -= fy; pv->frozen_force[tj][2] -= fz;
    }
    if (MOD_FROZEN(&s->types[ti])) {
        pv->frozen_force[ti][0] += fx; pv->frozen_force[ti][1] += fy; pv->frozen_force[ti][2] += fz;
    }
}

/* The pair loop for the particles [i0, i1); pv != NULL also sums the virial.
 * le: the box has Lees-Edwards shear. A constant: the loop is compiled once per
 * value (pair_loop below), so that a scene without shear runs no test for it. */
static inline __attribute__((always_inline))
void pair_loop_le(const System *s, const NeighborList *nl, int i0, int i1,
                  double *f, unsigned char *touched, PairVirial *pv, const int le)
{
    const int n = s->n;
    const Box *b = &s->box;
    const double inv_sqrt_dt = 1.0 / sqrt(s->dt);
    const double *x = s->x, *v = s->v_pred;
    enum { BATCH = PAIR_BATCH };
    int near[BATCH];
    double dd[BATCH][4];
    for (int i = i0; i < i1; i++) {
        const int ti = s->type[i];
        double fi[3] = {0.0, 0.0, 0.0};
        for (int k0 = nl->start[i]; k0 < nl->start[i + 1]; k0 += BATCH) {
            const int k1 = k0 + BATCH < nl->start[i + 1] ? k0 + BATCH : nl->start[i + 1];
            const int m = pairs_in_range(s, nl, i, k0, k1, near, dd, le);
            /* pass 2: the forces */
            for (int q = 0; q < m; q++) {
                const int j = near[q];
                const PairParams *p = &s->pair[ti][s->type[j]];
                const double r2 = dd[q][3];
                if (r2 >= p->rc2 || r2 < R_EPSILON * R_EPSILON) continue;
                const double d[3] = {dd[q][0], dd[q][1], dd[q][2]};
                double dvx = v[3 * i] - v[3 * j];
                if (le) {   /* velocity of the Lees-Edwards image */
                    const double dy = x[3 * i + 1] - x[3 * j + 1];
                    if (dy > b->half[1]) dvx -= b->shear_rate * b->L[1];
                    else if (dy < -b->half[1]) dvx += b->shear_rate * b->L[1];
                }
                const double r = sqrt(r2), inv_r = 1.0 / r;
                const double e[3] = {d[0] * inv_r, d[1] * inv_r, d[2] * inv_r};
                const double edv = e[0] * dvx + e[1] * (v[3 * i + 1] - v[3 * j + 1])
                                 + e[2] * (v[3 * i + 2] - v[3 * j + 2]);
                const double theta = rng_pair_normal(s->seed, s->step, s->id[i], s->id[j]);
                double F[PAIR_PARTS];
                pair_magnitudes(p, r, edv, theta, inv_sqrt_dt,
                                    &F[PART_CONSERVATIVE], &F[PART_DISSIPATIVE], &F[PART_RANDOM]);
                const double ft = F[0] + F[1] + F[2];
                const double fx = ft * e[0], fy = ft * e[1], fz = ft * e[2];
                fi[0] += fx; fi[1] += fy; fi[2] += fz;
                force_claim(f, NULL, touched, j, n);
                f[3 * j] -= fx; f[3 * j + 1] -= fy; f[3 * j + 2] -= fz;
                if (pv) accumulate_virial(pv, s, i, j, d, r, F, fx, fy, fz);
            }
        }
        force_claim(f, NULL, touched, i, n);
        f[3 * i] += fi[0]; f[3 * i + 1] += fi[1]; f[3 * i + 2] += fi[2];
    }
}

static void pair_loop_shear(const System *s, const NeighborList *nl, int i0, int i1, double *f,
                            unsigned char *touched, PairVirial *pv)
{
    pair_loop_le(s, nl, i0, i1, f, touched, pv, 1);
}

static void pair_loop_plain(const System *s, const NeighborList *nl, int i0, int i1, double *f,
                            unsigned char *touched, PairVirial *pv)
{
    pair_loop_le(s, nl, i0, i1, f, touched, pv, 0);
}

static void pair_loop(const System *s, const NeighborList *nl, int i0, int i1, double *f,
                      unsigned char *touched, PairVirial *pv)
{
    if (MOD_SHEAR(&s->box)) pair_loop_shear(s, nl, i0, i1, f, touched, pv);
    else pair_loop_plain(s, nl, i0, i1, f, touched, pv);
}

int forces_chunk_start(const NeighborList *nl, int n, int c)
{
    if (c >= FORCE_CHUNKS) return n;
    const size_t want = (size_t)nl->start[n] * (size_t)c / FORCE_CHUNKS;
    int lo = 0, hi = n;
    while (lo < hi) { int mid = (lo + hi) / 2; if ((size_t)nl->start[mid] < want) lo = mid + 1; else hi = mid; }
    return lo;
}

unsigned char *forces_chunk_mask(ForceWork *w, int c)
{
    unsigned char *m = w->touched + (size_t)c * w->mask_stride;
    memset(m, 0, (size_t)w->nblk);
    return m;
}

static void sum_block(const ForceWork *w, double *f0, const double *rest, int b)
{
    const size_t stride = 3 * (size_t)w->n, nb = w->mask_stride;
    const size_t k0 = 3 * ((size_t)b << FORCE_BLOCK_SHIFT);
    const size_t k1 = k0 + (3u << FORCE_BLOCK_SHIFT) < stride ? k0 + (3u << FORCE_BLOCK_SHIFT) : stride;
    const int own = w->touched[b];
    for (size_t k = k0; k < k1; k++) {
        double sum = own ? f0[k] : 0.0;
        for (int c = 1; c < FORCE_CHUNKS; c++)
            if (w->touched[(size_t)c * nb + (size_t)b]) sum += rest[(size_t)(c - 1) * stride + k];
        f0[k] = sum;
    }
}

void forces_sum_chunks(const ForceWork *w, double *f0, const double *rest, double *t0, const double *trest)
{
    /* contiguous blocks per thread, as the chunks and the integrator's loops */
    #pragma omp parallel for schedule(static)
    for (int b = 0; b < w->nblk; b++) {
        sum_block(w, f0, rest, b);
        if (t0) sum_block(w, t0, trest, b);
    }
}

void forces_body(System *s)
{
    if (!MOD_BODY_FORCE(s)) return;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        double sign = 1.0;
        if (t->body_force_flip_axis >= 0) {
            const int a = t->body_force_flip_axis;
            sign = s->x[3 * i + a] < s->box.half[a] ? 1.0 : -1.0;
        }
        for (int d = 0; d < 3; d++) s->f[3 * i + d] += sign * t->body_force[d];
    }
}

/* The chunks' virials added in chunk order (deterministic); the rotation
 * fields stay zero in scenes without rotation. */
void forces_reduce_virial(PairVirial *pv, const ForceWork *w)
{
    forces_zero_virial(pv);
    for (int c = 0; c < FORCE_CHUNKS; c++) {
        const PairVirial *cv = &w->chunk[c];
        for (int q = 0; q < PAIR_PARTS; q++)
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) pv->W[q][a][b] += cv->W[q][a][b];
        pv->epot += cv->epot;
        for (int t = 0; t < DPD_MAX_TYPES; t++)
            for (int d = 0; d < 3; d++) {
                pv->frozen_force[t][d] += cv->frozen_force[t][d];
                pv->frozen_torque[t][d] += cv->frozen_torque[t][d];
                pv->frozen_drag[t][d] += cv->frozen_drag[t][d];
                pv->frozen_torque_random[t][d] += cv->frozen_torque_random[t][d];
            }
        if (pv->nbins > 0)
            for (size_t k = 0; k < (size_t)pv->nbins * PAIR_PARTS * 9; k++) pv->Wbin[k] += cv->Wbin[k];
    }
}

void forces_compute(System *s, const NeighborList *nl, ForceWork *w, PairVirial *pv)
{
    if (MOD_ROTATION(s)) { rotation_forces_compute(s, nl, w, pv); forces_body(s); return; }
    const int n = s->n;
    const size_t stride = 3 * (size_t)n;
    /* contiguous chunks per thread (thread 0: the first half of the particles
     * on 2 threads), as the particle loops of the integrator: each thread
     * reads and writes mostly the particles it will move */
    #pragma omp parallel for schedule(static)
    for (int c = 0; c < FORCE_CHUNKS; c++) {
        /* chunk 0 accumulates straight into f: one buffer less to clear and read */
        double *buf = c == 0 ? s->f : w->buf + (size_t)(c - 1) * stride;
        const int i0 = forces_chunk_start(nl, n, c), i1 = forces_chunk_start(nl, n, c + 1);
        PairVirial *cv = NULL;
        if (pv) { cv = &w->chunk[c]; cv->bin_axis = pv->bin_axis; cv->nbins = pv->nbins; forces_zero_virial(cv); }
        pair_loop(s, nl, i0, i1, buf, forces_chunk_mask(w, c), cv);
    }
    forces_sum_chunks(w, s->f, w->buf, NULL, NULL);
    if (pv) forces_reduce_virial(pv, w);
    forces_body(s);
}
