/* transverse_relaxation.c - eta(k) from a stored C(k,t)/C(k,0) by the single
 * exponential of eq. 28, a slow mode beside a damped oscillation, or the
 * zero-frequency integral; `dpd tcaf-fit`. See transverse_relaxation.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>
#include "tcaf.h"
#include "transverse_relaxation.h"

/* the two-mode parameters, in this order */
enum { P_AMPLITUDE, P_RATE, P_DAMPING, P_FREQUENCY, P_SINE, NPAR };

/* C/C0 = A e^{-rate t} + (1 - A) e^{-damping t} cos(w t) + S e^{-damping t} sin(w t);
 * one mode: A = 1, S = 0 (eq. 28 with a free rate) */
static double two_mode_value(const double *p, double t)
{
    const double e2 = exp(-p[P_DAMPING] * t), wt = p[P_FREQUENCY] * t;
    return p[P_AMPLITUDE] * exp(-p[P_RATE] * t) + e2 * ((1.0 - p[P_AMPLITUDE]) * cos(wt) + p[P_SINE] * sin(wt));
}

static void two_mode_gradient(const double *p, double t, double *d)
{
    const double e1 = exp(-p[P_RATE] * t), e2 = exp(-p[P_DAMPING] * t), wt = p[P_FREQUENCY] * t;
    const double co = cos(wt), si = sin(wt), A = p[P_AMPLITUDE], S = p[P_SINE];
    d[P_AMPLITUDE] = e1 - e2 * co;
    d[P_RATE] = -t * A * e1;
    d[P_DAMPING] = -t * e2 * ((1.0 - A) * co + S * si);
    d[P_FREQUENCY] = t * e2 * (-(1.0 - A) * si + S * co);
    d[P_SINE] = e2 * si;
}

/* integral_{tc}^inf of the model (the integral's tail beyond t_cut) */
static double two_mode_tail(const double *p, double tc)
{
    const double g = p[P_DAMPING], w = p[P_FREQUENCY], wt = w * tc, e2 = exp(-g * tc);
    double tail = p[P_AMPLITUDE] * exp(-p[P_RATE] * tc) / p[P_RATE];
    tail += e2 * ((1.0 - p[P_AMPLITUDE]) * (g * cos(wt) - w * sin(wt)) + p[P_SINE] * (g * sin(wt) + w * cos(wt))) / (g * g + w * w);
    return tail;
}

/* The lags of a fit: t > 0 with a finite value and a positive error. */
typedef struct {
    const double *t, *c, *se;
    int n;
    const int *free;          /* indices of the fitted parameters */
    int nfree;
    double *p;                /* all NPAR parameters (the fixed ones keep their values) */
} Curve;

static void set_free(const Curve *cv, const gsl_vector *x)
{
    for (int j = 0; j < cv->nfree; j++) cv->p[cv->free[j]] = gsl_vector_get(x, (size_t)j);
}

static int residual_f(const gsl_vector *x, void *data, gsl_vector *f)
{
    const Curve *cv = data;
    set_free(cv, x);
    for (int i = 0; i < cv->n; i++) gsl_vector_set(f, (size_t)i, two_mode_value(cv->p, cv->t[i]) - cv->c[i]);
    return GSL_SUCCESS;
}

static int residual_df(const gsl_vector *x, void *data, gsl_matrix *J)
{
    const Curve *cv = data;
    set_free(cv, x);
    double d[NPAR];
    for (int i = 0; i < cv->n; i++) {
        two_mode_gradient(cv->p, cv->t[i], d);
        for (int j = 0; j < cv->nfree; j++) gsl_matrix_set(J, (size_t)i, (size_t)j, d[cv->free[j]]);
    }
    return GSL_SUCCESS;
}

/* Starts of the two-mode fit by variable projection: on a grid of (rate,
 * damping, frequency) the model is linear in A and S, solved by weighted least
 * squares. Grids: rates from 0.1 / T to 1 / dt (log), damping 0.5 / T to 2 / dt
 * (log), frequency 0 to pi / (2 dt) (linear): T the last lag, dt the first. The
 * best point of each frequency is kept, and the STARTS best of those more than two
 * frequency steps apart start the nonlinear fit (the chi^2 surface of an
 * oscillation has a valley per frequency). Returns the number of starts. */
enum { GRID_RATE = 20, GRID_DAMPING = 20, GRID_FREQUENCY = 64, STARTS = 4 };
_Static_assert(GRID_RATE % 4 == 0, "the rate grid's sums are formed four rates at a time");

