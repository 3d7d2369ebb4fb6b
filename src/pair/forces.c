/* forces.c - the pair driver: the walk over the neighbour list, cut into
 * FORCE_CHUNKS fixed chunks that accumulate into their own buffers, summed in
 * a fixed order (deterministic for any thread count); the virial by part; the
 * evaluators of pair_dpd.h and pair_pan2008.h compiled into the walk once per
 * model and Lees-Edwards state; the serial walk of the m = 0 assembly
 * (pair_visit); body forces. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "forces.h"
#include "pair_dpd.h"
#include "pair_pan2008.h"
#include "simd.h"

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

void dpd_pair_magnitudes(const PairParams *p, double r, double e_dot_v, double theta,
                         double inv_sqrt_dt, double *fc, double *fd, double *fr)
{
    dpd_pair_terms(p, r, e_dot_v, theta, inv_sqrt_dt, fc, fd, fr);
}

void pan2008_pair_force(const PairParams *p, const double d[3], const double dv[3],
                        const double wsum[3], double theta, const double xi[3],
                        double inv_sqrt_dt, double F[3][3], double Ftot[3], double tau[3])
{
    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double e[3], wc, f;
    pan_pair_geometry(p, d, r, e, &wc, &f);
    pan_pair_force(p, d, e, wc, f, dv, wsum, theta, xi, inv_sqrt_dt, F, Ftot, tau);
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

enum { MODEL_DPD, MODEL_PAN2008 };

/* pan_lanes_force compiled for AVX-512, AVX2 and baseline x86-64 (the same
 * operations without contraction, so the same bits), chosen by simd_level(). */
typedef void (*PanLanesFn)(PanLanes *, int, double, const PairParams *);
/* no-tree-sink: GCC would otherwise move each square root into the branch of
 * the select that uses it, and a square root under a condition keeps the loop
 * from vectorising without masks (it "could trap"); the bits are the same.
 * AVX-512 has the masks, and is faster without it (measured). */
#ifdef __clang__
#define PAN_LANES_OPT   /* clang has no optimize attribute (the fuzzer's build) */
#else
#define PAN_LANES_OPT optimize("no-tree-sink")
#endif
__attribute__((PAN_LANES_OPT)) static void pan_lanes_portable(PanLanes *L, int m, double inv_sqrt_dt, const PairParams *u)
{ pan_lanes_force(L, m, inv_sqrt_dt, u); }
#ifdef DPD_HAVE_X86_SIMD
__attribute__((target("avx2"), PAN_LANES_OPT)) static void pan_lanes_avx2(PanLanes *L, int m, double inv_sqrt_dt, const PairParams *u)
{ pan_lanes_force(L, m, inv_sqrt_dt, u); }
__attribute__((target("avx512f"))) static void pan_lanes_avx512(PanLanes *L, int m, double inv_sqrt_dt, const PairParams *u)
{ pan_lanes_force(L, m, inv_sqrt_dt, u); }
#endif

/* pairs_in_range (pair.h) eight candidates at a time, for boxes without
 * Lees-Edwards shear in 3 dimensions: the same subtractions, folds and r^2
 * (no contraction: -std=c11 keeps it off), so the same bits and the same kept
 * entries in the same order. The kept j, separations and r^2, and the pairs'
 * ids are compressed into registers and stored whole (near, dd, id_a and id_b
 * need RANGE_SLACK entries of room past the last one). */
#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>
#define AVX512 __attribute__((target("avx512f")))
/* box_min_image_le's fold along one axis, lane by lane: one period off each
 * side, and twice when twice is true (x: the scalar code folds twice) */
