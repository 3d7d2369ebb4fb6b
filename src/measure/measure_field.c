/* measure_field.c - distributions about fixed points, grid maps, body torques
 * and mean velocities (see measure_field.h). */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "measure_field.h"

/* Centroid of each frozen type, from the first particle by minimum images. */
static void frozen_centroids(FieldMeasure *f, const System *s)
{
    double first[DPD_MAX_TYPES][3], sum[DPD_MAX_TYPES][3] = {{0}};
    int cnt[DPD_MAX_TYPES] = {0};
    for (int i = 0; i < s->n; i++) {
        const int t = s->type[i];
        if (!s->types[t].frozen) continue;
        if (cnt[t] == 0) memcpy(first[t], s->x + 3 * i, sizeof first[t]);
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = s->x[3 * i + k] - first[t][k];
        box_min_image(&s->box, d, NULL);
        for (int k = 0; k < 3; k++) sum[t][k] += d[k];
        cnt[t]++;
    }
    for (int t = 0; t < s->ntypes; t++)
        for (int k = 0; k < 3; k++)
            f->centroid[t][k] = cnt[t] ? first[t][k] + sum[t][k] / cnt[t] : 0.0;
}

int field_init(FieldMeasure *f, const FieldParams *p, const System *s, int nblocks)
{
    memset(f, 0, sizeof *f);
    f->p = *p;
    f->nblocks = nblocks;
    if (f->p.around.on) {
        f->around_hist = calloc((size_t)nblocks * f->p.around.bins, sizeof(double));
        f->around_samples = calloc((size_t)nblocks, sizeof(long long));
        if (!f->around_hist || !f->around_samples) return -1;
        long long cnt = 0;
        for (int i = 0; i < s->n; i++) cnt += s->type[i] == f->p.around.type;
        double A = 1.0;
        for (int d = 0; d < s->box.dim; d++) A *= s->box.L[d];
        f->around_density = cnt / A;
    }
    if (f->p.map_on) {
        f->map_hist = calloc(3 * (size_t)f->p.map_bins[0] * f->p.map_bins[1], sizeof(double));
        if (!f->map_hist) return -1;
    }
    return 0;
}

void field_free(FieldMeasure *f)
{
    free(f->around_hist); free(f->around_samples); free(f->map_hist);
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) { series_free(&f->mean_v[t][d]); series_free(&f->torque[t][d]); }
}

void field_io(Io *io, FieldMeasure *f)
{
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) {
            io_series(io, &f->mean_v[t][d], "mean velocity");
            io_series(io, &f->torque[t][d], "body torque");
        }
    if (f->p.around.on) {
        io_array(io, f->around_hist, (size_t)f->nblocks * f->p.around.bins, sizeof(double), "around");
        io_array(io, f->around_samples, (size_t)f->nblocks, sizeof(long long), "around samples");
    }
    if (f->p.map_on) {
        io_array(io, f->map_hist, 3 * (size_t)f->p.map_bins[0] * f->p.map_bins[1], sizeof(double), "density map");
        io_bytes(io, &f->map_samples, sizeof f->map_samples, "density map samples");
    }
}

static void sample_velocities_and_torques(FieldMeasure *f, const System *s)
{
    double v[DPD_MAX_TYPES][3] = {{0}}, tq[DPD_MAX_TYPES][3] = {{0}};
    long long cnt[DPD_MAX_TYPES] = {0};
    if (s->step == 0 || s->n_frozen > 0) frozen_centroids(f, s);
    for (int i = 0; i < s->n; i++) {
        const int t = s->type[i];
        const double *x = s->x + 3 * i, *fi = s->f + 3 * i;
        if (!s->types[t].frozen) {
            for (int d = 0; d < 3; d++) v[t][d] += s->v[3 * i + d];
            cnt[t]++;
            continue;
        }
        /* torque about the centroid: r x F, r by minimum image */
        double r[3];
        for (int d = 0; d < 3; d++) r[d] = x[d] - f->centroid[t][d];
        box_min_image(&s->box, r, NULL);
        tq[t][0] += r[1] * fi[2] - r[2] * fi[1];
        tq[t][1] += r[2] * fi[0] - r[0] * fi[2];
        tq[t][2] += r[0] * fi[1] - r[1] * fi[0];
    }
    for (int t = 0; t < s->ntypes; t++)
        for (int d = 0; d < 3; d++) {
            if (s->types[t].frozen) series_push(&f->torque[t][d], tq[t][d]);
            else if (cnt[t] > 0) series_push(&f->mean_v[t][d], v[t][d] / cnt[t]);
        }
}

void field_sample(FieldMeasure *f, const System *s, int block)
{
    sample_velocities_and_torques(f, s);
    if (f->p.around.on) {
        double *h = f->around_hist + (size_t)block * f->p.around.bins;
        for (int i = 0; i < s->n; i++) {
            if (s->type[i] != f->p.around.type) continue;
            double d[3];
            for (int k = 0; k < 3; k++) d[k] = s->x[3 * i + k] - f->p.around_centre[k];
            box_min_image(&s->box, d, NULL);
            const int b = (int)(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / f->p.around.dq);
            if (b < f->p.around.bins) h[b] += 1.0;
        }
        f->around_samples[block]++;
    }
    if (f->p.map_on) {
        const int nx = f->p.map_bins[0], ny = f->p.map_bins[1];
        for (int i = 0; i < s->n; i++) {
            if (s->type[i] != f->p.map_type) continue;
            int bx = (int)(s->x[3 * i] / s->box.L[0] * nx), by = (int)(s->x[3 * i + 1] / s->box.L[1] * ny);
            if (bx >= nx) bx = nx - 1;
            if (by >= ny) by = ny - 1;
            double *h = f->map_hist + 3 * ((size_t)by * nx + bx);
            h[0] += 1.0;
            h[1] += s->v[3 * i];
            h[2] += s->v[3 * i + 1];
        }
        f->map_samples++;
    }
}

