/* pan_lanes_x86.c - the backend's Pan 2008 lanes (pair_avx512.h, registered
 * in pair_pan2008.c's PairStyle.accel): pan_lanes.h pan_lanes_force compiled
 * for AVX2 and AVX-512, the portable level's operations without contraction,
 * so its bits (tests/test_rotation.c lanes_same_bits_as_pair_by_pair). */
#include "pair_avx512.h"
#include "pan_lanes.h"

#ifdef DPD_HAVE_X86_SIMD
__attribute__((target("avx2"))) PAN_LANES_OPT void pan_lanes_avx2(void *L, int m, double inv_sqrt_dt, const PairParams *u)
{
    pan_lanes_force(L, m, inv_sqrt_dt, u);
}
__attribute__((target("avx512f"))) void pan_lanes_avx512(void *L, int m, double inv_sqrt_dt, const PairParams *u)
{
    pan_lanes_force(L, m, inv_sqrt_dt, u);
}
#endif
