/* pair_dpd.h - the standard DPD pair evaluator (Groot & Warren 1997; Mai-Duy
 * et al. 2019 eqs 2-7), plugged into the pair driver (forces.c). Included by
 * forces.c only: its functions are compiled into the driver's walk. */
#ifndef DPD_PAIR_DPD_H
#define DPD_PAIR_DPD_H

#include "pair.h"
#include "random.h"

/* The three force magnitudes along e_ij of one pair from its weights w_C and
 * w_R. theta ~ N(0,1); the noise is discretised as theta / sqrt(dt). */
static inline void dpd_pair_terms_w(const PairParams *p, double wc, double wr, double e_dot_v, double theta,
                                    double inv_sqrt_dt, double *fc, double *fd, double *fr)
{
    *fc = p->a * wc;                                   /* conservative, eq. 2 */
    *fd = -p->gamma * wr * wr * e_dot_v;               /* dissipative, eq. 3 */
    *fr = p->sigma * wr * theta * inv_sqrt_dt;         /* random, eq. 4 */
}

/* The same from the distance r. */
static inline void dpd_pair_terms(const PairParams *p, double r, double e_dot_v, double theta,
                                  double inv_sqrt_dt, double *fc, double *fd, double *fr)
{
    const double wc = 1.0 - r / p->rc;                 /* w_C, eq. 5 */
    const double wr = random_weight(wc, p->s);         /* w_R = sqrt(w_D), eq. 7 */
    dpd_pair_terms_w(p, wc, wr, e_dot_v, theta, inv_sqrt_dt, fc, fd, fr);
}

/* Virial of one pair by part, its Irving-Kirkwood split over slabs, the pair
 * energy and the force on frozen particles. Only on measurement steps, so kept
 * out of line (the pair loop then compiles alike with and without -DDPD_BARE). */
#ifdef __clang__
#define PAIR_NOCLONE   /* clang has no noclone (the fuzzer's build) */
#else
#define PAIR_NOCLONE __attribute__((noclone))
#endif
static __attribute__((noinline)) PAIR_NOCLONE void dpd_pair_record(PairVirial *pv, const System *s, int i, int j,
        const double d[3], double r, const double F[PAIR_PARTS], double fx, double fy, double fz)
{
    const double inv_r = 1.0 / r;
    const PairParams *p = &s->pair[s->type[i]][s->type[j]];
    for (int q = 0; q < PAIR_PARTS; q++) {
        double t[9];
        const double g = F[q] * inv_r;
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) t[3 * a + c] = d[a] * d[c] * g;   /* central: r_a r_b F / r */
        pair_virial_add(pv, s, i, q, d, t);
    }
    pv->epot += pair_energy(p, 1.0 - r / p->rc);
    const int ti = s->type[i], tj = s->type[j];
    if (MOD_FROZEN(&s->types[tj])) {
        pv->frozen_force[tj][0] -= fx; pv->frozen_force[tj][1] -= fy; pv->frozen_force[tj][2] -= fz;
    }
    if (MOD_FROZEN(&s->types[ti])) {
        pv->frozen_force[ti][0] += fx; pv->frozen_force[ti][1] += fy; pv->frozen_force[ti][2] += fz;
    }
}

/* One batch of particle i's pairs (pairs_in_range) with their theta_ij (eq. 4,
 * drawn for the batch by the walk): the force F_ij on i into
 * acc->fi, -F_ij on j into the chunk's buffer; pv != NULL: the virial too.
 * wr: NULL, or w_R of each pair whose exponent is general (weight_general),
 * formed for the walk's batch at once (forces.c). le: the box has
 * Lees-Edwards shear (a constant). */
static inline __attribute__((always_inline))
void dpd_pair_batch(const System *s, int i, const int *near, double (*dd)[4], const double *theta, int m,
                    PairAcc *acc, PairVirial *pv, const int le, const double *wr_batch)
{
    const double inv_sqrt_dt = acc->inv_sqrt_dt;
    const double *v = s->v_pred;
    const int ti = s->type[i];
    double fi[3] = {acc->fi[0], acc->fi[1], acc->fi[2]};   /* in registers across the batch */
    for (int q = 0; q < m; q++) {
        const int j = near[q];
        const PairParams *p = &s->pair[ti][s->type[j]];
        const double r2 = dd[q][3];
        if (!pair_interacts(p, r2)) continue;
        const double d[3] = {dd[q][0], dd[q][1], dd[q][2]};
        double dvx = v[3 * i] - v[3 * j];
        if (le) dvx -= pair_image_vx(s, i, j, le);     /* relative to j's Lees-Edwards image */
        const double r = sqrt(r2), inv_r = 1.0 / r;
        const double e[3] = {d[0] * inv_r, d[1] * inv_r, d[2] * inv_r};
        const double edv = e[0] * dvx + e[1] * (v[3 * i + 1] - v[3 * j + 1])
                         + e[2] * (v[3 * i + 2] - v[3 * j + 2]);
        const double wc = 1.0 - r / p->rc;                                    /* w_C, eq. 5 */
        const double wr = wr_batch && weight_general(p->s) ? wr_batch[q] : random_weight(wc, p->s);   /* eq. 7 */
        double F[PAIR_PARTS];
        dpd_pair_terms_w(p, wc, wr, edv, theta[q], inv_sqrt_dt, &F[PART_CONSERVATIVE], &F[PART_DISSIPATIVE], &F[PART_RANDOM]);
        const double ft = F[0] + F[1] + F[2];
        const double fx = ft * e[0], fy = ft * e[1], fz = ft * e[2];
        fi[0] += fx; fi[1] += fy; fi[2] += fz;
        force_claim(acc->f, NULL, acc->touched, j, acc->n);
        acc->f[3 * j] -= fx; acc->f[3 * j + 1] -= fy; acc->f[3 * j + 2] -= fz;
        if (pv) dpd_pair_record(pv, s, i, j, d, r, F, fx, fy, fz);
    }
    for (int a = 0; a < 3; a++) acc->fi[a] = fi[a];
}

#endif
