/* test_thermostat.c - the DPD thermostat holds kBT. Groot-Warren fluid
 * (n = 3, a = 25, gamma = 4.5, rc = 1, kBT = 1, dt = 0.01, lambda = 0.5).
 * Error model: the instantaneous kinetic temperature of N particles scatters
 * by sqrt(2 / (3N - 3)) (0.021 for N = 1536, measured 0.022), but it is
 * correlated: its integrated autocorrelation time, measured from a run
 * sampled every step, is ~0.55 time units (55 steps). The standard error of
 * the mean is then sqrt(2 / (3N)) sqrt(2 tau / T_run), which for the suggested
 * 8^3 box and 3000 steps is ~0.004 (block estimate 0.0034): too large to
 * resolve 1 %. Hence a 10^3 box (3000 particles) and 500 + 4500 steps sampled
 * every 10 in 15 blocks of 3 time units (> 5 tau): expected se ~ 0.002
 * (6000 steps gave 1.0016 +- 0.0016).
 * The check is |T - 1| < 0.01 AND the block standard error < 0.003, so a 1 %
 * bias is resolved at > 3 standard errors. The time-step bias of velocity
 * Verlet at dt = 0.01 is ~0.5 % (1.005 measured in the small run). */
#include "runutil.h"

static const char *SCENE =
    "dimension = 3;\n"
    "box = [10.0, 10.0, 10.0];\n"
    "kBT = 1.0;\n"
    "dt = 0.01;\n"
    "lambda = 0.5;\n"
    "seed = 97;\n"
    "equilibration = 500;\n"
    "steps = 4500;\n"
    "types = ( { name = \"w\"; density = 3.0; } );\n"
    "pairs = ( { types = [\"w\", \"w\"]; a = 25.0; gamma = 4.5; rc = 1.0; } );\n"
    "measure = { every = 10; blocks = 15; };\n";

static void groot_warren_temperature(void **state)
{
    (void)state;
    char dir[512], out[600];
    const int rc = run_scene_text("thermostat", SCENE, dir, sizeof dir, out, sizeof out);
    double T = NAN, se = NAN, np = 0, npse = 0;
    const int got = summary_get(out, "temperature", &T, &se);
    summary_get(out, "particles", &np, &npse);
    rm_rf(dir);
    CHECK_TRUE(rc == 0, "run_scene returned %d", rc);
    CHECK_TRUE(got == 0, "no temperature in summary.tsv");
    CHECK_TRUE(np == 3000, "%g particles, want 3000", np);
    print_message("T = %.5f +- %.5f (kBT = 1)\n", T, se);
    CHECK_ABS("kinetic temperature (1 %% of kBT)", T, 1.0, 0.01);
    CHECK_TRUE(se < 0.003, "block standard error %g >= 0.003: the test cannot resolve a 1 %% bias", se);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(groot_warren_temperature),
    };
    return cmocka_run_group_tests_name("thermostat", tests, NULL, NULL);
}
