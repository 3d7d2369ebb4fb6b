/* lengthscale.h - length scales that colloids introduce into the solvent
 * (Mai-Duy et al. 2019, section 4.2): the cube side per colloid (eq. 31) and
 * the Wigner-Seitz radius (eq. 32), and the volume fraction of k^3 spring-model
 * colloids of p constituent particles among the solvent particles. */
#ifndef DPD_LENGTHSCALE_H
#define DPD_LENGTHSCALE_H

/* phi = p k^3 / (N_solvent + p k^3): the constituent particles' share of all particles */
double colloid_volume_fraction(long long ncolloids, int p, long long nsolvent);
/* eq. 31: lambda = n_c^(-1/3) */
double lambda_cube(double nc);
/* eq. 32: lambda = (3 / (4 pi n_c))^(1/3) */
double lambda_sphere(double nc);
/* dpd wavelengths: the rows of Table 1 (cube and sphere columns). */
int cmd_wavelengths(int argc, char **argv);

#endif
