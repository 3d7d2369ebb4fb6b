/* weight_pow.c - w^p by weight_pow_lanes (weight_pow.h), one at a time and in
 * batches at the instruction set in use (simd.h SimdKernels.pow_batch); a
 * lane outside the lanes' domain takes libm's pow. */
#include <string.h>
#include "weight_pow.h"
#include "simd.h"

/* weight_pow_lanes is always inlined (weight_pow.h): no vector crosses a call */
#pragma GCC diagnostic ignored "-Wpsabi"

double weight_pow(double w, double p)
{
    const v8d wv = {w, 1, 1, 1, 1, 1, 1, 1}, pv = {p, 1, 1, 1, 1, 1, 1, 1};
    v8i bad;
    const v8d r = weight_pow_lanes(wv, pv, &bad);
    return bad[0] ? pow(w, p) : r[0];
}

/* the lanes' loop for any x86-64 (SSE2); the backend's for AVX2 and AVX-512 */
static void pow_batch_portable(const double *w, const double *p, double *out, int m)
{
    weight_pow_batch_lanes(w, p, out, m);
}

void weight_pow_batch(const double *w, const double *p, double *out, int m)
{
    const SimdKernels *k = simd_kernels();
    (k->pow_batch ? k->pow_batch : pow_batch_portable)(w, p, out, m);
}
