/* pair_avx512.c - the backend's pair kernels (src/simd/: every intrinsic of
 * the simulator; simd.h): the walk's candidate pass and the pair styles'
 * AVX-512 evaluators of one-type batches, behind the entry points
 * of pair_avx512.h, which forces.c picks once per force call (pair_kernels)
 * and the styles register as their accelerators (pair_style.h PairAccel).
 * Each kernel performs the scalar code's IEEE operations in its order (no
 * contraction: -std=c11 keeps it off), so it gives the same bits; the tests
 * compare every level with the scalar evaluators (test_forces
 * levels_same_forces, test_rotation lanes_same_bits_as_pair_by_pair,
 * test_reference_forces). On a compiler or machine without x86 SIMD this
 * file is empty and the styles register none of it (simd.h SIMD_X86). */
#include "pair_avx512.h"
#include "pair_walk.h"
#include "simd.h"

/* How many particles ahead the AVX-512 candidate pass fetches a particle's
 * candidates (x, v_pred) toward the cache; 0: not at all. The walk's half
 * shell comes back to a cell layer's particles one layer later: once a
 * layer's data (x, v_pred and the force buffer, 72 B per particle) outgrows a
 * quarter of a 1 MB L2, they come from L3 or memory (bench/RESULTS.md: at 1.9e5
 * particles the prefetch gained 2-10 % in two sets of alternating pairs; at
 * 3000, where it all stays in L2, it cost 3-5 %). It changes no number. */
int pair_prefetch_ahead(const System *s, const NeighborList *nl)
{
    const double layer_bytes = 72.0 * s->n / nl->nc[2];
    return layer_bytes > 256.0 * 1024.0 ? 16 : 0;
}

#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>
#define AVX512 __attribute__((target("avx512f")))

/* ---- shared by the kernels ------------------------------------------------ */
/* r / rc in eight lanes, as the scalar evaluators divide (eq. 5); when rc is a
 * power of two (rc = 1 in most scenes) the product r * (1 / rc) is the same
 * number, without the divider, which the lanes' square roots keep busy.
 * inv_rc: rc_power_of_two_inverse(rc), formed once. */
static inline double rc_power_of_two_inverse(double rc)
{
    int e;
    return frexp(rc, &e) == 0.5 ? 1.0 / rc : 0.0;
}
static inline __attribute__((target("avx512f"), always_inline))
__m512d r_over_rc_avx512(__m512d r, double rc, double inv_rc)
{
    return inv_rc != 0.0 ? _mm512_mul_pd(r, _mm512_set1_pd(inv_rc)) : _mm512_div_pd(r, _mm512_set1_pd(rc));
}

/* The lanes of live whose r^2 interacts (pair_interacts: !(r2 >= rc2 || r2 < eps2), a NaN interacts) */
static inline __attribute__((target("avx512f"), always_inline))
__mmask8 pair_interacts_avx512(__m512d r2, __m512d rc2, __m512d eps2, __mmask8 live)
{
    return live & ~(_mm512_cmp_pd_mask(r2, rc2, _CMP_GE_OQ) | _mm512_cmp_pd_mask(r2, eps2, _CMP_LT_OQ));
}

/* Pairs q0 .. q0 + cnt - 1 (cnt <= 8) of a particle's run in the walk's
 * planes (pl: x, y, z, r^2, PAIR_PLANE apart; near: j): their separations,
 * 3 j for the gathers, the live lanes and those that interact
 * (pair_interacts: !(r2 >= rc2 || r2 < eps2), a NaN interacts). */
typedef struct { __m512d d0, d1, d2, r2; __m256i j3; __mmask8 live, act; int cnt; } PairLanes8;
static inline __attribute__((target("avx512f"), always_inline))
PairLanes8 pair_lanes_load_avx512(const double *pl, const int *near, int q0, int m, __m512d rc2, __m512d eps2)
{
    PairLanes8 g;
    g.cnt = m - q0 < 8 ? m - q0 : 8;
    g.live = (__mmask8)((1u << g.cnt) - 1);
    g.d0 = _mm512_maskz_loadu_pd(g.live, pl + q0);
    g.d1 = _mm512_maskz_loadu_pd(g.live, pl + PAIR_PLANE + q0);
    g.d2 = _mm512_maskz_loadu_pd(g.live, pl + 2 * PAIR_PLANE + q0);
    g.r2 = _mm512_maskz_loadu_pd(g.live, pl + 3 * PAIR_PLANE + q0);
    g.act = pair_interacts_avx512(g.r2, rc2, eps2, g.live);
    const __m256i j = _mm512_castsi512_si256(_mm512_maskz_loadu_epi32((__mmask16)g.live, near + q0));
    g.j3 = _mm256_add_epi32(j, _mm256_add_epi32(j, j));
    return g;
}

