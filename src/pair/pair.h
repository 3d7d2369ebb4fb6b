/* pair.h - what every pair kernel shares, in one copy: the r -> 0 guard, the
 * weight functions of eqs 5-7 (Mai-Duy et al. 2019; Groot & Warren 1997), the
 * batch of listed pairs inside the cutoff, the per-chunk accumulator a kernel
 * writes its forces and torques into, and the virial by part.
 *
 * The pair driver (forces.c) walks the neighbour list of a chunk of particles
 * a batch of PAIR_BATCH entries at a time and hands each batch to an evaluator
 * (pair_dpd.h: standard DPD; pair_pan2008.h: rotating particles), the way
 * HOOMD-blue's PotentialPair hands pairs to an Evaluator. The m = 0 assembly
 * (overdamped.c) visits the same pairs through pair_visit (forces.h). */
#ifndef DPD_PAIR_H
#define DPD_PAIR_H

#include <math.h>
#include "system.h"
#include "neighbor.h"
#include "weight_pow.h"
#include "simd.h"

/* Pairs closer than this have no direction: they exert no force (LAMMPS'
 * EPSILON in pair_dpd.cpp). Springs use it too (bonds.c). */
#define PAIR_R_EPSILON 1e-10

/* A listed pair interacts: inside its own cutoff and not coincident (a NaN
 * r^2 interacts, so that the NaN reaches the forces and stops the run). */
static inline int pair_interacts(const PairParams *p, double r2)
{
    return !(r2 >= p->rc2 || r2 < PAIR_R_EPSILON * PAIR_R_EPSILON);
}

/* The exponent s of eqs 6-7 is none of 2, 1 and 0.5: w_R needs a power
 * (weight_pow.h), which the walk takes for a batch at once. */
static inline int weight_general(double s) { return !(s == 2.0 || s == 1.0 || s == 0.5); }

/* w_R = (1 - r/rc)^(s/2) from w_C = 1 - r/rc (eqs 5, 7), so that
 * w_D = w_R^2 = (1 - r/rc)^s (eq. 6); the usual exponents without a power. */
static inline double random_weight(double wc, double s)
{
    if (s == 2.0) return wc;
    if (s == 1.0) return sqrt(wc);
    if (s == 0.5) return sqrt(sqrt(wc));
    return weight_pow(wc, 0.5 * s);
}

/* w_D = (1 - r/rc)^s (eq. 6) computed directly, for the m = 0 matrix, which
 * needs w_D and w_R = sqrt(w_D): for s = 0.5, 1 and 2 this w_R is
 * random_weight's bit for bit (sqrt of a correctly rounded square is exact). */
static inline double dissipative_weight(double wc, double s)
{
    if (s == 2.0) return wc * wc;
    if (s == 1.0) return wc;
    if (s == 0.5) return sqrt(wc);
    return weight_pow(wc, s);
}

enum { PART_CONSERVATIVE = 0, PART_DISSIPATIVE = 1, PART_RANDOM = 2, PAIR_PARTS = 3 };

/* Pair virial sum_{i<j} r_ij F_ij (components [a][b] = r_a F_b), kept by part,
 * and optionally split over slabs along one axis (Irving & Kirkwood 1950). */
typedef struct {
    double W[PAIR_PARTS][3][3];
    double epot;
    int bin_axis, nbins;      /* nbins = 0: no binned stress */
    double *Wbin;             /* PAIR_PARTS x nbins x 9 */
    double frozen_force[DPD_MAX_TYPES][3]; /* force of mobile particles on frozen ones, by frozen type */
    double frozen_torque[DPD_MAX_TYPES][3]; /* rotation scenes: torque on frozen ones, by frozen type, */
    double frozen_drag[DPD_MAX_TYPES][3];   /* and force, both without the zero-mean random part; */
    double frozen_torque_random[DPD_MAX_TYPES][3]; /* the random part of the torque */
} PairVirial;

