/* output.h - one HDF5 file per run (parameters, provenance, time series,
 * results, optional H5MD trajectory) and summary.tsv. Files are written under
 * a temporary name and renamed when complete. */
#ifndef DPD_OUTPUT_H
#define DPD_OUTPUT_H

#include <hdf5.h>
#include "system.h"

typedef struct {
    hid_t file;
    char path[1024], tmp_path[1024];
    /* trajectory (H5MD /particles/all) */
    hid_t pos, vel, step, time, img;
    long long frames;
    int traj_on;
} Output;

typedef struct {
    const char *key;
    char value[512];
} ProvItem;

int  output_open(Output *o, const char *dir, const System *s, int trajectory);
int  output_frame(Output *o, const System *s);
/* Text attribute on a group path (created if needed). */
int  output_attr_text(Output *o, const char *group, const char *name, const char *value);
int  output_attr_double(Output *o, const char *group, const char *name, double value);
/* A 2D table (rows x cols doubles) with column names. */
int  output_table(Output *o, const char *path, const double *data, int rows, int cols,
                  const char *columns);
/* Copy a tab-separated text file (header line + numbers) into a dataset. */
int  output_tsv(Output *o, const char *path, const char *tsv_file);
int  output_series(Output *o, const char *name, const double *v, size_t n, int every, double dt);
int  output_close(Output *o, int complete);

/* Write text to dir/name atomically (temp file, fsync, rename). */
int  write_file_atomic(const char *dir, const char *name, const char *text, size_t len);

#endif
