/* setup.c - scene to system. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "setup.h"
#include "setup_parts.h"
#include "random.h"
#include "overdamped.h"
#include "rotation.h"

int setup_validate_only = 0;

static const char *const AXES[] = {"x", "y", "z", NULL};
static const char *const AXES_NONE[] = {"none", "x", "y", "z", NULL};
static const char *const PLACEMENTS[] = {"random", "lattice", NULL};

typedef struct {
    long long count;
    double lo[3], hi[3];
    int lattice;
    double *at;               /* explicit positions (3 per particle), or NULL */
} TypeInit;

int setup_type_index(const System *s, const char *name)
{
    for (int t = 0; t < s->ntypes; t++)
        if (strcmp(s->types[t].name, name) == 0) return t;
    return -1;
}

/* positions = ( [x, y], ... ): particles placed one by one (frozen bodies). */
static int read_positions(Scene *sc, config_setting_t *g, const System *s, TypeInit *ti)
{
    config_setting_t *list = scene_child(sc, g, "positions", CONFIG_TYPE_LIST);
    if (!list) return sc->failed ? -1 : 0;
    const int n = config_setting_length(list), dim = s->box.dim;
    if (n < 1) return scene_fail(sc, list, "'positions' is empty; give at least one [x, y%s]", dim == 3 ? ", z" : "");
    ti->at = calloc(3 * (size_t)n, sizeof(double));
    if (!ti->at) return scene_fail(sc, list, "out of memory");
    for (int k = 0; k < n; k++) {
        config_setting_t *e = config_setting_get_elem(list, (unsigned)k);
        const int t = config_setting_type(e);
        if ((t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST) || config_setting_length(e) != dim)
            return scene_fail(sc, e, "position %d must be an array of %d numbers", k, dim);
        for (int d = 0; d < dim; d++) {
            config_setting_t *c = config_setting_get_elem(e, (unsigned)d);
            const int ct = config_setting_type(c);
            const double x = ct == CONFIG_TYPE_FLOAT ? config_setting_get_float(c)
                           : ct == CONFIG_TYPE_INT ? (double)config_setting_get_int(c) : NAN;
            if (!(x >= 0.0 && x < s->box.L[d]))
                return scene_fail(sc, e, "position %d: %c = %g must be a number in [0, %g)", k, "xyz"[d], x, s->box.L[d]);
            ti->at[3 * k + d] = x;
        }
    }
    ti->count = n;
    return 1;
}

/* hold_mean_velocity = [ux, uy, uz]: the type's mean velocity is reset to this
 * vector after every step (integrator.c), so that a flow past frozen particles
 * runs at a prescribed superficial velocity instead of relaxing to it over the
 * total momentum's time N m / zeta; it is also the type's initial drift. */
static int read_held_velocity(Scene *sc, config_setting_t *g, System *s, ParticleType *pt)
{
    int got = 0;
    if (scene_vector(sc, g, "hold_mean_velocity", pt->held_velocity, s->box.dim, &got, -1e6, 1e6, 0) < 0) return -1;
    if (!got) return 0;
    const config_setting_t *key = config_setting_get_member(g, "hold_mean_velocity");
    if (pt->frozen) return scene_fail(sc, key, "hold_mean_velocity needs a mobile type (this one is frozen)");
    for (int d = 0; d < s->box.dim; d++)
        if (pt->body_force[d] != 0.0 || pt->wall_velocity[d] != 0.0)
            return scene_fail(sc, key, "hold_mean_velocity sets the type's drift and replaces its body force: "
                              "give no 'velocity' or 'body_force' with it");
    memcpy(pt->wall_velocity, pt->held_velocity, sizeof pt->held_velocity);   /* the initial drift */
    pt->hold_velocity = 1;
    s->has_held_velocity = 1;
    return 0;
}

