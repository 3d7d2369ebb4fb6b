/* test_msd.c - the MSD's diffusion coefficient and, above all, its standard
 * error. A gas of non-interacting particles (interact = false: no force at
 * all) moves ballistically, so every particle's MSD is |v_i|^2 t^2 exactly and
 * the D of the code (slope over the second half of the window, T/2 .. T) is
 * D_i = |v_i|^2 (T + T/2) / (2 d). Error model: the |v_i|^2 are independent
 * with mean d kBT/m and variance 2 d (kBT/m)^2 (Maxwell), so over N particles
 * E[D] = (3 T / 4) (1 - 1/N) (the centre-of-mass velocity is removed) and
 * var(D) = 2 d (3 T / 4)^2 / (d^2 N). Every time origin of one run gives the
 * same D: a standard error from blocks of time origins is ~0 here, while the
 * run-to-run scatter is var(D). The code takes its error from groups of
 * particles; its mean squared error over R runs must match var(D): the
 * estimate from G groups has a relative scatter sqrt(2 / (G - 1)) per run, so
 * the mean over R runs is within 4 sqrt(2 / (R (G - 1))) of 1 unless the
 * estimator is wrong (an error from origin blocks gives ~0 and fails). */
#include "runutil.h"

enum { N = 200, RUNS = 12, GROUPS = 20 };
static const double T_WINDOW = 1.0;   /* 100 steps of 0.01 */

static void scene_text(char *buf, size_t len, int seed)
{
    snprintf(buf, len,
             "dimension = 3;\n"
             "box = [10.0, 10.0, 10.0];\n"
             "kBT = 1.0;\n"
             "dt = 0.01;\n"
             "seed = %d;\n"
             "equilibration = 0;\n"
             "steps = 400;\n"
             "types = ( { name = \"gas\"; count = %d; } );\n"
             "pairs = ( { types = [\"gas\", \"gas\"]; a = 0.0; gamma = 0.0; interact = false; } );\n"
             "measure = { every = 10; blocks = %d;\n"
             "            msd = { every = 10; window = 100; origin_every = 10; }; };\n",
             seed, N, GROUPS);
}

static void ballistic_gas_msd_error(void **state)
{
    (void)state;
    const double d = 3.0, D_mean = 0.75 * T_WINDOW * (1.0 - 1.0 / N);
    const double var_D = 2.0 * d * pow(0.75 * T_WINDOW, 2) / (d * d * N);
    double sumD = 0.0, sum_se2 = 0.0;
    for (int r = 0; r < RUNS; r++) {
        char text[1024], dir[512], out[600];
        scene_text(text, sizeof text, 5100 + r);
        const int rc = run_scene_text("msd", text, dir, sizeof dir, out, sizeof out);
        double D = NAN, se = NAN, ratio = NAN, rse = NAN;
        const int got = summary_get(out, "D", &D, &se) | summary_get(out, "D_t_ratio_late_half", &ratio, &rse);
        rm_rf(dir);
        CHECK_TRUE(rc == 0 && got == 0, "run %d: status %d, D in summary.tsv: %s", r, rc, got ? "no" : "yes");
        /* ballistic: msd(T) / T over msd(T/2) / (T/2) is 2 for every group */
        CHECK_ABS("D(T) / D(T/2) of a ballistic gas", ratio, 2.0, 1e-9);
        sumD += D;
        sum_se2 += se * se;
    }
    const double meanD = sumD / RUNS, se2_ratio = (sum_se2 / RUNS) / var_D;
    print_message("D over %d runs %.4f (theory %.4f, sd of one run %.4f); mean se^2 / var(D) = %.3f\n",
                  RUNS, meanD, D_mean, sqrt(var_D), se2_ratio);
    CHECK_ABS("D of a ballistic gas, mean over runs (4 sd)", meanD, D_mean, 4.0 * sqrt(var_D / RUNS));
    CHECK_ABS("reported se^2 over the run-to-run variance (4 sd of the group estimate)",
              se2_ratio, 1.0, 4.0 * sqrt(2.0 / (RUNS * (GROUPS - 1.0))));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ballistic_gas_msd_error),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
