/* pair_pan2008.c - the pair style of rotating particles with central and
 * shear dissipation (Pan, Pivkin & Karniadakis 2008, eqs 1 and 13-15; the
 * fluid particle model of Espanol 1998 with A~ = 0): its evaluator, its
 * lanes (steps without the virial: the evaluator's operations pair by pair
 * in structure-of-arrays form, which the compiler vectorises, compiled for
 * each instruction set), its walks and its registration. With gamma^S = 0
 * its forces are the standard style's bit for bit. Its AVX-512 evaluator of
 * one-type batches is pair_avx512.c pan_one_type_avx512. */
#include "pair_walk.h"
#include "pair_avx512.h"
#include "simd.h"

static inline void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* One pair, eqs 13-15 and eq. 1, from its geometry (pan_pair): the force
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

/* One pair: its geometry (e_ij = r_ij / r from the walk, w_C = 1 - r/rc and
 * Pan's f = w_C^(s/2) in the scene's convention, w_D = f^2 = (1 - r/rc)^s,
 * formed as the standard style forms w_R), theta and xi from the pair's four
 * variates (eq. 15), then pan_pair_force. */
static inline __attribute__((always_inline))
void pan_pair(const PairParams *p, const PairIn *in, PairOut *out, int record)
{
    const double wc = 1.0 - in->r / p->rc;
    const double f = in->prep && weight_general(p->s) ? *in->prep : random_weight(wc, p->s);
    const double xi[3] = {in->noise[RNG_BATCH], in->noise[2 * RNG_BATCH], in->noise[3 * RNG_BATCH]};
    pan_pair_force(p, in->d, in->e, wc, f, in->dv, in->wsum, in->noise[0], xi, in->inv_sqrt_dt,
                   record ? out->part : NULL, out->F, out->tau);
    if (record) out->energy = pair_energy(p, wc);
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
 * This file is compiled with -fno-math-errno (Makefile): sqrt then never calls
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

/* Pass 3 for particle i's pairs [k0, k0 + c) of L: as the walk adds them pair by pair (pair_walk.h pair_batch). */
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

/* The pairs of particles [i, ie) of a walk batch without the virial, lane by
 * lane (the same bits as pan_pair), with their noise in rng_pair_normals'
 * planes; lanes: pass 2 at the level in use (PairKernels). One type, not a
 * general power: its parameters once, not per pair; and when every pair of
 * the batch interacts (one cutoff, none closer than PAIR_R_EPSILON), the
 * lanes read the separations and the noise where the walk left them (direct:
 * entry q of the batch is lane q). */
static inline __attribute__((always_inline))
void pan_batch_lanes(const System *s, int i, int ie, int *near, double (*dd)[4], const double *noise,
                     const int *count, PairAcc *acc, const int le, int close_last, PairLanesFn lanes)
{
    PanLanes L;
    int m = 0, c[PAIR_BATCH];
    const PairParams *u = s->ntypes == 1 && !weight_general(s->pair[0][0].s) ? &s->pair[0][0] : NULL;
    int total = 0, direct = u != NULL;
    for (int p = i; p < ie; p++) total += count[p - i];
    for (int q = 0; direct && q < total; q++) direct = pair_interacts(u, dd[q][3]);
    L.dd = direct ? (const double (*)[4])dd : NULL;
    L.noise = noise;
    for (int p = i, off = 0; p < ie; off += count[p - i], p++)
        c[p - i] = direct ? pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 1, 1)
                 : u ? pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 1, 0)
                     : pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 0, 0);
    lanes(&L, m, acc->inv_sqrt_dt, u);
    for (int p = i, k = 0; p < ie; k += c[p - i], p++) {
        pan_lanes_apply(&L, k, c[p - i], acc);
        if (p + 1 < ie || close_last) pair_close_spins(1, p, acc);
    }
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
PAN_LANES_OPT static void pan_lanes_portable(void *L, int m, double inv_sqrt_dt, const PairParams *u)
{ pan_lanes_force(L, m, inv_sqrt_dt, u); }
SIMD_TARGET_AVX2 PAN_LANES_OPT static void pan_lanes_avx2(void *L, int m, double inv_sqrt_dt, const PairParams *u)
{ pan_lanes_force(L, m, inv_sqrt_dt, u); }
SIMD_TARGET_AVX512 static void pan_lanes_avx512(void *L, int m, double inv_sqrt_dt, const PairParams *u)
{ pan_lanes_force(L, m, inv_sqrt_dt, u); }

static int pan_serves(const System *s) { return MOD_ROTATION(s); }

static const PairEvaluator pan_evaluator = {
    .nvar = 4, .spins = 1, .central = 0, .pair = pan_pair,
    .prepare_needed = scene_weights_general, .prepare = pair_random_weights, .batch_lanes = pan_batch_lanes,
};

PAIR_STYLE_WALKS(pan2008, pan_evaluator)

static void pan_one(const PairParams *p, const PairIn *in, PairOut *out)
{
    pan_pair(p, in, out, 1);
}

const PairStyle pair_style_pan2008 = {
    .name = "pan2008", .nvar = 4, .spins = 1, .central = 0, .serves = pan_serves,
    .walk = {pan2008_walk_plain, pan2008_walk_shear}, .one = pan_one, .overdamped = NULL,
    .accel = {[SIMD_PORTABLE] = {.lanes = pan_lanes_portable}, [SIMD_AVX2] = {.lanes = pan_lanes_avx2},
              [SIMD_AVX512] = {.one_type = SIMD_X86(pan_one_type_avx512), .lanes = pan_lanes_avx512}},
};
