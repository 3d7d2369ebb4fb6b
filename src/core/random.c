/* random.c - Philox counter blocks as a GSL generator, for GSL's ziggurat. */
#include <string.h>
#include <gsl/gsl_rng.h>
#include <gsl/gsl_randist.h>
#include "random.h"

static unsigned long counter_get(void *vs)
{
    CounterRng *c = vs;
    if (c->used == 4) {
        c->ctr.v[1] += 1u << 24;   /* next block of the same pair and step */
        c->out = philox4x32(c->ctr, c->key);
        c->used = 0;
    }
    return c->out.v[c->used++];
}

static double counter_get_double(void *vs)
{
    return counter_get(vs) * (1.0 / 4294967296.0);   /* [0, 1) as GSL requires */
}

static void counter_set(void *vs, unsigned long seed)
{
    (void)vs; (void)seed;   /* state is set by rng_counter_start */
}

static const gsl_rng_type counter_type = {
    "philox4x32-10-counter", 0xffffffffUL, 0, sizeof(CounterRng),
    &counter_set, &counter_get, &counter_get_double
};

double rng_counter_normal(CounterRng *c)
{
    gsl_rng r = {&counter_type, c};
    return gsl_ran_gaussian_ziggurat(&r, 1.0);
}

/* ---- batches ------------------------------------------------------------ */
#include <threads.h>
#include "simd.h"

/* Philox4x32-10 (Salmon et al. 2011), Random123's philox4x32 round for round:
 * out = (hi(M1 c2) ^ c1 ^ k0, lo(M1 c2), hi(M0 c0) ^ c3 ^ k1, lo(M0 c0)), the
 * key bumped by the Weyl constants between rounds. One lane per pair; the key
 * and the step words are the same for every lane. The portable loop below is
 * the reference; on x86-64 an AVX-512 or AVX2 version of the same rounds is
 * chosen at run time (one binary for any x86-64), its 32 x 32 -> 64 bit
 * products from the even and odd lanes (vpmuludq), which GCC's vectoriser
 * does not find. tests/test_random.c checks every lane against philox4x32. */
static void philox_portable(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
                            const uint32_t *restrict c2, const uint32_t *restrict c3,
                            uint32_t (*restrict w)[RNG_BATCH], int q0)
{
    for (int q = q0; q < m; q++) {
        uint32_t x0 = c0, x1 = c1, x2 = c2[q], x3 = c3[q], a = k0, b = k1;
        for (int r = 0; r < 10; r++) {
            const uint64_t p0 = (uint64_t)PHILOX_M4x32_0 * x0, p1 = (uint64_t)PHILOX_M4x32_1 * x2;
            x0 = (uint32_t)(p1 >> 32) ^ x1 ^ a;
            x1 = (uint32_t)p1;
            x2 = (uint32_t)(p0 >> 32) ^ x3 ^ b;
            x3 = (uint32_t)p0;
            a += PHILOX_W32_0; b += PHILOX_W32_1;
        }
        w[0][q] = x0; w[1][q] = x1; w[2][q] = x2; w[3][q] = x3;
    }
}

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
 * the rest is left to the portable loop. */
