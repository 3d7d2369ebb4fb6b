/* test_colloid.c - spring-model colloids (Mai-Duy et al. 2019, eq. 30; src/bodies/colloid.c).
 * - A free rigid body keeps its angular momentum exactly and turns by |omega| t
 *   about omega (Rodrigues), its quaternion stays a unit quaternion (1e-12).
 * - The spring forces on the particles and the reaction on the body sum to
 *   zero (momentum conservation; rounding of 6 terms of order H |dr|).
 * - Stability: one colloid (6 particles, no DPD forces) under velocity Verlet
 *   keeps a bounded spring energy at the chosen H = 400 for dt = 0.005 and
 *   0.01; the largest stable dt of a scan is printed and must lie between
 *   the harmonic bounds 2 / sqrt(H / m) (fixed site) and 2 / sqrt(H / mu)
 *   (mu the reduced mass with the body), widened by a factor 2 because the
 *   body lags by one step.
 * - Stress (momentum flux): for one colloid without DPD forces, d/dt of
 *   G = sum m r v + M R V is (K + W) with K = sum m v v + M V V and W the
 *   spring virial sum (r_i - R) F_S that colloid_step adds; G stays bounded,
 *   so the time mean of K + W is below 2 max|G| / T (+1 % of K for the
 *   O(dt) lag of the body). The colloid spins about (1, 1, 0) so that K_xy
 *   is not zero. Without W, or with the site form (r_i - r_bar_i) F_S alone,
 *   the same mean is far outside that bound (checked: the test can fail).
 * - Lees-Edwards: a colloid carried across y = L by its velocity (rate 0.5,
 *   offset 3.3) keeps its spring extension small and its body's V_x jumps
 *   by -rate L_y with its particles'.
 * - In a DPD solvent the rms spring extension equals sqrt(3 kBT / H) within
 *   3 standard errors plus 3 % (the body also fluctuates a little). */
#include "runutil.h"
#include "colloid.h"

static Colloids *one_colloid(System *s, double H, double dt)
{
    memset(s, 0, sizeof *s);
    const double L[3] = {10.0, 10.0, 10.0};
    box_init(&s->box, 3, L, 0.0);
    assert_int_equal(system_alloc(s, COLLOID_P), 0);
    s->ntypes = 1;
    snprintf(s->types[0].name, sizeof s->types[0].name, "c");
    s->types[0].mass = 1.0;
    s->dt = dt;
    s->kBT = 1.0;
    s->lambda = 0.5;
    for (int i = 0; i < s->n; i++) s->id[i] = (uint32_t)i;
    const ColloidParams p = {.type = 0, .per_axis = 1, .H = H, .d = 0.5, .mass = 6.0, .inertia = 1.0};
    Colloids *c = colloid_new(&p);
    assert_non_null(c);
    assert_int_equal(colloid_place(c, s), 0);
    return c;
}

static void free_body_keeps_angular_momentum(void **state)
{
    (void)state;
    System s;
    Colloids *c = one_colloid(&s, 400.0, 0.01);
    const double L0[3] = {0.3, -0.2, 0.5}, zero[3] = {0, 0, 0};
    memcpy(c->L, L0, sizeof L0);
    const int n = 1000;
    const double dt = 0.01;
    for (int k = 0; k < n; k++) colloid_body_advance(c, 0, zero, zero, dt, &s.box);
    for (int d = 0; d < 3; d++) CHECK_ABS("angular momentum of a free body", c->L[d], L0[d], 0.0);
    const double qn = sqrt(c->q[0] * c->q[0] + c->q[1] * c->q[1] + c->q[2] * c->q[2] + c->q[3] * c->q[3]);
    CHECK_ABS("unit quaternion", qn, 1.0, 1e-12);
    /* Rodrigues: site 0 (0.5, 0, 0) turned by |omega| n dt about omega */
    const double wn = sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]) / c->p.inertia;
    double e[3], v[3] = {0.5, 0, 0}, want[3], got[3];
    for (int d = 0; d < 3; d++) e[d] = L0[d] / (c->p.inertia * wn);
    const double th = wn * n * dt, ev = e[0] * v[0] + e[1] * v[1] + e[2] * v[2];
    const double exv[3] = {e[1] * v[2] - e[2] * v[1], e[2] * v[0] - e[0] * v[2], e[0] * v[1] - e[1] * v[0]};
    for (int d = 0; d < 3; d++) want[d] = c->R[d] + v[d] * cos(th) + exv[d] * sin(th) + e[d] * ev * (1 - cos(th));
    colloid_site(c, 0, 0, &s.box, got);
    for (int d = 0; d < 3; d++) CHECK_ABS("site turned by |omega| t about omega", got[d], want[d], 1e-10);
    colloid_free(c);
    system_free(&s);
}

