/* around.h - the distribution of a type in shells about centres (Phan-Thien
 * et al. 2016, eq. 48) and the radius where it first reaches a threshold:
 * measure.around about a point (measure_field.c, the exclusion radius),
 * colloids2d.around about the colloid centres (bonds.c, the colloid radius).
 * One rule for both: block errors for g, a jackknife over the blocks plus the
 * width of a bin for the radius. */
#ifndef DPD_AROUND_H
#define DPD_AROUND_H

#include <stdio.h>

/* The distribution of a type about centres (eq. 48): measure.around about a
 * point, colloids2d.around about the colloid centres. */
typedef struct {
    int on, type;
    int bins;                     /* of width dq, out to qmax */
    double dq, threshold;         /* the radius: first q where g >= threshold */
} AroundParams;

/* Counts of a type in shells about centres (eq. 48), per block of samples:
 * measure.around about a point, colloids2d.around about the colloid centres. */
typedef struct {
    const double *hist;           /* nblocks x bins */
    const long long *samples;     /* per block: samples x centres */
    int nblocks, bins, dim;
    double dq, density, threshold;
} AroundHist;

/* The table q, g, g_se (block errors) into the stream `table` (a file the
 * caller opened, or a table for io/: table.h) and the summary row `name`: the lower edge of the first bin where g reaches the threshold,
 * its error the jackknife over blocks plus the dq^2 / 12 of a bin (nan with
 * fewer than two blocks). The one rule of exclusion_radius and colloid_radius. */
int  around_write(const AroundHist *a, FILE *table, FILE *summary, const char *name);

#endif