static int write_around(const FieldMeasure *f, const System *s, FILE *summary, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/around.tsv", dir);
    const AroundHist a = {.hist = f->around_hist, .samples = f->around_samples, .nblocks = f->nblocks,
                          .bins = f->p.around.bins, .dim = s->box.dim, .dq = f->p.around.dq,
                          .density = f->around_density, .threshold = f->p.around.threshold};
    FILE *out = fopen(path, "w");
    if (!out) return -1;
    const int bad = around_write(&a, out, summary, "exclusion_radius");
    return fclose(out) || bad ? -1 : 0;
}

static int write_density_map(const FieldMeasure *f, const System *s, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/density_map.tsv", dir);
    FILE *out = fopen(path, "w");
    if (!out) return -1;
    const int nx = f->p.map_bins[0], ny = f->p.map_bins[1];
    double cell = s->box.L[0] / nx * s->box.L[1] / ny;
    if (s->box.dim == 3) cell *= s->box.L[2];
    fprintf(out, "x\ty\tdensity\tvx\tvy\n");
    for (int by = 0; by < ny; by++) {
        for (int bx = 0; bx < nx; bx++) {
            const double *h = f->map_hist + 3 * ((size_t)by * nx + bx);
            fprintf(out, "%.6g\t%.6g\t%.6g\t%.6g\t%.6g\n", (bx + 0.5) * s->box.L[0] / nx,
                    (by + 0.5) * s->box.L[1] / ny, f->map_samples ? h[0] / (f->map_samples * cell) : 0.0,
                    h[0] > 0 ? h[1] / h[0] : 0.0, h[0] > 0 ? h[2] / h[0] : 0.0);
        }
        fputc('\n', out);   /* gnuplot pm3d scan separator */
    }
    return fclose(out);
}

/* Their Fig. 6a: sum over the body's particles j of a (1 - r/rc) e_jp . e_op,
 * the radial part (about the body centroid o) of the conservative force on a
 * probe particle p at each grid point, in the plane z = centroid z. */
static int write_force_map(const FieldMeasure *f, const System *s, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/force_map.tsv", dir);
    FILE *out = fopen(path, "w");
    if (!out) return -1;
    const PairParams *p = &s->pair[f->p.fmap_body][f->p.fmap_probe];
    const double *o = f->centroid[f->p.fmap_body];
    const int nx = f->p.fmap_bins[0], ny = f->p.fmap_bins[1];
    fprintf(out, "x\ty\tradial_force\n");
    for (int by = 0; by < ny; by++) {
        for (int bx = 0; bx < nx; bx++) {
            const double X[3] = {(bx + 0.5) * s->box.L[0] / nx, (by + 0.5) * s->box.L[1] / ny, o[2]};
            double eo[3] = {X[0] - o[0], X[1] - o[1], X[2] - o[2]};
            box_min_image(&s->box, eo, NULL);
            const double ro = sqrt(eo[0] * eo[0] + eo[1] * eo[1] + eo[2] * eo[2]);
            double fr = 0.0;
            for (int j = 0; j < s->n && ro > 0.0; j++) {
                if (s->type[j] != f->p.fmap_body) continue;
                double d[3] = {X[0] - s->x[3 * j], X[1] - s->x[3 * j + 1], X[2] - s->x[3 * j + 2]};
                box_min_image(&s->box, d, NULL);
                const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (r >= p->rc || r < 1e-12) continue;
                fr += p->a * (1.0 - r / p->rc) * (d[0] * eo[0] + d[1] * eo[1] + d[2] * eo[2]) / (r * ro);
            }
            fprintf(out, "%.6g\t%.6g\t%.6g\n", X[0], X[1], fr);
        }
        fputc('\n', out);
    }
    return fclose(out);
}

int field_write(const FieldMeasure *f, const System *s, FILE *summary, const char *dir)
{
    for (int t = 0; t < s->ntypes; t++)
        for (int d = 0; d < 3; d++) {
            const int frozen = s->types[t].frozen;
            /* velocities along the box axes; torques: only z in 2D */
            /* rotation scenes report the eq. 1 torque under the same name (measure.c) */
            if (frozen && s->rotation) continue;
            if (frozen ? (s->box.dim == 2 && d < 2) : (d >= s->box.dim || f->mean_v[t][d].n == 0)) continue;
            char name[96];
            double v, se;
            snprintf(name, sizeof name, "%s_%s_%c", frozen ? "torque_on" : "mean_velocity", s->types[t].name, "xyz"[d]);
            series_stats(frozen ? &f->torque[t][d] : &f->mean_v[t][d], f->nblocks, &v, &se);
            fprintf(summary, "%s\t%.10g\t%.4g\n", name, v, se);
        }
    if (f->p.around.on && write_around(f, s, summary, dir)) return -1;
    if (f->p.map_on && write_density_map(f, s, dir)) return -1;
    if (f->p.fmap_on && write_force_map(f, s, dir)) return -1;
    return 0;
}