static void spring_reactions_balance(void **state)
{
    (void)state;
    System s;
    Colloids *c = one_colloid(&s, 400.0, 0.01);
    uint64_t rng = 3;
    for (int k = 0; k < 3 * s.n; k++) s.x[k] += 0.1 * (2 * tu_uniform(&rng) - 1);
    memset(s.f, 0, 3 * (size_t)s.n * sizeof(double));
    colloid_step(c, &s, NULL);
    for (int d = 0; d < 3; d++) {
        double sum = c->F[d];
        for (int i = 0; i < s.n; i++) sum += s.f[3 * i + d];
        CHECK_ABS("spring forces + reaction on the body", sum, 0.0, 1e-12 * c->p.H);
    }
    colloid_free(c);
    system_free(&s);
}

/* Velocity Verlet of the 6 particles with spring forces only; returns the
 * largest spring energy over the run divided by the initial one. */
static double energy_growth(double H, double dt, int steps)
{
    System s;
    Colloids *c = one_colloid(&s, H, dt);
    uint64_t rng = 5;
    for (int k = 0; k < 3 * s.n; k++) s.x[k] += 0.05 * (2 * tu_uniform(&rng) - 1);
    double e0 = 0.0, emax = 0.0;
    for (int st = 0; st <= steps; st++) {
        if (st > 0) {
            for (int k = 0; k < 3 * s.n; k++) { s.v[k] += 0.5 * dt * s.f[k]; s.x[k] += dt * s.v[k]; }
            for (int i = 0; i < s.n; i++) box_wrap(&s.box, s.x + 3 * i, s.img + 3 * i, NULL, NULL);
        }
        memset(s.f, 0, 3 * (size_t)s.n * sizeof(double));
        double e = 0.0;
        for (int b = 0; b < COLLOID_P; b++) {
            double site[3], dr[3];
            colloid_site(c, 0, b, &s.box, site);
            for (int d = 0; d < 3; d++) dr[d] = s.x[3 * b + d] - site[d];
            box_min_image(&s.box, dr, NULL);
            e += 0.5 * H * (dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
        }
        if (st == 0) e0 = e;
        if (!(e <= emax)) emax = e;
        if (!isfinite(e) || e > 1e6 * e0) break;
        colloid_step(c, &s, NULL);
        if (st > 0) for (int k = 0; k < 3 * s.n; k++) s.v[k] += 0.5 * dt * s.f[k];
    }
    colloid_free(c);
    system_free(&s);
    return emax / e0;
}

static void stable_at_chosen_step(void **state)
{
    (void)state;
    const double H = 400.0;
    const double g005 = energy_growth(H, 0.005, 20000), g01 = energy_growth(H, 0.01, 10000);
    print_message("H = %g: max spring energy / initial = %.3f (dt = 0.005), %.3f (dt = 0.01)\n", H, g005, g01);
    CHECK_TRUE(g005 < 3.0, "dt = 0.005: spring energy grew by %g", g005);
    CHECK_TRUE(g01 < 3.0, "dt = 0.01: spring energy grew by %g", g01);
    double dt_stable = 0.0;
    for (double dt = 0.01; dt < 0.3; dt *= 1.05) {
        if (energy_growth(H, dt, 4000) < 10.0) dt_stable = dt;
        else break;
    }
    const double lo = 0.5 * 2.0 / sqrt(H / 1.0), hi = 2.0 * 2.0 / sqrt(H / (6.0 / 7.0));
    print_message("largest stable dt at H = %g: %.4f (harmonic bounds %.4f .. %.4f, widened x2)\n", H, dt_stable, lo, hi);
    CHECK_TRUE(dt_stable > lo && dt_stable < hi, "largest stable dt %g outside [%g, %g]", dt_stable, lo, hi);
}

static void spring_virial_balances_momentum_flux(void **state)
{
    (void)state;
    System s;
    const double dt = 0.002;
    const int steps = 50000;
    Colloids *c = one_colloid(&s, 400.0, dt);
    uint64_t rng = 11;
    /* spin about (1, 1, 0) / sqrt 2 at |omega| = 2, plus random velocities */
    const double w[3] = {M_SQRT2, M_SQRT2, 0.0};
    for (int d = 0; d < 3; d++) { c->L[d] = c->p.inertia * w[d]; c->V[d] = 0.1 * (2 * tu_uniform(&rng) - 1); }
    double p[3] = {0, 0, 0};
    for (int i = 0; i < s.n; i++) {
        double a[3];
        for (int d = 0; d < 3; d++) a[d] = s.x[3 * i + d] - c->R[d];
        const double wxa[3] = {w[1] * a[2] - w[2] * a[1], w[2] * a[0] - w[0] * a[2], w[0] * a[1] - w[1] * a[0]};
        for (int d = 0; d < 3; d++) { s.v[3 * i + d] = wxa[d] + 0.3 * (2 * tu_uniform(&rng) - 1); p[d] += s.v[3 * i + d]; }
    }
    for (int d = 0; d < 3; d++) p[d] += c->p.mass * c->V[d];
    for (int d = 0; d < 3; d++) {   /* zero total momentum: G does not depend on the origin */
        const double u = p[d] / (s.n + c->p.mass);
        c->V[d] -= u;
        for (int i = 0; i < s.n; i++) s.v[3 * i + d] -= u;
    }
    PairVirial pv;
    memset(&pv, 0, sizeof pv);
    double KW[9] = {0}, Km[9] = {0}, KWsite[9] = {0}, Gmax[9] = {0};
    memset(s.f, 0, 3 * (size_t)s.n * sizeof(double));
    colloid_step(c, &s, NULL);
    for (int st = 0; st < steps; st++) {
        for (int k = 0; k < 3 * s.n; k++) { s.v[k] += 0.5 * dt * s.f[k]; s.x[k] += dt * s.v[k]; }
        memset(s.f, 0, 3 * (size_t)s.n * sizeof(double));
        forces_zero_virial(&pv);
        double R[3], Wsite[9] = {0};
        memcpy(R, c->R, sizeof R);
        /* the site form, for contrast: sum (r_i - r_bar_i) F_S */
        for (int k = 0; k < COLLOID_P; k++) {
            double site[3], dr[3];
            colloid_site(c, 0, k, &s.box, site);
            for (int d = 0; d < 3; d++) dr[d] = s.x[3 * k + d] - site[d];
            for (int a = 0; a < 3; a++)
                for (int e = 0; e < 3; e++) Wsite[3 * a + e] += dr[a] * (-c->p.H * dr[e]);
        }
        colloid_step(c, &s, &pv);
        for (int k = 0; k < 3 * s.n; k++) s.v[k] += 0.5 * dt * s.f[k];
        for (int a = 0; a < 3; a++)
            for (int e = 0; e < 3; e++) {
                double K = c->p.mass * c->V[a] * c->V[e], G = c->p.mass * R[a] * c->V[e];
                for (int i = 0; i < s.n; i++) {
                    K += s.v[3 * i + a] * s.v[3 * i + e];
                    G += s.x[3 * i + a] * s.v[3 * i + e];
                }
                Km[3 * a + e] += K / steps;
                KW[3 * a + e] += (K + pv.W[PART_CONSERVATIVE][a][e]) / steps;
                KWsite[3 * a + e] += (K + Wsite[3 * a + e]) / steps;
                if (fabs(G) > Gmax[3 * a + e]) Gmax[3 * a + e] = fabs(G);
            }
    }
    const double T = steps * dt, Kscale = (Km[0] + Km[4] + Km[8]) / 3.0;
    print_message("<K>: xx %.4f xy %.4f; <K + W>: xx %.2e xy %.2e; site form <K + W_site>: xx %.3f xy %.3f; "
                  "2 max|G| / T: xx %.3f xy %.3f\n", Km[0], Km[1], KW[0], KW[1], KWsite[0], KWsite[1],
                  2 * Gmax[0] / T, 2 * Gmax[1] / T);
    for (int q = 0; q < 9; q++) {
        const double tol = 2.0 * Gmax[q] / T + 0.01 * Kscale;
        CHECK_ABS("time mean of kinetic + spring virial (momentum flux balance)", KW[q], 0.0, tol);
    }
    /* the test can fail: K alone, and K with the site form, break the balance */
    CHECK_TRUE(fabs(Km[0]) > 5 * (2.0 * Gmax[0] / T + 0.01 * Kscale), "K_xx alone %g is not outside the bound", Km[0]);
    CHECK_TRUE(fabs(Km[1]) > 5 * (2.0 * Gmax[1] / T + 0.01 * Kscale), "K_xy alone %g is not outside the bound", Km[1]);
    CHECK_TRUE(fabs(KWsite[0]) > 5 * (2.0 * Gmax[0] / T + 0.01 * Kscale), "site form xx %g balances", KWsite[0]);
    colloid_free(c);
    system_free(&s);
}

static void lees_edwards_crossing(void **state)
{
    (void)state;
    System s;
    const double dt = 0.005, rate = 0.5;
    Colloids *c = one_colloid(&s, 400.0, dt);
    const double L[3] = {10.0, 10.0, 10.0};
    box_init(&s.box, 3, L, rate);
    s.box.le_offset = 3.3;
    /* body and particles move up at v_y = 1 with v_x = 0.2 from y = 9 */
    c->R[1] = 9.0;
    for (int k = 0; k < COLLOID_P; k++) colloid_site(c, 0, k, &s.box, s.x + 3 * k);
    c->V[0] = 0.2; c->V[1] = 1.0;
    for (int i = 0; i < s.n; i++) { s.v[3 * i] = 0.2; s.v[3 * i + 1] = 1.0; }
    memset(s.f, 0, 3 * (size_t)s.n * sizeof(double));
    colloid_step(c, &s, NULL);
    double ext_max = 0.0;
    const double y0 = c->R[1];
    int crossed = 0;
    for (int st = 0; st < 400; st++) {
        box_advance(&s.box, dt);
        for (int i = 0; i < s.n; i++) {
            for (int d = 0; d < 3; d++) { s.v[3 * i + d] += 0.5 * dt * s.f[3 * i + d]; s.x[3 * i + d] += dt * s.v[3 * i + d]; }
            box_wrap(&s.box, s.x + 3 * i, s.img + 3 * i, &s.v[3 * i], NULL);
        }
        /* particles and sites at the same time, before the body moves on */
        for (int k = 0; k < COLLOID_P; k++) {
            double site[3], dr[3];
            colloid_site(c, 0, k, &s.box, site);
            for (int d = 0; d < 3; d++) dr[d] = s.x[3 * k + d] - site[d];
            box_min_image(&s.box, dr, NULL);
            const double e = sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
            if (e > ext_max) ext_max = e;
        }
        memset(s.f, 0, 3 * (size_t)s.n * sizeof(double));
        const double ybefore = c->R[1];
        colloid_step(c, &s, NULL);
        if (c->R[1] < ybefore - 5.0) crossed = 1;
        for (int k = 0; k < 3 * s.n; k++) s.v[k] += 0.5 * dt * s.f[k];
    }
    print_message("Lees-Edwards crossing: body y %.2f -> %.2f, V_x %.4f (before 0.2; jump -rate L = %.1f), "
                  "largest spring extension %.2e\n", y0, c->R[1], c->V[0], -rate * L[1], ext_max);
    CHECK_TRUE(crossed, "the body did not cross y = L");
    CHECK_ABS("body V_x after crossing up: 0.2 - rate L_y", c->V[0], 0.2 - rate * L[1], 1e-9);
    CHECK_ABS("particle V_x after crossing up: 0.2 - rate L_y", s.v[0], 0.2 - rate * L[1], 1e-9);
    CHECK_TRUE(ext_max < 1e-6, "spring extension %g across the sheared boundary", ext_max);
    colloid_free(c);
    system_free(&s);
}

static const char *SCENE =
    "dimension = 3;\n"
    "box = [6.0, 6.0, 6.0];\n"
    "kBT = 1.0; dt = 0.01; seed = 9;\n"
    "equilibration = 100; steps = 900;\n"
    "types = ( { name = \"s\"; density = 4.0; }, { name = \"c\"; count = 6; } );\n"
    "pairs = ( { types = [\"s\", \"s\"]; a = 3.53; gamma = 6.97; s = 0.42; rc = 1.5; },\n"
    "          { types = [\"s\", \"c\"]; a = 3.53; gamma = 6.97; s = 0.42; rc = 1.5; },\n"
    "          { types = [\"c\", \"c\"]; a = 3.53; gamma = 6.97; s = 0.42; rc = 1.5; } );\n"
    "colloids = { type = \"c\"; per_axis = 1; H = 400.0; site_distance = 0.5; };\n"
    "measure = { every = 10; blocks = 10; };\n";

static void spring_extension_equipartition(void **state)
{
    (void)state;
    char dir[512], out[600];
    const int rc = run_scene_text("colloid", SCENE, dir, sizeof dir, out, sizeof out);
    double x = NAN, se = NAN, want = NAN, z;
    summary_get(out, "colloid_spring_extension_rms", &x, &se);
    summary_get(out, "colloid_spring_extension_rms_equipartition", &want, &z);
    rm_rf(dir);
    CHECK_TRUE(rc == 0, "run_scene returned %d", rc);
    print_message("rms extension %.5f +- %.5f, sqrt(3 kBT / H) = %.5f\n", x, se, want);
    CHECK_ABS("rms spring extension vs sqrt(3 kBT / H)", x, want, 0.03 * want + 3 * se);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(free_body_keeps_angular_momentum),
        cmocka_unit_test(spring_reactions_balance),
        cmocka_unit_test(stable_at_chosen_step),
        cmocka_unit_test(spring_virial_balances_momentum_flux),
        cmocka_unit_test(lees_edwards_crossing),
        cmocka_unit_test(spring_extension_equipartition),
    };
    return cmocka_run_group_tests_name("colloid", tests, NULL, NULL);
}