static inline AVX512 __m512d fold_avx512(__m512d d, __m512d half, __m512d L, const int twice)
{
    const __m512d nhalf = _mm512_sub_pd(_mm512_setzero_pd(), half);
    const __mmask8 hi = _mm512_cmp_pd_mask(d, half, _CMP_GT_OQ), lo = _mm512_cmp_pd_mask(d, nhalf, _CMP_LT_OQ);
    d = _mm512_mask_sub_pd(d, hi, d, L);
    d = _mm512_mask_add_pd(d, lo, d, L);
    if (twice) {
        d = _mm512_mask_sub_pd(d, _mm512_mask_cmp_pd_mask(hi, d, half, _CMP_GT_OQ), d, L);
        d = _mm512_mask_add_pd(d, _mm512_mask_cmp_pd_mask(lo, d, nhalf, _CMP_LT_OQ), d, L);
    }
    return d;
}
static inline AVX512 int range_avx512(const System *s, const NeighborList *nl, int i, int k0, int k1,
                               int *near, double (*dd)[4], double *pl, uint32_t *id_a, uint32_t *id_b, const int soa,
                               int ahead)
{
    const __m512i ida = _mm512_set1_epi32((int)s->id[i]);
    const __m256i lane_bit = _mm256_setr_epi32(31, 30, 29, 28, 27, 26, 25, 24);   /* keep's bit l to the sign of lane l */
    const double *x = s->x;
    const Box *b = &s->box;
    /* i at least `reach` from every face: no candidate is across one (each of
     * i and j moved less than skin / 2 since the build, which listed them
     * within rc + skin), so every fold would leave the separations as they are */
    const double reach = nl->cutoff + nl->skin + 1e-9;
    if (ahead && i + ahead < s->n)   /* walk_prefetch_ahead */
        for (int k = nl->start[i + ahead]; k < nl->start[i + ahead + 1]; k += 3) {   /* 3 particles' x: 72 B */
            const int jj = nl->nbr[k];
            _mm_prefetch((const char *)(x + 3 * jj), _MM_HINT_T0);
            _mm_prefetch((const char *)(s->v_pred + 3 * jj), _MM_HINT_T0);
        }
    int interior = 1;
    for (int a = 0; a < 3; a++) interior &= x[3 * i + a] >= reach && x[3 * i + a] <= b->L[a] - reach;
    const __m512d xi = _mm512_set1_pd(x[3 * i]), yi = _mm512_set1_pd(x[3 * i + 1]), zi = _mm512_set1_pd(x[3 * i + 2]);
    const __m512d rc2 = _mm512_set1_pd(s->rc_max * s->rc_max);
    /* the transpose of (dx, dy, dz, r2) x 8 into 8 quads: pairs of 128-bit halves */
    const __m512i lo_halves = _mm512_set_epi64(11, 10, 3, 2, 9, 8, 1, 0);
    const __m512i hi_halves = _mm512_set_epi64(15, 14, 7, 6, 13, 12, 5, 4);
    const __m512i first = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
    const __m512i second = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
    int m = 0;
    for (int k = k0; k < k1; k += 8) {
        const __mmask8 live = k1 - k >= 8 ? 0xff : (__mmask8)((1u << (k1 - k)) - 1);
        const __m512i j = _mm512_maskz_loadu_epi32((__mmask16)live, nl->nbr + k);
        const __m256i j3 = _mm512_castsi512_si256(_mm512_add_epi32(j, _mm512_add_epi32(j, j)));
        const __m512d z0 = _mm512_setzero_pd();
        __m512d dx = _mm512_sub_pd(xi, _mm512_mask_i32gather_pd(z0, live, j3, x, 8));
        __m512d dy = _mm512_sub_pd(yi, _mm512_mask_i32gather_pd(z0, live, j3, x + 1, 8));
        __m512d dz = _mm512_sub_pd(zi, _mm512_mask_i32gather_pd(z0, live, j3, x + 2, 8));
        if (!interior) {
            dy = fold_avx512(dy, _mm512_set1_pd(b->half[1]), _mm512_set1_pd(b->L[1]), 0);
            dx = fold_avx512(dx, _mm512_set1_pd(b->half[0]), _mm512_set1_pd(b->L[0]), 1);
            dz = fold_avx512(dz, _mm512_set1_pd(b->half[2]), _mm512_set1_pd(b->L[2]), 0);
        }
        const __m512d r2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
        const __mmask8 keep = _mm512_mask_cmp_pd_mask(live, r2, rc2, _CMP_LT_OQ);
        _mm512_storeu_si512(near + m, _mm512_maskz_compress_epi32((__mmask16)keep, j));
        /* the pair's stable ids, ordered, for its noise; gathered eight lanes
         * wide (a sixteen-lane gather costs twice as much, masked or not) */
        const __m256i keep8 = _mm256_cmpgt_epi32(_mm256_set1_epi32(0), _mm256_sllv_epi32(_mm256_set1_epi32(keep), lane_bit));
        const __m512i idj = _mm512_castsi256_si512(_mm256_mask_i32gather_epi32(_mm512_castsi512_si256(ida), (const int *)s->id,
                                                                               _mm512_castsi512_si256(j), keep8, 4));
        _mm512_storeu_si512(id_a + m, _mm512_maskz_compress_epi32((__mmask16)keep, _mm512_min_epu32(ida, idj)));
        _mm512_storeu_si512(id_b + m, _mm512_maskz_compress_epi32((__mmask16)keep, _mm512_max_epu32(ida, idj)));
        const __m512d cx = _mm512_maskz_compress_pd(keep, dx), cy = _mm512_maskz_compress_pd(keep, dy);
        const __m512d cz = _mm512_maskz_compress_pd(keep, dz), cr = _mm512_maskz_compress_pd(keep, r2);
        const int at = m;
        m += __builtin_popcount(keep);
        if (soa) {   /* planes x, y, z, r2 (PAIR_PLANE apart), as the AVX-512 evaluator reads them */
            _mm512_storeu_pd(pl + at, cx); _mm512_storeu_pd(pl + PAIR_PLANE + at, cy);
            _mm512_storeu_pd(pl + 2 * PAIR_PLANE + at, cz); _mm512_storeu_pd(pl + 3 * PAIR_PLANE + at, cr);
            continue;
        }
        const __m512d xy0 = _mm512_unpacklo_pd(cx, cy), xy1 = _mm512_unpackhi_pd(cx, cy);   /* x0 y0 x2 y2 .. | x1 y1 x3 y3 .. */
        const __m512d zr0 = _mm512_unpacklo_pd(cz, cr), zr1 = _mm512_unpackhi_pd(cz, cr);
        const __m512d e01 = _mm512_permutex2var_pd(xy0, lo_halves, zr0);   /* q0 q2 (even quads 0, 2) */
        const __m512d e23 = _mm512_permutex2var_pd(xy0, hi_halves, zr0);   /* q4 q6 */
        const __m512d o01 = _mm512_permutex2var_pd(xy1, lo_halves, zr1);   /* q1 q3 */
        const __m512d o23 = _mm512_permutex2var_pd(xy1, hi_halves, zr1);   /* q5 q7 */
        _mm512_storeu_pd(dd[at], _mm512_permutex2var_pd(e01, first, o01));
        _mm512_storeu_pd(dd[at + 2], _mm512_permutex2var_pd(e01, second, o01));
        _mm512_storeu_pd(dd[at + 4], _mm512_permutex2var_pd(e23, first, o23));
        _mm512_storeu_pd(dd[at + 6], _mm512_permutex2var_pd(e23, second, o23));
    }
    return m;
}
#undef AVX512
#endif

