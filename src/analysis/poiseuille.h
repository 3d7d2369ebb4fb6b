/* poiseuille.h - viscosity from a periodic (reverse) Poiseuille profile
 * (Backer et al. 2005): a body force +g in the lower half and -g in the upper
 * half along the gradient axis; in each half the steady profile is the parabola
 * v(z) = (n g / 2 mu) (z - z0)(z1 - z), fitted by weighted least squares (GSL). */
#ifndef DPD_POISEUILLE_H
#define DPD_POISEUILLE_H

typedef struct {
    double mu[2], mu_se[2];   /* lower half (+g), upper half (-g) */
    double chi2_dof[2];
    double mu_mean, mu_mean_se;
    double density;           /* mean number density used */
} PoiseuilleFit;

/* pos, v, v_se, dens: nbins bins spanning [0, L); g the body force per particle
 * (mass 1 assumed via the number density). Returns 0 on success. */
int poiseuille_fit(const double *pos, const double *v, const double *v_se, const double *dens,
                   int nbins, double L, double g, PoiseuilleFit *out);

/* The same from per-block profiles (block-major, nblocks x nbins, blocks
 * contiguous in time: profile_blocks.tsv): each half fitted per block with
 * equal weights, the blocks' curvatures averaged, the error from their
 * scatter. mu_mean comes from the mean curvature magnitude of the two halves
 * (its error carries their correlation); chi2_dof is nan. The bins of one
 * profile share the fluctuations of the whole channel's flow, so the per-bin
 * errors of poiseuille_fit understate the error of the curvature. */
int poiseuille_fit_blocks(const double *pos, const double *v, const double *dens, int nbins, int nblocks,
                          double g, PoiseuilleFit *out);

/* `dpd fit-poiseuille PROFILE.tsv --force G [--column vx]`: reads a profile.tsv
 * written by a run and prints quantity/value/stderr rows; with --blocks it reads
 * profile_blocks.tsv (measure.profile.per_block) and uses poiseuille_fit_blocks. */
int poiseuille_command(int argc, char **argv);

#endif
