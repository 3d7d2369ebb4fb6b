/* modules.h - the run-time tests of the optional modules on the hot path, in
 * one place. A scene switches a module on (Lees-Edwards shear, frozen or
 * moving particles, body forces, walls, rotation, colloids, bonds, the m = 0
 * solver, TCAF / MSD / RDF / COM / profile measurements); in a scene without
 * it the test is false and the module's code is skipped.
 *
 * A build with -DDPD_BARE (make build/dpd-bare) turns every test into the
 * constant 0: the compiler removes the module code from the pair kernel, the
 * integrator, the step loop and the sampling, and setup.c refuses scenes that
 * switch a module on. On a scene without modules the two builds compute the
 * same numbers bit for bit (tests/bare.sh); make bench runs them side by side
 * (what the tests of unused modules cost: instructions and CPU time). */
#ifndef DPD_MODULES_H
#define DPD_MODULES_H

#ifdef DPD_BARE
#define DPD_MODULES 0
#else
#define DPD_MODULES 1
#endif

#define MOD_SHEAR(b)      (DPD_MODULES && (b)->shear_rate != 0.0)   /* Lees-Edwards images */
#define MOD_FROZEN(t)     (DPD_MODULES && (t)->frozen)              /* frozen / moving particles */
#define MOD_BODY_FORCE(s) (DPD_MODULES && (s)->has_body_force)
#define MOD_ROTATION(s)   (DPD_MODULES && (s)->rotation)
#define MOD_ON(x)         (DPD_MODULES && (x))                      /* any other switch or pointer */

#endif
