/* weight_pow.c - w^p by weight_pow_lanes (weight_pow.h), one at a time and in
 * batches at the instruction set in use; a lane outside the lanes' domain
 * takes libm's pow. */
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

/* weight_pow_batch's loop, compiled once per instruction set */
static inline __attribute__((always_inline)) void pow_batch(const double *w, const double *p, double *out, int m)
{
    for (int q = 0; q < m; q += 8) {
        v8d wv, pv;
        memcpy(&wv, w + q, sizeof wv);
        memcpy(&pv, p + q, sizeof pv);
        v8i bad;
        const v8d r = weight_pow_lanes(wv, pv, &bad);
        long long any = 0;
        for (int l = 0; l < 8; l++) any |= bad[l];
        if (m - q >= 8 && !any) { memcpy(out + q, &r, sizeof r); continue; }
        const int n = m - q < 8 ? m - q : 8;
        for (int l = 0; l < n; l++) out[q + l] = bad[l] ? pow(wv[l], pv[l]) : r[l];
    }
}
static void pow_batch_portable(const double *w, const double *p, double *out, int m) { pow_batch(w, p, out, m); }
#ifdef DPD_HAVE_X86_SIMD
__attribute__((target("avx2"))) static void pow_batch_avx2(const double *w, const double *p, double *out, int m)
{ pow_batch(w, p, out, m); }
__attribute__((target("avx512f"))) static void pow_batch_avx512(const double *w, const double *p, double *out, int m)
{ pow_batch(w, p, out, m); }
#endif

void weight_pow_batch(const double *w, const double *p, double *out, int m)
{
    SIMD_PICK(pow_batch_portable, pow_batch_avx2, pow_batch_avx512)(w, p, out, m);
}
