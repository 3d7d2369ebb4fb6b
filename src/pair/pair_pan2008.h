/* pair_pan2008.h - the pair evaluator of rotating particles with central and
 * shear dissipation (Pan, Pivkin & Karniadakis 2008, eqs 1 and 13-15; the
 * fluid particle model of Espanol 1998 with A~ = 0), plugged into the pair
 * driver (forces.c), which includes it alone. With gamma^S = 0 its forces are
 * the standard kernel's bit for bit. */
#ifndef DPD_PAIR_PAN2008_H
#define DPD_PAIR_PAN2008_H

#include "pair.h"
#include "random.h"

static inline void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Geometry of one pair at distance r = |d| > 0: the unit vector e = r_ij / r,
 * w_C = 1 - r/rc and Pan's f = (1 - r/rc)^(s/2) in the scene's convention
 * (w_D = f^2 = (1 - r/rc)^s), computed as the standard kernel computes w_R. */
static inline __attribute__((always_inline)) void pan_pair_geometry(const PairParams *p, const double d[3], double r,
                                                                double e[3], double *wc, double *f)
{
    const double inv_r = 1.0 / r;
    e[0] = d[0] * inv_r; e[1] = d[1] * inv_r; e[2] = d[2] * inv_r;
    const double w = 1.0 - r / p->rc;
    *wc = w;
    *f = random_weight(w, p->s);
}

/* One pair, eqs 13-15 and eq. 1, from its geometry (pair_geometry): the force
 * F_ij on i (F_ji = -F_ij) in Ftot and the torque on each of i and j in tau; the
 * parts (conservative, dissipative, random) in F[0..2] only when F != NULL
 * (measurement steps, tests), so that the pair loop of the other steps computes
 * the totals alone. */
static inline __attribute__((always_inline)) void pan_pair_force(const PairParams *p, const double d[3],
                              const double e[3], double wc, double f,
                              const double dv[3], const double wsum[3], double theta, const double xi[3],
                              double inv_sqrt_dt, double (*F)[3], double Ftot[3], double tau[3])
{
    const double edv = e[0] * dv[0] + e[1] * dv[1] + e[2] * dv[2];
    /* conservative, eq. 7 */
    const double fc = p->a * wc;
    /* translational, eq. 13 central part: -gamma^C f^2 (v_ij . e) e */
    const double fdc = -p->gamma * f * f * edv;
    /* random, eq. 15 central part: (1/sqrt 3) sigma^C tr[dW] e = sigma^C theta e sqrt(dt) */
    const double frc = p->sigma * f * theta * inv_sqrt_dt;
    const double ft = fc + fdc + frc;   /* summed as the standard kernel sums it */
    for (int a = 0; a < 3; a++) Ftot[a] = ft * e[a];
    if (F)
        for (int a = 0; a < 3; a++) { F[0][a] = fc * e[a]; F[1][a] = fdc * e[a]; F[2][a] = frc * e[a]; }
    if (p->gamma_shear == 0.0) { tau[0] = tau[1] = tau[2] = 0.0; return; }  /* standard DPD, no torque */
    /* relative velocity at the midpoint: v_ij + (r_ij / 2) x (Omega_i + Omega_j) */
    const double h[3] = {0.5 * d[0], 0.5 * d[1], 0.5 * d[2]};
    double rot[3];
    cross3(h, wsum, rot);
    /* translational, eq. 13 shear part: -gamma^S f^2 [v_ij - (v_ij . e) e];
     * rotational, eq. 14: -gamma^S f^2 (r_ij / 2) x (Omega_i + Omega_j) (normal to e) */
    const double gs = p->gamma_shear * (f * f);
    /* random, eq. 15 antisymmetric part: sqrt 2 sigma^S dW^A . e = sigma^S (xi x e) sqrt(dt),
     * xi ~ N(0, 1) per component, shared by i and j so that F_ji = -F_ij */
    double xe[3];
    cross3(xi, e, xe);
    const double frs = p->sigma_shear * f * inv_sqrt_dt;
    double Fs[3];   /* non-central part */
    for (int a = 0; a < 3; a++) {
        const double fds = -gs * (dv[a] - edv * e[a] + rot[a]), frs_a = frs * xe[a];
        Fs[a] = fds + frs_a;
        Ftot[a] += Fs[a];
        if (F) { F[1][a] += fds; F[2][a] += frs_a; }
    }
    /* torque, eq. 1: T_i = T_j = -(r_ij / 2) x F_ij (central parts give none) */
    double c[3];
    cross3(h, Fs, c);
    tau[0] = -c[0]; tau[1] = -c[1]; tau[2] = -c[2];
}

