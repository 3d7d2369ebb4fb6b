/* tcaf.h - transverse current autocorrelation functions and the wave-number
 * dependent viscosity eta(k) of generalised hydrodynamics (Mai-Duy et al.
 * 2019, eqs 22-28).
 *
 * Every wave vector k = 2 pi (i/Lx, j/Ly, l/Lz) with 0 < i^2 + j^2 + l^2 <= n2max
 * (one of each pair +-k: C(-k,t) is the complex conjugate of C(k,t)) is
 * sampled, and optionally the axis vectors (n,0,0), (0,n,0), (0,0,n) beyond
 * that sphere up to n = axis_nmax (large |k| at a cost linear in n);
 * J(k,t) = sum_j v_j exp(i k.r_j) (eq. 23) is projected on the plane
 * normal to k (both transverse polarisations), and
 *   C_perp(k,t) = (k^2 / N) <J_perp(-k,0) . J_perp(k,t)> / 2        (eq. 26)
 * is averaged over the vectors of one shell |k| and over time origins.
 * eta(k) is fitted to C_perp(k,t)/C_perp(k,0) = exp(-eta k^2 t / rho) (eq. 28)
 * over the lags where the shell's average normalised TCAF is still >= fit_min;
 * its standard error is the scatter of the same fit over blocks of
 * consecutive time origins. eta(k -> 0) from a weighted polynomial fit in k^2. */
#ifndef DPD_TCAF_H
#define DPD_TCAF_H

#define TCAF_NMAX 31              /* largest |i|, |j|, |l| of a wave vector */
#define TCAF_MAX_ORDER 3          /* largest extrapolate_order (validator and coefficient arrays) */

#include <stdio.h>
#include <complex.h>
#include "system.h"
#include "io.h"

/* measure.tcaf of the scene, read and checked by the input layer (setup_measure.c). */
typedef struct {
    int every;                /* sampling interval (steps) */
    int window;               /* correlation window (steps, multiple of every) */
    int origin_every;         /* steps between time origins (multiple of every) */
    int n2max;                /* largest i^2 + j^2 + l^2 */
    int axis_nmax;            /* also (n,0,0), (0,n,0), (0,0,n) up to n = axis_nmax (0: none) */
    int type;                 /* -1: every mobile particle */
    double fit_min;           /* fit lags while <C/C0> >= fit_min */
    double extrap_kmax;       /* shells with |k| <= this enter the k -> 0 fit */
    int extrap_order;         /* polynomial degree in k^2 of the k -> 0 fit */
    int include_bodies;       /* the run adds the colloid bodies (tcaf_set_bodies) */
} TcafParams;

typedef struct {
    int on;                   /* set up by tcaf_init */
    TcafParams p;
    int nblocks;
    long long norig_expected; /* complete origins the run will give */
    /* derived */
    int nvec, nshell, nlags, nslots, nmax[3];
    int *vec;                 /* nvec x 3 integers */
    int *shell_of;            /* nvec */
    double *kvec;             /* nvec x 3 */
    double *shell_k;          /* nshell */
    int *shell_n2, *shell_nvec;
    int count;                /* particles in the selection */
    double rho;               /* mass density of the selection */
    double complex *J;        /* nvec x 3: current of this sample */
    double complex *origin;   /* nslots x nvec x 3: J_perp at the origin */
    long long *origin_step, *origin_index;
    double *curve;            /* nslots x nshell x nlags: running sums per origin */
    double *acc;              /* nblocks x nshell x nlags */
    long long *acc_n;         /* nblocks: complete origins */
    long long nstarted, ndone;
    /* tcaf_current's work arrays, made by tcaf_init: the wave vectors as runs
     * of consecutive l (items: +-l), the chunks' sums per lane, phase tables
     * and run factors */
    struct TcafRun *run;
    struct TcafItem *item;
    int nrun;
    double *lane_sum, *tabs, *abuf;
    /* optional rigid bodies whose momentum M V joins the current (include_bodies) */
    int nbody;
    const double *body_R, *body_V;
    double body_mass;
} Tcaf;

/* Add nbody bodies of mass M at R with velocity V (arrays owned by the caller,
 * read at every sample) to the current: J += sum_b M V_b exp(i k.R_b); rho too. */
