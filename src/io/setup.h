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

typedef struct {
    long long steps, equilibration;
    double skin;
    int trajectory_every;
    double max_temperature_ratio;  /* blow-up guard: stop if T > this x kBT */
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