/* Particle i's pairs in range, handed to the model's evaluator with their
 * noise (nvar variates per pair, drawn for all of them at once). */
static inline __attribute__((always_inline))
void pair_evaluate(const System *s, int i, int *near, double (*dd)[4], const double *noise, int m,
                   PairAcc *acc, PairVirial *pv, const int model, const int le, const double *wr)
{
    if (model == MODEL_PAN2008) pan_pair_batch(s, i, near, dd, noise, m, acc, pv, le);
    else dpd_pair_batch(s, i, near, dd, noise, m, acc, pv, le, wr);
}

/* Some type pair of the scene has a general weight exponent (weight_general) */
static int scene_weights_general(const System *s)
{
    for (int a = 0; a < s->ntypes; a++)
        for (int b = 0; b < s->ntypes; b++)
            if (s->pair[a][b].active && weight_general(s->pair[a][b].s)) return 1;
    return 0;
}

/* w_R (eq. 7) of every pair of a walk batch [i, ie) (separations and r^2 in
 * dd) that interacts with a general exponent, all at once (weight_pow_batch);
 * other entries get a placeholder. w_C = 1 - r/rc as the evaluator forms it,
 * so the same bits. */
static void batch_random_weights(const System *s, int i, int ie, const double (*dd)[4], const int *near,
                                 const int *count, double *wr)
{
    double w[PAIR_BATCH + 8], e[PAIR_BATCH + 8];
    int k = 0;
    for (int p = i; p < ie; p++) {
        const int ti = s->type[p];
        for (int q = 0; q < count[p - i]; q++, k++) {
            const PairParams *pp = &s->pair[ti][s->type[near[k]]];
            const double r2k = dd[k][3];
            const int use = weight_general(pp->s) && pair_interacts(pp, r2k);
            w[k] = use ? 1.0 - sqrt(r2k) / pp->rc : 1.0;
            e[k] = use ? 0.5 * pp->s : 1.0;
        }
    }
    for (int q = k; q < k + 8; q++) w[q] = e[q] = 1.0;
    weight_pow_batch(w, e, wr, k);
}