static int read_types(Scene *sc, System *s, TypeInit *ti)
{
    config_setting_t *list = scene_child(sc, NULL, "types", CONFIG_TYPE_LIST);
    if (!list) return sc->failed ? -1 : scene_fail(sc, NULL, "required key 'types' is missing (a list of groups)");
    s->ntypes = config_setting_length(list);
    if (s->ntypes < 1 || s->ntypes > DPD_MAX_TYPES)
        return scene_fail(sc, list, "%d types; allowed 1 to %d", s->ntypes, DPD_MAX_TYPES);
    const int dim = s->box.dim;
    for (int t = 0; t < s->ntypes; t++) {
        config_setting_t *g = config_setting_get_elem(list, (unsigned)t);
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return scene_fail(sc, g, "each type must be a group { name = ...; ... }");
        ParticleType *pt = &s->types[t];
        memset(pt, 0, sizeof *pt);
        const char *name;
        if (scene_string(sc, g, "name", &name, NULL, NULL, 1) < 0) return -1;
        if (strlen(name) == 0 || strlen(name) >= sizeof pt->name)
            return scene_fail(sc, g, "type name must have 1 to %zu characters", sizeof pt->name - 1);
        if (setup_type_index(s, name) >= 0 && setup_type_index(s, name) < t)
            return scene_fail(sc, g, "type name \"%s\" used twice", name);
        snprintf(pt->name, sizeof pt->name, "%s", name);
        if (scene_double(sc, g, "mass", &pt->mass, 1.0, 1e-12, 1e12, 0) < 0) return -1;
        if (scene_bool(sc, g, "frozen", &pt->frozen, 0) < 0) return -1;
        if (scene_vector(sc, g, "velocity", pt->wall_velocity, dim, NULL, -1e6, 1e6, 0) < 0) return -1;
        if (scene_vector(sc, g, "body_force", pt->body_force, dim, NULL, -1e6, 1e6, 0) < 0) return -1;
        const char *flip;
        if (scene_string(sc, g, "body_force_flip_axis", &flip, "none", AXES_NONE, 0) < 0) return -1;
        pt->body_force_flip_axis = strcmp(flip, "none") == 0 ? -1 : flip[0] - 'x';
        /* rotation scenes: I = 0.1 m by default, a solid sphere of radius rc / 2 (0.4 m (rc/2)^2) */
        if (scene_double(sc, g, "inertia", &pt->inertia, 0.1 * pt->mass, 1e-9, 1e9, 0) < 0) return -1;
        if (scene_vector(sc, g, "spin", pt->spin, 3, NULL, -1e6, 1e6, 0) < 0) return -1;
        if ((pt->spin[0] != 0.0 || pt->spin[1] != 0.0 || pt->spin[2] != 0.0) && (!pt->frozen || !s->rotation))
            return scene_fail(sc, g, "spin (a prescribed angular velocity) needs frozen = true and rotation = true");
        if (pt->body_force_flip_axis >= dim)
            return scene_fail(sc, g, "body_force_flip_axis \"%s\" does not exist in %dD", flip, dim);
        for (int d = 0; d < dim; d++) if (pt->body_force[d] != 0.0 && !pt->frozen) s->has_body_force = 1;
        if (read_held_velocity(sc, g, s, pt)) return -1;
        /* placement */
        for (int d = 0; d < 3; d++) { ti[t].lo[d] = 0.0; ti[t].hi[d] = d < dim ? s->box.L[d] : 0.0; }
        config_setting_t *reg = scene_child(sc, g, "region", CONFIG_TYPE_GROUP);
        if (sc->failed) return -1;
        if (reg) {
            if (scene_vector(sc, reg, "lo", ti[t].lo, dim, NULL, 0.0, 1e9, 1) < 0) return -1;
            if (scene_vector(sc, reg, "hi", ti[t].hi, dim, NULL, 0.0, 1e9, 1) < 0) return -1;
            for (int d = 0; d < dim; d++)
                if (ti[t].hi[d] <= ti[t].lo[d] || ti[t].hi[d] > s->box.L[d])
                    return scene_fail(sc, reg, "region must satisfy 0 <= lo < hi <= box along %c (lo %g, hi %g, box %g)",
                                      "xyz"[d], ti[t].lo[d], ti[t].hi[d], s->box.L[d]);
        }
        double vol = 1.0;
        for (int d = 0; d < dim; d++) vol *= ti[t].hi[d] - ti[t].lo[d];
        const int hp = read_positions(sc, g, s, &ti[t]);
        if (hp < 0) return -1;
        if (hp) {
            if (reg || config_setting_get_member(g, "density") || config_setting_get_member(g, "count")
                || config_setting_get_member(g, "placement"))
                return scene_fail(sc, g, "'positions' fixes the particles: give no 'count', 'density', "
                                  "'region' or 'placement' with it");
            continue;
        }
        double density;
        long long count;
        const int hd = scene_double(sc, g, "density", &density, 0.0, 0.0, 1e3, 0);
        const int hc = scene_int(sc, g, "count", &count, 0, 0, 100000000LL, 0);
        if (hd < 0 || hc < 0) return -1;
        if (hd == hc) return scene_fail(sc, g, "give exactly one of 'density' and 'count'");
        if (hd && density * vol > 2e8)   /* before llround: it overflows */
            return scene_fail(sc, config_setting_get_member(g, "density"), "density %g times volume %g "
                              "makes %g particles; allowed up to 2e8", density, vol, density * vol);
        ti[t].count = hd ? llround(density * vol) : count;
        const char *pl;
        if (scene_string(sc, g, "placement", &pl, "random", PLACEMENTS, 0) < 0) return -1;
        ti[t].lattice = strcmp(pl, "lattice") == 0;
    }
    return 0;
}

