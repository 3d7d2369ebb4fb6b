/* pairutil.h - one pair through a registered pair style (pair_style.h:
 * PairStyle.one, the style's evaluator out of line), in the forms the tests
 * use. */
#ifndef DPD_PAIRUTIL_H
#define DPD_PAIRUTIL_H

#include "testutil.h"
#include "pair_style.h"
#include "random.h"

/* The pair's input: separation d (r, e = d / r as the walk forms them),
 * relative velocity dv, Omega_i + Omega_j, variates theta and xi[3] (in the
 * walk's noise planes, noise: 4 RNG_BATCH doubles), 1 / sqrt(dt). */
static inline void pu_in(PairIn *in, double *noise, const double d[3], const double dv[3], const double wsum[3],
                         double theta, const double xi[3], double inv_sqrt_dt)
{
    memset(in, 0, sizeof *in);
    for (int a = 0; a < 3; a++) { in->d[a] = d[a]; in->dv[a] = dv[a]; in->wsum[a] = wsum[a]; }
    in->r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    in->inv_r = 1.0 / in->r;
    for (int a = 0; a < 3; a++) in->e[a] = d[a] * in->inv_r;
    noise[0] = theta;
    for (int k = 0; k < 3; k++) noise[(k + 1) * RNG_BATCH] = xi ? xi[k] : 0.0;
    in->noise = noise;
    in->prep = NULL;
    in->inv_sqrt_dt = inv_sqrt_dt;
}

static inline const PairStyle *pu_style(const char *name)
{
    const PairStyle *st = pair_style_find(name);
    CHECK_TRUE(st != NULL, "no pair style named %s", name);
    return st;
}

/* Standard DPD: the three force magnitudes along e_ij at distance r for a
 * given e_ij . v_ij (e = x exactly). */
static inline void dpd_pair_magnitudes(const PairParams *p, double r, double e_dot_v, double theta,
                                       double inv_sqrt_dt, double *fc, double *fd, double *fr)
{
    static double noise[4 * RNG_BATCH];
    const double d[3] = {r, 0.0, 0.0}, dv[3] = {e_dot_v, 0.0, 0.0}, zero[3] = {0.0, 0.0, 0.0};
    PairIn in;
    PairOut out;
    pu_in(&in, noise, d, dv, zero, theta, zero, inv_sqrt_dt);
    in.e[0] = 1.0;
    pu_style("dpd")->one(p, &in, &out);
    *fc = out.mag[PART_CONSERVATIVE]; *fd = out.mag[PART_DISSIPATIVE]; *fr = out.mag[PART_RANDOM];
}

/* Pan et al. 2008: F_ij by part (F[0] conservative, F[1] dissipative, F[2]
 * random), their total as the walk sums it (Ftot) and the torque on each of
 * i and j (eq. 1). d = r_i - r_j, dv = v_i - v_j, wsum = Omega_i + Omega_j. */
static inline void pan2008_pair_force(const PairParams *p, const double d[3], const double dv[3], const double wsum[3],
                                      double theta, const double xi[3], double inv_sqrt_dt, double F[3][3],
                                      double Ftot[3], double tau[3])
{
    static double noise[4 * RNG_BATCH];
    PairIn in;
    PairOut out;
    pu_in(&in, noise, d, dv, wsum, theta, xi, inv_sqrt_dt);
    pu_style("pan2008")->one(p, &in, &out);
    memcpy(F, out.part, sizeof out.part);
    for (int a = 0; a < 3; a++) { Ftot[a] = out.F[a]; tau[a] = out.tau[a]; }
}

#endif
