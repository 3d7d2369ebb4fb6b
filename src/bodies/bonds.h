/* bonds.h - massless spring colloids in 2D (Phan-Thien, Mai-Duy, Khoo &
 * Duong-Hong 2016, section 4.3, eqs 50-52): each colloid is 3 ordinary DPD
 * particles of one type at the corners of an equilateral triangle of side
 * r_bar, every pair joined by a spring F = -H (r - r_bar) e (eqs 50-51).
 * The springs are conservative: at m = 0 they join the right side f of
 * A v = f (eq. 18); at m > 0 they join the forces. Their virial joins the
 * conservative stress (so the suspension viscosity includes them).
 * Measured: the colloid centres (mean of the 3 particles by minimum image),
 * their MSD and D (eq. 52, time average), the distribution of a type about
 * the centres (eq. 48, the colloid size where it reaches a threshold), the
 * RDF between centres, the rms spring extension and the spring stress. */
#ifndef DPD_BONDS_H
#define DPD_BONDS_H

#include <stdio.h>
#include <stdint.h>
#include "system.h"
#include "blockavg.h"
#include "forces.h"
#include "overdamped.h"
#include "around.h"
#include "io.h"
#include "table.h"

enum { BOND_P = 3 };          /* particles per colloid */

/* colloids2d = { type; count; side; H; every; msd_window; around = {...};
 * rdf = {...}; } of the scene, read and checked by the input layer
 * (setup_bodies.c). */
typedef struct {
    int type;                 /* particle type of the constituent particles */
    int ncol;                 /* colloids ("count") */
    double side;              /* r_bar of eqs 50-51 */
    double H;                 /* spring stiffness */
    int every;                /* sampling interval (production steps) */
    int msd_window;           /* lags of the MSD, in samples */
    AroundParams around;      /* a type about the centres (eq. 48) */
    int rdf_on, rdf_bins;     /* RDF of the centres out to rdf_rmax */
    double rdf_rmax;
} BondParams;

typedef struct Bonds {
    BondParams p;
    uint32_t *ids;            /* ncol x 3 stable ids */
    int *index;               /* stable id -> array index (refreshed per call) */
    int nparticles;
    /* measurements */
    int nblocks;
    long long nsamples_expected;
    Series traj;              /* per sample: ncol x 2 unwrapped centres */
    Series ext2;              /* per sample: mean (r - r_bar)^2 over springs */
    Series spring_wyx;        /* per sample: sum over springs of d_y F_x (virial, yx) */
    double ext_max;           /* largest |r - r_bar| / r_bar seen */
    double around_density;    /* N / A of the around type (bonds_place) */
    double *around_hist;      /* nblocks x bins */
    long long *around_samples;
    double *rdf_hist;         /* nblocks x bins */
    long long *rdf_samples;
} Bonds;

/* The colloids of the parameters p (malloc'd) measured over a run of `steps`
 * production steps in nblocks blocks; NULL when out of memory. */
Bonds *bonds_new(const BondParams *p, int nblocks, long long steps);
void bonds_free(Bonds *b);
/* The centre trajectory, spring records and histograms, written or read for
 * the checkpoint. */
void bonds_io(Io *io, Bonds *b);
/* Centres on a square grid of cells (no overlap), random orientation;
 * the particles of the type, in array order, fill the corners. */
int  bonds_place(Bonds *b, System *s);
/* Spring force on particle a of the pair (a, b): -H (r - r_bar) e_ab (eq. 50),
 * b gets the opposite (eq. 51). d = x_a - x_b. Zero when r < PAIR_R_EPSILON. */
void bonds_spring(double H, double rbar, const double d[3], double F[3]);
/* Add the spring forces to the rows of f of the m = 0 system (eq. 18). */
void bonds_rhs(Bonds *b, const System *s, OdSystem *od);
/* Add the spring forces to s->f; pv != NULL: their virial joins the
 * conservative part (and the slabs). */
void bonds_forces(Bonds *b, System *s, PairVirial *pv);
/* One sample of the centres (every b->every production steps). */
void bonds_sample(Bonds *b, const System *s, long long prod_step);
/* Summary rows and the tables colloid_msd.tsv, colloid_around.tsv, colloid_rdf.tsv
 * (handed to io/: table.h). 0, or -1 (out of memory). */
int  bonds_write(const Bonds *b, const System *s, FILE *summary, Tables *ts);

#endif
