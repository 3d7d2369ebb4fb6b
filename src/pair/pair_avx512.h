/* pair_avx512.h - the pair layer's entry points into the vector backend
 * (src/simd/pair_avx512.c: the walk's candidate pass and the styles'
 * evaluators of one-type batches; src/simd/pan_lanes_x86.c: the Pan 2008
 * lanes), which forces.c pair_kernels picks per force call and the styles
 * register in their PairStyle.accel. They exist in x86-64 builds only: name
 * them through SIMD_X86 (simd.h), which is NULL elsewhere. */
#ifndef DPD_PAIR_AVX512_H
#define DPD_PAIR_AVX512_H

#include "pair_style.h"

/* The walk's candidate pass eight entries at a time (3D, no shear; the
 * scalar pairs_in_range's bits and entries), into rows or planes
 * (PairKernels.gather_rows, gather_planes). */
int pair_gather_rows_avx512(const System *s, const NeighborList *nl, int i, int i1, int *near, double (*dd)[4],
                            int *count, uint32_t *id_a, uint32_t *id_b, int *np, int ahead);
int pair_gather_planes_avx512(const System *s, const NeighborList *nl, int i, int i1, int *near, double *pl,
                              int *count, uint32_t *id_a, uint32_t *id_b, int *np, int ahead);
/* How many particles ahead the candidate pass fetches a particle's candidates toward the cache (0: none). */
int pair_prefetch_ahead(const System *s, const NeighborList *nl);

/* The styles' evaluators of one-type batches (PairOneTypeFn): standard DPD
 * (pair_dpd.c) and Pan et al. 2008 (pair_pan2008.c; refuses a general power). */
int dpd_one_type_avx512(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                        const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv);
int pan_one_type_avx512(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                        const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv);

/* The Pan 2008 style's lanes (PairLanesFn) for AVX2 and AVX-512: pan_lanes.h pan_lanes_force. */
void pan_lanes_avx2(void *L, int m, double inv_sqrt_dt, const PairParams *u);
void pan_lanes_avx512(void *L, int m, double inv_sqrt_dt, const PairParams *u);

#endif