#ifdef DPD_HAVE_X86_SIMD
/* batch_random_weights for one type pair u (a general exponent) on AVX-512:
 * the np entries' r^2 in one plane, w_C = 1 - r / rc eight at a time with the
 * scalar loop's operations (IEEE sqrt and division: the same bits). It was
 * 14 % of the mai-duy-2019 solvent's run as the scalar loop. */
__attribute__((target("avx512f"))) static void batch_random_weights_avx512(const PairParams *u, const double *r2,
                                                                          int np, double *wr)
{
    double w[PAIR_BATCH + 8], e[PAIR_BATCH + 8];
    const __m512d one = _mm512_set1_pd(1.0), rc = _mm512_set1_pd(u->rc), rc2 = _mm512_set1_pd(u->rc2);
    const __m512d eps2 = _mm512_set1_pd(PAIR_R_EPSILON * PAIR_R_EPSILON), half_s = _mm512_set1_pd(0.5 * u->s);
    for (int q = 0; q < np; q += 8) {
        const __mmask8 live = (__mmask8)(np - q >= 8 ? 0xff : (1u << (np - q)) - 1);
        const __m512d x = _mm512_maskz_loadu_pd(live, r2 + q);
        const __mmask8 use = pair_interacts_avx512(x, rc2, eps2, live);
        const __m512d wc = _mm512_sub_pd(one, _mm512_div_pd(_mm512_sqrt_pd(x), rc));
        _mm512_storeu_pd(w + q, _mm512_mask_blend_pd(use, one, wc));
        _mm512_storeu_pd(e + q, _mm512_mask_blend_pd(use, one, half_s));
    }
    for (int q = np; q < np + 8; q++) w[q] = e[q] = 1.0;
    weight_pow_batch(w, e, wr, np);
}
#endif

/* After particle i's last pair: its own sums into the chunk's buffers. */
static inline __attribute__((always_inline)) void pair_close(int i, PairAcc *acc, const int model)
{
    force_claim(acc->f, acc->tq, acc->touched, i, acc->n);
    for (int a = 0; a < 3; a++) acc->f[3 * i + a] += acc->fi[a];
    if (model == MODEL_PAN2008)
        for (int a = 0; a < 3; a++) acc->tq[3 * i + a] += acc->ti[a];
    for (int a = 0; a < 3; a++) acc->fi[a] = acc->ti[a] = 0.0;
}

#ifdef DPD_HAVE_X86_SIMD
/* The standard pairs of a walk batch [i, ie) on AVX-512 (dpd_pair_lanes_avx512,
 * the same bits as dpd_pair_batch): one type pair u, no shear; pv != NULL
 * (measurement steps): the virial and energy too (not binned, no frozen
 * type). Every particle of the batch closed after its pairs. Compiled once
 * without the virial and once with it (the lanes are inlined). */
static inline __attribute__((target("avx512f"), always_inline))
void dpd_batch_lanes(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                     const int *count, PairAcc *acc, const PairParams *u, const double *wr, PairVirial *pv)
{
    const int wcase = u->s == 2.0 ? 2 : u->s == 1.0 ? 1 : u->s == 0.5 ? 0 : -1;
    const double inv_rc = rc_power_of_two_inverse(u->rc);
    for (int p = i, off = 0; p < ie; off += count[p - i], p++) {
        dpd_pair_lanes_avx512(s, p, near + off, pl + off, noise + off, count[p - i], acc, u, wcase,
                              wcase < 0 ? wr + off : NULL, inv_rc, pv);
        pair_close(p, acc, MODEL_DPD);
    }
}
__attribute__((target("avx512f"))) static void dpd_batch_avx512(const System *s, int i, int ie, const int *near,
        const double *pl, const double *noise, const int *count, PairAcc *acc, const PairParams *u,
        const double *wr, PairVirial *pv)
{
    if (pv) dpd_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, wr, pv);
    else dpd_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, wr, NULL);
}
#endif

