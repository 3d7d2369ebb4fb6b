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

/* The same gas in a sheared box (Lees-Edwards, rate 0.5, L_y = 4: particles
 * cross the y boundary within the window). In the infinite sheared system a
 * free particle keeps its velocity, so its MSD is still |v_i|^2 t^2 exactly
 * (D(T) / D(T/2) = 2 for every group) with v_i its initial velocity, which
 * holds the streaming profile: E|v|^2 = d kBT (1 - 1/N) + rate^2 E(y - L_y/2)^2
 * = d kBT (1 - 1/N) + rate^2 L_y^2 / 12 (uniform y), D = (3T/4) E|v|^2 / d,
 * within 4 of the run's standard errors (groups of particles). The centre of
 * mass (measure.com) of the free particles moves on a straight line: its
 * second differences vanish to the 6 digits of com.tsv (with x + img L it
 * jumps by offset / N ~ 0.01 at each crossing). */
static void sheared_gas_msd_and_com(void **state)
{
    (void)state;
    const double d = 3.0, rate = 0.5, Ly = 4.0;
    char text[1400], dir[512], out[600];
    snprintf(text, sizeof text,
             "dimension = 3;\n"
             "box = [6.0, 4.0, 6.0];\n"
             "kBT = 1.0;\n"
             "dt = 0.01;\n"
             "seed = 5301;\n"
             "equilibration = 0;\n"
             "steps = 400;\n"
             "shear_rate = %g;\n"
             "types = ( { name = \"gas\"; count = %d; } );\n"
             "pairs = ( { types = [\"gas\", \"gas\"]; a = 0.0; gamma = 0.0; interact = false; } );\n"
             "measure = { every = 10; blocks = %d; com = true;\n"
             "            msd = { every = 10; window = 100; origin_every = 10; }; };\n",
             rate, N, GROUPS);
    const int rc = run_scene_text("msd-shear", text, dir, sizeof dir, out, sizeof out);
    double D = NAN, se = NAN, ratio = NAN, rse = NAN;
    const int got = summary_get(out, "D", &D, &se) | summary_get(out, "D_t_ratio_late_half", &ratio, &rse);
    char path[700];
    snprintf(path, sizeof path, "%s/com.tsv", out);
    FILE *f = fopen(path, "r");
    double x[64], y[64];
    int ns = 0;
    if (f) {
        char line[256];
        double t, vx, vy;
        while (fgets(line, sizeof line, f))
            if (ns < 64 && sscanf(line, "%lf\t%lf\t%lf\t%lf\t%lf", &t, &vx, &vy, &x[ns], &y[ns]) == 5) ns++;
        fclose(f);
    }
    rm_rf(dir);
    CHECK_TRUE(rc == 0 && got == 0 && ns >= 10, "status %d, D in summary.tsv: %s, com.tsv rows %d", rc, got ? "no" : "yes", ns);
    CHECK_ABS("sheared ballistic gas: D(T) / D(T/2)", ratio, 2.0, 1e-9);
    const double D_theory = 0.75 * T_WINDOW * (d * (1.0 - 1.0 / N) + rate * rate * Ly * Ly / 12.0) / d;
    print_message("sheared gas: D %.4f +- %.4f, theory %.4f\n", D, se, D_theory);
    CHECK_ABS("sheared ballistic gas: D against (3T/4) E|v|^2 / d (4 se)", D, D_theory, 4.0 * se);
    double worst = 0.0;
    for (int k = 1; k + 1 < ns; k++)
        worst = fmax(worst, fmax(fabs(x[k + 1] - 2.0 * x[k] + x[k - 1]), fabs(y[k + 1] - 2.0 * y[k] + y[k - 1])));
    /* com.tsv prints 6 digits of values below 10: 4 x 5e-6 per second difference */
    CHECK_ABS("sheared ballistic gas: second difference of the centre of mass", worst, 0.0, 2e-5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ballistic_gas_msd_error),
        cmocka_unit_test(sheared_gas_msd_and_com),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
