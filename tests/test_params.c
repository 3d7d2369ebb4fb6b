/* test_params.c - s and gamma that impose a viscosity eta and a Schmidt number
 * Sc (Mai-Duy et al. 2019, eqs 14-21). The expected values are recomputed here
 * in long double from the published formulas:
 *   3D: C = 6 Sc m kBT n^2 rc^2 / (5 eta^2),  (s+4)(s+5) = C,
 *       s = (-9 + sqrt(1 + 4C)) / 2,
 *       gamma = 5 eta (s+1)(s+2)(s+3)(s+4)(s+5) / (16 pi n^2 rc^5),
 *       s > 0  <=>  eta < eta_max = sqrt(3 Sc m kBT n^2 rc^2 / 50)   (eq. 16)
 *   2D: C = 3 Sc m kBT n^2 rc^2 / (4 eta^2),  (s+3)(s+4) = C,
 *       s = (-7 + sqrt(1 + 4C)) / 2,
 *       gamma = 4 eta (s+1)(s+2)(s+3)(s+4) / (3 pi n^2 rc^4),
 *       s > 0  <=>  eta < eta_max = sqrt(Sc m kBT n^2 rc^2 / 16)     (eq. 20)
 * Tolerance 1e-12 relative: the double code loses at most the cancellation
 * in -9 + sqrt(1 + 4C) (factor sqrt(1+4C)/(2s) ~ 12 here) times a few eps. */
#include "testutil.h"
#include "params.h"

static const long double PI_L = 3.141592653589793238462643383279502884L;

static void expected(int dim, long double eta, long double Sc, long double m, long double kBT,
                     long double n, long double rc, long double *s, long double *gamma, long double *eta_max)
{
    const long double k = m * kBT * n * n * rc * rc;
    if (dim == 3) {
        const long double C = 6.0L * Sc * k / (5.0L * eta * eta);
        *s = (-9.0L + sqrtl(1.0L + 4.0L * C)) / 2.0L;
        const long double q = *s;
        *gamma = 5.0L * eta * (q + 1) * (q + 2) * (q + 3) * (q + 4) * (q + 5) / (16.0L * PI_L * n * n * powl(rc, 5));
        *eta_max = sqrtl(3.0L * Sc * k / 50.0L);
    } else {
        const long double C = 3.0L * Sc * k / (4.0L * eta * eta);
        *s = (-7.0L + sqrtl(1.0L + 4.0L * C)) / 2.0L;
        const long double q = *s;
        *gamma = 4.0L * eta * (q + 1) * (q + 2) * (q + 3) * (q + 4) / (3.0L * PI_L * n * n * powl(rc, 4));
        *eta_max = sqrtl(Sc * k / 16.0L);
    }
}

/* The solvent of the paper (eq. 29): eta = 30, Sc = 500, n = 4, rc = 1.5. */
static void paper_solvent_3d(void **state)
{
    (void)state;
    ImposedParams p = params_from_eta_sc(3, 30, 500, 1, 1, 4, 1.5);
    CHECK_TRUE(p.valid, "paper solvent flagged invalid (s = %g)", p.s);
    CHECK_ABS("s to 2 decimals (paper: 0.42)", round(p.s * 100) / 100, 0.42, 1e-12);
    CHECK_ABS("gamma to 2 decimals (paper: 6.97)", round(p.gamma * 100) / 100, 6.97, 1e-12);
    long double s, g, em;
    expected(3, 30, 500, 1, 1, 4, 1.5, &s, &g, &em);
    CHECK_REL("s vs long double eq. 14", p.s, (double)s, 1e-12);
    CHECK_REL("gamma vs long double eq. 15", p.gamma, (double)g, 1e-12);
    CHECK_REL("eta_max vs eq. 16", p.eta_max, (double)em, 1e-12);
    /* the defining relation (s+4)(s+5) = C holds */
    CHECK_REL("(s+4)(s+5) = C", (p.s + 4) * (p.s + 5), p.C, 1e-13);
}

static void other_values(void **state)
{
    (void)state;
    static const double cases[][6] = {    /* eta, Sc, m, kBT, n, rc */
        {10, 100, 1, 1, 3, 1}, {50, 1000, 1, 1, 4, 1.5}, {2, 40, 2, 0.5, 5, 1.2}, {30, 500, 1, 1, 4, 1.5},
    };
    for (int dim = 2; dim <= 3; dim++)
        for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
            const double *c = cases[k];
            ImposedParams p = params_from_eta_sc(dim, c[0], c[1], c[2], c[3], c[4], c[5]);
            long double s, g, em;
            expected(dim, c[0], c[1], c[2], c[3], c[4], c[5], &s, &g, &em);
            char what[96];
            CHECK_TRUE(p.valid == (s > 0), "%dD case %zu: valid flag %d but s = %Lg", dim, k, p.valid, s);
            snprintf(what, sizeof what, "%dD case %zu: s", dim, k);
            CHECK_REL(what, p.s, (double)s, 1e-12);
            snprintf(what, sizeof what, "%dD case %zu: gamma", dim, k);
            CHECK_REL(what, p.gamma, (double)g, 1e-12);
            snprintf(what, sizeof what, "%dD case %zu: eta_max", dim, k);
            CHECK_REL(what, p.eta_max, (double)em, 1e-12);
        }
}

/* s > 0 exactly when eta < eta_max (eqs 16, 20) and Sc > Sc_min (eqs 17, 21). */
static void validity_bound(void **state)
{
    (void)state;
    for (int dim = 2; dim <= 3; dim++) {
        const double Sc = 500, m = 1, kBT = 1, n = 4, rc = 1.5;
        const ImposedParams ref = params_from_eta_sc(dim, 30, Sc, m, kBT, n, rc);
        const double emax = ref.eta_max;
        ImposedParams above = params_from_eta_sc(dim, emax * 1.001, Sc, m, kBT, n, rc);
        CHECK_TRUE(!above.valid && above.s <= 0, "%dD: eta = 1.001 eta_max: s = %g, valid %d (want s <= 0, invalid)",
                   dim, above.s, above.valid);
        ImposedParams far = params_from_eta_sc(dim, emax * 3, Sc, m, kBT, n, rc);
        CHECK_TRUE(!far.valid && far.s < 0, "%dD: eta = 3 eta_max: s = %g, valid %d", dim, far.s, far.valid);
        ImposedParams below = params_from_eta_sc(dim, emax * 0.999, Sc, m, kBT, n, rc);
        CHECK_TRUE(below.valid && below.s > 0, "%dD: eta = 0.999 eta_max: s = %g, valid %d (want s > 0)",
                   dim, below.s, below.valid);
        ImposedParams at = params_from_eta_sc(dim, emax, Sc, m, kBT, n, rc);
        CHECK_ABS("s at eta = eta_max", at.s, 0.0, 1e-12);
        /* Sc_min of eq. 17/21 is the same bound seen from Sc */
        ImposedParams sc = params_from_eta_sc(dim, 30, ref.Sc_min, m, kBT, n, rc);
        CHECK_ABS("s at Sc = Sc_min", sc.s, 0.0, 1e-12);
        ImposedParams sc_lo = params_from_eta_sc(dim, 30, 0.99 * ref.Sc_min, m, kBT, n, rc);
        CHECK_TRUE(!sc_lo.valid, "%dD: Sc = 0.99 Sc_min flagged valid (s = %g)", dim, sc_lo.s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(paper_solvent_3d),
        cmocka_unit_test(other_values),
        cmocka_unit_test(validity_bound),
    };
    return cmocka_run_group_tests_name("params", tests, NULL, NULL);
}