/* Pan 2008 without the virial, lane by lane (pair_pan2008.h, the same bits
 * as pair by pair): the pairs of particles [i, ie) of a walk batch, with
 * their noise in rng_pair_normals' planes. One type, not a general power:
 * its parameters once, not per pair; and when every pair of the batch
 * interacts (one cutoff, none closer than PAIR_R_EPSILON), the lanes read the
 * separations and the noise where the walk left them (direct: entry q of the
 * batch is lane q). */
static inline __attribute__((always_inline))
void pan_evaluate_lanes(const System *s, int i, int ie, int *near, double (*dd)[4], const double *noise,
                        const int *count, PairAcc *acc, const int le, const int close_last)
{
    PanLanes L;
    int m = 0, c[PAIR_BATCH];
    const PairParams *u = s->ntypes == 1 && !weight_general(s->pair[0][0].s) ? &s->pair[0][0] : NULL;
    int total = 0, direct = u != NULL;
    for (int p = i; p < ie; p++) total += count[p - i];
    for (int q = 0; direct && q < total; q++) direct = pair_interacts(u, dd[q][3]);
    L.dd = direct ? (const double (*)[4])dd : NULL;
    L.noise = noise;
    for (int p = i, off = 0; p < ie; off += count[p - i], p++)
        c[p - i] = direct ? pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 1, 1)
                 : u ? pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 1, 0)
                     : pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 0, 0);
    const PanLanesFn lanes = SIMD_PICK(pan_lanes_portable, pan_lanes_avx2, pan_lanes_avx512);
    lanes(&L, m, acc->inv_sqrt_dt, u);
    for (int p = i, k = 0; p < ie; k += c[p - i], p++) {
        pan_lanes_apply(&L, k, c[p - i], acc);
        if (p + 1 < ie || close_last) pair_close(p, acc, MODEL_PAN2008);
    }
}

#ifdef DPD_HAVE_X86_SIMD
/* The Pan 2008 pairs of a walk batch [i, ie) on AVX-512 (pan_pair_lanes_avx512,
 * the same bits as the lanes): one type pair u whose weight is not a general
 * power, no shear; pv as dpd_batch_lanes'; entry q's noise at
 * noise[v * RNG_BATCH + q]. */
static inline __attribute__((target("avx512f"), always_inline))
void pan_batch_lanes(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                     const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv)
{
    const int mode = pan_weight_mode(u);
    const double inv_rc = rc_power_of_two_inverse(u->rc);
    for (int p = i, off = 0; p < ie; off += count[p - i], p++) {
        pan_pair_lanes_avx512(s, p, near + off, pl + off, noise + off, count[p - i], acc, u, mode, inv_rc, pv);
        pair_close(p, acc, MODEL_PAN2008);
    }
}
__attribute__((target("avx512f"))) static void pan_batch_avx512(const System *s, int i, int ie, const int *near,
        const double *pl, const double *noise, const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv)
{
    if (pv) pan_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, pv);
    else pan_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, NULL);
}
#endif

/* The pairs of particles [i, ie) of a walk batch (count[p - i] entries each,
 * from entry 0 of near, dd and the noise planes), each particle closed after
 * its pairs (the last one only if close_last: a long list comes in several
 * batches). Pan 2008 without the virial: lane by lane (pan_evaluate_lanes). */
