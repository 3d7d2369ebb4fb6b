/* setup.h - from a validated scene to a ready system: types, pair table,
 * initial positions and velocities, measurement and run settings. The input
 * layer is scene.c (the file and its checks), setup.c (this), and
 * setup_measure.c, setup_bodies.c (the modules' parameter structs,
 * setup_parts.h): no other file reads the scene. */
#ifndef DPD_SETUP_H
#define DPD_SETUP_H

#include "scene.h"
#include "system.h"
#include "overdamped.h"
#include "measure.h"
#include "colloid.h"
#include "bonds.h"

/* The default blow-up limit of the thermal temperature, in kBT (stability.c): the Groot-Warren
 * fluid (a = 25, gamma = 4.5, rho = 3) at dt = 0.15 runs at 12.8 kBT. Measured on the committed
 * experiments' runs (2026-12-05): their thermal temperature stays below 1.6 kBT in production,
 * driven flows included (phan-thien-2016 fig04 and fig08: 1.5 and 1.9, where the whole system's
 * kinetic temperature is 13 to 16 kBT), and reaches 2.4 kBT at most in the first steps, where a
 * random initial state relaxes (methods/speed-accuracy, the largest stable dt of the mai-duy-2019
 * solvent): 5 keeps twice that margin and stops a run several times too hot. */
#define DEFAULT_MAX_THERMAL_RATIO 5.0

typedef struct {
    long long steps, equilibration;
    double skin;
    int trajectory_every;
    double max_temperature_ratio;  /* blow-up guard: stop if T > this x kBT */
    double max_thermal_ratio;      /* and if the thermal temperature (the flow removed) > this x kBT
                                    * (0: no such check, a scene that sets max_temperature_ratio) */
    /* m = 0 (Phan-Thien et al. 2016): velocities from A v = f every step */
    int overdamped;
    OdSettings od;            /* its solver (overdamped.h) */
    /* specular walls for mobile particles: confine_axis < 0 for none */
    int confine_axis;
    double confine_lo, confine_hi;
    /* frozen particles at rest during equilibration, at their velocity from
     * production step 0 (start-up flows, Phan-Thien et al. 2016 Fig. 4) */
    int walls_start_at_production;
    Colloids *colloids;       /* spring-model colloids (colloid.h), NULL if none */
    Bonds *bonds;             /* massless 2D spring colloids (bonds.h), NULL if none */
} RunConfig;

/* Reads every key; on error returns -1 with sc->error set. */
int setup_from_scene(Scene *sc, System *s, Measure *m, RunConfig *rc);
/* Non-zero: setup_from_scene only validates (returns before allocating and
 * placing particles); the scene fuzzer sets it. */
extern int setup_validate_only;

#endif
