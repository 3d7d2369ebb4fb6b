/* ziggurat_x86.c - the backend's ziggurat kernels (simd.h SimdKernels): the
 * first step of GSL's gsl_ran_gaussian_ziggurat on 16 words at a time
 * (random.c zig_accept's product and sign flip, so the same bits), the pairs
 * of a batch not accepted at once listed without a branch per pair, and GSL's
 * wedge test settled within the brackets random.c reads out of GSL
 * (wedge_init), the rest left open (WEDGE_OPEN) for GSL itself. The tables
 * are random.c's (ZigTables). tests/test_random.c runs each level against one
 * pair at a time. */
#include "simd_x86.h"

#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>

/* t->k[i] for 16 strips i < 128 from registers (two-table permutes of 32
 * entries, then bits 5 and 6 of i choose): cheaper than a gather */
__attribute__((target("avx512f"))) static inline __m512i zig_k_lookup_avx512(const uint32_t *zig_k, __m512i i)
{
    const __m512i *t = (const __m512i *)zig_k;
    const __m512i a = _mm512_permutex2var_epi32(_mm512_loadu_si512(t), i, _mm512_loadu_si512(t + 1));
    const __m512i b = _mm512_permutex2var_epi32(_mm512_loadu_si512(t + 2), i, _mm512_loadu_si512(t + 3));
    const __m512i c = _mm512_permutex2var_epi32(_mm512_loadu_si512(t + 4), i, _mm512_loadu_si512(t + 5));
    const __m512i d = _mm512_permutex2var_epi32(_mm512_loadu_si512(t + 6), i, _mm512_loadu_si512(t + 7));
    const __mmask16 b5 = _mm512_test_epi32_mask(i, _mm512_set1_epi32(32)), b6 = _mm512_test_epi32_mask(i, _mm512_set1_epi32(64));
    return _mm512_mask_blend_epi32(b6, _mm512_mask_blend_epi32(b5, a, b), _mm512_mask_blend_epi32(b5, c, d));
}
/* The ziggurat's first step on 16 words at a time: the same product
 * j * t->w[i] and the same sign flip as zig_accept, so the same bits; ok[g]
 * has bit l set if word 16 g + l was accepted at once. The last group is
 * masked (its bits past m set, as accepted): returns m, every word done. */
__attribute__((target("avx512f"))) int simd_zig_first_avx512(int m, const uint32_t *w, double *z, uint16_t *ok, const ZigTables *t)
{
    const __m512i low7 = _mm512_set1_epi32(0x7f), bit7 = _mm512_set1_epi32(0x80);
    const __m512i sign = _mm512_set1_epi64((long long)0x8000000000000000ULL);
    for (int q = 0; q < m; q += 16) {
        const __mmask16 live = m - q >= 16 ? 0xffff : (__mmask16)((1u << (m - q)) - 1);
        const __m512i k = _mm512_maskz_loadu_epi32(live, w + q);   /* 0 past m: strip 0, j = 0 */
        const __m512i i = _mm512_and_si512(k, low7), j = _mm512_srli_epi32(k, 8);
        ok[q / 16] = _mm512_cmplt_epu32_mask(j, zig_k_lookup_avx512(t->k, i)) | (__mmask16)~live;
        const __mmask16 neg = _mm512_testn_epi32_mask(k, bit7);
        for (int h = 0; h < 2; h++) {
            const __m256i ih = h ? _mm512_extracti64x4_epi64(i, 1) : _mm512_castsi512_si256(i);
            const __m256i jh = h ? _mm512_extracti64x4_epi64(j, 1) : _mm512_castsi512_si256(j);
            const __m512d x = _mm512_mul_pd(_mm512_cvtepu32_pd(jh), _mm512_i32gather_pd(ih, t->w, 8));
            const __m512i xi = _mm512_castpd_si512(x);
            _mm512_mask_storeu_pd(z + q + 8 * h, (__mmask8)(live >> (8 * h)),
                                  _mm512_castsi512_pd(_mm512_mask_xor_epi64(xi, (__mmask8)(neg >> (8 * h)), xi, sign)));
        }
    }
    return m;
}

