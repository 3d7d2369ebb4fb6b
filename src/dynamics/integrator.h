/* integrator.h - modified velocity Verlet of Groot & Warren (J. Chem. Phys.
 * 107, 4423, 1997, eq. 16):
 *   r(t+dt)  = r + dt v + dt^2 f / 2m
 *   v~       = v + lambda dt f / m          (velocity the forces see)
 *   f(t+dt)  = f(r(t+dt), v~(t+dt))
 *   v(t+dt)  = v + dt (f(t) + f(t+dt)) / 2m
 * lambda = 0.5 is the plain velocity Verlet. */
#ifndef DPD_INTEGRATOR_H
#define DPD_INTEGRATOR_H

#include "system.h"

/* The Lees-Edwards offset one step on (box_advance), with the image counters
 * of its wraps (box_offset_wrapped); returns its change, rate L_y dt. */
double integrate_advance_offset(System *s);
/* Positions, half-kick and prediction; advances the Lees-Edwards offset and
 * wraps. Returns the change of the offset; s->nonfinite = the number of
 * particles whose position is not finite. */
double integrate_predict(System *s);
/* Second half-kick with the new forces; adds to s->nonfinite the number of
 * mobile particles whose velocity is not finite. */
void integrate_correct(System *s);

/* Specular walls (a constraint after the move): a mobile particle that
 * crossed the plane x_axis = lo or hi is mirrored back, its normal velocity
 * (and prediction) reversed. axis < 0: no walls. */
void integrate_confine(System *s, int axis, double lo, double hi);

#endif
