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
        for (int a = 0; a < 4; a++) noise[m][a] = noise0[4 * q + a];
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

#endif
