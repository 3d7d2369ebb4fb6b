/* measure.h - measurements switched on by the scene: thermodynamics and the
 * global pressure tensor, binned profiles with the Irving-Kirkwood stress,
 * the radial distribution function and the mean-square displacement.
 * Errors are standard errors of the mean over contiguous blocks. */
#ifndef DPD_MEASURE_H
#define DPD_MEASURE_H

#include <stdio.h>
#include "system.h"
#include "neighbor.h"
#include "forces.h"
#include "blockavg.h"
#include "measure_field.h"
#include "tcaf.h"

enum { STRESS_KINETIC = 0, STRESS_CONSERVATIVE, STRESS_DISSIPATIVE, STRESS_RANDOM, STRESS_PARTS };

typedef struct {
    int every;                /* sampling interval (steps) */
    int nblocks;
    long long nsamples_expected;
    long long prod_steps;     /* production steps of the run */
    /* thermo */
    Series temperature, pressure, epot;
    Series P[STRESS_PARTS][9];   /* global pressure tensor by part (P = -T) */
    /* profile */
    int prof_on, prof_axis, prof_bins;
    double *prof;             /* nblocks x bins x PROF_Q sums */
    long long *prof_samples;  /* per block */
    /* rdf */
    int rdf_on, rdf_every, rdf_bins, rdf_types[2];
    double rdf_rmax;
    double *rdf_hist;         /* nblocks x bins */
    long long *rdf_samples;   /* per block */
    double rdf_norm_pairs;    /* (ordered) pair density normalisation */
    /* msd */
    int msd_on, msd_every, msd_window, msd_origin_every, msd_type; /* type -1: all mobile */
    int msd_nlags, msd_norig;
    double *msd_origin_pos;   /* norig x 3 n (by id) */
    long long *msd_origin_step;
    double *msd_curve;        /* norig x groups x nlags: curves of the active origins */
    Series msd_done;          /* completed curves, groups x nlags values each, flattened */
    long long msd_ndone;
    int msd_count;            /* particles in the selection */
    /* The errors come from groups of particles, not from blocks of time origins:
     * the origins of one window share most of their trajectory, the particles
     * move (nearly) independently. Group of a particle: its rank by id. */
    int msd_groups;
    int *msd_group_of_id;     /* n: group, or -1 outside the selection */
    int *msd_group_n;         /* particles per group */
    double *msd_gsum;         /* groups: scratch sums of one sample */
    /* profile per block (time-resolved start-up profiles) */
    int prof_per_block;
    double *prof_tsum;        /* per block: sum of sample times */
    /* centre of mass of the mobile particles (Phan-Thien et al. 2016, eqs 32-33) */
    int com_on;
    Series com_v[3], com_r[3];  /* number-weighted mean velocity; unwrapped centre minus its start */
    double com_r0[3];
    long long n_mobile;
    /* frozen body forces */
    Series frozen_force[DPD_MAX_TYPES][3];
    FieldParams field_par;    /* measure.around, density_map, force_map (setup_measure.c) */
    FieldMeasure field;       /* about points, on grids, torques, mean velocities */
    int tcaf_on;              /* measure.tcaf given: tcaf_par holds it */
    TcafParams tcaf_par;
    Tcaf tcaf;                /* transverse current autocorrelation (tcaf.h) */
    const struct Colloids *colloids;   /* rigid bodies whose momentum flux joins the stress, or NULL */
    Series frozen_torque[DPD_MAX_TYPES][3], rot_temperature;   /* rotation scenes */
    Series frozen_drag[DPD_MAX_TYPES][3], frozen_torque_random[DPD_MAX_TYPES][3];
    int n;
} Measure;

/* per bin: count, mass, momentum (3), sum m v v (9), pair virial (9 per part),
 * sum v (3, number-weighted: the velocity of massless particles) */
#define PROF_Q (2 + 3 + 9 + 9 * PAIR_PARTS + 3)
#define PROF_SUMV (2 + 3 + 9 + 9 * PAIR_PARTS)

int  measure_init(Measure *m, const System *s);
void measure_free(Measure *m);
/* Does the force call of this step need the virial? */
int  measure_wants_virial(const Measure *m, long long step);
/* Sample after the step is complete; pv holds the virial of this step's forces. */
void measure_sample(Measure *m, const System *s, const NeighborList *nl, const PairVirial *pv,
                    long long prod_step);
/* The accumulators (with the field measurements, not the TCAF), written or
 * read for the checkpoint; measure_rotation_io: those of rotation scenes. */
void measure_io(Io *io, Measure *m);
void measure_rotation_io(Io *io, Measure *m);
/* Write summary rows and the plot tables into dir. */
int  measure_write(const Measure *m, const System *s, FILE *summary, const char *dir);

#endif
