/* pair_dpd.h - the standard DPD pair evaluator (Groot & Warren 1997; Mai-Duy
 * et al. 2019 eqs 2-7), plugged into the pair driver (forces.c). Included by
 * forces.c only: its functions are compiled into the driver's walk. */
#ifndef DPD_PAIR_DPD_H
#define DPD_PAIR_DPD_H

#include "pair.h"
#include "random.h"
#include "simd.h"

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


#ifdef DPD_HAVE_X86_SIMD
#include <immintrin.h>
/* dpd_pair_batch for one type pair (u) without shear (pv != NULL: the virial
 * and energy as dpd_pair_record forms them, no frozen type, no bins), the per-pair
 * arithmetic eight pairs at a time on AVX-512: the same IEEE operations in
 * the same order (no contraction), so the same F_ij bits; the sums into
 * acc->fi and -F_ij into f_j are then added pair by pair in list order, as
 * dpd_pair_batch adds them. wcase: w_R from w_C (2: s = 2, 1: s = 1,
 * 0: s = 0.5, -1: the batch's wr, weight_general); inv_rc:
 * rc_power_of_two_inverse(u->rc). pl: the separations x,
 * y, z and r^2 of the pairs as planes, PAIR_PLANE apart (forces.c range_avx512). */
static inline __attribute__((target("avx512f"), always_inline))
void dpd_pair_lanes_avx512(const System *s, int i, const int *near, const double *pl, const double *theta,
                           int m, PairAcc *acc, const PairParams *u, const int wcase, const double *wr_batch,
                           double inv_rc, PairVirial *pv)
{
    const double energy = 0.5 * u->a * u->rc;   /* pair_energy's first factors */
    const double *v = s->v_pred;
    const __m512d vix = _mm512_set1_pd(v[3 * i]), viy = _mm512_set1_pd(v[3 * i + 1]), viz = _mm512_set1_pd(v[3 * i + 2]);
    const __m512d rc2 = _mm512_set1_pd(u->rc2), one = _mm512_set1_pd(1.0);
    const __m512d eps2 = _mm512_set1_pd(PAIR_R_EPSILON * PAIR_R_EPSILON);
    const __m512d a = _mm512_set1_pd(u->a), ngamma = _mm512_set1_pd(-u->gamma), sigma = _mm512_set1_pd(u->sigma);
    const __m512d isdt = _mm512_set1_pd(acc->inv_sqrt_dt);
    double fi0 = acc->fi[0], fi1 = acc->fi[1], fi2 = acc->fi[2];
    for (int q0 = 0; q0 < m; q0 += 8) {
        const PairLanes8 g = pair_lanes_load_avx512(pl, near, q0, m, rc2, eps2);
        const int cnt = g.cnt;
        const __mmask8 live = g.live, act = g.act;
        const __m512d dx = g.d0, dy = g.d1, dz = g.d2, r2 = g.r2;
        const __m256i j3 = g.j3;
        const __m512d z0 = _mm512_setzero_pd();
        const __m512d dvx = _mm512_sub_pd(vix, _mm512_mask_i32gather_pd(z0, live, j3, v, 8));
        const __m512d dvy = _mm512_sub_pd(viy, _mm512_mask_i32gather_pd(z0, live, j3, v + 1, 8));
        const __m512d dvz = _mm512_sub_pd(viz, _mm512_mask_i32gather_pd(z0, live, j3, v + 2, 8));
        const __m512d r = _mm512_sqrt_pd(r2), inv_r = _mm512_div_pd(one, r);
        const __m512d ex = _mm512_mul_pd(dx, inv_r), ey = _mm512_mul_pd(dy, inv_r), ez = _mm512_mul_pd(dz, inv_r);
        const __m512d edv = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ex, dvx), _mm512_mul_pd(ey, dvy)), _mm512_mul_pd(ez, dvz));
        const __m512d wc = _mm512_sub_pd(one, r_over_rc_avx512(r, u->rc, inv_rc));   /* w_C, eq. 5 */
        const __m512d wr = wcase == 2 ? wc : wcase == 1 ? _mm512_sqrt_pd(wc)              /* w_R, eq. 7 */
                         : wcase == 0 ? _mm512_sqrt_pd(_mm512_sqrt_pd(wc)) : _mm512_maskz_loadu_pd(live, wr_batch + q0);
        const __m512d fc = _mm512_mul_pd(a, wc);                                           /* eq. 2 */
        const __m512d fd = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(ngamma, wr), wr), edv); /* eq. 3 */
        const __m512d fr = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(sigma, wr), _mm512_maskz_loadu_pd(live, theta + q0)), isdt); /* eq. 4 */
        const __m512d ft = _mm512_add_pd(_mm512_add_pd(fc, fd), fr);
        if (pv) {   /* dpd_pair_record: r_a r_b F / r by part, the energy a rc w_C^2 / 2 */
            const __m512d d3[3] = {dx, dy, dz}, part[PAIR_PARTS] = {fc, fd, fr};
            __m512d t[PAIR_PARTS * 9];
            for (int q = 0; q < PAIR_PARTS; q++) {
                const __m512d g = _mm512_mul_pd(part[q], inv_r);
                for (int a3 = 0; a3 < 3; a3++)
                    for (int c = 0; c < 3; c++) t[9 * q + 3 * a3 + c] = _mm512_mul_pd(_mm512_mul_pd(d3[a3], d3[c]), g);
            }
            virial_lanes_add(pv, t, _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(energy), wc), wc), act);
        }
        double fx[8], fy[8], fz[8];
        _mm512_storeu_pd(fx, _mm512_mul_pd(ft, ex));
        _mm512_storeu_pd(fy, _mm512_mul_pd(ft, ey));
        _mm512_storeu_pd(fz, _mm512_mul_pd(ft, ez));
        for (int l = 0; l < cnt; l++) {
            if (!(act >> l & 1)) continue;
            const int jj = near[q0 + l];
            fi0 += fx[l]; fi1 += fy[l]; fi2 += fz[l];
            force_claim(acc->f, NULL, acc->touched, jj, acc->n);
            acc->f[3 * jj] -= fx[l]; acc->f[3 * jj + 1] -= fy[l]; acc->f[3 * jj + 2] -= fz[l];
        }
    }
    acc->fi[0] = fi0; acc->fi[1] = fi1; acc->fi[2] = fi2;
}
#endif

#endif