static inline __attribute__((always_inline))
void pair_evaluate_batch(const System *s, int i, int ie, int *near, double (*dd)[4], const double *noise,
                         const int *count, PairAcc *acc, PairVirial *pv, const int model, const int le,
                         const int close_last, const int general)
{
    if (model == MODEL_PAN2008 && !pv) {
        pan_evaluate_lanes(s, i, ie, near, dd, noise, count, acc, le, close_last);
        return;
    }
    /* w_R by batch on every step (weight_pow one at a time has the lanes'
     * bits, test_forces weight_pow_same_bits_at_every_level, but the cost of
     * eight: on the measurement steps of fig01's scene it was 10 % of the run) */
    double wr[PAIR_BATCH + 8];
    const int by_batch = model == MODEL_DPD && general;
    if (by_batch) batch_random_weights(s, i, ie, (const double (*)[4])dd, near, count, wr);
    for (int p = i, off = 0; p < ie; off += count[p - i], p++) {
        pair_evaluate(s, p, near + off, dd + off, noise + off, count[p - i], acc, pv, model, le,
                      by_batch ? wr + off : NULL);
        if (p + 1 < ie || close_last) pair_close(p, acc, model);
    }
}

/* The stable ids of pair (i, j), ordered (the key of its noise) */
static inline void pair_ids(const System *s, int i, int j, uint32_t *lo, uint32_t *hi)
{
    const uint32_t a = s->id[i], b = s->id[j];
    *lo = a < b ? a : b;
    *hi = a < b ? b : a;
}

/* Pass 1 of a walk batch: from particle i on (before i1), the list entries
 * of consecutive particles inside the largest cutoff, as long as the next
 * particle's whole list fits in the PAIR_BATCH slots (the caller has taken a
 * longer one alone): near, dd and the ids of each pair, count[p - i] entries
 * of particle p. Returns the end particle ie; *np the entries. wide: the
 * AVX-512 candidate pass (range_avx512), compiled in walk_gather_avx512. */
static inline __attribute__((always_inline))
int walk_gather(const System *s, const NeighborList *nl, int i, int i1, int *near, double (*dd)[4], double *pl,
                int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, const int le, const int wide, const int soa,
                int ahead)
{
    int np = 0, ie = i;
    while (ie < i1 && ie - i < PAIR_BATCH && nl->start[ie + 1] - nl->start[ie] <= PAIR_BATCH - np) {
        int c;
#ifdef DPD_HAVE_X86_SIMD
        if (wide) c = range_avx512(s, nl, ie, nl->start[ie], nl->start[ie + 1], near + np, dd + np, pl + np,
                                   id_a + np, id_b + np, soa, ahead);
        else
#endif
        {
            c = pairs_in_range(s, nl, ie, nl->start[ie], nl->start[ie + 1], near + np, dd + np, le);
            for (int q = np; q < np + c; q++) pair_ids(s, ie, near[q], id_a + q, id_b + q);
        }
        (void)wide; (void)pl; (void)soa; (void)ahead;
        count[ie - i] = c;
        np += c;
        ie++;
    }
    *np_out = np;
    return ie;
}
#ifdef DPD_HAVE_X86_SIMD
__attribute__((target("avx512f"))) static int walk_gather_avx512(const System *s, const NeighborList *nl, int i, int i1,
        int *near, double (*dd)[4], int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, int ahead)
{ return walk_gather(s, nl, i, i1, near, dd, NULL, count, id_a, id_b, np_out, 0, 1, 0, ahead); }
/* the same into planes, for the AVX-512 evaluator */
__attribute__((target("avx512f"))) static int walk_gather_avx512_planes(const System *s, const NeighborList *nl, int i,
        int i1, int *near, double *pl, int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, int ahead)
{ return walk_gather(s, nl, i, i1, near, NULL, pl, count, id_a, id_b, np_out, 0, 1, 1, ahead); }

/* How many particles ahead the AVX-512 candidate pass fetches a particle's
 * candidates (x, v_pred) toward the cache; 0: not at all. The walk's half
 * shell comes back to a cell layer's particles one layer later: once a
 * layer's data (x, v_pred and the force buffer, 72 B per particle) outgrows a
 * quarter of a 1 MB L2, they come from L3 or memory (bench/RESULTS.md: at 1.9e5
 * particles the prefetch gained 2-10 % in two sets of alternating pairs; at
 * 3000, where it all stays in L2, it cost 3-5 %). It changes no number. */
static int walk_prefetch_ahead(const System *s, const NeighborList *nl)
{
    const double layer_bytes = 72.0 * s->n / nl->nc[2];
    return layer_bytes > 256.0 * 1024.0 ? 16 : 0;
}
#endif