/* A measurement step's sums of eight pairs: their virial terms (t[k], lane l
 * pair l's component k = 9 part + 3 a + b, PairVirial W's order) and energies
 * e, added pair by pair in list order (the lanes set in act) into W and epot
 * as the pair-by-pair evaluators add them: the same bits. */
static inline __attribute__((target("avx512f"), always_inline))
void virial_lanes_add(PairVirial *pv, const __m512d t[PAIR_PARTS * 9], __m512d e, __mmask8 act)
{
    double T[PAIR_PARTS * 9][8], E[8], *W = &pv->W[0][0][0];
    for (int k = 0; k < PAIR_PARTS * 9; k++) _mm512_storeu_pd(T[k], t[k]);
    _mm512_storeu_pd(E, e);
    for (unsigned b = act; b; b &= b - 1) {
        const int l = __builtin_ctz(b);
        for (int k = 0; k < PAIR_PARTS * 9; k++) W[k] += T[k][l];
        pv->epot += E[l];
    }
}

/* ---- the candidate pass -------------------------------------------------- */
/* pairs_in_range (pair.h) eight candidates at a time, for boxes without
 * Lees-Edwards shear in 3 dimensions: the same subtractions, folds and r^2
 * (no contraction: -std=c11 keeps it off), so the same bits and the same kept
 * entries in the same order. The kept j, separations and r^2, and the pairs'
 * ids are compressed into registers and stored whole (near, dd, id_a and id_b
 * need RANGE_SLACK entries of room past the last one). */
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
    if (ahead && i + ahead < s->n)   /* pair_prefetch_ahead */
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

/* walk_gather (pair_walk.h) with range_avx512: into rows dd, or (soa) into planes pl */
static inline AVX512 __attribute__((always_inline))
int gather_avx512(const System *s, const NeighborList *nl, int i, int i1, int *near, double (*dd)[4], double *pl,
                  int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, const int soa, int ahead)
{
    int np = 0, ie = i;
    while (ie < i1 && ie - i < PAIR_BATCH && nl->start[ie + 1] - nl->start[ie] <= PAIR_BATCH - np) {
        const int c = range_avx512(s, nl, ie, nl->start[ie], nl->start[ie + 1], near + np, soa ? NULL : dd + np,
                                   soa ? pl + np : NULL, id_a + np, id_b + np, soa, ahead);
        count[ie - i] = c;
        np += c;
        ie++;
    }
    *np_out = np;
    return ie;
}
AVX512 int pair_gather_rows_avx512(const System *s, const NeighborList *nl, int i, int i1, int *near, double (*dd)[4],
                                   int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, int ahead)
{ return gather_avx512(s, nl, i, i1, near, dd, NULL, count, id_a, id_b, np_out, 0, ahead); }
AVX512 int pair_gather_planes_avx512(const System *s, const NeighborList *nl, int i, int i1, int *near, double *pl,
                                     int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, int ahead)
{ return gather_avx512(s, nl, i, i1, near, NULL, pl, count, id_a, id_b, np_out, 1, ahead); }

/* ---- standard DPD (pair_dpd.c) ------------------------------------------- */
/* pair_random_weights (pair.h) for one type pair u (a general exponent) on AVX-512:
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

/* pair_dpd.c dpd_pair through the walk (pair_walk.h pair_batch) for one type pair (u) without shear (pv != NULL: the virial
 * and energy as pair_record_central forms them, no bins; a frozen particle's force as it records it), the per-pair
 * arithmetic eight pairs at a time on AVX-512: the same IEEE operations in
 * the same order (no contraction), so the same F_ij bits; the sums into
 * acc->fi and -F_ij into f_j are then added pair by pair in list order, as
 * pair_batch adds them. wcase: w_R from w_C (2: s = 2, 1: s = 1,
 * 0: s = 0.5, -1: the batch's wr, weight_general); inv_rc:
 * rc_power_of_two_inverse(u->rc). pl: the separations x,
 * y, z and r^2 of the pairs as planes, PAIR_PLANE apart (range_avx512). */
