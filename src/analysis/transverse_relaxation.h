/* transverse_relaxation.h - eta(k) from a stored normalised transverse current
 * autocorrelation C(k,t)/C(k,0) (Mai-Duy et al. 2019, eqs 26-28), by three
 * estimators, and `dpd tcaf-fit`.
 *
 *  exp       eq. 28 as written: C/C0 = exp(-eta k^2 t / rho), amplitude 1, fitted
 *            while <C/C0> >= fit_min (the simulator's own fit, src/measure/tcaf.c). Right
 *            for a simple fluid, whose C(k,t) is one relaxing mode.
 *  two-mode  a slow (hydrodynamic) relaxation beside a damped oscillation:
 *              C/C0 = A e^{-t/tau} + (1 - A) e^{-t/tau2} cos(w t) + S e^{-t/tau2} sin(w t),
 *            weighted by the curve's errors over every stored lag; eta(k) =
 *            rho / (k^2 tau), the slow mode read with eq. 28. This is the
 *            autocorrelation of a linear system with one real and one complex pair
 *            of eigenvalues (a current that exchanges momentum through springs with
 *            rigid bodies it does not contain), normalised to C/C0 = 1 at t = 0;
 *            the sine term is the phase of the oscillation. Where no oscillation
 *            is resolved (two periods in the window, amplitude above twice its
 *            error) the curve is fitted with one mode, A = 1, S = 0.
 *  integral  the zero-frequency viscosity of generalised hydrodynamics: the Laplace
 *            transform of C/C0 is 1 / (z + k^2 eta(k, z) / rho), so
 *              eta(k) = rho / (k^2 integral_0^inf C/C0 dt),
 *            which is eq. 28's eta for one exponential and needs no model for the
 *            shape. The data are integrated (trapezoid) up to t_cut, the first lag
 *            where the fitted slow mode A e^{-t/tau} falls below the curve's
 *            standard error (the curve has reached its noise; else the last
 *            stored lag), and the fitted model beyond t_cut (`tail_fraction`).
 *
 * Errors. A stored tcaf.tsv holds the mean curve and, per lag, the standard
 * error over blocks of time origins, not the blocks' curves; the errors of
 * neighbouring lags are correlated (one time origin feeds every lag). Each
 * estimate is linearised in the curve, eta - eta0 = sum_i g_i (c_i - c0_i), and
 * two errors are given: `se`, with the lags correlated as Bartlett's formula
 * gives for the normalised autocorrelation of a Gaussian current (computed from
 * the fitted curve, scaled by the measured per-lag errors; checked against the
 * blocks' scatter in tests/test_transverse_relaxation.c), and `se_bound` =
 * sum_i |g_i| se_i, the largest standard error any correlation of the lags
 * allows (Cauchy-Schwarz). The k -> 0 limit (as src/measure/tcaf.c: weighted polynomial
 * in k^2 over |k| <= kmax) weights the shells by 1/se^2 and takes them as
 * independent (distinct wave vectors of a fluid at rest are uncorrelated); its
 * covariance is scaled by chi^2/dof when that exceeds 1. */
#ifndef DPD_TRANSVERSE_RELAXATION_H
#define DPD_TRANSVERSE_RELAXATION_H

typedef enum { RELAXATION_EXP, RELAXATION_TWO_MODE, RELAXATION_INTEGRAL } RelaxationModel;

typedef struct {
    double eta, eta_se, eta_se_bound;         /* eta(k) and its two errors (see above) */
    /* the two-mode fit (also behind the integral's tail); exp: amplitude 1, rate only */
    double amplitude, amplitude_se;           /* A, slow mode's share of C(k,0) */
    double rate, rate_se;                     /* 1 / tau: slow relaxation rate */
    double damping, frequency, sine;          /* 1 / tau2, w, S */
    double chi2_dof;                          /* weighted, lags taken as independent */
    double t_cut, integral, tail;             /* integral: data up to t_cut, model beyond */
    int points;                               /* lags used (t > 0) */
    int modes;                                /* 2: slow mode + oscillation, 1: one mode */
} ShellViscosity;

/* eta(k) of one shell from n lags t[0] = 0 < t[1] < ... (c[0] = 1, se[0] = 0):
 * k2 = |k|^2, rho the mass density of eq. 28, fit_min the exp model's window.
 * Returns 0, or -1 (fields nan) when the curve does not determine the model. */
int shell_viscosity(RelaxationModel model, const double *t, const double *c, const double *se, int n,
                    double k2, double rho, double fit_min, ShellViscosity *out);
/* The same for several models at once, out[j] by models[j]: the two-mode fit behind
 * the two-mode and the integral model is made once (the same numbers as one call
 * per model). Returns -1 when any model fails (its fields nan). */
int shell_viscosities(const RelaxationModel *models, int nmodels, const double *t, const double *c,
                      const double *se, int n, double k2, double rho, double fit_min, ShellViscosity *out);

/* `dpd tcaf-fit TCAF_TSV --rho R --box L [--model MODEL[,MODEL...]] [--fit-min F]
 * [--kmax K] [--order P] [--table FILE] [--curves FILE] [--summary FILE]`: eta(k) of
 * every shell of a run's tcaf.tsv and the k -> 0 limit, as quantity/value/stderr rows
 * (on stdout, or in --summary). Several models (exp, two-mode, integral) share one fit
 * (shell_viscosities); then --summary is required, and it, --table and --curves name
 * one file per model through %m, replaced by the model's name. */
int cmd_tcaf_fit(int argc, char **argv);

#endif
