/* setup_bodies.c - the colloids and colloids2d groups of a scene into the
 * parameters of the spring-model colloids (colloid.h, bonds.h). Part of the
 * input layer (setup_parts.h). */
#include <math.h>
#include "setup_parts.h"

/* type = "..." of a colloid group: a mobile type with `per` particles per colloid. */
static int read_colloid_type(Scene *sc, const config_setting_t *g, const System *s, const char **tn, int *t)
{
    if (scene_string(sc, g, "type", tn, NULL, NULL, 1) < 0) return -1;
    *t = setup_type_index(s, *tn);
    if (*t < 0) return scene_fail(sc, g, "unknown type \"%s\"", *tn);
    if (s->types[*t].frozen) return scene_fail(sc, g, "type \"%s\" is frozen; colloid particles must move", *tn);
    return 0;
}

/* The colloid type must hold `per` particles for each of the ncol colloids. */
static int check_count(Scene *sc, const config_setting_t *g, const char *tn, long long have, int ncol, int per)
{
    if (have == (long long)per * ncol) return 0;
    return scene_fail(sc, g, "type \"%s\" has %lld particles; %d colloids of %d need count = %d",
                      tn, have, ncol, per, per * ncol);
}

int setup_colloids(Scene *sc, const config_setting_t *g, const System *s, const long long *counts,
                   Colloids **out)
{
    *out = NULL;
    if (s->box.dim != 3) return scene_fail(sc, g, "spring-model colloids need dimension = 3");
    ColloidParams p = {0};
    const char *tn;
    long long v;
    if (read_colloid_type(sc, g, s, &tn, &p.type)) return -1;
    if (scene_int(sc, g, "per_axis", &v, 1, 1, 100, 1) < 0) return -1;
    p.per_axis = (int)v;
    const int ncol = p.per_axis * p.per_axis * p.per_axis;
    if (check_count(sc, g, tn, counts[p.type], ncol, COLLOID_P)) return -1;
    if (scene_double(sc, g, "H", &p.H, 0.0, 1e-6, 1e7, 1) < 0) return -1;
    if (scene_double(sc, g, "site_distance", &p.d, 0.5, 0.0, 10.0, 0) < 0) return -1;
    const double m = s->types[p.type].mass;
    if (scene_double(sc, g, "mass", &p.mass, COLLOID_P * m, 1e-9, 1e9, 0) < 0) return -1;
    /* default: the inertia of p point masses m at the sites, (2/3) p m d^2 */
    const double idef = p.d > 0 ? 2.0 / 3.0 * COLLOID_P * m * p.d * p.d : 1.0;
    if (scene_double(sc, g, "inertia", &p.inertia, idef, 1e-9, 1e9, 0) < 0) return -1;
    const double spacing = s->box.L[0] / p.per_axis;
    if (2.0 * p.d >= spacing)
        return scene_fail(sc, g, "site_distance %g: octahedra of size %g overlap at the lattice spacing %g",
                          p.d, 2.0 * p.d, spacing);
    *out = colloid_new(&p);
    return *out ? 0 : scene_fail(sc, g, "out of memory");
}

/* around = { type; dq; qmax; threshold; } about the colloid centres */
static int read_bonds_around(Scene *sc, const config_setting_t *a, const System *s, AroundParams *p)
{
    const char *tn;
    p->on = 1;
    if (scene_string(sc, a, "type", &tn, NULL, NULL, 1) < 0) return -1;
    p->type = setup_type_index(s, tn);
    if (p->type < 0) return scene_fail(sc, a, "unknown type \"%s\"", tn);
    return setup_around_range(sc, a, 0.5 * fmin(s->box.L[0], s->box.L[1]), p);
}

/* rdf = { rmax; bins; } of the colloid centres */
static int read_bonds_rdf(Scene *sc, const config_setting_t *rd, const System *s, BondParams *p)
{
    long long v;
    p->rdf_on = 1;
    const double hmin = 0.5 * fmin(s->box.L[0], s->box.L[1]);
    if (scene_double(sc, rd, "rmax", &p->rdf_rmax, hmin, 1e-3, hmin, 0) < 0) return -1;
    if (scene_int(sc, rd, "bins", &v, 60, 1, 100000, 0) < 0) return -1;
    p->rdf_bins = (int)v;
    return 0;
}

/* type, count, side, H: the colloids themselves */
static int read_bonds_shape(Scene *sc, const config_setting_t *g, const System *s, const long long *counts,
                            BondParams *p)
{
    const char *tn;
    long long v;
    if (read_colloid_type(sc, g, s, &tn, &p->type)) return -1;
    if (scene_int(sc, g, "count", &v, 1, 0, 100000, 1) < 0) return -1;   /* 0: the solvent alone */
    p->ncol = (int)v;
    if (check_count(sc, g, tn, counts[p->type], p->ncol, BOND_P)) return -1;
    if (scene_double(sc, g, "side", &p->side, 0.25, 1e-3, 0.5 * s->rc_max, 0) < 0) return -1;
    if (scene_double(sc, g, "H", &p->H, 1000.0, 0.0, 1e7, 0) < 0) return -1;
    /* colloids on a grid of cells of side L / m: their triangles must fit */
    const int m = p->ncol > 0 ? (int)ceil(sqrt((double)p->ncol)) : 1;
    const double cell = fmin(s->box.L[0], s->box.L[1]) / m;
    if (p->side >= cell)
        return scene_fail(sc, g, "side %g: %d colloids on a %d x %d grid of cells %g wide would overlap",
                          p->side, p->ncol, m, m, cell);
    return 0;
}

int setup_bonds(Scene *sc, const config_setting_t *g, const System *s, const long long *counts,
                long long steps, int nblocks, Bonds **out)
{
    *out = NULL;
    if (s->box.dim != 2) return scene_fail(sc, g, "colloids2d need dimension = 2");
    BondParams p = {0};
    long long v;
    if (read_bonds_shape(sc, g, s, counts, &p)) return -1;
    if (scene_int(sc, g, "every", &v, 10, 1, 1000000, 0) < 0) return -1;
    p.every = (int)v;
    if (scene_int(sc, g, "msd_window", &v, 100 * p.every, p.every, 100000000, 0) < 0) return -1;
    if (v % p.every) return scene_fail(sc, g, "msd_window (%lld) must be a multiple of every (%d)", v, p.every);
    if (v > steps / 2) return scene_fail(sc, g, "msd_window %lld is longer than half the run (%lld steps)", v, steps);
    p.msd_window = (int)(v / p.every);
    config_setting_t *a = scene_child(sc, g, "around", CONFIG_TYPE_GROUP);
    if (sc->failed || (a && read_bonds_around(sc, a, s, &p.around))) return -1;
    config_setting_t *rd = scene_child(sc, g, "rdf", CONFIG_TYPE_GROUP);
    if (sc->failed || (rd && read_bonds_rdf(sc, rd, s, &p))) return -1;
    if (p.ncol == 0) return 0;   /* every key read: nothing to build */
    *out = bonds_new(&p, nblocks, steps);
    return *out ? 0 : scene_fail(sc, g, "out of memory");
}