static int two_mode_starts(const Curve *cv, double start[STARTS][NPAR])
{
    const int n = cv->n;
    const double T = cv->t[n - 1], dt = cv->t[0];
    double *w = malloc((size_t)n * sizeof *w), *e = malloc((size_t)GRID_RATE * n * sizeof *e);
    double *gc = malloc((size_t)n * sizeof *gc), *gs = malloc((size_t)n * sizeof *gs);
    double *co = malloc((size_t)GRID_FREQUENCY * n * sizeof *co), *si = malloc((size_t)GRID_FREQUENCY * n * sizeof *si);
    double *ex = malloc((size_t)n * sizeof *ex);
    double see[GRID_RATE], sec[GRID_RATE], rates[GRID_RATE];
    if (!w || !e || !gc || !gs || !co || !si || !ex) { free(w); free(e); free(gc); free(gs); free(co); free(si); free(ex); return -1; }
    for (int f = 0; f < GRID_FREQUENCY; f++)
        for (int i = 0; i < n; i++) {
            const double om = (M_PI / (2.0 * dt)) * f / (GRID_FREQUENCY - 1.0);
            co[(size_t)f * n + i] = cos(om * cv->t[i]);
            si[(size_t)f * n + i] = sin(om * cv->t[i]);
        }
    for (int i = 0; i < n; i++) w[i] = 1.0 / (cv->se[i] * cv->se[i]);
    for (int a = 0; a < GRID_RATE; a++) {
        rates[a] = (0.1 / T) * pow((1.0 / dt) / (0.1 / T), a / (GRID_RATE - 1.0));
        see[a] = sec[a] = 0.0;
        for (int i = 0; i < n; i++) {
            const double x = exp(-rates[a] * cv->t[i]);
            e[(size_t)i * GRID_RATE + a] = w[i] * x;   /* weighted; lag-major: the rates of a lag side by side */
            see[a] += w[i] * x * x;
            sec[a] += w[i] * x * cv->c[i];
        }
    }
    double best[GRID_FREQUENCY], bp[GRID_FREQUENCY][NPAR];
    for (int f = 0; f < GRID_FREQUENCY; f++) best[f] = INFINITY;
    for (int b = 0; b < GRID_DAMPING; b++) {
        const double g = (0.5 / T) * pow((2.0 / dt) / (0.5 / T), b / (GRID_DAMPING - 1.0));
        for (int i = 0; i < n; i++) ex[i] = exp(-g * cv->t[i]);
        for (int f = 0; f < GRID_FREQUENCY; f++) {
            const double om = (M_PI / (2.0 * dt)) * f / (GRID_FREQUENCY - 1.0);
            double scc = 0, sss = 0, scs = 0, scy = 0, ssy = 0, syy = 0;
            for (int i = 0; i < n; i++) {
                gc[i] = ex[i] * co[(size_t)f * n + i];
                gs[i] = ex[i] * si[(size_t)f * n + i];
                const double y = cv->c[i] - gc[i];
                scc += w[i] * gc[i] * gc[i]; sss += w[i] * gs[i] * gs[i]; scs += w[i] * gc[i] * gs[i];
                scy += w[i] * gc[i] * y; ssy += w[i] * gs[i] * y; syy += w[i] * y * y;
            }
            /* the rates' sums over the lags four rates at a time, eight sums in registers (they
             * vectorise, and no sum waits on the one before): each rate's sum is still formed lag
             * by lag, in the same order */
            double sec_[GRID_RATE], ses[GRID_RATE];
            for (int a0 = 0; a0 < GRID_RATE; a0 += 4) {
                double c0 = 0, c1 = 0, c2 = 0, c3 = 0, s0 = 0, s1 = 0, s2 = 0, s3 = 0;
                for (int i = 0; i < n; i++) {
                    const double *ei = e + (size_t)i * GRID_RATE + a0, gci = gc[i], gsi = gs[i];
                    c0 += ei[0] * gci; c1 += ei[1] * gci; c2 += ei[2] * gci; c3 += ei[3] * gci;
                    s0 += ei[0] * gsi; s1 += ei[1] * gsi; s2 += ei[2] * gsi; s3 += ei[3] * gsi;
                }
                sec_[a0] = c0; sec_[a0 + 1] = c1; sec_[a0 + 2] = c2; sec_[a0 + 3] = c3;
                ses[a0] = s0; ses[a0 + 1] = s1; ses[a0 + 2] = s2; ses[a0 + 3] = s3;
            }
            for (int a = 0; a < GRID_RATE; a++) {
                /* basis b1 = e - gc (coefficient A), b2 = gs (S); y = c - gc */
                const double s11 = see[a] - 2 * sec_[a] + scc, s12 = ses[a] - scs, s22 = sss;
                const double s1y = (sec[a] - sec_[a]) - scy, s2y = ssy;
                double A, S, chi2;
                const double det = s11 * s22 - s12 * s12;
                if (s22 > 1e-12 * (s11 > 0 ? s11 : 1) && det > 1e-12 * s11 * s22) {
                    A = (s1y * s22 - s2y * s12) / det;
                    S = (s2y * s11 - s1y * s12) / det;
                    chi2 = syy - A * s1y - S * s2y;
                } else if (s11 > 0) {
                    A = s1y / s11; S = 0.0;
                    chi2 = syy - A * s1y;
                } else continue;
                if (chi2 < best[f]) {
                    best[f] = chi2;
                    bp[f][P_AMPLITUDE] = A; bp[f][P_RATE] = rates[a]; bp[f][P_DAMPING] = g; bp[f][P_FREQUENCY] = om; bp[f][P_SINE] = S;
                }
            }
        }
    }
    free(w); free(e); free(gc); free(gs); free(co); free(si); free(ex);
    int ns = 0, taken[GRID_FREQUENCY] = {0};
    while (ns < STARTS) {
        int fb = -1;
        for (int f = 0; f < GRID_FREQUENCY; f++)
            if (!taken[f] && isfinite(best[f]) && (fb < 0 || best[f] < best[fb])) fb = f;
        if (fb < 0) break;
        for (int f = fb - 2; f <= fb + 2; f++) if (f >= 0 && f < GRID_FREQUENCY) taken[f] = 1;
        memcpy(start[ns++], bp[fb], sizeof bp[fb]);
    }
    return ns;
}

/* Weighted nonlinear least squares (GSL trust region, Levenberg-Marquardt) of
 * the free parameters from p; on success p holds the fit and G (nfree x n) the
 * linear response of the parameters to the curve, dp_j / dc_i = G[j][i] / se_i,
 * with M^-1 = (J~^T J~)^-1 (J~ = J / se) in cov (nfree x nfree). */
static int weighted_fit(Curve *cv, double *G, double *cov, double *chi2_dof)
{
    const int n = cv->n, m = cv->nfree;
    if (n <= m) return -1;
    gsl_vector *x = gsl_vector_alloc((size_t)m), *wts = gsl_vector_alloc((size_t)n);
    gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
    gsl_multifit_nlinear_workspace *ws = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, (size_t)n, (size_t)m);
    gsl_matrix *M = gsl_matrix_alloc((size_t)m, (size_t)m), *Jt = gsl_matrix_alloc((size_t)n, (size_t)m);
    int rc = -1;
    if (!x || !wts || !ws || !M || !Jt) goto done;
    for (int j = 0; j < m; j++) gsl_vector_set(x, (size_t)j, cv->p[cv->free[j]]);
    for (int i = 0; i < n; i++) gsl_vector_set(wts, (size_t)i, 1.0 / (cv->se[i] * cv->se[i]));
    gsl_multifit_nlinear_fdf fdf = {.f = residual_f, .df = residual_df, .n = (size_t)n, .p = (size_t)m, .params = cv};
    gsl_multifit_nlinear_winit(x, wts, &fdf, ws);
    int info = 0;
    if (gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 1e-12, NULL, NULL, &info, ws) != GSL_SUCCESS) goto done;
    set_free(cv, gsl_multifit_nlinear_position(ws));
    /* J~ and M = J~^T J~ at the solution, then M^-1 and G = M^-1 J~^T */
    double d[NPAR], chi2 = 0.0;
    for (int i = 0; i < n; i++) {
        two_mode_gradient(cv->p, cv->t[i], d);
        for (int j = 0; j < m; j++) gsl_matrix_set(Jt, (size_t)i, (size_t)j, d[cv->free[j]] / cv->se[i]);
        const double r = (two_mode_value(cv->p, cv->t[i]) - cv->c[i]) / cv->se[i];
        chi2 += r * r;
    }
    gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, Jt, Jt, 0.0, M);
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    const int bad = gsl_linalg_cholesky_decomp1(M) || gsl_linalg_cholesky_invert(M);
    gsl_set_error_handler(old);
    if (bad) goto done;
    for (int a = 0; a < m; a++) {
        for (int b = 0; b < m; b++) cov[a * m + b] = gsl_matrix_get(M, (size_t)a, (size_t)b);
        for (int i = 0; i < n; i++) {
            double s = 0.0;
            for (int b = 0; b < m; b++) s += gsl_matrix_get(M, (size_t)a, (size_t)b) * gsl_matrix_get(Jt, (size_t)i, (size_t)b);
            G[(size_t)a * n + i] = s;
        }
    }
    *chi2_dof = chi2 / (n - m);
    rc = 0;