static int read_pairs(Scene *sc, System *s)
{
    config_setting_t *list = scene_child(sc, NULL, "pairs", CONFIG_TYPE_LIST);
    if (!list) return sc->failed ? -1 : scene_fail(sc, NULL, "required key 'pairs' is missing (a list of groups)");
    int seen[DPD_MAX_TYPES][DPD_MAX_TYPES] = {{0}};
    s->rc_max = 0.0;
    for (int k = 0; k < config_setting_length(list); k++) {
        config_setting_t *g = config_setting_get_elem(list, (unsigned)k);
        if (config_setting_type(g) != CONFIG_TYPE_GROUP)
            return scene_fail(sc, g, "each pair must be a group { types = [\"a\", \"b\"]; ... }");
        config_setting_t *tl = scene_child(sc, g, "types", CONFIG_TYPE_ARRAY);
        if (!tl) return sc->failed ? -1 : scene_fail(sc, g, "required key 'types' is missing (two type names)");
        if (config_setting_length(tl) != 2 || config_setting_type(config_setting_get_elem(tl, 0)) != CONFIG_TYPE_STRING)
            return scene_fail(sc, tl, "expected two type names, e.g. [\"solvent\", \"solvent\"]");
        int t2[2];
        for (int e = 0; e < 2; e++) {
            const char *nm = config_setting_get_string_elem(tl, e);
            t2[e] = setup_type_index(s, nm);
            if (t2[e] < 0) return scene_fail(sc, tl, "unknown type \"%s\"", nm);
        }
        if (seen[t2[0]][t2[1]]) return scene_fail(sc, g, "pair (%s, %s) defined twice",
                                                  s->types[t2[0]].name, s->types[t2[1]].name);
        seen[t2[0]][t2[1]] = seen[t2[1]][t2[0]] = 1;
        PairParams p = {.active = 1};
        /* a up to 1e7: the stability map bisects dt_max ~ 0.58 / sqrt(a) out to there */
        if (scene_double(sc, g, "a", &p.a, 0.0, 0.0, 1e7, 1) < 0) return -1;
        if (scene_double(sc, g, "gamma", &p.gamma, 0.0, 0.0, 1e6, 1) < 0) return -1;
        if (scene_double(sc, g, "s", &p.s, 2.0, 1e-3, 10.0, 0) < 0) return -1;
        if (scene_double(sc, g, "gamma_shear", &p.gamma_shear, 0.0, 0.0, 1e6, 0) < 0) return -1;
        if (p.gamma_shear > 0.0 && !s->rotation)
            return scene_fail(sc, g, "gamma_shear = %g needs rotation = true (Pan et al. 2008 shear dissipation)", p.gamma_shear);
        if (scene_double(sc, g, "rc", &p.rc, 1.0, 1e-3, 1e3, 0) < 0) return -1;
        int active;
        if (scene_bool(sc, g, "interact", &active, 1) < 0) return -1;
        p.active = active;
        system_set_pair(s, t2[0], t2[1], p);
    }
    for (int a = 0; a < s->ntypes; a++)
        for (int b = a; b < s->ntypes; b++)
            if (!seen[a][b])
                return scene_fail(sc, list, "pair (%s, %s) is not defined; every pair of types needs an entry "
                                  "(use interact = false for none)", s->types[a].name, s->types[b].name);
    return 0;
}