/* Virial by part (asymmetric, r_a F_b), its Irving-Kirkwood split, pair energy,
 * force and torque on frozen particles. Only on measurement steps. */
static void pan_pair_record(PairVirial *pv, const System *s, int i, int j, const double d[3], double wc,
                       const double F[3][3], const double tau[3])
{
    const PairParams *p = &s->pair[s->type[i]][s->type[j]];
    for (int q = 0; q < PAIR_PARTS; q++) {
        double t[9];
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) t[3 * a + c] = d[a] * F[q][c];   /* asymmetric: r_a F_b */
        pair_virial_add(pv, s, i, q, d, t);
    }
    pv->epot += pair_energy(p, wc);
    const int ti = s->type[i], tj = s->type[j];
    if (!s->types[ti].frozen && !s->types[tj].frozen) return;
    /* the random force of a step is independent of the configuration it acts
     * on: its torque and force have zero mean but a variance of order 1 / dt,
     * so drag and torque are reported without it (and the random torque apart) */
    double tr[3], Fr[3] = {-0.5 * F[2][0], -0.5 * F[2][1], -0.5 * F[2][2]};
    cross3(d, Fr, tr);   /* eq. 1 for the random part alone */
    for (int a = 0; a < 3; a++) {
        const double fa = F[0][a] + F[1][a] + F[2][a], fn = F[0][a] + F[1][a];
        if (s->types[tj].frozen) {
            pv->frozen_force[tj][a] -= fa; pv->frozen_drag[tj][a] -= fn;
            pv->frozen_torque[tj][a] += tau[a] - tr[a]; pv->frozen_torque_random[tj][a] += tr[a];
        }
        if (s->types[ti].frozen) {
            pv->frozen_force[ti][a] += fa; pv->frozen_drag[ti][a] += fn;
            pv->frozen_torque[ti][a] += tau[a] - tr[a]; pv->frozen_torque_random[ti][a] += tr[a];
        }
    }
}

/* One batch of particle i's pairs (pairs_in_range) in three passes, each a
 * short loop with independent iterations: the pairs inside their own cutoff
 * and their geometry; their noise; their forces and torques (bench/RESULTS.md,
 * issue 6: 3-7 % faster than one pass per pair by best of 5 on a noisy host,
 * not resolved). F_ij and the torque on i into acc->fi, acc->ti, their partners'
 * into the chunk's buffers; pv != NULL: the virial by part too. */
static inline __attribute__((always_inline))
void pan_pair_batch(const System *s, int i, int *near, double (*dd)[4], const double *noise0, int m0,
                    PairAcc *acc, PairVirial *pv, const int le)
{
    const double inv_sqrt_dt = acc->inv_sqrt_dt;
    const double *v = s->v_pred, *w = s->omega_pred;
    const int ti = s->type[i];
    double geo[PAIR_BATCH][8];     /* d[3], e[3], w_C, f */
    double noise[PAIR_BATCH][4];   /* theta, xi[3] */
    int m = 0;
    for (int q = 0; q < m0; q++) {
        const int j = near[q];
        const PairParams *p = &s->pair[ti][s->type[j]];
        const double r2 = dd[q][3];
        if (!pair_interacts(p, r2)) continue;
        near[m] = j;
        for (int a = 0; a < 4; a++) noise[m][a] = noise0[a * RNG_BATCH + q];   /* rng_pair_normals' planes */
        double *g = geo[m++];
        g[0] = dd[q][0]; g[1] = dd[q][1]; g[2] = dd[q][2];
        pan_pair_geometry(p, g, sqrt(r2), g + 3, g + 6, g + 7);
    }
    /* theta (eq. 15 central) and xi (eq. 15 antisymmetric) come from each
     * pair's sequence, drawn for the batch by the walk; xi = 0 where gamma^S = 0 */
    for (int q = 0; q < m; q++)
        if (s->pair[ti][s->type[near[q]]].gamma_shear == 0.0) noise[q][1] = noise[q][2] = noise[q][3] = 0.0;
    for (int q = 0; q < m; q++) {
        const int j = near[q];
        const PairParams *p = &s->pair[ti][s->type[j]];
        const double *g = geo[q];
        double dv[3] = {v[3 * i] - v[3 * j], v[3 * i + 1] - v[3 * j + 1], v[3 * i + 2] - v[3 * j + 2]};
        if (le) dv[0] -= pair_image_vx(s, i, j, le);   /* relative to j's Lees-Edwards image */
        const double wsum[3] = {w[3 * i] + w[3 * j], w[3 * i + 1] + w[3 * j + 1], w[3 * i + 2] + w[3 * j + 2]};
        double Ft[3], tau[3];
        if (pv) {
            double F[3][3];
            pan_pair_force(p, g, g + 3, g[6], g[7], dv, wsum, noise[q][0], noise[q] + 1, inv_sqrt_dt, F, Ft, tau);
            pan_pair_record(pv, s, i, j, g, g[6], F, tau);
        } else {
            pan_pair_force(p, g, g + 3, g[6], g[7], dv, wsum, noise[q][0], noise[q] + 1, inv_sqrt_dt, NULL, Ft, tau);
        }
        force_claim(acc->f, acc->tq, acc->touched, j, acc->n);
        for (int a = 0; a < 3; a++) {
            acc->fi[a] += Ft[a];
            acc->f[3 * j + a] -= Ft[a];
            acc->ti[a] += tau[a];
            acc->tq[3 * j + a] += tau[a];
        }
    }
}