static inline __attribute__((target("avx512f"), always_inline))
void dpd_pair_lanes_avx512(const System *s, int i, const int *near, const double *pl, const double *theta,
                           int m, PairAcc *acc, const PairParams *u, const int wcase, const double *wr_batch,
                           double inv_rc, PairVirial *pv)
{
    const double energy = 0.5 * u->a * u->rc;   /* pair_energy's first factors */
    const double *v = s->v_pred;
    const __m512d vix = _mm512_set1_pd(v[3 * i]), viy = _mm512_set1_pd(v[3 * i + 1]), viz = _mm512_set1_pd(v[3 * i + 2]);
    const __m512d rc2 = _mm512_set1_pd(u->rc2), one = _mm512_set1_pd(1.0);
    const __m512d eps2 = _mm512_set1_pd(PAIR_R_EPSILON * PAIR_R_EPSILON);
    const __m512d a = _mm512_set1_pd(u->a), ngamma = _mm512_set1_pd(-u->gamma), sigma = _mm512_set1_pd(u->sigma);
    const __m512d isdt = _mm512_set1_pd(acc->inv_sqrt_dt);
    double fi0 = acc->fi[0], fi1 = acc->fi[1], fi2 = acc->fi[2];
    const int frozen_i = pv && MOD_FROZEN(&s->types[s->type[i]]);   /* measurement steps: frozen particles' records */
    for (int q0 = 0; q0 < m; q0 += 8) {
        const PairLanes8 g = pair_lanes_load_avx512(pl, near, q0, m, rc2, eps2);
        const int cnt = g.cnt;
        const __mmask8 live = g.live, act = g.act;
        const __m512d dx = g.d0, dy = g.d1, dz = g.d2, r2 = g.r2;
        const __m256i j3 = g.j3;
        const __m512d z0 = _mm512_setzero_pd();
        const __m512d dvx = _mm512_sub_pd(vix, _mm512_mask_i32gather_pd(z0, live, j3, v, 8));
        const __m512d dvy = _mm512_sub_pd(viy, _mm512_mask_i32gather_pd(z0, live, j3, v + 1, 8));
        const __m512d dvz = _mm512_sub_pd(viz, _mm512_mask_i32gather_pd(z0, live, j3, v + 2, 8));
        const __m512d r = _mm512_sqrt_pd(r2), inv_r = _mm512_div_pd(one, r);
        const __m512d ex = _mm512_mul_pd(dx, inv_r), ey = _mm512_mul_pd(dy, inv_r), ez = _mm512_mul_pd(dz, inv_r);
        const __m512d edv = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ex, dvx), _mm512_mul_pd(ey, dvy)), _mm512_mul_pd(ez, dvz));
        const __m512d wc = _mm512_sub_pd(one, r_over_rc_avx512(r, u->rc, inv_rc));   /* w_C, eq. 5 */
        const __m512d wr = wcase == 2 ? wc : wcase == 1 ? _mm512_sqrt_pd(wc)              /* w_R, eq. 7 */
                         : wcase == 0 ? _mm512_sqrt_pd(_mm512_sqrt_pd(wc)) : _mm512_maskz_loadu_pd(live, wr_batch + q0);
        const __m512d fc = _mm512_mul_pd(a, wc);                                           /* eq. 2 */
        const __m512d fd = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(ngamma, wr), wr), edv); /* eq. 3 */
        const __m512d fr = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(sigma, wr), _mm512_maskz_loadu_pd(live, theta + q0)), isdt); /* eq. 4 */
        const __m512d ft = _mm512_add_pd(_mm512_add_pd(fc, fd), fr);
        if (pv) {   /* pair_record_central: r_a r_b F / r by part, the energy a rc w_C^2 / 2 */
            const __m512d d3[3] = {dx, dy, dz}, part[PAIR_PARTS] = {fc, fd, fr};
            __m512d t[PAIR_PARTS * 9];
            for (int q = 0; q < PAIR_PARTS; q++) {
                const __m512d g = _mm512_mul_pd(part[q], inv_r);
                for (int a3 = 0; a3 < 3; a3++)
                    for (int c = 0; c < 3; c++) t[9 * q + 3 * a3 + c] = _mm512_mul_pd(_mm512_mul_pd(d3[a3], d3[c]), g);
            }
            virial_lanes_add(pv, t, _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(energy), wc), wc), act);
        }
        double fx[8], fy[8], fz[8];
        _mm512_storeu_pd(fx, _mm512_mul_pd(ft, ex));
        _mm512_storeu_pd(fy, _mm512_mul_pd(ft, ey));
        _mm512_storeu_pd(fz, _mm512_mul_pd(ft, ez));
        for (int l = 0; l < cnt; l++) {
            if (!(act >> l & 1)) continue;
            const int jj = near[q0 + l];
            fi0 += fx[l]; fi1 += fy[l]; fi2 += fz[l];
            force_claim(acc->f, NULL, acc->touched, jj, acc->n);
            acc->f[3 * jj] -= fx[l]; acc->f[3 * jj + 1] -= fy[l]; acc->f[3 * jj + 2] -= fz[l];
            if (pv && (frozen_i || MOD_FROZEN(&s->types[s->type[jj]])))
                pair_record_frozen_central(pv, s, i, jj, (const double[3]){fx[l], fy[l], fz[l]});
        }
    }
    acc->fi[0] = fi0; acc->fi[1] = fi1; acc->fi[2] = fi2;
}

