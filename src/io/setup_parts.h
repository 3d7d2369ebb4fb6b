/* setup_parts.h - the pieces of the input layer (setup.c, setup_measure.c,
 * setup_bodies.c). Each reads one part of a scene, checks it and fills the
 * plain parameter structs of a module; the modules never see the scene.
 * Each returns 0, or -1 with the scene's error (file, line, key, allowed) set. */
#ifndef DPD_SETUP_PARTS_H
#define DPD_SETUP_PARTS_H

#include "scene.h"
#include "system.h"
#include "measure.h"
#include "colloid.h"
#include "bonds.h"

/* Index of the type called name, or -1. */
int setup_type_index(const System *s, const char *name);
/* dq, qmax, threshold of an around group a into p (bins), radii up to hmin. */
int setup_around_range(Scene *sc, const config_setting_t *a, double hmin, AroundParams *p);
/* The measure group (absent: the defaults) of a run of `steps` production steps. */
int setup_measure(Scene *sc, const System *s, Measure *m, long long steps);
/* colloids = {...} (group g) with counts[t] particles of each type: *out, or NULL on error. */
int setup_colloids(Scene *sc, const config_setting_t *g, const System *s, const long long *counts,
                   Colloids **out);
/* colloids2d = {...} (group g): *out, NULL on error or for count = 0. */
int setup_bonds(Scene *sc, const config_setting_t *g, const System *s, const long long *counts,
                long long steps, int nblocks, Bonds **out);

#endif
