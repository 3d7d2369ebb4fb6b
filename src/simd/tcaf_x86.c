/* tcaf_x86.c - the backend's TCAF block sums (simd.h SimdKernels.tcaf_block_sums):
 * tcaf_sums.h TCAF_BLOCK_SUMS on four lanes at a time (AVX2) and eight
 * (AVX-512), the portable kernel's operations on every lane, so its bits. */
#include "simd_x86.h"
#include "tcaf_sums.h"

#ifdef DPD_HAVE_X86_SIMD
TCAF_BLOCK_SUMS(simd_tcaf_block_sums_avx2, tcaf_v4, 4, __attribute__((target("avx2"))))
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
TCAF_BLOCK_SUMS(simd_tcaf_block_sums_avx512, tcaf_v8, 8, __attribute__((target("avx512f"))))
#pragma GCC diagnostic pop
#endif