/* The standard pairs of a walk batch [i, ie) on AVX-512 (dpd_pair_lanes_avx512,
 * the same bits as pair by pair): one type pair u, no shear; pv != NULL
 * (measurement steps): the virial and energy too (not binned), and the
 * force on frozen particles. Every particle of the batch closed after its pairs. Compiled once
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
        pair_close_spins(0, p, acc);
    }
}
__attribute__((target("avx512f"))) static void dpd_batch_avx512(const System *s, int i, int ie, const int *near,
        const double *pl, const double *noise, const int *count, PairAcc *acc, const PairParams *u,
        const double *wr, PairVirial *pv)
{
    if (pv) dpd_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, wr, pv);
    else dpd_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, wr, NULL);
}

/* ---- Pan et al. 2008 (pair_pan2008.c) ------------------------------------ */
/* -x, as C's unary minus (a flip of the sign bit: 0 - x would give +0 for +0) */
static inline __attribute__((target("avx512f"), always_inline)) __m512d neg(__m512d x)
{
    return _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(x), _mm512_set1_epi64((long long)0x8000000000000000ULL)));
}
/* Passes 1-3 for one type pair u whose weight is not a general power, no
 * shear; pv != NULL (measurement steps, no bins; frozen particles' records as
 * pair_record_frozen_eq1, pair by pair in list order): the virial
 * by part and the energy as pair_record_eq1 forms them, added pair by pair
 * (virial_lanes_add): particle i's m pairs (near; pl: separations x, y, z, r^2
 * as planes, PAIR_PLANE apart; nz: rng_pair_normals' planes from entry 0)
 * eight at a time on AVX-512, with pan_lanes_loop's operations in its order
 * (no contraction: the same bits), v_j and Omega_j gathered, then added to i
 * and to j pair by pair in list order as pan_lanes_apply adds them. inv_rc:
 * rc_power_of_two_inverse(u->rc). */
