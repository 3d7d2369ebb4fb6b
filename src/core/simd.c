/* simd.c - the vectorised kernels' instruction set, detected once. */
#include <stdlib.h>
#include <threads.h>
#include "simd.h"

static int level = 0, level_max = 0;
static once_flag detect_once = ONCE_FLAG_INIT;

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
