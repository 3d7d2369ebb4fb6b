/* runutil.h - run a scene through run_scene() in a temporary directory and
 * read its outputs (summary.tsv, run.h5). */
#ifndef DPD_RUNUTIL_H
#define DPD_RUNUTIL_H

#include "testutil.h"
#include <unistd.h>
#include <hdf5.h>
#include "run.h"

/* A fresh temporary directory (caller frees nothing; removed by rm_rf). */
static inline void make_tmpdir(char *buf, size_t len, const char *tag)
{
    const char *base = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    snprintf(buf, len, "%s/dpd-test-%s-XXXXXX", base, tag);
    assert_non_null(mkdtemp(buf));
}

static inline void rm_rf(const char *dir)
{
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "warning: could not remove %s\n", dir);
}

static inline void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

/* Run scene file `scene` into `outdir` with `threads` OpenMP threads. */
static inline int run_quiet(const char *scene, const char *outdir, int threads)
{
    RunOptions o = {.scene = scene, .outdir = outdir, .threads = threads, .quiet = 1,
                    .command_line = "test"};
    return run_scene(&o);
}

/* Write scene text `text` into a fresh temporary directory `dir` and run it
 * into `out` (= dir/out) on the default thread count; returns run_scene's status. */
static inline int run_scene_text(const char *tag, const char *text, char *dir, size_t dlen, char *out, size_t olen)
{
    char scene[600];
    make_tmpdir(dir, dlen, tag);
    snprintf(scene, sizeof scene, "%s/scene.cfg", dir);
    snprintf(out, olen, "%s/out", dir);
    write_text(scene, text);
    return run_quiet(scene, out, 0);
}

/* value and stderr of a quantity in summary.tsv; returns 0 if found. */
static inline int summary_get(const char *dir, const char *key, double *value, double *se)
{
    char path[1200], line[512];
    snprintf(path, sizeof path, "%s/summary.tsv", dir);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    int found = -1;
    while (fgets(line, sizeof line, f)) {
        char name[256];
        double v, e;
        if (sscanf(line, "%255[^\t]\t%lf\t%lf", name, &v, &e) == 3 && strcmp(name, key) == 0) {
            *value = v; *se = e; found = 0;
            break;
        }
    }
    fclose(f);
    return found;
}

/* The last frame of an H5MD dataset (frames x n x 3) as doubles or ints:
 * returns a malloc'd buffer of n x 3 and sets *n. */
static inline void *h5_last_frame(const char *file, const char *dset, hid_t memtype, size_t elsize, int *n)
{
    hid_t f = H5Fopen(file, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return NULL;
    hid_t d = H5Dopen2(f, dset, H5P_DEFAULT);
    if (d < 0) { H5Fclose(f); return NULL; }
    hid_t sp = H5Dget_space(d);
    hsize_t dims[3] = {0, 0, 0};
    void *buf = NULL;
    if (H5Sget_simple_extent_ndims(sp) == 3 && H5Sget_simple_extent_dims(sp, dims, NULL) == 3 && dims[0] > 0) {
        hsize_t start[3] = {dims[0] - 1, 0, 0}, count[3] = {1, dims[1], dims[2]};
        H5Sselect_hyperslab(sp, H5S_SELECT_SET, start, NULL, count, NULL);
        hid_t ms = H5Screate_simple(3, count, NULL);
        buf = malloc(dims[1] * dims[2] * elsize);
        if (buf && H5Dread(d, memtype, ms, sp, H5P_DEFAULT, buf) < 0) { free(buf); buf = NULL; }
        H5Sclose(ms);
        *n = (int)dims[1];
    }
    H5Sclose(sp);
    H5Dclose(d);
    H5Fclose(f);
    return buf;
}

#endif
