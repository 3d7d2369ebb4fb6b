/* rotation.h - rotating DPD particles with central and shear dissipation
 * (Pan, Pivkin & Karniadakis 2008, eqs 1 and 13-15; the fluid particle model of
 * Espanol 1998 with A~ = 0). Used only by scenes with `rotation = true`: they
 * get angular velocities, torques and the pair style of pair_pan2008.c;
 * other scenes pay nothing. */
#ifndef DPD_ROTATION_H
#define DPD_ROTATION_H

#include "system.h"

/* Allocate omega, omega_pred, torque; angular velocities drawn from
 * Maxwell-Boltzmann at kBT / I (mobile) or set to the type's spin (frozen). */
int  rotation_alloc(System *s);

/* Groot-Warren velocity Verlet for the angular velocities (called by the
 * integrator after/before its translational part). */
void rotation_predict(System *s);
void rotation_correct(System *s);

/* Rotational kinetic temperature sum I omega^2 / (3 N_mobile). */
double rotation_temperature(const System *s);

#endif
