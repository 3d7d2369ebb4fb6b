/* test_tcaf.c - transverse current autocorrelation functions (Mai-Duy et al.
 * 2019, eqs 22-28; src/measure/tcaf.c).
 * Synthetic fields on a simple cubic lattice of m^3 sites in a box L^3: for
 * wave vectors 2 pi n / L with |n_d| < m the discrete Fourier sums are exact,
 * sum_j cos^2(k x_j) = N / 2 and sum_j cos(k x_j) sin(k x_j) = 0, so the
 * expected currents are known to rounding (tolerances: a few 1e-12 relative,
 * N = 512 terms of order 1). The fits are checked noise-free (tolerance from
 * the solver's 1e-12 stopping rule) and with deterministic noise of known
 * amplitude (tolerance 4 standard errors of the linearised least squares). */
#include "testutil.h"
#include <complex.h>
#include "tcaf.h"
#include "simd.h"

enum { M = 8 };                       /* lattice sites per direction */
static const double LBOX = 6.0;

static void lattice(System *s)
{
    memset(s, 0, sizeof *s);
    const double L[3] = {LBOX, LBOX, LBOX};
    box_init(&s->box, 3, L, 0.0);
    assert_int_equal(system_alloc(s, M * M * M), 0);
    s->ntypes = 1;
    snprintf(s->types[0].name, sizeof s->types[0].name, "w");
    s->types[0].mass = 1.0;
    s->kBT = 1.0;
    s->dt = 0.01;
    int i = 0;
    for (int a = 0; a < M; a++)
        for (int b = 0; b < M; b++)
            for (int c = 0; c < M; c++, i++) {
                s->id[i] = (uint32_t)i;
                s->x[3 * i] = (a + 0.25) * LBOX / M;   /* offset: phases not all 0 */
                s->x[3 * i + 1] = (b + 0.5) * LBOX / M;
                s->x[3 * i + 2] = (c + 0.75) * LBOX / M;
            }
}

static void configure(Tcaf *t, int n2max, int window, int origin_every, int nblocks, long long steps,
                      const System *s)
{
    const TcafParams p = {.every = 1, .window = window, .origin_every = origin_every, .n2max = n2max,
                          .type = -1, .fit_min = 0.3, .extrap_kmax = 1e9, .extrap_order = 0};
    assert_int_equal(tcaf_init(t, &p, s, nblocks, steps), 0);
}

static int find_vec(const Tcaf *t, int i, int j, int l)
{
    for (int q = 0; q < t->nvec; q++)
        if (t->vec[3 * q] == i && t->vec[3 * q + 1] == j && t->vec[3 * q + 2] == l) return q;
    return -1;
}

/* Every vector of the half space with 0 < n^2 <= n2max appears once, and
 * shells are sorted by |k| with the right multiplicities. */
static void wave_vectors_half_space(void **state)
{
    (void)state;
    System s; lattice(&s);
    Tcaf t; configure(&t, 9, 10, 5, 2, 100, &s);
    int full = 0;
    for (int i = -3; i <= 3; i++)
        for (int j = -3; j <= 3; j++)
            for (int l = -3; l <= 3; l++) {
                const int n2 = i * i + j * j + l * l;
                if (n2 == 0 || n2 > 9) continue;
                full++;
                const int plus = find_vec(&t, i, j, l) >= 0, minus = find_vec(&t, -i, -j, -l) >= 0;
                CHECK_TRUE(plus + minus == 1, "vector (%d,%d,%d): %d of +-k kept, want exactly 1", i, j, l, plus + minus);
            }
    CHECK_TRUE(2 * t.nvec == full, "%d vectors kept, want half of %d", t.nvec, full);
    /* n^2 = 1: 3 vectors; n^2 = 9 holds (3,0,0) and (2,2,1) families: 3 + 12 = 15 */
    CHECK_TRUE(t.shell_n2[0] == 1 && t.shell_nvec[0] == 3, "first shell n2 %d with %d vectors, want 1 and 3",
               t.shell_n2[0], t.shell_nvec[0]);
    CHECK_TRUE(t.shell_n2[t.nshell - 1] == 9 && t.shell_nvec[t.nshell - 1] == 15,
               "last shell n2 %d with %d vectors, want 9 and 15", t.shell_n2[t.nshell - 1], t.shell_nvec[t.nshell - 1]);
    for (int q = 1; q < t.nshell; q++)
        CHECK_TRUE(t.shell_k[q] > t.shell_k[q - 1], "shells not sorted by |k| at %d", q);
    tcaf_free(&t);
    system_free(&s);
}

