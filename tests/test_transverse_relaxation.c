/* test_transverse_relaxation.c - eta(k) from a normalised C(k,t)/C(k,0) by the
 * single exponential of eq. 28, the slow mode beside a damped oscillation, and
 * the zero-frequency integral (src/analysis/transverse_relaxation.c).
 *
 * Exact curves: the estimators return eta = rho rate / k^2 (or rho / (k^2
 * integral)) to the fit's stopping rule (1e-8 relative), the integral to the
 * trapezoid rule's own error, computed here in closed form.
 * Noisy curves, two kinds of noise of known size, R realisations each:
 *  - white noise of standard deviation SIGMA added to an exact curve: the mean of
 *    the R estimates lies within 4 of its standard errors (sd / sqrt(R)) of the
 *    truth, and their scatter sd is below the bound sum_i |g_i| SIGMA (eta_se_bound:
 *    the largest error any correlation of the lags allows) within the sampling
 *    error of an sd, 4 / sqrt(2 (R - 1));
 *  - the curve measured as the simulator measures it: a stationary Gaussian
 *    current with a known autocorrelation (an Ornstein-Uhlenbeck mode beside an
 *    underdamped Brownian oscillator, sampled exactly), correlated over time
 *    origins, normalised by C(0), per-lag errors from 20 blocks of origins: the
 *    mean within 4 standard errors of the truth, and the scatter sd equal to the
 *    median of the propagated errors (eta_se, Bartlett's correlation of the lags)
 *    within 4 / sqrt(2 (R - 1)). */
#include "testutil.h"
#include <complex.h>
#include "transverse_relaxation.h"

enum { R = 100 };                    /* noisy realisations per case */
static const double RHO = 4.0, K2 = 0.5, DT = 0.01;

typedef struct { double A, rate, damping, frequency, sine; } Modes;

static double modes_value(const Modes *m, double t)
{
    return m->A * exp(-m->rate * t) + exp(-m->damping * t) * ((1 - m->A) * cos(m->frequency * t) + m->sine * sin(m->frequency * t));
}

/* integral_0^inf of the model */
static double modes_integral(const Modes *m)
{
    const double g = m->damping, w = m->frequency;
    return m->A / m->rate + ((1 - m->A) * g + m->sine * w) / (g * g + w * w);
}

/* trapezoid sum over every lag 0, DT, 2 DT, ... of the model, in closed form:
 * DT sum_l e^{-z l DT} - DT / 2 = (DT / 2) coth(z DT / 2), z complex */
static double modes_trapezoid(const Modes *m)
{
    const double x = m->rate * DT;
    const double complex z = (m->damping - I * m->frequency) * DT, B = (1 - m->A) - I * m->sine;
    return m->A * 0.5 * DT * cosh(x / 2) / sinh(x / 2) + creal(B * 0.5 * DT * ccosh(z / 2) / csinh(z / 2));
}

static double gauss(uint64_t *rng)
{
    const double u1 = tu_uniform(rng) + 1e-300, u2 = tu_uniform(rng);
    return sqrt(-2 * log(u1)) * cos(2 * M_PI * u2);
}

static void exact_curve(const Modes *m, int n, double *t, double *c, double *se, double sigma)
{
    for (int l = 0; l < n; l++) { t[l] = l * DT; c[l] = modes_value(m, t[l]); se[l] = l ? sigma : 0.0; }
}

/* Exact single exponential: every estimator returns rho rate / k^2; the two-mode
 * model finds no oscillation and fits one mode. */
static void one_mode_exact(void **state)
{
    (void)state;
    const Modes m = {1.0, 2.5, 1.0, 0.0, 0.0};
    const int n = 201;
    double t[201], c[201], se[201];
    exact_curve(&m, n, t, c, se, 0.01);
    const double want = RHO * m.rate / K2;
    ShellViscosity o;
    assert_int_equal(shell_viscosity(RELAXATION_EXP, t, c, se, n, K2, RHO, 0.3, &o), 0);
    CHECK_REL("exp: eta of an exact exponential", o.eta, want, 1e-8);
    assert_int_equal(shell_viscosity(RELAXATION_TWO_MODE, t, c, se, n, K2, RHO, 0.3, &o), 0);
    CHECK_TRUE(o.modes == 1, "two-mode on one exponential: %d modes, want 1", o.modes);
    CHECK_REL("two-mode: eta of an exact exponential", o.eta, want, 1e-8);
    assert_int_equal(shell_viscosity(RELAXATION_INTEGRAL, t, c, se, n, K2, RHO, 0.3, &o), 0);
    /* trapezoid up to t_cut, exact tail: the error is the trapezoid rule's up to t_cut */
    const double trap_err = (0.5 * DT / tanh(m.rate * DT / 2) - 1 / m.rate) * (1 - exp(-m.rate * o.t_cut));
    CHECK_REL("integral: eta of an exact exponential (trapezoid error)", o.eta, RHO / (K2 * (1 / m.rate + trap_err)), 1e-8);
    CHECK_REL("integral: the trapezoid error is small", o.eta, want, 2 * fabs(trap_err) * m.rate);
}

