/* tcaf_sums.h - the TCAF's block sums (tcaf.c tcaf_current), written once:
 * tcaf.c compiles them for any x86-64 (two lanes at a time, SSE2), the
 * backend (src/simd/tcaf_x86.c) for AVX2 and AVX-512 (four and eight); every
 * level does the same IEEE operations on every lane (no contraction), so the
 * same bits (tests/test_tcaf.c). Included by those two files only. */
#ifndef DPD_TCAF_SUMS_H
#define DPD_TCAF_SUMS_H

#include <stddef.h>
#include "simd.h"

#define TCAF_LANES 8

/* A run: fixed (i, |j|) (jneg: j < 0, the conjugate of the y table), its
 * items it0 ... it1 - 1. An item: l >= 0, the vector of +l and that of -l
 * (-1: not in the run). The half space of wave_vectors has +l wherever it
 * has -l. */
typedef struct TcafRun { int i, j, jneg, it0, it1; } TcafRun;
typedef struct TcafItem { int l, qp, qm; } TcafItem;

/* A tile's tables in rows of TCAF_LANES doubles (one per particle): from row
 * a, Re and Im of e^{i m k_x x} for m = 0 ... nmax[0] (rows a + 2m, a + 2m + 1);
 * then the same for y (from b) and z (from c); then the velocity (rows v ... v + 2). */
typedef struct TcafLayout { int a, b, c, v, stride; } TcafLayout;

/* The vector types (may_alias: they read the double arrays): 2, 4 or 8 lanes */
typedef double tcaf_v2 __attribute__((vector_size(16), may_alias));
typedef double tcaf_v4 __attribute__((vector_size(32), may_alias));
typedef double tcaf_v8 __attribute__((vector_size(64), may_alias));
/* what simd.h SimdKernels.tcaf_block_sums holds */
typedef void (*TcafBlockSumsFn)(const TcafRun *run, int nrun, const TcafItem *item, const TcafLayout *lay,
                                const double *tab, int ntile, double *abuf, double *acc);

/* The sums of a block of ntile tiles, added to the lanes' sums acc (vector q,
 * component c = 2d + (0: Re, 1: Im), lane k at ((q * 6 + c) * TCAF_LANES + k)).
 * VT holds W of a tile's lanes, which are done W at a time (h): every level
 * does the same operations on every lane. The sums of an item stay in
 * registers while the block's tiles are added. */
#define TCAF_ROW(VT, base, row) (*(VT *)((base) + (size_t)(row) * TCAF_LANES))
#define TCAF_BLOCK_SUMS(NAME, VT, W, ATTRS)                                                           \
ATTRS void NAME(const TcafRun *run, int nrun, const TcafItem *item, const TcafLayout *layp,             \
                const double *tab, int ntile, double *restrict abuf, double *restrict acc)             \
{                                                                                                      \
    const TcafLayout lay = *layp;                                                                      \
    for (int h = 0; h < TCAF_LANES; h += W)                                                            \
        for (int r = 0; r < nrun; r++) {                                                               \
            const TcafRun *R = &run[r];                                                                \
            for (int b = 0; b < ntile; b++) {   /* e^{i(k_x x + k_y y)}: (a)(b) or (a)(conj b) */       \
                const double *p = tab + (size_t)b * lay.stride * TCAF_LANES + h;                       \
                const VT ar = TCAF_ROW(VT, p, lay.a + 2 * R->i), ai = TCAF_ROW(VT, p, lay.a + 2 * R->i + 1); \
                const VT br = TCAF_ROW(VT, p, lay.b + 2 * R->j), bj = TCAF_ROW(VT, p, lay.b + 2 * R->j + 1); \
                const VT bi = R->jneg ? -bj : bj;                                                      \
                TCAF_ROW(VT, abuf + h, 2 * b) = ar * br - ai * bi;                                     \
                TCAF_ROW(VT, abuf + h, 2 * b + 1) = ar * bi + ai * br;                                 \
            }                                                                                          \
            for (int it = R->it0; it < R->it1; it++) {                                                 \
                const TcafItem *e = &item[it];                                                         \
                const int both = e->qm >= 0;                                                           \
                double *sp = acc + (size_t)e->qp * 6 * TCAF_LANES + h;                                 \
                double *sm = acc + (size_t)(both ? e->qm : 0) * 6 * TCAF_LANES + h;                    \
                VT s[6], m[6];                                                                         \
                for (int c = 0; c < 6; c++) { s[c] = TCAF_ROW(VT, sp, c); m[c] = TCAF_ROW(VT, sm, c); } \
                for (int b = 0; b < ntile; b++) {                                                      \
                    const double *p = tab + (size_t)b * lay.stride * TCAF_LANES + h;                   \
                    const VT abr = TCAF_ROW(VT, abuf + h, 2 * b), abi = TCAF_ROW(VT, abuf + h, 2 * b + 1); \
                    const VT cr = TCAF_ROW(VT, p, lay.c + 2 * e->l), cj = TCAF_ROW(VT, p, lay.c + 2 * e->l + 1); \
                    const VT v0 = TCAF_ROW(VT, p, lay.v), v1 = TCAF_ROW(VT, p, lay.v + 1), v2 = TCAF_ROW(VT, p, lay.v + 2); \
                    if (both) {   /* (ab)(c) and (ab)(conj c) from four products */                    \
                        const VT p1 = abr * cr, p2 = abi * cj, p3 = abr * cj, p4 = abi * cr;           \
                        const VT pr = p1 - p2, pi = p3 + p4, qr = p1 + p2, qi = p4 - p3;               \
                        s[0] += v0 * pr; s[1] += v0 * pi; s[2] += v1 * pr;                             \
                        s[3] += v1 * pi; s[4] += v2 * pr; s[5] += v2 * pi;                             \
                        m[0] += v0 * qr; m[1] += v0 * qi; m[2] += v1 * qr;                             \
                        m[3] += v1 * qi; m[4] += v2 * qr; m[5] += v2 * qi;                             \
                    } else {      /* +l alone: (ab)(c) */                                              \
                        const VT pr = abr * cr - abi * cj, pi = abr * cj + abi * cr;                   \
                        s[0] += v0 * pr; s[1] += v0 * pi; s[2] += v1 * pr;                             \
                        s[3] += v1 * pi; s[4] += v2 * pr; s[5] += v2 * pi;                             \
                    }                                                                                  \
                }                                                                                      \
                for (int c = 0; c < 6; c++) TCAF_ROW(VT, sp, c) = s[c];                                \
                if (both) for (int c = 0; c < 6; c++) TCAF_ROW(VT, sm, c) = m[c];                      \
            }                                                                                          \
        }                                                                                              \
}

#endif