__attribute__((target("avx2"))) static int philox_avx2(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
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
__attribute__((target("avx512f"))) static int philox_avx512(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
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

static void philox_lanes(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
                         const uint32_t *c2, const uint32_t *c3, uint32_t (*w)[RNG_BATCH])
{
    int q0 = 0;
#ifdef DPD_HAVE_X86_SIMD
    const int isa = simd_level();
    if (isa == SIMD_AVX512) q0 = philox_avx512(m, k0, k1, c0, c1, c2, c3, w);
    else if (isa == SIMD_AVX2) q0 = philox_avx2(m, k0, k1, c0, c1, c2, c3, w);
#endif
    philox_portable(m, k0, k1, c0, c1, c2, c3, w, q0);
}

static once_flag batch_once = ONCE_FLAG_INIT;
static void batch_init(void);

/* ordered: id_a[q] <= id_b[q] already (the pair driver's candidate pass) */
static void pair_blocks(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                        const int ordered, uint32_t w[4][RNG_BATCH])
{
    call_once(&batch_once, batch_init);
    if (ordered) {
        philox_lanes(m, seed, STREAM_PAIR_NOISE, (uint32_t)step, (uint32_t)(step >> 32), id_a, id_b, w);
        return;
    }
    uint32_t lo[RNG_BATCH], hi[RNG_BATCH];
    for (int q = 0; q < m; q++) {
        lo[q] = id_a[q] < id_b[q] ? id_a[q] : id_b[q];
        hi[q] = id_a[q] < id_b[q] ? id_b[q] : id_a[q];
    }
    philox_lanes(m, seed, STREAM_PAIR_NOISE, (uint32_t)step, (uint32_t)(step >> 32), lo, hi, w);
}

void rng_pair_blocks(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                     uint32_t w[4][RNG_BATCH])
{
    pair_blocks(seed, step, m, id_a, id_b, 0, w);
}

/* GSL's strip tables, read out of GSL itself (no copy of its constants): per
 * strip i, the word (j << 8 | 0x80 | i) is accepted at once iff j < zig_k[i],
 * and then gives j * zig_w[i]. Probed with a generator that counts its calls:
 * one call = accepted at once; later words (0x81: strip 1, j = 0) end any
 * further attempt. */
static uint32_t zig_k[128];
static double zig_w[128];
typedef struct { uint32_t first, second; int calls; } ZigProbe;
static unsigned long probe_get(void *vs)
{
    ZigProbe *p = vs;
    const int c = p->calls++;
    return c == 0 ? p->first : c == 1 ? p->second : 0x81u;
}
static double probe_get_double(void *vs) { return probe_get(vs) * (1.0 / 4294967296.0); }
static void probe_set(void *vs, unsigned long seed) { (void)vs; (void)seed; }
static const gsl_rng_type probe_type = {"ziggurat-probe", 0xffffffffUL, 0, sizeof(ZigProbe),
                                        &probe_set, &probe_get, &probe_get_double};
/* GSL's variate from the words first, second, then 0x81...: the words it took */
static int probe_words(uint32_t first, uint32_t second, double *x)
{
    ZigProbe p = {first, second, 0};
    gsl_rng r = {&probe_type, &p};
    *x = gsl_ran_gaussian_ziggurat(&r, 1.0);
    return p.calls;
}
static int probe(uint32_t i, uint32_t j, double *x)
{
    return probe_words((j << 8) | 0x80u | i, 0x81u, x) == 1;
}

/* GSL's wedge test, for a word k = (j << 8 | 0x80 | i) of strip i < 127 not
 * accepted at once: with U1 from the next word, y = y1 + (y0 - y1) U1
 * (y0, y1 = ytab[i], ytab[i + 1], table heights GSL does not export), kept
 * iff y < exp(-x^2 / 2), x = j wtab[i]. y is linear in U1, so it is
 * bracketed at two points, U1 = 1/4 and 3/4, by probing: GSL keeps the word
 * for j < J and not from J on, so exp(-x_J^2 / 2) <= y < exp(-x_{J-1}^2 / 2)
 * (x_j = j wtab[i]: GSL's own x and exp). Per strip: y(1/4) in
 * [wedge_a[0], wedge_a[1]], the slope in [wedge_b[0], wedge_b[1]]. The
 * brackets are about 1e-7 wide; a bound not found stays 0 or 1 (y is in
 * (0, 1]), and the test is then left to GSL. */
static double wedge_a[2][128], wedge_b[2][128];
static int wedge_kept(uint32_t i, uint32_t j, uint32_t u)
{
    double x;
    return probe_words((j << 8) | 0x80u | i, u, &x) == 2;   /* k and U1: kept by the wedge; more: a new attempt */
}
static void wedge_bracket(uint32_t i, uint32_t u, double *lo_y, double *hi_y)
{
    const uint32_t j0 = zig_k[i];
    uint32_t lo = j0, hi = 1u << 24;   /* J: the first j not kept, in [j0, 2^24] */
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (wedge_kept(i, mid, u)) lo = mid + 1; else hi = mid;
    }
    const double xJ = lo * zig_w[i], xJ1 = (lo - 1) * zig_w[i];
    *lo_y = lo < (1u << 24) ? exp(-0.5 * xJ * xJ) : 0.0;
    *hi_y = lo > j0 ? exp(-0.5 * xJ1 * xJ1) : 1.0;
}
static void wedge_init(void)
{
    for (uint32_t i = 0; i < 128; i++) {
        double alo = 0.0, ahi = 1.0, blo = 0.0, bhi = 1.0;   /* strip 127 (the tail): open */
        if (i < 127) {
            wedge_bracket(i, 1u << 30, &alo, &ahi);   /* U1 = 1/4 */
            wedge_bracket(i, 3u << 30, &blo, &bhi);   /* U1 = 3/4 */
        }
        wedge_a[0][i] = alo; wedge_a[1][i] = ahi;
        wedge_b[0][i] = (blo - ahi) / 0.5; wedge_b[1][i] = (bhi - alo) / 0.5;   /* slope dy / dU1 */
    }
}

int rng_ziggurat_wedge_brackets(double width)
{
    call_once(&batch_once, batch_init);
    int n = 0;
    for (int i = 0; i < 128; i++) n += wedge_a[1][i] - wedge_a[0][i] < width && wedge_b[1][i] - wedge_b[0][i] < 4 * width;
    return n;
}
static void zig_init(void)
{
    for (uint32_t i = 0; i < 128; i++) {
        uint32_t lo = 0, hi = 1u << 24;   /* accepted at once iff j < k: find k in [0, 2^24] */
        while (lo < hi) {
            const uint32_t mid = lo + (hi - lo) / 2;
            double x;
            if (probe(i, mid, &x)) lo = mid + 1; else hi = mid;
        }
        zig_k[i] = lo;
        /* j = 1: x = wtab[i], accepted at once or, in a strip that never is
         * (strip 0, the top one: zig_k = 0), kept by the wedge test with
         * U1 = 0 (y = ytab[1] < exp(-wtab[0]^2 / 2)) */
        double x;
        zig_w[i] = probe_words((1u << 8) | 0x80u | i, 0u, &x) <= 2 ? x : NAN;   /* NAN: the wedge test then stays open (GSL's) */
    }
}

static inline int zig_accept(uint32_t k, double *z)
{
    const uint32_t i = k & 0x7f, j = k >> 8;
    const double x = j * zig_w[i];
    /* GSL: sign * sigma * x, sigma = 1; x >= 0, so -x is x with its sign bit
     * set, here without a branch (the sign is a fair coin: a branch on it is
     * guessed wrong half the time) */
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    b ^= (uint64_t)(~k & 0x80u) << 56;
    memcpy(z, &b, sizeof b);
    return j < zig_k[i];
}

/* once per process: the strip tables */
static void batch_init(void)
{
    zig_init();
    wedge_init();
}

int rng_ziggurat_fast(uint32_t k, double *z)
{
    call_once(&batch_once, batch_init);
    return zig_accept(k, z);
}

#ifdef DPD_HAVE_X86_SIMD
/* zig_k[i] for 16 strips i < 128 from registers (two-table permutes of 32
 * entries, then bits 5 and 6 of i choose): cheaper than a gather */
__attribute__((target("avx512f"))) static inline __m512i zig_k_lookup_avx512(__m512i i)
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
 * j * zig_w[i] and the same sign flip as zig_accept, so the same bits; ok[g]
 * has bit l set if word 16 g + l was accepted at once. The last group is
 * masked (its bits past m set, as accepted): returns m, every word done. */
__attribute__((target("avx512f"))) static int zig_avx512(int m, const uint32_t *w, double *z, uint16_t *ok)
{
    const __m512i low7 = _mm512_set1_epi32(0x7f), bit7 = _mm512_set1_epi32(0x80);
    const __m512i sign = _mm512_set1_epi64((long long)0x8000000000000000ULL);
    for (int q = 0; q < m; q += 16) {
        const __mmask16 live = m - q >= 16 ? 0xffff : (__mmask16)((1u << (m - q)) - 1);
        const __m512i k = _mm512_maskz_loadu_epi32(live, w + q);   /* 0 past m: strip 0, j = 0 */
        const __m512i i = _mm512_and_si512(k, low7), j = _mm512_srli_epi32(k, 8);
        ok[q / 16] = _mm512_cmplt_epu32_mask(j, zig_k_lookup_avx512(i)) | (__mmask16)~live;
        const __mmask16 neg = _mm512_testn_epi32_mask(k, bit7);
        for (int h = 0; h < 2; h++) {
            const __m256i ih = h ? _mm512_extracti64x4_epi64(i, 1) : _mm512_castsi512_si256(i);
            const __m256i jh = h ? _mm512_extracti64x4_epi64(j, 1) : _mm512_castsi512_si256(j);
            const __m512d x = _mm512_mul_pd(_mm512_cvtepu32_pd(jh), _mm512_i32gather_pd(ih, zig_w, 8));
            const __m512i xi = _mm512_castpd_si512(x);
            _mm512_mask_storeu_pd(z + q + 8 * h, (__mmask8)(live >> (8 * h)),
                                  _mm512_castsi512_pd(_mm512_mask_xor_epi64(xi, (__mmask8)(neg >> (8 * h)), xi, sign)));
        }
    }
    return m;
}

/* The same on AVX2, 8 words per half of a group of 16 (so ok[] is laid out as
 * zig_avx512's): j and zig_k are below 2^24, so the signed compare and the
 * signed conversion are the unsigned ones. */
__attribute__((target("avx2"))) static int zig_avx2(int m, const uint32_t *w, double *z, uint16_t *ok)
{
    const __m256i low7 = _mm256_set1_epi32(0x7f), bit7 = _mm256_set1_epi32(0x80);
    const __m256d sign = _mm256_set1_pd(-0.0);
    int q = 0;
    for (; q + 16 <= m; q += 16) {
        unsigned accepted = 0;
        for (int h = 0; h < 2; h++) {
            const __m256i k = _mm256_loadu_si256((const __m256i *)(w + q + 8 * h));
            const __m256i i = _mm256_and_si256(k, low7), j = _mm256_srli_epi32(k, 8);
            const __m256i below = _mm256_cmpgt_epi32(_mm256_i32gather_epi32((const int *)zig_k, i, 4), j);
            accepted |= (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(below)) << (8 * h);
            const __m256i neg = _mm256_cmpeq_epi32(_mm256_and_si256(k, bit7), _mm256_setzero_si256());
            for (int g = 0; g < 2; g++) {
                const __m128i i4 = g ? _mm256_extracti128_si256(i, 1) : _mm256_castsi256_si128(i);
                const __m128i j4 = g ? _mm256_extracti128_si256(j, 1) : _mm256_castsi256_si128(j);
                const __m128i n4 = g ? _mm256_extracti128_si256(neg, 1) : _mm256_castsi256_si128(neg);
                const __m256d x = _mm256_mul_pd(_mm256_cvtepi32_pd(j4), _mm256_i32gather_pd(zig_w, i4, 8));
                const __m256d flip = _mm256_and_pd(_mm256_castsi256_pd(_mm256_cvtepi32_epi64(n4)), sign);
                _mm256_storeu_pd(z + q + 8 * h + 4 * g, _mm256_xor_pd(x, flip));
            }
        }
        ok[q / 16] = (uint16_t)accepted;
    }
    return q;
}
#endif

/* The wedge's outcome for a pair not accepted at once (pair_resume_one) */
enum { WEDGE_KEPT = 0, WEDGE_NOT_KEPT = 1, WEDGE_OPEN = 2 };

#ifdef DPD_HAVE_X86_SIMD
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
__attribute__((target("avx512f"))) static void wedge_avx512(int nbad, const uint32_t *kw, const uint32_t *uw,
                                                            uint8_t *out)
{
    const __m512d margin = _mm512_set1_pd(1e-12), u32 = _mm512_set1_pd(1.0 / 4294967296.0);
    for (int k = 0; k < nbad; k += 8) {
        const __m256i kk = _mm256_loadu_si256((const __m256i *)(kw + k)), uu = _mm256_loadu_si256((const __m256i *)(uw + k));
        const __m256i i = _mm256_and_si256(kk, _mm256_set1_epi32(0x7f)), j = _mm256_srli_epi32(kk, 8);
        const __m512d x = _mm512_mul_pd(_mm512_cvtepu32_pd(j), _mm512_i32gather_pd(i, zig_w, 8));
        const __m512d U1 = _mm512_mul_pd(_mm512_cvtepu32_pd(uu), u32);   /* GSL's gsl_rng_uniform */
        /* y = y(1/4) + slope (U1 - 1/4), its bounds by the sign of U1 - 1/4 */
        const __m512d dU = _mm512_sub_pd(U1, _mm512_set1_pd(0.25));
        const __mmask8 up = _mm512_cmp_pd_mask(dU, _mm512_setzero_pd(), _CMP_GE_OQ);
        const __m512d blo = _mm512_i32gather_pd(i, wedge_b[0], 8), bhi = _mm512_i32gather_pd(i, wedge_b[1], 8);
        const __m512d ylo = _mm512_add_pd(_mm512_i32gather_pd(i, wedge_a[0], 8), _mm512_mul_pd(_mm512_mask_blend_pd(up, bhi, blo), dU));
        const __m512d yhi = _mm512_add_pd(_mm512_i32gather_pd(i, wedge_a[1], 8), _mm512_mul_pd(_mm512_mask_blend_pd(up, blo, bhi), dU));
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
#endif

int rng_ziggurat_wedge(uint32_t k, uint32_t u)
{
    call_once(&batch_once, batch_init);
#ifdef DPD_HAVE_X86_SIMD
    if (simd_level() == SIMD_AVX512) {
        uint32_t kw[8] = {k}, uw[8] = {u};
        uint8_t out[8];
        wedge_avx512(1, kw, uw, out);
        return out[0];
    }
#endif
    (void)k; (void)u;
    return -1;
}

/* A pair's sequence from a given word on, as a GSL generator: its first
 * eight words (blocks 0 and 1) in an array, so that a resumed pair's words
 * are read without a test per word; a word past them (1.4e-4 of the pairs of
 * four variates, 1.7e-4 of those of one, which have four words) from its
 * Philox block, computed then. */
typedef struct {
    uint32_t w[8];
    int pos, lim;                 /* next word; words in w (4: block 1 not drawn) */
    philox4x32_ctr_t ctr;         /* block 0's counter (rng_pair_start's) */
    philox4x32_key_t key;
} PairWords;

static unsigned long words_get(void *vs)
{
    PairWords *c = vs;
    const int p = c->pos++;
    if (__builtin_expect(p < c->lim, 1)) return c->w[p];
    philox4x32_ctr_t ctr = c->ctr;
    ctr.v[1] += (uint32_t)(p >> 2) << 24;   /* block p / 4, as counter_get counts them */
    return philox4x32(ctr, c->key).v[p & 3];
}
static double words_get_double(void *vs) { return words_get(vs) * (1.0 / 4294967296.0); }
static const gsl_rng_type words_type = {
    "philox4x32-10-pair-words", 0xffffffffUL, 0, sizeof(PairWords),
    &counter_set, &words_get, &words_get_double
};

/* One normal from the pair's words at c->pos on, as gsl_ran_gaussian_ziggurat draws it */
static double words_normal(PairWords *c)
{
    gsl_rng r = {&words_type, c};
    return gsl_ran_gaussian_ziggurat(&r, 1.0);
}

/* One pair whose variate v0 the ziggurat did not accept at once: variates
 * 0 ... v0 - 1 (in z already) took its first v0 words. Where the batch's
 * wedge test settled variate v0 (wedge_avx512), it is z's value (kept: the
 * first step's x, as GSL returns it) or GSL's next attempt (not kept: the
 * word after U1, nearly always accepted at once); where it did not, GSL draws
 * it from word v0 on (not testing that word first: a test known to fail is a
 * branch the predictor gets wrong). The later variates resume where variate
 * v0 stopped; they too are nearly always accepted at once (97.2 % each): all
 * their first steps are taken before one test decides (one predictable
 * branch, where a loop of its own per variate was one wrong guess per pair:
 * the number of variates left is v0's, random). Anything else (one pair in
 * about 30) goes to GSL variate by variate. */
static void pair_resume_one(PairWords *c, int v0, int nvar, double *z, int q, int wedge)
{
    double t[4];   /* t[u]: variate v0 + u */
    unsigned all;
    int pos;
    if (__builtin_expect(wedge == WEDGE_OPEN, 0)) {
        c->pos = v0;
        t[0] = words_normal(c);
        pos = c->pos;
        all = 1;
    } else {   /* no branch on which: kept and not kept are even odds */
        const unsigned again = wedge == WEDGE_NOT_KEPT;
        double x;
        const unsigned ok = (unsigned)zig_accept(c->w[v0 + 2 < 8 ? v0 + 2 : 7], &x) & (unsigned)(v0 + 2 < c->lim);
        const double kept = z[v0 * RNG_BATCH + q];
        t[0] = again ? x : kept;
        all = (unsigned)!again | ok;
        pos = v0 + 2 + (int)again;
    }
    for (int u = 1; u < 4; u++) {   /* the next three words' first steps (a word past the eight: GSL below) */
        const int p = pos + u - 1, needed = v0 + u < nvar;
        all &= (unsigned)(zig_accept(c->w[p < 8 ? p : 7], &t[u]) & (p < c->lim)) | (unsigned)!needed;
    }
    if (__builtin_expect(all, 1)) {   /* stores at indices, not branches on v0 (the fastest of three forms) */
        double zz[7];
        for (int v = 0; v < nvar; v++) zz[v] = z[v * RNG_BATCH + q];
        for (int u = 0; u < 4; u++) zz[v0 + u] = t[u];
        for (int v = 0; v < nvar; v++) z[v * RNG_BATCH + q] = zz[v];
        return;
    }
    c->pos = v0;   /* rare: from variate v0 on, variate by variate */
    for (int v = v0; v < nvar; v++) {
        double x;
        if (v > v0 && c->pos < c->lim && zig_accept(c->w[c->pos], &x)) { c->pos++; z[v * RNG_BATCH + q] = x; }
        else z[v * RNG_BATCH + q] = words_normal(c);
    }
}

/* The pairs of a batch whose variate v0[k] the ziggurat did not accept at
 * once (bad[k]: their index in the batch). The first block is the batch's and
 * the second, which most pairs of several variates reach (GSL's path takes a
 * second word), is drawn for all of them at once. */
static void pair_normals_resume(uint32_t seed, uint64_t step, const uint32_t *id_a, const uint32_t *id_b,
                                const uint32_t (*w)[RNG_BATCH], int nbad, const int *bad, const int *v0,
                                int nvar, double *z)
{
    uint32_t lo[RNG_BATCH], hi[RNG_BATCH], w1[4][RNG_BATCH];
    for (int k = 0; k < nbad; k++) {
        const uint32_t a = id_a[bad[k]], b = id_b[bad[k]];
        lo[k] = a < b ? a : b; hi[k] = a < b ? b : a;
    }
    /* one variate rarely reaches the second block (its first has four words) */
    const int next = nvar > 1;
    if (next) philox_lanes(nbad, seed, STREAM_PAIR_NOISE, (uint32_t)step, (uint32_t)(step >> 32) + (1u << 24), lo, hi, w1);
    /* the wedge test of each pair's variate v0, all pairs at once: its word and U1's */
    uint8_t wedge[RNG_BATCH + 8];
    memset(wedge, WEDGE_OPEN, (size_t)nbad);
#ifdef DPD_HAVE_X86_SIMD
    if (simd_level() == SIMD_AVX512) {
        uint32_t kw[RNG_BATCH + 8], uw[RNG_BATCH + 8];
        for (int k = 0; k < nbad; k++) {
            const int q = bad[k], v = v0[k];
            kw[k] = w[v][q];
            uw[k] = v + 1 < 4 ? w[v + 1 < 4 ? v + 1 : 3][q] : w1[0][k];   /* nvar 1: v = 0 */
        }
        for (int k = nbad; k < ((nbad + 7) & ~7); k++) kw[k] = uw[k] = 0;
        wedge_avx512(nbad, kw, uw, wedge);
    }
#endif
    PairWords c;   /* rng_pair_start's counter and key */
    c.ctr.v[0] = (uint32_t)step; c.ctr.v[1] = (uint32_t)(step >> 32);
    c.key.v[0] = seed; c.key.v[1] = STREAM_PAIR_NOISE;
    c.lim = next ? 8 : 4;
    for (int k = 0; k < nbad; k++) {
        const int q = bad[k];
        c.ctr.v[2] = lo[k]; c.ctr.v[3] = hi[k];
        for (int u = 0; u < 4; u++) { c.w[u] = w[u][q]; c.w[4 + u] = next ? w1[u][k] : 0; }
        pair_resume_one(&c, v0[k], nvar, z, q, wedge[k]);
    }
}

#ifdef DPD_HAVE_X86_SIMD
/* The pairs of groups of 16 (ok[v][g]: zig_avx512's bits) not accepted at
 * once, without a branch per pair: each group's indices and first variates
 * not accepted (v0), packed to the front of a register and stored at the end
 * of the list (16 entries, the list has room). Returns their number. */
__attribute__((target("avx512f"))) static int bad_pairs_avx512(int groups, const uint16_t (*ok)[RNG_BATCH / 16],
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

static void pair_normals(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                         const int ordered, int nvar, double *z)
{
    uint32_t w[4][RNG_BATCH];
    pair_blocks(seed, step, m, id_a, id_b, ordered, w);
    int q0 = 0, nbad = 0, bad[RNG_BATCH + 16], v0[RNG_BATCH + 16];   /* + 16: bad_pairs_avx512's stores */
#ifdef DPD_HAVE_X86_SIMD
    const int isa = simd_level();
    if (isa != SIMD_PORTABLE) {   /* 16 pairs at a time, variate by variate, then the pairs not accepted at once */
        uint16_t ok[4][RNG_BATCH / 16];
        for (int v = 0; v < nvar; v++)
            q0 = isa == SIMD_AVX512 ? zig_avx512(m, w[v], z + v * RNG_BATCH, ok[v]) : zig_avx2(m, w[v], z + v * RNG_BATCH, ok[v]);
        if (isa == SIMD_AVX512) nbad = bad_pairs_avx512((q0 + 15) / 16, (const uint16_t (*)[RNG_BATCH / 16])ok, nvar, bad, v0);
        else
            for (int g = 0; g < (q0 + 15) / 16; g++) {
                unsigned all = ok[0][g];
                for (int v = 1; v < nvar; v++) all &= ok[v][g];
                for (unsigned b = (uint16_t)~all; b; b &= b - 1) {
                    const int l = __builtin_ctz(b);
                    unsigned not_ok = 0;   /* bit v: variate v not accepted (no branch on which) */
                    for (int v = 0; v < nvar; v++) not_ok |= (~(unsigned)ok[v][g] >> l & 1u) << v;
                    bad[nbad] = 16 * g + l; v0[nbad++] = __builtin_ctz(not_ok);   /* the first variate not accepted */
                }
            }
    }
#endif
    for (int q = q0; q < m; q++) {
        int v = 0;
        while (v < nvar && zig_accept(w[v][q], &z[v * RNG_BATCH + q])) v++;
        if (v < nvar) { bad[nbad] = q; v0[nbad++] = v; }
    }
    if (nbad > 0) pair_normals_resume(seed, step, id_a, id_b, (const uint32_t (*)[RNG_BATCH])w, nbad, bad, v0, nvar, z);
}

void rng_pair_normals(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                      int nvar, double *z)
{
    pair_normals(seed, step, m, id_a, id_b, 0, nvar, z);
}

void rng_pair_normals_ordered(uint32_t seed, uint64_t step, int m, const uint32_t *lo, const uint32_t *hi,
                              int nvar, double *z)
{
    pair_normals(seed, step, m, lo, hi, 1, nvar, z);
}
