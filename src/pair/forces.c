/* forces.c - the pair driver: the neighbour list cut into FORCE_CHUNKS fixed
 * chunks, each walked by the scene's pair style (pair_style.h; its walk is
 * pair_walk.h compiled with its evaluator) into its own buffers, summed in a
 * fixed order (deterministic for any thread count); the vector kernels of a
 * force call, chosen in one place (pair_kernels); the virial by part and its
 * recorders; the serial walk of the m = 0 assembly (pair_visit); body
 * forces. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "forces.h"
#include "pair_style.h"
#include "pair_avx512.h"
#include "simd.h"

int forces_init(ForceWork *w, const System *s, int nbins)
{
    const int n = s->n;
    const size_t chunk_bytes = (size_t)(FORCE_CHUNKS - 1) * 3 * (size_t)n * sizeof(double) + 1;
    memset(w, 0, sizeof *w);
    w->n = n;
    w->nbins = nbins;
    const PairStyle *st = pair_style_of(s);
    if (!st) return -1;
    w->buf = malloc(chunk_bytes);
    if (st->spins && !(w->tbuf = malloc(chunk_bytes))) { forces_free(w); return -1; }
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

void pair_virial_add(PairVirial *pv, const System *s, int i, int q, const double d[3], const double t[9])
{
    for (int kk = 0; kk < 9; kk++) pv->W[q][kk / 3][kk % 3] += t[kk];
    if (pv->nbins > 0)
        ik_distribute(pv->Wbin + (size_t)q * 9 * pv->nbins, pv->nbins, pv->bin_axis,
                      s->box.L[pv->bin_axis], s->x[3 * i + pv->bin_axis], d[pv->bin_axis], t);
}

void forces_zero_virial(PairVirial *pv)
{
    double *wb = pv->Wbin;
    int nb = pv->nbins, ax = pv->bin_axis;
    memset(pv, 0, sizeof *pv);
    pv->Wbin = wb; pv->nbins = nb; pv->bin_axis = ax;
    if (wb && nb > 0) memset(wb, 0, (size_t)nb * PAIR_PARTS * 9 * sizeof(double));
}

static inline void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

#ifdef __clang__
#define PAIR_NOCLONE   /* clang has no noclone (the fuzzer's build) */
#else
#define PAIR_NOCLONE __attribute__((noclone))
#endif

__attribute__((noinline)) PAIR_NOCLONE
void pair_record_central(PairVirial *pv, const System *s, int i, int j, const PairIn *in, const PairOut *out)
{
    const double *d = in->d;
    const double inv_r = 1.0 / in->r;
    for (int q = 0; q < PAIR_PARTS; q++) {
        double t[9];
        const double g = out->mag[q] * inv_r;
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) t[3 * a + c] = d[a] * d[c] * g;   /* central: r_a r_b F / r */
        pair_virial_add(pv, s, i, q, d, t);
    }
    pv->epot += out->energy;
    pair_record_frozen_central(pv, s, i, j, out->F);
}

void pair_record_frozen_central(PairVirial *pv, const System *s, int i, int j, const double F[3])
{
    const int ti = s->type[i], tj = s->type[j];
    if (MOD_FROZEN(&s->types[tj])) {
        pv->frozen_force[tj][0] -= F[0]; pv->frozen_force[tj][1] -= F[1]; pv->frozen_force[tj][2] -= F[2];
    }
    if (MOD_FROZEN(&s->types[ti])) {
        pv->frozen_force[ti][0] += F[0]; pv->frozen_force[ti][1] += F[1]; pv->frozen_force[ti][2] += F[2];
    }
}

__attribute__((noinline)) PAIR_NOCLONE
void pair_record_eq1(PairVirial *pv, const System *s, int i, int j, const PairIn *in, const PairOut *out)
{
    const double *d = in->d;
    const double (*F)[3] = out->part;
    for (int q = 0; q < PAIR_PARTS; q++) {
        double t[9];
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) t[3 * a + c] = d[a] * F[q][c];   /* asymmetric: r_a F_b */
        pair_virial_add(pv, s, i, q, d, t);
    }
    pv->epot += out->energy;
    pair_record_frozen_eq1(pv, s, i, j, d, F, out->tau);
}

void pair_record_frozen_eq1(PairVirial *pv, const System *s, int i, int j, const double d[3],
                            const double (*F)[3], const double tau[3])
{
    const int ti = s->type[i], tj = s->type[j];
    if (!MOD_FROZEN(&s->types[ti]) && !MOD_FROZEN(&s->types[tj])) return;
    /* the random force of a step is independent of the configuration it acts
     * on: its torque and force have zero mean but a variance of order 1 / dt,
     * so drag and torque are reported without it (and the random torque apart) */
    double tr[3], Fr[3] = {-0.5 * F[2][0], -0.5 * F[2][1], -0.5 * F[2][2]};
    cross3(d, Fr, tr);   /* eq. 1 for the random part alone */
    for (int a = 0; a < 3; a++) {
        const double fa = F[0][a] + F[1][a] + F[2][a], fn = F[0][a] + F[1][a];
        if (MOD_FROZEN(&s->types[tj])) {
            pv->frozen_force[tj][a] -= fa; pv->frozen_drag[tj][a] -= fn;
            pv->frozen_torque[tj][a] += tau[a] - tr[a]; pv->frozen_torque_random[tj][a] += tr[a];
        }
        if (MOD_FROZEN(&s->types[ti])) {
            pv->frozen_force[ti][a] += fa; pv->frozen_drag[ti][a] += fn;
            pv->frozen_torque[ti][a] += tau[a] - tr[a]; pv->frozen_torque_random[ti][a] += tr[a];
        }
    }
}

