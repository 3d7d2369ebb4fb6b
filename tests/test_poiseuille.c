/* test_poiseuille.c - the reverse Poiseuille viscosity fit (src/analysis/poiseuille.c,
 * Backer et al. 2005) and, above all, its standard error.
 * 1. An exact two-parabola profile (+g below L/2, -g above) gives mu exactly,
 *    from one profile and from identical blocks (error 0).
 * 2. Error model: synthetic runs of B blocks; each block is the exact profile
 *    plus a curvature fluctuation shared by all bins of a half (amplitude
 *    sd_c, independent between blocks) plus independent bin noise (sd_b).
 *    The curvature of each half then scatters by sd_c plus the fit's share of
 *    the bin noise; the block estimate's se^2, averaged over R runs, must match
 *    the run-to-run variance of mu within 4 sd of that average (a variance from
 *    B blocks has relative sd sqrt(2 / (B - 1))). Power: the per-bin fit of
 *    the run's mean profile (bin errors from the block scatter, bins taken as
 *    independent) must come out below half the true variance here, as it did
 *    for the real channel (chi2 / dof 0.3-0.6 and halves 3 sigma apart). */
#include "testutil.h"
#include <gsl/gsl_rng.h>
#include <gsl/gsl_randist.h>
#include "poiseuille.h"

enum { BINS = 40, BLOCKS = 20, RUNS = 2000 };
static const double L = 20.0, G = 0.05, RHO = 3.0, MU = 3.6;

static double exact_v(double z)
{
    /* lower half: v = (n g / 2 mu) z (L/2 - z); upper half: the mirror image, negative */
    const double a = RHO * G / (2.0 * MU), h = 0.5 * L;
    return z < h ? a * z * (h - z) : -a * (z - h) * (L - z);
}

static void bins(double *pos, double *dens)
{
    for (int b = 0; b < BINS; b++) { pos[b] = (b + 0.5) * L / BINS; dens[b] = RHO; }
}

static void exact_profile_gives_mu(void **state)
{
    (void)state;
    double pos[BINS], dens[BINS], v[BINS], se[BINS];
    bins(pos, dens);
    for (int b = 0; b < BINS; b++) { v[b] = exact_v(pos[b]); se[b] = 0.01; }
    PoiseuilleFit r;
    assert_int_equal(poiseuille_fit(pos, v, se, dens, BINS, L, G, &r), 0);
    CHECK_REL("mu of the lower half, exact profile", r.mu[0], MU, 1e-10);
    CHECK_REL("mu of the upper half, exact profile", r.mu[1], MU, 1e-10);
    CHECK_REL("mu, exact profile", r.mu_mean, MU, 1e-10);

    double vb[BLOCKS * BINS], db[BLOCKS * BINS];
    for (int k = 0; k < BLOCKS; k++)
        for (int b = 0; b < BINS; b++) { vb[k * BINS + b] = v[b]; db[k * BINS + b] = RHO; }
    assert_int_equal(poiseuille_fit_blocks(pos, vb, db, BINS, BLOCKS, G, &r), 0);
    CHECK_REL("mu (blocks), exact profile", r.mu_mean, MU, 1e-10);
    CHECK_REL("mu_lower (blocks), exact profile", r.mu[0], MU, 1e-10);
    CHECK_ABS("se of mu (blocks), identical blocks", r.mu_mean_se, 0.0, 1e-12);
    assert_int_not_equal(poiseuille_fit_blocks(pos, vb, db, BINS, 1, G, &r), 0);   /* one block: no error */
}

static void block_error_matches_run_scatter(void **state)
{
    (void)state;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, 20261202);
    const double a = RHO * G / (2.0 * MU), sd_c = 0.05 * a, sd_b = 0.004;
    double pos[BINS], dens[BINS], vb[BLOCKS * BINS], db[BLOCKS * BINS];
    bins(pos, dens);
    for (int k = 0; k < BLOCKS * BINS; k++) db[k] = RHO;
    double sum = 0.0, sum2 = 0.0, sum_se2 = 0.0, sum_se2_bins = 0.0;
    for (int run = 0; run < RUNS; run++) {
        double mean_v[BINS] = {0}, mean_v2[BINS] = {0};
        for (int k = 0; k < BLOCKS; k++) {
            /* a curvature fluctuation shared by the bins of each half */
            const double dc[2] = {gsl_ran_gaussian(rng, sd_c), gsl_ran_gaussian(rng, sd_c)};
            for (int b = 0; b < BINS; b++) {
                const double z = pos[b], h = 0.5 * L;
                const double shape = z < h ? z * (h - z) : -(z - h) * (L - z);
                const double x = exact_v(z) + (z < h ? dc[0] : dc[1]) * shape + gsl_ran_gaussian(rng, sd_b);
                vb[k * BINS + b] = x;
                mean_v[b] += x / BLOCKS;
                mean_v2[b] += x * x / BLOCKS;
            }
        }
        PoiseuilleFit r, rb;
        assert_int_equal(poiseuille_fit_blocks(pos, vb, db, BINS, BLOCKS, G, &r), 0);
        double se[BINS];
        for (int b = 0; b < BINS; b++)
            se[b] = sqrt((mean_v2[b] - mean_v[b] * mean_v[b]) * BLOCKS / (BLOCKS - 1.0) / BLOCKS);
        assert_int_equal(poiseuille_fit(pos, mean_v, se, dens, BINS, L, G, &rb), 0);
        sum += r.mu_mean;
        sum2 += r.mu_mean * r.mu_mean;
        sum_se2 += r.mu_mean_se * r.mu_mean_se;
        sum_se2_bins += rb.mu_mean_se * rb.mu_mean_se;
    }
    gsl_rng_free(rng);
    const double mean = sum / RUNS, var = (sum2 / RUNS - mean * mean) * RUNS / (RUNS - 1.0);
    const double ratio = (sum_se2 / RUNS) / var, ratio_bins = (sum_se2_bins / RUNS) / var;
    print_message("mu over %d runs %.5f (sd %.5f); mean se^2 / var: blocks %.3f, per-bin fit %.3f\n",
                  RUNS, mean, sqrt(var), ratio, ratio_bins);
    CHECK_ABS("mu, mean over runs (4 sd)", mean, MU, 4.0 * sqrt(var / RUNS) + 1e-3 * MU);
    /* the variance of the run scatter itself has relative sd sqrt(2 / (RUNS - 1)) */
    CHECK_ABS("block se^2 over the run-to-run variance",
              ratio, 1.0, 4.0 * sqrt(2.0 / (RUNS * (BLOCKS - 1.0)) + 2.0 / (RUNS - 1.0)));
    CHECK_TRUE(ratio_bins < 0.5, "power: the per-bin fit's se^2 / var is %.3f, want < 0.5", ratio_bins);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(exact_profile_gives_mu),
        cmocka_unit_test(block_error_matches_run_scatter),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