/* axis_nmax: beyond the sphere n^2 <= n2max only the axis vectors (n,0,0),
 * (0,n,0), (0,0,n) are added, one shell of 3 vectors per n up to axis_nmax;
 * the sphere is unchanged; a synthetic transverse mode on an axis shell gives
 * the current N U / 2 as on a sphere shell. */
static void axis_vectors_extend_k(void **state)
{
    (void)state;
    System s; lattice(&s);
    Tcaf t;
    const TcafParams p = {.every = 1, .window = 10, .origin_every = 5, .n2max = 2, .axis_nmax = 7,
                          .type = -1, .fit_min = 0.3, .extrap_kmax = 1e9};
    assert_int_equal(tcaf_init(&t, &p, &s, 2, 100), 0);
    /* sphere n^2 <= 2: 3 + 6 = 9 vectors; axes n = 2..7: 3 each */
    CHECK_TRUE(t.nvec == 9 + 3 * 6, "%d vectors, want 9 of the sphere + 18 on the axes", t.nvec);
    for (int n = 2; n <= 7; n++) {
        CHECK_TRUE(find_vec(&t, n, 0, 0) >= 0 && find_vec(&t, 0, n, 0) >= 0 && find_vec(&t, 0, 0, n) >= 0,
                   "axis vectors with n = %d missing", n);
        CHECK_TRUE(find_vec(&t, n, 1, 0) < 0 && find_vec(&t, 1, 1, n) < 0, "off-axis vector with n = %d kept", n);
    }
    CHECK_TRUE(t.shell_n2[t.nshell - 1] == 49 && t.shell_nvec[t.nshell - 1] == 3,
               "last shell n2 %d with %d vectors, want 49 and 3", t.shell_n2[t.nshell - 1], t.shell_nvec[t.nshell - 1]);
    CHECK_REL("largest |k|", t.shell_k[t.nshell - 1], 2.0 * M_PI * 7 / LBOX, 1e-14);
    for (int q = 1; q < t.nshell; q++)
        CHECK_TRUE(t.shell_k[q] > t.shell_k[q - 1], "shells not sorted by |k| at %d", q);
    /* v_z = U cos(k x), k = 2 pi 5 / L (|n_d| = 5 < M lattice sites: exact sums) */
    const double k = 2.0 * M_PI * 5 / LBOX, U = 0.3;
    memset(s.v, 0, 3 * (size_t)s.n * sizeof(double));
    for (int i = 0; i < s.n; i++) s.v[3 * i + 2] = U * cos(k * s.x[3 * i]);
    tcaf_current(&t, &s);
    const int q = find_vec(&t, 5, 0, 0);
    CHECK_ABS("|J_z(k)| of an axis mode", cabs(t.J[3 * q + 2]), s.n * U / 2, 1e-12 * s.n);
    CHECK_ABS("J_x(k) of an axis mode", cabs(t.J[3 * q]), 0.0, 1e-12 * s.n);
    tcaf_free(&t);
    system_free(&s);
}