done:
    gsl_vector_free(x); gsl_vector_free(wts);
    if (ws) gsl_multifit_nlinear_free(ws);
    gsl_matrix_free(M); gsl_matrix_free(Jt);
    return rc;
}

static void set_nan(ShellViscosity *o)
{
    o->eta = o->eta_se = o->eta_se_bound = NAN;
    o->amplitude = o->amplitude_se = o->rate = o->rate_se = NAN;
    o->damping = o->frequency = o->sine = o->chi2_dof = NAN;
    o->t_cut = o->integral = o->tail = NAN;
    o->points = o->modes = 0;
}

/* The correlation of the errors of the fitted lags (table lags lag[i], t = lag
 * dt) for the normalised autocorrelation of a stationary Gaussian current,
 * Bartlett's formula (1946):
 *   K(a, b) = A(b - a) + A(a + b) - 2 c(b) A(a) - 2 c(a) A(b) + 2 c(a) c(b) A(0),
 *   A(d) = sum_j c(j dt) c((j + d) dt) over all j, c even in t,
 * with c the fitted model (p) at every lag and beyond the stored window;
 * returns the m x m matrix K(a, b) / sqrt(K(a, a) K(b, b)) (malloc'd; NULL on
 * failure). The per-lag errors measured over blocks of origins set the scale. */
static double *lag_correlation(const double *p, int modes, double dt, const int *lag, int m)
{
    const int lmax = lag[m - 1];
    double slowest = p[P_RATE];
    if (modes == 2 && p[P_DAMPING] < slowest) slowest = p[P_DAMPING];
    const long long jl = lmax + (long long)ceil(12.0 / (slowest * dt));   /* products below e^-24 */
    const int J = (int)(jl > 200000 ? 200000 : jl);
    const int nc = J + 2 * lmax + 1;
    double *c = malloc((size_t)nc * sizeof *c), *A = malloc((size_t)(2 * lmax + 1) * sizeof *A);
    double *rs = malloc((size_t)m * sizeof *rs), *corr = malloc((size_t)m * m * sizeof *corr);
    if (!c || !A || !rs || !corr) { free(c); free(A); free(rs); free(corr); return NULL; }
    for (int j = 0; j < nc; j++) c[j] = two_mode_value(p, j * dt);
    for (int d = 0; d <= 2 * lmax; d++) {
        /* j and -j - d give the same product (c even) */
        double s = 0.0;
        for (int j = -J; j <= J; j++) s += c[j < 0 ? -j : j] * c[j + d < 0 ? -(j + d) : j + d];
        A[d] = s;
    }
#define KC(a, b) (A[(a) > (b) ? (a) - (b) : (b) - (a)] + A[(a) + (b)] - 2 * c[b] * A[a] - 2 * c[a] * A[b] + 2 * c[a] * c[b] * A[0])
    for (int i = 0; i < m; i++) { const double k = KC(lag[i], lag[i]); rs[i] = k > 0 ? 1.0 / sqrt(k) : 0.0; }
    for (int i = 0; i < m; i++)
        for (int k = 0; k < m; k++) corr[(size_t)i * m + k] = KC(lag[i], lag[k]) * rs[i] * rs[k];
#undef KC
    free(c); free(A); free(rs);
    return corr;
}

/* standard error of sum_i g_i (c_i - <c_i>), errors sig_i correlated as corr */
static double correlated_se(const double *corr, const double *g, const double *sig, int m)
{
    if (!corr) return NAN;
    double v = 0.0;
    for (int i = 0; i < m; i++) {
        const double gi = g[i] * sig[i];
        if (gi == 0.0) continue;
        for (int k = 0; k < m; k++) v += gi * g[k] * sig[k] * corr[(size_t)i * m + k];
    }
    return v > 0 ? sqrt(v) : 0.0;
}

/* the fit's row of parameter j in G, or -1 if j was held fixed */
static int row_of(const Curve *cv, int j)
{
    for (int r = 0; r < cv->nfree; r++) if (cv->free[r] == j) return r;
    return -1;
}

/* The two-mode fit where its oscillation is resolved, else one mode. Two modes
 * are kept when the fit (the best of the starts) converges with positive rates,
 * the damped cosine completes at least two periods in the stored window
 * (|w| T >= 4 pi) and its amplitude |(1 - A, S)| exceeds twice its standard
 * error (lags independent): without an oscillation (a simple fluid) the split of
 * C into two modes is not determined, and the curve is fitted with one mode,
 * C/C0 = e^{-rate t}, over the same lags and weights. */
static const int ALL_PARAMETERS[NPAR] = {P_AMPLITUDE, P_RATE, P_DAMPING, P_FREQUENCY, P_SINE};
static const int RATE_ONLY[1] = {P_RATE};