#ifdef DPD_HAVE_X86_SIMD
/* The type pair of a walk batch whose particles [i, ie) and partners
 * near[0 .. np) are all of one type t: &s->pair[t][t]; NULL if it mixes types,
 * or on a measurement step (pv) if t is frozen (the force on frozen types is
 * the pair-by-pair evaluators' to record). */
static inline const PairParams *batch_one_type(const System *s, int i, int ie, const int *near, int np,
                                               const PairVirial *pv)
{
    const unsigned t = s->type[i];
    unsigned mixed = 0;
    if (s->ntypes > 1) {
        for (int p = i + 1; p < ie; p++) mixed |= s->type[p] ^ t;
        for (int q = 0; q < np; q++) mixed |= s->type[near[q]] ^ t;
    }
    return mixed || (pv && MOD_FROZEN(&s->types[t])) ? NULL : &s->pair[t][t];
}

/* A batch's planes (x, y, z, r^2, PAIR_PLANE apart) as the rows dd[q] of the pair-by-pair evaluators */
static void planes_to_rows(const double *pl, int np, double (*dd)[4])
{
    for (int q = 0; q < np; q++)
        for (int c = 0; c < 4; c++) dd[q][c] = pl[c * PAIR_PLANE + q];
}
#endif

/* The walk over the particles [i0, i1) of one chunk. The list entries of
 * consecutive particles are gathered up to PAIR_BATCH at a time; those inside
 * the largest cutoff (pairs_in_range) get their noise in one call (Philox
 * lanes: a particle alone has only a few pairs) and go to the model's
 * evaluator particle by particle, in list order, so every sum is formed in the
 * same order as one pair at a time. A particle with more than PAIR_BATCH
 * entries is walked in batches of its own. The list holds interacting type
 * pairs only (neighbor.c keep_pair). model and le (Lees-Edwards shear) are
 * constants: the walk is compiled once per value (pair_chunk), so that a scene
 * without shear or rotation runs no test for them. */
static inline __attribute__((always_inline))
void pair_walk(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc,
               PairVirial *pv, const int model, const int le)
{
    const int nvar = model == MODEL_PAN2008 ? 4 : 1;
    _Static_assert(PAIR_BATCH <= RNG_BATCH, "a batch's noise fits rng_pair_normals' planes");
    int near[PAIR_BATCH + RANGE_SLACK], count[PAIR_BATCH];
    double dd[PAIR_BATCH + RANGE_SLACK][4], noise[4 * RNG_BATCH];   /* variate v of entry q at noise[v * RNG_BATCH + q] */
    uint32_t id_a[PAIR_BATCH + RANGE_SLACK], id_b[PAIR_BATCH + RANGE_SLACK];
#ifdef DPD_HAVE_X86_SIMD
    const int wide = !le && s->box.dim == 3 && simd_level() == SIMD_AVX512;
#endif
    const int general = model == MODEL_DPD && scene_weights_general(s);
#ifdef DPD_HAVE_X86_SIMD
    /* 3D, no shear, no binned virial: the batches into planes, and each batch
     * whose particles are all of one type (in a scene of several, most are the
     * solvent's) to the AVX-512 evaluator of that type pair */
    double pl[4 * PAIR_PLANE], wr[PAIR_BATCH + 8];
    const int planes = wide && (!pv || pv->nbins == 0);
    const int ahead = wide ? walk_prefetch_ahead(s, nl) : 0;
#endif
    for (int a = 0; a < 3; a++) acc->fi[a] = acc->ti[a] = 0.0;
    for (int i = i0; i < i1;) {
        if (nl->start[i + 1] - nl->start[i] > PAIR_BATCH) {   /* a long list: batches of its own */
            for (int k0 = nl->start[i]; k0 < nl->start[i + 1]; k0 += PAIR_BATCH) {
                const int k1 = k0 + PAIR_BATCH < nl->start[i + 1] ? k0 + PAIR_BATCH : nl->start[i + 1];
                const int m = pairs_in_range(s, nl, i, k0, k1, near, dd, le);
                for (int q = 0; q < m; q++) pair_ids(s, i, near[q], id_a + q, id_b + q);
                rng_pair_normals_ordered(s->seed, s->step, m, id_a, id_b, nvar, noise);
                pair_evaluate_batch(s, i, i + 1, near, dd, noise, &m, acc, pv, model, le, 0, general);
            }
            pair_close(i, acc, model);
            i++;
            continue;
        }
        int np, ie;
#ifdef DPD_HAVE_X86_SIMD
        if (planes) {
            ie = walk_gather_avx512_planes(s, nl, i, i1, near, pl, count, id_a, id_b, &np, ahead);
            rng_pair_normals_ordered(s->seed, s->step, np, id_a, id_b, nvar, noise);
            const PairParams *u = batch_one_type(s, i, ie, near, np, pv);
            if (u && model == MODEL_DPD) {
                if (weight_general(u->s)) batch_random_weights_avx512(u, pl + 3 * PAIR_PLANE, np, wr);
                dpd_batch_avx512(s, i, ie, near, pl, noise, count, acc, u, wr, pv);
            } else if (u && !weight_general(u->s)) {
                pan_batch_avx512(s, i, ie, near, pl, noise, count, acc, u, pv);
            } else {   /* several type pairs, or Pan 2008 with a general power: pair by pair */
                planes_to_rows(pl, np, dd);
                pair_evaluate_batch(s, i, ie, near, dd, noise, count, acc, pv, model, le, 1, general);
            }
            i = ie;
            continue;
        }
        if (wide) ie = walk_gather_avx512(s, nl, i, i1, near, dd, count, id_a, id_b, &np, ahead);
        else
#endif
        ie = walk_gather(s, nl, i, i1, near, dd, NULL, count, id_a, id_b, &np, le, 0, 0, 0);
        rng_pair_normals_ordered(s->seed, s->step, np, id_a, id_b, nvar, noise);
        pair_evaluate_batch(s, i, ie, near, dd, noise, count, acc, pv, model, le, 1, general);
        i = ie;
    }
}