/* (1 - k k / k^2) J is orthogonal to k, idempotent, and leaves a transverse J alone. */
static void transverse_projection_orthogonal(void **state)
{
    (void)state;
    uint64_t rng = 7;
    for (int trial = 0; trial < 100; trial++) {
        double k[3];
        double complex J[3], P[3], PP[3];
        for (int d = 0; d < 3; d++) {
            k[d] = 4.0 * tu_uniform(&rng) - 2.0;
            J[d] = (2.0 * tu_uniform(&rng) - 1.0) + I * (2.0 * tu_uniform(&rng) - 1.0);
        }
        tcaf_transverse(k, J, P);
        const double complex kP = k[0] * P[0] + k[1] * P[1] + k[2] * P[2];
        const double kn = sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
        CHECK_ABS("|k . J_perp| / |k|", cabs(kP) / kn, 0.0, 1e-14);
        tcaf_transverse(k, P, PP);
        for (int d = 0; d < 3; d++) CHECK_ABS("projection idempotent", cabs(PP[d] - P[d]), 0.0, 1e-14);
    }
}

/* v = U e_y cos(k x) with k = 2 pi / L e_x: J(k) = U N / 2 e_y (transverse),
 * every other vector 0; v = U e_x cos(k x): J_x = U N / 2 but J_perp = 0. */
static void synthetic_transverse_mode(void **state)
{
    (void)state;
    System s; lattice(&s);
    Tcaf t; configure(&t, 6, 10, 5, 2, 100, &s);
    const double U = 0.7, k = 2.0 * M_PI / LBOX, N = s.n;
    for (int i = 0; i < s.n; i++) {
        s.v[3 * i] = 0.0; s.v[3 * i + 1] = U * cos(k * s.x[3 * i]); s.v[3 * i + 2] = 0.0;
    }
    tcaf_current(&t, &s);
    const int q1 = find_vec(&t, 1, 0, 0);
    assert_true(q1 >= 0);
    for (int q = 0; q < t.nvec; q++)
        for (int d = 0; d < 3; d++) {
            const double complex want = (q == q1 && d == 1) ? U * N / 2.0 : 0.0;
            char what[96];
            snprintf(what, sizeof what, "J_%c of vector (%d,%d,%d)", "xyz"[d], t.vec[3 * q], t.vec[3 * q + 1], t.vec[3 * q + 2]);
            CHECK_ABS(what, cabs(t.J[3 * q + d] - want), 0.0, 1e-12 * N);
        }
    double complex P[3];
    tcaf_transverse(t.kvec + 3 * q1, t.J + 3 * q1, P);
    CHECK_ABS("transverse mode survives the projection", creal(P[1]), U * N / 2.0, 1e-12 * N);
    /* longitudinal mode */
    for (int i = 0; i < s.n; i++) { s.v[3 * i] = U * cos(k * s.x[3 * i]); s.v[3 * i + 1] = 0.0; }
    tcaf_current(&t, &s);
    CHECK_ABS("longitudinal J_x", creal(t.J[3 * q1]), U * N / 2.0, 1e-12 * N);
    tcaf_transverse(t.kvec + 3 * q1, t.J + 3 * q1, P);
    CHECK_ABS("longitudinal mode removed by the projection", cabs(P[0]) + cabs(P[1]) + cabs(P[2]), 0.0, 1e-12 * N);
    /* fluid at rest: no current at all */
    memset(s.v, 0, 3 * (size_t)s.n * sizeof(double));
    tcaf_current(&t, &s);
    for (int q = 0; q < 3 * t.nvec; q++) CHECK_TRUE(t.J[q] == 0.0, "fluid at rest: J[%d] = %g + %gi", q, creal(t.J[q]), cimag(t.J[q]));
    tcaf_free(&t);
    system_free(&s);
}

/* Noise-free C/C0 = exp(-eta k^2 t / rho) gives eta back; with Gaussian-like
 * noise of sd 0.01 the error is within 4 linearised standard errors. */