static int fit_relaxation(Curve *cv, double *G, double *cov, double *chi2_dof, int *modes)
{
    const double T = cv->t[cv->n - 1];
    double start[STARTS][NPAR], best[NPAR], best_chi2 = INFINITY, tcov[NPAR * NPAR];
    double *tG = malloc((size_t)NPAR * cv->n * sizeof *tG);
    if (!tG) return -1;
    cv->free = ALL_PARAMETERS; cv->nfree = NPAR;
    const int ns = cv->n >= 2 * NPAR ? two_mode_starts(cv, start) : 0;
    for (int s = 0; s < ns; s++) {
        double chi2;
        memcpy(cv->p, start[s], sizeof start[s]);
        if (weighted_fit(cv, tG, tcov, &chi2) == 0 && chi2 < best_chi2) {
            best_chi2 = chi2;
            memcpy(best, cv->p, sizeof best);
            memcpy(G, tG, (size_t)NPAR * cv->n * sizeof *G);
            memcpy(cov, tcov, sizeof tcov);
        }
    }
    free(tG);
    if (isfinite(best_chi2)) {
        memcpy(cv->p, best, sizeof best);
        *chi2_dof = best_chi2;
        /* the oscillation's amplitude h = |(1 - A, S)| and its error (lags independent, cov) */
        const double a1 = 1.0 - cv->p[P_AMPLITUDE], s1 = cv->p[P_SINE], h = hypot(a1, s1);
        const double dA = h > 0 ? -a1 / h : 0.0, dS = h > 0 ? s1 / h : 0.0;
        const double h_var = dA * dA * cov[P_AMPLITUDE * NPAR + P_AMPLITUDE] + 2 * dA * dS * cov[P_AMPLITUDE * NPAR + P_SINE] +
                             dS * dS * cov[P_SINE * NPAR + P_SINE];
        if (cv->p[P_RATE] > 0 && cv->p[P_DAMPING] > 0 && fabs(cv->p[P_FREQUENCY]) * T >= 4 * M_PI && h > 2 * sqrt(h_var)) {
            *modes = 2;
            return 0;
        }
    }
    /* one mode, started from the area under the curve up to its first value below 0.05 */
    double area = 0.0, tp = 0.0, cp = 1.0;
    for (int i = 0; i < cv->n && cp >= 0.05; i++) { area += 0.5 * (cv->t[i] - tp) * (cp + cv->c[i]); tp = cv->t[i]; cp = cv->c[i]; }
    const double p0[NPAR] = {1.0, area > 0 ? 1.0 / area : 1.0 / T, 1.0, 0.0, 0.0};
    memcpy(cv->p, p0, sizeof p0);
    cv->free = RATE_ONLY; cv->nfree = 1;
    if (weighted_fit(cv, G, cov, chi2_dof) || !(cv->p[P_RATE] > 0)) return -1;
    *modes = 1;
    return 0;
}

/* eq. 28 as the simulator fits it (src/measure/tcaf.c tcaf_fit_eta: unweighted, amplitude 1,
 * lags while <C/C0> >= fit_min); the response d eta / d c_i = J_i / sum J^2 (Gauss-Newton). */
static int single_exponential(const double *t, const double *c, const double *se, int n, double k2, double rho,
                              double fit_min, ShellViscosity *o)
{
    int m = 0;
    while (m + 1 < n && c[m + 1] >= fit_min && se[m + 1] > 0) m++;
    if (m < 3) return -1;   /* decay not resolved by the sampling interval (as src/measure/tcaf.c) */
    double eta;
    if (tcaf_fit_eta(t + 1, c + 1, m, k2, rho, &eta)) return -1;
    const double a = k2 / rho;
    double sjj = 0.0, bound = 0.0, *g = malloc((size_t)m * sizeof *g);
    int *lag = malloc((size_t)m * sizeof *lag);
    if (!g || !lag) { free(g); free(lag); return -1; }
    for (int i = 1; i <= m; i++) { const double J = -a * t[i] * exp(-eta * a * t[i]); sjj += J * J; }
    for (int i = 1; i <= m; i++) {
        g[i - 1] = -a * t[i] * exp(-eta * a * t[i]) / sjj;
        lag[i - 1] = i;
        bound += fabs(g[i - 1]) * se[i];
    }
    const double p[NPAR] = {1.0, eta * a, 1.0, 0.0, 0.0};
    double *corr = lag_correlation(p, 1, t[1], lag, m);
    o->eta = eta; o->eta_se = correlated_se(corr, g, se + 1, m); o->eta_se_bound = bound;
    free(g); free(lag); free(corr);
    o->amplitude = 1.0; o->amplitude_se = 0.0;
    o->rate = eta * a; o->rate_se = o->eta_se * a;
    o->points = m;
    o->modes = 1;
    o->t_cut = t[m];
    return 0;
}

/* The integral estimator: eta = rho / (k^2 int C/C0 dt), the data up to t_cut
 * (trapezoid from t = 0, C/C0 = 1; t_cut where the fitted slow mode falls
 * below the error) and the fitted model beyond; its error from g = d integral
 * / d c_i, the tail's response through the fitted parameters included. */
static int integral_viscosity(const Curve *cv, const double *G, const double *corr, double *g,
                              double scale, ShellViscosity *o)
{
    const double *ft = cv->t, *fc = cv->c, *fs = cv->se, *p = cv->p;
    const int m = cv->n;
    int cut = m - 1;
    for (int i = 0; i < m; i++)
        if (p[P_AMPLITUDE] * exp(-p[P_RATE] * ft[i]) < fs[i]) { cut = i; break; }
    double integral = 0.0, tprev = 0.0, cprev = 1.0;
    memset(g, 0, (size_t)m * sizeof *g);
    for (int i = 0; i <= cut; i++) {
        const double h = ft[i] - tprev;
        integral += 0.5 * h * (cprev + fc[i]);
        g[i] += 0.5 * h;
        if (i > 0) g[i - 1] += 0.5 * h;
        tprev = ft[i]; cprev = fc[i];
    }
    const double tail = two_mode_tail(p, ft[cut]);
    /* the tail's response to the curve through the fitted parameters (central differences) */
    for (int r = 0; r < cv->nfree; r++) {
        const int j = cv->free[r];
        double q[NPAR];
        memcpy(q, p, sizeof q);
        const double h = 1e-6 * (fabs(p[j]) > 1e-3 ? fabs(p[j]) : 1e-3);
        q[j] = p[j] + h; const double up = two_mode_tail(q, ft[cut]);
        q[j] = p[j] - h; const double dn = two_mode_tail(q, ft[cut]);
        const double dtail = (up - dn) / (2 * h);
        for (int i = 0; i < m; i++) g[i] += dtail * G[(size_t)r * m + i] / fs[i];
    }
    integral += tail;
    if (!(integral > 0)) return -1;
    double bound = 0.0;
    for (int i = 0; i < m; i++) bound += fabs(g[i]) * fs[i];
    o->integral = integral; o->tail = tail; o->t_cut = ft[cut];
    o->eta = scale / integral;
    o->eta_se = scale * correlated_se(corr, g, fs, m) / (integral * integral);
    o->eta_se_bound = scale * bound / (integral * integral);
    return 0;
}

/* eta(k) by the two-mode or the integral model from the fitted curve cv (G its
 * parameters' responses, corr the lags' correlation); o holds the fit's fields
 * already, g is scratch (m lags). */