static inline __attribute__((target("avx512f"), always_inline))
void pan_pair_lanes_avx512(const System *s, int i, const int *near, const double *pl, const double *nz, int m,
                           PairAcc *acc, const PairParams *u, const int mode, double inv_rc, PairVirial *pv)
{
    const double energy = 0.5 * u->a * u->rc;   /* pair_energy's first factors */
    const double *v = s->v_pred, *w = s->omega_pred;
    const __m512d vix = _mm512_set1_pd(v[3 * i]), viy = _mm512_set1_pd(v[3 * i + 1]), viz = _mm512_set1_pd(v[3 * i + 2]);
    const __m512d wix = _mm512_set1_pd(w[3 * i]), wiy = _mm512_set1_pd(w[3 * i + 1]), wiz = _mm512_set1_pd(w[3 * i + 2]);
    const __m512d one = _mm512_set1_pd(1.0), half = _mm512_set1_pd(0.5), z0 = _mm512_setzero_pd();
    const __m512d rc2 = _mm512_set1_pd(u->rc2);
    const __m512d eps2 = _mm512_set1_pd(PAIR_R_EPSILON * PAIR_R_EPSILON);
    const __m512d a = _mm512_set1_pd(u->a), ngamma = _mm512_set1_pd(-u->gamma), sigma = _mm512_set1_pd(u->sigma);
    const __m512d gshear = _mm512_set1_pd(u->gamma_shear), sshear = _mm512_set1_pd(u->sigma_shear);
    const __m512d isdt = _mm512_set1_pd(acc->inv_sqrt_dt);
    const int shear = u->gamma_shear != 0.0;
    double fi[3] = {acc->fi[0], acc->fi[1], acc->fi[2]}, ti[3] = {acc->ti[0], acc->ti[1], acc->ti[2]};
    const int frozen_i = pv && MOD_FROZEN(&s->types[s->type[i]]);   /* measurement steps: frozen particles' records */
    for (int q0 = 0; q0 < m; q0 += 8) {
        const PairLanes8 g = pair_lanes_load_avx512(pl, near, q0, m, rc2, eps2);
        const int cnt = g.cnt;
        const __mmask8 live = g.live, act = g.act;
        const __m512d d0 = g.d0, d1 = g.d1, d2 = g.d2, r2 = g.r2;
        const __m256i j3 = g.j3;
        /* pan_pair_geometry */
        const __m512d r = _mm512_sqrt_pd(r2), inv_r = _mm512_div_pd(one, r);
        const __m512d e0 = _mm512_mul_pd(d0, inv_r), e1 = _mm512_mul_pd(d1, inv_r), e2 = _mm512_mul_pd(d2, inv_r);
        const __m512d wc = _mm512_sub_pd(one, r_over_rc_avx512(r, u->rc, inv_rc));   /* w_C, eq. 5 */
        const __m512d f = mode == 0 ? wc : mode == 1 ? _mm512_sqrt_pd(wc) : _mm512_sqrt_pd(_mm512_sqrt_pd(wc));
        /* pan_lanes_fill: v_ij and Omega_i + Omega_j */
        const __m512d v0 = _mm512_sub_pd(vix, _mm512_mask_i32gather_pd(z0, live, j3, v, 8));
        const __m512d v1 = _mm512_sub_pd(viy, _mm512_mask_i32gather_pd(z0, live, j3, v + 1, 8));
        const __m512d v2 = _mm512_sub_pd(viz, _mm512_mask_i32gather_pd(z0, live, j3, v + 2, 8));
        const __m512d edv = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(e0, v0), _mm512_mul_pd(e1, v1)), _mm512_mul_pd(e2, v2));
        const __m512d fc = _mm512_mul_pd(a, wc);                                                  /* eq. 7 */
        const __m512d fdc = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(ngamma, f), f), edv);         /* eq. 13, central */
        const __m512d theta = _mm512_maskz_loadu_pd(live, nz + q0);
        const __m512d frc = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(sigma, f), theta), isdt);    /* eq. 15, central */
        const __m512d ft = _mm512_add_pd(_mm512_add_pd(fc, fdc), frc);
        double F[3][8], tau[3][8];
        __m512d F0 = _mm512_mul_pd(ft, e0), F1 = _mm512_mul_pd(ft, e1), F2 = _mm512_mul_pd(ft, e2);
        __m512d T0 = z0, T1 = z0, T2 = z0;
        __m512d P[PAIR_PARTS][3];   /* measurement steps: F by part (pan_pair_force's F) */
        if (pv) {
            const __m512d ee[3] = {e0, e1, e2};
            for (int c = 0; c < 3; c++) {
                P[0][c] = _mm512_mul_pd(fc, ee[c]); P[1][c] = _mm512_mul_pd(fdc, ee[c]); P[2][c] = _mm512_mul_pd(frc, ee[c]);
            }
        }
        if (shear) {
            const __m512d w0 = _mm512_add_pd(wix, _mm512_mask_i32gather_pd(z0, live, j3, w, 8));
            const __m512d w1 = _mm512_add_pd(wiy, _mm512_mask_i32gather_pd(z0, live, j3, w + 1, 8));
            const __m512d w2 = _mm512_add_pd(wiz, _mm512_mask_i32gather_pd(z0, live, j3, w + 2, 8));
            const __m512d h0 = _mm512_mul_pd(half, d0), h1 = _mm512_mul_pd(half, d1), h2 = _mm512_mul_pd(half, d2);
            /* (r_ij / 2) x (Omega_i + Omega_j) */
            const __m512d o0 = _mm512_sub_pd(_mm512_mul_pd(h1, w2), _mm512_mul_pd(h2, w1));
            const __m512d o1 = _mm512_sub_pd(_mm512_mul_pd(h2, w0), _mm512_mul_pd(h0, w2));
            const __m512d o2 = _mm512_sub_pd(_mm512_mul_pd(h0, w1), _mm512_mul_pd(h1, w0));
            const __m512d ngs = neg(_mm512_mul_pd(gshear, _mm512_mul_pd(f, f)));   /* -gs */
            const __m512d x0 = _mm512_maskz_loadu_pd(live, nz + RNG_BATCH + q0);
            const __m512d x1 = _mm512_maskz_loadu_pd(live, nz + 2 * RNG_BATCH + q0);
            const __m512d x2 = _mm512_maskz_loadu_pd(live, nz + 3 * RNG_BATCH + q0);
            /* xi x e */
            const __m512d xe0 = _mm512_sub_pd(_mm512_mul_pd(x1, e2), _mm512_mul_pd(x2, e1));
            const __m512d xe1 = _mm512_sub_pd(_mm512_mul_pd(x2, e0), _mm512_mul_pd(x0, e2));
            const __m512d xe2 = _mm512_sub_pd(_mm512_mul_pd(x0, e1), _mm512_mul_pd(x1, e0));
            const __m512d frs = _mm512_mul_pd(_mm512_mul_pd(sshear, f), isdt);
            /* eqs 13-14 and 15, non-central: dissipative fd, random fr */
            const __m512d fd0 = _mm512_mul_pd(ngs, _mm512_add_pd(_mm512_sub_pd(v0, _mm512_mul_pd(edv, e0)), o0)), fr0 = _mm512_mul_pd(frs, xe0);
            const __m512d fd1 = _mm512_mul_pd(ngs, _mm512_add_pd(_mm512_sub_pd(v1, _mm512_mul_pd(edv, e1)), o1)), fr1 = _mm512_mul_pd(frs, xe1);
            const __m512d fd2 = _mm512_mul_pd(ngs, _mm512_add_pd(_mm512_sub_pd(v2, _mm512_mul_pd(edv, e2)), o2)), fr2 = _mm512_mul_pd(frs, xe2);
            const __m512d s0 = _mm512_add_pd(fd0, fr0), s1 = _mm512_add_pd(fd1, fr1), s2 = _mm512_add_pd(fd2, fr2);
            if (pv) {   /* pan_pair_force's parts: F[1] += fds, F[2] += frs */
                P[1][0] = _mm512_add_pd(P[1][0], fd0); P[1][1] = _mm512_add_pd(P[1][1], fd1); P[1][2] = _mm512_add_pd(P[1][2], fd2);
                P[2][0] = _mm512_add_pd(P[2][0], fr0); P[2][1] = _mm512_add_pd(P[2][1], fr1); P[2][2] = _mm512_add_pd(P[2][2], fr2);
            }
            /* eq. 1: tau = -(h x F^S) */
            T0 = neg(_mm512_sub_pd(_mm512_mul_pd(h1, s2), _mm512_mul_pd(h2, s1)));
            T1 = neg(_mm512_sub_pd(_mm512_mul_pd(h2, s0), _mm512_mul_pd(h0, s2)));
            T2 = neg(_mm512_sub_pd(_mm512_mul_pd(h0, s1), _mm512_mul_pd(h1, s0)));
            F0 = _mm512_add_pd(F0, s0); F1 = _mm512_add_pd(F1, s1); F2 = _mm512_add_pd(F2, s2);
        }
        if (pv) {   /* pair_record_eq1: r_a F_b by part, the energy a rc w_C^2 / 2 */
            const __m512d d3[3] = {d0, d1, d2};
            __m512d t[PAIR_PARTS * 9];
            for (int q = 0; q < PAIR_PARTS; q++)
                for (int a3 = 0; a3 < 3; a3++)
                    for (int c = 0; c < 3; c++) t[9 * q + 3 * a3 + c] = _mm512_mul_pd(d3[a3], P[q][c]);
            virial_lanes_add(pv, t, _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(energy), wc), wc), act);
        }
        _mm512_storeu_pd(F[0], F0); _mm512_storeu_pd(F[1], F1); _mm512_storeu_pd(F[2], F2);
        _mm512_storeu_pd(tau[0], T0); _mm512_storeu_pd(tau[1], T1); _mm512_storeu_pd(tau[2], T2);
        double Pl[PAIR_PARTS][3][8];   /* measurement steps: the parts, for the frozen particles' records */
        if (pv)
            for (int q = 0; q < PAIR_PARTS; q++)
                for (int c = 0; c < 3; c++) _mm512_storeu_pd(Pl[q][c], P[q][c]);
        for (int l = 0; l < cnt; l++) {
            if (!(act >> l & 1)) continue;
            const int j = near[q0 + l];
            force_claim(acc->f, acc->tq, acc->touched, j, acc->n);
            for (int c = 0; c < 3; c++) {
                fi[c] += F[c][l];
                acc->f[3 * j + c] -= F[c][l];
                ti[c] += tau[c][l];
                acc->tq[3 * j + c] += tau[c][l];
            }
            if (pv && (frozen_i || MOD_FROZEN(&s->types[s->type[j]]))) {
                const double d[3] = {pl[q0 + l], pl[PAIR_PLANE + q0 + l], pl[2 * PAIR_PLANE + q0 + l]};
                double part[PAIR_PARTS][3];
                for (int q = 0; q < PAIR_PARTS; q++)
                    for (int c = 0; c < 3; c++) part[q][c] = Pl[q][c][l];
                pair_record_frozen_eq1(pv, s, i, j, d, (const double (*)[3])part,
                                       (const double[3]){tau[0][l], tau[1][l], tau[2][l]});
            }
        }
    }
    for (int c = 0; c < 3; c++) { acc->fi[c] = fi[c]; acc->ti[c] = ti[c]; }
}

