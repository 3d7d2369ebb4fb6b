/* poiseuille.c - parabolic fit per half of a reverse Poiseuille profile. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_statistics_double.h>
#include "poiseuille.h"

/* Fit v = c0 + c1 z + c2 z^2 on bins [b0, b1); return c2 and its error
 * (v_se NULL: equal weights, error and chi2 not meaningful). */
static int fit_half(const double *pos, const double *v, const double *v_se, int b0, int b1,
                    double *c2, double *c2_se, double *chi2_dof)
{
    const int m = b1 - b0;
    if (m < 4) return -1;
    gsl_matrix *X = gsl_matrix_alloc(m, 3), *cov = gsl_matrix_alloc(3, 3);
    gsl_vector *y = gsl_vector_alloc(m), *w = gsl_vector_alloc(m), *c = gsl_vector_alloc(3);
    gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc(m, 3);
    for (int k = 0; k < m; k++) {
        const double z = pos[b0 + k];
        gsl_matrix_set(X, k, 0, 1.0);
        gsl_matrix_set(X, k, 1, z);
        gsl_matrix_set(X, k, 2, z * z);
        gsl_vector_set(y, k, v[b0 + k]);
        const double se = v_se && v_se[b0 + k] > 0 ? v_se[b0 + k] : 1.0;
        gsl_vector_set(w, k, 1.0 / (se * se));
    }
    double chi2;
    int rc = gsl_multifit_wlinear(X, w, y, c, cov, &chi2, ws);
    *c2 = gsl_vector_get(c, 2);
    *chi2_dof = chi2 / (m - 3);
    /* errors from the bin errors, inflated when the fit is worse than they say */
    *c2_se = sqrt(gsl_matrix_get(cov, 2, 2)) * (*chi2_dof > 1.0 ? sqrt(*chi2_dof) : 1.0);
    gsl_multifit_linear_free(ws);
    gsl_matrix_free(X); gsl_matrix_free(cov);
    gsl_vector_free(y); gsl_vector_free(w); gsl_vector_free(c);
    return rc;
}

static int first_upper_bin(const double *pos, int nbins, double L)
{
    int half = 0;
    while (half < nbins && pos[half] < 0.5 * L) half++;
    return half;
}

int poiseuille_fit(const double *pos, const double *v, const double *v_se, const double *dens,
                   int nbins, double L, double g, PoiseuilleFit *out)
{
    memset(out, 0, sizeof *out);
    const int half = first_upper_bin(pos, nbins, L);
    double n = 0.0;
    for (int b = 0; b < nbins; b++) n += dens[b];
    n /= nbins;
    out->density = n;
    for (int h = 0; h < 2; h++) {
        double c2, c2_se;
        if (fit_half(pos, v, v_se, h ? half : 0, h ? nbins : half, &c2, &c2_se, &out->chi2_dof[h])) return -1;
        /* lower half: v'' = -n g / mu; upper half: +n g / mu */
        const double sgn = h ? 1.0 : -1.0;
        out->mu[h] = sgn * n * g / (2.0 * c2);
        out->mu_se[h] = fabs(out->mu[h]) * c2_se / fabs(c2);
    }
    out->mu_mean = 0.5 * (out->mu[0] + out->mu[1]);
    out->mu_mean_se = 0.5 * sqrt(out->mu_se[0] * out->mu_se[0] + out->mu_se[1] * out->mu_se[1]);
    return 0;
}

int poiseuille_fit_blocks(const double *pos, const double *v, const double *dens, int nbins, int nblocks,
                          double g, PoiseuilleFit *out)
{
    memset(out, 0, sizeof *out);
    if (nblocks < 2 || nbins < 8) return -1;
    const double L = pos[0] + pos[nbins - 1];   /* bin centres are symmetric in [0, L) */
    const int half = first_upper_bin(pos, nbins, L);
    double *c2 = malloc(3 * (size_t)nblocks * sizeof *c2), n = 0.0;
    if (!c2) return -1;
    for (size_t k = 0; k < (size_t)nblocks * (size_t)nbins; k++) n += dens[k];
    n /= (double)nblocks * nbins;
    out->density = n;
    for (int b = 0; b < nblocks; b++) {
        const double *vb = v + (size_t)b * nbins;
        double se, chi2;
        if (fit_half(pos, vb, NULL, 0, half, &c2[b], &se, &chi2) ||
            fit_half(pos, vb, NULL, half, nbins, &c2[nblocks + b], &se, &chi2)) { free(c2); return -1; }
        c2[2 * nblocks + b] = 0.5 * (c2[nblocks + b] - c2[b]);   /* mean curvature magnitude of the halves */
    }
    /* lower half: v'' = 2 c2 = -n g / mu; upper half: +n g / mu; the blocks'
     * curvatures are averaged first (mu is not linear in them) */
    for (int h = 0; h < 3; h++) {
        const double *c = c2 + (size_t)h * nblocks;
        const double m = gsl_stats_mean(c, 1, (size_t)nblocks);
        const double se = gsl_stats_sd_m(c, 1, (size_t)nblocks, m) / sqrt((double)nblocks);
        const double mu = (h == 0 ? -1.0 : 1.0) * n * g / (2.0 * m), mu_se = fabs(mu) * se / fabs(m);
        if (h < 2) { out->mu[h] = mu; out->mu_se[h] = mu_se; out->chi2_dof[h] = NAN; }
        else { out->mu_mean = mu; out->mu_mean_se = mu_se; }
    }
    free(c2);
    return 0;
}