/* Distribute one pair term t[a][b] over slabs along axis (segment from the image
 * of j at x_i - d to x_i); used by the evaluators and tests. */
void ik_distribute(double *Wbin, int nbins, int axis, double Laxis,
                   double xi_axis, double d_axis, const double t[9]);
/* A pair's 9 virial terms of one part into W and its slabs. */
void pair_virial_add(PairVirial *pv, const System *s, int i, int q, const double d[3], const double t[9]);
/* The pair energy a rc w_C^2 / 2 (the potential of eq. 2). */
static inline double pair_energy(const PairParams *p, double wc) { return 0.5 * p->a * p->rc * wc * wc; }

/* A chunk writes to its own particles, the next cell layer and the periodic
 * wrap: most of its buffer is never written. Buffers are cleared on a block's
 * first write and summed only over the blocks each chunk touched. */
#define FORCE_BLOCK_SHIFT 8   /* 256 particles per block */

/* What an evaluator writes into: the chunk's force (and torque) buffer, its
 * touched-block mask, and the sums of particle i's own pairs. */
typedef struct {
    double *f, *tq;           /* tq: rotation scenes only */
    unsigned char *touched;
    int n;
    double inv_sqrt_dt;       /* 1 / sqrt(dt): the noise is theta / sqrt(dt) (eq. 4) */
    double fi[3], ti[3];
} PairAcc;

/* Before writing particle j of a chunk's buffer(s) f (and t, or NULL): clear
 * its block if this is the block's first write of the step. */
static inline void force_claim(double *f, double *t, unsigned char *touched, int j, int n)
{
    const int b = j >> FORCE_BLOCK_SHIFT;
    if (touched[b]) return;
    touched[b] = 1;
    const int p0 = b << FORCE_BLOCK_SHIFT, p1 = p0 + (1 << FORCE_BLOCK_SHIFT) < n ? p0 + (1 << FORCE_BLOCK_SHIFT) : n;
    for (int k = 3 * p0; k < 3 * p1; k++) f[k] = 0.0;
    if (t) for (int k = 3 * p0; k < 3 * p1; k++) t[k] = 0.0;
}

#define PAIR_BATCH 256
/* room past a batch's last entry that the AVX-512 passes may write */
#define RANGE_SLACK 16
/* a walk batch's separations as planes: x, y, z, r^2, PAIR_PLANE apart */
#define PAIR_PLANE (PAIR_BATCH + RANGE_SLACK)
/* Pass 1 of the walk, branch free: the list entries k0..k1 of particle i that
 * lie inside the largest cutoff, with their minimum-image separation and r^2
 * (dd[q] = dx, dy, dz, r2). Returns their number. le: as box_min_image_le. */
static inline __attribute__((always_inline)) int pairs_in_range(const System *s, const NeighborList *nl, int i, int k0, int k1,
                                 int *near, double (*dd)[4], const int le)
{
    const double *x = s->x;
    const double rc2_max = s->rc_max * s->rc_max;
    int m = 0;
    for (int k = k0; k < k1; k++) {
        const int j = nl->nbr[k];
        double d[3] = {x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1], x[3 * i + 2] - x[3 * j + 2]};
        box_min_image_le(&s->box, d, NULL, le);
        const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        near[m] = j;
        dd[m][0] = d[0]; dd[m][1] = d[1]; dd[m][2] = d[2]; dd[m][3] = r2;
        m += (r2 < rc2_max);
    }
    return m;
}

/* The x velocity of particle j's nearest image relative to j, seen from i
 * (box_image_vx); 0 without shear (le = 0, a constant). */
static inline double pair_image_vx(const System *s, int i, int j, const int le)
{
    return DPD_MODULES && le ? box_image_vx(&s->box, s->x[3 * i + 1] - s->x[3 * j + 1]) : 0.0;
}

