/* pan_lanes.h - pass 2 of the Pan 2008 style's lanes (pair_pan2008.c),
 * written once: pair_pan2008.c compiles it for any x86-64, the backend
 * (src/simd/pan_lanes_x86.c) for AVX2 and AVX-512. Included by those two
 * files only; both are compiled with -fno-math-errno (Makefile). */
#ifndef DPD_PAN_LANES_H
#define DPD_PAN_LANES_H

#include <math.h>
#include "pair.h"
#include "random.h"

/* The Pan 2008 forces lane by lane (steps without the virial). A walk batch's interacting pairs in structure-of-arrays form: pass 1 gathers
 * each pair's geometry, velocities, noise and parameters (scalar: gathers and
 * square roots), pass 2 (pan_lanes_force) forms F_ij and the torque of every
 * pair with independent iterations, which vectorise, and pass 3 adds them to
 * i and scatters them to j in the walk's order. Pass 2 performs
 * pan_pair_force's operations in its order (C11 without contraction), so the
 * forces are the same bits. */
typedef struct {
    double d[3][PAIR_BATCH], r2[PAIR_BATCH], rc[PAIR_BATCH], f_pow[PAIR_BATCH];
    int wmode[PAIR_BATCH];   /* random_weight's case: 0 s = 2, 1 s = 1, 2 s = 0.5, 3 pow (f_pow, from pass 1) */
    double dv[3][PAIR_BATCH], ws[3][PAIR_BATCH], theta[PAIR_BATCH], xi[3][PAIR_BATCH];
    double a[PAIR_BATCH], gamma[PAIR_BATCH], sigma[PAIR_BATCH], gshear[PAIR_BATCH], sshear[PAIR_BATCH];
    double F[3][PAIR_BATCH], tau[3][PAIR_BATCH];
    int j[PAIR_BATCH];
    const double (*dd)[4], *noise;   /* direct (dd != NULL): the batch's separations and noise planes, read in place */
} PanLanes;

/* Pass 2: eqs 13-15 and eq. 1 as pan_pair_force (F == NULL), every pair at once;
 * where gamma^S = 0 the shear terms are computed and not used (a select).
 * Its includers are compiled with -fno-math-errno (Makefile): sqrt never calls
 * libm to set errno then (its argument is never negative here), which is what
 * lets this loop vectorise; IEEE sqrt gives the same bits either way. */
