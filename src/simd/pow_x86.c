/* pow_x86.c - the backend's w^p batches (simd.h SimdKernels.pow_batch):
 * weight_pow.h weight_pow_batch_lanes compiled for AVX2 and AVX-512. Its
 * IEEE operations without contraction give the portable build's bits;
 * tests/test_forces.c weight_pow_same_bits_at_every_level checks it. */
#include "simd_x86.h"
#include "weight_pow.h"

/* weight_pow_batch_lanes is always inlined: no 64-byte vector crosses a call */
#pragma GCC diagnostic ignored "-Wpsabi"

#ifdef DPD_HAVE_X86_SIMD
__attribute__((target("avx2"))) void simd_pow_batch_avx2(const double *w, const double *p, double *out, int m)
{
    weight_pow_batch_lanes(w, p, out, m);
}
__attribute__((target("avx512f"))) void simd_pow_batch_avx512(const double *w, const double *p, double *out, int m)
{
    weight_pow_batch_lanes(w, p, out, m);
}
#endif
