/* simd.c - the vectorised kernels' instruction set, detected once, and the
 * dispatch point: the backend's kernels (src/simd/) for each level, the
 * table of the level in use handed out by simd_kernels(). */
#include <stdlib.h>
#include <threads.h>
#include "simd.h"
#include "simd_x86.h"

static int level = 0, level_max = 0;
static once_flag detect_once = ONCE_FLAG_INIT;

/* by level; portable: every entry NULL (each concern's own kernel) */
static const SimdKernels kernels[3] = {
#ifdef DPD_HAVE_X86_SIMD
    [SIMD_AVX2] = {
        .philox = simd_philox_avx2, .zig_first = simd_zig_first_avx2,
        .pow_batch = simd_pow_batch_avx2, .tcaf_block_sums = simd_tcaf_block_sums_avx2,
    },
    /* the neighbour list's distance test on AVX-512 only (its compress; 3D boxes: neighbor.c) */
    [SIMD_AVX512] = {
        .philox = simd_philox_avx512, .zig_first = simd_zig_first_avx512,
        .zig_bad_pairs = simd_zig_bad_pairs_avx512, .zig_wedge = simd_zig_wedge_avx512,
        .pow_batch = simd_pow_batch_avx512, .tcaf_block_sums = simd_tcaf_block_sums_avx512,
        .nl_scan = simd_nl_scan_avx512, .nl_scan_block = simd_nl_scan_block_avx512,
    },
#endif
};

static void detect(void)
{
    int best = SIMD_PORTABLE;
#ifdef DPD_HAVE_X86_SIMD
    __builtin_cpu_init();
    best = __builtin_cpu_supports("avx512f") ? SIMD_AVX512 : __builtin_cpu_supports("avx2") ? SIMD_AVX2 : SIMD_PORTABLE;
#endif
    const char *cap = getenv("DPD_SIMD");
    if (cap && *cap >= '0' && *cap <= '2' && cap[1] == '\0' && *cap - '0' < best) best = *cap - '0';
    level = level_max = best;
}

int simd_level(void)
{
    call_once(&detect_once, detect);
    return level;
}

int simd_cap(int cap)
{
    call_once(&detect_once, detect);
    if (cap >= 0) level = cap < level_max ? cap : level_max;
    return level;
}

const SimdKernels *simd_kernels(void)
{
    return &kernels[simd_level()];
}
