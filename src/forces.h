/* forces.h - DPD pair forces (Groot & Warren 1997; Mai-Duy et al. 2019 eqs 2-7)
 * and body forces. Sums are deterministic for any thread count: the pair list
 * is cut into FORCE_CHUNKS fixed ranges, each accumulates into its own buffer,
 * and the buffers are added in a fixed order. */
#ifndef DPD_FORCES_H
#define DPD_FORCES_H

#include "system.h"
#include "neighbor.h"

#define FORCE_CHUNKS 4

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

/* A chunk writes to its own particles, the next cell layer and the periodic
 * wrap: most of its buffer is never written. Buffers are cleared on a block's
 * first write and summed only over the blocks each chunk touched. */
#define FORCE_BLOCK_SHIFT 8   /* 256 particles per block */

typedef struct {
    double *buf;              /* (FORCE_CHUNKS - 1) x 3 n; chunk 0 sums into f */
    double *tbuf;             /* rotation scenes: (FORCE_CHUNKS - 1) x 3 n torques; chunk 0 sums into torque */
    PairVirial chunk[FORCE_CHUNKS];
    unsigned char *touched;   /* FORCE_CHUNKS x mask_stride: block written by the chunk this step */
    size_t mask_stride;       /* nblk rounded up to a cache line */
    int n, nbins, nblk;
} ForceWork;

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
/* first particle of chunk c (n for c = FORCE_CHUNKS): equal numbers of
 * neighbour-list entries per chunk, cut at particle boundaries */
int forces_chunk_start(const NeighborList *nl, int n, int c);
/* The touched-block mask of chunk c, cleared for a new step. */
unsigned char *forces_chunk_mask(ForceWork *w, int c);
/* f0 = the sum of the chunks' buffers in chunk order (((b0 + b1) + b2) + b3,
 * untouched blocks skipped: the same sums); the same for t0/trest if not NULL. */
void forces_sum_chunks(const ForceWork *w, double *f0, const double *rest, double *t0, const double *trest);

/* Work buffers for the s->n particles of s, and torque buffers if s->rotation
 * (allocated here, never in the force call). Returns 0, or -1 if out of memory. */
int  forces_init(ForceWork *w, const System *s, int nbins);
void forces_free(ForceWork *w);
/* f = pair forces (with v_pred as the velocity) + body forces. If pv != NULL
 * the virial is accumulated into it (zeroed first; pv->Wbin must hold
 * PAIR_PARTS x nbins x 9 doubles when nbins > 0). */
void forces_compute(System *s, const NeighborList *nl, ForceWork *w, PairVirial *pv);
/* Zero a virial, keeping its bins (Wbin, nbins, bin_axis). */
void forces_zero_virial(PairVirial *pv);
/* pv = the sum of the per-chunk virials of the last pair loop, in chunk order. */
void forces_reduce_virial(PairVirial *pv, const ForceWork *w);

/* The three pair force magnitudes along e_ij for one pair (exposed for tests).
 * theta is the N(0,1) variate; inv_sqrt_dt scales the noise (theta/sqrt(dt)). */
void dpd_pair_magnitudes(const PairParams *p, double r, double e_dot_v, double theta,
                         double inv_sqrt_dt, double *fc, double *fd, double *fr);

/* Distribute one pair term t[a][b] over slabs along axis (segment from the image
 * of j at x_i - d to x_i); used by forces and tests. */
void ik_distribute(double *Wbin, int nbins, int axis, double Laxis,
                   double xi_axis, double d_axis, const double t[9]);

/* Body forces of the types (added after the pair forces). */
void forces_body(System *s);

#define PAIR_BATCH 256
/* Pass 1 of the pair kernels, branch free: the list entries k0..k1 of particle
 * i that lie inside the largest cutoff, with their minimum-image separation and
 * r^2 (dd[q] = dx, dy, dz, r2). Returns their number. le: as box_min_image_le. */
static inline __attribute__((always_inline)) int pairs_in_range(const System *s, const NeighborList *nl, int i, int k0, int k1,
                                 int near[PAIR_BATCH], double dd[PAIR_BATCH][4], const int le)
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

#endif
