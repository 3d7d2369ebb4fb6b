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

/* The rows of a table whose x lies in [lo, hi] with a finite y and a
 * positive finite standard error: x, y and the weights 1/se^2. */
typedef struct {
    const char *file, *xn, *yn, *sn;
    double lo, hi;
    int origin;               /* --origin: y = c1 x through (0, 0) (gsl_fit_wmul) */
    double *x, *y, *w;
    int n;
} LinePoints;

static int fit_line_args(int argc, char **argv, LinePoints *p)
{
    *p = (LinePoints){.lo = -INFINITY, .hi = INFINITY};
    for (int k = 0; k < argc; k++) {
        const char *o = argv[k];
        if (o[0] != '-') { p->file = o; continue; }
        if (!strcmp(o, "--origin")) { p->origin = 1; continue; }
        if (k + 1 >= argc) { fprintf(stderr, "dpd fit-line: %s needs a value\n", o); return 1; }
        const char *v = argv[++k];
        if (!strcmp(o, "--x")) p->xn = v;
        else if (!strcmp(o, "--y")) p->yn = v;
        else if (!strcmp(o, "--se")) p->sn = v;
        else if (!strcmp(o, "--range")) {
            if (sscanf(v, "%lf:%lf", &p->lo, &p->hi) != 2 || !(p->lo < p->hi)) {
                fprintf(stderr, "dpd fit-line: --range '%s': expected LO:HI with LO < HI\n", v);
                return 1;
            }
        } else { fprintf(stderr, "dpd fit-line: unknown option %s\n", o); return 1; }
    }
    if (!p->file || !p->xn || !p->yn || !p->sn) {
        fprintf(stderr, "usage: dpd fit-line TABLE --x COL --y COL --se COL [--range LO:HI]\n");
        return 1;
    }
    return 0;
}

/* The header's columns of x, y and se; 0, or 1 with the message. */
static int header_columns(const LinePoints *p, const char *line, int lineno, int *cx, int *cy, int *cs)
{
    char h1[8192], h2[8192], h3[8192];
    strcpy(h1, line); strcpy(h2, line); strcpy(h3, line);
    *cx = column_of(h1, p->xn); *cy = column_of(h2, p->yn); *cs = column_of(h3, p->sn);
    if (*cx >= 0 && *cy >= 0 && *cs >= 0) return 0;
    fprintf(stderr, "dpd fit-line: %s line %d: column '%s' not in the header\n", p->file, lineno,
            *cx < 0 ? p->xn : *cy < 0 ? p->yn : p->sn);
    return 1;
}

static int read_points(LinePoints *p)
{
    FILE *f = fopen(p->file, "r");
    if (!f) { fprintf(stderr, "dpd fit-line: cannot open '%s'\n", p->file); return 4; }
    char line[8192];
    int cx = -1, cy = -1, cs = -1, cap = 0, lineno = 0, status = 0;
    while (status == 0 && fgets(line, sizeof line, f)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (cx < 0) { status = header_columns(p, line, lineno, &cx, &cy, &cs); continue; }
        double val[MAX_COLS];
        int nc = 0;
        for (char *tok = strtok(line, "\t\n"); tok && nc < MAX_COLS; tok = strtok(NULL, "\t\n")) val[nc++] = strtod(tok, NULL);
        if (cx >= nc || cy >= nc || cs >= nc) continue;
        const double xv = val[cx], yv = val[cy], se = val[cs];
        if (!(xv >= p->lo && xv <= p->hi) || !isfinite(yv) || !(se > 0.0) || !isfinite(se)) continue;
        if (p->n == cap) {
            cap = cap ? 2 * cap : 64;
            if (grow(&p->x, cap) || grow(&p->y, cap) || grow(&p->w, cap)) {
                fprintf(stderr, "dpd fit-line: %s line %d: out of memory for %d rows\n", p->file, lineno, cap);
                status = 1;
                break;
            }
        }
        p->x[p->n] = xv; p->y[p->n] = yv; p->w[p->n] = 1.0 / (se * se); p->n++;
    }
    fclose(f);
    return status;
}

/* y = c1 x (gsl_fit_wmul), stderr scaled by chi^2/dof when > 1. */
static void print_fit_origin(const LinePoints *p)
{
    double c1, cov11, chisq;
    gsl_fit_wmul(p->x, 1, p->w, 1, p->y, 1, (size_t)p->n, &c1, &cov11, &chisq);
    const double chi2dof = chisq / (p->n - 1), scale = chi2dof > 1.0 ? chi2dof : 1.0;
    printf("quantity\tvalue\tstderr\n");
    printf("slope\t%.10g\t%.4g\n", c1, sqrt(scale * cov11));
    printf("chi2_dof\t%.10g\t0\n", chi2dof);
    printf("points\t%d\t0\n", p->n);
}

/* y = c0 + c1 x (gsl_fit_wlinear), the value at the range's centre, r^2. */
static void print_fit_line(const LinePoints *p)
{
    const int n = p->n;
    const double *x = p->x, *y = p->y;
    double c0, c1, cov00, cov01, cov11, chisq;
    gsl_fit_wlinear(x, 1, p->w, 1, y, 1, (size_t)n, &c0, &c1, &cov00, &cov01, &cov11, &chisq);
    const double chi2dof = chisq / (n - 2);
    const double scale = chi2dof > 1.0 ? chi2dof : 1.0;
    const double xm = isfinite(p->lo) && isfinite(p->hi) ? 0.5 * (p->lo + p->hi) : 0.0;
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

int cmd_fit_line(int argc, char **argv)
{
    LinePoints p;
    if (fit_line_args(argc, argv, &p)) return 1;
    int status = read_points(&p);
    if (status == 0 && p.origin && p.n >= 2) print_fit_origin(&p);
    else if (status == 0 && p.n < 3) {
        fprintf(stderr, "dpd fit-line: %s: %d usable rows in [%g, %g]; need at least 3\n", p.file, p.n, p.lo, p.hi);
        status = 1;
    } else if (status == 0) print_fit_line(&p);
    free(p.x); free(p.y); free(p.w);
    return status;
}