/* random_weight's case for the exponent s: 0 s = 2, 1 s = 1, 2 s = 0.5, 3 a power */
static inline int pan_weight_mode(const PairParams *p)
{
    return p->s == 2.0 ? 0 : p->s == 1.0 ? 1 : p->s == 0.5 ? 2 : 3;
}

/* ---- the same forces lane by lane (steps without the virial) -------------
 * A walk batch's interacting pairs in structure-of-arrays form: pass 1 gathers
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
 * forces.c is compiled with -fno-math-errno (Makefile): sqrt then never calls
 * libm to set errno (its argument is never negative here), which is what
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

/* Pass 1 for particle i's entries [0, m0) (near, dd; noise: rng_pair_normals'
 * planes from entry 0), appended to L at *m. Returns the pairs added. direct:
 * every entry interacts (the caller checked), and pass 2 reads r^2, d and the
 * noise from the batch's own arrays (L->dd, L->noise), so they are not copied. */
static inline __attribute__((always_inline))
int pan_lanes_fill(const System *s, int i, const int *near, double (*dd)[4], const double *noise, int m0,
                   PanLanes *restrict L, int *m, const int le, const int uniform, const int direct)
{
    const double *v = s->v_pred, *w = s->omega_pred;
    const int ti = s->type[i], k0 = *m;
    const int u_mode = uniform ? pan_weight_mode(&s->pair[0][0]) : 0;   /* one type: no lookup per pair */
    for (int q = 0; q < m0; q++) {
        const int j = near[q];
        const PairParams *p = uniform ? &s->pair[0][0] : &s->pair[ti][s->type[j]];
        const double r2 = dd[q][3];
        if (!direct && !pair_interacts(p, r2)) continue;
        const int k = (*m)++;
        if (!direct) L->r2[k] = r2;
        /* the geometry in pass 2, but for a weight exponent other than 2, 1, 0.5 (pow) */
        const int mode = uniform ? u_mode : pan_weight_mode(p);
        L->wmode[k] = mode;
        if (!uniform) {
            L->f_pow[k] = mode == 3 ? random_weight(1.0 - sqrt(r2) / p->rc, p->s) : 0.0;
            L->rc[k] = p->rc;
            L->a[k] = p->a; L->gamma[k] = p->gamma; L->sigma[k] = p->sigma;
            L->gshear[k] = p->gamma_shear; L->sshear[k] = p->sigma_shear;
        }
        double dvx = v[3 * i] - v[3 * j];
        if (le) dvx -= pair_image_vx(s, i, j, le);   /* relative to j's Lees-Edwards image */
        L->dv[0][k] = dvx; L->dv[1][k] = v[3 * i + 1] - v[3 * j + 1]; L->dv[2][k] = v[3 * i + 2] - v[3 * j + 2];
        for (int a = 0; a < 3; a++) {
            if (!direct) L->d[a][k] = dd[q][a];
            L->ws[a][k] = w[3 * i + a] + w[3 * j + a];
            if (!direct) L->xi[a][k] = noise[(a + 1) * RNG_BATCH + q];
        }
        if (!direct) L->theta[k] = noise[q];
        L->j[k] = j;
    }
    return *m - k0;
}

