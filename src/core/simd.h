/* simd.h - the instruction set of the vectorised kernels and the one place
 * that picks them. The level is chosen once per process from what the CPU
 * has (one binary runs on any x86-64), at most DPD_SIMD. Every vector kernel
 * lives in the backend, src/simd/ (the only files with intrinsics or
 * target("avx...") attributes; tests/layers.sh checks it), and accelerates a
 * portable kernel that stays in its concern's file as the reference and gives
 * the same bits; the tests run each level the CPU has against it.
 *
 * The concerns below the backend reach it only through simd_kernels(): the
 * table of the level in use, filled in simd.c (the dispatch point), a NULL
 * entry meaning "the portable kernel". The pair styles' accelerators are the
 * one other choice by level: a style registers them in its PairStyle.accel
 * (pair_style.h), declared in pair_avx512.h, and forces.c pair_kernels picks
 * them per force call. */
#ifndef DPD_SIMD_H
#define DPD_SIMD_H

#include <stddef.h>
#include <stdint.h>
#include "random.h"

enum { SIMD_PORTABLE = 0, SIMD_AVX2 = 1, SIMD_AVX512 = 2 };

/* x86-64 builds with GCC or clang have the backend; -DDPD_PORTABLE_SIMD
 * leaves it out (as any other target does): every level is then portable. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(DPD_PORTABLE_SIMD)
#define DPD_HAVE_X86_SIMD 1
#endif

/* The level in use: the best the CPU has, at most the environment's DPD_SIMD
 * (0, 1 or 2) if set. */
int simd_level(void);
/* Lower the level to at most cap (cap >= 0; a cap above what the CPU has
 * gives the CPU's best), for tests and benchmarks; returns the level in use. */
int simd_cap(int cap);

struct TcafRun;
struct TcafItem;
struct TcafLayout;

/* The backend's kernels at one level (NULL: none; the caller runs its
 * portable kernel). Each names the portable code whose bits it gives. */
typedef struct {
    /* random.c philox_portable on the pairs [0, return) of the m (the rest: portable) */
    int (*philox)(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1, const uint32_t *c2,
                  const uint32_t *c3, uint32_t (*w)[RNG_BATCH]);
    /* random.c zig_accept on words [0, return) in groups of 16 (ok[g] bit l: word 16 g + l
     * accepted at once) */
    int (*zig_first)(int m, const uint32_t *w, double *z, uint16_t *ok, const ZigTables *t);
    /* the pairs of groups not accepted at once, as random.c pair_normals lists them */
    int (*zig_bad_pairs)(int groups, const uint16_t (*ok)[RNG_BATCH / 16], int nvar, int *bad, int *v0);
    /* GSL's wedge test, settled within the brackets of random.c wedge_init (WEDGE_*) */
    void (*zig_wedge)(int nbad, const uint32_t *kw, const uint32_t *uw, uint8_t *out, const ZigTables *t);
    /* weight_pow.h weight_pow_batch_lanes */
    void (*pow_batch)(const double *w, const double *p, double *out, int m);
    /* tcaf_sums.h TCAF_BLOCK_SUMS */
    void (*tcaf_block_sums)(const struct TcafRun *run, int nrun, const struct TcafItem *item,
                            const struct TcafLayout *lay, const double *tab, int ntile, double *abuf, double *acc);
    /* neighbor.c scan_segment (3D): the candidates j0 .. j1 - 1 within cut2 of s appended at buf + len
     * (up to SCAN_SLACK slots past the last kept written); returns the new length */
    size_t (*nl_scan)(const double *x, int j0, int j1, double sx, double sy, double sz, double cut2, int *buf,
                      size_t len);
    /* nl_scan of the candidates j0 .. j1 - 1 for each of nb points sp[q], into buf at end[q] */
    void (*nl_scan_block)(const double *x, int j0, int j1, int nb, const double (*sp)[3], double cut2, int *buf,
                          size_t *end);
} SimdKernels;

/* The kernels of the level in use. */
const SimdKernels *simd_kernels(void);

/* A kernel that exists in x86-64 builds only (NULL elsewhere): the pair
 * styles' accelerators in their PairStyle.accel (pair_avx512.h). */
#ifdef DPD_HAVE_X86_SIMD
#define SIMD_X86(kernel) (kernel)
#else
#define SIMD_X86(kernel) NULL
#endif

#endif