static void place_particles(System *s, const TypeInit *ti)
{
    const int dim = s->box.dim;
    int i = 0;
    for (int t = 0; t < s->ntypes; t++) {
        double ext[3] = {1, 1, 1};
        for (int d = 0; d < dim; d++) ext[d] = ti[t].hi[d] - ti[t].lo[d];
        long long msite[3] = {1, 1, 1};
        if (ti[t].lattice && ti[t].count > 0) {
            double vol = 1.0;
            for (int d = 0; d < dim; d++) vol *= ext[d];
            const double h = pow(vol / ti[t].count, 1.0 / dim);
            for (int d = 0; d < dim; d++) msite[d] = llround(ext[d] / h) > 0 ? llround(ext[d] / h) : 1;
            while (msite[0] * msite[1] * msite[2] < ti[t].count) {
                int dm = 0;
                for (int d = 1; d < dim; d++) if (ext[d] / msite[d] > ext[dm] / msite[dm]) dm = d;
                msite[dm]++;
            }
        }
        for (long long k = 0; k < ti[t].count; k++, i++) {
            s->id[i] = (uint32_t)i;
            s->type[i] = (uint8_t)t;
            double *x = s->x + 3 * i;
            if (ti[t].at) {
                for (int d = 0; d < dim; d++) x[d] = ti[t].at[3 * k + d];
            } else if (ti[t].lattice) {
                /* spread the count evenly over the sites when there are more sites */
                const long long nsite = msite[0] * msite[1] * msite[2];
                long long q = (long long)((double)k * nsite / ti[t].count);
                for (int d = 0; d < dim; d++) {
                    const long long c = q % msite[d];
                    q /= msite[d];
                    x[d] = ti[t].lo[d] + (c + 0.5) * ext[d] / msite[d];
                }
            } else {
                philox4x32_ctr_t r = rng_block(s->seed, STREAM_INIT_POSITION, (uint64_t)i, 0, 0);
                for (int d = 0; d < dim; d++) x[d] = ti[t].lo[d] + rng_u01(r.v[d]) * ext[d];
            }
            for (int d = 0; d < dim; d++) if (x[d] >= s->box.L[d]) x[d] -= s->box.L[d];
        }
    }
}

static void initial_velocities(System *s)
{
    double p[3] = {0, 0, 0}, mtot = 0.0;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        double *v = s->v + 3 * i;
        if (t->frozen) { for (int d = 0; d < 3; d++) v[d] = t->wall_velocity[d]; continue; }
        philox4x32_ctr_t r = rng_block(s->seed, STREAM_INIT_VELOCITY, s->id[i], 0, 0);
        double z[4];
        rng_normal2(r.v[0], r.v[1], &z[0], &z[1]);
        rng_normal2(r.v[2], r.v[3], &z[2], &z[3]);
        const double sd = t->mass > 0.0 ? sqrt(s->kBT / t->mass) : 0.0;   /* m = 0: solved, not drawn */
        for (int d = 0; d < s->box.dim; d++) { v[d] = sd * z[d]; p[d] += t->mass * v[d]; }
        mtot += t->mass;
    }
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        double *v = s->v + 3 * i;
        if (mtot > 0 && s->n_frozen == 0)
            for (int d = 0; d < s->box.dim; d++) v[d] -= p[d] / mtot;
        /* a mobile type's velocity is its initial drift (a flow started near its steady state) */
        for (int d = 0; d < s->box.dim; d++) v[d] += t->wall_velocity[d];
        v[0] += box_stream_vx(&s->box, s->x[3 * i + 1]);
    }
    memcpy(s->v_pred, s->v, 3 * (size_t)s->n * sizeof(double));
}