/* Exact slow mode + damped oscillation (the measured shape at phi = 0.494):
 * the slow rate, amplitude, frequency are returned; the integral is the model's. */
static void two_mode_exact(void **state)
{
    (void)state;
    const Modes m = {0.7, 2.0, 1.1, 24.5, -0.04};
    const int n = 201;
    double t[201], c[201], se[201];
    exact_curve(&m, n, t, c, se, 0.01);
    ShellViscosity o;
    assert_int_equal(shell_viscosity(RELAXATION_TWO_MODE, t, c, se, n, K2, RHO, 0.3, &o), 0);
    CHECK_TRUE(o.modes == 2, "%d modes, want 2", o.modes);
    CHECK_REL("two-mode: eta = rho rate / k^2 of the slow mode", o.eta, RHO * m.rate / K2, 1e-7);
    CHECK_ABS("two-mode: amplitude of the slow mode", o.amplitude, m.A, 1e-7);
    CHECK_REL("two-mode: frequency", o.frequency, m.frequency, 1e-7);
    CHECK_REL("two-mode: damping", o.damping, m.damping, 1e-6);
    assert_int_equal(shell_viscosity(RELAXATION_INTEGRAL, t, c, se, n, K2, RHO, 0.3, &o), 0);
    /* trapezoid to t_cut + exact tail = exact integral + the trapezoid error on [0, t_cut] */
    double trap = 0.0;
    for (int l = 1; l < n && t[l] <= o.t_cut + 1e-12; l++) trap += 0.5 * DT * (c[l - 1] + c[l]);
    const double exact = modes_integral(&m);
    double rest = 0.0;   /* integral beyond t_cut, by the closed form of a shifted model */
    {
        const double tc = o.t_cut, g = m.damping, w = m.frequency, e2 = exp(-g * tc);
        rest = m.A * exp(-m.rate * tc) / m.rate +
               e2 * ((1 - m.A) * (g * cos(w * tc) - w * sin(w * tc)) + m.sine * (g * sin(w * tc) + w * cos(w * tc))) / (g * g + w * w);
    }
    CHECK_REL("integral: trapezoid to t_cut plus the model's tail", o.eta, RHO / (K2 * (trap + rest)), 1e-7);
    /* which differs from the exact integral by at most the infinite trapezoid sum's error */
    /* which differs from the exact integral by at most the composite trapezoid rule's error on
     * [0, t_cut], (t_cut / 12) DT^2 max |c''| */
    const double c2max = m.A * m.rate * m.rate +
                         hypot(1 - m.A, m.sine) * (m.damping * m.damping + m.frequency * m.frequency);
    CHECK_ABS("integral: within the trapezoid rule's error", RHO / (K2 * o.eta), exact, o.t_cut / 12 * DT * DT * c2max);
    print_message("integral %.8f, exact %.8f, trapezoid bound %.2g, infinite trapezoid sum's error %.2g\n",
                  RHO / (K2 * o.eta), exact, o.t_cut / 12 * DT * DT * c2max, modes_trapezoid(&m) - exact);
}

