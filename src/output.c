/* output.c - HDF5 run files (H5MD 1.1 layout for trajectories,
 * de Buyl, Colberg & Hoefling, Comput. Phys. Commun. 185, 1546, 2014). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <fcntl.h>
#include "output.h"

static hid_t ensure_group(hid_t file, const char *path)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", path);
    hid_t g = -1;
    for (char *p = buf + 1;; p++) {
        const int end = (*p == '\0');
        if (*p == '/' || end) {
            char c = *p;
            *p = '\0';
            if (H5Lexists(file, buf, H5P_DEFAULT) <= 0) {
                hid_t ng = H5Gcreate2(file, buf, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
                if (ng < 0) return -1;
                H5Gclose(ng);
            }
            *p = c;
            if (end) break;
        }
    }
    g = H5Gopen2(file, buf, H5P_DEFAULT);
    return g;
}

/* An existing object (group or dataset), or a new group. */
static hid_t object_at(hid_t file, const char *path)
{
    if (strcmp(path, "/") && H5Lexists(file, path, H5P_DEFAULT) > 0) return H5Oopen(file, path, H5P_DEFAULT);
    return ensure_group(file, path);
}

int output_attr_text(Output *o, const char *group, const char *name, const char *value)
{
    hid_t g = object_at(o->file, group);
    if (g < 0) return -1;
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, strlen(value) + 1);
    hid_t sp = H5Screate(H5S_SCALAR);
    if (H5Aexists(g, name) > 0) H5Adelete(g, name);
    hid_t a = H5Acreate2(g, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t rc = a >= 0 ? H5Awrite(a, t, value) : -1;
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp); H5Tclose(t); H5Oclose(g);
    return rc < 0 ? -1 : 0;
}

int output_attr_double(Output *o, const char *group, const char *name, double value)
{
    hid_t g = object_at(o->file, group);
    if (g < 0) return -1;
    hid_t sp = H5Screate(H5S_SCALAR);
    if (H5Aexists(g, name) > 0) H5Adelete(g, name);
    hid_t a = H5Acreate2(g, name, H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t rc = a >= 0 ? H5Awrite(a, H5T_NATIVE_DOUBLE, &value) : -1;
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp); H5Oclose(g);
    return rc < 0 ? -1 : 0;
}

static hid_t parent_of(Output *o, const char *path, char *leaf, size_t n)
{
    const char *slash = strrchr(path, '/');
    if (!slash) return -1;
    char grp[512];
    size_t len = (size_t)(slash - path);
    if (len == 0) { grp[0] = '/'; grp[1] = '\0'; }
    else { memcpy(grp, path, len); grp[len] = '\0'; }
    snprintf(leaf, n, "%s", slash + 1);
    return ensure_group(o->file, grp);
}

int output_table(Output *o, const char *path, const double *data, int rows, int cols,
                 const char *columns)
{
    char leaf[256];
    hid_t g = parent_of(o, path, leaf, sizeof leaf);
    if (g < 0) return -1;
    hsize_t dims[2] = {(hsize_t)rows, (hsize_t)cols};
    hid_t sp = H5Screate_simple(2, dims, NULL);
    hid_t d = H5Dcreate2(g, leaf, H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    herr_t rc = d >= 0 && rows > 0 ? H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
    H5Sclose(sp);
    H5Gclose(g);
    if (d < 0) return -1;
    H5Dclose(d);
    if (rc < 0) return -1;
    return columns ? output_attr_text(o, path, "columns", columns) : 0;
}

int output_tsv(Output *o, const char *path, const char *tsv_file)
{
    FILE *f = fopen(tsv_file, "r");
    if (!f) return -1;
    char line[8192], header[8192] = "";
    double *data = NULL;
    size_t n = 0, cap = 0;
    int cols = -1, rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        line[strcspn(line, "\n")] = '\0';
        if (!header[0]) { snprintf(header, sizeof header, "%s", line); continue; }
        int c = 0;
        for (char *save = NULL, *tok = strtok_r(line, "\t", &save); tok; tok = strtok_r(NULL, "\t", &save)) {
            if (n == cap) {
                cap = cap ? 2 * cap : 1024;
                double *p = realloc(data, cap * sizeof *p);
                if (!p) { free(data); fclose(f); return -1; }
                data = p;
            }
            data[n++] = strtod(tok, NULL);
            c++;
        }
        if (cols < 0) cols = c;
        if (c != cols) { free(data); fclose(f); return -1; }
        rows++;
    }
    fclose(f);
    int rc = output_table(o, path, data, rows, cols < 0 ? 0 : cols, header);
    free(data);
    return rc;
}