static void fit_recovers_decay(void **state)
{
    (void)state;
    const double eta = 27.3, k2 = 0.7, rho = 4.0, a = k2 / rho;
    double t[40], c[40], e;
    for (int i = 0; i < 40; i++) { t[i] = 0.01 * (i + 1); c[i] = exp(-eta * a * t[i]); }
    assert_int_equal(tcaf_fit_eta(t, c, 40, k2, rho, &e), 0);
    CHECK_REL("eta from a noise-free exponential", e, eta, 1e-9);
    uint64_t rng = 11;
    const double sd = 0.01;
    double s2 = 0.0;
    for (int i = 0; i < 40; i++) {
        double z = 0.0;   /* sum of 12 uniforms - 6: mean 0, variance 1 */
        for (int r = 0; r < 12; r++) z += tu_uniform(&rng);
        c[i] += sd * (z - 6.0);
        const double dc = a * t[i] * exp(-eta * a * t[i]);
        s2 += dc * dc;
    }
    assert_int_equal(tcaf_fit_eta(t, c, 40, k2, rho, &e), 0);
    const double se = sd / sqrt(s2);
    print_message("noisy fit: eta %.4f, want %.4f +- %.4f\n", e, eta, se);
    CHECK_ABS("eta from a noisy exponential (4 standard errors)", e, eta, 4.0 * se);
}

/* eta = 29 - 1.5 k^2 + 0.02 k^4 is returned exactly by the order-2 fit; the
 * order-1 fit of an exactly linear law too. */
static void extrapolation_exact_for_polynomials(void **state)
{
    (void)state;
    double k[8], e1[8], e2[8], w[8], c[3];
    for (int i = 0; i < 8; i++) {
        k[i] = 0.4 * (i + 1);
        const double x = k[i] * k[i];
        e1[i] = 29.0 - 1.5 * x;
        e2[i] = e1[i] + 0.02 * x * x;
        w[i] = 1.0 + i;
    }
    assert_int_equal(tcaf_extrapolate(k, e1, w, 8, 1, c), 0);
    CHECK_ABS("order 1: eta(k -> 0)", c[0], 29.0, 1e-10);
    CHECK_ABS("order 1: k^2 coefficient", c[1], -1.5, 1e-10);
    assert_int_equal(tcaf_extrapolate(k, e2, w, 8, 2, c), 0);
    CHECK_ABS("order 2: eta(k -> 0)", c[0], 29.0, 1e-9);
    CHECK_ABS("order 2: k^4 coefficient", c[2], 0.02, 1e-10);
}

/* The whole pipeline: a transverse mode whose amplitude decays as exp(-t/tau)
 * sampled every step, correlated over time origins, normalised and fitted:
 * eta = rho / (k^2 tau) for its shell (eq. 28), in every block. */
static void sampled_decaying_mode_gives_its_viscosity(void **state)
{
    (void)state;
    System s; lattice(&s);
    const int window = 60, origin_every = 10, nblocks = 4;
    const long long steps = 400;
    Tcaf t; configure(&t, 1, window, origin_every, nblocks, steps, &s);
    const double k = 2.0 * M_PI / LBOX, tau = 0.2, U = 0.5;
    for (long long st = 0; st <= steps; st++) {
        /* C(t0, t0 + t) = U^2 exp(-2 t0 / tau) exp(-t / tau): normalised, exp(-t / tau) */
        const double age = (double)st * s.dt;
        for (int i = 0; i < s.n; i++) s.v[3 * i + 2] = U * exp(-age / tau) * cos(k * s.x[3 * i]);
        tcaf_sample(&t, &s, st);
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    char dir[] = "/tmp/dpd-test-tcaf-XXXXXX";
    assert_non_null(mkdtemp(dir));
    assert_int_equal(tcaf_write(&t, &s, f, dir), 0);
    fclose(f);
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "warning: could not remove %s\n", dir);
    double eta = NAN, se = NAN;
    const char *p = strstr(buf, "tcaf_eta_n2_1\t");
    assert_non_null(p);
    assert_int_equal(sscanf(p, "tcaf_eta_n2_1\t%lf\t%lf", &eta, &se), 2);
    const double want = t.rho / (k * k * tau);
    print_message("eta = %.6f +- %.2g, want rho / (k^2 tau) = %.6f\n", eta, se, want);
    CHECK_REL("eta of a mode decaying with tau (eq. 28)", eta, want, 1e-8);
    CHECK_TRUE(t.ndone >= nblocks, "%lld complete origins", t.ndone);
    free(buf);
    tcaf_free(&t);
    system_free(&s);
}

