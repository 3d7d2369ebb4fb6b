/* poiseuille.c - parabolic fit per half of a reverse Poiseuille profile. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <gsl/gsl_multifit.h>
#include "poiseuille.h"

/* Fit v = c0 + c1 z + c2 z^2 on bins [b0, b1); return c2 and its error. */
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
        const double se = v_se[b0 + k] > 0 ? v_se[b0 + k] : 1.0;
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

int poiseuille_fit(const double *pos, const double *v, const double *v_se, const double *dens,
                   int nbins, double L, double g, PoiseuilleFit *out)
{
    memset(out, 0, sizeof *out);
    int half = 0;
    while (half < nbins && pos[half] < 0.5 * L) half++;
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

int poiseuille_command(int argc, char **argv)
{
    const char *path = NULL, *col = "vx";
    double g = 0.0;
    for (int k = 0; k < argc; k++) {
        if (!strcmp(argv[k], "--force") && k + 1 < argc) g = strtod(argv[++k], NULL);
        else if (!strcmp(argv[k], "--column") && k + 1 < argc) col = argv[++k];
        else if (argv[k][0] != '-' && !path) path = argv[k];
        else { fprintf(stderr, "dpd fit-poiseuille: unexpected argument '%s'\n", argv[k]); return 1; }
    }
    if (!path || g == 0.0) { fprintf(stderr, "usage: dpd fit-poiseuille PROFILE.tsv --force G [--column vx]\n"); return 1; }
    FILE *f = fopen(path, "r");
    if (!f) { fprintf(stderr, "dpd fit-poiseuille: cannot open %s\n", path); return 4; }
    char line[8192];
    int cv = -1, cd = -1, nb = 0, cap = 0;
    double *pos = NULL, *v = NULL, *vse = NULL, *dn = NULL;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        if (cv < 0) {   /* header */
            int k = 0;
            for (char *tok = strtok(line, "\t\n"); tok; tok = strtok(NULL, "\t\n"), k++) {
                if (!strcmp(tok, col)) cv = k;
                if (!strcmp(tok, "density")) cd = k;
            }
            if (cv < 0 || cd < 0) { fprintf(stderr, "dpd fit-poiseuille: %s has no column '%s' or 'density'\n", path, col); fclose(f); return 2; }
            continue;
        }
        if (nb == cap) {
            cap = cap ? 2 * cap : 64;
            pos = realloc(pos, cap * sizeof *pos); v = realloc(v, cap * sizeof *v);
            vse = realloc(vse, cap * sizeof *vse); dn = realloc(dn, cap * sizeof *dn);
            if (!pos || !v || !vse || !dn) { fclose(f); return 4; }
        }
        double x[64];
        int k = 0;
        for (char *tok = strtok(line, "\t\n"); tok && k < 64; tok = strtok(NULL, "\t\n")) x[k++] = strtod(tok, NULL);
        if (k <= cv + 1) continue;
        pos[nb] = x[0]; v[nb] = x[cv]; vse[nb] = x[cv + 1]; dn[nb] = x[cd];
        nb++;
    }
    fclose(f);
    int status = 0;
    PoiseuilleFit r;
    const double L = nb > 0 ? pos[0] + pos[nb - 1] : 0.0;   /* bin centres are symmetric in [0, L) */
    if (nb < 8 || poiseuille_fit(pos, v, vse, dn, nb, L, g, &r)) {
        fprintf(stderr, "dpd fit-poiseuille: fit failed (%d bins in %s)\n", nb, path);
        status = 2;
    } else {
        printf("quantity\tvalue\tstderr\n");
        printf("mu_lower\t%.10g\t%.4g\n", r.mu[0], r.mu_se[0]);
        printf("mu_upper\t%.10g\t%.4g\n", r.mu[1], r.mu_se[1]);
        printf("mu\t%.10g\t%.4g\n", r.mu_mean, r.mu_mean_se);
        printf("fit_chi2_per_dof_lower\t%.6g\t0\n", r.chi2_dof[0]);
        printf("fit_chi2_per_dof_upper\t%.6g\t0\n", r.chi2_dof[1]);
        printf("fit_density\t%.8g\t0\n", r.density);
    }
    free(pos); free(v); free(vse); free(dn);
    return status;
}