int output_series(Output *o, const char *name, const double *v, size_t n, int every, double dt)
{
    char path[512];
    snprintf(path, sizeof path, "/observables/%s/value", name);
    if (output_table(o, path, v, (int)n, 1, NULL)) return -1;
    double *st = malloc((n ? n : 1) * sizeof *st);
    if (!st) return -1;
    for (size_t k = 0; k < n; k++) st[k] = (double)k * every * dt;
    snprintf(path, sizeof path, "/observables/%s/time", name);
    int rc = output_table(o, path, st, (int)n, 1, NULL);
    free(st);
    return rc;
}

static hid_t extensible(hid_t g, const char *name, hid_t type, int cols, int dim)
{
    hsize_t dims[3] = {0, 0, (hsize_t)dim}, maxd[3] = {H5S_UNLIMITED, 0, (hsize_t)dim}, chunk[3] = {1, 0, (hsize_t)dim};
    int rank = cols > 0 ? 3 : 1;
    dims[1] = maxd[1] = chunk[1] = (hsize_t)(cols > 0 ? cols : 1);
    hid_t sp = H5Screate_simple(rank, dims, maxd);
    hid_t pl = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(pl, rank, chunk);
    hid_t d = H5Dcreate2(g, name, type, sp, H5P_DEFAULT, pl, H5P_DEFAULT);
    H5Pclose(pl);
    H5Sclose(sp);
    return d;
}

