/* measure_field.h - measurements about fixed bodies and on grids:
 *  - the distribution of a type about a fixed point (Phan-Thien et al. 2016,
 *    eq. 48) and the exclusion radius where it first reaches a threshold;
 *  - a number-density map on a grid over x and y, with the number-weighted
 *    mean velocity of each bin (its divergence measures compressibility);
 *  - the radial conservative force field of a body on a grid (their Fig. 6a);
 *  - always: the mean velocity of each mobile type, and the torque that the
 *    mobile particles exert on each frozen type about its centroid (in
 *    rotation scenes measure.c reports the eq. 1 torque instead).
 * Errors: block standard errors; the exclusion radius, a threshold crossing,
 * gets a jackknife error over the blocks plus the width of a bin (around_write). */
#ifndef DPD_MEASURE_FIELD_H
#define DPD_MEASURE_FIELD_H

#include <stdio.h>
#include "system.h"
#include "blockavg.h"
#include "io.h"
#include "around.h"

/* measure.around, measure.density_map, measure.force_map of the scene, read
 * and checked by the input layer (setup_measure.c). */
typedef struct {
    AroundParams around;          /* around = { centre; type; dq; qmax; threshold; } */
    double around_centre[3];
    int map_on, map_type, map_bins[2];   /* density_map = { type; bins = [nx, ny]; } */
    int fmap_on, fmap_body, fmap_probe, fmap_bins[2];   /* force_map = { body; probe; bins; } */
} FieldParams;

typedef struct FieldMeasure {
    FieldParams p;
    int nblocks;
    double *around_hist;          /* nblocks x bins: counts */
    long long *around_samples;    /* per block */
    double around_density;        /* N / A of the type (eq. 48) */
    double *map_hist;             /* per bin: count, sum vx, sum vy */
    long long map_samples;
    /* always */
    Series mean_v[DPD_MAX_TYPES][3];
    Series torque[DPD_MAX_TYPES][3];
    double centroid[DPD_MAX_TYPES][3];
} FieldMeasure;

/* The measurements p asks for, with nblocks blocks; -1 out of memory. */
int  field_init(FieldMeasure *f, const FieldParams *p, const System *s, int nblocks);
void field_free(FieldMeasure *f);
/* One sample; s->f must hold this step's pair forces (for the torques). */
void field_sample(FieldMeasure *f, const System *s, int block);
int  field_write(const FieldMeasure *f, const System *s, FILE *summary, const char *dir);
/* The accumulators, written or read for the checkpoint. */
void field_io(Io *io, FieldMeasure *f);

#endif
