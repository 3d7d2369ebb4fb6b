/* neighbor_avx512.c - the backend's neighbour-list distance test (simd.h
 * SimdKernels.nl_scan, nl_scan_block; AVX-512, 3D boxes): neighbor.c
 * scan_segment's subtractions and r^2 (no contraction), so the same test
 * results and the same entries in the same order; at most 16 slots past the
 * last kept entry written (neighbor.c SCAN_SLACK). tests/test_forces.c
 * levels_same_forces compares the lists of every level. */
#include "simd_x86.h"

#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>

/* scan_segment eight candidates at a time: their coordinates read as three
 * whole vectors (x is x, y, z per particle) and sorted into x, y and z lanes,
 * the same subtractions and r^2 (no contraction), so the same test results;
 * the kept j compressed and stored whole. */
/* The coordinates of candidates j .. j + cnt - 1 (cnt <= 8) in x, y and z
 * lanes: three whole vectors of x (x, y, z per particle) sorted by six
 * permutations, no gather */
static inline __attribute__((target("avx512f"), always_inline))
void load_group_avx512(const double *x, int j, int cnt, __m512d *X, __m512d *Y, __m512d *Z)
{
    /* lanes of x, y, z from A = x[3j .. 3j + 7], B = the next 8, C = the 8 after */
    const __m512i xab = _mm512_set_epi64(0, 0, 15, 12, 9, 6, 3, 0), xc = _mm512_set_epi64(13, 10, 5, 4, 3, 2, 1, 0);
    const __m512i yab = _mm512_set_epi64(0, 0, 0, 13, 10, 7, 4, 1), yc = _mm512_set_epi64(14, 11, 8, 4, 3, 2, 1, 0);
    const __m512i zab = _mm512_set_epi64(0, 0, 0, 14, 11, 8, 5, 2), zc = _mm512_set_epi64(15, 12, 9, 4, 3, 2, 1, 0);
    const int nv = 3 * cnt;
    const double *p = x + 3 * (size_t)j;
    const __m512d A = _mm512_maskz_loadu_pd((__mmask8)(nv >= 8 ? 0xff : (1u << nv) - 1), p);
    const __m512d B = _mm512_maskz_loadu_pd((__mmask8)(nv >= 16 ? 0xff : nv <= 8 ? 0 : (1u << (nv - 8)) - 1), p + 8);
    const __m512d C = _mm512_maskz_loadu_pd((__mmask8)(nv >= 24 ? 0xff : nv <= 16 ? 0 : (1u << (nv - 16)) - 1), p + 16);
    *X = _mm512_permutex2var_pd(_mm512_permutex2var_pd(A, xab, B), xc, C);
    *Y = _mm512_permutex2var_pd(_mm512_permutex2var_pd(A, yab, B), yc, C);
    *Z = _mm512_permutex2var_pd(_mm512_permutex2var_pd(A, zab, B), zc, C);
}

/* The distance test of one point (sx, sy, sz) against a loaded group: the
 * same subtractions and r^2 as scan_segment (no contraction), so the same
 * results; the kept j compressed and stored whole at buf + len. */
static inline __attribute__((target("avx512f"), always_inline))
size_t test_group_avx512(__m512d X, __m512d Y, __m512d Z, int j, int cnt, double sx, double sy, double sz,
                         __m512d c2, int *buf, size_t len)
{
    const __m512i step = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
    const __m512d dx = _mm512_sub_pd(_mm512_set1_pd(sx), X), dy = _mm512_sub_pd(_mm512_set1_pd(sy), Y);
    const __m512d dz = _mm512_sub_pd(_mm512_set1_pd(sz), Z);
    const __m512d r2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
    const __mmask8 keep = _mm512_mask_cmp_pd_mask((__mmask8)((1u << cnt) - 1), r2, c2, _CMP_LT_OQ);
    const __m512i js = _mm512_add_epi32(_mm512_set1_epi32(j), step);
    _mm512_storeu_si512(buf + len, _mm512_maskz_compress_epi32((__mmask16)keep, js));
    return len + (size_t)__builtin_popcount(keep);
}

__attribute__((target("avx512f")))
size_t simd_nl_scan_avx512(const double *x, int j0, int j1, double sx, double sy, double sz, double cut2, int *buf,
                           size_t len)
{
    const __m512d c2 = _mm512_set1_pd(cut2);
    for (int j = j0; j < j1; j += 8) {
        const int cnt = j1 - j < 8 ? j1 - j : 8;
        __m512d X, Y, Z;
        load_group_avx512(x, j, cnt, &X, &Y, &Z);
        len = test_group_avx512(X, Y, Z, j, cnt, sx, sy, sz, c2, buf, len);
    }
    return len;
}

/* The candidates j0 .. j1 - 1 of one stencil segment against nb points sp[q]
 * (neighbor.c build_cells): each group of eight loaded and sorted into lanes
 * once, then tested against every point, point q's kept j stored at end[q]. */
__attribute__((target("avx512f")))
void simd_nl_scan_block_avx512(const double *x, int j0, int j1, int nb, const double (*sp)[3], double cut2, int *buf,
                               size_t *end)
{
    const __m512d c2 = _mm512_set1_pd(cut2);
    for (int j = j0; j < j1; j += 8) {
        const int cnt = j1 - j < 8 ? j1 - j : 8;
        __m512d X, Y, Z;
        load_group_avx512(x, j, cnt, &X, &Y, &Z);
        for (int q = 0; q < nb; q++)
            end[q] = test_group_avx512(X, Y, Z, j, cnt, sp[q][0], sp[q][1], sp[q][2], c2, buf, end[q]);
    }
}
#endif
