/* pair_style.h - a pair style: the one evaluator of a pair interaction, and
 * what the pair driver (forces.c: the walk and the virial) and the m = 0
 * assembly (overdamped.c) ask of it. The shape is HOOMD-blue's pair
 * evaluators (EvaluatorPairDPDThermo: its parameters per type pair, one
 * evaluation per pair that returns the force, the energy and apart the
 * conservative force the virial needs, inside the one pair loop of the
 * PotentialPair template) written in C: a style's file fills a PairEvaluator
 * of inline functions and hands it to the walk template (pair_walk.h), which
 * is compiled once per style and box, so that no pair goes through a
 * function pointer; what runs once per step, chunk or batch (the walk of a
 * chunk, the vector kernels, the m = 0 terms) is reached through the style's
 * PairStyle, a table of function pointers like CoMD's BasePotential (force,
 * print, destroy), registered by name.
 *
 * Per type pair a style reads PairParams (system.h): the DPD family's a,
 * gamma, sigma, s, gamma_shear, sigma_shear, rc, and coef[] for parameters of
 * its own. Per pair it gets a PairIn and returns a PairOut: the force F_ij on
 * i (-F_ij goes to j), the torque on each of i and j (styles with spins), and
 * on measurement steps the parts the virial records (conservative,
 * dissipative, random: PART_*) and the pair energy.
 *
 * The scalar evaluator is the style's reference. Vector kernels are optional
 * accelerators of a style (PairAccel, by instruction-set level), each tested
 * to give the scalar evaluator's bits; their intrinsics live in the vector
 * backend (src/simd/pair_avx512.c, pan_lanes_x86.c; entry points in
 * pair_avx512.h), and forces.c picks them once per force call
 * (pair_kernels). Adding a style is one file (a PairEvaluator, its walks,
 * a PairStyle) and one registration (pair_styles.c for a built-in one, or
 * pair_style_register): README.md, "Pair styles", has a worked example. */
#ifndef DPD_PAIR_STYLE_H
#define DPD_PAIR_STYLE_H

#include "pair.h"
#include "neighbor.h"

/* One interacting pair as the walk hands it to a style: i's pair with j. */
typedef struct {
    double d[3];          /* r_ij = r_i - r_j, minimum image */
    double r, inv_r;      /* |r_ij| (PAIR_R_EPSILON <= r < rc), 1 / r */
    double e[3];          /* e_ij = r_ij / r (d times inv_r) */
    double dv[3];         /* v_ij = v_i - v_j of the predicted velocities, relative to j's Lees-Edwards image */
    double wsum[3];       /* Omega_i + Omega_j: styles with spins */
    const double *noise;  /* the pair's N(0,1) variates: variate k at noise[k * RNG_BATCH] */
    const double *prep;   /* NULL, or the style's value of this pair prepared with the batch's (PairEvaluator.prepare) */
    double inv_sqrt_dt;   /* 1 / sqrt(dt): a random force is theta / sqrt(dt) (Groot & Warren eq. 4) */
} PairIn;

/* What a style returns for one pair. */
typedef struct {
    double F[3];                  /* F_ij, the force on i; -F_ij on j */
    double tau[3];                /* spins: the torque on i and on j (eq. 1 of Pan et al. 2008: both -(r_ij / 2) x F_ij) */
    /* read on measurement steps (record != 0) only; a style may fill them always
     * (the compiler drops what is not read) or only then: */
    double mag[PAIR_PARTS];       /* central styles: each part's magnitude along e_ij */
    double part[PAIR_PARTS][3];   /* other styles: each part as a vector */
    double energy;                /* the pair energy */
} PairOut;

/* The kernels of one force call (forces.c pair_kernels, the one place they
 * are chosen): NULL where the scalar code runs. */
typedef struct PairKernels PairKernels;
typedef void (*PairLanesFn)(void *lanes, int m, double inv_sqrt_dt, const PairParams *u);
/* A walk batch [i, ie) whose pairs all have the parameters u (one type pair,
 * or several with the same parameters: pair_walk.h batch_one_type), in a 3D
 * box without shear, its separations as planes (pl: x, y, z, r^2, PAIR_PLANE
 * apart), noise as rng_pair_normals' planes; pv: a measurement step (no
 * binned virial; the pairs with a frozen particle recorded as
 * pair_record_frozen_* do). Returns 0 if it does not take u
 * (the walk then goes pair by pair). Each particle closed after its pairs. */
typedef int (*PairOneTypeFn)(const System *s, int i, int ie, const int *near, const double *pl, const double *noise,
                             const int *count, PairAcc *acc, const PairParams *u, PairVirial *pv);
/* The candidate pass of a walk batch on AVX-512 (src/simd/pair_avx512.c): as
 * walk_gather (pair_walk.h), into rows dd or planes pl. */
typedef int (*PairGatherRowsFn)(const System *s, const NeighborList *nl, int i, int i1, int *near, double (*dd)[4],
                                int *count, uint32_t *id_a, uint32_t *id_b, int *np, int ahead);
typedef int (*PairGatherPlanesFn)(const System *s, const NeighborList *nl, int i, int i1, int *near, double *pl,
                                  int *count, uint32_t *id_a, uint32_t *id_b, int *np, int ahead);
