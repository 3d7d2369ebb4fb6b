/* philox_x86.c - the backend's Philox4x32-10 lanes (simd.h SimdKernels.philox):
 * random.c philox_portable's rounds, Random123's philox4x32 round for round,
 * on 8 (AVX2) or 16 (AVX-512) pairs at once, the 32 x 32 -> 64 bit products
 * from the even and odd lanes (vpmuludq), which GCC's vectoriser does not
 * find. The same integer operations, so the same words; tests/test_random.c
 * checks every lane against philox4x32 at every level. */
#include "simd_x86.h"

#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>
/* The lanes' primitives per instruction set: hi and lo words of x * M
 * lane by lane, even lanes' products directly, odd lanes' after shifting
 * them down; broadcast, xor, unaligned load and store. */
#define AVX2 __attribute__((target("avx2"))) static inline
AVX2 void mulhilo_avx2(__m256i x, __m256i M, __m256i *hi, __m256i *lo)
{
    const __m256i e = _mm256_mul_epu32(x, M), o = _mm256_mul_epu32(_mm256_srli_epi64(x, 32), M);
    *lo = _mm256_blend_epi32(e, _mm256_slli_epi64(o, 32), 0xAA);
    *hi = _mm256_blend_epi32(_mm256_srli_epi64(e, 32), o, 0xAA);
}
AVX2 __m256i set1_avx2(uint32_t v) { return _mm256_set1_epi32((int)v); }
AVX2 __m256i xor_avx2(__m256i a, __m256i b) { return _mm256_xor_si256(a, b); }
AVX2 __m256i load_avx2(const uint32_t *p) { return _mm256_loadu_si256((const __m256i *)p); }
AVX2 void store_avx2(uint32_t *p, __m256i v) { _mm256_storeu_si256((__m256i *)p, v); }
#undef AVX2
#define AVX512 __attribute__((target("avx512f"))) static inline
AVX512 void mulhilo_avx512(__m512i x, __m512i M, __m512i *hi, __m512i *lo)
{
    const __m512i e = _mm512_mul_epu32(x, M), o = _mm512_mul_epu32(_mm512_srli_epi64(x, 32), M);
    *lo = _mm512_mask_blend_epi32(0xAAAA, e, _mm512_slli_epi64(o, 32));
    *hi = _mm512_mask_blend_epi32(0xAAAA, _mm512_srli_epi64(e, 32), o);
}
AVX512 __m512i set1_avx512(uint32_t v) { return _mm512_set1_epi32((int)v); }
AVX512 __m512i xor_avx512(__m512i a, __m512i b) { return _mm512_xor_si512(a, b); }
#undef AVX512

/* philox_portable's ten rounds on LANES pairs at once, with the primitives of SUFFIX */
#define PHILOX_ROUNDS(SUFFIX, TARGET, VEC)                                                               \
__attribute__((target(TARGET))) static inline void rounds_##SUFFIX(VEC *x, uint32_t k0, uint32_t k1)       \
{                                                                                                         \
    const VEC M0 = set1_##SUFFIX(PHILOX_M4x32_0), M1 = set1_##SUFFIX(PHILOX_M4x32_1);                     \
    uint32_t a = k0, b = k1;                                                                              \
    for (int r = 0; r < 10; r++) {                                                                        \
        VEC h0, l0, h1, l1;                                                                               \
        mulhilo_##SUFFIX(x[0], M0, &h0, &l0);                                                             \
        mulhilo_##SUFFIX(x[2], M1, &h1, &l1);                                                             \
        x[0] = xor_##SUFFIX(xor_##SUFFIX(h1, x[1]), set1_##SUFFIX(a));                                    \
        x[1] = l1;                                                                                        \
        x[2] = xor_##SUFFIX(xor_##SUFFIX(h0, x[3]), set1_##SUFFIX(b));                                    \
        x[3] = l0;                                                                                        \
        a += PHILOX_W32_0; b += PHILOX_W32_1;                                                             \
    }                                                                                                     \
}
PHILOX_ROUNDS(avx2, "avx2", __m256i)
PHILOX_ROUNDS(avx512, "avx512f", __m512i)
#undef PHILOX_ROUNDS

/* The rounds on 8 pairs at a time; returns the pairs done (a multiple of 8),
 * the rest is left to the portable loop (philox_portable). */
__attribute__((target("avx2"))) int simd_philox_avx2(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
        const uint32_t *c2, const uint32_t *c3, uint32_t (*w)[RNG_BATCH])
{
    int q = 0;
    for (; q + 8 <= m; q += 8) {
        __m256i x[4] = {set1_avx2(c0), set1_avx2(c1), load_avx2(c2 + q), load_avx2(c3 + q)};
        rounds_avx2(x, k0, k1);
        for (int u = 0; u < 4; u++) store_avx2(w[u] + q, x[u]);
    }
    return q;
}

/* The rounds on 16 pairs at a time, the last group masked: every pair done
 * (a short batch, such as the pairs the ziggurat resumes, is not left to the
 * portable loop, eight times slower per pair). */
__attribute__((target("avx512f"))) int simd_philox_avx512(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
        const uint32_t *c2, const uint32_t *c3, uint32_t (*w)[RNG_BATCH])
{
    for (int q = 0; q < m; q += 16) {
        const __mmask16 live = m - q >= 16 ? 0xffff : (__mmask16)((1u << (m - q)) - 1);
        __m512i x[4] = {set1_avx512(c0), set1_avx512(c1), _mm512_maskz_loadu_epi32(live, c2 + q),
                        _mm512_maskz_loadu_epi32(live, c3 + q)};
        rounds_avx512(x, k0, k1);
        for (int u = 0; u < 4; u++) _mm512_mask_storeu_epi32(w[u] + q, live, x[u]);
    }
    return m;
}
#endif