static int fitted_viscosity(RelaxationModel model, const Curve *cv, const double *G, const double *corr,
                            double *g, double scale, ShellViscosity *o)
{
    const int m = cv->n, rr = row_of(cv, P_RATE);
    if (model == RELAXATION_INTEGRAL) return integral_viscosity(cv, G, corr, g, scale, o);
    /* eq. 28 for the slow mode: eta = rho rate / k^2 */
    double bound = 0.0;
    for (int i = 0; i < m; i++) { g[i] = G[(size_t)rr * m + i] / cv->se[i]; bound += fabs(g[i]) * cv->se[i]; }
    o->eta = scale * cv->p[P_RATE];
    o->eta_se = scale * o->rate_se;
    o->eta_se_bound = scale * bound;
    o->t_cut = cv->t[m - 1];
    return 0;
}

int shell_viscosities(const RelaxationModel *models, int nmodels, const double *t, const double *c,
                      const double *se, int n, double k2, double rho, double fit_min, ShellViscosity *out)
{
    int rc = 0, fitted = 0;
    for (int j = 0; j < nmodels; j++) {
        set_nan(&out[j]);
        if (models[j] != RELAXATION_EXP) fitted = 1;
    }
    if (n < 3 || !(k2 > 0) || !(rho > 0) || t[0] != 0.0 || !(t[1] > 0)) return -1;
    const double dt = t[1];
    for (int i = 2; i < n; i++)
        if (fabs(t[i] - i * dt) > 1e-6 * i * dt) return -1;   /* lags evenly spaced from t = 0 */
    for (int j = 0; j < nmodels; j++)
        if (models[j] == RELAXATION_EXP && single_exponential(t, c, se, n, k2, rho, fit_min, &out[j])) {
            set_nan(&out[j]);
            rc = -1;
        }
    if (!fitted) return rc;
    /* the two-mode fit behind both the two-mode and the integral model: made once */
    double *ft = malloc((size_t)n * sizeof *ft), *fc = malloc((size_t)n * sizeof *fc), *fs = malloc((size_t)n * sizeof *fs);
    double *G = malloc((size_t)NPAR * n * sizeof *G), *g = calloc((size_t)n, sizeof *g), *corr = NULL;
    int *lag = malloc((size_t)n * sizeof *lag);
    int frc = -1, m = 0, modes = 0;
    double p[NPAR] = {1.0, 1.0, 1.0, 0.0, 0.0}, cov[NPAR * NPAR], chi2_dof;
    Curve cv = {ft, fc, fs, 0, ALL_PARAMETERS, NPAR, p};
    ShellViscosity fit;
    set_nan(&fit);
    if (!ft || !fc || !fs || !lag || !G || !g) goto done;
    /* the lags of the fit: t > 0, finite, positive error */
    for (int i = 1; i < n; i++)
        if (isfinite(c[i]) && se[i] > 0 && isfinite(se[i])) { ft[m] = t[i]; fc[m] = c[i]; fs[m] = se[i]; lag[m] = i; m++; }
    cv.n = m;
    if (m < 3 || fit_relaxation(&cv, G, cov, &chi2_dof, &modes)) goto done;
    const int ra = row_of(&cv, P_AMPLITUDE), rr = row_of(&cv, P_RATE);
    /* the parameters' errors with the lags correlated (Bartlett), from their responses G / se */
    if (!(corr = lag_correlation(p, modes, dt, lag, m))) goto done;
    for (int i = 0; i < m; i++) g[i] = ra >= 0 ? G[(size_t)ra * m + i] / fs[i] : 0.0;
    fit.amplitude = p[P_AMPLITUDE];
    fit.amplitude_se = ra >= 0 ? correlated_se(corr, g, fs, m) : 0.0;
    for (int i = 0; i < m; i++) g[i] = G[(size_t)rr * m + i] / fs[i];
    fit.rate = p[P_RATE];
    fit.rate_se = correlated_se(corr, g, fs, m);
    if (modes == 2) { fit.damping = p[P_DAMPING]; fit.frequency = fabs(p[P_FREQUENCY]); fit.sine = p[P_FREQUENCY] < 0 ? -p[P_SINE] : p[P_SINE]; }
    fit.chi2_dof = chi2_dof;
    fit.points = m;
    fit.modes = modes;
    frc = 0;
done:
    for (int j = 0; j < nmodels; j++) {
        if (models[j] == RELAXATION_EXP) continue;
        out[j] = fit;
        if (frc || fitted_viscosity(models[j], &cv, G, corr, g, rho / k2, &out[j])) {
            set_nan(&out[j]);
            out[j].points = fit.points;
            rc = -1;
        }
    }
    free(ft); free(fc); free(fs); free(lag); free(G); free(g); free(corr);
    return rc;
}

int shell_viscosity(RelaxationModel model, const double *t, const double *c, const double *se, int n,
                    double k2, double rho, double fit_min, ShellViscosity *o)
{
    return shell_viscosities(&model, 1, t, c, se, n, k2, rho, fit_min, o);
}

/* ---- dpd tcaf-fit ---- */

typedef struct {
    int nlag, nshell;
    double *t;          /* nlag */
    double *c, *se;     /* nshell x nlag */
    int *n2;            /* nshell */
} TcafTable;

static void table_free(TcafTable *tb)
{
    free(tb->t); free(tb->c); free(tb->se); free(tb->n2);
    memset(tb, 0, sizeof *tb);
}

