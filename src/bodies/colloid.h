/* colloid.h - spring-model colloids (Mai-Duy et al. 2019, section 4.1, eq. 30;
 * Phan-Thien, Mai-Duy & Khoo 2014): each colloid is p = 6 ordinary DPD
 * particles of one type, each tied by a spring H to a reference site at a
 * vertex of an octahedron (distance d from the centre) carried by a rigid
 * body. The body moves by Newton-Euler (quaternion orientation, isotropic
 * inertia) under the spring reactions of the previous step. */
#ifndef DPD_COLLOID_H
#define DPD_COLLOID_H

#include <stdio.h>
#include <stdint.h>
#include "system.h"
#include "blockavg.h"
#include "forces.h"
#include "io.h"

enum { COLLOID_P = 6 };

/* colloids = { type; per_axis; H; site_distance; mass; inertia; } of the
 * scene, read and checked by the input layer (setup_bodies.c). */
typedef struct {
    int type;                 /* particle type of the constituent particles */
    int per_axis;             /* k: k^3 colloids on a cubic lattice */
    double H;                 /* spring stiffness, eq. 30 */
    double d;                 /* distance of the reference sites from the body centre */
    double mass, inertia;     /* rigid reference body */
} ColloidParams;

typedef struct Colloids {
    ColloidParams p;
    int ncol;                 /* per_axis^3 */
    double body[COLLOID_P][3];   /* site offsets in the body frame */
    double *R, *V, *q, *L;    /* per body: centre, velocity, unit quaternion (w,x,y,z), angular momentum */
    double *F, *T;            /* per body: spring reaction force and torque of the step */
    uint32_t *ids;            /* ncol x p stable particle ids */
    int *index;               /* stable id -> array index */
    int nparticles;
    int record;               /* accumulate statistics */
    Series ext2;              /* mean |r_i - site_i|^2 per sampled step */
    long long nsteps;
} Colloids;

/* per_axis^3 bodies of the parameters p (malloc'd), placed by colloid_place;
 * NULL when out of memory. */
Colloids *colloid_new(const ColloidParams *p);
void colloid_free(Colloids *c);
/* The rigid bodies (centre, velocity, quaternion, angular momentum, last
 * reactions) and the extension record, written or read for the checkpoint. */
void colloid_io(Io *io, Colloids *c);
/* Bodies at the lattice sites (identity orientation, at rest); constituent
 * particles on their reference sites. */
int  colloid_place(Colloids *c, System *s);
/* Reference site k of body b (eq. 30: r_bar). */
void colloid_site(const Colloids *c, int b, int k, const Box *box, double out[3]);
/* Add the spring forces -H (r_i - r_bar_i) to s->f, collect the reactions on
 * the bodies, then advance the bodies by one step with them (Newton-Euler).
 * pv != NULL: add the springs' virial sum (r_i - R_body) F_S (and their
 * energy) to its conservative part, with the bodies at this step's place. */
void colloid_step(Colloids *c, System *s, PairVirial *pv);
/* K += sum_b M (V_b - u_stream)(V_b - u_stream): the bodies' momentum flux. */
void colloid_kinetic(const Colloids *c, const Box *box, double K[9]);
/* Advance body b by dt under force F and torque T (public for tests); the
 * centre is left unwrapped (colloid_step wraps it at the next step). */
void colloid_body_advance(Colloids *c, int b, const double F[3], const double T[3], double dt, const Box *box);
/* Summary rows: spring extension, its equipartition value sqrt(3 kBT / H). */
void colloid_write(const Colloids *c, const System *s, FILE *summary, int nblocks);

#endif
