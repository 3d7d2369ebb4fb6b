/* random.h - counter-based random numbers (Random123 Philox4x32-10,
 * Salmon et al., SC'11). Key = (seed, stream), counter = (step, min id, max id):
 * the noise of a pair depends only on the step and on the two stable ids,
 * never on thread count, particle order or neighbour-list history. */
#ifndef DPD_RANDOM_H
#define DPD_RANDOM_H

#include <stdint.h>
#include <math.h>
#include <Random123/philox.h>

/* The one registry of stream ids. Never reuse or renumber a stream. */
enum rng_stream {
    STREAM_PAIR_NOISE     = 1,  /* theta_ij of eq. 4 (1st variate of the pair's sequence); in rotation
                                   scenes also xi_ij of Pan 2008 eq. 15 (2nd-4th variates), see
                                   rng_pair_start; counter = (step, min id, max id) */
    STREAM_INIT_POSITION  = 2,  /* initial placement, counter = (particle id, attempt) */
    STREAM_INIT_VELOCITY  = 3,  /* Maxwell-Boltzmann start, counter = (particle id) */
    STREAM_PAIR_NOISE_ROT = 4,  /* retired (never reuse): xi_ij of Pan 2008 eq. 15 until the kernel of
                                   branch rot (issue 6) drew it from STREAM_PAIR_NOISE; the committed
                                   pan-2008 results were made with it */
    STREAM_INIT_SPIN      = 5,  /* Maxwell-Boltzmann angular velocities, counter = (particle id) */
    STREAM_TEST           = 99
};

static inline philox4x32_ctr_t rng_block(uint32_t seed, uint32_t stream,
                                         uint64_t a, uint32_t b, uint32_t c)
{
    philox4x32_ctr_t ctr = {{(uint32_t)a, (uint32_t)(a >> 32), b, c}};
    philox4x32_key_t key = {{seed, stream}};
    return philox4x32(ctr, key);
}

/* Uniform in the open interval (0, 1) from 32 random bits. */
static inline double rng_u01(uint32_t u)
{
    return ((double)u + 0.5) * (1.0 / 4294967296.0);
}

/* Two independent standard normal variates (Box-Muller) from two words. */
static inline void rng_normal2(uint32_t u1, uint32_t u2, double *z1, double *z2)
{
    const double r = sqrt(-2.0 * log(rng_u01(u1)));
    const double phi = 6.283185307179586 * rng_u01(u2);
    *z1 = r * cos(phi);
    *z2 = r * sin(phi);
}

/* A GSL generator whose words are the Philox blocks of one counter: GSL's
 * ziggurat (Marsaglia & Tsang 2000, gsl_ran_gaussian_ziggurat) then turns them
 * into N(0,1) variates. Further blocks, rarely needed, count up in the top
 * byte of the counter's second word (steps stay below 2^56). */
typedef struct {
    philox4x32_ctr_t ctr, out;
    philox4x32_key_t key;
    int used;
} CounterRng;

double rng_counter_normal(CounterRng *c);

static inline __attribute__((always_inline)) void rng_counter_start(CounterRng *c, uint32_t seed, uint32_t stream,
                                     uint64_t a, uint32_t b, uint32_t d)
{
    c->ctr.v[0] = (uint32_t)a; c->ctr.v[1] = (uint32_t)(a >> 32); c->ctr.v[2] = b; c->ctr.v[3] = d;
    c->key.v[0] = seed; c->key.v[1] = stream;
    c->out = philox4x32(c->ctr, c->key);
    c->used = 0;
}

/* The noise sequence of the pair (i, j) at a step, the same for (j, i): its
 * successive rng_counter_normal variates are theta_ij (eq. 4), then, in rotation
 * scenes, xi_ij[0..2] (Pan 2008 eq. 15). One Philox block serves all four unless
 * the ziggurat needs more words (2.8 % of variates, 11 % of 4-variate pairs). */
static inline void rng_pair_start(CounterRng *c, uint32_t seed, uint64_t step, uint32_t id_i, uint32_t id_j)
{
    const uint32_t lo = id_i < id_j ? id_i : id_j, hi = id_i < id_j ? id_j : id_i;
    rng_counter_start(c, seed, STREAM_PAIR_NOISE, step, lo, hi);
}

/* theta_ij = theta_ji ~ N(0,1) for the pair (i, j) at a step (eq. 5). */
static inline __attribute__((always_inline)) double rng_pair_normal(uint32_t seed, uint64_t step, uint32_t id_i, uint32_t id_j)
{
    CounterRng c;
    rng_pair_start(&c, seed, step, id_i, id_j);
    return rng_counter_normal(&c);
}

/* Batches of pairs (the pair driver's PAIR_BATCH): the noise of up to
 * RNG_BATCH pairs at one step, bit for bit what rng_pair_normal and
 * rng_counter_normal give one pair at a time. The Philox blocks of the batch
 * are computed together (vectorised, with the instruction set chosen at run
 * time), and a variate whose word the ziggurat accepts at once (97.2 %) is read
 * from GSL's own strip tables; from the first variate that is not, a pair
 * takes GSL's path (its first block reused, its second drawn for all such
 * pairs of the batch at once). */
#define RNG_BATCH 256

/* GSL's ziggurat strip tables as random.c reads them out of GSL at start, for
 * the batch kernels (random.c, and the backend's: simd.h SimdKernels): per
 * strip i, the word (j << 8 | 0x80 | i) is accepted at once iff j < k[i], and
 * then gives j * w[i]; wedge_a and wedge_b bracket GSL's wedge test (random.c
 * wedge_init). */
typedef struct ZigTables {
    uint32_t k[128];
    double w[128];
    double wedge_a[2][128], wedge_b[2][128];
} ZigTables;
/* The wedge's outcome for a pair not accepted at once */
enum { WEDGE_KEPT = 0, WEDGE_NOT_KEPT = 1, WEDGE_OPEN = 2 };

/* The first block of each pair's noise sequence: counter (step, lo id, hi id). */
void rng_pair_blocks(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                     uint32_t w[4][RNG_BATCH]);
/* nvar (1 ... 4) variates per pair, variate v of pair q into z[v * RNG_BATCH + q]
 * (one plane per variate): theta_ij, then xi_ij[0..2] as in rng_pair_start. */
void rng_pair_normals(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                      int nvar, double *z);
/* The same for ids already ordered, lo[q] <= hi[q] (the pair driver's batches). */
void rng_pair_normals_ordered(uint32_t seed, uint64_t step, int m, const uint32_t *lo, const uint32_t *hi,
                              int nvar, double *z);
/* The ziggurat's first step on one word (GSL's gsl_ran_gaussian_ziggurat for a
 * 32-bit generator): 1 and the variate in *z if it accepts the word at once. */
int rng_ziggurat_fast(uint32_t k, double *z);
/* The heights of GSL's strips that the batch path's wedge test has bracketed
 * to less than width (of 128; strip 0's, 1, is not probed). */
int rng_ziggurat_wedge_brackets(double width);
/* The batch path's wedge test of a word k not accepted at once, U1 from the
 * word u: 0 kept, 1 not kept, 2 left to GSL; -1 where it is not used (no
 * AVX-512). For the tests. */
int rng_ziggurat_wedge(uint32_t k, uint32_t u);

#endif