/* overdamped = { solver = "pcg"; stop = "change"; tolerance = 1e-7; ... }: every
 * mobile particle is massless and its velocity solves A v = f (eqs 14-18). */
static int read_overdamped(Scene *sc, System *s, RunConfig *rc)
{
    static const char *const SOLVERS[] = {"scheme1", "scheme2_paper", "scheme2_consistent", "pcg", "pcg_2level", NULL};
    static const char *const STOPS[] = {"change", "residual", NULL};
    config_setting_t *g = scene_child(sc, NULL, "overdamped", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    rc->overdamped = g != NULL;
    if (!g) return 0;
    const char *name;
    if (scene_string(sc, g, "solver", &name, "pcg", SOLVERS, 0) < 0) return -1;
    for (int k = 0; SOLVERS[k]; k++) if (!strcmp(SOLVERS[k], name)) rc->od.solver = (OdSolver)k;
    if (scene_string(sc, g, "stop", &name, "change", STOPS, 0) < 0) return -1;
    rc->od.stop = strcmp(name, "change") ? OD_STOP_RESIDUAL : OD_STOP_CHANGE;
    if (scene_double(sc, g, "tolerance", &rc->od.tol, 1e-7, 1e-15, 1e-1, 0) < 0) return -1;
    long long v;
    if (scene_int(sc, g, "max_iterations", &v, 100000, 1, 100000000, 0) < 0) return -1;
    rc->od.max_iter = (int)v;
    if (scene_bool(sc, g, "allow_unconverged", &rc->od.allow_unconverged, 0) < 0) return -1;
    if (scene_double(sc, g, "reference_tolerance", &rc->od.reference_tol, 0.0, 0.0, 1e-3, 0) < 0) return -1;
    if (scene_bool(sc, g, "reference_own_fixed_point", &rc->od.reference_own, 0) < 0) return -1;
    for (int t = 0; t < s->ntypes; t++)
        if (!s->types[t].frozen) s->types[t].mass = 0.0;   /* m = 0: no kinetic terms */
    return 0;
}

/* confine = { axis = "y"; lo = 1.0; hi = 11.0; }: mobile particles that cross
 * a plane are reflected back (specular: position mirrored, normal velocity
 * reversed), keeping the fluid out of frozen wall regions. */
static int read_confine(Scene *sc, System *s, RunConfig *rc)
{
    rc->confine_axis = -1;
    config_setting_t *g = scene_child(sc, NULL, "confine", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    if (!g) return 0;
    const char *ax;
    if (scene_string(sc, g, "axis", &ax, "y", AXES, 0) < 0) return -1;
    rc->confine_axis = ax[0] - 'x';
    if (rc->confine_axis >= s->box.dim) return scene_fail(sc, g, "axis \"%s\" does not exist in %dD", ax, s->box.dim);
    const double L = s->box.L[rc->confine_axis];
    if (scene_double(sc, g, "lo", &rc->confine_lo, 0.0, 0.0, L, 1) < 0) return -1;
    if (scene_double(sc, g, "hi", &rc->confine_hi, L, 0.0, L, 1) < 0) return -1;
    if (rc->confine_hi <= rc->confine_lo) return scene_fail(sc, g, "need lo < hi (lo %g, hi %g)", rc->confine_lo, rc->confine_hi);
    if (rc->confine_axis == 1 && s->box.shear_rate != 0.0)
        return scene_fail(sc, g, "walls across y cannot be combined with Lees-Edwards shear_rate");
    return 0;
}

static int setup_particles(Scene *sc, System *s, Measure *m, RunConfig *rc, TypeInit *ti);

int setup_from_scene(Scene *sc, System *s, Measure *m, RunConfig *rc)
{
    memset(s, 0, sizeof *s);
    memset(rc, 0, sizeof *rc);
    long long v;
    if (scene_int(sc, NULL, "dimension", &v, 3, 2, 3, 1) < 0) return -1;
    const int dim = (int)v;
    double L[3] = {0, 0, 0};
    if (scene_vector(sc, NULL, "box", L, dim, NULL, 1e-6, 1e6, 1) < 0) return -1;
    double rate;
    if (scene_double(sc, NULL, "shear_rate", &rate, 0.0, -1e3, 1e3, 0) < 0) return -1;
    box_init(&s->box, dim, L, rate);
    if (scene_double(sc, NULL, "kBT", &s->kBT, 1.0, 0.0, 1e6, 0) < 0) return -1;
    if (scene_double(sc, NULL, "dt", &s->dt, 0.01, 1e-9, 10.0, 1) < 0) return -1;
    if (scene_double(sc, NULL, "lambda", &s->lambda, 0.5, 0.0, 1.0, 0) < 0) return -1;
    if (scene_int(sc, NULL, "seed", &v, 1, 0, 4294967295LL, 0) < 0) return -1;
    s->seed = (uint32_t)v;
    if (scene_int(sc, NULL, "steps", &rc->steps, 0, 0, 1000000000000LL, 1) < 0) return -1;
    if (scene_int(sc, NULL, "equilibration", &rc->equilibration, 0, 0, 1000000000000LL, 0) < 0) return -1;
    if (scene_double(sc, NULL, "skin", &rc->skin, 0.3, 0.0, 10.0, 0) < 0) return -1;
    /* the blow-up guard (stability.c): by default the thermal temperature (velocities relative to
     * the local flow) at most DEFAULT_MAX_THERMAL_RATIO x kBT, and the whole system's kinetic
     * temperature at most 100 x kBT; a scene that sets max_temperature_ratio chooses the
     * whole system's kinetic temperature alone (the stability map's criterion) */
    const int set_ratio = scene_double(sc, NULL, "max_temperature_ratio", &rc->max_temperature_ratio, 100.0, 1.0, 1e12, 0);
    if (set_ratio < 0) return -1;
    rc->max_thermal_ratio = set_ratio ? 0.0 : DEFAULT_MAX_THERMAL_RATIO;
    if (scene_bool(sc, NULL, "walls_start_at_production", &rc->walls_start_at_production, 0) < 0) return -1;
    if (scene_bool(sc, NULL, "rotation", &s->rotation, 0) < 0) return -1;
    /* the spins and the shear noise are 3-vectors: in 2D they push particles out of the plane */
    if (s->rotation && dim == 2)
        return scene_fail(sc, config_lookup(&sc->cfg, "rotation"), "rotation = true needs dimension = 3 "
                          "(allowed in 2D: false); 2D rotation would keep omega_z only, which is not implemented");
    TypeInit ti[DPD_MAX_TYPES];
    memset(ti, 0, sizeof ti);
    const int r = read_types(sc, s, ti) ? -1 : setup_particles(sc, s, m, rc, ti);
    for (int t = 0; t < DPD_MAX_TYPES; t++) free(ti[t].at);
    return r;
}

/* The bare build (-DDPD_BARE, src/core/modules.h) has no optional modules: a
 * scene that switches one on is refused. */
static int refuse_in_bare_build(Scene *sc, const System *s, const Measure *m, const RunConfig *rc)
{
#ifdef DPD_BARE
    const char *mod = NULL;
    int frozen_type = 0;
    for (int t = 0; t < s->ntypes; t++) frozen_type |= s->types[t].frozen;
    if (s->box.shear_rate != 0.0) mod = "shear_rate (Lees-Edwards)";
    else if (frozen_type) mod = "frozen particles";
    else if (s->has_body_force) mod = "a body force";
    else if (s->has_held_velocity) mod = "hold_mean_velocity";
    else if (s->rotation) mod = "rotation";
    else if (rc->overdamped) mod = "overdamped";
    else if (rc->confine_axis >= 0) mod = "confining walls";
    else if (rc->colloids) mod = "colloids";
    else if (rc->bonds) mod = "colloids2d";
    else if (m->tcaf_on) mod = "measure.tcaf";
    else if (m->msd_on) mod = "measure.msd";
    else if (m->rdf_on) mod = "measure.rdf";
    else if (m->com_on) mod = "measure.com";
    else if (m->prof_on) mod = "measure.profile";
    if (mod) return scene_fail(sc, NULL, "this is the bare build (-DDPD_BARE), without optional modules, "
                               "and the scene switches on %s; run it with bin/dpd", mod);
#else
    (void)sc; (void)s; (void)m; (void)rc;
#endif
    return 0;
}

/* The rest of the scene, once the types are known. */
static int setup_particles(Scene *sc, System *s, Measure *m, RunConfig *rc, TypeInit *ti)
{
    const int dim = s->box.dim;
    const double *L = s->box.L;
    long long v;
    if (read_pairs(sc, s)) return -1;
    for (int d = 0; d < dim; d++)
        if (s->rc_max + rc->skin > 0.5 * L[d]) {
            config_setting_t *b = config_lookup(&sc->cfg, "box");
            return scene_fail(sc, b, "largest rc (%g) plus skin (%g) exceeds half the box along %c (%g); "
                              "enlarge the box or reduce rc", s->rc_max, rc->skin, "xyz"[d], 0.5 * L[d]);
        }
    long long total = 0;
    int nfrozen = 0;
    for (int t = 0; t < s->ntypes; t++) {
        total += ti[t].count;
        if (s->types[t].frozen) nfrozen += (int)ti[t].count;
    }
    if (total < 1 || total > 200000000LL)
        return scene_fail(sc, NULL, "the scene makes %lld particles; allowed 1 to 2e8", total);
    config_setting_t *out = scene_child(sc, NULL, "output", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    rc->trajectory_every = 0;
    if (out) {
        if (scene_int(sc, out, "trajectory_every", &v, 0, 0, 1000000000LL, 0) < 0) return -1;
        rc->trajectory_every = (int)v;
    }
    if (read_overdamped(sc, s, rc)) return -1;
    if (read_confine(sc, s, rc)) return -1;
    if (setup_measure(sc, s, m, rc->steps)) return -1;
    config_setting_t *cg = scene_child(sc, NULL, "colloids", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    if (cg) {
        long long counts[DPD_MAX_TYPES];
        for (int t = 0; t < s->ntypes; t++) counts[t] = ti[t].count;
        if (rc->overdamped) return scene_fail(sc, cg, "colloids need massive particles (no 'overdamped' group)");
        if (setup_colloids(sc, cg, s, counts, &rc->colloids)) return -1;
    }
    config_setting_t *bg = scene_child(sc, NULL, "colloids2d", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    if (bg) {
        long long counts[DPD_MAX_TYPES];
        for (int t = 0; t < s->ntypes; t++) counts[t] = ti[t].count;
        if (setup_bonds(sc, bg, s, counts, rc->steps, m->nblocks, &rc->bonds)) return -1;
    }
    if (scene_check_unknown(sc)) return -1;
    if (s->rotation && rc->overdamped)
        return scene_fail(sc, scene_child(sc, NULL, "overdamped", CONFIG_TYPE_GROUP),
                          "rotation = true cannot be combined with overdamped (the m = 0 solver has no spins)");
    if (s->has_held_velocity && rc->overdamped)
        return scene_fail(sc, scene_child(sc, NULL, "overdamped", CONFIG_TYPE_GROUP),
                          "a type's hold_mean_velocity needs massive particles: no 'overdamped' group with it");
    if (refuse_in_bare_build(sc, s, m, rc)) return -1;
    if (setup_validate_only) return 0;
    if (system_alloc(s, (int)total)) return scene_fail(sc, NULL, "out of memory for %lld particles", total);
    s->box.le_offset = 0.0;
    s->n_frozen = nfrozen;
    place_particles(s, ti);
    if (rc->colloids && colloid_place(rc->colloids, s)) return scene_fail(sc, NULL, "out of memory for the colloids");
    if (rc->bonds && bonds_place(rc->bonds, s)) return scene_fail(sc, NULL, "out of memory for the colloids");
    initial_velocities(s);
    if (s->rotation) {
        s->rotation = 0;
        if (rotation_alloc(s)) return scene_fail(sc, NULL, "out of memory for angular velocities");
    }
    return 0;
}
