/* simd.h - the instruction set of the vectorised kernels (the pair noise's
 * Philox lanes and ziggurat step, the neighbour build's distance test, the
 * walk's candidate pass, the Pan 2008 lanes, the TCAF sums),
 * chosen once per process from what the CPU has: one binary runs on any
 * x86-64. Every vectorised kernel has a portable twin that gives the same
 * bits; the tests run each level the CPU has against it. */
#ifndef DPD_SIMD_H
#define DPD_SIMD_H

enum { SIMD_PORTABLE = 0, SIMD_AVX2 = 1, SIMD_AVX512 = 2 };

#if defined(__x86_64__) && defined(__GNUC__) && !defined(DPD_PORTABLE_SIMD)
#define DPD_HAVE_X86_SIMD 1
#endif

/* The level in use: the best the CPU has, at most the environment's DPD_SIMD
 * (0, 1 or 2) if set. */
int simd_level(void);
/* Lower the level to at most cap (cap >= 0; a cap above what the CPU has
 * gives the CPU's best), for tests and benchmarks; returns the level in use. */
int simd_cap(int cap);

/* The variant of a kernel for the level in use: SIMD_PICK(portable, avx2,
 * avx512), the last two compiled with target("avx2") and target("avx512f")
 * (x86-64 builds only; elsewhere the portable one). */
#ifdef DPD_HAVE_X86_SIMD
#define SIMD_PICK(portable, avx2, avx512) \
    (simd_level() == SIMD_AVX512 ? (avx512) : simd_level() == SIMD_AVX2 ? (avx2) : (portable))
#else
#define SIMD_PICK(portable, avx2, avx512) (portable)
#endif

/* A function compiled for AVX2 or AVX-512 (x86-64 builds; elsewhere the
 * portable code again), and a kernel that exists in x86-64 builds only
 * (NULL elsewhere): a file that compiles one kernel for every level, or
 * names the pair backend's (pair_avx512.h), needs no guard of its own. */
#ifdef DPD_HAVE_X86_SIMD
#define SIMD_TARGET_AVX2 __attribute__((target("avx2")))
#define SIMD_TARGET_AVX512 __attribute__((target("avx512f")))
#define SIMD_X86(kernel) (kernel)
#else
#define SIMD_TARGET_AVX2
#define SIMD_TARGET_AVX512
#define SIMD_X86(kernel) NULL
#endif

#endif
