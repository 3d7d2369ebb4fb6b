/* rotation.c - pair forces and torques of Pan, Pivkin & Karniadakis (2008) and
 * the angular-velocity integration. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "rotation.h"
#include "random.h"

#define R_EPSILON 1e-10   /* pairs closer than this have no direction: skipped */

int rotation_alloc(System *s)
{
    const size_t n3 = 3 * (size_t)s->n;
    s->omega = calloc(n3 + 1, sizeof(double));
    s->omega_pred = calloc(n3 + 1, sizeof(double));
    s->torque = calloc(n3 + 1, sizeof(double));
    if (!s->omega || !s->omega_pred || !s->torque) return -1;
    s->rotation = 1;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        double *w = s->omega + 3 * i;
        if (t->frozen) { for (int d = 0; d < 3; d++) w[d] = t->spin[d]; continue; }
        philox4x32_ctr_t r = rng_block(s->seed, STREAM_INIT_SPIN, s->id[i], 0, 0);
        double z[4];
        rng_normal2(r.v[0], r.v[1], &z[0], &z[1]);
        rng_normal2(r.v[2], r.v[3], &z[2], &z[3]);
        const double sd = sqrt(s->kBT / t->inertia);   /* equipartition: I <w_a^2> = kBT */
        for (int d = 0; d < 3; d++) w[d] = sd * z[d];
    }
    memcpy(s->omega_pred, s->omega, n3 * sizeof(double));
    return 0;
}

static inline void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Geometry of one pair at distance r = |d| > 0: the unit vector e = r_ij / r,
 * w_C = 1 - r/rc and Pan's f = (1 - r/rc)^(s/2) in the scene's convention
 * (w_D = f^2 = (1 - r/rc)^s), computed as the standard kernel computes w_R. */
static inline __attribute__((always_inline)) void pair_geometry(const PairParams *p, const double d[3], double r,
                                                                double e[3], double *wc, double *f)
{
    const double inv_r = 1.0 / r;
    e[0] = d[0] * inv_r; e[1] = d[1] * inv_r; e[2] = d[2] * inv_r;
    const double w = 1.0 - r / p->rc;
    *wc = w;
    *f = p->s == 0.5 ? sqrt(sqrt(w)) : p->s == 1.0 ? sqrt(w) : p->s == 2.0 ? w : pow(w, 0.5 * p->s);
}

/* One pair, eqs 13-15 and eq. 1, from its geometry (pair_geometry): the force
 * F_ij on i (F_ji = -F_ij) in Ftot and the torque on each of i and j in tau; the
 * parts (conservative, dissipative, random) in F[0..2] only when F != NULL
 * (measurement steps, tests), so that the pair loop of the other steps computes
 * the totals alone. */