/* The same on AVX2, 8 words per half of a group of 16 (so ok[] is laid out as
 * simd_zig_first_avx512's): j and t->k are below 2^24, so the signed compare and the
 * signed conversion are the unsigned ones. */
__attribute__((target("avx2"))) int simd_zig_first_avx2(int m, const uint32_t *w, double *z, uint16_t *ok, const ZigTables *t)
{
    const __m256i low7 = _mm256_set1_epi32(0x7f), bit7 = _mm256_set1_epi32(0x80);
    const __m256d sign = _mm256_set1_pd(-0.0);
    int q = 0;
    for (; q + 16 <= m; q += 16) {
        unsigned accepted = 0;
        for (int h = 0; h < 2; h++) {
            const __m256i k = _mm256_loadu_si256((const __m256i *)(w + q + 8 * h));
            const __m256i i = _mm256_and_si256(k, low7), j = _mm256_srli_epi32(k, 8);
            const __m256i below = _mm256_cmpgt_epi32(_mm256_i32gather_epi32((const int *)t->k, i, 4), j);
            accepted |= (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(below)) << (8 * h);
            const __m256i neg = _mm256_cmpeq_epi32(_mm256_and_si256(k, bit7), _mm256_setzero_si256());
            for (int g = 0; g < 2; g++) {
                const __m128i i4 = g ? _mm256_extracti128_si256(i, 1) : _mm256_castsi256_si128(i);
                const __m128i j4 = g ? _mm256_extracti128_si256(j, 1) : _mm256_castsi256_si128(j);
                const __m128i n4 = g ? _mm256_extracti128_si256(neg, 1) : _mm256_castsi256_si128(neg);
                const __m256d x = _mm256_mul_pd(_mm256_cvtepi32_pd(j4), _mm256_i32gather_pd(t->w, i4, 8));
                const __m256d flip = _mm256_and_pd(_mm256_castsi256_pd(_mm256_cvtepi32_epi64(n4)), sign);
                _mm256_storeu_pd(z + q + 8 * h + 4 * g, _mm256_xor_pd(x, flip));
            }
        }
        ok[q / 16] = (uint16_t)accepted;
    }
    return q;
}

/* exp(t) for t <= 0 (the wedge's -x^2 / 2 >= -6): t = n ln 2 + r, |r| <=
 * ln 2 / 2, Taylor to r^11 (remainder below 1e-14), times 2^n. Within 1e-14
 * of exp(t): its use is only where the margin of 1e-12 settles a test. */
__attribute__((target("avx512f"))) static inline __m512d exp_nonpositive_avx512(__m512d t)
{
    const __m512d n = _mm512_roundscale_pd(_mm512_mul_pd(t, _mm512_set1_pd(1.4426950408889634)), _MM_FROUND_TO_NEAREST_INT);
    const __m512d r = _mm512_sub_pd(_mm512_sub_pd(t, _mm512_mul_pd(n, _mm512_set1_pd(6.93147180369123816490e-01))),
                                    _mm512_mul_pd(n, _mm512_set1_pd(1.90821492927058770002e-10)));
    static const double inv_fact[12] = {1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040,
                                        1.0 / 40320, 1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800};
    __m512d p = _mm512_set1_pd(inv_fact[11]);
    for (int k = 10; k >= 0; k--) p = _mm512_add_pd(_mm512_mul_pd(p, r), _mm512_set1_pd(inv_fact[k]));
    return _mm512_scalef_pd(p, n);
}

/* GSL's wedge test (wedge_init) for the nbad pairs not accepted at once, eight
 * at a time: kw[k] the word not accepted, uw[k] the next (U1); both padded
 * with zeros to a multiple of 8, out has as much room. Kept where y's upper
 * bound is below exp(-x^2 / 2) by more than the margin, not kept where y's
 * lower bound is above it by more; open otherwise, and in the tail strip
 * (127, GSL's other test). */
