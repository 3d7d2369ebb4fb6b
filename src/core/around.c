/* around.c - g(q) about centres (eq. 48 of Phan-Thien et al. 2016) and its
 * threshold radius with a jackknife error. */
#include <stdlib.h>
#include <math.h>
#include "around.h"
#include "blockavg.h"

static double shell_measure(int dim, double q0, double q1)
{
    return dim == 3 ? 4.0 / 3.0 * M_PI * (q1 * q1 * q1 - q0 * q0 * q0) : M_PI * (q1 * q1 - q0 * q0);
}

/* g(q) of eq. 48 from histogram sums h over nsamp samples; the radius is the
 * lower edge of the first bin where g reaches the threshold. */
static double radius_from(const AroundHist *a, const double *h, long long nsamp)
{
    for (int b = 0; b < a->bins; b++) {
        const double q0 = b * a->dq;
        const double g = h[b] / (nsamp * a->density * shell_measure(a->dim, q0, q0 + a->dq));
        if (g >= a->threshold) return q0;
    }
    return a->bins * a->dq;
}

int around_write(const AroundHist *a, FILE *out, FILE *summary, const char *name)
{
    const int B = a->nblocks, nb = a->bins;
    double *all = calloc((size_t)nb, sizeof(double)), *loo = calloc((size_t)nb, sizeof(double));
    double *g = calloc((size_t)B + 1, sizeof(double)), *r = calloc((size_t)B + 1, sizeof(double));
    if (!out || !all || !loo || !g || !r) { free(all); free(loo); free(g); free(r); return -1; }
    long long ntot = 0;
    for (int k = 0; k < B; k++) {
        ntot += a->samples[k];
        for (int b = 0; b < nb; b++) all[b] += a->hist[(size_t)k * nb + b];
    }
    fprintf(out, "q\tg\tg_se\n");
    for (int b = 0; b < nb; b++) {
        const double q0 = b * a->dq, sh = shell_measure(a->dim, q0, q0 + a->dq);
        int used = 0;
        for (int k = 0; k < B; k++)
            if (a->samples[k] > 0)
                g[used++] = a->hist[(size_t)k * nb + b] / (a->samples[k] * a->density * sh);
        double mean, se;
        block_stats(g, (size_t)used, used, &mean, &se);
        fprintf(out, "%.6g\t%.6g\t%.3g\n", q0 + 0.5 * a->dq, mean, se);
    }
    /* jackknife over blocks: the crossing is a nonlinear function of g */
    const double r_all = ntot > 0 ? radius_from(a, all, ntot) : NAN;
    int used = 0;
    double rbar = 0.0, var = 0.0;
    for (int k = 0; k < B; k++) {
        if (a->samples[k] == 0 || a->samples[k] == ntot) continue;
        for (int b = 0; b < nb; b++) loo[b] = all[b] - a->hist[(size_t)k * nb + b];
        r[used] = radius_from(a, loo, ntot - a->samples[k]);
        rbar += r[used++];
    }
    if (used > 1) {
        rbar /= used;
        for (int k = 0; k < used; k++) var += (r[k] - rbar) * (r[k] - rbar);
        var *= (used - 1.0) / used;
    }
    /* the radius is a bin edge: a uniform bin adds dq^2 / 12 to the jackknife
     * variance (which is zero when every leave-one-out estimate lands on the
     * same edge) */
    var += a->dq * a->dq / 12.0;
    fprintf(summary, "%s\t%.10g\t%.4g\n", name, r_all, used > 1 ? sqrt(var) : NAN);
    free(all); free(loo); free(g); free(r);
    return ferror(out) ? -1 : 0;
}

