/* setup_measure.c - the measure group of a scene into the parameters of the
 * measurements (measure.h, measure_field.h, tcaf.h). Part of the input layer
 * (setup_parts.h). */
#include <string.h>
#include <math.h>
#include "setup_parts.h"

static const char *const AXES[] = {"x", "y", "z", NULL};

static int read_type(Scene *sc, const config_setting_t *g, const char *key, const System *s, int *t)
{
    const char *name;
    if (scene_string(sc, g, key, &name, NULL, NULL, 1) < 0) return -1;
    *t = setup_type_index(s, name);
    if (*t < 0) return scene_fail(sc, g, "%s: unknown type \"%s\"", key, name);
    return 0;
}

static int read_bins(Scene *sc, const config_setting_t *g, int out[2])
{
    double b[2];
    if (scene_vector(sc, g, "bins", b, 2, NULL, 1.0, 4096.0, 1) < 0) return -1;
    for (int k = 0; k < 2; k++) {
        if (b[k] != floor(b[k])) return scene_fail(sc, g, "bins: %g is not a whole number", b[k]);
        out[k] = (int)b[k];
    }
    return 0;
}

int setup_around_range(Scene *sc, const config_setting_t *a, double hmin, AroundParams *p)
{
    double qmax;
    if (scene_double(sc, a, "dq", &p->dq, 0.01, 1e-6, hmin, 0) < 0) return -1;
    if (scene_double(sc, a, "qmax", &qmax, hmin, p->dq, hmin, 0) < 0) return -1;
    if (scene_double(sc, a, "threshold", &p->threshold, 1e-3, 0.0, 1.0, 0) < 0) return -1;
    p->bins = (int)floor(qmax / p->dq + 0.5);
    if (p->bins < 1) p->bins = 1;
    return 0;
}

/* around = { centre; type; dq; qmax; threshold; } about a point */
static int read_around(Scene *sc, const config_setting_t *a, const System *s, FieldParams *f)
{
    const int dim = s->box.dim;
    f->around.on = 1;
    if (scene_vector(sc, a, "centre", f->around_centre, dim, NULL, 0.0, 1e9, 1) < 0) return -1;
    for (int d = 0; d < dim; d++)
        if (f->around_centre[d] >= s->box.L[d])
            return scene_fail(sc, a, "centre: %c = %g outside the box [0, %g)", "xyz"[d],
                              f->around_centre[d], s->box.L[d]);
    if (read_type(sc, a, "type", s, &f->around.type)) return -1;
    double hmin = 0.5 * s->box.L[0];
    for (int d = 1; d < dim; d++) if (0.5 * s->box.L[d] < hmin) hmin = 0.5 * s->box.L[d];
    return setup_around_range(sc, a, hmin, &f->around);
}