/* The vector kernels of a force call, in one place: the instruction set in
 * use (simd.c, detected once per process, capped by DPD_SIMD), the box and
 * the step decide; the walk only tests them for NULL. On AVX-512 in 3D
 * without shear: the candidate pass eight entries at a time, into planes
 * for the style's evaluator of one-type batches, or into rows when the
 * virial is binned (those batches go pair by pair); at every level the
 * style's lanes. */
static void pair_kernels(PairKernels *k, const PairStyle *st, const System *s, const NeighborList *nl,
                         const PairVirial *pv, int le)
{
    const int level = simd_level();
    memset(k, 0, sizeof *k);
    k->lanes = st->accel[level].lanes;
    if (level == SIMD_AVX512 && !le && s->box.dim == 3) {
        k->ahead = pair_prefetch_ahead(s, nl);
        if (!pv || pv->nbins == 0) {
            k->gather_planes = SIMD_X86(pair_gather_planes_avx512);
            k->one_type = st->accel[level].one_type;
        } else {
            k->gather_rows = SIMD_X86(pair_gather_rows_avx512);
        }
    }
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
    int other[FORCE_CHUNKS], no = 0;   /* the other chunks that wrote to block b, in chunk order */
    for (int c = 1; c < FORCE_CHUNKS; c++)
        if (w->touched[(size_t)c * nb + (size_t)b]) other[no++] = c;
    if (no == 0) {   /* chunk 0's sums alone (most blocks): already in place, or none */
        if (!own) for (size_t k = k0; k < k1; k++) f0[k] = 0.0;
        return;
    }
    /* each element's sum in chunk order, as one sum per element would form
     * it (0.0 first where chunk 0 wrote nothing): chunk by chunk over the
     * block, so that the elements go side by side */
    if (!own) for (size_t k = k0; k < k1; k++) f0[k] = 0.0;
    for (int q = 0; q < no; q++) {
        const double *restrict r = rest + (size_t)(other[q] - 1) * stride;
        double *restrict f = f0;
        #pragma omp simd
        for (size_t k = k0; k < k1; k++) f[k] += r[k];
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
    const PairStyle *st = pair_style_of(s);
    const int n = s->n, spins = st->spins, le = MOD_SHEAR(&s->box);
    const size_t stride = 3 * (size_t)n;
    const PairWalkFn walk = st->walk[le];   /* the style's walk, compiled for this box */
    PairKernels k;
    pair_kernels(&k, st, s, nl, pv, le);
    /* contiguous chunks per thread (thread 0: the first half of the particles
     * on 2 threads), as the particle loops of the integrator: each thread
     * reads and writes mostly the particles it will move */
    #pragma omp parallel for schedule(static)
    for (int c = 0; c < FORCE_CHUNKS; c++) {
        /* chunk 0 accumulates straight into f (and the torques): one buffer less to clear and read */
        PairAcc acc = {.f = c == 0 ? s->f : w->buf + (size_t)(c - 1) * stride,
                       .tq = !spins ? NULL : c == 0 ? s->torque : w->tbuf + (size_t)(c - 1) * stride,
                       .touched = forces_chunk_mask(w, c), .n = n, .inv_sqrt_dt = 1.0 / sqrt(s->dt)};
        const int i0 = forces_chunk_start(nl, n, c), i1 = forces_chunk_start(nl, n, c + 1);
        PairVirial *cv = NULL;
        if (pv) { cv = &w->chunk[c]; cv->bin_axis = pv->bin_axis; cv->nbins = pv->nbins; forces_zero_virial(cv); }
        walk(s, nl, i0, i1, &acc, cv, &k);
    }
    if (spins) forces_sum_chunks(w, s->f, w->buf, s->torque, w->tbuf);
    else forces_sum_chunks(w, s->f, w->buf, NULL, NULL);
    if (pv) forces_reduce_virial(pv, w);
    forces_body(s);
}

/* The serial walk for the m = 0 assembly: every interacting listed pair, in
 * list order, with its minimum-image separation d = r_i - r_j, r^2 and the x
 * velocity of j's nearest Lees-Edwards image relative to j. */
void pair_visit(const System *s, const NeighborList *nl, PairVisitor visit, void *ctx)
{
    const int le = MOD_SHEAR(&s->box);
    int near[PAIR_BATCH];
    double dd[PAIR_BATCH][4];
    for (int i = 0; i < s->n; i++)
        for (int k0 = nl->start[i]; k0 < nl->start[i + 1]; k0 += PAIR_BATCH) {
            const int k1 = k0 + PAIR_BATCH < nl->start[i + 1] ? k0 + PAIR_BATCH : nl->start[i + 1];
            const int m = pairs_in_range(s, nl, i, k0, k1, near, dd, 1);
            for (int q = 0; q < m; q++) {
                const int j = near[q];
                if (!pair_interacts(&s->pair[s->type[i]][s->type[j]], dd[q][3])) continue;
                visit(ctx, i, j, dd[q], dd[q][3], pair_image_vx(s, i, j, le));
            }
        }
}
