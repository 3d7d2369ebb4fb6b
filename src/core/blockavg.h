/* blockavg.h - time series with block-averaged standard errors
 * (Flyvbjerg & Petersen, J. Chem. Phys. 91, 461, 1989: the error of the mean
 * of correlated data from the scatter of the means of contiguous blocks). */
#ifndef DPD_BLOCKAVG_H
#define DPD_BLOCKAVG_H

#include <stddef.h>

/* The most blocks a run's errors come from: the scene's limit on measure.blocks
 * (setup.c) and the size of the per-block arrays of the writers (blockavg.c,
 * measure.c, tcaf.c), which refuse more (their check sits beside each array). */
#define MAX_BLOCKS 1000

typedef struct {
    double *v;
    size_t n, cap;
    /* the samples the run will push, when known (0: not known): the first
     * growth reserves them all, so that a long run holds its series once and
     * not up to twice over (doubling); untouched pages cost no memory */
    size_t expect;
} Series;

int    series_push(Series *s, double x);
/* Free the values; the expected count stays. */
void   series_free(Series *s);
/* Mean and the standard error from nblocks equal contiguous blocks (the
 * remainder at the start is dropped). With fewer samples than blocks, or more
 * blocks than MAX_BLOCKS, the error is nan. */
void   series_stats(const Series *s, int nblocks, double *mean, double *stderr_);
/* Same for a plain array. */
void   block_stats(const double *v, size_t n, int nblocks, double *mean, double *stderr_);

#endif