/* Pass 3 for particle i's pairs [k0, k0 + c) of L: as pan_pair_batch adds them. */
static inline __attribute__((always_inline))
void pan_lanes_apply(const PanLanes *restrict L, int k0, int c, PairAcc *acc)
{
    /* i's sums in registers (acc->fi could alias the buffers for all the
     * compiler knows, and a sum through memory waits on its own store) */
    double fi[3] = {acc->fi[0], acc->fi[1], acc->fi[2]}, ti[3] = {acc->ti[0], acc->ti[1], acc->ti[2]};
    for (int k = k0; k < k0 + c; k++) {
        const int j = L->j[k];
        force_claim(acc->f, acc->tq, acc->touched, j, acc->n);
        for (int a = 0; a < 3; a++) {
            fi[a] += L->F[a][k];
            acc->f[3 * j + a] -= L->F[a][k];
            ti[a] += L->tau[a][k];
            acc->tq[3 * j + a] += L->tau[a][k];
        }
    }
    for (int a = 0; a < 3; a++) { acc->fi[a] = fi[a]; acc->ti[a] = ti[a]; }
}


#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>
/* -x, as C's unary minus (a flip of the sign bit: 0 - x would give +0 for +0) */
static inline __attribute__((target("avx512f"), always_inline)) __m512d neg(__m512d x)
{
    return _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(x), _mm512_set1_epi64((long long)0x8000000000000000ULL)));
}
/* Passes 1-3 for one type pair u whose weight is not a general power, no
 * shear; pv != NULL (measurement steps, no frozen type, no bins): the virial
 * by part and the energy as pan_pair_record forms them, added pair by pair
 * (virial_lanes_add): particle i's m pairs (near; pl: separations x, y, z, r^2
 * as planes, PAIR_PLANE apart; nz: rng_pair_normals' planes from entry 0)
 * eight at a time on AVX-512, with pan_lanes_loop's operations in its order
 * (no contraction: the same bits), v_j and Omega_j gathered, then added to i
 * and to j pair by pair in list order as pan_lanes_apply adds them. inv_rc:
 * rc_power_of_two_inverse(u->rc). */