/* measure.around, measure.density_map, measure.force_map of group g (NULL: none). */
static int read_field(Scene *sc, const config_setting_t *g, const System *s, FieldParams *f)
{
    memset(f, 0, sizeof *f);
    if (!g) return 0;
    config_setting_t *a = scene_child(sc, g, "around", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    if (a && read_around(sc, a, s, f)) return -1;
    config_setting_t *m = scene_child(sc, g, "density_map", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    if (m) {
        f->map_on = 1;
        if (read_type(sc, m, "type", s, &f->map_type) || read_bins(sc, m, f->map_bins)) return -1;
    }
    config_setting_t *fm = scene_child(sc, g, "force_map", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    if (fm) {
        f->fmap_on = 1;
        if (read_type(sc, fm, "body", s, &f->fmap_body) || read_type(sc, fm, "probe", s, &f->fmap_probe)
            || read_bins(sc, fm, f->fmap_bins)) return -1;
        if (!s->types[f->fmap_body].frozen)
            return scene_fail(sc, fm, "body: type \"%s\" is not frozen", s->types[f->fmap_body].name);
    }
    return 0;
}

/* every, window and origin_every of a time correlation (msd, tcaf): the
 * window and the origins' spacing multiples of every, under 1000 origins in
 * flight. */
static int read_window(Scene *sc, const config_setting_t *g, int every_default, int *every, int *window,
                       int *origin_every)
{
    long long v;
    if (scene_int(sc, g, "every", &v, every_default, 1, 1000000, 0) < 0) return -1;
    *every = (int)v;
    if (scene_int(sc, g, "window", &v, 0, 1, 100000000, 1) < 0) return -1;   /* required: no default */
    *window = (int)v;
    if (scene_int(sc, g, "origin_every", &v, *window / 10 > 0 ? *window / 10 : 1, 1, 100000000, 0) < 0) return -1;
    *origin_every = (int)v;
    if (*window % *every || *origin_every % *every)
        return scene_fail(sc, g, "window (%d) and origin_every (%d) must be multiples of every (%d)",
                          *window, *origin_every, *every);
    if (*window / *origin_every + 1 > 1000)
        return scene_fail(sc, g, "window / origin_every = %d origins in flight; allowed up to 999",
                          *window / *origin_every);
    return 0;
}

/* measure.tcaf = { every; window; origin_every; n2max; axis_nmax; type; fit_min;
 * extrapolate_kmax; extrapolate_order; include_bodies; } */
static int read_tcaf(Scene *sc, const config_setting_t *g, const System *s, TcafParams *t,
                     long long steps, int nblocks)
{
    long long v;
    memset(t, 0, sizeof *t);
    if (read_window(sc, g, 1, &t->every, &t->window, &t->origin_every)) return -1;
    if (scene_int(sc, g, "n2max", &v, 9, 1, 400, 0) < 0) return -1;
    t->n2max = (int)v;
    if (scene_int(sc, g, "axis_nmax", &v, 0, 0, TCAF_NMAX, 0) < 0) return -1;
    t->axis_nmax = (int)v;
    if (scene_bool(sc, g, "include_bodies", &t->include_bodies, 0) < 0) return -1;
    if (scene_double(sc, g, "fit_min", &t->fit_min, 0.3, 1e-6, 0.99, 0) < 0) return -1;
    if (scene_double(sc, g, "extrapolate_kmax", &t->extrap_kmax, 1e9, 0.0, 1e9, 0) < 0) return -1;
    if (scene_int(sc, g, "extrapolate_order", &v, 1, 0, TCAF_MAX_ORDER, 0) < 0) return -1;
    t->extrap_order = (int)v;
    const char *tn;
    if (scene_string(sc, g, "type", &tn, NULL, NULL, 0) < 0) return -1;
    t->type = tn ? setup_type_index(s, tn) : -1;
    if (tn && t->type < 0) return scene_fail(sc, g, "unknown type \"%s\"", tn);
    if (s->box.shear_rate != 0.0)
        return scene_fail(sc, g, "the TCAF needs a fluid at rest; the scene has shear_rate = %g", s->box.shear_rate);
    const long long norig = steps >= t->window ? (steps - t->window) / t->origin_every + 1 : 0;
    if (norig < nblocks)
        return scene_fail(sc, g, "the run gives %lld complete time origins (steps %lld, window %d, origin_every %d); "
                          "need at least one per block (%d)", norig, steps, t->window, t->origin_every, nblocks);
    return 0;
}

/* profile = { axis; bins; per_block; } */
static int read_profile(Scene *sc, const config_setting_t *p, const System *s, Measure *m)
{
    const char *ax;
    long long v;
    m->prof_on = 1;
    if (scene_string(sc, p, "axis", &ax, "y", AXES, 0) < 0) return -1;
    m->prof_axis = ax[0] - 'x';
    if (m->prof_axis >= s->box.dim) return scene_fail(sc, p, "axis \"%s\" does not exist in %dD", ax, s->box.dim);
    if (scene_int(sc, p, "bins", &v, 20, 1, 100000, 0) < 0) return -1;
    m->prof_bins = (int)v;
    return scene_bool(sc, p, "per_block", &m->prof_per_block, 0) < 0 ? -1 : 0;
}

/* rdf = { rmax; bins; every; types = ["a", "b"]; } */
static int read_rdf(Scene *sc, const config_setting_t *r, const System *s, Measure *m)
{
    long long v;
    m->rdf_on = 1;
    if (scene_double(sc, r, "rmax", &m->rdf_rmax, s->rc_max, 1e-6, s->rc_max, 0) < 0) return -1;
    if (scene_int(sc, r, "bins", &v, 100, 1, 100000, 0) < 0) return -1;
    m->rdf_bins = (int)v;
    if (scene_int(sc, r, "every", &v, m->every, 1, 1000000, 0) < 0) return -1;
    m->rdf_every = (int)v;
    m->rdf_types[0] = m->rdf_types[1] = -1;
    config_setting_t *tl = scene_child(sc, r, "types", CONFIG_TYPE_ARRAY);
    if (sc->failed) return -1;
    if (!tl) return 0;
    if (config_setting_length(tl) != 2) return scene_fail(sc, tl, "expected two type names");
    for (int e = 0; e < 2; e++) {
        const char *nm = config_setting_get_string_elem(tl, e);
        m->rdf_types[e] = nm ? setup_type_index(s, nm) : -1;
        if (m->rdf_types[e] < 0) return scene_fail(sc, tl, "unknown type \"%s\"", nm ? nm : "(not a string)");
    }
    return 0;
}

/* msd = { every; window; origin_every; type; } */
static int read_msd(Scene *sc, const config_setting_t *d, const System *s, Measure *m, long long steps)
{
    m->msd_on = 1;
    if (read_window(sc, d, m->every, &m->msd_every, &m->msd_window, &m->msd_origin_every)) return -1;
    if (m->msd_window > steps)
        return scene_fail(sc, d, "window %d is longer than the run (%lld steps)", m->msd_window, steps);
    const char *tn;
    if (scene_string(sc, d, "type", &tn, NULL, NULL, 0) < 0) return -1;
    m->msd_type = tn ? setup_type_index(s, tn) : -1;
    if (tn && m->msd_type < 0) return scene_fail(sc, d, "unknown type \"%s\"", tn);
    return 0;
}

int setup_measure(Scene *sc, const System *s, Measure *m, long long steps)
{
    memset(m, 0, sizeof *m);
    config_setting_t *g = scene_child(sc, NULL, "measure", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    long long v;
    m->every = 10;     /* defaults when the scene has no measure group */
    m->nblocks = 20;
    if (g) {
        if (scene_int(sc, g, "every", &v, 10, 1, 1000000, 0) < 0) return -1;
        m->every = (int)v;
        if (scene_int(sc, g, "blocks", &v, 20, 2, MAX_BLOCKS, 0) < 0) return -1;
        m->nblocks = (int)v;
    }
    m->nsamples_expected = steps / m->every + 1;
    if (read_field(sc, g, s, &m->field_par)) return -1;
    m->prod_steps = steps;
    if (!g) return 0;
    config_setting_t *p = scene_child(sc, g, "profile", CONFIG_TYPE_GROUP);
    if (sc->failed || (p && read_profile(sc, p, s, m))) return -1;
    if (scene_bool(sc, g, "com", &m->com_on, 0) < 0) return -1;
    config_setting_t *r = scene_child(sc, g, "rdf", CONFIG_TYPE_GROUP);
    if (sc->failed || (r && read_rdf(sc, r, s, m))) return -1;
    config_setting_t *d = scene_child(sc, g, "msd", CONFIG_TYPE_GROUP);
    if (sc->failed || (d && read_msd(sc, d, s, m, steps))) return -1;
    config_setting_t *tc = scene_child(sc, g, "tcaf", CONFIG_TYPE_GROUP);
    if (sc->failed) return -1;
    m->tcaf_on = tc != NULL;
    return tc && read_tcaf(sc, tc, s, &m->tcaf_par, steps, m->nblocks) ? -1 : 0;
}
