/* output.c - HDF5 run files (H5MD 1.1 layout for trajectories,
 * de Buyl, Colberg & Hoefling, Comput. Phys. Commun. 185, 1546, 2014). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <fcntl.h>
#include <dirent.h>
#include <errno.h>
#include "output.h"
#include "checkpoint.h"

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

static int attr_text(hid_t file, const char *group, const char *name, const char *value)
{
    hid_t g = object_at(file, group);
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

int output_attr_text(Output *o, const char *group, const char *name, const char *value)
{
    return attr_text(o->file, group, name, value);
}

/* The /h5md group of an H5MD 1.1 file: run.h5 and every trajectory segment. */
static int h5md_header(hid_t file)
{
    hid_t g = ensure_group(file, "/h5md");
    if (g < 0) return -1;
    int version[2] = {1, 1};
    hsize_t two = 2;
    hid_t sp = H5Screate_simple(1, &two, NULL);
    hid_t a = H5Acreate2(g, "version", H5T_NATIVE_INT, sp, H5P_DEFAULT, H5P_DEFAULT);
    herr_t rc = a >= 0 ? H5Awrite(a, H5T_NATIVE_INT, version) : -1;
    if (a >= 0) H5Aclose(a);
    H5Sclose(sp); H5Gclose(g);
    if (rc < 0) return -1;
    return attr_text(file, "/h5md/author", "name", "dpd reproducibility package")
         | attr_text(file, "/h5md/creator", "name", "dpd") | attr_text(file, "/h5md/creator", "version", DPD_GIT);
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

int output_series(Output *o, const char *name, const double *v, size_t n, long long first_step, int every,
                  double dt)
{
    char path[512];
    snprintf(path, sizeof path, "/series/%s/value", name);
    if (output_table(o, path, v, (int)n, 1, NULL)) return -1;
    double *st = malloc((n ? n : 1) * sizeof *st);
    long long *sp = malloc((n ? n : 1) * sizeof *sp);
    if (!st || !sp) { free(st); free(sp); return -1; }
    for (size_t k = 0; k < n; k++) {
        sp[k] = first_step + (long long)k * every;
        st[k] = (double)sp[k] * dt;
    }
    snprintf(path, sizeof path, "/series/%s/time", name);
    int rc = output_table(o, path, st, (int)n, 1, NULL);
    free(st);
    /* the step of every sample, as H5MD time series have */
    char leaf[256];
    snprintf(path, sizeof path, "/series/%s/step", name);
    hid_t g = rc ? -1 : parent_of(o, path, leaf, sizeof leaf);
    if (g < 0) { free(sp); return -1; }
    hsize_t dims[1] = {(hsize_t)n};
    hid_t ds = H5Screate_simple(1, dims, NULL);
    hid_t d = H5Dcreate2(g, leaf, H5T_NATIVE_LLONG, ds, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    rc = d >= 0 && (n == 0 || H5Dwrite(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, sp) >= 0) ? 0 : -1;
    if (d >= 0) H5Dclose(d);
    H5Sclose(ds); H5Gclose(g); free(sp);
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

/* The H5MD trajectory group /particles/all of a file: box, species (in id
 * order like the frames) and the extensible position, velocity and image
 * datasets and box edges, all sharing position's step and time. The edges
 * are a time series of D x D matrices (rows: the cell's edge vectors), as
 * MDAnalysis's reader wants them and H5MD allows: with shear the cell is the
 * sheared one, second edge (offset, L_y, 0), whose lattice is the
 * Lees-Edwards images', so position + image . edges unwraps (box.h). */
static int traj_create(hid_t file, const System *s, hid_t h[TRAJ_SETS])
{
    hid_t box = ensure_group(file, "/particles/all/box");
    if (box < 0) return -1;
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
    H5Aclose(ab); H5Tclose(st); H5Sclose(spn); H5Gclose(box);
    int *sp_id = malloc((size_t)s->n * sizeof(int) + 1);
    if (!sp_id) return -1;
    for (int i = 0; i < s->n; i++) sp_id[s->id[i]] = s->type[i];
    hsize_t nn = (hsize_t)s->n;
    hid_t sps = H5Screate_simple(1, &nn, NULL);
    hid_t all = ensure_group(file, "/particles/all");
    hid_t dsp = H5Dcreate2(all, "species", H5T_NATIVE_INT, sps, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (dsp >= 0) { H5Dwrite(dsp, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, sp_id); H5Dclose(dsp); }
    H5Sclose(sps); H5Gclose(all); free(sp_id);
    hid_t pg = ensure_group(file, "/particles/all/position");
    h[TRAJ_POS] = extensible(pg, "value", H5T_NATIVE_DOUBLE, s->n, dim);
    h[TRAJ_STEP] = extensible(pg, "step", H5T_NATIVE_LLONG, 0, 1);
    h[TRAJ_TIME] = extensible(pg, "time", H5T_NATIVE_DOUBLE, 0, 1);
    H5Gclose(pg);
    static const char *shared[] = {"/particles/all/velocity", "/particles/all/image", "/particles/all/box/edges"};
    for (int k = 0; k < 3; k++) {
        hid_t g = ensure_group(file, shared[k]);
        if (g < 0) return -1;
        const int q = k == 0 ? TRAJ_VEL : k == 1 ? TRAJ_IMG : TRAJ_BOX;
        h[q] = extensible(g, "value", q == TRAJ_IMG ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, q == TRAJ_BOX ? dim : s->n, dim);
        H5Lcreate_hard(file, "/particles/all/position/step", g, "step", H5P_DEFAULT, H5P_DEFAULT);
        H5Lcreate_hard(file, "/particles/all/position/time", g, "time", H5P_DEFAULT, H5P_DEFAULT);
        H5Gclose(g);
    }
    /* the time between frames as an observable sampled with the frames: MDAnalysis's H5MD reader
     * (2.4) takes a trajectory's dt only from /observables/dt/value[frame] (else it warns and says
     * 1.0); a time series with position's step and time, as H5MD asks of an observable */
    hid_t og = ensure_group(file, "/observables/dt");
    if (og < 0) return -1;
    h[TRAJ_DT] = extensible(og, "value", H5T_NATIVE_DOUBLE, 0, 1);
    H5Lcreate_hard(file, "/particles/all/position/step", og, "step", H5P_DEFAULT, H5P_DEFAULT);
    H5Lcreate_hard(file, "/particles/all/position/time", og, "time", H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(og);
    for (int k = 0; k < TRAJ_SETS; k++) if (h[k] < 0) return -1;
    return 0;
}

static void traj_close(hid_t h[TRAJ_SETS])
{
    for (int k = 0; k < TRAJ_SETS; k++) if (h[k] > 0) { H5Dclose(h[k]); h[k] = -1; }
}

int output_open(Output *o, const char *dir, const System *s, int trajectory_every)
{
    const int trajectory = trajectory_every > 0;
    memset(o, 0, sizeof *o);
    for (int k = 0; k < TRAJ_SETS; k++) o->traj[k] = o->seg[k] = -1;
    o->seg_file = -1;
    snprintf(o->dir, sizeof o->dir, "%s", dir);
    snprintf(o->path, sizeof o->path, "%s/run.h5", dir);
    snprintf(o->tmp_path, sizeof o->tmp_path, "%s/run.h5.part", dir);
    /* HDF5 1.10 closes a file whose H5Fclose failed (disk full) again at exit
     * and crashes there: no exit-time cleanup (fails harmlessly if too late) */
    H5dont_atexit();
    if (!getenv("DPD_HDF5_DEBUG")) H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    o->file = H5Fcreate(o->tmp_path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (o->file < 0) return -1;
    o->traj_on = trajectory;
    o->frame_every = trajectory_every;
    o->segmented = trajectory;
    if (h5md_header(o->file) || (trajectory && traj_create(o->file, s, o->traj))) {
        /* nothing of it stays open (the caller never closes an Output it could not open):
         * the datasets first, or the file would stay open behind its id (H5F_CLOSE_WEAK) */
        traj_close(o->traj);
        H5Fclose(o->file);
        o->file = -1;
        return -1;
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

/* Read frame `frame` of an extensible dataset (the inverse of append). */
static int read_frame(hid_t d, hid_t type, long long frame, int cols, int dim, void *buf)
{
    const int rank = cols > 0 ? 3 : 1;
    hid_t fs = H5Dget_space(d);
    if (fs < 0) return -1;
    hsize_t start[3] = {(hsize_t)frame, 0, 0}, count[3] = {1, (hsize_t)(cols > 0 ? cols : 1), (hsize_t)dim};
    herr_t rc = H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL);
    hid_t ms = H5Screate_simple(rank, count, NULL);
    if (rc >= 0) rc = H5Dread(d, type, ms, fs, H5P_DEFAULT, buf);
    H5Sclose(ms); H5Sclose(fs);
    return rc < 0 ? -1 : 0;
}

static const char *SET_PATH[TRAJ_SETS] = {
    "/particles/all/position/value", "/particles/all/velocity/value", "/particles/all/image/value",
    "/particles/all/box/edges/value", "/particles/all/position/step", "/particles/all/position/time",
    "/observables/dt/value"};

/* Rows of one frame of each set (0: a scalar per frame), and its type. */
static int set_rows(int q, const System *s)
{
    return q == TRAJ_BOX ? s->box.dim : q == TRAJ_STEP || q == TRAJ_TIME || q == TRAJ_DT ? 0 : s->n;
}
static hid_t set_type(int q)
{
    return q == TRAJ_IMG ? H5T_NATIVE_INT : q == TRAJ_STEP ? H5T_NATIVE_LLONG : H5T_NATIVE_DOUBLE;
}

static void segment_path(const Output *o, int k, int part, char *buf, size_t len)
{
    if (part) snprintf(buf, len, "%s/.trajectory-%04d.h5.part", o->dir, k);
    else snprintf(buf, len, "%s/trajectory-%04d.h5", o->dir, k);
}

/* Frames are stored in id order so that a particle keeps its row. */
int output_frame(Output *o, const System *s)
{
    if (!o->traj_on) return 0;
    hid_t *h = o->traj;
    long long at = o->frames;
    if (o->segmented) {   /* into the open segment file, created with its first frame */
        if (o->seg_file < 0) {
            char part[1100];
            segment_path(o, o->nseg, 1, part, sizeof part);
            o->seg_file = H5Fcreate(part, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
            if (o->seg_file < 0 || h5md_header(o->seg_file) || traj_create(o->seg_file, s, o->seg)) return -1;
            o->seg_frames = 0;
        }
        h = o->seg;
        at = o->seg_frames;
    }
    const int n = s->n;
    double *buf = malloc(3 * (size_t)n * sizeof(double) + 1);
    int *ib = malloc(3 * (size_t)n * sizeof(int) + 1);
    if (!buf || !ib) { free(buf); free(ib); return -1; }
    int rc = 0;
    const int dim = s->box.dim;
    for (int i = 0; i < n; i++) memcpy(buf + dim * s->id[i], s->x + 3 * i, dim * sizeof(double));
    rc |= append(h[TRAJ_POS], H5T_NATIVE_DOUBLE, at, n, dim, buf);
    for (int i = 0; i < n; i++) memcpy(buf + dim * s->id[i], s->v + 3 * i, dim * sizeof(double));
    rc |= append(h[TRAJ_VEL], H5T_NATIVE_DOUBLE, at, n, dim, buf);
    for (int i = 0; i < n; i++) memcpy(ib + dim * s->id[i], s->img + 3 * i, dim * sizeof(int));
    rc |= append(h[TRAJ_IMG], H5T_NATIVE_INT, at, n, dim, ib);
    double edges[9] = {0};   /* rows: the edge vectors; the y edge carries the Lees-Edwards offset */
    for (int d = 0; d < dim; d++) edges[d * dim + d] = s->box.L[d];
    if (MOD_SHEAR(&s->box)) edges[dim] = s->box.le_offset;
    rc |= append(h[TRAJ_BOX], H5T_NATIVE_DOUBLE, at, dim, dim, edges);
    long long st = (long long)s->step;
    rc |= append(h[TRAJ_STEP], H5T_NATIVE_LLONG, at, 0, 1, &st);
    rc |= append(h[TRAJ_TIME], H5T_NATIVE_DOUBLE, at, 0, 1, &s->time);
    const double frame_dt = o->frame_every * s->dt;
    rc |= append(h[TRAJ_DT], H5T_NATIVE_DOUBLE, at, 0, 1, &frame_dt);
    free(buf); free(ib);
    o->frames++;
    if (o->segmented) o->seg_frames++;
    return rc;
}

static void fsync_path(const char *path, int dir)
{
    int fd = open(path, dir ? O_RDONLY | O_DIRECTORY : O_RDONLY);
    if (fd >= 0) { fsync(fd); close(fd); }
}

/* The checksum of a file's bytes (FNV-1a, checkpoint_hash); 0 or -1 if it cannot be read. */
static int file_checksum(const char *path, uint64_t *sum)
{
    FILE *f = fopen(path, "rb");
    if (!f) return -1;
    unsigned char buf[1 << 16];
    uint64_t h = 0;
    size_t got;
    while ((got = fread(buf, 1, sizeof buf, f)) > 0) h = checkpoint_hash(buf, got, h);
    const int bad = ferror(f);
    fclose(f);
    *sum = h;
    return bad ? -1 : 0;
}

/* Segment k against its recorded checksum; 0, or -1 with err set. */
static int segment_verify(const Output *o, int k, char *err, size_t errlen)
{
    char path[1100];
    segment_path(o, k, 0, path, sizeof path);
    uint64_t sum;
    if (file_checksum(path, &sum)) {
        snprintf(err, errlen, "trajectory segment %s is missing or unreadable", path);
        return -1;
    }
    if (sum != o->seg_sum[k]) {
        snprintf(err, errlen, "trajectory segment %s does not match its checksum (written %016llx, now "
                 "%016llx): the file changed after it was closed", path, (unsigned long long)o->seg_sum[k],
                 (unsigned long long)sum);
        return -1;
    }
    return 0;
}

static int seg_sum_room(Output *o, int n)
{
    if (n <= o->seg_cap) return 0;
    const int cap = n + n / 2 + 16;
    uint64_t *p = realloc(o->seg_sum, (size_t)cap * sizeof *p);
    if (!p) return -1;
    o->seg_sum = p;
    o->seg_cap = cap;
    return 0;
}

int output_segment_commit(Output *o)
{
    if (!o->segmented || o->seg_file < 0) return 0;
    traj_close(o->seg);
    const herr_t c = H5Fclose(o->seg_file);
    o->seg_file = -1;
    char part[1100], path[1100];
    segment_path(o, o->nseg, 1, part, sizeof part);
    segment_path(o, o->nseg, 0, path, sizeof path);
    if (c < 0) { unlink(part); return -1; }
    fsync_path(part, 0);
    /* the checksum of the bytes as closed: a resume and the final assembly compare it */
    if (seg_sum_room(o, o->nseg + 1) || file_checksum(part, &o->seg_sum[o->nseg])) return -1;
    if (rename(part, path)) return -1;
    fsync_path(o->dir, 1);
    o->nseg++;
    o->seg_frames = 0;
    return 0;
}

/* k of a file name trajectory-k.h5 (*part = 0) or .trajectory-k.h5.part (*part = 1), else -1 */
static int segment_index(const char *name, int *part)
{
    *part = name[0] == '.';
    const char *p = name + *part;
    if (strncmp(p, "trajectory-", 11)) return -1;
    p += 11;
    if (*p < '0' || *p > '9') return -1;
    char *end;
    const long k = strtol(p, &end, 10);
    if (strcmp(end, *part ? ".h5.part" : ".h5") || k > 1000000) return -1;
    return (int)k;
}

/* Frames in a segment file, or -1 if it cannot be read. */
static long long segment_frames(const char *path)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return -1;
    long long n = -1;
    hid_t d = H5Dopen2(f, SET_PATH[TRAJ_STEP], H5P_DEFAULT);
    if (d >= 0) {
        hid_t sp = H5Dget_space(d);
        hsize_t dims[1];
        if (sp >= 0 && H5Sget_simple_extent_ndims(sp) == 1 && H5Sget_simple_extent_dims(sp, dims, NULL) == 1)
            n = (long long)dims[0];
        if (sp >= 0) H5Sclose(sp);
        H5Dclose(d);
    }
    H5Fclose(f);
    return n;
}

int output_segments_resume(Output *o, int nseg, long long frames, const uint64_t *sums, char *err, size_t errlen)
{
    if (!o->segmented) return 0;
    /* segments written after the checkpoint (and any partial one) are stale */
    DIR *dp = opendir(o->dir);
    if (dp) {
        struct dirent *e;
        while ((e = readdir(dp))) {
            int part;
            const int k = segment_index(e->d_name, &part);
            if (k >= 0 && (part || k >= nseg)) {
                char p[1400];
                snprintf(p, sizeof p, "%s/%s", o->dir, e->d_name);
                unlink(p);
            }
        }
        closedir(dp);
    }
    if (seg_sum_room(o, nseg)) { snprintf(err, errlen, "out of memory"); return -1; }
    for (int k = 0; k < nseg; k++) o->seg_sum[k] = sums[k];
    long long total = 0;
    for (int k = 0; k < nseg; k++) {
        char path[1100];
        segment_path(o, k, 0, path, sizeof path);
        if (access(path, F_OK) == 0 && segment_verify(o, k, err, errlen)) {
            snprintf(err + strlen(err), errlen - strlen(err), "; delete %s/checkpoint.dpd to start afresh", o->dir);
            return -1;
        }
        const long long n = segment_frames(path);
        if (n < 0) {
            snprintf(err, errlen, "trajectory segment %s of the checkpoint is missing or unreadable; "
                     "delete %s/checkpoint.dpd to start afresh", path, o->dir);
            return -1;
        }
        total += n;
    }
    if (total != frames) {
        snprintf(err, errlen, "the trajectory segments in %s hold %lld frames, the checkpoint %lld; "
                 "delete %s/checkpoint.dpd to start afresh", o->dir, total, frames, o->dir);
        return -1;
    }
    o->nseg = nseg;
    o->frames = frames;
    return 0;
}

int output_segments_merge(Output *o, const System *s, char *err, size_t errlen)
{
    if (!o->segmented) return 0;
    if (output_segment_commit(o)) { snprintf(err, errlen, "closing the last trajectory segment failed (disk full?)"); return -1; }
    for (int k = 0; k < o->nseg; k++)
        if (segment_verify(o, k, err, errlen)) return -1;
    const int n = s->n, dim = s->box.dim;
    double *buf = malloc((3 * (size_t)n + 9) * sizeof(double));   /* a frame, or the 3 x 3 edges */
    int *ib = malloc(3 * (size_t)n * sizeof(int) + 1);
    if (!buf || !ib) { free(buf); free(ib); return -1; }
    long long at = 0;
    int rc = 0;
    for (int k = 0; k < o->nseg && rc == 0; k++) {
        char path[1100];
        segment_path(o, k, 0, path, sizeof path);
        const long long nf = segment_frames(path);
        hid_t f = nf >= 0 ? H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT) : -1;
        if (f < 0) { rc = -1; break; }
        hid_t h[TRAJ_SETS];
        for (int q = 0; q < TRAJ_SETS; q++) {
            h[q] = H5Dopen2(f, SET_PATH[q], H5P_DEFAULT);
            if (h[q] < 0) rc = -1;
        }
        for (long long fr = 0; fr < nf && rc == 0; fr++, at++)
            for (int q = 0; q < TRAJ_SETS && rc == 0; q++) {
                const int rows = set_rows(q, s);
                void *b = q == TRAJ_IMG ? (void *)ib : (void *)buf;
                rc |= read_frame(h[q], set_type(q), fr, rows, rows ? dim : 1, b);
                rc |= append(o->traj[q], set_type(q), at, rows, rows ? dim : 1, b);
            }
        traj_close(h);
        H5Fclose(f);
    }
    free(buf); free(ib);
    if (rc || at != o->frames) {
        snprintf(err, errlen, "copying the trajectory segments into run.h5 failed (disk full?)");
        return -1;
    }
    return 0;
}

void output_segments_remove(Output *o)
{
    for (int k = 0; o->segmented && k < o->nseg; k++) {
        char path[1100];
        segment_path(o, k, 0, path, sizeof path);
        unlink(path);
    }
}

int output_close(Output *o, int complete)
{
    free(o->seg_sum);
    o->seg_sum = NULL;
    o->seg_cap = 0;
    if (o->traj_on) traj_close(o->traj);
    if (o->seg_file >= 0) { traj_close(o->seg); H5Fclose(o->seg_file); o->seg_file = -1; }
    if (o->segmented) {   /* a failed run: its open segment is no part of any checkpoint */
        char part[1100];
        segment_path(o, o->nseg, 1, part, sizeof part);
        unlink(part);
    }
    if (H5Fclose(o->file) < 0) return -1;
    if (!complete) return 0;   /* the .part file stays: never mistaken for a result */
    int fd = open(o->tmp_path, O_RDONLY);
    if (fd >= 0) { fsync(fd); close(fd); }
    return rename(o->tmp_path, o->path);
}

/* Every file a complete run leaves (run_output.c, the modules' tables): a new run removes them
 * before its first step, so that a run that then fails leaves no part of an older result beside
 * its INCOMPLETE (tests/io_errors.sh runs scenes with every table and checks that none is left). */
static const char *const RESULT_FILES[] = {
    "summary.tsv", "provenance.tsv", "run.h5",
    "profile.tsv", "profile_blocks.tsv", "com.tsv", "rdf.tsv", "msd.tsv",                /* measure.c */
    "around.tsv", "density_map.tsv", "force_map.tsv",                                     /* measure_field.c */
    "tcaf.tsv", "tcaf_eta.tsv", "tcaf_extrapolation.tsv",                                 /* tcaf.c */
    "colloid_around.tsv", "colloid_rdf.tsv", "colloid_msd.tsv",                           /* bonds.c */
    "solver.tsv"};                                                                        /* overdamped.c */

int output_remove_results(const char *dir)
{
    int bad = 0;
    for (size_t k = 0; k < sizeof RESULT_FILES / sizeof RESULT_FILES[0]; k++) {
        char path[1100];
        snprintf(path, sizeof path, "%s/%s", dir, RESULT_FILES[k]);
        if (unlink(path) && errno != ENOENT) bad = 1;
    }
    if (!bad) fsync_path(dir, 1);
    return bad ? -1 : 0;
}

int output_write_tables(const char *dir, const Tables *ts, const char **failed)
{
    for (int k = 0; k < ts->n; k++)
        if (write_file_atomic(dir, ts->t[k]->name, ts->t[k]->text ? ts->t[k]->text : "", ts->t[k]->len)) {
            *failed = ts->t[k]->name;
            return -1;
        }
    return 0;
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
