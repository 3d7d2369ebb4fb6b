/* pair.h - what every pair kernel shares, in one copy: the r -> 0 guard, the
 * weight functions of eqs 5-7 (Mai-Duy et al. 2019; Groot & Warren 1997), the
 * batch of listed pairs inside the cutoff, the per-chunk accumulator a kernel
 * writes its forces and torques into, and the virial by part.
 *
 * The pair driver (forces.c) walks the neighbour list of a chunk of particles
 * a batch of PAIR_BATCH entries at a time (pair_walk.h) and hands each pair to
 * the evaluator of the scene's pair style (pair_style.h; pair_dpd.c: standard
 * DPD, pair_pan2008.c: rotating particles), the way HOOMD-blue's PotentialPair
 * hands pairs to an Evaluator. The m = 0 assembly (overdamped.c) visits the
 * same pairs through pair_visit (forces.h) and takes each pair's terms from
 * the style. */
#ifndef DPD_PAIR_H
#define DPD_PAIR_H

#include <math.h>
#include "system.h"
#include "neighbor.h"
#include "weight_pow.h"
#include "simd.h"

/* the pair table's entries a shift apart (system.h PairParams.coef) */
_Static_assert(sizeof(PairParams) == 128, "PairParams is 128 bytes");

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

/* Some type pair of the scene has a general weight exponent (weight_general) */
static inline int scene_weights_general(const System *s)
{
    for (int a = 0; a < s->ntypes; a++)
        for (int b = 0; b < s->ntypes; b++)
            if (s->pair[a][b].active && weight_general(s->pair[a][b].s)) return 1;
    return 0;
}

/* w_R (eq. 7) of every pair of a walk batch [i, ie) (separations and r^2 in
 * dd, count[p - i] entries of particle p) that interacts with a general
 * exponent, all at once (weight_pow_batch); other entries get a placeholder.
 * w_C = 1 - r/rc as the evaluators form it, so the same bits as
 * random_weight one pair at a time. The styles of the DPD family prepare
 * their batches with it (PairEvaluator.prepare). */
static inline void pair_random_weights(const System *s, int i, int ie, const double (*dd)[4], const int *near,
                                       const int *count, double *wr)
{
    double w[PAIR_BATCH + 8], e[PAIR_BATCH + 8];
    int k = 0;
    for (int p = i; p < ie; p++) {
        const int ti = s->type[p];
        for (int q = 0; q < count[p - i]; q++, k++) {
            const PairParams *pp = &s->pair[ti][s->type[near[k]]];
            const double r2k = dd[k][3];
            const int use = weight_general(pp->s) && pair_interacts(pp, r2k);
            w[k] = use ? 1.0 - sqrt(r2k) / pp->rc : 1.0;
            e[k] = use ? 0.5 * pp->s : 1.0;
        }
    }
    for (int q = k; q < k + 8; q++) w[q] = e[q] = 1.0;
    weight_pow_batch(w, e, wr, k);
}

#endif
