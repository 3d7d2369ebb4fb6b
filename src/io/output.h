/* output.h - one HDF5 file per run (parameters, provenance, time series,
 * results, optional H5MD trajectory) and summary.tsv. Files are written under
 * a temporary name and renamed when complete. */
#ifndef DPD_OUTPUT_H
#define DPD_OUTPUT_H

#include <stdint.h>
#include <hdf5.h>
#include "system.h"
#include "table.h"

/* trajectory datasets: position, velocity, image (frames x n x dim), box edges
 * (frames x dim x dim), step, time, and the time between frames (frames) */
enum { TRAJ_POS, TRAJ_VEL, TRAJ_IMG, TRAJ_BOX, TRAJ_STEP, TRAJ_TIME, TRAJ_DT, TRAJ_SETS };

/* A run with a trajectory writes its frames into segment files
 * DIR/trajectory-NNNN.h5 (each a valid H5MD file, written as
 * .trajectory-NNNN.h5.part and renamed when a checkpoint closes it), so a
 * killed run never leaves a half-written HDF5 file behind its checkpoint; the
 * complete run copies them in order into run.h5 and removes them. */
typedef struct {
    hid_t file;
    char path[1024], tmp_path[1024], dir[1024];
    /* trajectory (H5MD /particles/all) */
    hid_t traj[TRAJ_SETS];
    long long frames;         /* frames written (all segments included) */
    int traj_on;
    int frame_every;          /* steps between frames (output_open's trajectory_every) */
    int segmented;
    hid_t seg_file, seg[TRAJ_SETS];
    int nseg;                 /* complete segment files */
    long long seg_frames;     /* frames in the open segment */
    uint64_t *seg_sum;        /* the checksum of each complete segment file (FNV-1a of its bytes) */
    int seg_cap;
} Output;

typedef struct {
    const char *key;
    char value[512];
} ProvItem;

/* trajectory_every > 0: an H5MD trajectory with a frame every that many steps */
int  output_open(Output *o, const char *dir, const System *s, int trajectory_every);
int  output_frame(Output *o, const System *s);
/* Close the open trajectory segment, rename it complete (before a checkpoint) and
 * record its checksum (o->seg_sum, kept in the checkpoint). */
int  output_segment_commit(Output *o);
/* At the start of a segmented run: keep the nseg complete segments of the
 * checkpoint (which must hold `frames` frames and have the checksums sums; 0, 0,
 * NULL for a fresh run), delete later or partial ones. -1 with err set if a
 * segment is missing, short or does not match its checksum. */
int  output_segments_resume(Output *o, int nseg, long long frames, const uint64_t *sums, char *err, size_t errlen);
/* At the end of a complete run: every segment's frames into run.h5, in order,
 * each segment checked against its checksum first. -1 with err set. */
int  output_segments_merge(Output *o, const System *s, char *err, size_t errlen);
/* After run.h5 is in place: delete the segment files. */
void output_segments_remove(Output *o);
/* Text attribute on a group path (created if needed). */
int  output_attr_text(Output *o, const char *group, const char *name, const char *value);
int  output_attr_double(Output *o, const char *group, const char *name, double value);
/* A 2D table (rows x cols doubles) with column names. */
int  output_table(Output *o, const char *path, const double *data, int rows, int cols,
                  const char *columns);
/* Copy a tab-separated text file (header line + numbers) into a dataset. */
int  output_tsv(Output *o, const char *path, const char *tsv_file);
/* /series/NAME: value, and the step and time of sample k, first_step + k every. Not
 * /observables: H5MD readers such as MDAnalysis take those to be sampled with the
 * trajectory's frames (they read value[frame]), which the measurements are not. */
int  output_series(Output *o, const char *name, const double *v, size_t n, long long first_step, int every,
                   double dt);
int  output_close(Output *o, int complete);

/* Remove the files of an earlier complete run from dir (summary.tsv, provenance.tsv, run.h5,
 * the tables): 0, or -1 (errno) if one could not be removed. Checkpoints and trajectory
 * segments stay (a resumed run needs them). */
int  output_remove_results(const char *dir);

/* Every table of ts into dir, each atomically (write_file_atomic). 0, or -1 with the
 * name of the table that failed in *failed. */
int  output_write_tables(const char *dir, const Tables *ts, const char **failed);

/* Write text to dir/name atomically (temp file, fsync, rename). */
int  write_file_atomic(const char *dir, const char *name, const char *text, size_t len);

#endif
