/* test_lengthscale.c - eqs 31-32 of Mai-Duy et al. 2019 and the phi of its
 * tables (src/analysis/lengthscale.c). Expected values are recomputed here from the
 * definitions (long double); tolerance 1e-14 relative (a cube root and a few
 * products in double). */
#include "testutil.h"
#include "lengthscale.h"

static void closed_forms(void **state)
{
    (void)state;
    const long double PI_L = 3.141592653589793238462643383279502884L;
    for (int k = 3; k <= 13; k++) {
        const long double nc = (long double)k * k * k / 3375.0L;
        CHECK_REL("eq. 31: cube side 15 / k", lambda_cube((double)nc), 15.0 / k, 1e-14);
        CHECK_REL("eq. 32: Wigner-Seitz radius", lambda_sphere((double)nc),
                  (double)cbrtl(3.0L / (4.0L * PI_L * nc)), 1e-14);
        /* n_c lambda_cube^3 = 1 and (4 pi / 3) n_c lambda_sphere^3 = 1 */
        CHECK_REL("one colloid per cube", (double)nc * pow(lambda_cube((double)nc), 3), 1.0, 1e-14);
        CHECK_REL("one colloid per sphere", 4.0 * M_PI / 3.0 * (double)nc * pow(lambda_sphere((double)nc), 3), 1.0, 1e-14);
        CHECK_REL("phi = 6 k^3 / (13500 + 6 k^3)", colloid_volume_fraction((long long)k * k * k, 6, 13500),
                  6.0 * k * k * k / (13500.0 + 6.0 * k * k * k), 1e-15);
    }
    CHECK_ABS("phi at k = 3 (paper: 0.0119)", colloid_volume_fraction(27, 6, 13500), 0.0119, 5e-5);
    CHECK_ABS("phi at k = 13 (paper: 0.4940)", colloid_volume_fraction(2197, 6, 13500), 0.4940, 5e-5);
}

int main(void)
{
    const struct CMUnitTest tests[] = { cmocka_unit_test(closed_forms) };
    return cmocka_run_group_tests_name("lengthscale", tests, NULL, NULL);
}