static inline __attribute__((target("avx512f"), always_inline))
void pan_pair_lanes_avx512(const System *s, int i, const int *near, const double *pl, const double *nz, int m,
                           PairAcc *acc, const PairParams *u, const int mode, double inv_rc, PairVirial *pv)
{
    const double energy = 0.5 * u->a * u->rc;   /* pair_energy's first factors */
    const double *v = s->v_pred, *w = s->omega_pred;
    const __m512d vix = _mm512_set1_pd(v[3 * i]), viy = _mm512_set1_pd(v[3 * i + 1]), viz = _mm512_set1_pd(v[3 * i + 2]);
    const __m512d wix = _mm512_set1_pd(w[3 * i]), wiy = _mm512_set1_pd(w[3 * i + 1]), wiz = _mm512_set1_pd(w[3 * i + 2]);
    const __m512d one = _mm512_set1_pd(1.0), half = _mm512_set1_pd(0.5), z0 = _mm512_setzero_pd();
    const __m512d rc2 = _mm512_set1_pd(u->rc2);
    const __m512d eps2 = _mm512_set1_pd(PAIR_R_EPSILON * PAIR_R_EPSILON);
    const __m512d a = _mm512_set1_pd(u->a), ngamma = _mm512_set1_pd(-u->gamma), sigma = _mm512_set1_pd(u->sigma);
    const __m512d gshear = _mm512_set1_pd(u->gamma_shear), sshear = _mm512_set1_pd(u->sigma_shear);
    const __m512d isdt = _mm512_set1_pd(acc->inv_sqrt_dt);
    const int shear = u->gamma_shear != 0.0;
    double fi[3] = {acc->fi[0], acc->fi[1], acc->fi[2]}, ti[3] = {acc->ti[0], acc->ti[1], acc->ti[2]};
    for (int q0 = 0; q0 < m; q0 += 8) {
        const PairLanes8 g = pair_lanes_load_avx512(pl, near, q0, m, rc2, eps2);
        const int cnt = g.cnt;
        const __mmask8 live = g.live, act = g.act;
        const __m512d d0 = g.d0, d1 = g.d1, d2 = g.d2, r2 = g.r2;
        const __m256i j3 = g.j3;
        /* pan_pair_geometry */
        const __m512d r = _mm512_sqrt_pd(r2), inv_r = _mm512_div_pd(one, r);
        const __m512d e0 = _mm512_mul_pd(d0, inv_r), e1 = _mm512_mul_pd(d1, inv_r), e2 = _mm512_mul_pd(d2, inv_r);
        const __m512d wc = _mm512_sub_pd(one, r_over_rc_avx512(r, u->rc, inv_rc));   /* w_C, eq. 5 */
        const __m512d f = mode == 0 ? wc : mode == 1 ? _mm512_sqrt_pd(wc) : _mm512_sqrt_pd(_mm512_sqrt_pd(wc));
        /* pan_lanes_fill: v_ij and Omega_i + Omega_j */
        const __m512d v0 = _mm512_sub_pd(vix, _mm512_mask_i32gather_pd(z0, live, j3, v, 8));
        const __m512d v1 = _mm512_sub_pd(viy, _mm512_mask_i32gather_pd(z0, live, j3, v + 1, 8));
        const __m512d v2 = _mm512_sub_pd(viz, _mm512_mask_i32gather_pd(z0, live, j3, v + 2, 8));
        const __m512d edv = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(e0, v0), _mm512_mul_pd(e1, v1)), _mm512_mul_pd(e2, v2));
        const __m512d fc = _mm512_mul_pd(a, wc);                                                  /* eq. 7 */
        const __m512d fdc = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(ngamma, f), f), edv);         /* eq. 13, central */
        const __m512d theta = _mm512_maskz_loadu_pd(live, nz + q0);
        const __m512d frc = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(sigma, f), theta), isdt);    /* eq. 15, central */
        const __m512d ft = _mm512_add_pd(_mm512_add_pd(fc, fdc), frc);
        double F[3][8], tau[3][8];
        __m512d F0 = _mm512_mul_pd(ft, e0), F1 = _mm512_mul_pd(ft, e1), F2 = _mm512_mul_pd(ft, e2);
        __m512d T0 = z0, T1 = z0, T2 = z0;
        __m512d P[PAIR_PARTS][3];   /* measurement steps: F by part (pan_pair_force's F) */
        if (pv) {
            const __m512d ee[3] = {e0, e1, e2};
            for (int c = 0; c < 3; c++) {
                P[0][c] = _mm512_mul_pd(fc, ee[c]); P[1][c] = _mm512_mul_pd(fdc, ee[c]); P[2][c] = _mm512_mul_pd(frc, ee[c]);
            }
        }
        if (shear) {
            const __m512d w0 = _mm512_add_pd(wix, _mm512_mask_i32gather_pd(z0, live, j3, w, 8));
            const __m512d w1 = _mm512_add_pd(wiy, _mm512_mask_i32gather_pd(z0, live, j3, w + 1, 8));
            const __m512d w2 = _mm512_add_pd(wiz, _mm512_mask_i32gather_pd(z0, live, j3, w + 2, 8));
            const __m512d h0 = _mm512_mul_pd(half, d0), h1 = _mm512_mul_pd(half, d1), h2 = _mm512_mul_pd(half, d2);
            /* (r_ij / 2) x (Omega_i + Omega_j) */
            const __m512d o0 = _mm512_sub_pd(_mm512_mul_pd(h1, w2), _mm512_mul_pd(h2, w1));
            const __m512d o1 = _mm512_sub_pd(_mm512_mul_pd(h2, w0), _mm512_mul_pd(h0, w2));
            const __m512d o2 = _mm512_sub_pd(_mm512_mul_pd(h0, w1), _mm512_mul_pd(h1, w0));
            const __m512d ngs = neg(_mm512_mul_pd(gshear, _mm512_mul_pd(f, f)));   /* -gs */
            const __m512d x0 = _mm512_maskz_loadu_pd(live, nz + RNG_BATCH + q0);
            const __m512d x1 = _mm512_maskz_loadu_pd(live, nz + 2 * RNG_BATCH + q0);
            const __m512d x2 = _mm512_maskz_loadu_pd(live, nz + 3 * RNG_BATCH + q0);
            /* xi x e */
            const __m512d xe0 = _mm512_sub_pd(_mm512_mul_pd(x1, e2), _mm512_mul_pd(x2, e1));
            const __m512d xe1 = _mm512_sub_pd(_mm512_mul_pd(x2, e0), _mm512_mul_pd(x0, e2));
            const __m512d xe2 = _mm512_sub_pd(_mm512_mul_pd(x0, e1), _mm512_mul_pd(x1, e0));
            const __m512d frs = _mm512_mul_pd(_mm512_mul_pd(sshear, f), isdt);
            /* eqs 13-14 and 15, non-central: dissipative fd, random fr */
            const __m512d fd0 = _mm512_mul_pd(ngs, _mm512_add_pd(_mm512_sub_pd(v0, _mm512_mul_pd(edv, e0)), o0)), fr0 = _mm512_mul_pd(frs, xe0);
            const __m512d fd1 = _mm512_mul_pd(ngs, _mm512_add_pd(_mm512_sub_pd(v1, _mm512_mul_pd(edv, e1)), o1)), fr1 = _mm512_mul_pd(frs, xe1);
            const __m512d fd2 = _mm512_mul_pd(ngs, _mm512_add_pd(_mm512_sub_pd(v2, _mm512_mul_pd(edv, e2)), o2)), fr2 = _mm512_mul_pd(frs, xe2);
            const __m512d s0 = _mm512_add_pd(fd0, fr0), s1 = _mm512_add_pd(fd1, fr1), s2 = _mm512_add_pd(fd2, fr2);
            if (pv) {   /* pan_pair_force's parts: F[1] += fds, F[2] += frs */
                P[1][0] = _mm512_add_pd(P[1][0], fd0); P[1][1] = _mm512_add_pd(P[1][1], fd1); P[1][2] = _mm512_add_pd(P[1][2], fd2);
                P[2][0] = _mm512_add_pd(P[2][0], fr0); P[2][1] = _mm512_add_pd(P[2][1], fr1); P[2][2] = _mm512_add_pd(P[2][2], fr2);
            }
            /* eq. 1: tau = -(h x F^S) */
            T0 = neg(_mm512_sub_pd(_mm512_mul_pd(h1, s2), _mm512_mul_pd(h2, s1)));
            T1 = neg(_mm512_sub_pd(_mm512_mul_pd(h2, s0), _mm512_mul_pd(h0, s2)));
            T2 = neg(_mm512_sub_pd(_mm512_mul_pd(h0, s1), _mm512_mul_pd(h1, s0)));
            F0 = _mm512_add_pd(F0, s0); F1 = _mm512_add_pd(F1, s1); F2 = _mm512_add_pd(F2, s2);
        }
        if (pv) {   /* pan_pair_record: r_a F_b by part, the energy a rc w_C^2 / 2 */
            const __m512d d3[3] = {d0, d1, d2};
            __m512d t[PAIR_PARTS * 9];
            for (int q = 0; q < PAIR_PARTS; q++)
                for (int a3 = 0; a3 < 3; a3++)
                    for (int c = 0; c < 3; c++) t[9 * q + 3 * a3 + c] = _mm512_mul_pd(d3[a3], P[q][c]);
            virial_lanes_add(pv, t, _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(energy), wc), wc), act);
        }
        _mm512_storeu_pd(F[0], F0); _mm512_storeu_pd(F[1], F1); _mm512_storeu_pd(F[2], F2);
        _mm512_storeu_pd(tau[0], T0); _mm512_storeu_pd(tau[1], T1); _mm512_storeu_pd(tau[2], T2);
        for (int l = 0; l < cnt; l++) {
            if (!(act >> l & 1)) continue;
            const int j = near[q0 + l];
            force_claim(acc->f, acc->tq, acc->touched, j, acc->n);
            for (int c = 0; c < 3; c++) {
                fi[c] += F[c][l];
                acc->f[3 * j + c] -= F[c][l];
                ti[c] += tau[c][l];
                acc->tq[3 * j + c] += tau[c][l];
            }
        }
    }
    for (int c = 0; c < 3; c++) { acc->fi[c] = fi[c]; acc->ti[c] = ti[c]; }
}
#endif

#endif