static inline __attribute__((always_inline)) void pair_force(const PairParams *p, const double d[3],
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

void rotation_pair_force(const PairParams *p, const double d[3], const double dv[3],
                         const double wsum[3], double theta, const double xi[3],
                         double inv_sqrt_dt, double F[3][3], double Ftot[3], double tau[3])
{
    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double e[3], wc, f;
    pair_geometry(p, d, r, e, &wc, &f);
    pair_force(p, d, e, wc, f, dv, wsum, theta, xi, inv_sqrt_dt, F, Ftot, tau);
}

/* Virial by part (asymmetric, r_a F_b), its Irving-Kirkwood split, pair energy,
 * force and torque on frozen particles. Only on measurement steps. */
static void accumulate(PairVirial *pv, const System *s, int i, int j, const double d[3], double wc,
                       const double F[3][3], const double tau[3])
{
    const PairParams *p = &s->pair[s->type[i]][s->type[j]];
    for (int q = 0; q < PAIR_PARTS; q++) {
        double t[9];
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) t[3 * a + c] = d[a] * F[q][c];
        for (int kk = 0; kk < 9; kk++) pv->W[q][kk / 3][kk % 3] += t[kk];
        if (pv->nbins > 0)
            ik_distribute(pv->Wbin + (size_t)q * 9 * pv->nbins, pv->nbins, pv->bin_axis,
                          s->box.L[pv->bin_axis], s->x[3 * i + pv->bin_axis], d[pv->bin_axis], t);
    }
    pv->epot += 0.5 * p->a * p->rc * wc * wc;
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

/* The pair loop for the particles [i0, i1), a batch of list entries at a time
 * in four passes, each a short loop with independent iterations: the pairs
 * inside the largest cutoff; their geometry; their noise; their forces and
 * torques (bench/RESULTS.md, issue 6: 3-7 % faster than one pass per pair by
 * best of 5 on a noisy host, not resolved). pv != NULL also sums the virial by part. */
static void pair_loop(const System *s, const NeighborList *nl, int i0, int i1,
                      double *restrict f, double *restrict tq, unsigned char *touched, PairVirial *pv)
{
    const int n = s->n;
    const Box *b = &s->box;
    const double inv_sqrt_dt = 1.0 / sqrt(s->dt);
    const double *x = s->x, *v = s->v_pred, *w = s->omega_pred;
    enum { BATCH = PAIR_BATCH };
    int near[BATCH];
    double dd[BATCH][4];
    double geo[BATCH][8];     /* d[3], e[3], w_C, f */
    double noise[BATCH][4];   /* theta, xi[3] */
    CounterRng rng[BATCH];
    for (int i = i0; i < i1; i++) {
        const int ti = s->type[i];
        const uint32_t id_i = s->id[i];
        const double vi[3] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
        const double wi[3] = {w[3 * i], w[3 * i + 1], w[3 * i + 2]};
        double fi[3] = {0.0, 0.0, 0.0}, ti_[3] = {0.0, 0.0, 0.0};
        for (int k0 = nl->start[i]; k0 < nl->start[i + 1]; k0 += BATCH) {
          const int k1 = k0 + BATCH < nl->start[i + 1] ? k0 + BATCH : nl->start[i + 1];
          const int m0 = pairs_in_range(s, nl, i, k0, k1, near, dd, 1);
          /* pass 2: the pairs inside their own cutoff, and their geometry */
          int m = 0;
          for (int q = 0; q < m0; q++) {
            const int j = near[q];
            const PairParams *p = &s->pair[ti][s->type[j]];
            const double r2 = dd[q][3];
            if (!p->active || r2 >= p->rc2 || r2 < R_EPSILON * R_EPSILON) continue;
            near[m] = j;
            double *g = geo[m++];
            g[0] = dd[q][0]; g[1] = dd[q][1]; g[2] = dd[q][2];
            pair_geometry(p, g, sqrt(r2), g + 3, g + 6, g + 7);
          }
          /* pass 3: the pairs' Philox blocks, then from each theta (eq. 15 central)
           * and xi (eq. 15 antisymmetric), one pair sequence */
          for (int q = 0; q < m; q++) rng_pair_start(&rng[q], s->seed, s->step, id_i, s->id[near[q]]);
          for (int q = 0; q < m; q++) {
            noise[q][0] = rng_counter_normal(&rng[q]);
            if (s->pair[ti][s->type[near[q]]].gamma_shear != 0.0)
                for (int a = 1; a < 4; a++) noise[q][a] = rng_counter_normal(&rng[q]);
            else
                noise[q][1] = noise[q][2] = noise[q][3] = 0.0;
          }
          /* pass 4: forces and torques */
          for (int q = 0; q < m; q++) {
            const int j = near[q];
            const PairParams *p = &s->pair[ti][s->type[j]];
            const double *g = geo[q];
            double dv[3] = {vi[0] - v[3 * j], vi[1] - v[3 * j + 1], vi[2] - v[3 * j + 2]};
            if (b->shear_rate != 0.0) {   /* velocity of the Lees-Edwards image */
                const double dy = x[3 * i + 1] - x[3 * j + 1];
                if (dy > b->half[1]) dv[0] -= b->shear_rate * b->L[1];
                else if (dy < -b->half[1]) dv[0] += b->shear_rate * b->L[1];
            }
            const double wsum[3] = {wi[0] + w[3 * j], wi[1] + w[3 * j + 1], wi[2] + w[3 * j + 2]};
            double Ft[3], tau[3];
            if (pv) {
                double F[3][3];
                pair_force(p, g, g + 3, g[6], g[7], dv, wsum, noise[q][0], noise[q] + 1, inv_sqrt_dt, F, Ft, tau);
                accumulate(pv, s, i, j, g, g[6], F, tau);
            } else {
                pair_force(p, g, g + 3, g[6], g[7], dv, wsum, noise[q][0], noise[q] + 1, inv_sqrt_dt, NULL, Ft, tau);
            }
            force_claim(f, tq, touched, j, n);
            for (int a = 0; a < 3; a++) {
                fi[a] += Ft[a];
                f[3 * j + a] -= Ft[a];
                ti_[a] += tau[a];
                tq[3 * j + a] += tau[a];
            }
          }
        }
        force_claim(f, tq, touched, i, n);
        for (int a = 0; a < 3; a++) { f[3 * i + a] += fi[a]; tq[3 * i + a] += ti_[a]; }
    }
}

void rotation_forces_compute(System *s, const NeighborList *nl, ForceWork *w, PairVirial *pv)
{
    const int n = s->n;
    const size_t stride = 3 * (size_t)n;
    /* contiguous chunks per thread (thread 0: the first half of the particles
     * on 2 threads), as the particle loops of the integrator: each thread
     * reads and writes mostly the particles it will move */
    #pragma omp parallel for schedule(static)
    for (int c = 0; c < FORCE_CHUNKS; c++) {
        double *fb = c == 0 ? s->f : w->buf + (size_t)(c - 1) * stride;
        double *tb = c == 0 ? s->torque : w->tbuf + (size_t)(c - 1) * stride;
        const int i0 = forces_chunk_start(nl, n, c), i1 = forces_chunk_start(nl, n, c + 1);
        PairVirial *cv = NULL;
        if (pv) { cv = &w->chunk[c]; cv->bin_axis = pv->bin_axis; cv->nbins = pv->nbins; forces_zero_virial(cv); }
        pair_loop(s, nl, i0, i1, fb, tb, forces_chunk_mask(w, c), cv);
    }
    forces_sum_chunks(w, s->f, w->buf, s->torque, w->tbuf);
    if (pv) forces_reduce_virial(pv, w);
}

/* Called inside integrate_predict after the positions: same scheme as the
 * velocities, Omega_pred = Omega + lambda dt T / I, Omega += dt T / (2 I). */
void rotation_predict(System *s)
{
    const double dt = s->dt, lam = s->lambda;
    #pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        double *w = s->omega + 3 * i, *wp = s->omega_pred + 3 * i;
        const double *T = s->torque + 3 * i;
        if (t->frozen) { for (int d = 0; d < 3; d++) w[d] = wp[d] = t->spin[d]; continue; }
        const double iI = 1.0 / t->inertia;
        for (int d = 0; d < 3; d++) {
            wp[d] = w[d] + lam * dt * T[d] * iI;
            w[d] += 0.5 * dt * T[d] * iI;
        }
    }
}

void rotation_correct(System *s)
{
    const double dt = s->dt;
    #pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        const double h = 0.5 * dt / t->inertia;
        for (int d = 0; d < 3; d++) s->omega[3 * i + d] += h * s->torque[3 * i + d];
    }
}

double rotation_temperature(const System *s)
{
    double sum = 0.0;
    long long nm = 0;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        const double *w = s->omega + 3 * i;
        sum += t->inertia * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        nm++;
    }
    return nm > 0 ? sum / (3.0 * nm) : 0.0;
}