struct PairKernels {
    PairGatherRowsFn gather_rows;       /* the candidate pass into rows */
    PairGatherPlanesFn gather_planes;   /* ... into planes, with one_type for batches of one type */
    PairOneTypeFn one_type;
    PairLanesFn lanes;                  /* the style's lanes (PairAccel.lanes) */
    int ahead;                          /* the candidate pass fetches the lists this many particles ahead */
};

/* A style's accelerators at one instruction-set level (NULL: none). */
typedef struct {
    PairOneTypeFn one_type;   /* AVX-512: batches of one type pair */
    PairLanesFn lanes;        /* its own pass over a batch's pairs without the virial (PairEvaluator.batch_lanes) */
} PairAccel;

/* The compile-time side of a style: inline functions that the walk template
 * (pair_walk.h) calls for every pair. A static const PairEvaluator handed to
 * pair_walk is folded by the compiler: its calls are direct and inlined. */
typedef struct {
    int nvar;      /* N(0,1) variates per pair (rng_pair_normals_ordered: 1 or 4) */
    int spins;     /* the style gives torques and reads Omega (s->omega_pred) */
    int central;   /* forces along e_ij: the virial is r_a r_b F / r by part (out.mag), else r_a F_b (out.part) */
    /* one pair; record: the parts and the energy too (a measurement step) */
    void (*pair)(const PairParams *p, const PairIn *in, PairOut *out, int record);
    /* optional: values every pair of a walk batch needs, formed for the batch at
     * once (prep[q] of entry q; e.g. a power of w_C), when needed(s) */
    int (*prepare_needed)(const System *s);
    void (*prepare)(const System *s, int i, int ie, const double (*dd)[4], const int *near, const int *count, double *prep);
    /* optional: the pairs of a walk batch on a step without the virial, lane by
     * lane with the level's lanes (the same bits as pair), each particle closed
     * after its pairs (the last one only if close_last) */
    void (*batch_lanes)(const System *s, int i, int ie, int *near, double (*dd)[4], const double *noise, const int *count,
                        PairAcc *acc, int le, int close_last, PairLanesFn lanes);
} PairEvaluator;

/* The walk of one chunk's particles [i0, i1) (pair_walk.h PAIR_STYLE_WALKS). */
typedef void (*PairWalkFn)(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc, PairVirial *pv,
                           const PairKernels *k);

/* The run-time side of a style, registered by name. */
typedef struct PairStyle {
    const char *name;
    int nvar, spins, central;        /* as its PairEvaluator's */
    /* a built-in style serves the scenes for which this is true (pair_style_of) */
    int (*serves)(const System *s);
    PairWalkFn walk[2];              /* [0] periodic box, [1] Lees-Edwards shear */
    /* the evaluator out of line, every part and the energy (in->prep may be NULL): tests, and code outside the walk */
    void (*one)(const PairParams *p, const PairIn *in, PairOut *out);
    /* the m = 0 assembly (overdamped.c), for central styles whose friction is
     * linear in v_ij: F_ij = (fcr - g e_ij . v_ij) e_ij; fcr, the part that
     * does not depend on the velocities (conservative and random, theta the
     * pair's variate), and g. NULL: the style has no m = 0 form. */
    void (*overdamped)(const PairParams *p, double r, double theta, double inv_sqrt_dt, double *fcr, double *g);
    PairAccel accel[3];              /* by level: SIMD_PORTABLE, SIMD_AVX2, SIMD_AVX512 */
} PairStyle;

/* The style a System uses: s->pair_style if set, else the registered style
 * that serves it (pair_styles.c: rotation scenes Pan et al. 2008, the others
 * standard DPD); NULL if none does. */
const PairStyle *pair_style_of(const System *s);
/* Register a style (before any run); 0, or -1 if its name is taken or the registry is full. */
int pair_style_register(const PairStyle *st);
/* A registered style by name; NULL if none. */
const PairStyle *pair_style_find(const char *name);

/* A pair's virial by part, energy and the force (and torque) on frozen
 * particles, on measurement steps (forces.c; out of line, so that the pair
 * loop compiles alike with and without -DDPD_BARE). Central styles: r_a r_b
 * F / r by part (out->mag) and the total force on a frozen particle (out->F);
 * others: r_a F_b by part (out->part), and on frozen particles the sum of the
 * parts, the drag without the random part and the torque of eq. 1 split into
 * its random part and the rest (out->tau). */
void pair_record_central(PairVirial *pv, const System *s, int i, int j, const PairIn *in, const PairOut *out);
void pair_record_eq1(PairVirial *pv, const System *s, int i, int j, const PairIn *in, const PairOut *out);
/* Their records of the force (and torque) on frozen particles alone, which
 * the one-type kernels (src/simd/pair_avx512.c) call for their pairs with a
 * frozen particle: F on i (central); the separation d, the parts F and tau
 * on i (eq. 1). */
void pair_record_frozen_central(PairVirial *pv, const System *s, int i, int j, const double F[3]);
void pair_record_frozen_eq1(PairVirial *pv, const System *s, int i, int j, const double d[3],
                            const double (*F)[3], const double tau[3]);

#endif