/* include_bodies: a body of mass M at R moving with V adds M V exp(i k.R) to
 * every J(k), and its mass to rho. */
static void bodies_join_the_current(void **state)
{
    (void)state;
    System s; lattice(&s);
    Tcaf t; configure(&t, 2, 10, 5, 2, 100, &s);
    memset(s.v, 0, 3 * (size_t)s.n * sizeof(double));
    const double R[3] = {1.3, 2.1, 0.4}, V[3] = {0.2, -0.5, 0.7}, M = 6.0;
    const double rho0 = t.rho;
    tcaf_set_bodies(&t, &s, 1, R, V, M);
    CHECK_REL("rho with the body", t.rho, rho0 + M / (LBOX * LBOX * LBOX), 1e-14);
    tcaf_current(&t, &s);
    for (int q = 0; q < t.nvec; q++) {
        const double *k = t.kvec + 3 * q, ph = k[0] * R[0] + k[1] * R[1] + k[2] * R[2];
        for (int d = 0; d < 3; d++)
            CHECK_ABS("J of a moving body", cabs(t.J[3 * q + d] - M * V[d] * cexp(I * ph)), 0.0, 1e-13);
    }
    tcaf_free(&t);
    system_free(&s);
}

/* More blocks than tcaf_write's per-block arrays hold (issue 24, bug 4c; the
 * validator allows 1000): refused, not silently cut to the first ones. */
static void too_many_blocks_are_refused(void **state)
{
    (void)state;
    System s; lattice(&s);
    const int nblocks = 1100;
    Tcaf t; configure(&t, 1, 2, 1, nblocks, nblocks + 2, &s);
    for (int b = 0; b < nblocks; b++) t.acc_n[b] = 1;   /* one complete origin per block */
    t.ndone = nblocks;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    char dir[] = "/tmp/dpd-test-tcaf-XXXXXX";
    assert_non_null(mkdtemp(dir));
    const int rc = tcaf_write(&t, &s, f, dir);
    fclose(f);
    TcafResult r;
    CHECK_TRUE(tcaf_analyse(&t, &s, &r) != 0, "tcaf_analyse of %d blocks succeeded: it must refuse them", nblocks);
    tcaf_result_free(&r);
    free(buf);
    char cmd[256];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "warning: could not remove %s\n", dir);
    CHECK_TRUE(rc != 0, "tcaf_write of %d blocks returned %d: it must refuse more blocks than it holds", nblocks, rc);
    tcaf_free(&t);
    system_free(&s);
}

/* tcaf_analyse on a synthetic state: in block b every shell decays as
 * exp(-eta_b k^2 t / rho) (eq. 28) with eta_b = (E0 + E1 k^2)(1 + d_b), the
 * d_b of mean 0, and C(k,0) at equipartition. Each block's fit gives eta_b
 * back (exact exponentials), so eta_se and the k -> 0 coefficients' errors are
 * the known block scatter; the pooled curve, a mean of exponentials, gives eta
 * to second order in d_b (tolerance 1e-3). The curves carry a ripple of 1e-9:
 * on an exact exponential GSL's driver makes no progress and the fit fails. */
static double ripple(int l) { return l == 0 ? 1.0 : 1.0 + (l % 2 ? 1e-9 : -1e-9); }