#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>
/* r / rc in eight lanes, as the scalar evaluators divide (eq. 5); when rc is a
 * power of two (rc = 1 in most scenes) the product r * (1 / rc) is the same
 * number, without the divider, which the lanes' square roots keep busy.
 * inv_rc: rc_power_of_two_inverse(rc), formed once. */
static inline double rc_power_of_two_inverse(double rc)
{
    int e;
    return frexp(rc, &e) == 0.5 ? 1.0 / rc : 0.0;
}
static inline __attribute__((target("avx512f"), always_inline))
__m512d r_over_rc_avx512(__m512d r, double rc, double inv_rc)
{
    return inv_rc != 0.0 ? _mm512_mul_pd(r, _mm512_set1_pd(inv_rc)) : _mm512_div_pd(r, _mm512_set1_pd(rc));
}

/* The lanes of live whose r^2 interacts (pair_interacts: !(r2 >= rc2 || r2 < eps2), a NaN interacts) */
static inline __attribute__((target("avx512f"), always_inline))
__mmask8 pair_interacts_avx512(__m512d r2, __m512d rc2, __m512d eps2, __mmask8 live)
{
    return live & ~(_mm512_cmp_pd_mask(r2, rc2, _CMP_GE_OQ) | _mm512_cmp_pd_mask(r2, eps2, _CMP_LT_OQ));
}

/* Pairs q0 .. q0 + cnt - 1 (cnt <= 8) of a particle's run in the walk's
 * planes (pl: x, y, z, r^2, PAIR_PLANE apart; near: j): their separations,
 * 3 j for the gathers, the live lanes and those that interact
 * (pair_interacts: !(r2 >= rc2 || r2 < eps2), a NaN interacts). */
typedef struct { __m512d d0, d1, d2, r2; __m256i j3; __mmask8 live, act; int cnt; } PairLanes8;
static inline __attribute__((target("avx512f"), always_inline))
PairLanes8 pair_lanes_load_avx512(const double *pl, const int *near, int q0, int m, __m512d rc2, __m512d eps2)
{
    PairLanes8 g;
    g.cnt = m - q0 < 8 ? m - q0 : 8;
    g.live = (__mmask8)((1u << g.cnt) - 1);
    g.d0 = _mm512_maskz_loadu_pd(g.live, pl + q0);
    g.d1 = _mm512_maskz_loadu_pd(g.live, pl + PAIR_PLANE + q0);
    g.d2 = _mm512_maskz_loadu_pd(g.live, pl + 2 * PAIR_PLANE + q0);
    g.r2 = _mm512_maskz_loadu_pd(g.live, pl + 3 * PAIR_PLANE + q0);
    g.act = pair_interacts_avx512(g.r2, rc2, eps2, g.live);
    const __m256i j = _mm512_castsi512_si256(_mm512_maskz_loadu_epi32((__mmask16)g.live, near + q0));
    g.j3 = _mm256_add_epi32(j, _mm256_add_epi32(j, j));
    return g;
}

/* A measurement step's sums of eight pairs: their virial terms (t[k], lane l
 * pair l's component k = 9 part + 3 a + b, PairVirial W's order) and energies
 * e, added pair by pair in list order (the lanes set in act) into W and epot
 * as the pair-by-pair evaluators add them: the same bits. */
static inline __attribute__((target("avx512f"), always_inline))
void virial_lanes_add(PairVirial *pv, const __m512d t[PAIR_PARTS * 9], __m512d e, __mmask8 act)
{
    double T[PAIR_PARTS * 9][8], E[8], *W = &pv->W[0][0][0];
    for (int k = 0; k < PAIR_PARTS * 9; k++) _mm512_storeu_pd(T[k], t[k]);
    _mm512_storeu_pd(E, e);
    for (unsigned b = act; b; b &= b - 1) {
        const int l = __builtin_ctz(b);
        for (int k = 0; k < PAIR_PARTS * 9; k++) W[k] += T[k][l];
        pv->epot += E[l];
    }
}
#endif

#endif
