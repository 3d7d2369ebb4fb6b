/* rotation.h - rotating DPD particles with central and shear dissipation
 * (Pan, Pivkin & Karniadakis 2008, eqs 1 and 13-15; the fluid particle model of
 * Espanol 1998 with A~ = 0). Used only by scenes with `rotation = true`: they
 * get angular velocities, torques and this pair kernel; other scenes pay nothing. */
#ifndef DPD_ROTATION_H
#define DPD_ROTATION_H

#include "system.h"
#include "neighbor.h"
#include "forces.h"

/* Allocate omega, omega_pred, torque; angular velocities drawn from
 * Maxwell-Boltzmann at kBT / I (mobile) or set to the type's spin (frozen). */
int  rotation_alloc(System *s);

/* Forces and torques of eqs 13-15 and eq. 1 for every pair, deterministic for
 * any thread count (FORCE_CHUNKS fixed chunks summed in a fixed order), plus the
 * virial by part when pv != NULL (full asymmetric r_a F_b). No body forces.
 * w comes from forces_init of this rotation system (its torque buffers). */
void rotation_forces_compute(System *s, const NeighborList *nl, ForceWork *w, PairVirial *pv);

/* One pair: force F_ij on i (F_ji = -F_ij) and torque tau on each of i and j
 * (eq. 1: T_i = T_j = -(r_ij / 2) x F_ij). d = r_i - r_j, dv = v_i - v_j,
 * wsum = Omega_i + Omega_j, theta ~ N(0,1) (central noise), xi[3] ~ N(0,1)
 * (antisymmetric noise). F parts: [0] conservative, [1] dissipative
 * (translational + rotational), [2] random, each a vector; Ftot their sum,
 * rounded as the standard kernel rounds it (bit-identical when gamma^S = 0).
 * Exposed for tests. */
void rotation_pair_force(const PairParams *p, const double d[3], const double dv[3],
                         const double wsum[3], double theta, const double xi[3],
                         double inv_sqrt_dt, double F[3][3], double Ftot[3], double tau[3]);

/* Groot-Warren velocity Verlet for the angular velocities (called by the
 * integrator after/before its translational part). */
void rotation_predict(System *s);
void rotation_correct(System *s);

/* Rotational kinetic temperature sum I omega^2 / (3 N_mobile). */
double rotation_temperature(const System *s);

#endif
