/* blockavg.c - block averaging. */
#include <stdlib.h>
#include <math.h>
#include <gsl/gsl_statistics_double.h>
#include "blockavg.h"

int series_push(Series *s, double x)
{
    if (s->n == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 256;
        if (cap < s->expect) cap = s->expect;
        double *p = realloc(s->v, cap * sizeof *p);
        if (!p) return -1;
        s->v = p;
        s->cap = cap;
    }
    s->v[s->n++] = x;
    return 0;
}

void series_free(Series *s)
{
    free(s->v);
    s->v = NULL;
    s->n = s->cap = 0;
}

void block_stats(const double *v, size_t n, int nblocks, double *mean, double *stderr_)
{
    *mean = n ? gsl_stats_mean(v, 1, n) : NAN;
    *stderr_ = NAN;
    if (nblocks < 2 || n < (size_t)nblocks) return;
    const size_t len = n / (size_t)nblocks, skip = n - len * (size_t)nblocks;
    double bm[MAX_BLOCKS];
    if (nblocks > MAX_BLOCKS) return;   /* more than bm holds */
    for (int b = 0; b < nblocks; b++) bm[b] = gsl_stats_mean(v + skip + (size_t)b * len, 1, len);
    *mean = gsl_stats_mean(bm, 1, (size_t)nblocks);
    *stderr_ = gsl_stats_sd(bm, 1, (size_t)nblocks) / sqrt((double)nblocks);
}

void series_stats(const Series *s, int nblocks, double *mean, double *stderr_)
{
    block_stats(s->v, s->n, nblocks, mean, stderr_);
}