/* The Pan 2008 pairs of a walk batch [i, ie) on AVX-512 (pan_pair_lanes_avx512,
 * the same bits as the lanes): one type pair u whose weight is not a general
 * power, no shear; pv as dpd_batch_lanes'; entry q's noise at
 * noise[v * RNG_BATCH + q]. */
static inline __attribute__((target("avx512f"), always_inline))
void pan_batch_lanes(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                     const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv)
{
    const int mode = u->s == 2.0 ? 0 : u->s == 1.0 ? 1 : 2;   /* random_weight: s = 2, 1, 0.5 */
    const double inv_rc = rc_power_of_two_inverse(u->rc);
    for (int p = i, off = 0; p < ie; off += count[p - i], p++) {
        pan_pair_lanes_avx512(s, p, near + off, pl + off, noise + off, count[p - i], acc, u, mode, inv_rc, pv);
        pair_close_spins(1, p, acc);
    }
}
__attribute__((target("avx512f"))) static void pan_batch_avx512(const System *s, int i, int ie, const int *near,
        const double *pl, const double *noise, const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv)
{
    if (pv) pan_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, pv);
    else pan_batch_lanes(s, i, ie, near, pl, noise, count, acc, u, NULL);
}

/* ---- the styles' accelerators (pair_avx512.h) ---------------------------- */
AVX512 int dpd_one_type_avx512(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                               const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv)
{
    double wr[PAIR_BATCH + 8];
    int np = 0;
    for (int p = i; p < ie; p++) np += count[p - i];
    if (weight_general(u->s)) batch_random_weights_avx512(u, pl + 3 * PAIR_PLANE, np, wr);
    dpd_batch_avx512(s, i, ie, near, pl, noise, count, acc, u, wr, pv);
    return 1;
}
AVX512 int pan_one_type_avx512(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                               const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv)
{
    if (weight_general(u->s)) return 0;   /* a general power: pair by pair */
    pan_batch_avx512(s, i, ie, near, pl, noise, count, acc, u, pv);
    return 1;
}
#undef AVX512
#endif
