/* linefit.c - `dpd fit-line TABLE --x COL --y COL --se COL --range LO:HI`.
 * Fits y = c0 + c1 x to the rows with LO <= x <= HI, weights 1/se^2
 * (gsl_fit_wlinear). The covariance is scaled by chi^2/dof when that exceeds 1
 * (scatter larger than the stated errors, e.g. correlated bins). Prints
 * quantity/value/stderr rows: slope, value at the centre of the range, r2
 * (unweighted coefficient of determination), chi2_dof, points. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <gsl/gsl_fit.h>
#include "linefit.h"

#define MAX_COLS 64

static int column_of(char *header, const char *name)
{
    int c = 0;
    for (char *tok = strtok(header, "\t\n"); tok; tok = strtok(NULL, "\t\n"), c++)
        if (!strcmp(tok, name)) return c;
    return -1;
}

/* *p grown to cap doubles; on failure *p keeps its old block (the caller frees it) */
static int grow(double **p, int cap)
{
    double *q = realloc(*p, (size_t)cap * sizeof *q);
    if (!q) return -1;
    *p = q;
    return 0;
}

int cmd_fit_line(int argc, char **argv)
{
    const char *file = NULL, *xn = NULL, *yn = NULL, *sn = NULL;
    double lo = -INFINITY, hi = INFINITY;
    int origin = 0;           /* --origin: y = c1 x through (0, 0) (gsl_fit_wmul) */
    for (int k = 0; k < argc; k++) {
        const char *o = argv[k];
        if (o[0] != '-') { file = o; continue; }
        if (!strcmp(o, "--origin")) { origin = 1; continue; }
        if (k + 1 >= argc) { fprintf(stderr, "dpd fit-line: %s needs a value\n", o); return 1; }
        const char *v = argv[++k];
        if (!strcmp(o, "--x")) xn = v;
        else if (!strcmp(o, "--y")) yn = v;
        else if (!strcmp(o, "--se")) sn = v;
        else if (!strcmp(o, "--range")) {
            if (sscanf(v, "%lf:%lf", &lo, &hi) != 2 || !(lo < hi)) {
                fprintf(stderr, "dpd fit-line: --range '%s': expected LO:HI with LO < HI\n", v);
                return 1;
            }
        } else { fprintf(stderr, "dpd fit-line: unknown option %s\n", o); return 1; }
    }
    if (!file || !xn || !yn || !sn) {
        fprintf(stderr, "usage: dpd fit-line TABLE --x COL --y COL --se COL [--range LO:HI]\n");
        return 1;
    }
    FILE *f = fopen(file, "r");
    if (!f) { fprintf(stderr, "dpd fit-line: cannot open '%s'\n", file); return 4; }
    char line[8192];
    int cx = -1, cy = -1, cs = -1, n = 0, cap = 0, lineno = 0;
    double *x = NULL, *y = NULL, *w = NULL;
    int status = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (cx < 0) {
            char h1[8192], h2[8192], h3[8192];
            strcpy(h1, line); strcpy(h2, line); strcpy(h3, line);
            cx = column_of(h1, xn); cy = column_of(h2, yn); cs = column_of(h3, sn);
            if (cx < 0 || cy < 0 || cs < 0) {
                fprintf(stderr, "dpd fit-line: %s line %d: column '%s' not in the header\n", file, lineno,
                        cx < 0 ? xn : cy < 0 ? yn : sn);
                status = 1;
                break;
            }
            continue;
        }
        double val[MAX_COLS];
        int nc = 0;
        for (char *tok = strtok(line, "\t\n"); tok && nc < MAX_COLS; tok = strtok(NULL, "\t\n")) val[nc++] = strtod(tok, NULL);
        if (cx >= nc || cy >= nc || cs >= nc) continue;
        const double xv = val[cx], yv = val[cy], se = val[cs];
        if (!(xv >= lo && xv <= hi) || !isfinite(yv) || !(se > 0.0) || !isfinite(se)) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            if (grow(&x, cap) || grow(&y, cap) || grow(&w, cap)) {
                fprintf(stderr, "dpd fit-line: %s line %d: out of memory for %d rows\n", file, lineno, cap);
                status = 1;
                break;
            }
        }
        x[n] = xv; y[n] = yv; w[n] = 1.0 / (se * se); n++;
    }
    fclose(f);
    if (status == 0 && origin && n >= 2) {
        double c1, cov11, chisq;
        gsl_fit_wmul(x, 1, w, 1, y, 1, (size_t)n, &c1, &cov11, &chisq);
        const double chi2dof = chisq / (n - 1), scale = chi2dof > 1.0 ? chi2dof : 1.0;
        printf("quantity\tvalue\tstderr\n");
        printf("slope\t%.10g\t%.4g\n", c1, sqrt(scale * cov11));
        printf("chi2_dof\t%.10g\t0\n", chi2dof);
        printf("points\t%d\t0\n", n);
        free(x); free(y); free(w);
        return 0;
    }
    if (status == 0 && n < 3) {
        fprintf(stderr, "dpd fit-line: %s: %d usable rows in [%g, %g]; need at least 3\n", file, n, lo, hi);
        status = 1;
    }
    if (status == 0) {
        double c0, c1, cov00, cov01, cov11, chisq;
        gsl_fit_wlinear(x, 1, w, 1, y, 1, (size_t)n, &c0, &c1, &cov00, &cov01, &cov11, &chisq);
        const double chi2dof = chisq / (n - 2);
        const double scale = chi2dof > 1.0 ? chi2dof : 1.0;
        const double xm = isfinite(lo) && isfinite(hi) ? 0.5 * (lo + hi) : 0.0;
        double ym = 0.0, sst = 0.0, ssr = 0.0;
        for (int k = 0; k < n; k++) ym += y[k] / n;
        for (int k = 0; k < n; k++) {
            const double e = y[k] - (c0 + c1 * x[k]);
            ssr += e * e;
            sst += (y[k] - ym) * (y[k] - ym);
        }
        printf("quantity\tvalue\tstderr\n");
        printf("slope\t%.10g\t%.4g\n", c1, sqrt(scale * cov11));
        printf("value_at_centre\t%.10g\t%.4g\n", c0 + c1 * xm, sqrt(scale * (cov00 + 2 * xm * cov01 + xm * xm * cov11)));
        printf("r2\t%.10g\t0\n", sst > 0 ? 1.0 - ssr / sst : 1.0);
        printf("chi2_dof\t%.10g\t0\n", chi2dof);
        printf("points\t%d\t0\n", n);
    }
    free(x); free(y); free(w);
    return status;
}