static int grow(double **a, int cap)
{
    double *p = realloc(*a, (size_t)cap * sizeof *p);
    if (!p) return -1;
    *a = p;
    return 0;
}

static void print_fit(const PoiseuilleFit *r, int blocks)
{
    printf("quantity\tvalue\tstderr\n");
    printf("mu_lower\t%.10g\t%.4g\n", r->mu[0], r->mu_se[0]);
    printf("mu_upper\t%.10g\t%.4g\n", r->mu[1], r->mu_se[1]);
    printf("mu\t%.10g\t%.4g\n", r->mu_mean, r->mu_mean_se);
    if (!blocks) {
        printf("fit_chi2_per_dof_lower\t%.6g\t0\n", r->chi2_dof[0]);
        printf("fit_chi2_per_dof_upper\t%.6g\t0\n", r->chi2_dof[1]);
    } else printf("fit_blocks\t%d\t0\n", blocks);
    printf("fit_density\t%.8g\t0\n", r->density);
}

int poiseuille_command(int argc, char **argv)
{
    const char *path = NULL, *col = "vx";
    double g = 0.0;
    int blocks = 0;
    for (int k = 0; k < argc; k++) {
        if (!strcmp(argv[k], "--force") && k + 1 < argc) g = strtod(argv[++k], NULL);
        else if (!strcmp(argv[k], "--column") && k + 1 < argc) col = argv[++k];
        else if (!strcmp(argv[k], "--blocks")) blocks = 1;
        else if (argv[k][0] != '-' && !path) path = argv[k];
        else { fprintf(stderr, "dpd fit-poiseuille: unexpected argument '%s'\n", argv[k]); return 1; }
    }
    if (!path || g == 0.0) {
        fprintf(stderr, "usage: dpd fit-poiseuille PROFILE.tsv --force G [--column vx]\n"
                        "       dpd fit-poiseuille PROFILE_BLOCKS.tsv --blocks --force G [--column vx]\n");
        return 1;
    }
    FILE *f = fopen(path, "r");
    if (!f) { fprintf(stderr, "dpd fit-poiseuille: cannot open %s\n", path); return 4; }
    char line[8192];
    int cpos = -1, cv = -1, cd = -1, cb = -1, header = 0, n = 0, cap = 0;
    double *pos = NULL, *v = NULL, *vse = NULL, *dn = NULL, *blk = NULL;
    int status = 0, reported = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        if (!header) {   /* columns by name */
            header = 1;
            int k = 0;
            for (char *tok = strtok(line, "\t\n"); tok; tok = strtok(NULL, "\t\n"), k++) {
                if (!strcmp(tok, col)) cv = k;
                if (!strcmp(tok, "density")) cd = k;
                if (!strcmp(tok, "pos")) cpos = k;
                if (!strcmp(tok, "block")) cb = k;
            }
            if (cv < 0 || cd < 0 || cpos < 0 || (blocks && cb < 0)) {
                fprintf(stderr, "dpd fit-poiseuille: %s has no column '%s', 'density', 'pos'%s\n", path, col,
                        blocks ? " or 'block' (--blocks reads profile_blocks.tsv)" : "");
                status = 2;
                reported = 1;
                break;
            }
            continue;
        }
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            if (grow(&pos, cap) || grow(&v, cap) || grow(&vse, cap) || grow(&dn, cap) || grow(&blk, cap)) {
                fprintf(stderr, "dpd fit-poiseuille: out of memory reading %s\n", path);
                status = 4;
                break;
            }
        }
        double x[64];
        int k = 0;
        for (char *tok = strtok(line, "\t\n"); tok && k < 64; tok = strtok(NULL, "\t\n")) x[k++] = strtod(tok, NULL);
        if (k <= cv || k <= cd || k <= cpos) continue;
        pos[n] = x[cpos]; v[n] = x[cv]; vse[n] = k > cv + 1 ? x[cv + 1] : 0.0; dn[n] = x[cd];
        blk[n] = cb >= 0 ? x[cb] : 0.0;
        n++;
    }
    fclose(f);
    PoiseuilleFit r;
    if (status == 0 && !blocks) {
        const double L = n > 0 ? pos[0] + pos[n - 1] : 0.0;   /* bin centres are symmetric in [0, L) */
        if (n < 8 || poiseuille_fit(pos, v, vse, dn, n, L, g, &r)) status = 2;
        else print_fit(&r, 0);
    } else if (status == 0) {
        /* blocks are contiguous runs of rows with the same bins */
        int nbins = 0;
        while (nbins < n && blk[nbins] == blk[0]) nbins++;
        const int nb = nbins > 0 ? n / nbins : 0;
        int ok = nb >= 2 && nb * nbins == n;
        for (int i = 0; ok && i < n; i++) ok = pos[i] == pos[i % nbins] && blk[i] == blk[i - i % nbins] && isfinite(v[i]);
        if (!ok) {
            fprintf(stderr, "dpd fit-poiseuille: %s: need at least 2 blocks of the same bins, every bin sampled\n", path);
            status = 2;
            reported = 1;
        } else if (poiseuille_fit_blocks(pos, v, dn, nbins, nb, g, &r)) status = 2;
        else print_fit(&r, nb);
    }
    if (status == 2 && !reported) fprintf(stderr, "dpd fit-poiseuille: fit failed (%d rows in %s)\n", n, path);
    free(pos); free(v); free(vse); free(dn); free(blk);
    return status;
}