void tcaf_set_bodies(Tcaf *t, const System *s, int nbody, const double *R, const double *V, double M);
/* Wave vectors and buffers for the parameters p; -1 on bad sizes or memory. */
int  tcaf_init(Tcaf *t, const TcafParams *p, const System *s, int nblocks, long long prod_steps);
void tcaf_free(Tcaf *t);
/* The time origins in flight, their running sums and the block sums, written
 * or read for the checkpoint. */
void tcaf_io(Io *io, Tcaf *t);
/* J(k) of the selection for every wave vector into t->J (eq. 23). */
void tcaf_current(Tcaf *t, const System *s);
/* J_perp = (1 - k k / k^2) J (both transverse polarisations, eqs 25-26). */
void tcaf_transverse(const double k[3], const double complex J[3], double complex out[3]);
/* Sample at production step `step` (call when step % every == 0). */
void tcaf_sample(Tcaf *t, const System *s, long long step);
/* eta from C(t)/C(0) = exp(-eta k^2 t / rho) (eq. 28), least squares over the
 * n points (t_i, c_i) (GSL nonlinear least squares); returns 0 on success. */
int  tcaf_fit_eta(const double *t, const double *c, int n, double k2, double rho, double *eta);
/* Weighted least-squares polynomial of degree `order` in k^2 through (k_i,
 * eta_i) with weights w_i: coefficients c[0..order] (c[0] = eta(k -> 0)). */
int  tcaf_extrapolate(const double *k, const double *eta, const double *w, int n, int order,
                      double *coef);
/* The same, also giving the covariance of the coefficients ((order + 1)^2,
 * row-major, (X^T W X)^-1: the weights taken as 1/se^2) and the weighted chi^2;
 * either may be NULL. */
int  tcaf_extrapolate_cov(const double *k, const double *eta, const double *w, int n, int order,
                          double *coef, double *covariance, double *chi2);
/* What the TCAF of a run gives (tcaf_analyse; tcaf_write prints it). Shell q
 * is |k| = shell_k[q] of the Tcaf, lag l the time l dt_lag. Errors are the
 * standard errors over the blocks of time origins. */
typedef struct {
    int nshell, nlags;
    int nblocks;              /* blocks with a complete time origin */
    double dt_lag;            /* time between lags */
    double *c, *c_se;         /* nshell x nlags: C_perp(k,t)/C_perp(k,0), eqs 26 and 28 */
    double *eta, *eta_se;     /* nshell: eta(k) of eq. 28 (nan: decay not resolved, < 3 lags) */
    int *fit_points;          /* nshell: lags in the fit (those with <C/C0> >= fit_min) */
    double *c0_ratio, *c0_ratio_se;      /* nshell: C_perp(k,0) / (k^2 kBT <1/m>), 1 at equipartition */
    double c0_ratio_mean, c0_ratio_mean_se;   /* over the shells */
    /* eta(k) = sum_p coef[p] k^(2p) over the shells with |k| <= extrap_kmax:
     * coef[0] = eta(k -> 0); p up to extrap_order */
    double coef[TCAF_MAX_ORDER + 1], coef_se[TCAF_MAX_ORDER + 1];
    int nextrap;              /* shells in that fit */
    double kend;              /* largest |k| among them */
    double drop, drop_se;     /* eta(first shell) - eta(last shell with an eta) */
} TcafResult;

/* Fits, block errors and the k -> 0 extrapolation of the accumulated TCAF
 * (malloc'd arrays: tcaf_result_free). Returns 0, or -1 when out of memory or
 * with more blocks than MAX_BLOCKS (blockavg.h). */
int  tcaf_analyse(const Tcaf *t, const System *s, TcafResult *out);
void tcaf_result_free(TcafResult *r);
/* tcaf.tsv (normalised TCAF per shell), tcaf_eta.tsv (eta(k)),
 * tcaf_extrapolation.tsv and the summary rows tcaf_eta_k0,
 * tcaf_eta_k2_coefficient, tcaf_eta_drop, ...: tcaf_analyse, formatted. */
int  tcaf_write(const Tcaf *t, const System *s, FILE *summary, const char *dir);

#endif