static void analyse_synthetic_blocks(void **state)
{
    (void)state;
    System s; lattice(&s);
    enum { B = 4, WINDOW = 20 };
    const double E0 = 30.0, E1 = -2.0, D[B] = {-0.015, -0.005, 0.005, 0.015};
    const TcafParams p = {.every = 1, .window = WINDOW, .origin_every = 5, .n2max = 2, .type = -1,
                          .fit_min = 0.3, .extrap_kmax = 1e9, .extrap_order = 1};
    Tcaf t;
    assert_int_equal(tcaf_init(&t, &p, &s, B, 200), 0);
    const int ns = t.nshell, L = t.nlags;
    assert_int_equal(ns, 2);
    for (int b = 0; b < B; b++) {
        t.acc_n[b] = 5;
        for (int q = 0; q < ns; q++) {
            const double k2 = t.shell_k[q] * t.shell_k[q], eta = (E0 + E1 * k2) * (1 + D[b]);
            /* sum over origins of sum_k J_perp J_perp: C(k,0) = k^2 kBT <1/m> (mass 1, 2 polarisations) */
            const double c0 = t.acc_n[b] * (double)t.count * 2 * t.shell_nvec[q];
            for (int l = 0; l < L; l++) t.acc[((size_t)b * ns + q) * L + l] = c0 * exp(-eta * k2 * l * s.dt / t.rho) * ripple(l);
        }
    }
    t.ndone = 5 * B;
    TcafResult r;
    assert_int_equal(tcaf_analyse(&t, &s, &r), 0);
    CHECK_TRUE(r.nshell == ns && r.nlags == L && r.nblocks == B, "sizes %d %d %d", r.nshell, r.nlags, r.nblocks);
    double sd = 0.0;   /* sample standard deviation of 1 + d_b */
    for (int b = 0; b < B; b++) sd += D[b] * D[b];
    const double rel_se = sqrt(sd / (B - 1)) / sqrt((double)B);
    for (int q = 0; q < ns; q++) {
        const double k2 = t.shell_k[q] * t.shell_k[q], eta = E0 + E1 * k2;
        print_message("shell %d: eta %.6f +- %.3g (want %.6f +- %.3g), %d fit points\n", q, r.eta[q], r.eta_se[q],
                      eta, rel_se * eta, r.fit_points[q]);
        CHECK_REL("eta(k) of the pooled curve", r.eta[q], eta, 1e-3);
        CHECK_REL("eta_se: the scatter of the blocks' eta", r.eta_se[q], rel_se * eta, 1e-6);
        CHECK_REL("C(k,0) at equipartition", r.c0_ratio[q], 1.0, 1e-12);
        for (int l = 0; l < L; l++) {
            double want = 0.0;
            for (int b = 0; b < B; b++) want += exp(-eta * (1 + D[b]) * k2 * l * s.dt / t.rho) * ripple(l) / B;
            CHECK_REL("pooled C(k,t)/C(k,0)", r.c[(size_t)q * L + l], want, 1e-12);
        }
        const int n = r.fit_points[q];
        CHECK_TRUE(n >= 3 && n + 1 < L && r.c[(size_t)q * L + n] >= p.fit_min && r.c[(size_t)q * L + n + 1] < p.fit_min,
                   "shell %d: %d fit points do not end where C/C0 drops below %g", q, n, p.fit_min);
    }
    CHECK_REL("mean equipartition ratio", r.c0_ratio_mean, 1.0, 1e-12);
    CHECK_TRUE(r.nextrap == 2 && r.kend == t.shell_k[1], "%d shells up to %g in the k -> 0 fit", r.nextrap, r.kend);
    CHECK_REL("eta(k -> 0)", r.coef[0], E0, 1e-3);
    CHECK_REL("k^2 coefficient", r.coef[1], E1, 2e-2);
    CHECK_REL("eta(k -> 0) error: the blocks' scatter", r.coef_se[0], rel_se * E0, 1e-6);
    CHECK_REL("k^2 coefficient error", r.coef_se[1], rel_se * fabs(E1), 1e-6);
    const double k20 = t.shell_k[0] * t.shell_k[0], k21 = t.shell_k[1] * t.shell_k[1];
    CHECK_REL("eta drop over the shells", r.drop, E1 * (k20 - k21), 2e-2);
    CHECK_REL("eta drop error", r.drop_se, rel_se * fabs(E1 * (k20 - k21)), 1e-6);
    tcaf_result_free(&r);
    tcaf_free(&t);
    system_free(&s);
}