static inline __attribute__((always_inline))
void pan_lanes_loop(PanLanes *restrict L, int m, double inv_sqrt_dt, const PairParams *u, const int uniform,
                    const int direct)
{
    const double (*dd)[4] = L->dd;
    const double *nz = L->noise;
    const double u_rc = uniform ? u->rc : 0.0, u_a = uniform ? u->a : 0.0, u_gamma = uniform ? u->gamma : 0.0;
    const double u_sigma = uniform ? u->sigma : 0.0, u_gs = uniform ? u->gamma_shear : 0.0;
    const double u_ss = uniform ? u->sigma_shear : 0.0;
    #pragma omp simd
    for (int q = 0; q < m; q++) {
        /* pan_pair_geometry: e = r_ij / r, w_C = 1 - r/rc, f = random_weight(w_C, s) */
        const double d0 = direct ? dd[q][0] : L->d[0][q], d1 = direct ? dd[q][1] : L->d[1][q];
        const double d2 = direct ? dd[q][2] : L->d[2][q];
        const double r = sqrt(direct ? dd[q][3] : L->r2[q]), inv_r = 1.0 / r;
        const double e0 = d0 * inv_r, e1 = d1 * inv_r, e2 = d2 * inv_r;
        const double wc = 1.0 - r / (uniform ? u_rc : L->rc[q]);
        const double sq = sqrt(wc), sq2 = sqrt(sq), fp = uniform ? 0.0 : L->f_pow[q];   /* all formed: no branch in the loop */
        /* the mode per pair even when uniform: a mode fixed for the loop lets
         * GCC unswitch it into square roots under conditions (2.5x slower) */
        const int mode = L->wmode[q];
        const double f = mode == 0 ? wc : mode == 1 ? sq : mode == 2 ? sq2 : fp;
        const double v0 = L->dv[0][q], v1 = L->dv[1][q], v2 = L->dv[2][q];
        const double edv = e0 * v0 + e1 * v1 + e2 * v2;
        const double fc = (uniform ? u_a : L->a[q]) * wc;                               /* eq. 7 */
        const double fdc = -(uniform ? u_gamma : L->gamma[q]) * f * f * edv;            /* eq. 13, central */
        const double theta = direct ? nz[q] : L->theta[q];
        const double frc = (uniform ? u_sigma : L->sigma[q]) * f * theta * inv_sqrt_dt;   /* eq. 15, central */
        const double ft = fc + fdc + frc;
        const double h0 = 0.5 * d0, h1 = 0.5 * d1, h2 = 0.5 * d2;
        const double w0 = L->ws[0][q], w1 = L->ws[1][q], w2 = L->ws[2][q];
        const double r0 = h1 * w2 - h2 * w1, r1 = h2 * w0 - h0 * w2, r2 = h0 * w1 - h1 * w0;   /* (r_ij / 2) x (Omega_i + Omega_j) */
        const double gshear = uniform ? u_gs : L->gshear[q], gs = gshear * (f * f);
        const double x0 = direct ? nz[RNG_BATCH + q] : L->xi[0][q], x1 = direct ? nz[2 * RNG_BATCH + q] : L->xi[1][q];
        const double x2 = direct ? nz[3 * RNG_BATCH + q] : L->xi[2][q];
        const double xe0 = x1 * e2 - x2 * e1, xe1 = x2 * e0 - x0 * e2, xe2 = x0 * e1 - x1 * e0;   /* xi x e */
        const double frs = (uniform ? u_ss : L->sshear[q]) * f * inv_sqrt_dt;
        const double s0 = -gs * (v0 - edv * e0 + r0) + frs * xe0;               /* eqs 13-14 and 15, non-central */
        const double s1 = -gs * (v1 - edv * e1 + r1) + frs * xe1;
        const double s2 = -gs * (v2 - edv * e2 + r2) + frs * xe2;
        const double c0 = h1 * s2 - h2 * s1, c1 = h2 * s0 - h0 * s2, c2 = h0 * s1 - h1 * s0;   /* eq. 1 */
        /* both forms computed, then selected (no arithmetic under a condition) */
        const double fc0 = ft * e0, fc1 = ft * e1, fc2 = ft * e2;
        const double fs0 = fc0 + s0, fs1 = fc1 + s1, fs2 = fc2 + s2;
        const int shear = gshear != 0.0;
        L->F[0][q] = shear ? fs0 : fc0;
        L->F[1][q] = shear ? fs1 : fc1;
        L->F[2][q] = shear ? fs2 : fc2;
        L->tau[0][q] = shear ? -c0 : 0.0;
        L->tau[1][q] = shear ? -c1 : 0.0;
        L->tau[2][q] = shear ? -c2 : 0.0;
    }
}

/* Pass 2; u != NULL: every pair of the batch has the parameters u (a scene of
 * one type whose weight is not a general power), read once, not per pair. */
static inline __attribute__((always_inline)) void pan_lanes_force(PanLanes *restrict L, int m, double inv_sqrt_dt,
                                                                  const PairParams *u)
{
    if (u && L->dd) pan_lanes_loop(L, m, inv_sqrt_dt, u, 1, 1);
    else if (u) pan_lanes_loop(L, m, inv_sqrt_dt, u, 1, 0);
    else pan_lanes_loop(L, m, inv_sqrt_dt, NULL, 0, 0);
}

/* pan_lanes_force compiled for AVX-512, AVX2 and baseline x86-64 (the same
 * operations without contraction, so the same bits): the style's lanes at
 * each level (PairStyle.accel). no-tree-sink: GCC would otherwise move each
 * square root into the branch of the select that uses it, and a square root
 * under a condition keeps the loop from vectorising without masks (it
 * "could trap"); the bits are the same. AVX-512 has the masks, and is faster
 * without it (measured). */
#ifdef __clang__
#define PAN_LANES_OPT   /* clang has no optimize attribute (the fuzzer's build) */
#else
#define PAN_LANES_OPT __attribute__((optimize("no-tree-sink")))
#endif

#endif
