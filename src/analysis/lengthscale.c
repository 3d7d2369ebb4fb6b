/* lengthscale.c - eqs 31-32 of Mai-Duy et al. 2019 and the phi of its tables. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "lengthscale.h"

double colloid_volume_fraction(long long ncolloids, int p, long long nsolvent)
{
    const double nc = (double)p * (double)ncolloids;
    return nc / ((double)nsolvent + nc);
}

double lambda_cube(double nc)
{
    return 1.0 / cbrt(nc);                    /* eq. 31 */
}

double lambda_sphere(double nc)
{
    return cbrt(3.0 / (4.0 * M_PI * nc));     /* eq. 32 */
}

int cmd_wavelengths(int argc, char **argv)
{
    double L = 15.0, n = 4.0;
    long long kmin = 3, kmax = 13;
    int p = 6;
    for (int a = 0; a < argc; a++) {
        if (a + 1 >= argc) { fprintf(stderr, "dpd wavelengths: %s needs a value\n", argv[a]); return 1; }
        const char *o = argv[a];
        char *end;
        const double v = strtod(argv[++a], &end);
        if (*end) { fprintf(stderr, "dpd wavelengths: %s: '%s' is not a number\n", o, argv[a]); return 1; }
        if (!strcmp(o, "--box")) L = v;
        else if (!strcmp(o, "--n")) n = v;
        else if (!strcmp(o, "--p")) p = (int)v;
        else if (!strcmp(o, "--kmin")) kmin = (long long)v;
        else if (!strcmp(o, "--kmax")) kmax = (long long)v;
        else { fprintf(stderr, "dpd wavelengths: unknown option %s\n", o); return 1; }
    }
    if (L <= 0 || n <= 0 || p < 1 || kmin < 1 || kmax < kmin) {
        fprintf(stderr, "dpd wavelengths: need --box > 0, --n > 0, --p >= 1, 1 <= --kmin <= --kmax\n");
        return 1;
    }
    const double V = L * L * L;
    const long long nsolvent = llround(n * V);
    printf("quantity\tvalue\tstderr\n");
    for (long long k = kmin; k <= kmax; k++) {
        const long long nc = k * k * k;       /* colloids on a k^3 cubic lattice */
        const double phi = colloid_volume_fraction(nc, p, nsolvent);
        char tag[32];
        snprintf(tag, sizeof tag, "phi%.4f", phi);
        printf("phi_k%lld\t%.10g\t0\n", k, phi);
        printf("lambda_cube_%s\t%.10g\t0\n", tag, lambda_cube(nc / V));
        printf("lambda_sphere_%s\t%.10g\t0\n", tag, lambda_sphere(nc / V));
    }
    return 0;
}
