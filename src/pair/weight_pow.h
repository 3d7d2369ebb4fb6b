/* weight_pow.h - w^p for the weight functions of a general exponent (eqs 6-7:
 * w_R = w_C^(s/2), w_D = w_C^s), eight at a time, in IEEE additions,
 * multiplications and divisions only: GCC's vector extensions compile it for
 * any instruction set, and without contraction (-std=c11) every set gives the
 * same bits, and the scalar wrapper (weight_pow) the same bits as the lanes.
 * libm's pow is a scalar call (a third of the Mai-Duy solvent's run), and
 * libmvec's vector pow differs between instruction sets.
 *
 * Method: w = 2^k m, m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh f with
 * f = (m - 1)/(m + 1) (Abramowitz & Stegun 4.1.27), its leading term 2f in
 * double-double (Dekker 1971 product, Knuth's two-sum); ln 2 split as in
 * fdlibm (ln2_hi with 32 significant bits, so k ln2_hi is exact);
 * z = p ln w in double-double; exp z = 2^n exp r, r = z - n ln 2 in
 * [-ln2/2, ln2/2], exp r by its Taylor series to r^14 with 1 + r in
 * double-double (Tang 1989, without the table); the series by Estrin's scheme
 * (Knuth, TAOCP vol. 2, 4.6.4), whose short chains keep the lanes busy. Error: within 1 ulp of the
 * exact power (test_weight_pow measures it against powl).
 *
 * Domain of the lanes: w in [2^-1000, 1], p in (0, 8], p ln w >= -700; any
 * other lane (w = 0 when r/rc rounds to 1, NaN) takes libm's pow. */
#ifndef DPD_WEIGHT_POW_H
#define DPD_WEIGHT_POW_H

#include <math.h>
#include <string.h>

typedef double v8d __attribute__((vector_size(64)));
typedef long long v8i __attribute__((vector_size(64)));
typedef unsigned long long v8u __attribute__((vector_size(64)));

/* The helpers below are always inlined: no 64-byte vector crosses a call, so
 * the ABI note GCC gives for them on targets without AVX-512 does not apply. */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#define V8_INLINE static inline __attribute__((always_inline))

/* a b = p + e exactly (Dekker 1971: halves of 26 bits, no fused multiply-add) */
V8_INLINE void v8_two_prod(v8d a, v8d b, v8d *p, v8d *e)
{
    const v8d ca = a * 134217729.0, cb = b * 134217729.0;
    const v8d ah = ca - (ca - a), al = a - ah, bh = cb - (cb - b), bl = b - bh;
    *p = a * b;
    *e = ((ah * bh - *p) + ah * bl + al * bh) + al * bl;
}

/* a + b = s + e exactly (Knuth) */
V8_INLINE void v8_two_sum(v8d a, v8d b, v8d *s, v8d *e)
{
    *s = a + b;
    const v8d bb = *s - a;
    *e = (a - (*s - bb)) + (b - bb);
}

