/* simd_x86.h - the entry points of the x86-64 backend (src/simd/) that simd.c
 * puts in its tables (SimdKernels): included by simd.c and by the backend's
 * files only, which define them (tests/layers.sh checks it), so that no
 * concern calls a vector kernel other than through simd_kernels(). Defined in
 * x86-64 builds only (simd.h DPD_HAVE_X86_SIMD). */
#ifndef DPD_SIMD_X86_H
#define DPD_SIMD_X86_H

#include "simd.h"

/* philox_x86.c */
int simd_philox_avx2(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1, const uint32_t *c2,
                     const uint32_t *c3, uint32_t (*w)[RNG_BATCH]);
int simd_philox_avx512(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1, const uint32_t *c2,
                       const uint32_t *c3, uint32_t (*w)[RNG_BATCH]);
/* ziggurat_x86.c */
int simd_zig_first_avx2(int m, const uint32_t *w, double *z, uint16_t *ok, const ZigTables *t);
int simd_zig_first_avx512(int m, const uint32_t *w, double *z, uint16_t *ok, const ZigTables *t);
int simd_zig_bad_pairs_avx512(int groups, const uint16_t (*ok)[RNG_BATCH / 16], int nvar, int *bad, int *v0);
void simd_zig_wedge_avx512(int nbad, const uint32_t *kw, const uint32_t *uw, uint8_t *out, const ZigTables *t);
/* pow_x86.c */
void simd_pow_batch_avx2(const double *w, const double *p, double *out, int m);
void simd_pow_batch_avx512(const double *w, const double *p, double *out, int m);
/* tcaf_x86.c */
void simd_tcaf_block_sums_avx2(const struct TcafRun *run, int nrun, const struct TcafItem *item,
                               const struct TcafLayout *lay, const double *tab, int ntile, double *abuf, double *acc);
void simd_tcaf_block_sums_avx512(const struct TcafRun *run, int nrun, const struct TcafItem *item,
                                 const struct TcafLayout *lay, const double *tab, int ntile, double *abuf, double *acc);
/* neighbor_avx512.c */
size_t simd_nl_scan_avx512(const double *x, int j0, int j1, double sx, double sy, double sz, double cut2, int *buf,
                           size_t len);
void simd_nl_scan_block_avx512(const double *x, int j0, int j1, int nb, const double (*sp)[3], double cut2, int *buf,
                               size_t *end);

#endif