/* The current J(k) = sum_i v_i e^{i k.r_i} (eq. 24) of tcaf_current, eight
 * particles side by side (each lane its own sums, +-l of a run from shared
 * products), is the same bits at every instruction-set level the CPU has, and agrees with the plain sum of v e^{i k.r} from cexp() over the
 * particles for each wave vector, to rounding (1e-11 for 512 terms of order 1). Particles
 * at random positions, velocities and wave vectors up to n^2 = 25 plus axes to
 * 7, so runs of every length 1 ... 11 occur. */
static void current_same_bits_every_level(void **state)
{
    (void)state;
    System s; lattice(&s);
    uint64_t st = 11;
    for (int i = 0; i < s.n; i++)
        for (int d = 0; d < 3; d++) { s.x[3 * i + d] = LBOX * tu_uniform(&st); s.v[3 * i + d] = 2 * tu_uniform(&st) - 1; }
    Tcaf t;
    const TcafParams p = {.every = 1, .window = 10, .origin_every = 5, .n2max = 25, .axis_nmax = 7,
                          .type = -1, .fit_min = 0.3, .extrap_kmax = 1e9};
    assert_int_equal(tcaf_init(&t, &p, &s, 2, 100), 0);
    const int best = simd_cap(-1);
    double complex *ref = malloc((size_t)t.nvec * 3 * sizeof *ref);
    assert_non_null(ref);
    int bad = 0;
    for (int level = 0; level <= 2; level++) {
        if (simd_cap(level) != level) { printf("TCAF level %d: not on this CPU\n", level); continue; }
        tcaf_current(&t, &s);
        if (level == 0) memcpy(ref, t.J, (size_t)t.nvec * 3 * sizeof *ref);
        else bad += memcmp(ref, t.J, (size_t)t.nvec * 3 * sizeof *ref) != 0;
        CHECK_TRUE(bad == 0, "J(k) at level %d differs from the portable level's bits", level);
    }
    simd_cap(best);
    double worst = 0.0;
    for (int q = 0; q < t.nvec; q++)
        for (int d = 0; d < 3; d++) {
            double complex sum = 0.0;
            for (int i = 0; i < s.n; i++) {
                const double *k = t.kvec + 3 * q, *x = s.x + 3 * i;
                sum += s.v[3 * i + d] * cexp(I * (k[0] * x[0] + k[1] * x[1] + k[2] * x[2]));
            }
            const double e = cabs(sum - t.J[3 * q + d]);
            if (e > worst) worst = e;
        }
    /* against e^{i k.r} from cexp: the tables' recurrences agree to rounding (512 terms of order 1) */
    CHECK_ABS("max |J - sum v e^{ik.r}|", worst, 0.0, 1e-11);
    free(ref);
    tcaf_free(&t);
    system_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wave_vectors_half_space),
        cmocka_unit_test(axis_vectors_extend_k),
        cmocka_unit_test(current_same_bits_every_level),
        cmocka_unit_test(transverse_projection_orthogonal),
        cmocka_unit_test(synthetic_transverse_mode),
        cmocka_unit_test(fit_recovers_decay),
        cmocka_unit_test(extrapolation_exact_for_polynomials),
        cmocka_unit_test(sampled_decaying_mode_gives_its_viscosity),
        cmocka_unit_test(bodies_join_the_current),
        cmocka_unit_test(too_many_blocks_are_refused),
        cmocka_unit_test(analyse_synthetic_blocks),
    };
    return cmocka_run_group_tests_name("tcaf", tests, NULL, NULL);
}
