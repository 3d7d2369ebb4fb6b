/* system.h - particles, particle types and per-type-pair DPD parameters.
 *
 * Units: every quantity is in DPD reduced units (mass m, length rc of the
 * scene, energy kBT); the code never converts units.
 * Vectors are stored as 3 doubles even in 2D, where z (and L[2]) is unused. */
#ifndef DPD_SYSTEM_H
#define DPD_SYSTEM_H

#include <stdint.h>
#include <stddef.h>
#include "box.h"

#define DPD_MAX_TYPES 8

typedef struct {
    char name[32];
    double mass;
    int frozen;               /* frozen particles move at wall_velocity, feel no force */
    double wall_velocity[3];
    double body_force[3];     /* per particle */
    int body_force_flip_axis; /* -1: none; else sign flips in the upper half along this axis */
    double inertia;           /* moment of inertia (rotation scenes only, src/dynamics/rotation.c) */
    double spin[3];           /* prescribed angular velocity of frozen particles (rotation scenes) */
    int hold_velocity;        /* 1: the type's mean velocity is reset to held_velocity every step */
    double held_velocity[3];
} ParticleType;

typedef struct {
    int active;               /* 0: the pair does not interact at all */
    double a;                 /* repulsion, eq. 2 */
    double gamma;             /* dissipation, eq. 3 */
    double sigma;             /* noise amplitude, eq. 7: sqrt(2 gamma kBT), derived */
    double s;                 /* w_D = (1 - r/rc)^s, eq. 6 */
    double gamma_shear;       /* Pan et al. 2008 gamma^S (rotation scenes; gamma is gamma^C) */
    double sigma_shear;       /* sqrt(2 gamma^S kBT), derived */
    double rc;
    double rc2;               /* rc^2, derived */
    double coef[7];           /* parameters of a pair style of its own (src/pair/pair_style.h); 7: the
                               * struct is 128 bytes, an entry of the pair table a shift away */
} PairParams;

typedef struct {
    Box box;
    int n;                    /* number of particles */
    double *x, *v, *f;        /* position, velocity, force: 3 n each */
    double *v_pred;           /* Groot-Warren predicted velocity: 3 n */
    int32_t *img;             /* periodic image counters (unwrapped positions): 3 n */
    uint32_t *id;             /* stable particle id, 0..n-1 */
    uint8_t *type;
    int ntypes;
    ParticleType types[DPD_MAX_TYPES];
    PairParams pair[DPD_MAX_TYPES][DPD_MAX_TYPES];
    /* derived by system_set_pair, never set elsewhere: the first type pair (a DPD_MAX_TYPES + b, row
     * by row) whose parameters are the same bits as pair[ti][tj]'s, so that a walk batch mixing
     * types whose pairs all have one class goes to a one-type kernel (pair_walk.h batch_one_type) */
    uint8_t pair_class[DPD_MAX_TYPES][DPD_MAX_TYPES];
    double rc_max;
    double kBT;
    double dt;
    double lambda;            /* Groot-Warren velocity prediction, lambda = 0.5: velocity Verlet */
    uint64_t step;
    double time;
    uint32_t seed;
    int has_body_force;
    int has_held_velocity;    /* some type holds its mean velocity (integrator.c) */
    int n_frozen;
    int nonfinite;            /* particles whose position or velocity the last step made non-finite
                               * (counted by the integrator's particle loops; the run then stops) */
    /* rotational degrees of freedom (Pan et al. 2008), only when the scene asks:
     * NULL otherwise. Angular velocity, its Groot-Warren prediction, torque: 3 n each */
    int rotation;
    double *omega, *omega_pred, *torque;
    /* the pair style (src/pair/pair_style.h); NULL: the registered style that
     * serves the scene (rotation scenes Pan et al. 2008, else standard DPD) */
    const struct PairStyle *pair_style;
} System;

int  system_alloc(System *s, int n);
void system_free(System *s);
/* Reorder all per-particle arrays so that particle perm[k] becomes particle k.
 * *spare: a buffer of at least 3 n doubles, which trades places with the
 * 3-vector arrays (s->x and the others may point elsewhere afterwards, and
 * *spare to what was one of them). */
void system_permute(System *s, const int *perm, double **spare);
/* Count of mobile particles and degrees of freedom used for the temperature. */
int  system_dof(const System *s);
double system_kinetic_temperature(const System *s);
void system_set_pair(System *s, int ti, int tj, PairParams p);

#endif