/* a run's tcaf.tsv: comment lines, the header "t c_n2_N c_n2_N_se ...", one row per lag */
static int table_read(const char *path, TcafTable *tb)
{
    memset(tb, 0, sizeof *tb);
    FILE *f = fopen(path, "r");
    if (!f) { fprintf(stderr, "dpd tcaf-fit: cannot open '%s'\n", path); return 4; }
    char *line = NULL;
    size_t cap = 0;
    int ncol = 0, *col_shell = NULL, *col_is_se = NULL, rc = 0, lineno = 0, rowcap = 0;
    double *vals = NULL;
    while (getline(&line, &cap, f) > 0) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (!ncol) {
            int k = 0;
            for (char *s = line; *s; s++) if (*s == '\t') k++;
            ncol = k + 1;
            col_shell = calloc((size_t)ncol, sizeof *col_shell);
            col_is_se = calloc((size_t)ncol, sizeof *col_is_se);
            tb->n2 = calloc((size_t)ncol, sizeof *tb->n2);
            vals = calloc((size_t)ncol, sizeof *vals);
            if (!col_shell || !col_is_se || !tb->n2 || !vals) { rc = 1; break; }
            k = 0;
            for (char *tok = strtok(line, "\t\n"); tok; tok = strtok(NULL, "\t\n"), k++) {
                int n2, len = 0;
                col_shell[k] = -1;
                if (k == 0) {
                    if (strcmp(tok, "t")) break;
                    continue;
                }
                if (sscanf(tok, "c_n2_%d%n", &n2, &len) != 1) continue;
                if (tok[len] == '\0') { tb->n2[tb->nshell] = n2; col_shell[k] = tb->nshell++; }
                else if (!strcmp(tok + len, "_se") && tb->nshell > 0 && tb->n2[tb->nshell - 1] == n2) {
                    col_shell[k] = tb->nshell - 1; col_is_se[k] = 1;
                }
            }
            if (k == 0 || tb->nshell == 0) {
                fprintf(stderr, "dpd tcaf-fit: %s line %d: expected the header of a tcaf.tsv "
                                "(t, c_n2_N, c_n2_N_se, ...)\n", path, lineno);
                rc = 2;
                break;
            }
            continue;
        }
        if (tb->nlag == rowcap) {
            rowcap = rowcap ? 2 * rowcap : 256;
            double *t2 = realloc(tb->t, (size_t)rowcap * sizeof *t2);
            if (t2) tb->t = t2;
            double *c2 = t2 ? realloc(tb->c, (size_t)rowcap * tb->nshell * sizeof *c2) : NULL;
            if (c2) tb->c = c2;
            double *s2 = c2 ? realloc(tb->se, (size_t)rowcap * tb->nshell * sizeof *s2) : NULL;
            if (s2) tb->se = s2;
            if (!t2 || !c2 || !s2) { fprintf(stderr, "dpd tcaf-fit: %s: out of memory\n", path); rc = 1; break; }
        }
        int k = 0;
        for (char *tok = strtok(line, "\t\n"); tok && k < ncol; tok = strtok(NULL, "\t\n")) vals[k++] = strtod(tok, NULL);
        if (k < ncol) {
            fprintf(stderr, "dpd tcaf-fit: %s line %d: %d columns, the header has %d\n", path, lineno, k, ncol);
            rc = 2;
            break;
        }
        tb->t[tb->nlag] = vals[0];
        for (int j = 1; j < ncol; j++) {
            if (col_shell[j] < 0) continue;
            double *dst = col_is_se[j] ? tb->se : tb->c;
            dst[(size_t)tb->nlag * tb->nshell + col_shell[j]] = vals[j];
        }
        tb->nlag++;
    }
    free(line); free(col_shell); free(col_is_se); free(vals);
    fclose(f);
    if (rc == 0 && tb->nlag < 3) {
        fprintf(stderr, "dpd tcaf-fit: %s: %d lags; need at least 3\n", path, tb->nlag);
        rc = 2;
    }
    if (rc == 0 && !(tb->t[0] == 0.0)) {
        fprintf(stderr, "dpd tcaf-fit: %s: the first lag is t = %g, expected 0 (C/C0 = 1)\n", path, tb->t[0]);
        rc = 2;
    }
    if (rc) table_free(tb);
    return rc;
}

static const char *model_name(RelaxationModel m)
{
    return m == RELAXATION_EXP ? "exp" : m == RELAXATION_TWO_MODE ? "two-mode" : "integral";
}

static int parse_double(const char *opt, const char *v, double lo, double hi, double *out)
{
    char *end;
    const double x = strtod(v, &end);
    if (end == v || *end || !(x >= lo && x <= hi)) {
        fprintf(stderr, "dpd tcaf-fit: %s '%s': expected a number in [%g, %g]\n", opt, v, lo, hi);
        return -1;
    }
    *out = x;
    return 0;
}

/* The options of dpd tcaf-fit. */
typedef struct {
    const char *file, *table, *curves, *summary;
    double rho, box, fit_min, kmax;
    int order;
    RelaxationModel models[3];
    int nmodels;
} TcafFitArgs;

/* --model exp|two-mode|integral, or several, comma separated, each once */
static int parse_models(const char *v, TcafFitArgs *a)
{
    a->nmodels = 0;
    for (const char *s = v;;) {
        const size_t len = strcspn(s, ",");
        RelaxationModel m;
        if (len == 3 && !strncmp(s, "exp", len)) m = RELAXATION_EXP;
        else if (len == 8 && !strncmp(s, "two-mode", len)) m = RELAXATION_TWO_MODE;
        else if (len == 8 && !strncmp(s, "integral", len)) m = RELAXATION_INTEGRAL;
        else { fprintf(stderr, "dpd tcaf-fit: --model '%s': expected exp, two-mode or integral, or several of them comma separated\n", v); return -1; }
        for (int j = 0; j < a->nmodels; j++)
            if (a->models[j] == m) { fprintf(stderr, "dpd tcaf-fit: --model '%s': %s twice\n", v, model_name(m)); return -1; }
        a->models[a->nmodels++] = m;
        if (!s[len]) return 0;
        s += len + 1;
    }
}

/* a per-model output name: NAME with %m replaced by the model's name */
static int model_path(const char *name, RelaxationModel m, char *out, size_t cap)
{
    const char *at = strstr(name, "%m");
    const int n = at ? snprintf(out, cap, "%.*s%s%s", (int)(at - name), name, model_name(m), at + 2)
                     : snprintf(out, cap, "%s", name);
    if (n < 0 || (size_t)n >= cap) { fprintf(stderr, "dpd tcaf-fit: the file name '%s' is too long\n", name); return -1; }
    return 0;
}

