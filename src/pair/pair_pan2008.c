/* pair_pan2008.c - the pair style of rotating particles with central and
 * shear dissipation (Pan, Pivkin & Karniadakis 2008, eqs 1 and 13-15; the
 * fluid particle model of Espanol 1998 with A~ = 0): its evaluator, its
 * lanes (steps without the virial: the evaluator's operations pair by pair
 * in structure-of-arrays form, which the compiler vectorises, compiled for
 * each instruction set: pan_lanes.h), its walks and its registration. With
 * gamma^S = 0 its forces are the standard style's bit for bit. Its vector
 * kernels are the backend's (src/simd/): pan_lanes_x86.c and, for one-type
 * batches on AVX-512, pair_avx512.c pan_one_type_avx512. */
#include "pair_walk.h"
#include "pair_avx512.h"
#include "pan_lanes.h"
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
 * PanLanes and pass 2 (pan_lanes_force): pan_lanes.h, compiled here for any
 * x86-64 and by the backend (src/simd/pan_lanes_x86.c) for AVX2 and AVX-512. */

/* Pass 1 for particle i's entries [0, m0) (near, dd; noise: rng_pair_normals'
 * planes from entry 0), appended to L at *m. Returns the pairs added. direct:
 * every entry interacts (the caller checked), and pass 2 reads r^2, d and the
 * noise from the batch's own arrays (L->dd, L->noise), so they are not copied. */
static inline __attribute__((always_inline))
int pan_lanes_fill(const System *s, int i, const int *near, double (*dd)[4], const double *noise, int m0,
                   PanLanes *restrict L, int *m, const int le, const int uniform, const PairParams *u,
                   const int direct)
{
    const double *v = s->v_pred, *w = s->omega_pred;
    const int ti = s->type[i], k0 = *m;
    const int u_mode = uniform ? pan_weight_mode(u) : 0;   /* one parameter set (u): no lookup per pair */
    for (int q = 0; q < m0; q++) {
        const int j = near[q];
        const PairParams *p = uniform ? u : &s->pair[ti][s->type[j]];
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
 * planes; lanes: pass 2 at the level in use (PairKernels). One parameter set
 * (pair_walk.h batch_one_type: one type, or several alike), not a general
 * power: its parameters once, not per pair; and when every pair of
 * the batch interacts (one cutoff, none closer than PAIR_R_EPSILON), the
 * lanes read the separations and the noise where the walk left them (direct:
 * entry q of the batch is lane q). */
static inline __attribute__((always_inline))
void pan_batch_lanes(const System *s, int i, int ie, int *near, double (*dd)[4], const double *noise,
                     const int *count, PairAcc *acc, const int le, int close_last, PairLanesFn lanes)
{
    PanLanes L;
    int m = 0, c[PAIR_BATCH];
    const PairParams *u = batch_one_type(s, i, ie, near, count);   /* one parameter set, or NULL */
    if (u && weight_general(u->s)) u = NULL;
    int total = 0, direct = u != NULL;
    for (int p = i; p < ie; p++) total += count[p - i];
    for (int q = 0; direct && q < total; q++) direct = pair_interacts(u, dd[q][3]);
    L.dd = direct ? (const double (*)[4])dd : NULL;
    L.noise = noise;
    for (int p = i, off = 0; p < ie; off += count[p - i], p++)
        c[p - i] = direct ? pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 1, u, 1)
                 : u ? pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 1, u, 0)
                     : pan_lanes_fill(s, p, near + off, dd + off, noise + off, count[p - i], &L, &m, le, 0, NULL, 0);
    lanes(&L, m, acc->inv_sqrt_dt, u);
    for (int p = i, k = 0; p < ie; k += c[p - i], p++) {
        pan_lanes_apply(&L, k, c[p - i], acc);
        if (p + 1 < ie || close_last) pair_close_spins(1, p, acc);
    }
}

/* pan_lanes_force for any x86-64: the style's lanes at the portable level;
 * the backend's (pan_lanes_avx2, pan_lanes_avx512) at the others
 * (PairStyle.accel), the same operations, so the same bits. */
PAN_LANES_OPT static void pan_lanes_portable(void *L, int m, double inv_sqrt_dt, const PairParams *u)
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
    .accel = {[SIMD_PORTABLE] = {.lanes = pan_lanes_portable}, [SIMD_AVX2] = {.lanes = SIMD_X86(pan_lanes_avx2)},
              [SIMD_AVX512] = {.one_type = SIMD_X86(pan_one_type_avx512), .lanes = SIMD_X86(pan_lanes_avx512)}},
};