static void walk_dpd_plain(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc, PairVirial *pv)
{ pair_walk(s, nl, i0, i1, acc, pv, MODEL_DPD, 0); }
static void walk_dpd_shear(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc, PairVirial *pv)
{ pair_walk(s, nl, i0, i1, acc, pv, MODEL_DPD, 1); }
static void walk_pan2008_plain(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc, PairVirial *pv)
{ pair_walk(s, nl, i0, i1, acc, pv, MODEL_PAN2008, 0); }
static void walk_pan2008_shear(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc, PairVirial *pv)
{ pair_walk(s, nl, i0, i1, acc, pv, MODEL_PAN2008, 1); }

/* One chunk with the walk the scene's model and box need. */
static void pair_chunk(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc, PairVirial *pv)
{
    const int le = MOD_SHEAR(&s->box);
    if (MOD_ROTATION(s)) (le ? walk_pan2008_shear : walk_pan2008_plain)(s, nl, i0, i1, acc, pv);
    else (le ? walk_dpd_shear : walk_dpd_plain)(s, nl, i0, i1, acc, pv);
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
    const int n = s->n, rot = MOD_ROTATION(s);
    const size_t stride = 3 * (size_t)n;
    /* contiguous chunks per thread (thread 0: the first half of the particles
     * on 2 threads), as the particle loops of the integrator: each thread
     * reads and writes mostly the particles it will move */
    #pragma omp parallel for schedule(static)
    for (int c = 0; c < FORCE_CHUNKS; c++) {
        /* chunk 0 accumulates straight into f (and the torques): one buffer less to clear and read */
        PairAcc acc = {.f = c == 0 ? s->f : w->buf + (size_t)(c - 1) * stride,
                       .tq = !rot ? NULL : c == 0 ? s->torque : w->tbuf + (size_t)(c - 1) * stride,
                       .touched = forces_chunk_mask(w, c), .n = n, .inv_sqrt_dt = 1.0 / sqrt(s->dt)};
        const int i0 = forces_chunk_start(nl, n, c), i1 = forces_chunk_start(nl, n, c + 1);
        PairVirial *cv = NULL;
        if (pv) { cv = &w->chunk[c]; cv->bin_axis = pv->bin_axis; cv->nbins = pv->nbins; forces_zero_virial(cv); }
        pair_chunk(s, nl, i0, i1, &acc, cv);
    }
    if (rot) forces_sum_chunks(w, s->f, w->buf, s->torque, w->tbuf);
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