/* mean and sample standard deviation; median */
static void stats(const double *x, int n, double *mean, double *sd)
{
    double s = 0, ss = 0;
    for (int i = 0; i < n; i++) s += x[i];
    *mean = s / n;
    for (int i = 0; i < n; i++) ss += (x[i] - *mean) * (x[i] - *mean);
    *sd = sqrt(ss / (n - 1));
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *x, int n)
{
    qsort(x, (size_t)n, sizeof *x, cmp_double);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

static void check_ensemble(const char *what, const double *est, double *se, int n, double want, int se_is_bound)
{
    double mean, sd;
    stats(est, n, &mean, &sd);
    const double med = median(se, n), tol_sd = 4.0 / sqrt(2.0 * (n - 1));
    print_message("%s: mean %.5g (want %.5g, se of mean %.3g), sd %.4g, median %s %.4g\n", what, mean, want,
                  sd / sqrt(n), sd, se_is_bound ? "bound" : "se", med);
    char msg[160];
    snprintf(msg, sizeof msg, "%s: mean of %d estimates (4 se of the mean)", what, n);
    CHECK_ABS(msg, mean, want, 4 * sd / sqrt(n));
    if (se_is_bound) {
        snprintf(msg, sizeof msg, "%s: scatter below the any-correlation bound", what);
        CHECK_TRUE(sd <= med * (1 + tol_sd), "%s: sd %.4g > median bound %.4g (1 + %.2f)", msg, sd, med, tol_sd);
    } else {
        snprintf(msg, sizeof msg, "%s: scatter equals the propagated error (sampling error of an sd)", what);
        CHECK_REL(msg, sd / med, 1.0, tol_sd);
    }
}

/* realisation r of a curve by the three estimators: est[e][r] and err[e][r], the propagated error
 * or (bound) the any-correlation bound; eq. 28 (e = 0) only for one mode (with_exp) */
static void estimate(const double *t, const double *c, const double *se, int n, int with_exp, int bound, int r,
                     double est[3][R], double err[3][R])
{
    const RelaxationModel models[3] = {RELAXATION_EXP, RELAXATION_TWO_MODE, RELAXATION_INTEGRAL};
    for (int e = with_exp ? 0 : 1; e < 3; e++) {
        ShellViscosity o;
        assert_int_equal(shell_viscosity(models[e], t, c, se, n, K2, RHO, 0.3, &o), 0);
        est[e][r] = o.eta;
        err[e][r] = bound ? o.eta_se_bound : o.eta_se;
    }
}

/* white noise of known size on exact one- and two-mode curves */
static void white_noise_within_the_bound(void **state)
{
    (void)state;
    const Modes cases[2] = {{1.0, 2.5, 1.0, 0.0, 0.0}, {0.7, 2.0, 1.1, 24.5, -0.04}};
    const double SIGMA = 0.01;
    const int n = 201;
    uint64_t rng = 2024;
    for (int k = 0; k < 2; k++) {
        const Modes *m = &cases[k];
        double est[3][R], bound[3][R];
        for (int r = 0; r < R; r++) {
            double t[201], c[201], se[201];
            exact_curve(m, n, t, c, se, SIGMA);
            for (int l = 1; l < n; l++) c[l] += SIGMA * gauss(&rng);
            estimate(t, c, se, n, k == 0, 1, r, est, bound);   /* eq. 28 is not for two modes */
        }
        const double slow = RHO * m->rate / K2;
        double t0[201], c0[201], s0[201];
        exact_curve(m, n, t0, c0, s0, SIGMA);
        ShellViscosity exact_int;
        assert_int_equal(shell_viscosity(RELAXATION_INTEGRAL, t0, c0, s0, n, K2, RHO, 0.3, &exact_int), 0);
        if (k == 0) check_ensemble("white noise, one mode, exp", est[0], bound[0], R, slow, 1);
        check_ensemble(k ? "white noise, two modes, two-mode" : "white noise, one mode, two-mode", est[1], bound[1], R, slow, 1);
        /* the integral's expectation: its value on the exact curve (same t_cut rule) */
        check_ensemble(k ? "white noise, two modes, integral" : "white noise, one mode, integral", est[2], bound[2], R,
                       exact_int.eta, 1);
    }
}

/* A stationary Gaussian current J = sqrt(A) x + sqrt(1 - A) v: x an Ornstein-
 * Uhlenbeck mode of rate `rate`, v the velocity of a Brownian oscillator of
 * friction gamma = 2 damping and frequency w0^2 = frequency^2 + damping^2, both of
 * unit variance, sampled exactly every DT. Its normalised autocorrelation is
 *   A e^{-rate t} + (1 - A) e^{-damping t} (cos w t - (damping / w) sin w t). */
typedef struct { double ax, sx, m[4], ch[3]; double x, y, v; } Current;

static void current_init(Current *cu, const Modes *m, uint64_t *rng)
{
    const double g = 2 * m->damping, w = m->frequency, w0sq = w * w + m->damping * m->damping;
    cu->ax = exp(-m->rate * DT);
    cu->sx = sqrt(1 - cu->ax * cu->ax);
    /* e^{B DT}, B = [[0, 1], [-w0^2, -g]]: e^{-g DT / 2} [cos(w DT) 1 + sin(w DT) / w (B + g / 2)] */
    const double e = exp(-g * DT / 2), co = cos(w * DT), si = sin(w * DT) / w;
    cu->m[0] = e * (co + si * g / 2); cu->m[1] = e * si;
    cu->m[2] = e * (-si * w0sq);      cu->m[3] = e * (co - si * g / 2);
    /* stationary covariance diag(1 / w0^2, 1) (unit velocity variance); step noise S - M S M^T, Cholesky */
    const double S0 = 1 / w0sq, S1 = 1.0;
    const double q00 = S0 - (cu->m[0] * cu->m[0] * S0 + cu->m[1] * cu->m[1] * S1);
    const double q01 = -(cu->m[0] * cu->m[2] * S0 + cu->m[1] * cu->m[3] * S1);
    const double q11 = S1 - (cu->m[2] * cu->m[2] * S0 + cu->m[3] * cu->m[3] * S1);
    cu->ch[0] = sqrt(q00); cu->ch[1] = q01 / cu->ch[0]; cu->ch[2] = sqrt(q11 - cu->ch[1] * cu->ch[1]);
    cu->x = gauss(rng); cu->y = sqrt(S0) * gauss(rng); cu->v = gauss(rng);
}

static double current_step(Current *cu, const Modes *m, uint64_t *rng)
{
    cu->x = cu->ax * cu->x + cu->sx * gauss(rng);
    const double z0 = gauss(rng), z1 = gauss(rng);
    const double y = cu->m[0] * cu->y + cu->m[1] * cu->v + cu->ch[0] * z0;
    const double v = cu->m[2] * cu->y + cu->m[3] * cu->v + cu->ch[1] * z0 + cu->ch[2] * z1;
    cu->y = y; cu->v = v;
    return sqrt(m->A) * cu->x + sqrt(1 - m->A) * cu->v;
}

/* C(t)/C(0) of `samples` values of the current as src/measure/tcaf.c measures it: origins
 * every ORIGIN lags, window `n` lags, 20 contiguous blocks of origins; the mean
 * curve over all origins normalised by its C(0), the per-lag error the scatter of
 * the blocks' curves (each normalised by its own C(0)) / sqrt(20) */
enum { ORIGIN = 10, BLOCKS = 20 };

static void measured_curve(const Modes *m, int n, int samples, uint64_t *rng, double *t, double *c, double *se)
{
    double *J = malloc((size_t)samples * sizeof *J), *acc = calloc((size_t)BLOCKS * n, sizeof *acc);
    int cnt[BLOCKS] = {0};
    assert_non_null(J); assert_non_null(acc);
    Current cu;
    current_init(&cu, m, rng);
    for (int i = 0; i < 1000; i++) current_step(&cu, m, rng);
    for (int i = 0; i < samples; i++) J[i] = current_step(&cu, m, rng);
    const int norig = (samples - n) / ORIGIN + 1;
    for (int o = 0; o < norig; o++) {
        const int b = (int)((long long)o * BLOCKS / norig);
        for (int l = 0; l < n; l++) acc[(size_t)b * n + l] += J[o * ORIGIN] * J[o * ORIGIN + l];
        cnt[b]++;
    }
    for (int l = 0; l < n; l++) {
        double s = 0, s0 = 0, r[BLOCKS];
        for (int b = 0; b < BLOCKS; b++) { s += acc[(size_t)b * n + l]; s0 += acc[(size_t)b * n]; r[b] = acc[(size_t)b * n + l] / acc[(size_t)b * n]; }
        double mean, sd;
        stats(r, BLOCKS, &mean, &sd);
        t[l] = l * DT; c[l] = s / s0; se[l] = l ? sd / sqrt(BLOCKS) : 0.0;
    }
    (void)cnt;
    free(J); free(acc);
}

static void measured_current_errors_propagate(void **state)
{
    (void)state;
    /* slow mode tau = 0.3 beside an oscillation of period 0.26 (phi = 0.494's) decaying in 0.5 */
    const Modes cases[2] = {{1.0, 3.3, 2.0, 24.0, 0.0}, {0.7, 3.3, 2.0, 24.0, 0.0}};   /* case 0: the oscillator has no weight */
    const int n = 121, samples = 20000;   /* window 1.2, run 200 time units */
    uint64_t rng = 77;
    for (int k = 0; k < 2; k++) {
        Modes m = cases[k];
        if (k) m.sine = -(1 - m.A) * m.damping / m.frequency;   /* the oscillator's velocity */
        double est[3][R], err[3][R];
        for (int r = 0; r < R; r++) {
            double t[121], c[121], se[121];
            measured_curve(&m, n, samples, &rng, t, c, se);
            estimate(t, c, se, n, k == 0, 0, r, est, err);
        }
        const double slow = RHO * m.rate / K2, zero_frequency = RHO / (K2 * modes_integral(&m));
        if (k == 0) check_ensemble("measured current, one mode, exp", est[0], err[0], R, slow, 0);
        check_ensemble(k ? "measured current, two modes, two-mode" : "measured current, one mode, two-mode", est[1], err[1], R, slow, 0);
        check_ensemble(k ? "measured current, two modes, integral" : "measured current, one mode, integral", est[2], err[2], R,
                       zero_frequency, 0);
    }
}

/* the same fields, bit for bit (nan included) */
static int same_viscosity(const ShellViscosity *a, const ShellViscosity *b)
{
    const double x[] = {a->eta, a->eta_se, a->eta_se_bound, a->amplitude, a->amplitude_se, a->rate, a->rate_se,
                        a->damping, a->frequency, a->sine, a->chi2_dof, a->t_cut, a->integral, a->tail};
    const double y[] = {b->eta, b->eta_se, b->eta_se_bound, b->amplitude, b->amplitude_se, b->rate, b->rate_se,
                        b->damping, b->frequency, b->sine, b->chi2_dof, b->t_cut, b->integral, b->tail};
    return !memcmp(x, y, sizeof x) && a->points == b->points && a->modes == b->modes;
}

/* shell_viscosities: several models from one fit give each model's own call's numbers, bit for bit
 * (a measured two-mode curve, a measured one-mode curve, and one without errors, which no model fits) */
static void several_models_share_one_fit(void **state)
{
    (void)state;
    const Modes cases[2] = {{0.6, 2.0, 4.0, 25.0, 0.0}, {1.0, 3.0, 1.0, 0.0, 0.0}};
    const RelaxationModel all[3] = {RELAXATION_INTEGRAL, RELAXATION_EXP, RELAXATION_TWO_MODE};
    uint64_t rng = 91;
    for (int k = 0; k < 3; k++) {
        double t[121], c[121], se[121];
        if (k < 2) measured_curve(&cases[k], 121, 20000, &rng, t, c, se);
        else for (int i = 0; i < 121; i++) { t[i] = i * DT; c[i] = exp(-i * DT); se[i] = 0.0; }   /* no lag has an error */
        ShellViscosity both[3], one;
        const int rc = shell_viscosities(all, 3, t, c, se, 121, K2, RHO, 0.3, both);
        int each_rc = 0;
        for (int j = 0; j < 3; j++) {
            each_rc |= shell_viscosity(all[j], t, c, se, 121, K2, RHO, 0.3, &one);
            CHECK_TRUE(same_viscosity(&both[j], &one), "case %d, model %d: one shared fit differs from the model's own call", k, j);
        }
        CHECK_TRUE((rc != 0) == (each_rc != 0), "case %d: status %d, the calls' %d", k, rc, each_rc);
        if (k == 2) CHECK_TRUE(rc != 0 && isnan(both[0].eta) && isnan(both[1].eta) && isnan(both[2].eta),
                               "a curve without errors fitted: status %d", rc);
    }
}

/* a curve that cannot be fitted is refused, not answered */
static void refusals(void **state)
{
    (void)state;
    double t[5] = {0, 0.01, 0.02, 0.03, 0.04}, c[5] = {1, 0.2, 0.1, 0.05, 0.0}, se[5] = {0, 0.01, 0.01, 0.01, 0.01};
    ShellViscosity o;
    CHECK_TRUE(shell_viscosity(RELAXATION_EXP, t, c, se, 5, K2, RHO, 0.3, &o) != 0 && isnan(o.eta),
               "exp with fewer than 3 lags above fit_min: eta %g, want nan", o.eta);
    const double tb[5] = {0, 0.01, 0.03, 0.04, 0.05};
    CHECK_TRUE(shell_viscosity(RELAXATION_INTEGRAL, tb, c, se, 5, K2, RHO, 0.3, &o) != 0,
               "unevenly spaced lags accepted");
    CHECK_TRUE(shell_viscosity(RELAXATION_TWO_MODE, t, c, se, 5, -1.0, RHO, 0.3, &o) != 0, "k^2 < 0 accepted");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_mode_exact),
        cmocka_unit_test(two_mode_exact),
        cmocka_unit_test(white_noise_within_the_bound),
        cmocka_unit_test(measured_current_errors_propagate),
        cmocka_unit_test(several_models_share_one_fit),
        cmocka_unit_test(refusals),
    };
    return cmocka_run_group_tests_name("transverse_relaxation", tests, NULL, NULL);
}