static int tcaf_fit_args(int argc, char **argv, TcafFitArgs *a)
{
    double order_d = 1;
    *a = (TcafFitArgs){.rho = NAN, .box = NAN, .fit_min = 0.3, .kmax = 2.0, .models = {RELAXATION_TWO_MODE}, .nmodels = 1};
    for (int k = 0; k < argc; k++) {
        const char *o = argv[k];
        if (o[0] != '-') {
            if (a->file) { fprintf(stderr, "dpd tcaf-fit: more than one table given ('%s', '%s')\n", a->file, o); return 1; }
            a->file = o;
            continue;
        }
        if (k + 1 >= argc) { fprintf(stderr, "dpd tcaf-fit: %s needs a value\n", o); return 1; }
        const char *v = argv[++k];
        int bad = 0;
        if (!strcmp(o, "--rho")) bad = parse_double(o, v, 1e-12, 1e12, &a->rho);
        else if (!strcmp(o, "--box")) bad = parse_double(o, v, 1e-12, 1e12, &a->box);
        else if (!strcmp(o, "--fit-min")) bad = parse_double(o, v, 1e-6, 0.99, &a->fit_min);
        else if (!strcmp(o, "--kmax")) bad = parse_double(o, v, 0.0, 1e9, &a->kmax);
        else if (!strcmp(o, "--order")) bad = parse_double(o, v, 0, 3, &order_d) || order_d != floor(order_d);
        else if (!strcmp(o, "--table")) a->table = v;
        else if (!strcmp(o, "--curves")) a->curves = v;
        else if (!strcmp(o, "--summary")) a->summary = v;
        else if (!strcmp(o, "--model")) { if (parse_models(v, a)) return 1; }
        else { fprintf(stderr, "dpd tcaf-fit: unknown option %s\n", o); return 1; }
        if (bad) { if (!strcmp(o, "--order")) fprintf(stderr, "dpd tcaf-fit: --order: 0, 1, 2 or 3\n"); return 1; }
    }
    if (!a->file || !isfinite(a->rho) || !isfinite(a->box)) {
        fprintf(stderr, "usage: dpd tcaf-fit TCAF_TSV --rho R --box L [--model exp|two-mode|integral[,...]] [--fit-min F]\n"
                        "                    [--kmax K] [--order P] [--table FILE] [--curves FILE] [--summary FILE]\n");
        return 1;
    }
    /* several models: a file per model, named through %m; the summaries cannot share stdout */
    if (a->nmodels > 1) {
        if (!a->summary) { fprintf(stderr, "dpd tcaf-fit: --model with %d models needs --summary FILE (with %%m)\n", a->nmodels); return 1; }
        const char *named[3][2] = {{"--summary", a->summary}, {"--table", a->table}, {"--curves", a->curves}};
        for (int j = 0; j < 3; j++)
            if (named[j][1] && !strstr(named[j][1], "%m")) {
                fprintf(stderr, "dpd tcaf-fit: %s '%s': with several models it must name each model's file with %%m\n", named[j][0], named[j][1]);
                return 1;
            }
    }
    a->order = (int)order_d;
    return 0;
}

/* eta(k) of every shell, and the extrapolation k -> 0 over |k| <= kmax. */
typedef struct {
    int S, P, nx;             /* shells, polynomial coefficients, shells in the extrapolation */
    ShellViscosity *sv;
    double *k;                /* |k| of each shell */
    double coef[4], coef_se[4], c0_bound, chi2_dof;
    RelaxationModel model;
} TcafFit;

static void tcaf_fit_free(TcafFit *f) { free(f->sv); free(f->k); }

/* eta(k) per shell from the table's columns, f[j] by the j-th model (shell_viscosities: one
 * fit for them all). */
static int fit_shells(const TcafTable *tb, const TcafFitArgs *a, TcafFit *f)
{
    const int L = tb->nlag, S = tb->nshell, M = a->nmodels;
    int ok = 1;
    for (int j = 0; j < M; j++) {
        f[j].S = S;
        f[j].model = a->models[j];
        f[j].sv = calloc((size_t)S, sizeof *f[j].sv);
        f[j].k = malloc((size_t)S * sizeof *f[j].k);
        ok = ok && f[j].sv && f[j].k;
    }
    double *cc = malloc((size_t)L * sizeof *cc), *ss = malloc((size_t)L * sizeof *ss);
    ok = ok && cc && ss;
    for (int q = 0; ok && q < S; q++) {
        const double k = 2.0 * M_PI * sqrt((double)tb->n2[q]) / a->box;
        ShellViscosity sv[3];
        for (int l = 0; l < L; l++) { cc[l] = tb->c[(size_t)l * S + q]; ss[l] = tb->se[(size_t)l * S + q]; }
        shell_viscosities(a->models, M, tb->t, cc, ss, L, k * k, a->rho, a->fit_min, sv);
        for (int j = 0; j < M; j++) { f[j].k[q] = k; f[j].sv[q] = sv[j]; }
    }
    free(cc); free(ss);
    return ok ? 0 : -1;
}

/* k -> 0: weighted polynomial in k^2 (src/measure/tcaf.c) over the fitted shells with
 * |k| <= kmax, covariance scaled by chi^2/dof when > 1; and its error from the
 * shells' bounds (shells independent): dc0/deta_i = sum_j cov_0j k_i^2j w_i. */
static int extrapolate_shells(const TcafFitArgs *a, TcafFit *f)
{
    const int S = f->S, P = a->order + 1;
    double *kx = malloc((size_t)S * sizeof *kx), *ex = malloc((size_t)S * sizeof *ex), *wx = malloc((size_t)S * sizeof *wx);
    double *si = malloc((size_t)S * sizeof *si);
    if (!kx || !ex || !wx || !si) { free(kx); free(ex); free(wx); free(si); return -1; }
    int nx = 0;
    for (int q = 0; q < S; q++)
        if (f->k[q] <= a->kmax * (1 + 1e-12) && isfinite(f->sv[q].eta) && f->sv[q].eta_se > 0) {
            kx[nx] = f->k[q]; ex[nx] = f->sv[q].eta; wx[nx] = 1.0 / (f->sv[q].eta_se * f->sv[q].eta_se);
            si[nx] = f->sv[q].eta_se_bound; nx++;
        }
    double cov[16], chi2 = NAN;
    for (int p = 0; p < 4; p++) f->coef[p] = f->coef_se[p] = NAN;
    f->P = P; f->nx = nx; f->c0_bound = NAN;
    const int fitted = nx > P && tcaf_extrapolate_cov(kx, ex, wx, nx, a->order, f->coef, cov, &chi2) == 0;
    f->chi2_dof = fitted ? chi2 / (nx - P) : NAN;
    const double sc = f->chi2_dof > 1.0 ? f->chi2_dof : 1.0;
    if (fitted) {
        for (int p = 0; p < P; p++) f->coef_se[p] = sqrt(sc * cov[p * P + p]);
        double v = 0.0;
        for (int i = 0; i < nx; i++) {
            double d = 0.0, xp = 1.0;
            for (int j = 0; j < P; j++) { d += cov[j] * xp; xp *= kx[i] * kx[i]; }
            d *= wx[i];
            v += d * d * si[i] * si[i];
        }
        f->c0_bound = sqrt(sc * v);
    } else for (int p = 0; p < P; p++) f->coef[p] = NAN;
    free(kx); free(ex); free(wx); free(si);
    return 0;
}