__attribute__((target("avx512f"))) void simd_zig_wedge_avx512(int nbad, const uint32_t *kw, const uint32_t *uw, uint8_t *out,
                                                            const ZigTables *t)
{
    const __m512d margin = _mm512_set1_pd(1e-12), u32 = _mm512_set1_pd(1.0 / 4294967296.0);
    for (int k = 0; k < nbad; k += 8) {
        const __m256i kk = _mm256_loadu_si256((const __m256i *)(kw + k)), uu = _mm256_loadu_si256((const __m256i *)(uw + k));
        const __m256i i = _mm256_and_si256(kk, _mm256_set1_epi32(0x7f)), j = _mm256_srli_epi32(kk, 8);
        const __m512d x = _mm512_mul_pd(_mm512_cvtepu32_pd(j), _mm512_i32gather_pd(i, t->w, 8));
        const __m512d U1 = _mm512_mul_pd(_mm512_cvtepu32_pd(uu), u32);   /* GSL's gsl_rng_uniform */
        /* y = y(1/4) + slope (U1 - 1/4), its bounds by the sign of U1 - 1/4 */
        const __m512d dU = _mm512_sub_pd(U1, _mm512_set1_pd(0.25));
        const __mmask8 up = _mm512_cmp_pd_mask(dU, _mm512_setzero_pd(), _CMP_GE_OQ);
        const __m512d blo = _mm512_i32gather_pd(i, t->wedge_b[0], 8), bhi = _mm512_i32gather_pd(i, t->wedge_b[1], 8);
        const __m512d ylo = _mm512_add_pd(_mm512_i32gather_pd(i, t->wedge_a[0], 8), _mm512_mul_pd(_mm512_mask_blend_pd(up, bhi, blo), dU));
        const __m512d yhi = _mm512_add_pd(_mm512_i32gather_pd(i, t->wedge_a[1], 8), _mm512_mul_pd(_mm512_mask_blend_pd(up, blo, bhi), dU));
        const __m512d e = exp_nonpositive_avx512(_mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(-0.5), x), x));
        const __mmask8 tail = (__mmask8)_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(i, _mm256_set1_epi32(127))));
        const __mmask8 kept = _mm512_cmp_pd_mask(yhi, _mm512_sub_pd(e, margin), _CMP_LT_OQ) & (__mmask8)~tail;
        const __mmask8 not_kept = _mm512_cmp_pd_mask(ylo, _mm512_add_pd(e, margin), _CMP_GT_OQ) & (__mmask8)~tail;
        /* WEDGE_OPEN, less 2 where kept, less 1 where not kept */
        const __m128i st = _mm512_cvtepi64_epi8(_mm512_sub_epi64(_mm512_sub_epi64(_mm512_set1_epi64(WEDGE_OPEN),
                               _mm512_maskz_set1_epi64(kept, 2)), _mm512_maskz_set1_epi64(not_kept, 1)));
        _mm_storel_epi64((__m128i *)(out + k), st);
    }
}

/* The pairs of groups of 16 (ok[v][g]: simd_zig_first_avx512's bits) not accepted at
 * once, without a branch per pair: each group's indices and first variates
 * not accepted (v0), packed to the front of a register and stored at the end
 * of the list (16 entries, the list has room). Returns their number. */
__attribute__((target("avx512f"))) int simd_zig_bad_pairs_avx512(int groups, const uint16_t (*ok)[RNG_BATCH / 16],
                                                               int nvar, int *bad, int *v0)
{
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    int nbad = 0;
    for (int g = 0; g < groups; g++) {
        __mmask16 all = ok[0][g];
        for (int v = 1; v < nvar; v++) all &= ok[v][g];
        __m512i first = _mm512_setzero_si512();   /* the first variate not accepted: from the last down */
        for (int v = nvar - 1; v >= 0; v--) first = _mm512_mask_mov_epi32(first, (__mmask16)~ok[v][g], _mm512_set1_epi32(v));
        const __mmask16 b = (__mmask16)~all;
        _mm512_storeu_si512(bad + nbad, _mm512_maskz_compress_epi32(b, _mm512_add_epi32(lane, _mm512_set1_epi32(16 * g))));
        _mm512_storeu_si512(v0 + nbad, _mm512_maskz_compress_epi32(b, first));
        nbad += __builtin_popcount(b);
    }
    return nbad;
}
#endif