/* w^p lane by lane; bad: 1 in the lanes outside the domain, 0 elsewhere */
V8_INLINE v8d weight_pow_lanes(v8d w, v8d p, v8i *bad)
{
    const double LN2_HI = 6.93147180369123816490e-01, LN2_LO = 1.90821492927058770002e-10;  /* fdlibm */
    const double INV_LN2 = 1.44269504088896338700e+00, SHIFT = 6755399441055744.0;          /* 1.5 2^52 */
    /* w = 2^k m */
    const v8i b = (v8i)w;
    v8i ex = ((b >> 52) & 0x7ff) - 1023;
    v8i mb = (b & 0x000fffffffffffffLL) | 0x3ff0000000000000LL;
    /* m > sqrt 2: the bits compared as integers (a comparison of doubles is
     * done lane by lane on AVX-512F without DQ; the sign of a difference is not) */
    const v8i big = (v8i)(((v8u)(0x3ff6a09e667f3bcdLL - mb)) >> 63);   /* 1 where m > sqrt 2 */
    mb -= big << 52;   /* m / 2 */
    ex += big;         /* k + 1 */
    const v8d m = (v8d)mb;
    const v8d k = (v8d)(ex + (1024 + 0x4330000000000000LL)) - (4503599627370496.0 + 1024.0);
    /* f = (m - 1)/(m + 1) = fh + fl */
    const v8d one = {1, 1, 1, 1, 1, 1, 1, 1}, u = m - 1.0;   /* exact (Sterbenz) */
    v8d vh, vl, P, Pe;
    v8_two_sum(m, one, &vh, &vl);
    const v8d fh = u / vh;
    v8_two_prod(fh, vh, &P, &Pe);
    const v8d fl = (((u - P) - Pe) - fh * vl) * ((1.0 - fh) * 0.5);   /* 1/(m + 1) = (1 - f)/2: no second division */
    /* ln m = 2 f + 2 f z T(z), z = f^2, T = 1/3 + z/5 + ... + z^10/23 */
    const v8d z = fh * fh, z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;   /* Estrin's scheme: short chains */
    const v8d T = ((1.0 / 3 + z * (1.0 / 5)) + z2 * (1.0 / 7 + z * (1.0 / 9)))
                + z4 * ((1.0 / 11 + z * (1.0 / 13)) + z2 * (1.0 / 15 + z * (1.0 / 17)))
                + z8 * ((1.0 / 19 + z * (1.0 / 21)) + z2 * (1.0 / 23));
    const v8d C = (2.0 * fh) * (z * T);
    /* ln w = k ln2 + 2 fh + (2 fl + C) = yh + yl */
    v8d sh, sl;
    v8_two_sum(k * LN2_HI, 2.0 * fh, &sh, &sl);
    sl = sl + (k * LN2_LO + (2.0 * fl + C));
    const v8d yh = sh + sl, yl = sl - (yh - sh);
    /* p ln w = zh + zl */
    v8d zh, zl;
    v8_two_prod(p, yh, &zh, &zl);
    zl = zl + p * yl;
    /* exp: z = n ln2 + r + rl */
    const v8d t = zh * INV_LN2 + SHIFT, n = t - SHIFT;
    const v8i ni = (v8i)t - (v8i)(one * SHIFT);   /* n: t's bits above SHIFT's */
    const v8d rh = zh - n * LN2_HI;   /* exact */
    v8d r, rl;
    v8_two_sum(rh, zl - n * LN2_LO, &r, &rl);
    /* Q = sum_{i=0}^{12} r^i / (i + 2)!, by Estrin's scheme */
    const v8d r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const v8d Q = ((0.5 + r * (1.0 / 6)) + r2 * (1.0 / 24 + r * (1.0 / 120)))
                + r4 * ((1.0 / 720 + r * (1.0 / 5040)) + r2 * (1.0 / 40320 + r * (1.0 / 362880)))
                + r8 * (((1.0 / 3628800 + r * (1.0 / 39916800)) + r2 * (1.0 / 479001600 + r * (1.0 / 6227020800.0)))
                        + r4 * (1.0 / 87178291200.0));
    const v8d q = r2 * Q;
    const v8d eh = one + r, el = r - (eh - one);   /* |1| >= |r| */
    const v8d E = eh + (el + (q + rl * (one + r)));
    const v8d scale = (v8d)((v8u)(ni + 1023) << 52);
    /* the domain, by the sign bits of differences of the bit patterns
     * (positive doubles order as their bits): w in [2^-1000, 1], p in (0, 8],
     * |zh| <= 700; a NaN or a negative value falls outside */
    const v8u wb = (v8u)w, pb = (v8u)p, zb = (v8u)zh & 0x7fffffffffffffffULL;
    const v8u out = (wb - 0x0170000000000000ULL) | (0x3ff0000000000000ULL - wb) | wb
                  | (pb - 1) | (0x4020000000000000ULL - pb) | pb | (0x4085e00000000000ULL - zb);
    *bad = (v8i)(out >> 63);
    return E * scale;
}

/* out[q] = w[q]^p[q] for q < m, eight at a time (weight_pow_batch's loop):
 * compiled by weight_pow.c for any x86-64 and by the backend
 * (src/simd/pow_x86.c) for AVX2 and AVX-512, the same bits at each. */
V8_INLINE void weight_pow_batch_lanes(const double *w, const double *p, double *out, int m)
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

#undef V8_INLINE
#pragma GCC diagnostic pop

/* w^p for one w (the other lanes idle): the lanes' bits */
double weight_pow(double w, double p);
/* out[q] = w[q]^p[q] for q < m, at the instruction set in use; w and p hold
 * m rounded up to 8 entries (the padding any w, p of the domain) */
void weight_pow_batch(const double *w, const double *p, double *out, int m);

#endif