int output_open(Output *o, const char *dir, const System *s, int trajectory)
{
    memset(o, 0, sizeof *o);
    snprintf(o->path, sizeof o->path, "%s/run.h5", dir);
    snprintf(o->tmp_path, sizeof o->tmp_path, "%s/run.h5.part", dir);
    /* HDF5 1.10 closes a file whose H5Fclose failed (disk full) again at exit
     * and crashes there: no exit-time cleanup (fails harmlessly if too late) */
    H5dont_atexit();
    if (!getenv("DPD_HDF5_DEBUG")) H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    o->file = H5Fcreate(o->tmp_path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (o->file < 0) return -1;
    /* H5MD root metadata */
    hid_t g = ensure_group(o->file, "/h5md");
    if (g < 0) return -1;
    int version[2] = {1, 1};
    hsize_t two = 2;
    hid_t sp = H5Screate_simple(1, &two, NULL);
    hid_t a = H5Acreate2(g, "version", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, version);
    H5Aclose(a); H5Sclose(sp); H5Gclose(g);
    output_attr_text(o, "/h5md/author", "name", "dpd reproducibility package");
    output_attr_text(o, "/h5md/creator", "name", "dpd");
    output_attr_text(o, "/h5md/creator", "version", DPD_GIT);
    o->traj_on = trajectory;
    if (trajectory) {
        hid_t box = ensure_group(o->file, "/particles/all/box");
        const int dim = s->box.dim;
        hsize_t nd = (hsize_t)dim;
        hid_t sp1 = H5Screate(H5S_SCALAR);
        hid_t ad = H5Acreate2(box, "dimension", H5T_NATIVE_INT, sp1, H5P_DEFAULT, H5P_DEFAULT);
        H5Awrite(ad, H5T_NATIVE_INT, &dim);
        H5Aclose(ad); H5Sclose(sp1);
        hid_t spn = H5Screate_simple(1, &nd, NULL);
        hid_t st = H5Tcopy(H5T_C_S1);
        H5Tset_size(st, 9);
        char bnd[3][9] = {"periodic", "periodic", "periodic"};
        hid_t ab = H5Acreate2(box, "boundary", st, spn, H5P_DEFAULT, H5P_DEFAULT);
        H5Awrite(ab, st, bnd);
        H5Aclose(ab); H5Tclose(st);
        hid_t de = H5Dcreate2(box, "edges", H5T_NATIVE_DOUBLE, spn, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        H5Dwrite(de, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, s->box.L);
        H5Dclose(de); H5Sclose(spn); H5Gclose(box);
        /* species (time independent), in id order like the frames */
        int *sp_id = malloc((size_t)s->n * sizeof(int) + 1);
        if (!sp_id) return -1;
        for (int i = 0; i < s->n; i++) sp_id[s->id[i]] = s->type[i];
        hsize_t nn = (hsize_t)s->n;
        hid_t sps = H5Screate_simple(1, &nn, NULL);
        hid_t all = ensure_group(o->file, "/particles/all");
        hid_t dsp = H5Dcreate2(all, "species", H5T_NATIVE_INT, sps, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        if (dsp >= 0) { H5Dwrite(dsp, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, sp_id); H5Dclose(dsp); }
        H5Sclose(sps); H5Gclose(all); free(sp_id);
        hid_t pg = ensure_group(o->file, "/particles/all/position");
        o->pos = extensible(pg, "value", H5T_NATIVE_DOUBLE, s->n, dim);
        o->step = extensible(pg, "step", H5T_NATIVE_LLONG, 0, 1);
        o->time = extensible(pg, "time", H5T_NATIVE_DOUBLE, 0, 1);
        H5Gclose(pg);
        hid_t vg = ensure_group(o->file, "/particles/all/velocity");
        o->vel = extensible(vg, "value", H5T_NATIVE_DOUBLE, s->n, dim);
        H5Lcreate_hard(o->file, "/particles/all/position/step", vg, "step", H5P_DEFAULT, H5P_DEFAULT);
        H5Lcreate_hard(o->file, "/particles/all/position/time", vg, "time", H5P_DEFAULT, H5P_DEFAULT);
        H5Gclose(vg);
        hid_t ig = ensure_group(o->file, "/particles/all/image");
        o->img = extensible(ig, "value", H5T_NATIVE_INT, s->n, dim);
        H5Lcreate_hard(o->file, "/particles/all/position/step", ig, "step", H5P_DEFAULT, H5P_DEFAULT);
        H5Lcreate_hard(o->file, "/particles/all/position/time", ig, "time", H5P_DEFAULT, H5P_DEFAULT);
        H5Gclose(ig);
        if (o->pos < 0 || o->vel < 0 || o->step < 0 || o->time < 0 || o->img < 0) return -1;
    }
    return 0;
}

static int append(hid_t d, hid_t type, long long frame, int cols, int dim, const void *buf)
{
    const int rank = cols > 0 ? 3 : 1;
    hsize_t dims[3] = {(hsize_t)frame + 1, (hsize_t)(cols > 0 ? cols : 1), (hsize_t)dim};
    if (H5Dset_extent(d, dims) < 0) return -1;
    hid_t fs = H5Dget_space(d);
    hsize_t start[3] = {(hsize_t)frame, 0, 0}, count[3] = {1, dims[1], (hsize_t)dim};
    H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL);
    hid_t ms = H5Screate_simple(rank, count, NULL);
    herr_t rc = H5Dwrite(d, type, ms, fs, H5P_DEFAULT, buf);
    H5Sclose(ms); H5Sclose(fs);
    return rc < 0 ? -1 : 0;
}

/* Frames are stored in id order so that a particle keeps its row. */
int output_frame(Output *o, const System *s)
{
    if (!o->traj_on) return 0;
    const int n = s->n;
    double *buf = malloc(3 * (size_t)n * sizeof(double) + 1);
    int *ib = malloc(3 * (size_t)n * sizeof(int) + 1);
    if (!buf || !ib) { free(buf); free(ib); return -1; }
    int rc = 0;
    const int dim = s->box.dim;
    for (int i = 0; i < n; i++) memcpy(buf + dim * s->id[i], s->x + 3 * i, dim * sizeof(double));
    rc |= append(o->pos, H5T_NATIVE_DOUBLE, o->frames, n, dim, buf);
    for (int i = 0; i < n; i++) memcpy(buf + dim * s->id[i], s->v + 3 * i, dim * sizeof(double));
    rc |= append(o->vel, H5T_NATIVE_DOUBLE, o->frames, n, dim, buf);
    for (int i = 0; i < n; i++) memcpy(ib + dim * s->id[i], s->img + 3 * i, dim * sizeof(int));
    rc |= append(o->img, H5T_NATIVE_INT, o->frames, n, dim, ib);
    long long st = (long long)s->step;
    rc |= append(o->step, H5T_NATIVE_LLONG, o->frames, 0, 1, &st);
    rc |= append(o->time, H5T_NATIVE_DOUBLE, o->frames, 0, 1, &s->time);
    free(buf); free(ib);
    o->frames++;
    return rc;
}

int output_close(Output *o, int complete)
{
    if (o->traj_on) {
        H5Dclose(o->pos); H5Dclose(o->vel); H5Dclose(o->step); H5Dclose(o->time); H5Dclose(o->img);
    }
    if (H5Fclose(o->file) < 0) return -1;
    if (!complete) return 0;   /* the .part file stays: never mistaken for a result */
    int fd = open(o->tmp_path, O_RDONLY);
    if (fd >= 0) { fsync(fd); close(fd); }
    return rename(o->tmp_path, o->path);
}

int write_file_atomic(const char *dir, const char *name, const char *text, size_t len)
{
    char tmp[1024], path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    snprintf(tmp, sizeof tmp, "%s/.%s.part", dir, name);
    FILE *f = fopen(tmp, "w");
    if (!f) return -1;
    int bad = fwrite(text, 1, len, f) != len;
    bad |= fflush(f) != 0;
    bad |= fsync(fileno(f)) != 0;
    bad |= fclose(f) != 0;
    if (bad) { unlink(tmp); return -1; }
    return rename(tmp, path);
}