/* the quantity/value/stderr rows: to stdout (path NULL) or to path */
static int write_fit_summary(const TcafTable *tb, const TcafFit *f, const char *path)
{
    FILE *out = path ? fopen(path, "w") : stdout;
    if (!out) { fprintf(stderr, "dpd tcaf-fit: cannot write '%s'\n", path); return 4; }
    fprintf(out, "quantity\tvalue\tstderr\n");
    fprintf(out, "eta_k0\t%.10g\t%.4g\n", f->coef[0], f->coef_se[0]);
    if (f->P > 1) fprintf(out, "eta_k2_coefficient\t%.10g\t%.4g\n", f->coef[1], f->coef_se[1]);
    if (f->P > 2) fprintf(out, "eta_k4_coefficient\t%.10g\t%.4g\n", f->coef[2], f->coef_se[2]);
    if (f->P > 3) fprintf(out, "eta_k6_coefficient\t%.10g\t%.4g\n", f->coef[3], f->coef_se[3]);
    fprintf(out, "eta_k0_se_bound\t%.4g\t0\n", f->c0_bound);
    fprintf(out, "extrapolation_chi2_dof\t%.6g\t0\n", f->chi2_dof);
    fprintf(out, "extrapolation_shells\t%d\t0\n", f->nx);
    for (int q = 0; q < f->S; q++) fprintf(out, "eta_n2_%d\t%.10g\t%.4g\n", tb->n2[q], f->sv[q].eta, f->sv[q].eta_se);
    if (path ? fclose(out) : fflush(out)) { fprintf(stderr, "dpd tcaf-fit: cannot write '%s'\n", path ? path : "(stdout)"); return 4; }
    return 0;
}

/* --table: every shell's fit, with the extrapolation's value at its k. */
static int write_fit_table(const TcafTable *tb, const TcafFitArgs *a, const TcafFit *f, const char *path)
{
    FILE *out = fopen(path, "w");
    if (!out) { fprintf(stderr, "dpd tcaf-fit: cannot write '%s'\n", path); return 4; }
    fprintf(out, "# eta(k) by the %s model (src/transverse_relaxation.h) from %s, rho = %g, box %g", model_name(f->model), a->file, a->rho, a->box);
    if (f->model == RELAXATION_EXP) fprintf(out, ", fit while <C/C0> >= %g", a->fit_min);
    fprintf(out, ";\n# eta_se: the lags correlated as Bartlett's formula gives for the fitted curve; eta_se_bound: sum_i |d eta / d c_i| se_i,\n"
                 "# the largest error any correlation of the lags allows; modes: 2 slow mode + oscillation, 1 one mode;\n"
                 "# k -> 0: weighted polynomial of degree %d in k^2 over |k| <= %g (%d shells, chi2/dof %.3g):", a->order, a->kmax, f->nx, f->chi2_dof);
    for (int p = 0; p < f->P; p++) fprintf(out, " c%d = %.6g +- %.3g", p, f->coef[p], f->coef_se[p]);
    fprintf(out, "\nk\tn2\teta\teta_se\teta_se_bound\tmodes\tpoints\tt_cut\tamplitude\tamplitude_se\trate\trate_se\t"
                 "damping\tfrequency\tsine\tchi2_dof\tintegral\ttail_fraction\teta_extrapolation\n");
    for (int q = 0; q < f->S; q++) {
        double fit = 0.0, xp = 1.0;
        for (int p = 0; p < f->P; p++) { fit += f->coef[p] * xp; xp *= f->k[q] * f->k[q]; }
        const ShellViscosity *o = &f->sv[q];
        fprintf(out, "%.6g\t%d\t%.8g\t%.3g\t%.3g\t%d\t%d\t%.4g\t%.6g\t%.3g\t%.6g\t%.3g\t%.6g\t%.6g\t%.6g\t%.4g\t%.6g\t%.4g\t%.6g\n",
                f->k[q], tb->n2[q], o->eta, o->eta_se, o->eta_se_bound, o->modes, o->points, o->t_cut, o->amplitude,
                o->amplitude_se, o->rate, o->rate_se, o->damping, o->frequency, o->sine, o->chi2_dof, o->integral,
                o->tail / o->integral, f->k[q] <= a->kmax * (1 + 1e-12) ? fit : NAN);
    }
    if (fclose(out)) { fprintf(stderr, "dpd tcaf-fit: cannot write '%s'\n", path); return 4; }
    return 0;
}

/* --curves: C/C0 of each shell's fitted model at the table's lags. */
static int write_fit_curves(const TcafTable *tb, const TcafFit *f, const char *path)
{
    FILE *out = fopen(path, "w");
    if (!out) { fprintf(stderr, "dpd tcaf-fit: cannot write '%s'\n", path); return 4; }
    fprintf(out, "# C/C0 of the fitted %s model per shell (nan where not fitted)\nt", model_name(f->model));
    for (int q = 0; q < f->S; q++) fprintf(out, "\tfit_n2_%d", tb->n2[q]);
    fputc('\n', out);
    for (int l = 0; l < tb->nlag; l++) {
        fprintf(out, "%.6g", tb->t[l]);
        for (int q = 0; q < f->S; q++) {
            const ShellViscosity *o = &f->sv[q];
            const int two = o->modes == 2;
            const double p[NPAR] = {o->amplitude, o->rate, two ? o->damping : 1.0, two ? o->frequency : 0.0, two ? o->sine : 0.0};
            fprintf(out, "\t%.6g", isfinite(o->eta) ? two_mode_value(p, tb->t[l]) : NAN);
        }
        fputc('\n', out);
    }
    if (fclose(out)) { fprintf(stderr, "dpd tcaf-fit: cannot write '%s'\n", path); return 4; }
    return 0;
}

int cmd_tcaf_fit(int argc, char **argv)
{
    TcafFitArgs a;
    if (tcaf_fit_args(argc, argv, &a)) return 1;
    TcafTable tb;
    int rc = table_read(a.file, &tb);
    if (rc) return rc;
    TcafFit f[3] = {{0}};
    if (fit_shells(&tb, &a, f)) rc = 1;
    for (int j = 0; rc == 0 && j < a.nmodels; j++)
        if (extrapolate_shells(&a, &f[j])) rc = 1;
    if (rc) fprintf(stderr, "dpd tcaf-fit: out of memory\n");
    /* each model's files: the names with %m replaced (tcaf_fit_args: required with several) */
    char path[4096];
    for (int j = 0; rc == 0 && j < a.nmodels; j++) {
        if (rc == 0 && a.summary) rc = model_path(a.summary, f[j].model, path, sizeof path) ? 1 : write_fit_summary(&tb, &f[j], path);
        if (rc == 0 && !a.summary) rc = write_fit_summary(&tb, &f[j], NULL);
        if (rc == 0 && a.table) rc = model_path(a.table, f[j].model, path, sizeof path) ? 1 : write_fit_table(&tb, &a, &f[j], path);
        if (rc == 0 && a.curves) rc = model_path(a.curves, f[j].model, path, sizeof path) ? 1 : write_fit_curves(&tb, &f[j], path);
    }
    for (int j = 0; j < a.nmodels; j++) tcaf_fit_free(&f[j]);
    table_free(&tb);
    return rc;
}
