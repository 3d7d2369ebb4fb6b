/* forces.h - the pair driver: the pair forces of the scene's pair style
 * (pair_style.h; standard DPD: Groot & Warren 1997, Mai-Duy et al. 2019 eqs
 * 2-7, pair_dpd.c; rotating particles: Pan et al. 2008 eqs 1 and 13-15,
 * pair_pan2008.c) and body forces.
 * Sums are deterministic for any thread count: the pair list is cut into
 * FORCE_CHUNKS fixed ranges, each accumulates into its own buffer, and the
 * buffers are added in a fixed order. */
#ifndef DPD_FORCES_H
#define DPD_FORCES_H

#include "pair.h"

#define FORCE_CHUNKS 4

typedef struct {
    double *buf;              /* (FORCE_CHUNKS - 1) x 3 n; chunk 0 sums into f */
    double *tbuf;             /* rotation scenes: (FORCE_CHUNKS - 1) x 3 n torques; chunk 0 sums into torque */
    PairVirial chunk[FORCE_CHUNKS];
    unsigned char *touched;   /* FORCE_CHUNKS x mask_stride: block written by the chunk this step */
    size_t mask_stride;       /* nblk rounded up to a cache line */
    int n, nbins, nblk;
} ForceWork;

/* first particle of chunk c (n for c = FORCE_CHUNKS): equal numbers of
 * neighbour-list entries per chunk, cut at particle boundaries */
int forces_chunk_start(const NeighborList *nl, int n, int c);
/* The touched-block mask of chunk c, cleared for a new step. */
unsigned char *forces_chunk_mask(ForceWork *w, int c);
/* f0 = the sum of the chunks' buffers in chunk order (((b0 + b1) + b2) + b3,
 * untouched blocks skipped: the same sums); the same for t0/trest if not NULL. */
void forces_sum_chunks(const ForceWork *w, double *f0, const double *rest, double *t0, const double *trest);

/* Work buffers for the s->n particles of s, and torque buffers if its pair
 * style has spins (allocated here, never in the force call). Returns 0, or -1
 * if out of memory or no pair style serves s (pair_style_of). */
int  forces_init(ForceWork *w, const System *s, int nbins);
void forces_free(ForceWork *w);
/* f = pair forces (with v_pred as the velocity; a style with spins: and the
 * torques, with omega_pred) + body forces. If pv != NULL the virial is
 * accumulated into it (zeroed first; pv->Wbin must hold PAIR_PARTS x nbins x 9
 * doubles when nbins > 0). */
void forces_compute(System *s, const NeighborList *nl, ForceWork *w, PairVirial *pv);
/* Zero a virial, keeping its bins (Wbin, nbins, bin_axis). */
void forces_zero_virial(PairVirial *pv);
/* pv = the sum of the per-chunk virials of the last pair loop, in chunk order. */
void forces_reduce_virial(PairVirial *pv, const ForceWork *w);

/* Body forces of the types (added after the pair forces). */
void forces_body(System *s);

/* Every interacting listed pair, in list order on the calling thread: i, j,
 * d = r_i - r_j (minimum image), r^2 and the x velocity of j's nearest
 * Lees-Edwards image relative to j (0 without shear). For the m = 0 assembly. */
typedef void (*PairVisitor)(void *ctx, int i, int j, const double d[3], double r2, double image_vx);
void pair_visit(const System *s, const NeighborList *nl, PairVisitor visit, void *ctx);

#endif
